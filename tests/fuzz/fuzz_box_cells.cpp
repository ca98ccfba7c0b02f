// libFuzzer target: the cell measures in a box (measure_cells, box cells by the regions of one exit where
// they apply, box_cell_regions.h) of a small site set decoded from the bytes (fuzz_sites.h), in the box
// around the sites grown by a margin. The cells partition the box, so their volumes must add up to its
// volume within their estimates; every value and error must be finite, every volume and distance integral
// non-negative, every direction integral no longer than its volume (|u| = 1), every volume derivative
// d m_i / d w_j <= 0. Any exception is a finding but the line cubature's refusal of a pair hidden in
// floating point only (cell_cubature.h).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz/fuzz_sites.h"
#include "io/round_trip.h"
#include "io/write_sites.h"
#include "measure/cell_measures.h"
#include "octree/octree_diagram.h"

namespace {

using namespace apollonius;

// The box as six round-trip numbers, lo then hi.
std::string box_text(const Axis_box& box) {
  return round_trip(box.lo[0]) + ' ' + round_trip(box.lo[1]) + ' ' + round_trip(box.lo[2]) + ' ' +
         round_trip(box.hi[0]) + ' ' + round_trip(box.hi[1]) + ' ' + round_trip(box.hi[2]);
}

[[noreturn]] void report(const char* what, const std::vector<Site>& sites, const Axis_box& box) {
  std::cerr << what << " in the box " << box_text(box) << " on these sites:\n";
  write_sites_text(std::cerr, sites, "fuzz_box_cells input");
  __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<Site> sites;
  if (!fuzzing::decode_sites(data, size, sites)) return -1;
  // The measures are doubles: keep every value within 2^+-30 of the unit (or 0), so that the cells'
  // scales stay within what a relative tolerance of 1e-6 can see next to the box's.
  for (const Site& s : sites)
    for (double v : {s.x, s.y, s.z, s.w})
      if (v != 0 && !(std::fabs(v) > 0x1p-30 && std::fabs(v) < 0x1p30)) return -1;
  Axis_box box{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  for (const Site& s : sites) {
    const double c[3] = {s.x, s.y, s.z};
    for (int a = 0; a < 3; ++a) box.lo[a] = std::min(box.lo[a], c[a]), box.hi[a] = std::max(box.hi[a], c[a]);
  }
  double extent = 0;
  for (int a = 0; a < 3; ++a) extent = std::max(extent, box.hi[a] - box.lo[a]);
  const double margin = 0.25 * extent + 1;
  for (int a = 0; a < 3; ++a) box.lo[a] -= margin, box.hi[a] += margin;
  static const bool print_input = std::getenv("APOLLONIUS_FUZZ_PRINT_SITES") != nullptr;
  if (print_input) {
    std::cout << "box " << box_text(box) << '\n';
    write_sites_text(std::cout, sites, "fuzz_box_cells input");
    std::cout.flush();
  }
  std::vector<Cell_measure> m;
  try {
    m = measure_cells(sites, octree_diagram(sites), box, {1e-6, 1});
  } catch (const std::domain_error&) {
    return 0;  // a pair hidden in floating point only: refused by the line cubature, by design
  }
  const double volume = (box.hi[0] - box.lo[0]) * (box.hi[1] - box.lo[1]) * (box.hi[2] - box.lo[2]);
  double total = 0, errors = 0;
  for (const Cell_measure& c : m) {
    for (double v : {c.volume, c.volume_error, c.distance_integral, c.distance_error, c.direction_error})
      if (!std::isfinite(v) || v < 0) report("a volume, distance integral or error is not a finite number >= 0", sites, box);
    const double direction = std::sqrt(dot(c.direction_integral, c.direction_integral));
    if (!(direction <= c.volume * (1 + 1e-9) + c.volume_error + c.direction_error))
      report("a direction integral is longer than its volume", sites, box);
    for (const auto& [j, derivative] : c.volume_derivatives)
      if (!std::isfinite(derivative) || derivative > 1e-9 * volume) report("a volume derivative is positive", sites, box);
    total += c.volume, errors += c.volume_error;
  }
  if (std::fabs(total - volume) > errors + 1e-9 * volume) report("the volumes do not add up to the box's", sites, box);
  return 0;
}
