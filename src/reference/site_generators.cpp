#include "reference/site_generators.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
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
  return i == static_cast<std::size_t>(Site_family::circle_mixed) + 1;
}
static_assert(lists_every_family_in_enum_order());

Site random_site(Random& random, long extent, double min_weight, double max_weight) {
  return {random.eighths(-extent, extent), random.eighths(-extent, extent), random.eighths(-extent, extent),
          static_cast<double>(random.integer(static_cast<long>(8 * min_weight), static_cast<long>(8 * max_weight))) / 8.0};
}


// An integer vector and its integer length.
struct Integer_point {
  long long x, y, z, norm;
};

// (a^2 + b^2 - c^2 - d^2, 2(ad + bc), 2(bd - ac)) has the integer length a^2 + b^2 + c^2 + d^2 (Euler's
// four-square identity); every primitive Pythagorean quadruple is of this form.
Integer_point pythagorean_quadruple(long long a, long long b, long long c, long long d) {
  return {a * a + b * b - c * c - d * d, 2 * (a * d + b * c), 2 * (b * d - a * c), a * a + b * b + c * c + d * d};
}

Integer_point divided_by_gcd(Integer_point p) {
  const long long g = std::gcd(std::gcd(p.x, p.y), p.z);
  return g == 0 ? p : Integer_point{p.x / g, p.y / g, p.z / g, p.norm / g};
}

// x, y, z in a random order of the axes (one of six permutations).
std::array<long long, 3> permuted(const std::array<long long, 3>& v, long permutation) {
  static constexpr int kAxes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  return {v[kAxes[permutation][0]], v[kAxes[permutation][1]], v[kAxes[permutation][2]]};
}

Site site_at(const std::array<long, 3>& origin, const std::array<long long, 3>& offset, double w) {
  return {static_cast<double>(origin[0] + offset[0]), static_cast<double>(origin[1] + offset[1]),
          static_cast<double>(origin[2] + offset[2]), w};
}

std::array<long, 3> small_integer_point(Random& random) {
  return {random.integer(-3, 3), random.integer(-3, 3), random.integer(-3, 3)};
}

// Balls at integer points O + p with |p| an integer, weight |p| - R: every ball touches the sphere of
// radius R about O (from outside, or from inside for a negative weight), so all of them tie at O. One ball
// per ray from O, so none hides another. `planar`: the centres lie in a plane through O (Pythagorean triples
// (a^2 - b^2, 2ab)), all tangent to one circle of that plane. The range of a, b, c, d grows when new rays
// get rare, so any n is reached.
std::vector<Site> tangent_to_one_sphere(std::size_t n, Random& random, bool planar) {
  const std::array<long, 3> origin = small_integer_point(random);
  const long radius = random.integer(1, 3);
  const long permutation = random.integer(0, 5);
  std::set<std::array<long long, 3>> rays;
  std::vector<Site> sites;
  long bound = 2;
  std::size_t misses = 0;
  while (sites.size() < n) {
    const long long a = random.integer(-bound, bound), b = random.integer(-bound, bound);
    Integer_point p;
    if (planar) {
      p = {a * a - b * b, 2 * a * b, 0, a * a + b * b};
      if (random.integer(0, 1)) std::swap(p.x, p.y);
    } else {
      p = pythagorean_quadruple(a, b, random.integer(-bound, bound), random.integer(-bound, bound));
    }
    p = divided_by_gcd(p);
    if (p.norm == 0 || !rays.insert({p.x, p.y, p.z}).second) {
      if (++misses > 8 * (sites.size() + 8)) ++bound, misses = 0;
      continue;
    }
    sites.push_back(site_at(origin, permuted({p.x, p.y, p.z}, permutation), static_cast<double>(p.norm - radius)));
  }
  return sites;
}

// Balls tangent to the two spheres of radius R about O and O + (0, 0, 4k): centres O + (x, y, 2k) with
// x^2 + y^2 + 4k^2 = N^2, weight N - R, so all of them tie at both sphere centres. Such points are the
// quadruples above with bd - ac = k: a and c at random, b a divisor of k + ac.
std::vector<Site> tangent_to_two_spheres(std::size_t n, Random& random) {
  const std::array<long, 3> origin = small_integer_point(random);
  const long radius = random.integer(1, 3), k = random.integer(1, 2), permutation = random.integer(0, 5);
  std::set<std::pair<long long, long long>> used;
  std::vector<Site> sites;
  long bound = 2;
  std::size_t misses = 0;
  while (sites.size() < n) {
    const long long a = random.integer(-bound, bound), c = random.integer(-bound, bound), t = k + a * c;
    long long b = 0, d = random.integer(-bound, bound);
    if (t != 0) {
      std::vector<long long> divisors;
      for (long long q = 1; q * q <= std::abs(t); ++q)
        if (t % q == 0) divisors.insert(divisors.end(), {q, -q, t / q, -t / q});
      b = divisors[static_cast<std::size_t>(random.integer(0, static_cast<long>(divisors.size()) - 1))];
      d = t / b;
    }
    const Integer_point p = pythagorean_quadruple(a, b, c, d);  // p.z == 2k
    if (!used.insert({p.x, p.y}).second) {
      if (++misses > 8 * (sites.size() + 8)) ++bound, misses = 0;
      continue;
    }
    sites.push_back(site_at(origin, permuted({p.x, p.y, p.z}, permutation), static_cast<double>(p.norm - radius)));
  }
  return sites;
}

