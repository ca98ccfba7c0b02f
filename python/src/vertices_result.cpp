#include "vertices_result.h"

#include <algorithm>
#include <string>

#include "compressed_rows.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace apollonius::python {
namespace {

std::string repr(const Vertices_result& r) {
  return "<Vertices: " + std::to_string(r.tie_sets.size()) + " vertices of " + std::to_string(r.site_count) +
         " sites, " + std::to_string(r.hidden.site.size()) + " hidden>";
}

}  // namespace

Hidden_sites hidden_to_python(const std::vector<Hidden_site>& hidden_sites) {
  const py::ssize_t h = static_cast<py::ssize_t>(hidden_sites.size());
  Hidden_sites hidden{py::array_t<std::int64_t>(h), py::array_t<std::int64_t>(h), py::array_t<bool>(h)};
  for (py::ssize_t i = 0; i < h; ++i) {
    const Hidden_site& hs = hidden_sites[static_cast<std::size_t>(i)];
    hidden.site.mutable_at(i) = hs.site;
    hidden.hidden_by.mutable_at(i) = hs.hidden_by;
    hidden.duplicate.mutable_at(i) = hs.duplicate;
  }
  return hidden;
}

Vertices_result vertices_to_python(const Diagram& d, py::object stats) {
  const py::ssize_t m = static_cast<py::ssize_t>(d.vertices.size());
  py::array_t<double> points({m, py::ssize_t{4}});
  double* p = points.mutable_data();
  for (const Diagram_vertex& v : d.vertices) p = std::copy(v.rounded.begin(), v.rounded.end(), p);
  const Compressed_rows tie_sets =
      compressed_rows(d.vertices, [](const Diagram_vertex& v) -> const std::vector<Site_index>& { return v.tie_set; });
  const Hidden_sites hidden = hidden_to_python(d.hidden);
  py::array_t<std::int64_t> without(static_cast<py::ssize_t>(d.sites_without_vertex.size()));
  std::copy(d.sites_without_vertex.begin(), d.sites_without_vertex.end(), without.mutable_data());
  return Vertices_result{d.site_count, points, Tie_sets{tie_sets.offsets, tie_sets.values}, hidden, without,
                         std::move(stats)};
}

void bind_vertices_result(py::module_& module) {
  py::class_<Tie_sets>(module, "TieSets",
                       "The tie sets of the vertices (or of the edges) in compressed rows: vertex i's sites are\n"
                       "sites[offsets[i]:offsets[i + 1]], ascending, 4 or more (3 or more for an edge). Indexing\n"
                       "gives that slice (a view); len() is the number of vertices (edges).")
      .def_readonly("offsets", &Tie_sets::offsets, "(m + 1,) int64: where the sites of each vertex (edge) start")
      .def_readonly("sites", &Tie_sets::sites, "int64: the sites of every vertex (edge), one after the other")
      .def("__len__", &Tie_sets::size, "The number of rows: vertices (edges).")
      .def(
          "__getitem__",
          [](const Tie_sets& t, py::ssize_t i) { return row_view(t.offsets, t.sites, i); },
          "i"_a, "The sites tied at vertex (or edge) i, an int64 view into sites; IndexError out of range.");

  py::class_<Hidden_sites>(module, "HiddenSites",
                           "The sites whose cells have no interior, ascending: site i lies inside (or tangent\n"
                           "inside) the ball of hidden_by[i], or duplicates it exactly (duplicate[i]). For a\n"
                           "duplicate, hidden_by is the first identical earlier site, otherwise the smallest\n"
                           "index of a site that hides it.")
      .def_readonly("site", &Hidden_sites::site, "int64: the hidden sites")
      .def_readonly("hidden_by", &Hidden_sites::hidden_by, "int64: the site that hides each")
      .def_readonly("duplicate", &Hidden_sites::duplicate, "bool: whether each is an exact duplicate")
      .def("__len__", [](const Hidden_sites& h) { return h.site.size(); }, "The number of hidden sites.");

  py::class_<Vertices_result>(module, "Vertices",
                              "Every vertex of the diagram, sorted by tie set, then by x, y, z, r (the order of\n"
                              "the command line's output). len() is the number of vertices.")
      .def_readonly("points", &Vertices_result::points,
                    "(m, 4) float64: x, y, z and r of each vertex, the correctly rounded doubles of the exact\n"
                    "centre and weighted distance (inf or -inf beyond the double range)")
      .def_readonly("tie_sets", &Vertices_result::tie_sets, "TieSets: the sites at equal least distance of each vertex")
      .def_readonly("hidden", &Vertices_result::hidden, "HiddenSites: the sites that take no part in the diagram")
      .def_readonly("sites_without_vertex", &Vertices_result::sites_without_vertex,
                    "int64: the sites, not hidden, in no vertex's tie set, ascending")
      .def_readonly("site_count", &Vertices_result::site_count, "the number of input sites")
      .def_readonly("stats", &Vertices_result::stats,
                    "None, or with stats=True a dict: 'predicates', a list of {'name', 'evaluations',\n"
                    "'exact_stages'} as in the command line's JSON, and 'octree', the phase times (seconds)\n"
                    "and sizes that --stats prints")
      .def("__len__", [](const Vertices_result& r) { return r.tie_sets.size(); }, "The number of vertices.")
      .def("__repr__", &repr);
}

}  // namespace apollonius::python
