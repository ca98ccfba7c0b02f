// centroidal(centres, weights, domain): the centroidal Apollonius diagram in a box (the command line's
// 'centroidal'): the final sites, whether it converged, and the history of its iterations.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "centroidal/centroidal_diagram.h"
#include "centroidal/centroidal_parameters.h"
#include "interruptible_call.h"
#include "io/input_error.h"
#include "site_arrays.h"
#include "thread_count.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace apollonius::python {
namespace {

// One row of the history, the columns of the command line's --history CSV in its order.
struct History_row {
  std::int64_t iteration;
  double E4, max_relative_mass_error, largest_site_move, seconds, median_residual, E4_before_weight_step,
      E4_error_estimate;
  std::int64_t weight_retries;
};

// Invariant: centres, weights and volumes have one entry per site; history one per iteration, and
// iterations == len(history).
struct Centroidal_python_result {
  py::array_t<double> centres, weights, volumes;
  bool converged = false;
  std::size_t iterations = 0;
  py::array_t<History_row> history;
  double mass_error = 0, median_residual = 0, energy = 0;
  std::vector<std::string> reports;
};

// The parameters the command line takes as option values, as Python's arguments: the same reasons, with
// the argument's name where the command line names its option or file (and the 0-based site or mass
// where it gives the line).
[[noreturn]] void raise_for_python(const Centroidal_parameter_error& e) {
  const char* name = "";
  switch (e.parameter) {
    case Centroidal_parameter::domain: name = "domain"; break;
    case Centroidal_parameter::sites: name = "centres"; break;
    case Centroidal_parameter::masses: name = "masses"; break;
    case Centroidal_parameter::tolerance: name = "tolerance"; break;
    case Centroidal_parameter::median_tolerance: name = "median_tolerance"; break;
    case Centroidal_parameter::max_iterations: name = "max_iterations"; break;
  }
  throw Input_error(name, 0, (e.site >= 0 ? "site " + std::to_string(e.site) + ": " : std::string()) + e.what());
}

Axis_box domain_from_python(const py::object& domain) {
  const py::array_t<double, py::array::c_style> values = exact_float64_array(domain, "domain");
  if (values.ndim() != 1 || values.size() != 6)
    throw Input_error("domain", 0, "expected 6 numbers X0 Y0 Z0 X1 Y1 Z1");
  Axis_box box;
  for (int k = 0; k < 3; ++k) box.lo[k] = values.at(k), box.hi[k] = values.at(k + 3);
  return box;
}

std::vector<double> masses_from_python(const py::object& masses, std::size_t site_count) {
  // Equal masses by default, as the command line's.
  if (masses.is_none()) return std::vector<double>(site_count, 1.0 / static_cast<double>(site_count));
  const py::array_t<double, py::array::c_style> values = exact_float64_array(masses, "masses");
  if (values.ndim() != 1) {
    std::string shape = "(";
    for (py::ssize_t k = 0; k < values.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(values.shape(k));
    throw Input_error("masses", 0, "expected shape (n,), one per site, found " + shape + ")");
  }
  return {values.data(), values.data() + values.size()};
}

Centroidal_python_result result_to_python(const Centroidal_result& r) {
  const py::ssize_t n = static_cast<py::ssize_t>(r.sites.size());
  Centroidal_python_result out;
  out.centres = py::array_t<double>({n, py::ssize_t{3}});
  out.weights = py::array_t<double>(n);
  out.volumes = py::array_t<double>(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    const Site& s = r.sites[static_cast<std::size_t>(i)];
    out.centres.mutable_at(i, 0) = s.x;
    out.centres.mutable_at(i, 1) = s.y;
    out.centres.mutable_at(i, 2) = s.z;
    out.weights.mutable_at(i) = s.w;
    out.volumes.mutable_at(i) = r.volumes[static_cast<std::size_t>(i)];
  }
  out.converged = r.converged;
  out.iterations = r.history.size();
  out.history = py::array_t<History_row>(static_cast<py::ssize_t>(r.history.size()));
  History_row* row = out.history.mutable_data();
  for (const Centroidal_iteration& h : r.history)
    *row++ = {h.iteration, h.energy, h.mass_error, h.largest_move, h.seconds, h.median_error, h.energy_before,
              h.energy_error, h.weight_retries};
  if (!r.history.empty()) {
    out.mass_error = r.history.back().mass_error;
    out.median_residual = r.history.back().median_error;
    out.energy = r.history.back().energy;
  }
  out.reports = r.reports;
  return out;
}

std::string repr(const Centroidal_python_result& r) {
  return "<CentroidalResult: " + std::to_string(r.weights.size()) + " sites, " +
         (r.converged ? "converged" : "not converged") + " after " + std::to_string(r.iterations) + " iterations>";
}

}  // namespace

void bind_centroidal(py::module_& module) {
  PYBIND11_NUMPY_DTYPE(History_row, iteration, E4, max_relative_mass_error, largest_site_move, seconds,
                       median_residual, E4_before_weight_step, E4_error_estimate, weight_retries);
  py::class_<Centroidal_python_result>(module, "CentroidalResult",
                                       "The centroidal Apollonius diagram that centroidal() reached: the final\n"
                                       "sites, whether the stopping rule was met, and every iteration's row.")
      .def_readonly("centres", &Centroidal_python_result::centres, "(n, 3) float64: the final centres")
      .def_readonly("weights", &Centroidal_python_result::weights, "(n,) float64: the final weights")
      .def_readonly("volumes", &Centroidal_python_result::volumes,
                    "(n,) float64: the final cells' volumes in the domain (cubatures, APPROXIMATE)")
      .def_readonly("converged", &Centroidal_python_result::converged,
                    "bool: whether every relative mass error and median residual, each with its quadrature\n"
                    "error estimate, reached the tolerance (False: the state after max_iterations)")
      .def_readonly("iterations", &Centroidal_python_result::iterations, "int: the iterations run")
      .def_readonly("history", &Centroidal_python_result::history,
                    "structured array, one row per iteration, the columns of the command line's --history\n"
                    "CSV: iteration, E4, max_relative_mass_error, largest_site_move, seconds,\n"
                    "median_residual, E4_before_weight_step, E4_error_estimate, weight_retries")
      .def_readonly("mass_error", &Centroidal_python_result::mass_error,
                    "float: the final max relative mass error max_i (|M_i - m_i| + e_i) / M_i")
      .def_readonly("median_residual", &Centroidal_python_result::median_residual,
                    "float: the final max median residual (|G_i| + e_G) / m_i")
      .def_readonly("energy", &Centroidal_python_result::energy, "float: the final E4 (paper eq. 41)")
      .def_readonly("reports", &Centroidal_python_result::reports,
                    "list of str: the degenerate situations met and how each was handled (the command line\n"
                    "prints them on standard error)")
      .def("__repr__", &repr);

  module.def(
      "centroidal",
      [](const py::object& centres, const py::object& weights, const py::object& domain, const py::object& masses,
         double tolerance, std::optional<double> median_tolerance, int max_iterations, int threads) {
        check_thread_count(threads);
        const std::vector<Site> sites = sites_from_python(centres, weights);
        const Axis_box box = domain_from_python(domain);
        const std::vector<double> fractions = masses_from_python(masses, sites.size());
        try {
          // As the command line, in its order: the options, then the sites and masses.
          check_centroidal_domain(box);
          check_centroidal_tolerance(tolerance);
          if (median_tolerance) check_centroidal_tolerance(*median_tolerance, Centroidal_parameter::median_tolerance);
          check_centroidal_iterations(max_iterations);
          check_centroidal_sites(sites, fractions, box);
        } catch (const Centroidal_parameter_error& e) {
          raise_for_python(e);
        }
        const Centroidal_result result = interruptible_call([&](const Cancellation& cancellation) {
          Centroidal_options options;
          options.tolerance = tolerance;
          options.median_tolerance = median_tolerance;
          options.max_iterations = max_iterations;
          options.threads = threads;
          options.cancellation = &cancellation;
          return centroidal_diagram(sites, fractions, box, options);
        });
        return result_to_python(result);
      },
      "centres"_a, "weights"_a, "domain"_a, py::kw_only(), "masses"_a = py::none(), "tolerance"_a = 1e-6,
      "median_tolerance"_a = py::none(), "max_iterations"_a = 100, "threads"_a = 1,
      R"(centroidal(centres, weights, domain, *, masses=None, tolerance=1e-6, median_tolerance=None, max_iterations=100, threads=1) -> CentroidalResult

The centroidal Apollonius diagram in a box (paper section 7; the command line's 'centroidal'): moves
the sites to the geometric medians of their cells and sets the weights so that each cell holds its
target volume. The diagrams are certified; the volumes and medians are cubatures with error estimates.

centres: (n, 3) and weights: (n,), the initial sites, as for vertices(); no two at one centre.
domain: (X0, Y0, Z0, X1, Y1, Z1), a box with a volume that contains every centre.
masses: None (equal), or (n,) target volumes as fractions of the domain's volume, each positive,
  summing to 1 within 1e-9.
tolerance: stop when every relative volume error |M_i - m_i| / M_i and every median residual, each
  with its quadrature error estimate, is at most this; from 1e-10 to 0.5.
median_tolerance: None (tolerance), or the median residuals' own tolerance, from 1e-10 to 0.5 (the
  volumes still to tolerance).
max_iterations: 1 to 100000; the state reached then is returned with converged False.
threads: 1 to 1024 worker threads; the result is the same for every number.
Returns CentroidalResult: .centres, .weights (the command line's output, the same doubles), .converged,
.iterations, .history (its --history rows), .mass_error, .median_residual, .energy, .volumes, .reports.
Raises ValueError for bad input and parameters, with the command line's reason (naming the argument,
and the 0-based site or mass, where the command line names its option or file and line).
The computation releases the GIL; Ctrl-C (KeyboardInterrupt) stops it within a fraction of a second.)");
}

}  // namespace apollonius::python
