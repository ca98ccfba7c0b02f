#include "diagram/site_set.h"

#include <algorithm>
#include <numeric>

#include "predicates/kernels.h"
#include "predicates/rounding_guard.h"

namespace apollonius {

template <class Kernel>
std::vector<Hidden_site> classify_hidden_sites(const std::vector<Site>& sites, const Cancellation* cancellation) {
  const std::size_t n = sites.size();
  std::vector<Hidden_site> hidden;
  if (n < 2) return hidden;
  // Ball i can only lie in ball j if |x_i - x_j| <= w_j - w_i <= max w - min w: after sorting by x, a sweep
  // visits only the pairs whose x gap is not certainly larger than the weight range.
  std::vector<Site_index> by_x(n);
  std::iota(by_x.begin(), by_x.end(), Site_index{0});
  std::sort(by_x.begin(), by_x.end(), [&](Site_index a, Site_index b) { return sites[a].x < sites[b].x; });
  const auto [lightest, heaviest] =
      std::minmax_element(sites.begin(), sites.end(), [](const Site& a, const Site& b) { return a.w < b.w; });
  double weight_range;  // a double >= max w - min w
  {
    Rounding_guard guard;
    weight_range = (Interval(heaviest->w) - Interval(lightest->w)).sup();
  }
  // Rounding to nearest is monotone and keeps doubles: a rounded x gap above weight_range is above it exactly.
  auto certainly_apart = [&](Site_index left, Site_index right) {
    return sites[right].x - sites[left].x > weight_range;
  };

  std::vector<Hidden_site> by_site(n, Hidden_site{0, 0, false});
  std::vector<bool> is_hidden_site(n, false);
  auto record = [&](Site_index i, Site_index j) {
    const bool duplicate = sites[i] == sites[j];
    Hidden_site& h = by_site[i];
    // Prefer a duplicate over a containing ball, then the smallest index.
    if (!is_hidden_site[i] || (duplicate && !h.duplicate) || (duplicate == h.duplicate && j < h.hidden_by))
      h = Hidden_site{i, j, duplicate};
    is_hidden_site[i] = true;
  };
  for (std::size_t a = 0; a < n; ++a) {
    throw_if_cancelled(cancellation);
    for (std::size_t b = a + 1; b < n && !certainly_apart(by_x[a], by_x[b]); ++b) {
      const Site_index i = by_x[a], j = by_x[b];
      if (Kernel::hidden(sites[i], i, sites[j], j)) record(i, j);
      if (Kernel::hidden(sites[j], j, sites[i], i)) record(j, i);
    }
  }
  for (Site_index i = 0; i < n; ++i)
    if (is_hidden_site[i]) hidden.push_back(by_site[i]);
  return hidden;
}

template std::vector<Hidden_site> classify_hidden_sites<Certified_kernel>(const std::vector<Site>&, const Cancellation*);
template std::vector<Hidden_site> classify_hidden_sites<Floating_kernel>(const std::vector<Site>&, const Cancellation*);

std::vector<Site_index> active_sites(std::size_t site_count, const std::vector<Hidden_site>& hidden) {
  std::vector<bool> is_hidden_site(site_count, false);
  for (const Hidden_site& h : hidden) is_hidden_site[h.site] = true;
  std::vector<Site_index> active;
  for (Site_index i = 0; i < site_count; ++i)
    if (!is_hidden_site[i]) active.push_back(i);
  return active;
}

}  // namespace apollonius
