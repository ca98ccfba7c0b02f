// The whole diagram against the brute-force reference (src/reference/brute_force_edges.h) on every
// generator family: every edge, tie set, ends and curve shape, equal; then the faces and cells, checked by
// the Euler relation. A failure prints the family, size and seed: `apollonius3d
// generate KIND --n N --seed S` writes that input. APOLLONIUS_TOPOLOGY_SEEDS sets the seeds per family.
#include <doctest/doctest.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "reference/brute_force_diagram.h"
#include "reference/brute_force_edges.h"
#include "reference/site_generators.h"
#include "topology/build_topology.h"
#include "topology/euler_characteristic.h"

using namespace apollonius;

namespace {

std::string describe(const Diagram_edge& e) {
  std::string text = "sites";
  for (Site_index s : e.tie_set) text += " " + std::to_string(s);
  text += e.start ? ", from vertex " + std::to_string(*e.start) : ", from infinity";
  text += e.end ? ", to vertex " + std::to_string(*e.end) : ", to infinity";
  return text + (e.closed ? ", closed " : ", ") + to_string(e.curve);
}

bool same(const Diagram_edge& x, const Diagram_edge& y) {
  return x.tie_set == y.tie_set && x.start == y.start && x.end == y.end && x.closed == y.closed && x.curve == y.curve;
}

std::uint64_t seeds_per_family() {
  const char* text = std::getenv("APOLLONIUS_TOPOLOGY_SEEDS");
  return text != nullptr ? std::strtoull(text, nullptr, 10) : 12;
}

}  // namespace

TEST_CASE("edges equal the brute-force reference on every family") {
  std::size_t inputs = 0, edges = 0, vertex_free = 0;
  for (const std::string& name : site_family_names()) {
    for (std::uint64_t seed = 1; seed <= seeds_per_family(); ++seed) {
      const std::size_t n = 5 + seed % 12;
      CAPTURE(name);
      CAPTURE(n);
      CAPTURE(seed);
      const std::vector<Site> sites = generate_sites(site_family_from_name(name), n, seed);
      const Diagram diagram = brute_force_diagram(sites);
      const std::vector<Diagram_edge> expected = brute_force_edges(sites, diagram);
      Diagram_topology t;
      try {
        t = build_topology(sites, diagram, regions_for_every_site(diagram));
      } catch (const std::logic_error& e) {
        FAIL_CHECK("build_topology: " << std::string(e.what()));
        continue;
      }
      for (const Diagram_edge& e : expected) vertex_free += e.start || e.end ? 0 : 1;
      std::size_t i = 0, j = 0;
      const std::vector<Diagram_edge>& reference = expected;
      while (i < t.edges.size() || j < reference.size()) {
        if (i < t.edges.size() && j < reference.size() && same(t.edges[i], reference[j])) {
          ++i, ++j;
          continue;
        }
        const bool ours_first = j == reference.size() ||
                                (i < t.edges.size() && std::tie(t.edges[i].tie_set, t.edges[i].start, t.edges[i].end) <
                                                           std::tie(reference[j].tie_set, reference[j].start, reference[j].end));
        if (ours_first)
          FAIL_CHECK("only the topology layer: " << describe(t.edges[i++]));
        else
          FAIL_CHECK("only the reference: " << describe(reference[j++]));
      }
      CHECK(t.edges.size() == reference.size());
      CHECK(euler_defect(t) == 0);
      ++inputs;
      edges += reference.size();
    }
  }
  MESSAGE(inputs << " inputs, " << edges << " edges (" << vertex_free << " with no vertex), all equal");
  CHECK(vertex_free > 0);
  CHECK(edges > 10 * inputs);
}
