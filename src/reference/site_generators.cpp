#include "reference/site_generators.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <stdexcept>

namespace apollonius {
namespace {

// SplitMix64: fixed, portable output, unlike the std distributions.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform integer in [low, high].
  long integer(long low, long high) { return low + static_cast<long>(next() % static_cast<std::uint64_t>(high - low + 1)); }
  // A multiple of 1/8 in [low, high].
  double eighths(long low, long high) { return static_cast<double>(integer(8 * low, 8 * high)) / 8.0; }

 private:
  std::uint64_t state_;
};

// name_of indexes kSiteFamilies by the enum's value: the table must list every family, in enum order.
constexpr bool lists_every_family_in_enum_order() {
  std::size_t i = 0;
  for (const Site_family_description& d : kSiteFamilies)
    if (static_cast<std::size_t>(d.family) != i++) return false;
  return i == static_cast<std::size_t>(Site_family::wide_range) + 1;
}
static_assert(lists_every_family_in_enum_order());

Site random_site(Random& random, long extent, double min_weight, double max_weight) {
  return {random.eighths(-extent, extent), random.eighths(-extent, extent), random.eighths(-extent, extent),
          static_cast<double>(random.integer(static_cast<long>(8 * min_weight), static_cast<long>(8 * max_weight))) / 8.0};
}

}  // namespace

const char* name_of(Site_family family) { return kSiteFamilies[static_cast<std::size_t>(family)].name; }

const std::vector<std::string>& site_family_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const Site_family_description& d : kSiteFamilies) v.push_back(d.name);
    return v;
  }();
  return names;
}

Site_family site_family_from_name(const std::string& name) {
  for (const Site_family_description& d : kSiteFamilies)
    if (name == d.name) return d.family;
  throw std::invalid_argument("unknown site family '" + name + "'");
}

