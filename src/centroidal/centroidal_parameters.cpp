#include "centroidal/centroidal_parameters.h"

#include <array>
#include <cmath>
#include <map>

#include "io/read_masses.h"
#include "io/round_trip.h"

namespace apollonius {
namespace {

[[noreturn]] void refuse(Centroidal_parameter parameter, const std::string& reason, long site = -1) {
  throw Centroidal_parameter_error(parameter, reason, site);
}

std::string printed(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return round_trip(value);
}

}  // namespace

void check_centroidal_domain(const Axis_box& domain) {
  for (const double* bounds : {domain.lo.data(), domain.hi.data()})
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(bounds[a])) refuse(Centroidal_parameter::domain, "needs a finite number, not " + printed(bounds[a]));
  for (int a = 0; a < 3; ++a)
    if (!(domain.lo[a] < domain.hi[a]))
      refuse(Centroidal_parameter::domain, "needs X0 < X1, Y0 < Y1 and Z0 < Z1 (a box with a volume)");
}

void check_centroidal_tolerance(double tolerance, Centroidal_parameter which) {
  if (!(tolerance >= kLeastCentroidalTolerance && tolerance <= kGreatestCentroidalTolerance))
    refuse(which, "must lie in [1e-10, 0.5], not " + printed(tolerance));
}

void check_centroidal_iterations(int max_iterations) {
  if (max_iterations < 1 || max_iterations > kMostCentroidalIterations)
    refuse(Centroidal_parameter::max_iterations, "needs an integer from 1 to " +
                                                     std::to_string(kMostCentroidalIterations) + ", not " +
                                                     std::to_string(max_iterations));
}

void check_centroidal_sites(const std::vector<Site>& sites, const std::vector<double>& fractions,
                            const Axis_box& domain) {
  if (sites.empty()) refuse(Centroidal_parameter::sites, "no sites");
  // The masses as read_masses (io/read_masses.h) checks a file of them, in its order, with its reasons.
  double sum = 0;
  for (std::size_t i = 0; i < fractions.size(); ++i) {
    const long at = static_cast<long>(i);
    if (!std::isfinite(fractions[i]))
      refuse(Centroidal_parameter::masses, "not a finite number: " + printed(fractions[i]), at);
    if (!(fractions[i] > 0))
      refuse(Centroidal_parameter::masses, "a mass must be positive, not " + printed(fractions[i]), at);
    if (i == sites.size())
      refuse(Centroidal_parameter::masses, "more masses than the " + std::to_string(sites.size()) + " sites", at);
    sum += fractions[i];
  }
  if (fractions.size() != sites.size())
    refuse(Centroidal_parameter::masses,
           std::to_string(fractions.size()) + " masses for " + std::to_string(sites.size()) + " sites");
  if (!(std::fabs(sum - 1) <= kMassSumTolerance))
    refuse(Centroidal_parameter::masses, "the masses sum to " + round_trip(sum) + ", not 1 (within 1e-9)");
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const double x[3] = {sites[i].x, sites[i].y, sites[i].z};
    for (int a = 0; a < 3; ++a)
      if (!(domain.lo[a] <= x[a] && x[a] <= domain.hi[a]))
        refuse(Centroidal_parameter::sites,
               "the site (" + round_trip(x[0]) + ", " + round_trip(x[1]) + ", " + round_trip(x[2]) +
                   ") lies outside the domain",
               static_cast<long>(i));
  }
  std::map<std::array<double, 3>, std::size_t> centres;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const auto [it, inserted] = centres.insert({{sites[i].x, sites[i].y, sites[i].z}, i});
    if (!inserted)
      refuse(Centroidal_parameter::sites,
             "the site has the centre of site " + std::to_string(it->second) +
                 " (0-based): one would hide the other for any weights",
             static_cast<long>(i));
  }
}

}  // namespace apollonius
