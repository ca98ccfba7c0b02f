// The triples that a vertex's star offers (topology/departure_star.h) hold every triple along which an edge
// leaves it: each family's edges through vertices, with every tie set of 4 or more sites listed by its star,
// equal those from every triple, and every departure of every vertex is among its star's triples. A failure
// prints the family, size and seed (`apollonius3d generate KIND --n N --seed S` writes that input).
// APOLLONIUS_DEPARTURE_STAR_SEEDS sets the seeds per family and size, APOLLONIUS_DIFFERENTIAL_TIME_LIMIT the
// CPU seconds allowed per input.
#include <doctest/doctest.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "octree/octree_diagram.h"
#include "predicates/predicate_counter.h"
#include "predicates/trisector.h"
#include "reference/site_generators.h"
#include "support/time_limit.h"
#include "topology/build_topology.h"
#include "topology/departure_star.h"
#include "topology/trisector_edges.h"
#include "topology/validate_topology.h"
#include "topology/vertex_fan.h"
#include "topology/vertex_triples.h"

using namespace apollonius;
using apollonius::testing::Input_time_limit;
using apollonius::testing::seconds_from_environment;

namespace {

constexpr std::size_t kEveryTriple = std::numeric_limits<std::size_t>::max();

bool same(const Diagram_edge& x, const Diagram_edge& y) {
  return x.tie_set == y.tie_set && x.start == y.start && x.end == y.end && x.closed == y.closed && x.curve == y.curve;
}

// Every triple of v's tie set along which departures_along finds an edge leaving v.
std::vector<std::array<Site_index, 3>> departing_triples(const std::vector<Site>& sites, const Diagram_vertex& v) {
  std::vector<std::array<Site_index, 3>> out;
  std::vector<Departure> departures;
  const std::vector<Site_index>& tie = v.tie_set;
  for (std::size_t i = 0; i < tie.size(); ++i)
    for (std::size_t j = i + 1; j < tie.size(); ++j)
      for (std::size_t l = j + 1; l < tie.size(); ++l) {
        const std::array<Site_index, 3> triple{tie[i], tie[j], tie[l]};
        const Trisector trisector(triple, {sites[triple[0]], sites[triple[1]], sites[triple[2]]});
        departures.clear();
        departures_along(sites, v, trisector, {i, j, l}, departures);
        if (!departures.empty()) out.push_back(triple);
      }
  return out;
}

// The vertex with the largest tie set (the first of them), or end() if there is none.
std::vector<Diagram_vertex>::const_iterator largest_tie(const Diagram& diagram) {
  return std::max_element(diagram.vertices.begin(), diagram.vertices.end(),
                          [](const Diagram_vertex& a, const Diagram_vertex& b) { return a.tie_set.size() < b.tie_set.size(); });
}

struct Star_counts {
  std::size_t vertices = 0, given_up = 0, departures = 0, offered = 0;
};

// Checks that each vertex's departures are among its star's triples.
void check_stars(const std::vector<Site>& sites, const Diagram& diagram, Star_counts& counts) {
  std::vector<std::array<Site_index, 3>> offered;
  for (const Diagram_vertex& v : diagram.vertices) {
    ++counts.vertices;
    if (!candidate_departure_triples(sites, v, offered)) {
      ++counts.given_up;
      continue;
    }
    CHECK(std::is_sorted(offered.begin(), offered.end()));
    CHECK(std::adjacent_find(offered.begin(), offered.end()) == offered.end());
    for (const std::array<Site_index, 3>& t : departing_triples(sites, v)) {
      ++counts.departures;
      CHECK_MESSAGE(std::binary_search(offered.begin(), offered.end(), t),
                    "departure " << t[0] << " " << t[1] << " " << t[2] << " not offered by the star");
    }
    counts.offered += offered.size();
  }
}

}  // namespace

