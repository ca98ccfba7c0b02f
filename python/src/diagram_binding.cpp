// diagram(centres, weights): the whole diagram as numpy arrays, the content of the command line's
// 'diagram' JSON (docs/contract.md, "The whole diagram"): vertices, edges, faces and cells by id.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "bindings.h"
#include "compressed_rows.h"
#include "interruptible_call.h"
#include "octree/octree_diagram.h"
#include "site_arrays.h"
#include "thread_count.h"
#include "topology/build_topology.h"
#include "topology/validate_topology.h"
#include "vertices_result.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace apollonius::python {
namespace {

// Invariant: every array has one entry per edge; start and end are vertex ids, -1 where the edge has no
// such end (at infinity, or a closed edge).
struct Edges_result {
  Tie_sets tie_sets;
  py::array_t<std::int64_t> start, end;
  py::array_t<bool> closed;
  py::array curve;  // str
};

// Two levels of compressed rows: face f's boundary components are the rows component_offsets[f] to
// component_offsets[f + 1] - 1 of (edge_offsets, edges). Invariant: sites and bounded have one entry per face.
struct Faces_result {
  py::array_t<std::int64_t> sites;  // (f, 2): a < b
  py::array_t<std::int64_t> component_offsets, edge_offsets, edges;
  py::array_t<bool> bounded;
};

// Invariant: one entry per site that is not hidden, ascending by site.
struct Cells_result {
  py::array_t<std::int64_t> site;
  Compressed_rows faces;
  py::array_t<bool> bounded;
};

struct Diagram_result {
  Vertices_result vertices;
  Edges_result edges;
  Faces_result faces;
  Cells_result cells;
};

py::object optional_index(std::int64_t index) { return index < 0 ? py::none() : py::object(py::int_(index)); }

// The curve names as a str array (numpy's fixed-width UCS-4), written straight into it.
py::array curve_names(const std::vector<Diagram_edge>& edges) {
  std::size_t width = 1;
  for (const Diagram_edge& e : edges) width = std::max(width, std::strlen(to_string(e.curve)));
  py::array names = py::module_::import("numpy").attr("zeros")(edges.size(), "dtype"_a = "<U" + std::to_string(width));
  auto* out = static_cast<char32_t*>(names.mutable_data());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const char* name = to_string(edges[i].curve);
    std::copy(name, name + std::strlen(name), out + i * width);
  }
  return names;
}

Edges_result edges_to_python(const std::vector<Diagram_edge>& edges) {
  const py::ssize_t n = static_cast<py::ssize_t>(edges.size());
  const Compressed_rows tie_sets =
      compressed_rows(edges, [](const Diagram_edge& e) -> const std::vector<Site_index>& { return e.tie_set; });
  Edges_result result{Tie_sets{tie_sets.offsets, tie_sets.values}, py::array_t<std::int64_t>(n),
                      py::array_t<std::int64_t>(n), py::array_t<bool>(n), curve_names(edges)};
  for (py::ssize_t i = 0; i < n; ++i) {
    const Diagram_edge& e = edges[static_cast<std::size_t>(i)];
    result.start.mutable_at(i) = e.start ? static_cast<std::int64_t>(*e.start) : -1;
    result.end.mutable_at(i) = e.end ? static_cast<std::int64_t>(*e.end) : -1;
    result.closed.mutable_at(i) = e.closed;
  }
  return result;
}

Faces_result faces_to_python(const std::vector<Diagram_face>& faces) {
  const py::ssize_t n = static_cast<py::ssize_t>(faces.size());
  Faces_result result{py::array_t<std::int64_t>({n, py::ssize_t{2}}), py::array_t<std::int64_t>(n + 1), {}, {},
                      py::array_t<bool>(n)};
  std::vector<const std::vector<std::size_t>*> components;
  std::int64_t* component_offset = result.component_offsets.mutable_data();
  component_offset[0] = 0;
  for (py::ssize_t f = 0; f < n; ++f) {
    const Diagram_face& face = faces[static_cast<std::size_t>(f)];
    result.sites.mutable_at(f, 0) = face.a;
    result.sites.mutable_at(f, 1) = face.b;
    result.bounded.mutable_at(f) = face.bounded;
    for (const std::vector<std::size_t>& component : face.boundary) components.push_back(&component);
    component_offset[f + 1] = static_cast<std::int64_t>(components.size());
  }
  const Compressed_rows rows =
      compressed_rows(components, [](const std::vector<std::size_t>* c) -> const std::vector<std::size_t>& { return *c; });
  result.edge_offsets = rows.offsets;
  result.edges = rows.values;
  return result;
}

// Face f's boundary components: a list of int64 views into edges.
py::list face_boundary(const Faces_result& faces, py::ssize_t f) {
  const py::ssize_t n = faces.bounded.size();
  if (f < 0) f += n;
  if (f < 0 || f >= n) throw py::index_error("face index out of range");
  py::list components;
  for (std::int64_t c = faces.component_offsets.at(f); c < faces.component_offsets.at(f + 1); ++c)
    components.append(row_view(faces.edge_offsets, faces.edges, c));
  return components;
}