std::vector<Site> generate_sites(Site_family family, std::size_t n, std::uint64_t seed) {
  if (family == Site_family::scaled_up || family == Site_family::scaled_down) {
    std::vector<Site> sites = generate_sites(Site_family::uniform, n, seed);
    const int e = family == Site_family::scaled_up ? 300 : -300;
    for (Site& s : sites) s = scaled_by_power_of_two(s, e);
    return sites;
  }
  if (family == Site_family::lattice_noise) {
    std::vector<Site> sites = generate_sites(Site_family::lattice, n, seed);
    Random random(seed);
    for (Site& s : sites)
      for (double* c : {&s.x, &s.y, &s.z}) {
        const long step = random.integer(-1, 1);
        if (step != 0) *c = std::nextafter(*c, step * INFINITY);
      }
    return sites;
  }
  Random random(seed * 0x2545F4914F6CDD1Dull + static_cast<std::uint64_t>(family));
  std::vector<Site> sites;
  sites.reserve(n);
  std::set<std::array<double, 4>> lattice_sites;  // the lattice family's sites so far: repeats found in O(log n)
  while (sites.size() < n) {
    switch (family) {
      case Site_family::uniform: sites.push_back(random_site(random, 10, 0.5, 3)); break;
      case Site_family::equal_weights: {
        Site s = random_site(random, 10, 1, 1);
        sites.push_back(s);
        break;
      }
      case Site_family::lattice: {
        long side = 1;  // at least twice as many lattice points as sites, so that the loop ends quickly
        while ((side + 1) * (side + 1) * (side + 1) < 2 * static_cast<long>(n)) ++side;
        const Site s{4.0 * random.integer(0, side), 4.0 * random.integer(0, side), 4.0 * random.integer(0, side),
                     random.integer(0, 1) ? 1.0 : 1.5};
        // Lattice points repeat; a repeat is a duplicate site, which the duplicates family covers.
        if (lattice_sites.insert({s.x, s.y, s.z, s.w}).second) sites.push_back(s);
        break;
      }
      case Site_family::coplanar: {
        Site s = random_site(random, 10, 0.5, 3);
        s.z = 0;
        sites.push_back(s);
        break;
      }
      case Site_family::collinear: {
        // Points on one of three axis-parallel lines through random integer points.
        const long line = random.integer(0, 2);
        const double t = random.eighths(-10, 10);
        const double offset[3][3] = {{0, 1, -2}, {3, 0, 1}, {-1, 2, 0}};
        Site s{offset[line][0], offset[line][1], offset[line][2], static_cast<double>(random.integer(1, 8)) / 4.0};
        (line == 0 ? s.x : line == 1 ? s.y : s.z) += t;
        sites.push_back(s);
        break;
      }
      case Site_family::nested: {
        if (!sites.empty() && random.integer(0, 2) == 0) {
          // A ball inside (sometimes tangent inside) an earlier one: centre offset 1/8 along x.
          const Site& outer = sites[static_cast<std::size_t>(random.integer(0, static_cast<long>(sites.size()) - 1))];
          const double w = outer.w - 0.125 * static_cast<double>(random.integer(1, 2));
          sites.push_back({outer.x + 0.125, outer.y, outer.z, w});
        } else {
          sites.push_back(random_site(random, 10, 1, 3));
        }
        break;
      }
      case Site_family::tangent: {
        // Externally tangent pairs along an axis: |x_i - x_j| = w_i + w_j.
        Site s = random_site(random, 10, 1, 2);
        sites.push_back(s);
        if (sites.size() < n) sites.push_back({s.x + s.w + 1.5, s.y, s.z, 1.5});
        break;
      }
      case Site_family::mixed_sign: sites.push_back(random_site(random, 10, -2, 2)); break;
      case Site_family::duplicates: {
        if (!sites.empty() && random.integer(0, 3) == 0)
          sites.push_back(sites[static_cast<std::size_t>(random.integer(0, static_cast<long>(sites.size()) - 1))]);
        else
          sites.push_back(random_site(random, 10, 0.5, 3));
        break;
      }
      case Site_family::far_vertices: {
        // Four points on the unit circle of the plane z = 0, one lifted by 2^-20: their circumsphere is
        // about 10^6 times their size. The other sites lie below z = -2, clear of that sphere.
        if (sites.empty()) {
          const double lift = std::ldexp(1.0, -20) * static_cast<double>(random.integer(1, 3));
          sites = {{1, 0, 0, 0.25}, {0, 1, 0, 0.25}, {-1, 0, 0, 0.25}, {0, -1, lift, 0.25}};
          while (sites.size() > n) sites.pop_back();
        } else {
          sites.push_back({random.eighths(-2, 2), random.eighths(-2, 2), random.eighths(-6, -2), 0.25});
        }
        break;
      }
      case Site_family::wide_range: {
        // Small clusters seen from far away, and far balls seen from a small cluster.
        Site s = random_site(random, 10, 0.5, 3);
        const long choice = random.integer(0, 7);
        if (choice < 2) {
          const int e = static_cast<int>(random.integer(20, 900)) * (choice == 0 ? 1 : -1);
          s = scaled_by_power_of_two(s, e);
        }
        sites.push_back(s);
        break;
      }
      case Site_family::scaled_up:
      case Site_family::scaled_down:
      case Site_family::lattice_noise:
        break;  // built from other families above
      case Site_family::cospherical: {
        // Balls tangent to the sphere of radius 2 about the origin from outside: centre on an axis at
        // distance c, weight c - 2.
        const long axis = random.integer(0, 5);
        const double c = static_cast<double>(random.integer(20, 80)) / 8.0;
        Site s{0, 0, 0, c - 2};
        const double sign = axis % 2 ? -1.0 : 1.0;
        (axis / 2 == 0 ? s.x : axis / 2 == 1 ? s.y : s.z) = sign * c;
        if (std::none_of(sites.begin(), sites.end(), [&](const Site& t) { return t.x == s.x && t.y == s.y && t.z == s.z; }))
          sites.push_back(s);
        else
          sites.push_back(random_site(random, 10, 0.5, 1));
        break;
      }
    }
  }
  return sites;
}

}  // namespace apollonius
