// The parameters of a centroidal Apollonius diagram (centroidal_diagram.h) and their checks, shared by the
// library, the command line and the Python module, so that all three refuse the same parameters with the
// same reason. Each check throws Centroidal_parameter_error naming the parameter and, where one is at
// fault, the 0-based site or mass; the callers add the file and line, or the array's name.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "predicates/axis_box.h"
#include "predicates/site.h"

namespace apollonius {

enum class Centroidal_parameter { domain, sites, masses, tolerance, median_tolerance, max_iterations };

// The reason says what is wrong without naming the parameter ("must lie in [1e-10, 0.5], not 0"); site is
// the 0-based site or mass it is about, or -1.
struct Centroidal_parameter_error : std::invalid_argument {
  Centroidal_parameter_error(Centroidal_parameter parameter, const std::string& reason, long site)
      : std::invalid_argument(reason), parameter(parameter), site(site) {}
  Centroidal_parameter parameter;
  long site;
};

// The loosest and tightest tolerances: below 1e-10 the cubature's rounding (about 1e-14 relative per
// cell) and its error estimates leave too little room.
inline constexpr double kLeastCentroidalTolerance = 1e-10, kGreatestCentroidalTolerance = 0.5;
inline constexpr int kMostCentroidalIterations = 100000;

// Finite, with X0 < X1, Y0 < Y1 and Z0 < Z1.
void check_centroidal_domain(const Axis_box& domain);
// In [kLeastCentroidalTolerance, kGreatestCentroidalTolerance]; `which` names it in the error (the
// tolerance of the volumes, or that of the medians).
void check_centroidal_tolerance(double tolerance, Centroidal_parameter which = Centroidal_parameter::tolerance);
// From 1 to kMostCentroidalIterations.
void check_centroidal_iterations(int max_iterations);
// At least one site; one mass fraction per site, each positive and finite, summing to 1 within
// kMassSumTolerance (io/read_masses.h); every centre in the closed domain; no two sites at one centre (one would hide the
// other whatever the weights, so that cell could never have a volume).
void check_centroidal_sites(const std::vector<Site>& sites, const std::vector<double>& mass_fractions,
                            const Axis_box& domain);

}  // namespace apollonius