Cells_result cells_to_python(const std::vector<Diagram_cell>& cells) {
  const py::ssize_t n = static_cast<py::ssize_t>(cells.size());
  Cells_result result{py::array_t<std::int64_t>(n),
                      compressed_rows(cells, [](const Diagram_cell& c) -> const std::vector<std::size_t>& { return c.faces; }),
                      py::array_t<bool>(n)};
  for (py::ssize_t i = 0; i < n; ++i) {
    result.site.mutable_at(i) = cells[static_cast<std::size_t>(i)].site;
    result.bounded.mutable_at(i) = cells[static_cast<std::size_t>(i)].bounded;
  }
  return result;
}

// Python's index i of a sequence of n, or IndexError.
py::ssize_t checked_index(py::ssize_t i, py::ssize_t n, const char* what) {
  if (i < 0) i += n;
  if (i < 0 || i >= n) throw py::index_error(std::string(what) + " index out of range");
  return i;
}

std::string repr(const Diagram_result& d) {
  return "<Diagram: " + std::to_string(d.vertices.tie_sets.size()) + " vertices, " +
         std::to_string(d.edges.closed.size()) + " edges, " + std::to_string(d.faces.bounded.size()) + " faces, " +
         std::to_string(d.cells.site.size()) + " cells of " + std::to_string(d.vertices.site_count) + " sites>";
}

void bind_result_classes(py::module_& module) {
  py::class_<Edges_result>(module, "Edges",
                           "The edges of the diagram: the connected pieces of the points where exactly the sites\n"
                           "of a tie set (3 or more) tie, sorted by tie set, then start, then end. Each runs\n"
                           "forward along the trisector of its three smallest sites, from start to end. len() is\n"
                           "the number of edges; edges[i] is a dict of edge i: sites, start and end (vertex ids,\n"
                           "None at infinity or for a closed edge), closed, curve.")
      .def_readonly("tie_sets", &Edges_result::tie_sets, "TieSets: the sites of each edge, ascending")
      .def_readonly("start", &Edges_result::start, "int64: the vertex id where each edge starts, -1 if none")
      .def_readonly("end", &Edges_result::end, "int64: the vertex id where each edge ends, -1 if none")
      .def_readonly("closed", &Edges_result::closed, "bool: whether each edge is a whole closed curve with no vertex")
      .def_readonly("curve", &Edges_result::curve,
                    "str: the shape of each edge's trisector: point, ellipse, hyperbola, parabola, line or circle")
      .def("__len__", [](const Edges_result& e) { return e.closed.size(); }, "The number of edges.")
      .def(
          "__getitem__",
          [](const Edges_result& e, py::ssize_t i) {
            i = checked_index(i, e.closed.size(), "edge");
            return py::dict("sites"_a = row_view(e.tie_sets.offsets, e.tie_sets.sites, i),
                            "start"_a = optional_index(e.start.at(i)), "end"_a = optional_index(e.end.at(i)),
                            "closed"_a = e.closed.at(i), "curve"_a = e.curve.attr("__getitem__")(i).attr("item")());
          },
          "i"_a, "Edge i as a dict: sites (int64 view), start, end (vertex ids or None), closed, curve.");

  py::class_<Faces_result>(module, "Faces",
                           "The faces of the diagram: the connected pieces of the points where exactly two sites\n"
                           "a < b tie, sorted by (a, b), then by their first boundary edge. Each boundary\n"
                           "component is a list of edge ids in order along it: a closed cycle, or an open chain\n"
                           "between two ends at infinity. len() is the number of faces; faces[f] is a dict of\n"
                           "face f: sites, boundary, bounded.")
      .def_readonly("sites", &Faces_result::sites, "(f, 2) int64: the two sites of each face, a < b")
      .def_readonly("component_offsets", &Faces_result::component_offsets,
                    "(f + 1,) int64: face f's boundary components are the rows component_offsets[f] to\n"
                    "component_offsets[f + 1] - 1 of edge_offsets and edges")
      .def_readonly("edge_offsets", &Faces_result::edge_offsets,
                    "int64: boundary component c is edges[edge_offsets[c]:edge_offsets[c + 1]]")
      .def_readonly("edges", &Faces_result::edges, "int64: the edge ids of every boundary component, one after the other")
      .def_readonly("bounded", &Faces_result::bounded, "bool: whether each face is bounded")
      .def("boundary", &face_boundary, "f"_a,
           "boundary(f) -> list: face f's boundary components, each an int64 view of its edge ids in order.")
      .def("__len__", [](const Faces_result& f) { return f.bounded.size(); }, "The number of faces.")
      .def(
          "__getitem__",
          [](const Faces_result& faces, py::ssize_t f) {
            f = checked_index(f, faces.bounded.size(), "face");
            return py::dict("sites"_a = py::make_tuple(faces.sites.at(f, 0), faces.sites.at(f, 1)),
                            "boundary"_a = face_boundary(faces, f), "bounded"_a = faces.bounded.at(f));
          },
          "f"_a, "Face f as a dict: sites (a, b), boundary (a list of int64 views of edge ids), bounded.");

  py::class_<Cells_result>(module, "Cells",
                           "The cells of the diagram, one per site that is not hidden, ascending by site: the\n"
                           "points where that site is nearest. len() is the number of cells; cells[c] is a dict\n"
                           "of cell c (not of site c): site, faces, bounded.")
      .def_readonly("site", &Cells_result::site, "int64: the site of each cell")
      .def_property_readonly("face_offsets", [](const Cells_result& c) { return c.faces.offsets; },
                             "(c + 1,) int64: cell c's faces are faces[face_offsets[c]:face_offsets[c + 1]]")
      .def_property_readonly("faces", [](const Cells_result& c) { return c.faces.values; },
                             "int64: the face ids of every cell, ascending within each, one cell after the other")
      .def_readonly("bounded", &Cells_result::bounded, "bool: whether each cell is bounded")
      .def("__len__", [](const Cells_result& c) { return c.site.size(); }, "The number of cells.")
      .def(
          "__getitem__",
          [](const Cells_result& cells, py::ssize_t c) {
            c = checked_index(c, cells.site.size(), "cell");
            return py::dict("site"_a = cells.site.at(c), "faces"_a = row_view(cells.faces.offsets, cells.faces.values, c),
                            "bounded"_a = cells.bounded.at(c));
          },
          "c"_a, "Cell c as a dict: site, faces (int64 view of face ids), bounded.");

  py::class_<Diagram_result>(module, "Diagram",
                             "The whole diagram: vertices (Vertices, with the hidden sites), edges, faces and\n"
                             "cells, with ids that index these lists, as in the command line's 'diagram' JSON.")
      .def_readonly("vertices", &Diagram_result::vertices, "Vertices: the vertices; ids index them")
      .def_readonly("edges", &Diagram_result::edges, "Edges: the edges; ids index them")
      .def_readonly("faces", &Diagram_result::faces, "Faces: the faces; ids index them")
      .def_readonly("cells", &Diagram_result::cells, "Cells: one per site that is not hidden")
      .def_property_readonly("site_count", [](const Diagram_result& d) { return d.vertices.site_count; },
                             "the number of input sites")
      .def("__repr__", &repr);
}

}  // namespace

