#include "certify/equidistant_points.h"

#include <algorithm>
#include <optional>

#include "predicates/vertex_conflict.h"
#include "predicates/vertices_of.h"

namespace apollonius {
namespace {

// The points of quadruple q ⊆ set that tie with every site of set, or nothing if q's equidistant set is
// not discrete.
std::optional<Equidistant_points> points_from_quadruple(const Quadruple& q, const std::vector<Site_index>& set,
                                                         const std::vector<Site>& sites) {
  const Quadruple_vertices roots = vertices_of(q);
  if (roots.rank_deficient || roots.equidistant_curve) return std::nullopt;
  using Status = Equidistant_points::Status;
  if (roots.vertices.empty()) return Equidistant_points{Status::no_valid_root, {}};
  Equidistant_points result{Status::isolated, {}};
  for (const Vertex& p : roots.vertices) {
    const bool ties_with_all = std::all_of(set.begin(), set.end(), [&](Site_index s) {
      const auto& own = q.indices;
      return std::find(own.begin(), own.end(), s) != own.end() || vertex_conflict(p, sites[s]) == Sign::ZERO;
    });
    if (ties_with_all) result.points.push_back(p);
  }
  if (result.points.empty()) result.status = Status::not_equidistant;
  return result;
}

}  // namespace

Equidistant_points equidistant_points(const std::vector<Site_index>& set, const std::vector<Site>& sites) {
  const std::size_t k = set.size();
  for (std::size_t a = 0; a < k; ++a)
    for (std::size_t b = a + 1; b < k; ++b)
      for (std::size_t c = b + 1; c < k; ++c)
        for (std::size_t d = c + 1; d < k; ++d)
          if (auto points = points_from_quadruple(make_quadruple({set[a], set[b], set[c], set[d]}, sites), set, sites))
            return std::move(*points);
  return {Equidistant_points::Status::rank_deficient, {}};
}

}  // namespace apollonius
