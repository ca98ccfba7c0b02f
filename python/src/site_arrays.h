// Sites from Python: centres (n, 3) and weights (n,), any array-like that converts to float64 exactly.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

#include "predicates/site.h"

namespace apollonius::python {

// A C-contiguous float64 array of the values of `values` (`name` in messages): a float64 array itself
// when it is one, otherwise one conversion. Values that have no exact double (large integers, long
// doubles, fractions) and arrays of no number type (strings, complex, bool) are bad input: the exact
// diagram of other numbers than those given would be silently wrong.
pybind11::array_t<double, pybind11::array::c_style> exact_float64_array(pybind11::handle values, const char* name);

// The sites of centres (n, 3) and weights (n,), checked by io/read_sites.h's sites_from_arrays. Bad input
// raises Input_error (ValueError in Python).
std::vector<Site> sites_from_python(pybind11::handle centres, pybind11::handle weights);

}  // namespace apollonius::python
