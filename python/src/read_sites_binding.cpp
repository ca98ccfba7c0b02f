// read_sites(path): the sites of a file as the command line reads them, with the atom labels of a structure.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "bindings.h"
#include "interruptible_call.h"
#include "io/read_sites.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace apollonius::python {
namespace {

// The code points of a name of a structure file: UTF-8, an invalid byte becoming U+FFFD (Python's decoder
// with "replace"); ASCII, the usual case, without Python.
std::u32string code_points(const std::string& text) {
  if (std::all_of(text.begin(), text.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; }))
    return std::u32string(text.begin(), text.end());
  const py::str decoded = py::reinterpret_steal<py::str>(
      PyUnicode_DecodeUTF8(text.data(), static_cast<py::ssize_t>(text.size()), "replace"));
  std::u32string points(static_cast<std::size_t>(PyUnicode_GET_LENGTH(decoded.ptr())), U'\0');
  if (!points.empty() && PyUnicode_AsUCS4(decoded.ptr(), reinterpret_cast<Py_UCS4*>(points.data()),
                                          static_cast<py::ssize_t>(points.size()), 0) == nullptr)
    throw py::error_already_set();
  return points;
}

// A str column (numpy's fixed-width UCS-4), written straight into the array that numpy allocates.
template <class Field>
py::array string_column(const std::vector<Atom_label>& labels, Field field) {
  std::size_t width = 1;  // numpy's narrowest str
  for (const Atom_label& label : labels) width = std::max(width, code_points(field(label)).size());
  py::array column = py::module_::import("numpy").attr("zeros")(labels.size(), "dtype"_a = "<U" + std::to_string(width));
  auto* out = static_cast<char32_t*>(column.mutable_data());
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const std::u32string points = code_points(field(labels[i]));
    std::copy(points.begin(), points.end(), out + i * width);
  }
  return column;
}

template <class Field>
py::array_t<std::int64_t> integer_column(const std::vector<Atom_label>& labels, Field field) {
  py::array_t<std::int64_t> column(static_cast<py::ssize_t>(labels.size()));
  std::transform(labels.begin(), labels.end(), column.mutable_data(), field);
  return column;
}

// Invariant: every column has one entry per site.
struct Atom_labels {
  py::array chain, residue_name, residue_number, insertion_code, atom_name, element, alternate_location, serial;
  std::size_t size;
};

Atom_labels labels_to_python(const std::vector<Atom_label>& labels) {
  // One-letter codes: '' when absent (' ' in the files).
  const auto code = [](char c) { return c == ' ' ? std::string() : std::string(1, c); };
  return Atom_labels{
      string_column(labels, [](const Atom_label& a) { return a.chain; }),
      string_column(labels, [](const Atom_label& a) { return a.residue_name; }),
      integer_column(labels, [](const Atom_label& a) { return std::int64_t{a.residue_number}; }),
      string_column(labels, [&](const Atom_label& a) { return code(a.insertion_code); }),
      string_column(labels, [](const Atom_label& a) { return a.atom_name; }),
      string_column(labels, [](const Atom_label& a) { return a.element; }),
      string_column(labels, [&](const Atom_label& a) { return code(a.alternate_location); }),
      integer_column(labels, [](const Atom_label& a) { return std::int64_t{a.serial}; }),
      labels.size()};
}

// Invariant: centres is (n, 3), weights (n,), labels None or n labels.
struct Sites {
  py::array_t<double> centres, weights;
  py::object labels;
  std::string format;
};

const char* format_name(Input_format format) {
  switch (format) {
    case Input_format::balls: return "balls";
    case Input_format::vdrc: return "vdrc";
    case Input_format::structure: return "structure";
  }
  return "unknown";
}

Sites sites_to_python(const Site_input& input) {
  const py::ssize_t n = static_cast<py::ssize_t>(input.sites.size());
  py::array_t<double> centres({n, py::ssize_t{3}}), weights(n);
  auto c = centres.mutable_unchecked<2>();
  auto w = weights.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const Site& s = input.sites[static_cast<std::size_t>(i)];
    c(i, 0) = s.x, c(i, 1) = s.y, c(i, 2) = s.z, w(i) = s.w;
  }
  py::object labels = py::none();
  if (input.format == Input_format::structure) labels = py::cast(labels_to_python(input.labels));
  return Sites{centres, weights, labels, format_name(input.format)};
}

}  // namespace