TEST_CASE("edges from the vertices' stars equal those from every triple, on every family") {
  const auto seeds = static_cast<std::uint64_t>(seconds_from_environment("APOLLONIUS_DEPARTURE_STAR_SEEDS", 4));
  const double time_limit = seconds_from_environment("APOLLONIUS_DIFFERENTIAL_TIME_LIMIT", 60);
  std::size_t inputs = 0, undecided = 0, edges = 0;
  Star_counts counts;
  for (const Site_family_description& f : kSiteFamilies) {
    const bool slow = f.family == Site_family::wide_range || f.family == Site_family::lattice_noise;
    for (const std::size_t n : slow ? std::vector<std::size_t>{8, 14} : std::vector<std::size_t>{12, 40}) {
      for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
        const std::string family = f.name;
        CAPTURE(family);
        CAPTURE(n);
        CAPTURE(seed);
        const std::vector<Site> sites = generate_sites(f.family, n, seed);
        Input_time_limit limit(time_limit, family + " " + std::to_string(n) + " seed " + std::to_string(seed));
        const Diagram diagram = octree_diagram(sites, Octree_options{});
        std::vector<Diagram_edge> every, starred;
        try {
          every = edges_through_vertices(sites, diagram, Vertex_triples(sites, diagram, nullptr, kEveryTriple), 1);
        } catch (const std::logic_error&) {  // a tie this version does not decide (build_topology.h)
          ++undecided;
          continue;
        }
        starred = edges_through_vertices(sites, diagram, Vertex_triples(sites, diagram, nullptr, 3), 1);
        check_stars(sites, diagram, counts);
        ++inputs;
        edges += every.size();
        REQUIRE(starred.size() == every.size());
        for (std::size_t e = 0; e < every.size(); ++e) CHECK(same(starred[e], every[e]));
      }
    }
  }
  MESSAGE(inputs << " inputs (" << undecided << " undecided), " << edges << " edges, " << counts.vertices
                 << " stars (" << counts.given_up << " given up), " << counts.departures << " departures, "
                 << counts.offered << " triples offered");
  CHECK(inputs > 100);
  CHECK(counts.departures > 1000);
  CHECK(counts.given_up * 20 < counts.vertices);
}

// The star of the vertex of a family's largest tie set offers O(k) of its C(k, 3) triples, and they hold
// every departure. Balls tangent to one sphere tie at its centre, their directions n_k in general position;
// balls tangent to one circle tie at its centre with their n_k on one circle, where every triple ties to
// first order along the circle's axis and only the second-order star (over the lifts) separates them.
void check_star_of_largest_tie(Site_family family, std::size_t n, std::size_t at_least_tied) {
  const std::vector<Site> sites = generate_sites(family, n, 2);
  const std::string name = std::string(name_of(family)) + " " + std::to_string(n) + " seed 2";
  INFO(name);
  Input_time_limit limit(seconds_from_environment("APOLLONIUS_DIFFERENTIAL_TIME_LIMIT", 60), name);
  const Diagram diagram = octree_diagram(sites, Octree_options{});
  const auto largest = largest_tie(diagram);
  REQUIRE(largest != diagram.vertices.end());
  const std::size_t k = largest->tie_set.size();
  CHECK(k >= at_least_tied);
  std::vector<std::array<Site_index, 3>> offered;
  REQUIRE(candidate_departure_triples(sites, *largest, offered));
  CHECK(offered.size() <= 64 * k);
  const std::vector<std::array<Site_index, 3>> departures = departing_triples(sites, *largest);
  CHECK(departures.size() >= k / 2);
  for (const std::array<Site_index, 3>& t : departures) CHECK(std::binary_search(offered.begin(), offered.end(), t));
  const std::vector<Diagram_edge> every =
      edges_through_vertices(sites, diagram, Vertex_triples(sites, diagram, nullptr, kEveryTriple), 1);
  const std::vector<Diagram_edge> starred = edges_through_vertices(sites, diagram, Vertex_triples(sites, diagram), 1);
  REQUIRE(starred.size() == every.size());
  for (std::size_t e = 0; e < every.size(); ++e) CHECK(same(starred[e], every[e]));
  MESSAGE(name << ": " << k << " tied sites, " << offered.size() << " triples offered, " << departures.size()
               << " departures");
}

TEST_CASE("the star of a vertex of a hundred and twenty tied sites") {
  check_star_of_largest_tie(Site_family::sphere_tangent, 120, 100);
}

TEST_CASE("the second-order star of a hundred and twenty balls tangent to one circle") {
  check_star_of_largest_tie(Site_family::circle_tangent, 120, 100);
}