// The integer points of the sphere of radius r about the origin.
std::vector<std::array<long long, 3>> integer_points_on_sphere(long long r) {
  std::vector<std::array<long long, 3>> points;
  for (long long x = -r; x <= r; ++x)
    for (long long y = -r; y <= r; ++y) {
      const long long rest = r * r - x * x - y * y;
      if (rest < 0) continue;
      const long long z = static_cast<long long>(std::llround(std::sqrt(static_cast<double>(rest))));
      if (z * z != rest) continue;
      points.push_back({x, y, z});
      if (z != 0) points.push_back({x, y, -z});
    }
  return points;
}

// Two to four shells of integer points about O, each on a sphere of integer radius r_j with one weight
// r_j - s_j, s_j 1 or 2: every shell is cospherical with equal weights, and shells of the same s_j also tie
// at O (where a ball of an outer shell on the same ray hides the inner one).
std::vector<Site> concentric_shells(std::size_t n, Random& random) {
  const std::array<long, 3> origin = small_integer_point(random);
  std::vector<Site> sites;
  std::size_t shells = static_cast<std::size_t>(random.integer(2, 4));
  long long r = random.integer(1, 3);
  while (sites.size() < n) {
    const std::size_t quota = (n - sites.size() + shells - 1) / shells;
    std::vector<std::array<long long, 3>> points;
    for (r += random.integer(1, 3);; ++r) {
      points = integer_points_on_sphere(r);
      if (points.size() >= quota) break;
    }
    const double w = static_cast<double>(r - random.integer(1, 2));
    for (std::size_t k = 0; k < quota; ++k) {  // quota distinct points, by a partial shuffle
      std::swap(points[k], points[k + static_cast<std::size_t>(random.integer(0, static_cast<long>(points.size() - k) - 1))]);
      sites.push_back(site_at(origin, points[k], w));
    }
    if (shells > 1) --shells;
  }
  return sites;
}

// The integer points of the circle x^2 + y^2 = R^2, R a product of primes p = 1 mod 4: the Gaussian
// integers of norm R^2, u * prod pi_p^e conj(pi_p)^(2 - e), with p = pi_p conj(pi_p), e = 0, 1, 2 and u a
// unit: 4 * 3^k of them for k primes. Enough primes for `at_least` points, and at most nine (R about
// 1.1e13, exact in doubles).
std::vector<std::array<long long, 2>> integer_points_on_circle(std::size_t at_least, long long& radius) {
  static constexpr long long kGaussianPrimes[9][2] = {{2, 1}, {3, 2}, {4, 1}, {5, 2}, {6, 1}, {5, 4}, {7, 2}, {6, 5}, {8, 3}};
  std::vector<std::array<long long, 2>> points = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  radius = 1;
  for (const auto& pi : kGaussianPrimes) {
    if (points.size() >= at_least) break;
    radius *= pi[0] * pi[0] + pi[1] * pi[1];
    // pi^2, pi conj(pi) = p and conj(pi)^2.
    const long long factors[3][2] = {{pi[0] * pi[0] - pi[1] * pi[1], 2 * pi[0] * pi[1]},
                                     {pi[0] * pi[0] + pi[1] * pi[1], 0},
                                     {pi[0] * pi[0] - pi[1] * pi[1], -2 * pi[0] * pi[1]}};
    std::vector<std::array<long long, 2>> next;
    for (const auto& z : points)
      for (const auto& f : factors) next.push_back({z[0] * f[0] - z[1] * f[1], z[0] * f[1] + z[1] * f[0]});
    points = std::move(next);
  }
  return points;
}

// n balls with centres on one circle about O (in a plane of two axes), of one weight (`mixed`: each of
// three weights). The weights are multiples of 1/8 up to R. Without `mixed`, one ball in eight lies
// elsewhere near the circle, so that vertices join the circle's axis, where all its balls tie. Beyond the
// 78,732 points of the largest circle, points repeat (duplicate sites).
std::vector<Site> on_one_circle(std::size_t n, Random& random, bool mixed) {
  const std::array<long, 3> origin = small_integer_point(random);
  long long radius = 0;
  std::vector<std::array<long long, 2>> points = integer_points_on_circle(n + static_cast<std::size_t>(random.integer(0, 1)) * n, radius);
  const long permutation = random.integer(0, 5);
  const double weights[3] = {random.eighths(0, radius), random.eighths(0, radius), random.eighths(0, radius)};
  std::vector<Site> sites;
  for (std::size_t k = 0; sites.size() < n; ++k) {
    if (!mixed && random.integer(0, 7) == 0) {
      const long extent = static_cast<long>(radius);
      sites.push_back({static_cast<double>(origin[0]) + random.eighths(-extent, extent),
                       static_cast<double>(origin[1]) + random.eighths(-extent, extent),
                       static_cast<double>(origin[2]) + random.eighths(-extent, extent), random.eighths(0, extent)});
      continue;
    }
    const std::size_t i = k % points.size();
    if (k < points.size())
      std::swap(points[i], points[i + static_cast<std::size_t>(random.integer(0, static_cast<long>(points.size() - i) - 1))]);
    sites.push_back(site_at(origin, permuted({points[i][0], points[i][1], 0}, permutation),
                            weights[mixed ? random.integer(0, 2) : 0]));
  }
  return sites;
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
  switch (family) {
    case Site_family::sphere_tangent: return tangent_to_one_sphere(n, random, false);
    case Site_family::circle_tangent: return tangent_to_one_sphere(n, random, true);
    case Site_family::two_spheres: return tangent_to_two_spheres(n, random);
    case Site_family::shells: return concentric_shells(n, random);
    case Site_family::circle: return on_one_circle(n, random, false);
    case Site_family::circle_mixed: return on_one_circle(n, random, true);
    default: break;
  }
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
      case Site_family::sphere_tangent:
      case Site_family::circle_tangent:
      case Site_family::two_spheres:
      case Site_family::shells:
      case Site_family::circle:
      case Site_family::circle_mixed:
        break;  // built above
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
