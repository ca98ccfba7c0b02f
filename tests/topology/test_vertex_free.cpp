// vertex_free_parts (topology/vertex_free.h) offers the candidate triples and pairs of an octree set of more
// than kAllTriplesUpTo sites from the lifted triangulation of the union of such sets. A bound of 4 sends every
// larger set that way: the vertex-free parts must equal those found from every triple and pair, on every
// generator family. A
// failure prints the family, size and seed (`apollonius3d generate KIND --n N --seed S` writes that input).
// APOLLONIUS_VERTEX_FREE_SEEDS sets the seeds per family and size, APOLLONIUS_DIFFERENTIAL_TIME_LIMIT the
// seconds allowed per input.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "io/write_topology.h"
#include "octree/octree_diagram.h"
#include "predicates/predicate_counter.h"
#include "reference/brute_force_diagram.h"
#include "reference/site_generators.h"
#include "topology/build_topology.h"
#include "topology/validate_topology.h"
#include "topology/vertex_free.h"

using namespace apollonius;

namespace {

double from_environment(const char* name, double fallback) {
  const char* text = std::getenv(name);
  return text != nullptr ? std::strtod(text, nullptr) : fallback;
}

bool same(const Diagram_edge& x, const Diagram_edge& y) {
  return x.tie_set == y.tie_set && x.start == y.start && x.end == y.end && x.closed == y.closed && x.curve == y.curve;
}

Vertex_free_parts sorted(Vertex_free_parts parts) {
  std::sort(parts.edges.begin(), parts.edges.end(), edge_precedes);
  std::sort(parts.sheets.begin(), parts.sheets.end());
  return parts;
}

constexpr std::size_t kEveryTriple = std::numeric_limits<std::size_t>::max();

}  // namespace

TEST_CASE("vertex-free parts from the triples of lifted triangulations equal those from every triple") {
  const auto seeds = static_cast<std::uint64_t>(from_environment("APOLLONIUS_VERTEX_FREE_SEEDS", 3));
  const double time_limit = from_environment("APOLLONIUS_DIFFERENTIAL_TIME_LIMIT", 60);
  std::size_t inputs = 0, undecided = 0, large_sets = 0, edges = 0, closed = 0, sheets = 0, fewer = 0, fewer_pairs = 0;
  for (const Site_family_description& f : kSiteFamilies) {
    // Fewer sites where the topology is slow (deep octrees, long exact numbers).
    const bool slow = f.family == Site_family::wide_range || f.family == Site_family::lattice_noise;
    for (const std::size_t n : slow ? std::vector<std::size_t>{8, 14} : std::vector<std::size_t>{12, 40}) {
      for (std::uint64_t seed = 1; seed <= seeds; ++seed)
      for (const bool lifted_fallback : {false, true}) {  // the octree's regions, or none (a box budget of 0)
        const std::string family = f.name;
        CAPTURE(family);
        CAPTURE(n);
        CAPTURE(seed);
        CAPTURE(lifted_fallback);
        const std::vector<Site> sites = generate_sites(f.family, n, seed);
        Octree_regions regions;
        Octree_options options;
        options.regions = &regions;
        if (lifted_fallback) options.box_budget = 0;
        const auto start = std::chrono::steady_clock::now();
        Diagram_topology topology;
        try {
          topology = build_edges(sites, octree_diagram(sites, options));
        } catch (const std::logic_error&) {  // a tie this version does not decide (build_topology.h)
          ++undecided;
          continue;
        }
        const Vertex_free_parts every =
            sorted(vertex_free_parts(sites, topology.vertices, topology.edges, regions, 1, nullptr, kEveryTriple));
        const Vertex_free_parts triangulated =
            sorted(vertex_free_parts(sites, topology.vertices, topology.edges, regions, 1, nullptr, 4));
        CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < time_limit);
        ++inputs;
        REQUIRE(triangulated.edges.size() == every.edges.size());
        for (std::size_t e = 0; e < every.edges.size(); ++e) CHECK(same(triangulated.edges[e], every.edges[e]));
        CHECK(triangulated.sheets == every.sheets);
        CHECK(triangulated.candidate_triples <= every.candidate_triples);
        CHECK(triangulated.candidate_pairs <= every.candidate_pairs);
        fewer += triangulated.candidate_triples < every.candidate_triples;
        fewer_pairs += triangulated.candidate_pairs < every.candidate_pairs;
        for (const Octree_regions::Box& box : regions.boxes) large_sets += box.sites.size() > 4;
        for (const std::vector<Site_index>& set : regions.far_sets) large_sets += set.size() > 4;
        edges += every.edges.size();
        closed += std::count_if(every.edges.begin(), every.edges.end(), [](const Diagram_edge& e) { return e.closed; });
        sheets += every.sheets.size();
      }
    }
  }
  MESSAGE(inputs << " inputs (" << undecided << " with a tie not decided), " << large_sets
                 << " sets of more than 4 sites; " << fewer << " inputs with fewer candidate triples, " << fewer_pairs
                 << " with fewer pairs; vertex-free: " << edges
                 << " edges (" << closed << " closed), " << sheets << " whole sheets");
  CHECK(inputs > 100);
  CHECK(large_sets > 100);
  CHECK(fewer > 10);  // the triangulation leaves triples out, and the parts stay the same
  CHECK(fewer_pairs > 10);
  CHECK(closed > 0);
  CHECK(edges > closed);
  CHECK(sheets > 0);
}

