#include "io/write_vertices.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "io/round_trip.h"

namespace apollonius {

namespace {

std::string json_number(double value) {
  if (std::isfinite(value)) return round_trip(value);
  return "\"" + round_trip(value) + "\"";
}

std::string json_string(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(c));
      quoted += escape;
    } else {
      quoted += c;
    }
  }
  return quoted + "\"";
}

template <class Integers>
std::string json_array(const Integers& values) {
  std::string array = "[";
  for (const auto value : values) {
    if (array.size() > 1) array += ", ";
    array += std::to_string(value);
  }
  return array + "]";
}

// Elements one per line between "[" and "]", separated by commas, element(i) giving the i-th.
template <class Element>
void write_json_lines(std::ostream& out, std::size_t count, const Element& element) {
  out << "[";
  for (std::size_t i = 0; i < count; ++i) out << (i == 0 ? "\n    " : ",\n    ") << element(i);
  out << (count == 0 ? "]" : "\n  ]");
}

}  // namespace

void write_vertices_text(std::ostream& out, const Diagram& diagram) {
  std::string line;
  for (const Diagram_vertex& v : diagram.vertices) {
    line.clear();
    for (const Site_index site : v.tie_set) line += std::to_string(site) + ' ';
    line += round_trip(v.rounded[0]) + ' ' + round_trip(v.rounded[1]) + ' ' + round_trip(v.rounded[2]) + ' ' +
            round_trip(v.rounded[3]) + '\n';
    out << line;
  }
}

void write_vertices_json(std::ostream& out, const Diagram& diagram, const std::vector<Predicate_statistics>* stats) {
  out << "{\n  \"format\": \"apollonius3d-vertices\",\n  \"version\": 1,\n  \"sites\": " << diagram.site_count
      << ",\n  \"vertices\": ";
  write_json_lines(out, diagram.vertices.size(), [&](std::size_t i) {
    const Diagram_vertex& v = diagram.vertices[i];
    return "{\"sites\": " + json_array(v.tie_set) + ", \"x\": " + json_number(v.rounded[0]) +
           ", \"y\": " + json_number(v.rounded[1]) + ", \"z\": " + json_number(v.rounded[2]) +
           ", \"r\": " + json_number(v.rounded[3]) + "}";
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
