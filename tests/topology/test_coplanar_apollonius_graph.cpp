// Coplanar sites against CGAL's Apollonius_graph_2 (exact filtered traits), an independent oracle: in the
// sites' plane z = 0 the diagram's trace is the 2D Apollonius diagram of the circles there, and each 2D
// vertex (a finite face of the Apollonius graph) is where a 3D edge of the same three sites crosses the
// plane. The diagram is symmetric in the plane; with no vertex in it, vertices come in mirror pairs (the
// two roots of one quadruple, one tie set), an edge crosses the plane exactly when the mirror maps it to
// itself, and then it crosses once (from a vertex to its mirror, or a whole open curve) or twice (a whole
// closed curve). So the multiset of 2D vertex triples equals the multiset of crossing 3D edges, closed ones
// twice. Inputs with a vertex in the plane (four circles tangent to one) are counted and skipped.
#include <doctest/doctest.h>

#include <CGAL/Apollonius_graph_2.h>
#include <CGAL/Apollonius_graph_filtered_traits_2.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <random>
#include <string>

#include "reference/brute_force_diagram.h"
#include "reference/site_generators.h"
#include "topology/build_topology.h"
#include "topology/euler_characteristic.h"

using namespace apollonius;

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
// The exact stage in Gmpq rather than the default MP_Float, whose code shifts negative values (UBSan).
using Traits = CGAL::Apollonius_graph_filtered_traits_2<Kernel, CGAL::Integral_domain_without_division_tag,
                                                        CGAL::Simple_cartesian<CGAL::Gmpq>>;
using Apollonius_graph = CGAL::Apollonius_graph_2<Traits>;
using Triple = std::array<Site_index, 3>;

std::map<Triple, int> planar_vertices(const std::vector<Site>& sites) {
  std::map<std::array<double, 3>, Site_index> index;
  Apollonius_graph graph;
  for (Site_index i = 0; i < sites.size(); ++i) {
    index.emplace(std::array<double, 3>{sites[i].x, sites[i].y, sites[i].w}, i);
    graph.insert(Traits::Site_2(Traits::Point_2(sites[i].x, sites[i].y), sites[i].w));
  }
  std::map<Triple, int> count;
  for (auto f = graph.finite_faces_begin(); f != graph.finite_faces_end(); ++f) {
    Triple t;
    for (int k = 0; k < 3; ++k) {
      const Traits::Site_2 s = f->vertex(k)->site();
      t[k] = index.at({s.point().x(), s.point().y(), s.weight()});
    }
    std::sort(t.begin(), t.end());
    ++count[t];
  }
  return count;
}

// The crossing 3D edges by triple; nothing when a vertex lies in the plane (no mirror of its own).
std::optional<std::map<Triple, int>> crossing_edges(const Diagram& diagram, const Diagram_topology& t) {
  std::map<std::vector<Site_index>, int> roots;
  for (const Diagram_vertex& v : diagram.vertices) ++roots[v.tie_set];
  for (const auto& [tie, count] : roots)
    if (count != 2) return std::nullopt;
  std::map<Triple, int> count;
  for (const Diagram_edge& e : t.edges) {
    if (e.tie_set.size() != 3) return std::nullopt;
    const Triple triple{e.tie_set[0], e.tie_set[1], e.tie_set[2]};
    if (e.closed)
      count[triple] += 2;
    else if (!e.start && !e.end)
      count[triple] += 1;
    else if (e.start && e.end && *e.start != *e.end &&
             diagram.vertices[*e.start].tie_set == diagram.vertices[*e.end].tie_set)
      count[triple] += 1;
  }
  return count;
}

std::string describe(const std::map<Triple, int>& m) {
  std::string text;
  for (const auto& [t, c] : m)
    text += " (" + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + ")x" + std::to_string(c);
  return text;
}

std::uint64_t seeds() {
  const char* text = std::getenv("APOLLONIUS_TOPOLOGY_SEEDS");
  return text != nullptr ? 25 * std::strtoull(text, nullptr, 10) : 300;
}

std::size_t planar_vertices_compared = 0;

// Compares one input; returns whether it was checked (no vertex in the plane).
bool check(const std::vector<Site>& sites) {
  const Diagram diagram = brute_force_diagram(sites);
  const Diagram_topology t = build_topology(sites, diagram, regions_for_every_site(diagram));
  CHECK(euler_defect(t) == 0);
  const std::optional<std::map<Triple, int>> ours = crossing_edges(diagram, t);
  if (!ours) return false;
  const std::map<Triple, int> expected = planar_vertices(sites);
  for (const auto& [triple, count] : expected) planar_vertices_compared += count;
  CHECK_MESSAGE(*ours == expected, "3D:" << describe(*ours) << "\nApollonius_graph_2:" << describe(expected));
  return true;
}

}  // namespace

TEST_CASE("random coplanar balls: the trace in the plane equals Apollonius_graph_2") {
  std::size_t checked = 0;
  for (std::uint64_t seed = 1; seed <= seeds(); ++seed) {
    CAPTURE(seed);
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> coordinate(-10.0, 10.0), weight(0.0, 3.0);
    std::vector<Site> sites(4 + seed % 12);
    for (Site& s : sites) s = {coordinate(random), coordinate(random), 0.0, weight(random)};
    checked += check(sites) ? 1 : 0;
  }
  MESSAGE(checked << " of " << seeds() << " inputs checked, " << planar_vertices_compared << " 2D vertices in all");
  CHECK(checked == seeds());
  CHECK(planar_vertices_compared > 3 * checked);
}

TEST_CASE("the coplanar family (integer centres, few weights): the same, where no vertex is in the plane") {
  std::size_t checked = 0, skipped = 0;
  for (std::uint64_t seed = 1; seed <= seeds() / 3; ++seed) {
    CAPTURE(seed);
    const std::vector<Site> sites = generate_sites(site_family_from_name("coplanar"), 5 + seed % 12, seed);
    if (check(sites))
      ++checked;
    else
      ++skipped;
  }
  MESSAGE(checked << " inputs checked, " << skipped << " with a vertex in the plane or a degenerate edge skipped");
  CHECK(checked > skipped);
}