// Fixed: every triple of every tie set was listed, so the vertex where these 1,000 balls tie (the sphere's
// centre) made C(1000, 3) = 166 million triples: `diagram` took 115 s and 4.7 GB. Its star offers 4,000 or so.
TEST_CASE("regression: diagram_triples_blowup_sphere_tangent_1000_2") {
  const std::vector<Site> sites = generate_sites(Site_family::sphere_tangent, 1000, 2);
  const double seconds = seconds_from_environment("APOLLONIUS_DIFFERENTIAL_TIME_LIMIT", 60);
  Input_time_limit limit(seconds, "sphere-tangent 1000 seed 2");
  Octree_regions regions;
  Octree_options options;
  options.regions = &regions;
  const Diagram_topology topology = build_topology(sites, octree_diagram(sites, options), regions);
  validate_topology(sites, topology);
  std::size_t largest = 0;
  for (const Diagram_vertex& v : topology.vertices.vertices) largest = std::max(largest, v.tie_set.size());
  CHECK(largest == 1000);
  // The release build's counts, the same as before the star.
  CHECK(topology.vertices.vertices.size() == 1642);
  CHECK(topology.edges.size() == 4621);
  CHECK(topology.faces.size() == 3978);
  CHECK(topology.cells.size() == 1000);
}

// departures_along with v's enclosures (gradients and lifts) against departures_along with neither, on
// every triple the star offers at the vertex where 120 balls tangent to one circle tie. Their n_k lie on one
// circle, so every first order is 0: the lifts' second order decides most sites without a predicate.
TEST_CASE("the enclosures' second order at a vertex of balls tangent to one circle agrees with the predicate") {
  const std::vector<Site> sites = generate_sites(Site_family::circle_tangent, 120, 2);
  Input_time_limit limit(seconds_from_environment("APOLLONIUS_DIFFERENTIAL_TIME_LIMIT", 60), "circle-tangent 120 seed 2");
  const Diagram diagram = octree_diagram(sites, Octree_options{});
  REQUIRE(largest_tie(diagram) != diagram.vertices.end());
  const Diagram_vertex& v = *largest_tie(diagram);
  const std::size_t k = v.tie_set.size();
  REQUIRE(k >= 100);
  Tie_gradients gradients;
  std::vector<Interval> lifts;
  REQUIRE(tie_gradients(sites, v, gradients, &lifts));
  std::vector<std::array<Site_index, 3>> offered;
  REQUIRE(candidate_departure_triples(sites, v, offered));
  const auto same_departures = [](const std::vector<Departure>& x, const std::vector<Departure>& y) {
    if (x.size() != y.size()) return false;
    for (std::size_t d = 0; d < x.size(); ++d)
      if (x[d].triple != y[d].triple || x[d].tie_set != y[d].tie_set || x[d].direction != y[d].direction) return false;
    return true;
  };
  const auto sides_predicates = [] {
    for (const Predicate_statistics& p : predicate_statistics())
      if (p.name == "sides_near_vertex") return p.evaluations;
    return std::uint64_t{0};
  };
  std::uint64_t with_enclosures = 0, without = 0;
  std::size_t departing = 0;
  std::vector<Departure> enclosed, plain;
  for (const std::array<Site_index, 3>& triple : offered) {
    std::array<std::size_t, 3> positions{};
    for (int m = 0; m < 3; ++m)
      positions[m] = static_cast<std::size_t>(std::lower_bound(v.tie_set.begin(), v.tie_set.end(), triple[m]) - v.tie_set.begin());
    const Trisector trisector(triple, {sites[triple[0]], sites[triple[1]], sites[triple[2]]});
    enclosed.clear();
    plain.clear();
    std::uint64_t before = sides_predicates();
    departures_along(sites, v, trisector, positions, enclosed, &gradients, &lifts);
    with_enclosures += sides_predicates() - before;
    before = sides_predicates();
    departures_along(sites, v, trisector, positions, plain);
    without += sides_predicates() - before;
    CAPTURE(triple[0]);
    CAPTURE(triple[1]);
    CAPTURE(triple[2]);
    CHECK(same_departures(enclosed, plain));
    departing += !plain.empty();
  }
  MESSAGE(k << " tied sites, " << offered.size() << " triples, " << departing << " departing; sides_near_vertex "
            << with_enclosures << " times with the enclosures, " << without << " without");
  CHECK(departing >= k / 2);
  // Without them each departing triple asks about all k - 3 other sites; with them only where the second
  // order is uncertain or 0.
  CHECK(without >= departing * (k - 3));
  CHECK(with_enclosures * 10 < without);
}
