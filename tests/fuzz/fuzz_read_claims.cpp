// libFuzzer target: arbitrary bytes as a certify CLAIM, read by every claim reader (claimed_vertices.h in
// each format, claimed_topology.h) for an input of 9 sites. The readers' contract: a result whose
// invariants hold, or Input_error. Any other exception, a crash or a sanitizer report is a bug; so is a
// claim that breaks its invariant (a site out of range or repeated, a link past the list).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include "certify/claimed_topology.h"
#include "certify/claimed_vertices.h"
#include "io/input_error.h"

namespace {

constexpr std::size_t kSites = 9;  // the seeds' input, vdrc ANO3_3CONNECT

void check(const std::vector<apollonius::Site_index>& sites, std::size_t least) {
  if (sites.size() < least || !std::is_sorted(sites.begin(), sites.end()) ||
      std::adjacent_find(sites.begin(), sites.end()) != sites.end() || sites.back() >= kSites)
    __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace apollonius;
  const std::string content(reinterpret_cast<const char*>(data), size);
  for (const Claim_format format : {Claim_format::text, Claim_format::json, Claim_format::voronota}) {
    try {
      const Claimed_vertex_list list = read_claimed_vertices(content, "fuzz", format, kSites);
      for (const Claimed_vertex& claim : list.vertices) {
        check(claim.sites, 4);
        if (claim.links)
          for (const long long link : *claim.links)
            if (link < -1 || (link >= 0 && static_cast<std::size_t>(link) >= list.vertices.size())) __builtin_trap();
      }
    } catch (const Input_error&) {
    }
  }
  try {
    const Claimed_topology topology = read_claimed_topology(content, "fuzz", kSites);
    for (std::size_t c = 0; c < 3; ++c)
      for (const Claimed_set& set : topology.categories[c].sets) check(set.sites, c + 2);
  } catch (const Input_error&) {
  }
  (void)detect_claim_format(content);
  return 0;
}
