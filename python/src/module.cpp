// The Python module apollonius3d (python/README.md): the exact 3D Apollonius diagram over numpy arrays.
#include <pybind11/pybind11.h>

#include "bindings.h"

PYBIND11_MODULE(apollonius3d, module) {
  module.doc() =
      "apollonius3d: the exact 3D Apollonius diagram (additively weighted Voronoi diagram, Voronoi diagram of\n"
      "balls), every decision an exact sign.\n\n"
      "Sites are centres (n, 3) and weights (n,), float64 (any array-like converts if it does so exactly);\n"
      "site indices in every result are 0-based, in input order.\n\n"
      "read_sites(path)            balls text, vdrc, PDB or mmCIF: centres, weights, atom labels\n"
      "vertices(centres, weights)  every vertex of the diagram with its whole tie set\n"
      "diagram(centres, weights)   the whole diagram: vertices, edges, faces, cells\n"
      "certify(centres, weights, claim)  another program's vertex list, judged claim by claim\n"
      "contacts(centres, weights)  contact areas, SAS and volumes within the probe (approximate)\n"
      "centroidal(centres, weights, domain)  the centroidal Apollonius diagram in a box\n\n"
      "Bad input raises ValueError with the command line's message; internal errors raise RuntimeError.\n"
      "Computations release the GIL, and Ctrl-C stops them within a fraction of a second.";
  module.attr("__version__") = APOLLONIUS3D_VERSION;
  // Each docstring starts with its signature, written for people (pybind11's shows "object" for arrays).
  pybind11::options options;
  options.disable_function_signatures();
  apollonius::python::bind_errors(module);
  apollonius::python::bind_read_sites(module);
  apollonius::python::bind_vertices(module);
  apollonius::python::bind_diagram(module);
  apollonius::python::bind_certify(module);
  apollonius::python::bind_contacts(module);
  apollonius::python::bind_centroidal(module);
}
