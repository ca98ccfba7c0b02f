// Sites as balls text (docs/contract.md), what the balls reader reads back as the same doubles in the same
// order.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "predicates/site.h"

namespace apollonius {

// An optional `# comment` line, then one `x y z w` line per site, each number printed round-trip.
// Precondition: every value is finite and comment holds no line break.
void write_sites_text(std::ostream& out, const std::vector<Site>& sites, const std::string& comment);

}  // namespace apollonius
