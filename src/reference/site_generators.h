// Reproducible site sets for tests and users (`apollonius3d generate`): each family stresses one kind
// of degeneracy. Coordinates are small integers or dyadic fractions so that the sets are exact as written.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "predicates/site.h"

namespace apollonius {

enum class Site_family {
  uniform,
  equal_weights,
  lattice,
  coplanar,
  collinear,
  nested,
  tangent,
  mixed_sign,
  duplicates,
  cospherical,
  scaled_up,
  scaled_down,
  lattice_noise,
  far_vertices,
  wide_range,
  sphere_tangent,
  circle_tangent,
  two_spheres,
  shells,
  circle,
  circle_mixed,
};

struct Site_family_description {
  Site_family family;
  const char* name;     // on the command line and in test messages
  const char* summary;  // one line: what the family stresses
};

// Every family, in enum order; `apollonius3d generate --list` prints this table.
inline constexpr Site_family_description kSiteFamilies[] = {
    {Site_family::uniform, "uniform", "random integer centres in a cube, random weights"},
    {Site_family::equal_weights, "equal-weights", "random centres, one weight: the vertices are Delaunay circumcentres"},
    {Site_family::lattice, "lattice", "integer lattice points with two weights: massively cospherical"},
    {Site_family::coplanar, "coplanar", "every centre in the plane z = 0"},
    {Site_family::collinear, "collinear", "groups of centres on a few lines"},
    {Site_family::nested, "nested", "balls inside (or tangent inside) other balls: hidden sites"},
    {Site_family::tangent, "tangent", "pairs of externally tangent balls"},
    {Site_family::mixed_sign, "mixed-sign", "weights of both signs"},
    {Site_family::duplicates, "duplicates", "exact repeats of earlier sites"},
    {Site_family::cospherical, "cospherical", "many balls tangent to one sphere"},
    {Site_family::scaled_up, "scaled-up", "uniform, scaled by 2^300"},
    {Site_family::scaled_down, "scaled-down", "uniform, scaled by 2^-300"},
    {Site_family::lattice_noise, "lattice-noise", "lattice points moved by one ulp: vertices nearly, but not exactly, coincide"},
    {Site_family::far_vertices, "far-vertices", "nearly cocircular points above a cloud: vertices 10^6 input diameters away"},
    {Site_family::wide_range, "wide-range", "uniform, one site in eight scaled by 2^k and one by 2^-k, k from 20 to 900"},
    {Site_family::sphere_tangent, "sphere-tangent", "every ball tangent to one sphere, integer centres: all tie at its centre"},
    {Site_family::circle_tangent, "circle-tangent", "coplanar integer centres, every ball tangent to one circle: all tie at its centre"},
    {Site_family::two_spheres, "two-spheres", "every ball tangent to two equal spheres: all tie at both centres"},
    {Site_family::shells, "shells", "concentric shells of integer points, one weight per shell"},
    {Site_family::circle, "circle", "centres on one circle with one weight (all tie along its axis), one site in eight elsewhere"},
    {Site_family::circle_mixed, "circle-mixed", "centres on one circle, weights from three values"},
};

const std::vector<std::string>& site_family_names();
Site_family site_family_from_name(const std::string& name);  // throws std::invalid_argument
const char* name_of(Site_family family);

// n sites of the family from `seed`; the same arguments give the same sites on every platform.
std::vector<Site> generate_sites(Site_family family, std::size_t n, std::uint64_t seed);

}  // namespace apollonius
