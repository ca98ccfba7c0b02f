#include "io/write_topology.h"

#include "io/json_output.h"
#include "topology/topology_tie_sets.h"

namespace apollonius {
namespace {

Json end_json(const std::optional<std::size_t>& v) { return v ? Json(*v) : Json(nullptr); }

}  // namespace

void write_diagram_json(std::ostream& out, const Diagram_topology& t, const std::vector<Predicate_statistics>* stats) {
  Json document{{"format", "apollonius3d-diagram"}, {"version", 1}, {"sites", t.vertices.site_count}};
  Json& vertices = document["vertices"] = Json::array();
  for (std::size_t v = 0; v < t.vertices.vertices.size(); ++v) {
    const Diagram_vertex& vertex = t.vertices.vertices[v];
    Json point = Json::array();
    for (double x : vertex.rounded) point.push_back(json_number(x));
    vertices.push_back({{"id", v}, {"sites", vertex.tie_set}, {"point", point}});
  }
  Json& edges = document["edges"] = Json::array();
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    const Diagram_edge& edge = t.edges[e];
    // [v, w]; [v, null] with one end at infinity; [null, null] infinite both ways; [] closed.
    Json ends = Json::array();
    if (!edge.closed) {
      if (edge.start && edge.end) {
        ends = {*edge.start, *edge.end};
      } else if (edge.start || edge.end) {
        ends = {end_json(edge.start ? edge.start : edge.end), nullptr};
      } else {
        ends = {nullptr, nullptr};
      }
    }
    edges.push_back({{"id", e}, {"sites", edge.tie_set}, {"ends", ends}, {"curve", to_string(edge.curve)}});
  }
  Json& faces = document["faces"] = Json::array();
  for (std::size_t f = 0; f < t.faces.size(); ++f) {
    const Diagram_face& face = t.faces[f];
    faces.push_back({{"id", f}, {"sites", {face.a, face.b}}, {"boundary", face.boundary}, {"bounded", face.bounded}});
  }
  Json& cells = document["cells"] = Json::array();
  for (const Diagram_cell& c : t.cells) cells.push_back({{"site", c.site}, {"faces", c.faces}, {"bounded", c.bounded}});
  Json& hidden = document["hidden_sites"] = Json::array();
  for (const Hidden_site& h : t.vertices.hidden)
    hidden.push_back({{"site", h.site}, {"hidden_by", h.hidden_by}, {"duplicate", h.duplicate}});
  if (stats != nullptr) {
    Json predicates = Json::array();
    for (const Predicate_statistics& s : *stats)
      predicates.push_back({{"name", s.name}, {"evaluations", s.evaluations}, {"exact_stages", s.exact_stages}});
    document["stats"] = {{"predicates", predicates}};
  }
  write_json_document(out, document);
}

void write_diagram_topology(std::ostream& out, const Diagram_topology& t) {
  const Topology_tie_sets sets = topology_tie_sets(t);
  Json document{{"bisectors", sets.bisectors}, {"trisectors", sets.trisectors}, {"quadrisectors", sets.quadrisectors}};
  write_json_document(out, document);
}

}  // namespace apollonius
