// certify(centres, weights, claim): another program's vertex list judged against the exact diagram, as
// the command line's 'certify' judges it (certify/README.md).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bindings.h"
#include "certify/certify_report.h"
#include "certify/claimed_vertices.h"
#include "certify/judge_claims.h"
#include "interruptible_call.h"
#include "io/atomic_file.h"
#include "io/input_error.h"
#include "io/text_input.h"
#include "octree/octree_diagram.h"
#include "site_arrays.h"
#include "thread_count.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace apollonius::python {
namespace {

// How the sites are named in the report: they came from arrays, not from a file.
const std::string kInputName = "<arrays>";

struct Certification_result {
  bool passed;
  py::dict counts;
  py::array verdicts;                // str, one per claim
  py::array_t<std::int64_t> vertex;  // one per claim: the diagram vertex it represents (or names), or -1
  py::array_t<std::int64_t> missing;
  std::string summary;
};

// What the computation hands back to the GIL-holding thread.
struct Judged {
  Verdict_counts counts;
  std::vector<Claim_judgement> claims;
  std::vector<std::size_t> missing;
  std::string summary;
};

Certification_result to_python(const Judged& judged) {
  const Verdict_counts& c = judged.counts;
  py::dict counts("claims"_a = c.claims, "confirmed"_a = c.confirmed, "surplus"_a = c.surplus,
                  "duplicate"_a = c.duplicate, "coordinates_off"_a = c.coordinates_off, "wrong_root"_a = c.wrong_root,
                  "not_a_vertex"_a = c.not_a_vertex, "missing"_a = c.missing, "discrepancies"_a = c.discrepancies,
                  "largest_absolute_error"_a = c.largest_error.absolute,
                  "largest_relative_error"_a = c.largest_error.relative);
  py::list verdicts;
  py::array_t<std::int64_t> vertex(static_cast<py::ssize_t>(judged.claims.size()));
  for (std::size_t i = 0; i < judged.claims.size(); ++i) {
    verdicts.append(name_of(judged.claims[i].verdict));
    vertex.mutable_at(static_cast<py::ssize_t>(i)) =
        judged.claims[i].vertex ? static_cast<std::int64_t>(*judged.claims[i].vertex) : -1;
  }
  py::array_t<std::int64_t> missing(static_cast<py::ssize_t>(judged.missing.size()));
  std::copy(judged.missing.begin(), judged.missing.end(), missing.mutable_data());
  return Certification_result{c.discrepancies == 0, counts,
                              py::module_::import("numpy").attr("array")(verdicts, "dtype"_a = "U"), vertex, missing,
                              judged.summary};
}

}  // namespace

void bind_certify(py::module_& module) {
  py::class_<Certification_result>(module, "Certification",
                                   "The verdict on each claim of a vertex list and the vertices no claim represents.")
      .def_readonly("passed", &Certification_result::passed, "True when there is no discrepancy")
      .def_readonly("counts", &Certification_result::counts,
                    "dict: claims, confirmed, surplus, duplicate, coordinates_off, wrong_root, not_a_vertex,\n"
                    "missing, discrepancies, and the largest absolute and relative coordinate errors")
      .def_readonly("verdicts", &Certification_result::verdicts,
                    "str array, one per claim: confirmed, surplus, duplicate, coordinates_off, wrong_root or\n"
                    "not_a_vertex")
      .def_readonly("vertex", &Certification_result::vertex,
                    "int64, one per claim: the index of the certified vertex (as vertices() orders them) that\n"
                    "the claim represents, or for wrong_root that its sites name; -1 for not_a_vertex")
      .def_readonly("missing", &Certification_result::missing,
                    "int64: the certified vertices (as vertices() orders them) that no claim represents")
      .def_readonly("summary", &Certification_result::summary,
                    "the command line's summary: the counts and the first ten discrepancies")
      .def("__bool__", [](const Certification_result& r) { return r.passed; }, "True when passed.")
      .def("__repr__", [](const Certification_result& r) {
        return std::string("<Certification: ") + (r.passed ? "passed" : "failed") + ", " +
               std::string(py::str(r.counts["discrepancies"])) + " discrepancies>";
      });

  module.def(
      "certify",
      [](const py::object& centres, const py::object& weights, const py::object& claim,
         const std::optional<std::string>& format, double coord_tol, bool strict, int threads,
         const py::object& report) {
        check_thread_count(threads);
        if (!(coord_tol >= 0) || !std::isfinite(coord_tol))
          throw py::value_error("coord_tol: needs a finite number >= 0, not " + std::string(py::str(py::float_(coord_tol))));
        std::optional<Claim_format> claim_format;
        if (format) {
          claim_format = claim_format_from_name(*format);
          if (!claim_format) throw py::value_error("format: needs text, json or voronota, not '" + *format + "'");
        }
        const py::module_ os = py::module_::import("os");
        const std::string claim_path = py::str(os.attr("fsdecode")(claim));
        const std::optional<std::string> report_path =
            report.is_none() ? std::nullopt : std::optional<std::string>(py::str(os.attr("fsdecode")(report)));
        const std::vector<Site> sites = sites_from_python(centres, weights);
        const Judged judged = interruptible_call([&](const Cancellation& cancellation) {
          // As the command line: the claim is read and checked before the diagram is computed.
          const std::string claim_name = input_name(claim_path);
          const Claimed_vertex_list claims =
              read_claimed_vertices(read_input_file(claim_path), claim_name, claim_format, sites.size());
          Octree_options options;
          options.threads = threads;
          options.cancellation = &cancellation;
          const Diagram diagram = octree_diagram(sites, options);
          Certification certification =
              judge_claims(sites, diagram, claims.vertices, Coordinate_tolerance{coord_tol, input_scale(sites)});
          const Certify_report full{kInputName, claim_name, diagram, claims, certification, strict};
          if (report_path)
            write_file_atomically(*report_path, [&](std::ostream& out) { write_certify_report_json(out, full); });
          std::ostringstream summary;
          write_certify_summary(summary, full);
          return Judged{count_verdicts(certification, strict), std::move(certification.claims),
                        std::move(certification.missing), summary.str()};
        });
        return to_python(judged);
      },
      "centres"_a, "weights"_a, "claim"_a, py::kw_only(), "format"_a = py::none(), "coord_tol"_a = 1e-9,
      "strict"_a = false, "threads"_a = 1, "report"_a = py::none(),
      R"(certify(centres, weights, claim, *, format=None, coord_tol=1e-9, strict=False, threads=1, report=None) -> Certification

Judges another implementation's vertex list for these sites against the exact diagram, claim by claim,
as the command line's 'certify' does (certify/README.md). Which points are vertices is decided exactly;
the only tolerance tells 'confirmed' from 'coordinates_off': |claimed - exact| <= coord_tol * max(S,
|exact|), S the largest |x|, |y|, |z|, |w| of the sites.

centres, weights: as for vertices().
claim: path (str or os.PathLike) of the claimed vertex list: our text or JSON output, or Voronota's
'calculate-vertices' output with or without --link; format: 'text', 'json', 'voronota' or None to
detect it by content.
strict: surplus claims (another claim of a vertex of 5 or more tied sites) count as discrepancies.
report: None, or a path to which the full JSON report is written atomically, as with --report (the
input is named "<arrays>").
Returns Certification: .passed, .counts, .verdicts, .vertex, .missing, .summary.
Raises ValueError for bad sites or a bad claim file ("FILE:LINE: reason", the command line's message),
OSError when the report cannot be written. Releases the GIL; Ctrl-C stops the diagram's computation.)");
}

}  // namespace apollonius::python
