#include "octree/leaf_decision.h"

#include <algorithm>

#include "predicates/kernels.h"

namespace apollonius {
namespace {

// The tie set of v among `owners`, or false if one of them is strictly closer.
template <class Kernel>
bool tie_set_among(const Vertex& v, const std::vector<Site>& sites, const std::vector<Site_index>& owners,
                   std::vector<Site_index>& tie) {
  const auto& own = v.sites();
  tie.assign(own.begin(), own.end());
  for (Site_index s : owners) {
    if (std::find(own.begin(), own.end(), s) != own.end()) continue;
    const Sign sign = Kernel::conflict(v, sites[s]);
    if (sign == Sign::NEGATIVE) return false;
    if (sign == Sign::ZERO) tie.push_back(s);
  }
  std::sort(tie.begin(), tie.end());
  return true;
}

}  // namespace

template <class Kernel>
void append_unique(std::vector<Found_vertex>& out, std::size_t first, Found_vertex found) {
  const bool seen = std::any_of(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(), [&](const Found_vertex& f) {
    return f.tie_set == found.tie_set && Kernel::compare(f.vertex, found.vertex) == Sign::ZERO;
  });
  if (seen) return;
  out.push_back(std::move(found));
  settle<Kernel>(out.back());
}

template <class Kernel>
void decide_quadruples(const std::vector<Site>& sites, const std::vector<Site_index>& candidates,
                       const std::vector<Site_index>& owners, const std::function<bool(const Vertex&)>& located,
                       std::vector<Found_vertex>& out, std::size_t first) {
  const std::size_t k = candidates.size();
  std::vector<Site_index> tie;
  for (std::size_t a = 0; a < k; ++a)
    for (std::size_t b = a + 1; b < k; ++b)
      for (std::size_t c = b + 1; c < k; ++c)
        for (std::size_t d = c + 1; d < k; ++d) {
          const Quadruple q = make_quadruple({candidates[a], candidates[b], candidates[c], candidates[d]}, sites);
          for (const Vertex& v : Kernel::vertices_of_quadruple(q).vertices)
            if (located(v) && tie_set_among<Kernel>(v, sites, owners, tie)) append_unique<Kernel>(out, first, {tie, v});
        }
}

namespace {

// Whether two vertices certainly differ: their interval enclosures are disjoint.
bool certainly_apart(const Vertex& u, const Vertex& v) {
  const std::array<Interval, 4> a = u.point_interval(), b = v.point_interval();
  for (int j = 0; j < 4; ++j)
    if (a[j].sup() < b[j].inf() || b[j].sup() < a[j].inf()) return true;
  return false;
}

}  // namespace

template <class Kernel>
std::size_t root_equal_to(const Vertex& u, const Quadruple_vertices& roots) {
  if (roots.vertices.size() <= 1) return 0;
  if (certainly_apart(roots.vertices[0], u)) return 1;
  if (certainly_apart(roots.vertices[1], u)) return 0;
  return Kernel::compare(roots.vertices[0], u) == Sign::ZERO ? 0 : 1;
}

template void decide_quadruples<Certified_kernel>(const std::vector<Site>&, const std::vector<Site_index>&,
                                                  const std::vector<Site_index>&, const std::function<bool(const Vertex&)>&,
                                                  std::vector<Found_vertex>&, std::size_t);
template void decide_quadruples<Floating_kernel>(const std::vector<Site>&, const std::vector<Site_index>&,
                                                 const std::vector<Site_index>&, const std::function<bool(const Vertex&)>&,
                                                 std::vector<Found_vertex>&, std::size_t);
template void append_unique<Certified_kernel>(std::vector<Found_vertex>&, std::size_t, Found_vertex);
template void append_unique<Floating_kernel>(std::vector<Found_vertex>&, std::size_t, Found_vertex);

template std::size_t root_equal_to<Certified_kernel>(const Vertex&, const Quadruple_vertices&);
template std::size_t root_equal_to<Floating_kernel>(const Vertex&, const Quadruple_vertices&);

}  // namespace apollonius
