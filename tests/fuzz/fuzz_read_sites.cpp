// libFuzzer target: arbitrary bytes as an input file, format detected by content (balls, vdrc, PDB or
// mmCIF through gemmi). The reader's contract (io/read_sites.h, docs/contract.md): it returns at least one
// site, every value finite, or it throws Input_error. Any other exception, a crash or a sanitizer report
// is a bug; so is a non-finite value, which the CLI would then hand to the algorithms.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/input_error.h"
#include "io/read_sites.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string content(reinterpret_cast<const char*>(data), size);
  apollonius::Site_input input;
  try {
    input = apollonius::read_sites_from_text(content, "fuzz", {});
  } catch (const apollonius::Input_error&) {
    return 0;
  }
  if (input.sites.empty()) __builtin_trap();
  for (const apollonius::Site& s : input.sites)
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z) || !std::isfinite(s.w)) __builtin_trap();
  return 0;
}
