// Contacts between balls as Voronota's calculate-contacts defines them, on the exact Apollonius diagram
// (SPEC section 8): with the probe P, contact(i, j) = area of the face of i and j where d_i <= P; sas(i) =
// area of the sphere |x - x_i| = w_i + P inside the cell of i; volume(i) = volume of the cell where d_i <=
// P. APPROXIMATE: cubatures of each cell clipped by its ball of radius w_i + P (cell_cubature.h), each with
// an ERROR ESTIMATE. Which sites are hidden (no cell, no contact) is decided exactly.
#pragma once

#include <cstddef>
#include <vector>

#include "diagram/cancellation.h"
#include "diagram/diagram.h"
#include "predicates/site.h"

namespace apollonius {

struct Contact_options {
  double probe = 1.4;                 // P >= 0, Voronota's default
  double relative_tolerance = 1e-4;   // per cell: estimated errors <= this x its clipped volume and area
  int threads = 1;
  const Cancellation* cancellation = nullptr;  // checked once per cell, and per panel of its cubature
};

// Invariant: a < b; the mean of the integrals over both cells, its error the mean of their estimates plus
// half their difference (the two sides are independent cubatures of one face).
struct Contact {
  Site_index a, b;
  double area, error;
};

struct Contact_measures {
  std::vector<Contact> contacts;     // ascending (a, b), every face with some area where d <= P
  std::vector<double> sas, sas_error, volume, volume_error;  // per site: 0 for hidden sites and for w <= -P
  std::vector<Hidden_site> hidden;   // ascending, exact (site_set.h)
  std::size_t directions = 0;        // rays evaluated, over all cells
};

// Cost: the hidden-site sweep, then per cell one cubature over the sites whose probe-grown balls meet its
// own (found in a grid of cell side 2 max(w + P): O(n) for atoms, O(n^2) if one ball dwarfs the rest). The
// result is the same for every thread count. Throws std::invalid_argument for a probe that is negative or
// not finite, or a tolerance outside (0, 0.5]; Unmeasurable_pair (exit_regions.h) for two balls within
// about 1e-4 of their grown radius of each other, neither hiding the other.
Contact_measures measure_contacts(const std::vector<Site>& sites, const Contact_options& options = {});

}  // namespace apollonius
