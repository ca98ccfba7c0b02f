// vertices(centres, weights): the vertices of the diagram as numpy arrays, the JSON output's content
// (docs/contract.md, "Vertex JSON") with the octree's statistics.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "interruptible_call.h"
#include "io/input_error.h"
#include "octree/octree_diagram.h"
#include "predicates/predicate_counter.h"
#include "site_arrays.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace apollonius::python {
namespace {

// Compressed rows: the tie set of vertex i is sites[offsets[i]:offsets[i + 1]].
// Invariant: offsets has one entry per vertex and one more, from 0 to len(sites), ascending.
struct Tie_sets {
  py::array_t<std::int64_t> offsets, sites;
  std::size_t size() const { return static_cast<std::size_t>(offsets.size() - 1); }
};

// Invariant: the three arrays have one entry per hidden site, ascending by site.
struct Hidden_sites {
  py::array_t<std::int64_t> site, hidden_by;
  py::array_t<bool> duplicate;
};

struct Vertices_result {
  std::size_t site_count;
  py::array_t<double> points;  // (m, 4): x, y, z, r
  Tie_sets tie_sets;
  Hidden_sites hidden;
  py::array_t<std::int64_t> sites_without_vertex;
  py::object stats;  // None unless asked for
};

// What the computation hands back to the GIL-holding thread.
struct Computed {
  Diagram diagram;
  Octree_statistics octree;
  std::vector<Predicate_statistics> predicates;
};

template <class T>
py::array_t<T> vector_to_array(const std::vector<T>& values) {
  py::array_t<T> array(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

py::dict stats_to_python(const Computed& computed) {
  py::list predicates;
  for (const Predicate_statistics& s : computed.predicates)
    predicates.append(py::dict("name"_a = s.name, "evaluations"_a = s.evaluations, "exact_stages"_a = s.exact_stages));
  const Octree_statistics& o = computed.octree;
  py::dict octree("partition_seconds"_a = o.partition_seconds, "propagation_seconds"_a = o.propagation_seconds,
                  "refinement_seconds"_a = o.refinement_seconds, "far_field_seconds"_a = o.far_field_seconds,
                  "assembly_seconds"_a = o.assembly_seconds, "seed_boxes"_a = o.seed_boxes,
                  "seed_candidates"_a = o.seed_candidates, "escaping_sites"_a = o.escaping_sites, "boxes"_a = o.boxes,
                  "leaves"_a = o.leaves, "leaf_candidates"_a = o.leaf_candidates, "quadruples"_a = o.quadruples,
                  "distinct_quadruples"_a = o.distinct_quadruples, "far_field_quadruples"_a = o.far_field_quadruples);
  return py::dict("predicates"_a = predicates, "octree"_a = octree);
}

// The one copy of the results: from the Diagram into arrays that numpy allocates and owns.
Vertices_result to_python(const Computed& computed, bool stats) {
  const Diagram& d = computed.diagram;
  const py::ssize_t m = static_cast<py::ssize_t>(d.vertices.size());
  py::array_t<double> points({m, py::ssize_t{4}});
  py::array_t<std::int64_t> offsets(m + 1);
  std::size_t tied = 0;
  for (const Diagram_vertex& v : d.vertices) tied += v.tie_set.size();
  py::array_t<std::int64_t> sites(static_cast<py::ssize_t>(tied));
  double* p = points.mutable_data();
  std::int64_t* o = offsets.mutable_data();
  std::int64_t* s = sites.mutable_data();
  o[0] = 0;
  for (py::ssize_t i = 0; i < m; ++i) {
    const Diagram_vertex& v = d.vertices[static_cast<std::size_t>(i)];
    std::copy(v.rounded.begin(), v.rounded.end(), p + 4 * i);
    s = std::copy(v.tie_set.begin(), v.tie_set.end(), s);
    o[i + 1] = o[i] + static_cast<std::int64_t>(v.tie_set.size());
  }
  const py::ssize_t h = static_cast<py::ssize_t>(d.hidden.size());
  Hidden_sites hidden{py::array_t<std::int64_t>(h), py::array_t<std::int64_t>(h), py::array_t<bool>(h)};
  for (py::ssize_t i = 0; i < h; ++i) {
    const Hidden_site& hs = d.hidden[static_cast<std::size_t>(i)];
    hidden.site.mutable_at(i) = hs.site;
    hidden.hidden_by.mutable_at(i) = hs.hidden_by;
    hidden.duplicate.mutable_at(i) = hs.duplicate;
  }
  const std::vector<std::int64_t> without(d.sites_without_vertex.begin(), d.sites_without_vertex.end());
  return Vertices_result{d.site_count, points, Tie_sets{offsets, sites}, hidden, vector_to_array(without),
                         stats ? py::object(stats_to_python(computed)) : py::none()};
}

// threads as the command line's --threads: 1 to 1024.
void check_threads(int threads) {
  if (threads < 1 || threads > 1024)
    throw py::value_error("threads: needs an integer from 1 to 1024, not " + std::to_string(threads));
}

std::optional<Axis_box> box_from_python(const py::object& box) {
  if (box.is_none()) return std::nullopt;
  const py::array_t<double, py::array::c_style> values = exact_float64_array(box, "box");
  if (values.ndim() != 1 || values.size() != 6)
    throw Input_error("box", 0, "expected 6 numbers X0 Y0 Z0 X1 Y1 Z1");
  Axis_box b;
  for (int k = 0; k < 3; ++k) b.lo[k] = values.at(k), b.hi[k] = values.at(k + 3);
  for (int k = 0; k < 6; ++k)
    if (!std::isfinite(values.at(k))) throw Input_error("box", 0, "needs finite numbers");
  for (int k = 0; k < 3; ++k)
    if (!(b.lo[k] <= b.hi[k])) throw Input_error("box", 0, "needs X0 <= X1, Y0 <= Y1, Z0 <= Z1");
  return b;
}

std::string repr(const Vertices_result& r) {
  return "<Vertices: " + std::to_string(r.tie_sets.size()) + " vertices of " + std::to_string(r.site_count) +
         " sites, " + std::to_string(r.hidden.site.size()) + " hidden>";
}

}  // namespace

void bind_vertices(py::module_& module) {
  py::class_<Tie_sets>(module, "TieSets",
                       "The tie sets of the vertices in compressed rows: vertex i's sites are\n"
                       "sites[offsets[i]:offsets[i + 1]], ascending, 4 or more. Indexing gives that slice\n"
                       "(a view); len() is the number of vertices.")
      .def_readonly("offsets", &Tie_sets::offsets, "(m + 1,) int64: where each vertex's sites start")
      .def_readonly("sites", &Tie_sets::sites, "int64: every vertex's sites, one vertex after the other")
      .def("__len__", &Tie_sets::size, "The number of vertices.")
      .def(
          "__getitem__",
          [](const Tie_sets& t, py::ssize_t i) {
            const py::ssize_t n = static_cast<py::ssize_t>(t.size());
            if (i < 0) i += n;
            if (i < 0 || i >= n) throw py::index_error("vertex index out of range");
            return t.sites[py::slice(t.offsets.at(i), t.offsets.at(i + 1), 1)];
          },
          "i"_a, "The sites tied at vertex i (an int64 view into sites).");

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

  module.def(
      "vertices",
      [](const py::object& centres, const py::object& weights, int threads, const py::object& box, bool stats) {
        check_threads(threads);
        const std::vector<Site> sites = sites_from_python(centres, weights);
        const std::optional<Axis_box> restriction = box_from_python(box);
        if (stats) reset_predicate_statistics();
        Computed computed = interruptible_call([&](const Cancellation& cancellation) {
          Computed c;
          Octree_options options;
          options.threads = threads;
          options.statistics = &c.octree;
          options.cancellation = &cancellation;
          c.diagram = octree_diagram(sites, options);
          if (restriction) restrict_to_box(c.diagram, *restriction);
          return c;
        });
        // Read once the worker thread has ended and handed in its counts.
        if (stats) computed.predicates = predicate_statistics();
        return to_python(computed, stats);
      },
      "centres"_a, "weights"_a, py::kw_only(), "threads"_a = 1, "box"_a = py::none(), "stats"_a = false,
      R"(vertices(centres, weights, *, threads=1, box=None, stats=False) -> Vertices

Every vertex of the Apollonius diagram of the sites in R^3, exactly (the command line's 'vertices'):
the points where 4 or more sites are at equal least weighted distance |x - c_i| - w_i, with the whole
tie set, also far outside the sites' bounding box.

centres: (n, 3) and weights: (n,), float64 or anything that converts to it exactly (lists, integer or
float32 arrays, ...); each double is taken as the rational number it denotes.
threads: 1 to 1024 worker threads; the result is the same for every number.
box: None, or (X0, Y0, Z0, X1, Y1, Z1): only the vertices whose centre lies in that closed box.
stats: also count the predicates and their exact stages (counters shared by the whole process:
concurrent computations in other threads add to them) and report the octree's phases.
Returns Vertices: .points (m, 4), .tie_sets, .hidden, .sites_without_vertex, .stats.
Raises ValueError for bad input (wrong shape, no exact float64, NaN or infinity, no site), with the
command line's kind of message, e.g. "centres: site 3, z: not a finite number: nan". The computation
releases the GIL; Ctrl-C (KeyboardInterrupt) stops it within a fraction of a second.)");
}

}  // namespace apollonius::python
