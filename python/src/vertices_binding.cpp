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
#include "octree/vertex_algorithm.h"
#include "predicates/predicate_counter.h"
#include "site_arrays.h"
#include "thread_count.h"
#include "vertices_result.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace apollonius::python {
namespace {

// What the computation hands back to the GIL-holding thread.
struct Computed {
  Diagram diagram;
  Octree_statistics octree;
  std::vector<Predicate_statistics> predicates;
};

py::dict stats_to_python(const Computed& computed) {
  py::list predicates;
  for (const Predicate_statistics& s : computed.predicates)
    predicates.append(py::dict("name"_a = s.name, "evaluations"_a = s.evaluations, "exact_stages"_a = s.exact_stages));
  const Octree_statistics& o = computed.octree;
  py::dict octree("partition_seconds"_a = o.partition_seconds, "propagation_seconds"_a = o.propagation_seconds,
                  "refinement_seconds"_a = o.refinement_seconds, "far_field_seconds"_a = o.far_field_seconds,
                  "assembly_seconds"_a = o.assembly_seconds, "seed_boxes"_a = o.seed_boxes,
                  "seed_candidates"_a = o.seed_candidates, "escaping_sites"_a = o.escaping_sites, "boxes"_a = o.boxes,
                  "box_candidates"_a = o.box_candidates,
                  "leaves"_a = o.leaves, "leaf_candidates"_a = o.leaf_candidates, "lifted_leaves"_a = o.lifted_leaves,
                  "quadruples"_a = o.quadruples,
                  "distinct_quadruples"_a = o.distinct_quadruples, "far_field_quadruples"_a = o.far_field_quadruples,
                  "lifted_fallback"_a = o.lifted_fallback, "lifted_small_input"_a = o.lifted_small_input,
                  "lifted_one_weight"_a = o.lifted_one_weight, "lifted_deep_input"_a = o.lifted_deep_input,
                  "lifted_seed_candidates"_a = o.lifted_seed_candidates,
                  "lifted_seconds"_a = o.lifted_seconds, "lifted_quadruples"_a = o.lifted_quadruples);
  return py::dict("predicates"_a = predicates, "octree"_a = octree);
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

}  // namespace

void bind_vertices(py::module_& module) {
  bind_vertices_result(module);
  module.def(
      "vertices",
      [](const py::object& centres, const py::object& weights, int threads, const py::object& box, bool stats,
         const std::string& algorithm) {
        check_thread_count(threads);
        Octree_options algorithm_options;
        if (!use_vertex_algorithm(algorithm, algorithm_options)) {
          std::string names;
          for (const char* name : kVertexAlgorithms) names += std::string(names.empty() ? "" : ", ") + name;
          throw py::value_error("algorithm: '" + algorithm + "' is not one of " + names);
        }
        const std::vector<Site> sites = sites_from_python(centres, weights);
        const std::optional<Axis_box> restriction = box_from_python(box);
        if (stats) reset_predicate_statistics();
        Computed computed = interruptible_call([&](const Cancellation& cancellation) {
          Computed c;
          Octree_options options = algorithm_options;
          options.threads = threads;
          options.statistics = &c.octree;
          options.cancellation = &cancellation;
          c.diagram = octree_diagram(sites, options);
          if (restriction) restrict_to_box(c.diagram, *restriction);
          return c;
        });
        // Read once the worker thread has ended and handed in its counts.
        if (stats) computed.predicates = predicate_statistics();
        return vertices_to_python(computed.diagram, stats ? py::object(stats_to_python(computed)) : py::none());
      },
      "centres"_a, "weights"_a, py::kw_only(), "threads"_a = 1, "box"_a = py::none(), "stats"_a = false,
      "algorithm"_a = "auto",
      R"(vertices(centres, weights, *, threads=1, box=None, stats=False, algorithm="auto") -> Vertices

Every vertex of the Apollonius diagram of the sites in R^3, exactly (the command line's 'vertices'):
the points where 4 or more sites are at equal least weighted distance |x - c_i| - w_i, with the whole
tie set, also far outside the sites' bounding box.

centres: (n, 3) and weights: (n,), float64 or anything that converts to it exactly (lists, integer or
float32 arrays, ...); each double is taken as the rational number it denotes.
threads: 1 to 1024 worker threads; the result is the same for every number.
box: None, or (X0, Y0, Z0, X1, Y1, Z1): only the vertices whose centre lies in that closed box.
stats: also count the predicates and their exact stages (counters shared by the whole process:
concurrent computations in other threads add to them) and report the octree's phases.
algorithm: "auto" (the lifted triangulation for at most 256 sites that are not hidden, for balls of one
radius, or where the octree would refine through far more binades than the sites' spacing needs, such as
a cluster beside one ball 1e12 away; else the octree),
"octree" or "lifted", as the command line's --algorithm; the same answer from each.
Returns Vertices: .points (m, 4), .tie_sets, .hidden, .sites_without_vertex, .stats.
Raises ValueError for bad input (wrong shape, no exact float64, NaN or infinity, no site), with the
command line's kind of message, e.g. "centres: site 3, z: not a finite number: nan". The computation
releases the GIL; Ctrl-C (KeyboardInterrupt) stops it within a fraction of a second.)");
}

}  // namespace apollonius::python