TEST_CASE("the reference offers every triple whatever the bound") {
  const std::vector<Site> sites = generate_sites(Site_family::uniform, 20, 5);
  const Diagram diagram = brute_force_diagram(sites);
  const Octree_regions regions = regions_for_every_site(diagram);
  REQUIRE(regions.far_sets.size() == 1);
  REQUIRE(regions.far_sets[0].size() > 4);
  const Diagram_topology topology = build_edges(sites, diagram);
  const Vertex_free_parts every =
      vertex_free_parts(sites, topology.vertices, topology.edges, regions, 1, nullptr, kEveryTriple);
  const Vertex_free_parts bounded = vertex_free_parts(sites, topology.vertices, topology.edges, regions, 1, nullptr, 4);
  CHECK(bounded.candidate_triples == every.candidate_triples);
  CHECK(every.candidate_triples > 0);
}

TEST_CASE("whole sheets from the lifted triangulation's edges: balls centred on one line") {
  // Balls of one radius: every face is the whole plane between two neighbours on the line, and the octree's
  // boxes along the line hold many of them. A bound of 4 finds each from the union's edges.
  for (const std::size_t n : {10, 30, 60}) {
    CAPTURE(n);
    std::vector<Site> sites;
    for (std::size_t k = 0; k < n; ++k)
      sites.push_back({4.0 * static_cast<double>(k) + (k % 2 == 0 ? 0.25 : 0.0), 0, 0, 1});
    Octree_regions regions;
    Octree_options options;
    options.regions = &regions;
    const Diagram_topology topology = build_edges(sites, octree_diagram(sites, options));
    const Vertex_free_parts every =
        sorted(vertex_free_parts(sites, topology.vertices, topology.edges, regions, 1, nullptr, kEveryTriple));
    const Vertex_free_parts triangulated =
        sorted(vertex_free_parts(sites, topology.vertices, topology.edges, regions, 1, nullptr, 4));
    CHECK(every.sheets.size() == n - 1);
    CHECK(triangulated.sheets == every.sheets);
    CHECK(triangulated.candidate_pairs < every.candidate_pairs);
  }
}

TEST_CASE("balls on one circle with mixed weights: thousands of tied boxes share one triangulation") {
  // Regression: `generate circle-mixed --n 300 --seed 2` made 4,111 octree sets of 65 to 171 tied sites,
  // each triangulated on its own (past 300 s), and 60 million triple occurrences from the smaller ones.
  const double time_limit = from_environment("APOLLONIUS_DIFFERENTIAL_TIME_LIMIT", 60);
  const std::vector<Site> sites = generate_sites(Site_family::circle_mixed, 300, 2);
  const auto start = std::chrono::steady_clock::now();
  Octree_regions regions;
  Octree_options options;
  options.regions = &regions;
  options.octree_alone();  // the boxes, past the budget that would turn to the lifted fallback
  const Diagram_topology topology = build_topology(sites, octree_diagram(sites, options), regions);
  validate_topology(sites, topology);
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < time_limit);
  std::size_t large_sets = 0;
  for (const Octree_regions::Box& box : regions.boxes) large_sets += box.sites.size() > 64;
  CHECK(large_sets > 1000);
  // No vertex: every edge is a closed curve or a curve infinite both ways (the release build's counts).
  CHECK(topology.vertices.vertices.empty());
  CHECK(topology.edges.size() == 65);
  CHECK(topology.faces.size() == 242);
  CHECK(topology.cells.size() == 178);

  // By default the octree spends its budget (1,024 boxes per active site, plus 16,384) and stops: the lifted
  // fallback's regions, one far set that offers its triangulation's triples, give the same diagram.
  Octree_regions fallback_regions;
  Octree_options by_default;
  by_default.regions = &fallback_regions;
  const Diagram_topology fallback = build_topology(sites, octree_diagram(sites, by_default), fallback_regions);
  CHECK(fallback_regions.lifted_fallback);
  std::ostringstream expected, got;
  write_diagram_json(expected, topology, nullptr);
  write_diagram_json(got, fallback, nullptr);
  CHECK(got.str() == expected.str());
}

TEST_CASE("one curve of many tied balls costs one test per site, not one per site and triple") {
  // Regression: `generate circle-mixed --n 4000 --seed 2` keeps 1,298 balls of one weight on one circle, tied
  // along its axis. The lifted fallback's one far set offered 1,296 triples of them, each tested exactly
  // against every site: 1.7 million exact tests (15 s). The first triple's test finds the whole tie set, and
  // the triples within it are not tested again.
  const std::vector<Site> sites = generate_sites(Site_family::circle_mixed, 4000, 2);
  for (const int threads : {1, 2}) {
    CAPTURE(threads);
    Octree_regions regions;
    Octree_options options;
    options.regions = &regions;
    const Diagram diagram = octree_diagram(sites, options);
    REQUIRE(regions.far_sets.size() == 1);
    const std::size_t active = regions.far_sets.front().size();
    CHECK(active == 1298);
    reset_predicate_statistics();
    Topology_options topology_options;
    topology_options.threads = threads;
    const Diagram_topology topology = build_topology(sites, diagram, regions, topology_options);
    std::uint64_t tests = 0;
    for (const Predicate_statistics& p : predicate_statistics())
      if (p.name == "curve_point_conflict") tests = p.evaluations;
    validate_topology(sites, topology);
    REQUIRE(topology.edges.size() == 1);
    CHECK(topology.edges.front().tie_set.size() == active);
    CHECK(topology.edges.front().curve == Curve_shape::line);
    // Each thread's first triple may test every site before another's curve is known.
    CHECK(tests >= active - 3);
    CHECK(tests <= static_cast<std::uint64_t>(threads) * active);
  }
}