void bind_diagram(py::module_& module) {
  bind_result_classes(module);
  module.def(
      "diagram",
      [](const py::object& centres, const py::object& weights, int threads) {
        check_thread_count(threads);
        const std::vector<Site> sites = sites_from_python(centres, weights);
        const Diagram_topology topology = interruptible_call([&](const Cancellation& cancellation) {
          Octree_regions regions;
          Octree_options options;
          options.threads = threads;
          options.regions = &regions;
          options.cancellation = &cancellation;
          Diagram vertices = octree_diagram(sites, options);
          throw_if_cancelled(&cancellation);
          Diagram_topology built = build_topology(sites, std::move(vertices), regions, {threads, &cancellation});
          validate_topology(sites, built, &cancellation);  // as the command line: a violation is an internal error
          return built;
        });
        return Diagram_result{vertices_to_python(topology.vertices, py::none()), edges_to_python(topology.edges),
                              faces_to_python(topology.faces), cells_to_python(topology.cells)};
      },
      "centres"_a, "weights"_a, py::kw_only(), "threads"_a = 1,
      R"(diagram(centres, weights, *, threads=1) -> Diagram

The whole Apollonius diagram of the sites in R^3, exactly (the command line's 'diagram'): its vertices
with their tie sets, its edges (with their ends, in order along their curves; closed and infinite ones
included), its faces (with their boundary components and whether bounded) and its cells, checked by
the Euler relation before it is returned. Ids index the result's lists, as in the JSON output.

centres: (n, 3) and weights: (n,), float64 or anything that converts to it exactly, as for vertices().
threads: 1 to 1024 worker threads; the result is the same for every number.
Returns Diagram: .vertices (Vertices), .edges (Edges), .faces (Faces), .cells (Cells), all numpy
arrays in compressed rows, with edges[i], faces[f], cells[c] as dicts for one at a time.
Raises ValueError for bad input, with the command line's message, and RuntimeError for what this
version does not decide (some degenerate vertices and edges: the command line exits 3 there too).
The computation releases the GIL. Ctrl-C (KeyboardInterrupt) stops it within a fraction of a second, in
every phase: vertices, edges, faces, cells and their validation.)");
}

}  // namespace apollonius::python
