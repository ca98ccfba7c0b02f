// Reading the target masses of `apollonius3d centroidal` (docs/contract.md): one number per line, the
// fraction of the domain's volume that the cell of the site of the same rank should hold; `#` starts a
// comment. Every failure is an Input_error naming the file, the 1-based line (0 for the whole file) and
// the reason.
#pragma once

#include <string>
#include <vector>

namespace apollonius {

// The masses of `path` ("-" for standard input) for site_count sites: each a positive finite number, as
// many as there are sites, summing to 1 within 1e-9.
std::vector<double> read_masses(const std::string& path, std::size_t site_count);

// The same for content already in memory; name is used in messages.
std::vector<double> read_masses_from_text(const std::string& content, const std::string& name, std::size_t site_count);

// How far from 1 the masses may sum: decimal fractions printed with 10 or more digits pass.
inline constexpr double kMassSumTolerance = 1e-9;

}  // namespace apollonius