void bind_read_sites(py::module_& module) {
  py::class_<Atom_labels>(module, "AtomLabels",
                          "The atoms of the sites read from a structure file, one entry per site in each column\n"
                          "(numpy arrays): chain, residue_name, residue_number, insertion_code, atom_name,\n"
                          "element, alternate_location, serial. Absent one-letter codes are ''.")
      .def_readonly("chain", &Atom_labels::chain, "author chain names (str)")
      .def_readonly("residue_name", &Atom_labels::residue_name, "residue names, e.g. 'GLY' (str)")
      .def_readonly("residue_number", &Atom_labels::residue_number,
                    "author residue sequence numbers (int64; -999 where the file gives none)")
      .def_readonly("insertion_code", &Atom_labels::insertion_code, "insertion codes (str, '' for none)")
      .def_readonly("atom_name", &Atom_labels::atom_name, "atom names, e.g. 'CA' (str)")
      .def_readonly("element", &Atom_labels::element, "element symbols, e.g. 'C', 'Se' (str)")
      .def_readonly("alternate_location", &Atom_labels::alternate_location,
                    "alternate location codes (str, '' for none; only the first of an atom's is kept)")
      .def_readonly("serial", &Atom_labels::serial, "atom serial numbers (int64; mmCIF: _atom_site.id)")
      .def("__len__", [](const Atom_labels& l) { return l.size; }, "The number of atoms.")
      .def("__repr__", [](const Atom_labels& l) { return "<AtomLabels of " + std::to_string(l.size) + " atoms>"; });

  py::class_<Sites>(module, "Sites",
                    "The sites of an input file: centres (n, 3) and weights (n,), float64, in file order; labels\n"
                    "(AtomLabels) for a structure file, else None; format: 'balls', 'vdrc' or 'structure'.\n"
                    "Unpacks as centres, weights: vertices(*read_sites(path)) computes its vertices.")
      .def_readonly("centres", &Sites::centres, "the ball centres or atom positions, (n, 3) float64")
      .def_readonly("weights", &Sites::weights, "the weights: radii, for atoms van der Waals radii (Bondi 1964), (n,) float64")
      .def_readonly("labels", &Sites::labels, "AtomLabels for a structure file, None for balls and vdrc inputs")
      .def_readonly("format", &Sites::format, "'balls', 'vdrc' or 'structure'")
      .def("__len__", [](const Sites& s) { return s.weights.size(); }, "The number of sites.")
      .def("__iter__", [](const Sites& s) { return py::iter(py::make_tuple(s.centres, s.weights)); },
           "Iterates over centres, weights, so that a Sites unpacks into the arguments of vertices().")
      .def("__repr__", [](const Sites& s) {
        return "<Sites: " + std::to_string(s.weights.size()) + " sites from " + s.format + " input>";
      });

  module.def(
      "read_sites",
      [](const py::object& path, bool keep_hydrogens, bool keep_waters) {
        const std::string file = py::str(py::module_::import("os").attr("fsdecode")(path));
        Read_options options;
        options.keep_hydrogens = keep_hydrogens;
        options.keep_waters = keep_waters;
        options.atom_labels = true;
        const Site_input input = interruptible_call([&](const Cancellation&) { return read_sites(file, options); });
        return sites_to_python(input);
      },
      "path"_a, py::kw_only(), "keep_hydrogens"_a = false, "keep_waters"_a = false,
      R"(read_sites(path, *, keep_hydrogens=False, keep_waters=False) -> Sites

The sites of a file, read as the command line reads them (docs/contract.md, "Inputs"): balls text
'x y z w', the vdrc format, or a PDB or mmCIF structure (.pdb .ent .cif .mmcif, optionally .gz), whose
atoms become balls with van der Waals radii. Hydrogens and waters are left out unless kept; of alternate
locations the first is kept.

path: str or os.PathLike; "-" reads standard input.
Returns Sites: .centres (n, 3), .weights (n,), .labels (AtomLabels, structures only), .format.
Raises ValueError with the command line's message ("FILE:LINE: reason") for a missing, unreadable,
empty or malformed file. Reading releases the GIL.)");
}

}  // namespace apollonius::python
