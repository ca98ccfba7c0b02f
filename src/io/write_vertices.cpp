#include "io/write_vertices.h"

#include <algorithm>
#include <charconv>
#include <string>

#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include "diagram/threads.h"
#include "io/json_output.h"
#include "io/round_trip.h"

namespace apollonius {

namespace {

// Vertices per block: about 150 KB of text.
constexpr std::size_t kBlockVertices = 2048;

// Appends the lines of block b of the vertices to text.
void format_block(const std::vector<Diagram_vertex>& vertices, std::size_t b, std::string& text) {
  char number[32];
  for (std::size_t k = b * kBlockVertices; k < std::min(vertices.size(), (b + 1) * kBlockVertices); ++k) {
    const Diagram_vertex& v = vertices[k];
    for (const Site_index site : v.tie_set) {
      text.append(number, std::to_chars(number, number + sizeof number, site).ptr);
      text += ' ';
    }
    for (int j = 0; j < 4; ++j) {
      text.append(number, write_round_trip(number, v.rounded[j]));
      text += j < 3 ? ' ' : '\n';
    }
  }
}

}  // namespace

void write_vertices_text(std::ostream& out, const Diagram& diagram, int threads) {
  const std::vector<Diagram_vertex>& vertices = diagram.vertices;
  const std::size_t blocks = (vertices.size() + kBlockVertices - 1) / kBlockVertices;
  threads = usable_threads(threads);
  if (threads == 1 || blocks <= 1) {
    std::string text;
    for (std::size_t b = 0; b < blocks; ++b) {
      text.clear();
      format_block(vertices, b, text);
      out << text;
    }
    return;
  }
  // Else formatting would be serial after the parallel octree (docs/benchmarks.md). Blocks in flight are
  // bounded (two per thread), so the text held stays a few blocks whatever the diagram's size.
  tbb::task_arena arena(threads);
  arena.execute([&] {
    std::size_t next = 0;
    tbb::parallel_pipeline(
        static_cast<std::size_t>(2 * threads),
        tbb::make_filter<void, std::size_t>(tbb::filter_mode::serial_in_order,
                                            [&](tbb::flow_control& control) -> std::size_t {
                                              if (next == blocks) control.stop();
                                              return next++;
                                            }) &
            tbb::make_filter<std::size_t, std::string>(tbb::filter_mode::parallel,
                                                       [&](std::size_t b) {
                                                         std::string text;
                                                         format_block(vertices, b, text);
                                                         return text;
                                                       }) &
            tbb::make_filter<std::string, void>(tbb::filter_mode::serial_in_order,
                                                [&](const std::string& text) { out << text; }));
  });
}

void write_vertices_json(std::ostream& out, const Diagram& diagram, const std::vector<Predicate_statistics>* stats) {
  Json document{{"format", "apollonius3d-vertices"}, {"version", 1}, {"sites", diagram.site_count}};
  Json& vertices = document["vertices"] = Json::array();
  for (const Diagram_vertex& v : diagram.vertices) {
    Json vertex{{"sites", v.tie_set}};
    add_point_members(vertex, v.rounded);
    vertices.push_back(std::move(vertex));
  }
  Json& hidden = document["hidden_sites"] = Json::array();
  for (const Hidden_site& h : diagram.hidden)
    hidden.push_back({{"site", h.site}, {"hidden_by", h.hidden_by}, {"duplicate", h.duplicate}});
  document["sites_without_vertex"] = diagram.sites_without_vertex;
  if (stats != nullptr) {
    Json predicates = Json::array();
    for (const Predicate_statistics& s : *stats)
      predicates.push_back({{"name", s.name}, {"evaluations", s.evaluations}, {"exact_stages", s.exact_stages}});
    document["stats"] = {{"predicates", predicates}};
  }
  write_json_document(out, document);
}

}  // namespace apollonius
