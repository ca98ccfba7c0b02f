#include "io/write_vertices.h"

#include <charconv>
#include <string>

#include "io/json_output.h"
#include "io/round_trip.h"

namespace apollonius {

void write_vertices_text(std::ostream& out, const Diagram& diagram) {
  std::string text;
  char number[32];
  for (const Diagram_vertex& v : diagram.vertices) {
    for (const Site_index site : v.tie_set) {
      text.append(number, std::to_chars(number, number + sizeof number, site).ptr);
      text += ' ';
    }
    for (int j = 0; j < 4; ++j) {
      text.append(number, write_round_trip(number, v.rounded[j]));
      text += j < 3 ? ' ' : '\n';
    }
    if (text.size() > (1u << 16)) {  // written in chunks
      out << text;
      text.clear();
    }
  }
  out << text;
}

void write_vertices_json(std::ostream& out, const Diagram& diagram, const std::vector<Predicate_statistics>* stats) {
  out << "{\n  \"format\": \"apollonius3d-vertices\",\n  \"version\": 1,\n  \"sites\": " << diagram.site_count
      << ",\n  \"vertices\": ";
  write_json_lines(out, diagram.vertices.size(), [&](std::size_t i) {
    const Diagram_vertex& v = diagram.vertices[i];
    return "{\"sites\": " + json_array(v.tie_set) + ", " + json_point_members(v.rounded) + "}";
  });
  out << ",\n  \"hidden_sites\": ";
  write_json_lines(out, diagram.hidden.size(), [&](std::size_t i) {
    const Hidden_site& h = diagram.hidden[i];
    return "{\"site\": " + std::to_string(h.site) + ", \"hidden_by\": " + std::to_string(h.hidden_by) +
           ", \"duplicate\": " + (h.duplicate ? "true" : "false") + "}";
  });
  out << ",\n  \"sites_without_vertex\": " << json_array(diagram.sites_without_vertex);
  if (stats != nullptr) {
    out << ",\n  \"stats\": {\"predicates\": ";
    write_json_lines(out, stats->size(), [&](std::size_t i) {
      const Predicate_statistics& s = (*stats)[i];
      return "{\"name\": " + json_string(s.name) + ", \"evaluations\": " + std::to_string(s.evaluations) +
             ", \"exact_stages\": " + std::to_string(s.exact_stages) + "}";
    });
    out << "}";
  }
  out << "\n}\n";
}

}  // namespace apollonius
