// The parts of the Python module apollonius3d, one function per feature; module.cpp calls each once.
// Bindings only: every computation and every check of input is in the C++ layers.
#pragma once

#include <pybind11/pybind11.h>

namespace apollonius::python {

void bind_errors(pybind11::module_& module);      // errors.cpp: C++ exceptions as Python ones
void bind_read_sites(pybind11::module_& module);  // read_sites_binding.cpp
void bind_vertices(pybind11::module_& module);    // vertices_binding.cpp
void bind_diagram(pybind11::module_& module);     // diagram_binding.cpp
void bind_certify(pybind11::module_& module);     // certify_binding.cpp
void bind_contacts(pybind11::module_& module);    // contacts_binding.cpp
void bind_centroidal(pybind11::module_& module);  // centroidal_binding.cpp

}  // namespace apollonius::python
