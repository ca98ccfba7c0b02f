#include "io/write_topology.h"

#include "io/json_stream.h"
#include "topology/topology_tie_sets.h"

namespace apollonius {
namespace {

void end_or_null(Json_stream& json, const std::optional<std::size_t>& v) { v ? json.unsigned_number(*v) : json.null(); }

// A top-level member whose value is a list of sets, one per line.
void sets_member(Json_stream& json, std::string_view key, const std::vector<std::vector<Site_index>>& sets) {
  json.member(key);
  json.begin_lines();
  for (const std::vector<Site_index>& set : sets) {
    json.line();
    json.array_of(set);
  }
  json.end_lines();
}

}  // namespace

void write_diagram_json(std::ostream& out, const Diagram_topology& t, const std::vector<Predicate_statistics>* stats) {
  Json_stream json(out);
  json.member("format");
  json.string("apollonius3d-diagram");
  json.member("version");
  json.integer(1);
  json.member("sites");
  json.unsigned_number(t.vertices.site_count);
  json.member("vertices");
  json.begin_lines();
  for (std::size_t v = 0; v < t.vertices.vertices.size(); ++v) {
    const Diagram_vertex& vertex = t.vertices.vertices[v];
    json.line();
    json.begin_object();
    json.key("id");
    json.unsigned_number(v);
    json.key("sites");
    json.array_of(vertex.tie_set);
    json.key("point");
    json.begin_array();
    for (double x : vertex.rounded) json.number_or_infinity(x);
    json.end_array();
    json.end_object();
  }
  json.end_lines();
  json.member("edges");
  json.begin_lines();
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    const Diagram_edge& edge = t.edges[e];
    json.line();
    json.begin_object();
    json.key("id");
    json.unsigned_number(e);
    json.key("sites");
    json.array_of(edge.tie_set);
    // [v, w]; [v, null] with one end at infinity; [null, null] infinite both ways; [] closed.
    json.key("ends");
    json.begin_array();
    if (!edge.closed) {
      if (edge.start && edge.end) {
        json.unsigned_number(*edge.start);
        json.unsigned_number(*edge.end);
      } else {
        end_or_null(json, edge.start ? edge.start : edge.end);
        json.null();
      }
    }
    json.end_array();
    json.key("curve");
    json.string(to_string(edge.curve));
    json.end_object();
  }
  json.end_lines();
  json.member("faces");
  json.begin_lines();
  for (std::size_t f = 0; f < t.faces.size(); ++f) {
    const Diagram_face& face = t.faces[f];
    json.line();
    json.begin_object();
    json.key("id");
    json.unsigned_number(f);
    json.key("sites");
    json.begin_array();
    json.unsigned_number(face.a);
    json.unsigned_number(face.b);
    json.end_array();
    json.key("boundary");
    json.begin_array();
    for (const std::vector<std::size_t>& component : face.boundary) json.array_of(component);
    json.end_array();
    json.key("bounded");
    json.boolean(face.bounded);
    json.end_object();
  }
  json.end_lines();
  json.member("cells");
  json.begin_lines();
  for (const Diagram_cell& c : t.cells) {
    json.line();
    json.begin_object();
    json.key("site");
    json.unsigned_number(c.site);
    json.key("faces");
    json.array_of(c.faces);
    json.key("bounded");
    json.boolean(c.bounded);
    json.end_object();
  }
  json.end_lines();
  json.member("hidden_sites");
  json.begin_lines();
  for (const Hidden_site& h : t.vertices.hidden) {
    json.line();
    json.begin_object();
    json.key("site");
    json.unsigned_number(h.site);
    json.key("hidden_by");
    json.unsigned_number(h.hidden_by);
    json.key("duplicate");
    json.boolean(h.duplicate);
    json.end_object();
  }
  json.end_lines();
  if (stats != nullptr) {
    json.member("stats");
    json.begin_object();
    json.key("predicates");
    json.begin_array();
    for (const Predicate_statistics& s : *stats) {
      json.begin_object();
      json.key("name");
      json.string(s.name);
      json.key("evaluations");
      json.unsigned_number(s.evaluations);
      json.key("exact_stages");
      json.unsigned_number(s.exact_stages);
      json.end_object();
    }
    json.end_array();
    json.end_object();
  }
  json.finish();
}

void write_diagram_topology(std::ostream& out, const Diagram_topology& t) {
  const Topology_tie_sets sets = topology_tie_sets(t);
  Json_stream json(out);
  sets_member(json, "bisectors", sets.bisectors);
  sets_member(json, "trisectors", sets.trisectors);
  sets_member(json, "quadrisectors", sets.quadrisectors);
  json.finish();
}

}  // namespace apollonius
