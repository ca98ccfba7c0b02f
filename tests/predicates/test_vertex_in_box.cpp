// vertex_in_box's exact stage decides by the correctly rounded coordinates and falls back to Q(sqrt d) only
// when one equals the box bound, once per vertex (rounding_sides); once they are computed, its static filter
// decides by them too, every bound included. Checked against the comparison in Q(sqrt d) alone, for boxes whose bounds
// sit on, next to and a few ulps from every coordinate of every vertex of every generator family, and of
// the regression inputs that made the exact stage slow.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "reference/brute_force_diagram.h"
#include "support/exact_checks.h"
#include "io/read_sites.h"
#include "reference/site_generators.h"
#include "predicates/vertex_in_box.h"
#include "predicates/vertices_of.h"

using namespace apollonius;
using namespace apollonius::testing;

namespace {

// The reference: every bound compared with the exact coordinate in Q(sqrt d).
bool in_box_in_field(const Vertex& v, const Axis_box& box, const std::array<bool, 3>& closed_above) {
  const std::array<Root_number<Exact>, 4> p = exact_point(v);
  for (int a = 0; a < 3; ++a) {
    if (compare_numbers(p[a], box.lo[a]) == Sign::NEGATIVE) return false;
    const Sign above = compare_numbers(p[a], box.hi[a]);
    if (above == Sign::POSITIVE || (above == Sign::ZERO && !closed_above[a])) return false;
  }
  return true;
}

// Doubles on, next to and a few ulps from x (x finite or not), ascending, all finite.
std::vector<double> bounds_near(double x) {
  constexpr double largest = std::numeric_limits<double>::max();
  const double centre = std::isfinite(x) ? x : std::copysign(largest, x);
  std::vector<double> bounds = {centre};
  double below = centre, above = centre;
  for (int step = 0; step < 3; ++step) {
    if (below > -largest) below = std::nextafter(below, -INFINITY), bounds.insert(bounds.begin(), below);
    if (above < largest) above = std::nextafter(above, INFINITY), bounds.push_back(above);
  }
  return bounds;
}

struct Tally {
  std::size_t boxes = 0, inside = 0, on_bound = 0;
};

// Every box whose bounds on each axis are two of bounds_near (lo < hi), around the vertex's rounded point;
// the other axes get the whole double range, so that each axis's bounds are tested on their own.
void check_vertex(const Vertex& v, Tally& tally) {
  const Vertex fresh = [&] {
    for (const Vertex& w : vertices_of(v.quadruple()).vertices)
      if (w.root() == v.root()) return w;
    FAIL("the vertex's root vanished");
    return v;
  }();
  const std::array<double, 4> rounded = exactly_rounded_point(fresh);
  const std::array<Root_number<Exact>, 4> exact = exact_point(fresh);
  constexpr double largest = std::numeric_limits<double>::max();
  for (int axis = 0; axis < 3; ++axis) {
    const std::vector<double> near = bounds_near(rounded[axis]);
    for (std::size_t l = 0; l < near.size(); ++l)
      for (std::size_t h = l + 1; h < near.size(); ++h)
        for (bool closed : {false, true}) {
          Axis_box box{{-largest, -largest, -largest}, {largest, largest, largest}};
          box.lo[axis] = near[l];
          box.hi[axis] = near[h];
          std::array<bool, 3> closed_above = {true, true, true};
          closed_above[axis] = closed;
          const bool expected = in_box_in_field(fresh, box, closed_above);
          CAPTURE(axis);
          CAPTURE(near[l]);
          CAPTURE(near[h]);
          CHECK(Vertex_in_box_predicate::evaluate<Exact>(fresh, box, closed_above) == expected);
          // The filtered predicate: its static filter answers by the rounded point, now computed.
          CHECK(vertex_in_box(fresh, box, closed_above) == expected);
          ++tally.boxes;
          tally.inside += expected;
          tally.on_bound += compare_numbers(exact[axis], near[l]) == Sign::ZERO ||
                            compare_numbers(exact[axis], near[h]) == Sign::ZERO;
        }
  }
}

}  // namespace

TEST_CASE("vertex_in_box by rounded coordinates equals the comparison in Q(sqrt d)") {
  Tally tally;
  for (const std::string& name : site_family_names()) {
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
      CAPTURE(name);
      CAPTURE(seed);
      const std::vector<Site> sites = generate_sites(site_family_from_name(name), 5 + seed % 6, seed);
      for (const Diagram_vertex& v : brute_force_diagram(sites).vertices) check_vertex(v.vertex, tally);
    }
  }
  MESSAGE(tally.boxes << " boxes, " << tally.inside << " containing their vertex, " << tally.on_bound
                      << " with the vertex on a bound");
  CHECK(tally.inside > tally.boxes / 10);
  CHECK(tally.on_bound > 100);  // lattices and symmetric families put vertices exactly on doubles
}

TEST_CASE("vertex_in_box on the inputs whose exact stage was slow") {
  // fuzz_vertices: subnormal coordinates and coordinates near 1e50 among a dozen sites; the interval stage
  // could not place their vertices against the many small boxes near them, and each comparison in
  // Q(sqrt d) took tens of microseconds (5.5 s and 6.6 s for the octree, now well under 2 s).
  Tally tally;
  for (const char* name : {"octree_exact_in_box_slow_for_subnormal_sites.balls", "octree_exact_in_box_slow_for_subnormal_sites_2.balls"}) {
    CAPTURE(name);
    const std::vector<Site> sites = read_sites(std::string(APOLLONIUS_TEST_DATA) + "/regression/" + name, {}).sites;
    for (const Diagram_vertex& v : brute_force_diagram(sites).vertices) check_vertex(v.vertex, tally);
  }
  CHECK(tally.boxes > 0);
}
