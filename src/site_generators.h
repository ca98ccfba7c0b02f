// Reproducible site sets for tests and users (`generate` in a later issue): each family stresses one kind
// of degeneracy. Coordinates are small integers or dyadic fractions so that the sets are exact as written.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "site.h"

namespace apollonius {

enum class Site_family {
  uniform,        // random integer centres in a cube, random weights
  equal_weights,  // random centres, one weight: the vertices are Delaunay circumcentres
  lattice,        // integer lattice points with two weights: massively cospherical
  coplanar,       // every centre in the plane z = 0
  collinear,      // groups of centres on a few lines
  nested,         // balls inside (or tangent inside) other balls: hidden sites
  tangent,        // pairs of externally tangent balls
  mixed_sign,     // weights of both signs
  duplicates,     // exact repeats of earlier sites
  cospherical,    // many balls tangent to one sphere
  scaled_up,      // uniform, scaled by 2^300
  scaled_down,    // uniform, scaled by 2^-300
  lattice_noise,  // lattice points moved by one ulp: vertices nearly, but not exactly, coincide
  far_vertices,   // nearly cocircular points above a cloud: vertices 10^6 input diameters away
};

const std::vector<std::string>& site_family_names();
Site_family site_family_from_name(const std::string& name);  // throws std::invalid_argument
const char* name_of(Site_family family);

// n sites of the family from `seed`; the same arguments give the same sites on every platform.
std::vector<Site> generate_sites(Site_family family, std::size_t n, std::uint64_t seed);

}  // namespace apollonius
