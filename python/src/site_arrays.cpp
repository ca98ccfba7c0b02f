#include "site_arrays.h"

#include <string>

#include "io/input_error.h"
#include "io/read_sites.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace apollonius::python {
namespace {

std::string shape_of(const py::array& array) {
  std::string shape = "(";
  for (py::ssize_t k = 0; k < array.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(array.shape(k));
  return shape + (array.ndim() == 1 ? ",)" : ")");
}

// The message of the Python exception being handled, for Input_error's reason.
std::string message_of(const py::error_already_set& error) { return py::str(error.value()); }

}  // namespace

py::array_t<double, py::array::c_style> exact_float64_array(py::handle values, const char* name) {
  const py::module_ numpy = py::module_::import("numpy");
  py::array array;
  try {
    array = numpy.attr("asarray")(values);
  } catch (const py::error_already_set& e) {
    throw Input_error(name, 0, "not an array of numbers: " + message_of(e));
  }
  const char kind = array.dtype().kind();
  const std::string dtype = py::str(array.dtype());
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'O')
    throw Input_error(name, 0, "expected numbers, found an array of dtype " + dtype);
  py::array_t<double, py::array::c_style> converted;
  try {
    converted = numpy.attr("asarray")(array, "dtype"_a = "float64", "order"_a = "C");
  } catch (const py::error_already_set& e) {
    throw Input_error(name, 0, "cannot convert to float64: " + message_of(e));
  }
  const bool always_exact = kind == 'f' && array.dtype().itemsize() <= 8;  // float16, float32, float64
  if (!always_exact) {
    // Converted back to the original type, each finite value must be what it was (Python compares ints,
    // floats, Fractions and Decimals exactly). Non-finite values are left to sites_from_arrays. Casting
    // 2^64 back to uint64 overflows: numpy's warning about it is silenced, the value is refused.
    const py::object quiet = numpy.attr("errstate")("invalid"_a = "ignore", "over"_a = "ignore");
    quiet.attr("__enter__")();
    py::array where;
    try {
      const py::array finite = numpy.attr("isfinite")(converted);
      const py::array differs = numpy.attr("logical_and")(
          finite, numpy.attr("not_equal")(converted.attr("astype")(array.dtype()), array));
      where = numpy.attr("flatnonzero")(differs);
    } catch (...) {
      quiet.attr("__exit__")(py::none(), py::none(), py::none());
      throw;
    }
    quiet.attr("__exit__")(py::none(), py::none(), py::none());
    if (where.size() > 0) {
      const py::ssize_t first = where.attr("__getitem__")(0).cast<py::ssize_t>();
      const py::object value = array.attr("flat").attr("__getitem__")(first);
      std::string place = std::to_string(first);
      if (array.ndim() == 2 && array.shape(1) == 3)
        place = "site " + std::to_string(first / 3) + ", " + std::string(1, "xyz"[first % 3]);
      else if (array.ndim() == 1)
        place = "site " + std::to_string(first);
      throw Input_error(name, 0, place + ": " + std::string(py::str(value)) + " (" + dtype +
                                     ") is not exactly a double; round it first if that is meant");
    }
  }
  return converted;
}

std::vector<Site> sites_from_python(py::handle centres, py::handle weights) {
  const py::array_t<double, py::array::c_style> c = exact_float64_array(centres, "centres");
  if (c.ndim() != 2 || c.shape(1) != 3) throw Input_error("centres", 0, "expected shape (n, 3), found " + shape_of(c));
  const py::array_t<double, py::array::c_style> w = exact_float64_array(weights, "weights");
  if (w.ndim() != 1 || w.shape(0) != c.shape(0))
    throw Input_error("weights", 0, "expected shape (" + std::to_string(c.shape(0)) + ",), one per centre, found " +
                                        shape_of(w));
  return sites_from_arrays(c.data(), w.data(), static_cast<std::size_t>(c.shape(0)));
}

}  // namespace apollonius::python
