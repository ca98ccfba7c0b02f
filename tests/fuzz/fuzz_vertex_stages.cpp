// libFuzzer target: the staged vertex predicates against their exact stage alone. A small site set decoded
// from the bytes; for every quadruple, vertices_of's double-double stage and its conditioned line (where
// they answer) against its exact evaluation, and for every vertex, the ball stages of vertex_conflict
// (against every site) and vertex_in_box (against bounds on, next to and a few ulps from each rounded
// coordinate) and the rounding sides against exact comparisons. Any difference prints the input's
// quadruple and traps. The octree and the brute force share these predicates, so fuzz_vertices cannot see
// such an error; this target can.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <vector>

#include "fuzz/fuzz_sites.h"
#include "io/write_sites.h"
#include "predicates/rounding_guard.h"
#include "predicates/vertex_conflict.h"
#include "predicates/vertex_in_box.h"
#include "predicates/vertex_rounding.h"
#include "predicates/vertices_of.h"

namespace {

using namespace apollonius;

[[noreturn]] void report(const char* what, const Quadruple& q) {
  std::cerr << "fuzz_vertex_stages: " << what << " for the quadruple " << q.indices[0] << " " << q.indices[1] << " "
            << q.indices[2] << " " << q.indices[3] << "\n";
  std::abort();
}

Root_number<Exact> dyadic(double x) { return {Exact(x), Exact(0), Exact(0), Exact(1)}; }

void check_vertex(const Vertex& v, const std::vector<Site>& sites) {
  for (const Site& s : sites)
    if (const std::optional<Sign> fast = Vertex_conflict_predicate::ball_stage(v, s))
      if (*fast != Vertex_conflict_predicate::evaluate<Exact>(v, s)) report("vertex_conflict's ball stage differs", v.quadruple());
  const std::array<Root_number<Exact>, 4> p = exact_point(v);
  const std::array<double, 4>& rounded = v.rounded();
  for (int axis = 0; axis < 3; ++axis) {
    if (!std::isfinite(rounded[axis])) continue;
    if (v.rounding_sides()[axis] != compare(p[axis], dyadic(rounded[axis]))) report("a rounding side differs", v.quadruple());
    double below = rounded[axis], above = rounded[axis];
    for (int step = 0; step < 3; ++step) {
      for (const double bound : {below, above}) {
        Axis_box box{{-INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}};
        for (const bool upper : {false, true}) {
          (upper ? box.hi : box.lo)[axis] = bound;
          if (const std::optional<bool> fast = Vertex_in_box_predicate::ball_stage(v, box, {false, false, false}))
            if (*fast != Vertex_in_box_predicate::evaluate<Exact>(v, box, {false, false, false}))
              report("vertex_in_box's ball stage differs", v.quadruple());
          (upper ? box.hi : box.lo)[axis] = upper ? INFINITY : -INFINITY;
        }
      }
      below = std::nextafter(below, -INFINITY), above = std::nextafter(above, INFINITY);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<Site> sites;
  if (!apollonius::fuzzing::decode_sites(data, size, sites)) return -1;
  static const bool print_sites = std::getenv("APOLLONIUS_FUZZ_PRINT_SITES") != nullptr;
  if (print_sites) {
    apollonius::write_sites_text(std::cout, sites, "fuzz_vertex_stages input");
    std::cout.flush();
  }
  const std::size_t n = sites.size();
  for (Site_index a = 0; a < n; ++a)
    for (Site_index b = a + 1; b < n; ++b)
      for (Site_index c = b + 1; c < n; ++c)
        for (Site_index d = c + 1; d < n; ++d) {
          const Quadruple q = make_quadruple({a, b, c, d}, sites);
          const Quadruple_vertices exact = Vertices_of_predicate::evaluate<Exact>(q);
          // A filter stage's answer, where it gives one, against the exact stage: flags, roots and boxes.
          const auto check_stage = [&](const std::optional<Quadruple_vertices>& stage, const char* differs,
                                       const char* root_differs, const char* box_misses) {
            if (!stage) return;
            if (stage->rank_deficient != exact.rank_deficient || stage->equidistant_curve != exact.equidistant_curve ||
                stage->vertices.size() != exact.vertices.size())
              report(differs, q);
            for (std::size_t k = 0; k < exact.vertices.size(); ++k) {
              if (stage->vertices[k].root() != exact.vertices[k].root()) report(root_differs, q);
              const Interval box_x = stage->vertices[k].coordinates<Interval>().scaled[0];
              const Vertex_coordinates<Exact>& X = exact.vertices[k].coordinates<Exact>();
              const Root_number<Exact> x{X.scaled[0].a, X.scaled[0].b, X.discriminant, X.denominator};
              if (compare(dyadic(box_x.inf()), x) == Sign::POSITIVE || compare(x, dyadic(box_x.sup())) == Sign::POSITIVE)
                report(box_misses, q);
            }
          };
          check_stage(vertices_from_balls(q), "vertices_of's ball stage differs", "a ball vertex's root differs",
                      "a ball vertex's box misses it");
          std::optional<Quadruple_vertices> conditioned;
          {
            const Rounding_guard guard;
            conditioned = Vertices_of_predicate::conditioned_vertices(q);
          }
          check_stage(conditioned, "vertices_of's conditioned line differs", "a conditioned vertex's root differs",
                      "a conditioned vertex's box misses it");
          for (const Vertex& v : exact.vertices) check_vertex(v, sites);
        }
  return 0;
}
