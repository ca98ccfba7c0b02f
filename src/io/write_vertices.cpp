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
