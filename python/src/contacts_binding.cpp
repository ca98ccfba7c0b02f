// contacts(centres, weights, probe=1.4): contact areas, SAS and volumes (the command line's 'contacts',
// docs/contract.md) as numpy arrays. APPROXIMATE quantities, each with its error estimate.
#include <pybind11/numpy.h>

#include <cmath>
#include <string>
#include <vector>

#include "bindings.h"
#include "interruptible_call.h"
#include "io/round_trip.h"
#include "measure/contact_measures.h"
#include "site_arrays.h"
#include "thread_count.h"
#include "vertices_result.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace apollonius::python {
namespace {

// Invariant: pairs has one row (a, b), a < b, per entry of area and error, ascending; the per-site
// arrays have one entry per site.
struct Contacts_result {
  double probe, tolerance;
  py::array_t<std::int64_t> pairs;  // (k, 2)
  py::array_t<double> area, error;
  py::array_t<double> sas, sas_error, volume, volume_error;
  Hidden_sites hidden;
};

py::array_t<double> to_array(const std::vector<double>& values) {
  py::array_t<double> a(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

Contacts_result contacts_to_python(const Contact_measures& m, const Contact_options& options) {
  const py::ssize_t k = static_cast<py::ssize_t>(m.contacts.size());
  Contacts_result r{options.probe, options.relative_tolerance, py::array_t<std::int64_t>({k, py::ssize_t{2}}),
                    py::array_t<double>(k), py::array_t<double>(k), to_array(m.sas), to_array(m.sas_error),
                    to_array(m.volume), to_array(m.volume_error), {}};
  auto pairs = r.pairs.mutable_unchecked<2>();
  auto area = r.area.mutable_unchecked<1>();
  auto error = r.error.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < k; ++i) {
    const Contact& c = m.contacts[static_cast<std::size_t>(i)];
    pairs(i, 0) = c.a, pairs(i, 1) = c.b, area(i) = c.area, error(i) = c.error;
  }
  r.hidden = hidden_to_python(m.hidden);
  return r;
}

}  // namespace

void bind_contacts(py::module_& module) {
  py::class_<Contacts_result>(module, "Contacts",
                              "Contact areas, SAS areas and volumes (contacts()). APPROXIMATE: cubatures, each with\n"
                              "its error estimate (not a bound).")
      .def_readonly("probe", &Contacts_result::probe, "the probe radius P")
      .def_readonly("tolerance", &Contacts_result::tolerance, "the relative tolerance per cell")
      .def_readonly("pairs", &Contacts_result::pairs, "int64 (k, 2): the balls (a, b), a < b, of each contact, ascending")
      .def_readonly("area", &Contacts_result::area, "float64 (k,): the area of each contact face where d <= P")
      .def_readonly("error", &Contacts_result::error, "float64 (k,): each area's error estimate")
      .def_readonly("sas", &Contacts_result::sas, "float64 (n,): each ball's solvent-accessible area (0 if hidden)")
      .def_readonly("sas_error", &Contacts_result::sas_error, "float64 (n,): its error estimate")
      .def_readonly("volume", &Contacts_result::volume, "float64 (n,): each cell's volume where d <= P")
      .def_readonly("volume_error", &Contacts_result::volume_error, "float64 (n,): its error estimate")
      .def_readonly("hidden", &Contacts_result::hidden, "HiddenSites: the balls with no cell (decided exactly)")
      .def("__len__", [](const Contacts_result& r) { return r.area.size(); }, "The number of contacts.")
      .def("__repr__", [](const Contacts_result& r) {
        return "<apollonius3d.Contacts: " + std::to_string(r.area.size()) + " contacts between " +
               std::to_string(r.sas.size()) + " balls, probe " + py::repr(py::float_(r.probe)).cast<std::string>() + ">";
      });
  module.def(
      "contacts",
      [](const py::object& centres, const py::object& weights, double probe, double tolerance, int threads) {
        check_thread_count(threads);
        if (!(probe >= 0) || !std::isfinite(probe))
          throw py::value_error("probe: needs a finite number >= 0, not " + round_trip(probe));
        if (!(tolerance >= 1e-10 && tolerance <= 0.5))
          throw py::value_error("tolerance: needs a number in [1e-10, 0.5], not " + round_trip(tolerance));
        const std::vector<Site> sites = sites_from_python(centres, weights);
        Contact_options options;
        options.probe = probe;
        options.relative_tolerance = tolerance;
        options.threads = threads;
        const Contact_measures measures = interruptible_call([&](const Cancellation& cancellation) {
          Contact_options o = options;
          o.cancellation = &cancellation;
          return measure_contacts(sites, o);
        });
        return contacts_to_python(measures, options);
      },
      "centres"_a, "weights"_a, py::kw_only(), "probe"_a = 1.4, "tolerance"_a = 1e-4, "threads"_a = 1,
      R"(contacts(centres, weights, *, probe=1.4, tolerance=1e-4, threads=1) -> Contacts

Contacts between balls as Voronota's calculate-contacts defines them, on the exact diagram (the command
line's 'contacts'): with d_i(x) = |x - c_i| - w_i, the area of each face of balls a and b where
d <= probe, each ball's solvent-accessible area (its sphere of radius w + probe inside its cell) and the
volume of its cell where d <= probe. Hidden balls (inside another, or duplicates) are decided exactly and
have none. APPROXIMATE: cubatures with error estimates; per cell the estimated errors are at most
tolerance times its clipped volume and boundary area.

centres: (n, 3) and weights: (n,), float64 or anything that converts to it exactly.
probe: the probe radius, a finite number >= 0. tolerance: from 1e-10 to 0.5.
threads: 1 to 1024 worker threads; the result is the same for every number.
Returns Contacts: .pairs (k, 2), .area, .error, .sas, .sas_error, .volume, .volume_error, .hidden.
Raises ValueError for bad input or parameters. Releases the GIL; Ctrl-C stops it within a second.)");
}

}  // namespace apollonius::python
