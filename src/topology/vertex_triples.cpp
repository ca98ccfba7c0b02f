#include "topology/vertex_triples.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

namespace apollonius {
namespace {

Flat_lists<Vertex_triple> sorted_by_first_site(std::size_t site_count, const Diagram& diagram,
                                               const Cancellation* cancellation) {
  if (diagram.vertices.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("vertex triples: more than 2^32 vertices");
  // Written straight into buckets by smallest site (a counting pass first), then each bucket sorted: small
  // entries, one pass over fresh memory.
  Flat_lists<Vertex_triple> lists(
      site_count,
      [&](auto emit) {
        for (std::size_t v = 0; v < diagram.vertices.size(); ++v) {
          const std::vector<Site_index>& tie = diagram.vertices[v].tie_set;
          for (std::size_t i = 0; i < tie.size(); ++i)
            for (std::size_t j = i + 1; j < tie.size(); ++j)
              for (std::size_t l = j + 1; l < tie.size(); ++l)
                emit(tie[i], Vertex_triple{{tie[i], tie[j], tie[l]}, static_cast<std::uint32_t>(v)});
        }
      },
      cancellation);
  for (std::size_t s = 0; s < site_count; ++s) {
    if (s % 4096 == 0) throw_if_cancelled(cancellation);
    const auto bucket = lists[s];
    // One bucket shares its first site: the rest of (triple, vertex) as two 64-bit keys.
    const auto key = [](const Vertex_triple& x) {
      return std::pair{std::uint64_t{x.triple[1]} << 32 | x.triple[2], x.vertex};
    };
    std::sort(bucket.begin(), bucket.end(),
              [&](const Vertex_triple& x, const Vertex_triple& y) { return key(x) < key(y); });
  }
  return lists;
}

}  // namespace

Vertex_triples::Vertex_triples(std::size_t site_count, const Diagram& diagram, const Cancellation* cancellation)
    : by_first_site_(sorted_by_first_site(site_count, diagram, cancellation)) {}

bool Vertex_triples::contains(const std::array<Site_index, 3>& triple) const {
  const auto bucket = by_first_site_[triple[0]];
  const auto before = [](const Vertex_triple& x, const std::array<Site_index, 3>& t) { return x.triple < t; };
  const auto at = std::lower_bound(bucket.begin(), bucket.end(), triple, before);
  return at != bucket.end() && at->triple == triple;
}

}  // namespace apollonius
