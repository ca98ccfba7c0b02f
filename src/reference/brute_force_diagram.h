// The reference algorithm: every quadruple of active sites, every valid root, tested against every other
// active site. O(n^5), meant to be read and trusted; every faster algorithm is tested against it.
#pragma once

#include <vector>

#include "diagram/diagram.h"

namespace apollonius {

Diagram brute_force_diagram(const std::vector<Site>& sites);

}  // namespace apollonius
