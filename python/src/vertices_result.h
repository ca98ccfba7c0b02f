// The vertices of a diagram as numpy arrays, the vertex JSON's content (docs/contract.md, "Vertex JSON"):
// what vertices() returns, and the vertices of diagram()'s result.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>

#include "diagram/diagram.h"

namespace apollonius::python {

// Compressed rows: the tie set of row i is sites[offsets[i]:offsets[i + 1]].
// Invariant: offsets has one entry per row and one more, from 0 to len(sites), ascending.
struct Tie_sets {
  pybind11::array_t<std::int64_t> offsets, sites;
  std::size_t size() const { return static_cast<std::size_t>(offsets.size() - 1); }
};

// Invariant: the three arrays have one entry per hidden site, ascending by site.
struct Hidden_sites {
  pybind11::array_t<std::int64_t> site, hidden_by;
  pybind11::array_t<bool> duplicate;
};

struct Vertices_result {
  std::size_t site_count;
  pybind11::array_t<double> points;  // (m, 4): x, y, z, r
  Tie_sets tie_sets;
  Hidden_sites hidden;
  pybind11::array_t<std::int64_t> sites_without_vertex;
  pybind11::object stats;  // None unless asked for
};

// The hidden sites as arrays (vertices(), contacts()).
Hidden_sites hidden_to_python(const std::vector<Hidden_site>& hidden);

// The one copy of the vertices: from the Diagram into arrays that numpy allocates and owns.
Vertices_result vertices_to_python(const Diagram& diagram, pybind11::object stats);

// The Python classes Vertices, TieSets and HiddenSites.
void bind_vertices_result(pybind11::module_& module);

}  // namespace apollonius::python
