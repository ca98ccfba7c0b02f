// Which input sites take part in the diagram: hidden sites and exact duplicates are classified exactly
// (predicate is_hidden) and left out, the others are the active sites.
#pragma once

#include <vector>

#include "diagram/cancellation.h"
#include "diagram/diagram.h"
#include "predicates/site.h"

namespace apollonius {

// Every hidden site, ascending. hidden_by is the first identical earlier site for a duplicate, otherwise
// the smallest index of a site that hides it. Kernel: kernels.h (the certified one, unless for the
// floating path). Checks cancellation (cancellation.h) every 1,024 sites. With threads > 1 the sites are
// classified in parallel, with the same result.
template <class Kernel>
std::vector<Hidden_site> classify_hidden_sites(const std::vector<Site>& sites,
                                               const Cancellation* cancellation = nullptr, int threads = 1);

// The indices of the sites not in `hidden`, ascending.
std::vector<Site_index> active_sites(std::size_t site_count, const std::vector<Hidden_site>& hidden);

}  // namespace apollonius
