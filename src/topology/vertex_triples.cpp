#include "topology/vertex_triples.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

#include "topology/departure_star.h"

namespace apollonius {

Vertex_triples::Vertex_triples(const std::vector<Site>& sites, const Diagram& diagram, const Cancellation* cancellation,
                               std::size_t every_triple_up_to)
    : every_triple_up_to_(every_triple_up_to) {
  const std::size_t site_count = sites.size();
  if (diagram.vertices.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("vertex triples: more than 2^32 vertices");
  // The large tie sets' candidates first: the lists below are emitted twice.
  std::vector<std::uint32_t> starred_vertices;
  std::vector<std::vector<std::array<Site_index, 3>>> star_triples;
  std::vector<std::array<Site_index, 3>> triples;
  for (std::size_t v = 0; v < diagram.vertices.size(); ++v) {
    const Diagram_vertex& vertex = diagram.vertices[v];
    if (vertex.tie_set.size() <= every_triple_up_to) continue;
    throw_if_cancelled(cancellation);
    if (!candidate_departure_triples(sites, vertex, triples)) continue;
    starred_vertices.push_back(static_cast<std::uint32_t>(v));
    star_triples.push_back(std::move(triples));
  }
  starred_by_site_ = Flat_lists<std::uint32_t>(site_count, [&](auto emit) {
    for (std::size_t i = 0; i < starred_vertices.size(); ++i)
      for (const Site_index s : diagram.vertices[starred_vertices[i]].tie_set) emit(s, static_cast<std::uint32_t>(i));
  });
  // Written straight into buckets by smallest site (a counting pass first), then each bucket sorted: small
  // entries, one pass over fresh memory.
  by_first_site_ = Flat_lists<Vertex_triple>(
      site_count,
      [&](auto emit) {
        std::size_t next_starred = 0;
        for (std::size_t v = 0; v < diagram.vertices.size(); ++v) {
          const auto index = static_cast<std::uint32_t>(v);
          if (next_starred < starred_vertices.size() && starred_vertices[next_starred] == index) {
            for (const std::array<Site_index, 3>& t : star_triples[next_starred]) emit(t[0], Vertex_triple{t, index});
            ++next_starred;
            continue;
          }
          const std::vector<Site_index>& tie = diagram.vertices[v].tie_set;
          for (std::size_t i = 0; i < tie.size(); ++i)
            for (std::size_t j = i + 1; j < tie.size(); ++j)
              for (std::size_t l = j + 1; l < tie.size(); ++l)
                emit(tie[i], Vertex_triple{{tie[i], tie[j], tie[l]}, index});
        }
      },
      cancellation);
  for (std::size_t s = 0; s < site_count; ++s) {
    if (s % 4096 == 0) throw_if_cancelled(cancellation);
    const auto bucket = by_first_site_[s];
    // One bucket shares its first site: the rest of (triple, vertex) as two 64-bit keys.
    const auto key = [](const Vertex_triple& x) {
      return std::pair{std::uint64_t{x.triple[1]} << 32 | x.triple[2], x.vertex};
    };
    std::sort(bucket.begin(), bucket.end(),
              [&](const Vertex_triple& x, const Vertex_triple& y) { return key(x) < key(y); });
  }
}

bool Vertex_triples::contains(const std::array<Site_index, 3>& triple) const {
  const auto bucket = by_first_site_[triple[0]];
  const auto before = [](const Vertex_triple& x, const std::array<Site_index, 3>& t) { return x.triple < t; };
  const auto at = std::lower_bound(bucket.begin(), bucket.end(), triple, before);
  if (at != bucket.end() && at->triple == triple) return true;
  // A starred tie set holding all three: common to the three sites' lists (each ascending, nearly always
  // of one entry).
  const auto holds = [&](Site_index s, std::uint32_t i) {
    const auto list = starred_by_site_[s];
    return std::binary_search(list.begin(), list.end(), i);
  };
  for (const std::uint32_t i : starred_by_site_[triple[0]])
    if (holds(triple[1], i) && holds(triple[2], i)) return true;
  return false;
}

}  // namespace apollonius
