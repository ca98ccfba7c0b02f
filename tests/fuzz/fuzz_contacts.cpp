// libFuzzer target: the contacts of a small ball set decoded from the bytes (fuzz_sites.h), with a probe
// of 0, 0.5 or 1.4. Every value and error must be finite and non-negative; each cell's volume and SAS at
// most its grown ball's; each face's area the same from both of its cells (the cells are integrated apart,
// each in its own frames) within the two estimates. Any exception is a finding, but Unmeasurable_pair.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <vector>

#include "fuzz/fuzz_sites.h"
#include "io/write_sites.h"
#include "measure/cell_cubature.h"
#include "measure/contact_measures.h"
#include "measure/exit_regions.h"

namespace {

using namespace apollonius;

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void report(const char* what, const std::vector<Site>& sites, double probe) {
  std::cerr << what << " (probe " << probe << ") on these sites:\n";
  write_sites_text(std::cerr, sites, "fuzz_contacts input");
  __builtin_trap();
}

bool finite_non_negative(double x) { return std::isfinite(x) && x >= 0; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return -1;
  const double probes[] = {0, 0.5, 1.4};
  const double probe = probes[data[0] % 3];
  std::vector<Site> sites;
  if (!fuzzing::decode_sites(data + 1, size - 1, sites)) return -1;
  static const bool print_sites = std::getenv("APOLLONIUS_FUZZ_PRINT_SITES") != nullptr;
  if (print_sites) {
    write_sites_text(std::cout, sites, "fuzz_contacts input");
    std::cout.flush();
  }
  // The measures are doubles: balls beyond 2^±60 of the unit would overflow their squares' products.
  for (const Site& s : sites)
    for (double v : {s.x, s.y, s.z, s.w})
      if (v != 0 && !(std::fabs(v) > 0x1p-60 && std::fabs(v) < 0x1p60)) return -1;
  Contact_measures m;
  try {
    m = measure_contacts(sites, {probe, 1e-6});
  } catch (const Unmeasurable_pair&) {
    return 0;  // two balls too close for doubles: refused by design (exit_regions.h)
  }
  for (std::size_t i = 0; i < sites.size(); ++i) {
    if (!finite_non_negative(m.volume[i]) || !finite_non_negative(m.volume_error[i]) ||
        !finite_non_negative(m.sas[i]) || !finite_non_negative(m.sas_error[i]))
      report("a volume, SAS or error is not a finite number >= 0", sites, probe);
    const double R = sites[i].w + probe;
    if (!(R > 0)) continue;
    const double rounding = 1e-12;
    if (m.volume[i] > 4 * kPi / 3 * R * R * R * (1 + rounding) + m.volume_error[i])
      report("a volume exceeds its grown ball's", sites, probe);
    if (m.sas[i] > 4 * kPi * R * R * (1 + rounding) + m.sas_error[i]) report("a SAS exceeds its sphere's", sites, probe);
  }
  for (const Contact& c : m.contacts)
    if (!finite_non_negative(c.area) || !finite_non_negative(c.error))
      report("a contact area or error is not a finite number >= 0", sites, probe);
  // Both sides of each face, each cell integrated alone (every other visible ball a candidate).
  std::vector<bool> hidden(sites.size(), false);
  for (const Hidden_site& h : m.hidden) hidden[h.site] = true;
  std::vector<Cell_measure> cells(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const double R = sites[i].w + probe;
    if (hidden[i] || !(R > 0)) continue;
    Cut_candidates candidates;
    candidates.clearance.fill(INFINITY);
    for (std::size_t j = 0; j < sites.size(); ++j)
      if (j != i && !hidden[j]) candidates.cuts.push_back(Radial_cut::between(sites[i], sites[j], static_cast<Site_index>(j)));
    const Axis_box box = box_beyond(sites[i], 2 * R);
    Cell_cubature_options options;
    options.clip_radius = R;
    options.median_integrals = false;
    options.relative_tolerance = 1e-6;
    cells[i] = integrate_cell(sites[i], candidates, box, options).measure;
  }
  for (std::size_t i = 0; i < sites.size(); ++i)
    for (const Cell_measure::Face_area& f : cells[i].contact_areas) {
      if (!finite_non_negative(f.area) || !finite_non_negative(f.error)) report("a face's area is not finite", sites, probe);
      const Cell_measure::Face_area* other = nullptr;
      for (const Cell_measure::Face_area& g : cells[f.site].contact_areas)
        if (g.site == i) other = &g;
      const double area = other ? other->area : 0, error = other ? other->error : 0;
      const double R = std::max(sites[i].w, sites[f.site].w) + probe;
      if (std::fabs(f.area - area) > f.error + error + 1e-12 * R * R) report("a face's two sides differ", sites, probe);
    }
  return 0;
}
