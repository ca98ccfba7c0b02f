// Contacts, SAS and clipped volumes (measure_contacts) against independent computations: closed forms for
// one and two balls (union volume and area, the planar disc of equal weights), a one-dimensional
// Gauss-Kronrod integral over the surface of revolution of a two-ball hyperboloid face, and Monte Carlo
// with a stated confidence for random balls (points on each sphere, in each ball, and, for equal weights,
// on each planar face); the error estimates against the actual errors; hidden balls; thread counts.
#include <doctest/doctest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "measure/cell_cubature.h"
#include "measure/contact_measures.h"
#include "measure/exit_regions.h"

using namespace apollonius;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Actual error within the estimate (plus rounding: 1e-12 relative).
void check_estimate(double value, double error, double exact) {
  CHECK(std::fabs(value - exact) <= error + 1e-12 * std::fabs(exact));
}

const Contact* find_contact(const Contact_measures& m, Site_index a, Site_index b) {
  for (const Contact& c : m.contacts)
    if (c.a == a && c.b == b) return &c;
  return nullptr;
}

// The face of balls 0 (at the origin) and 1 (at distance D along x) where t = |x| <= R: rays at angle
// theta from the axis meet it at t = (D^2 - alpha^2) / (2 (alpha + D cos theta)), alpha = w1 - w0; it is a
// surface of revolution, of area 2 pi int t sin(theta) sqrt(t^2 + t'^2) d theta up to t = R.
double revolution_face_area(double D, double alpha, double R) {
  const double c = D * D - alpha * alpha;
  const double cos_end = (c / (2 * R) - alpha) / D;
  if (cos_end >= 1) return 0;
  const double end = cos_end <= -1 ? kPi : std::acos(cos_end);
  const auto f = [&](double theta) {
    const double q = alpha + D * std::cos(theta);
    const double t = c / (2 * q), dt = c * D * std::sin(theta) / (2 * q * q);
    return 2 * kPi * t * std::sin(theta) * std::sqrt(t * t + dt * dt);
  };
  return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, 0.0, end, 15, 1e-14);
}

// d_k(x) = |x - x_k| - w_k, the least over the sites, and its index (the first on a tie).
std::pair<double, std::size_t> nearest(const std::vector<Site>& sites, double x, double y, double z) {
  double best = INFINITY;
  std::size_t k = 0;
  for (std::size_t j = 0; j < sites.size(); ++j) {
    const double d = std::sqrt((x - sites[j].x) * (x - sites[j].x) + (y - sites[j].y) * (y - sites[j].y) +
                               (z - sites[j].z) * (z - sites[j].z)) - sites[j].w;
    if (d < best) best = d, k = j;
  }
  return {best, k};
}

}  // namespace

TEST_CASE("a lone ball: its whole sphere is accessible and its volume is the ball's") {
  for (const double w : {0.0, 1.0, 1.7, 25.0})
    for (const double probe : {0.0, 1.4, 3.0}) {
      if (w + probe <= 0) continue;
      const Contact_measures m = measure_contacts({{1, -2, 3, w}}, {probe});
      const double R = w + probe;
      CHECK(m.contacts.empty());
      check_estimate(m.sas[0], m.sas_error[0], 4 * kPi * R * R);
      check_estimate(m.volume[0], m.volume_error[0], 4 * kPi * R * R * R / 3);
    }
}

TEST_CASE("a clipped lone cell: the sphere's closed forms give every integral of the ball") {
  // Over the ball of radius R about the site: int |x| = pi R^4, int x / |x| = 0, int (I - u u^T) / |x| =
  // (4 pi / 3) R^2 I, volume and sphere area.
  const double R = 2.5;
  Cut_candidates none;
  none.clearance.fill(INFINITY);
  Cell_cubature_options options;
  options.clip_radius = R;
  const Cell_measure m = integrate_cell({0.5, 0, 0, 1}, none, {{-5.5, -6, -6}, {6.5, 6, 6}}, options).measure;
  CHECK(std::fabs(m.volume - 4 * kPi * R * R * R / 3) < 1e-12 * R * R * R);
  CHECK(std::fabs(m.distance_integral - kPi * R * R * R * R) < 1e-12 * R * R * R * R);
  CHECK(std::fabs(m.sphere_area - 4 * kPi * R * R) < 1e-12 * R * R);
  for (double c : m.direction_integral) CHECK(std::fabs(c) < 1e-12 * R * R * R);
  for (int k = 0; k < 3; ++k) CHECK(std::fabs(m.median_hessian[k] - 4 * kPi / 3 * R * R) < 1e-12 * R * R);
  for (int k = 3; k < 6; ++k) CHECK(std::fabs(m.median_hessian[k]) < 1e-12 * R * R);
}

TEST_CASE("two balls: the face against a surface-of-revolution integral, the union's volume and area") {
  // (w0, w1, distance): equal weights (a planar disc), unequal ones, touching only within the probe, apart.
  const double cases[][3] = {{1, 1, 2},     {1.5, 1.5, 0.5}, {1, 1.8, 2.5}, {1.8, 1, 2.5}, {0.5, 2, 1.6},
                             {1, 1.2, 4.5}, {1, 1, 5.7},     {1, 1, 6},     {2, 1, 1.2},   {0, 3, 3.5}};
  for (const auto& row : cases)
    for (const double probe : {0.0, 1.4}) {
      const double w0 = row[0], w1 = row[1], D = row[2];
      CAPTURE(w0);
      CAPTURE(w1);
      CAPTURE(D);
      CAPTURE(probe);
      const std::vector<Site> sites = {{0, 0, 0, w0}, {D, 0, 0, w1}};
      const Contact_measures m = measure_contacts(sites, {probe, 1e-8});
      const double R0 = w0 + probe, R1 = w1 + probe;
      const double exact_area = revolution_face_area(D, w1 - w0, R0);
      const Contact* c = find_contact(m, 0, 1);
      if (exact_area == 0) {
        CHECK((c == nullptr || c->area <= c->error));
      } else {
        REQUIRE(c != nullptr);
        check_estimate(c->area, c->error, exact_area);
        if (w0 == w1) check_estimate(c->area, c->error, kPi * (R0 * R0 - D * D / 4));
      }
      // The clipped cells tile the union of the two balls; their spheres' accessible parts, its boundary.
      double union_volume = 4 * kPi * (R0 * R0 * R0 + R1 * R1 * R1) / 3, union_area = 4 * kPi * (R0 * R0 + R1 * R1);
      if (D < R0 + R1) {
        union_volume -= kPi * (R0 + R1 - D) * (R0 + R1 - D) * (D * D + 2 * D * (R0 + R1) - 3 * (R0 - R1) * (R0 - R1)) / (12 * D);
        const double d0 = (D * D + R0 * R0 - R1 * R1) / (2 * D);  // from ball 0 to the spheres' common plane
        union_area -= 2 * kPi * R0 * (R0 - d0) + 2 * kPi * R1 * (R1 - (D - d0));
      }
      check_estimate(m.volume[0] + m.volume[1], m.volume_error[0] + m.volume_error[1], union_volume);
      check_estimate(m.sas[0] + m.sas[1], m.sas_error[0] + m.sas_error[1], union_area);
    }
}

TEST_CASE("far balls, whose grid cells are clamped together, still find each other") {
  // 1e7 is beyond the neighbour grid's 2^20 cells of side 2 (w + P): both balls share the clamped cell, and
  // the neighbouring cells clamp onto it too.
  for (const double x : {1e7, -1e7}) {
    CAPTURE(x);
    const double w = 1.5, D = 2, probe = 1.4, R = w + probe;
    const Contact_measures m = measure_contacts({{x, x, x, w}, {x + D, x, x, w}}, {probe, 1e-8});
    const Contact* c = find_contact(m, 0, 1);
    REQUIRE(c != nullptr);
    check_estimate(c->area, c->error, kPi * (R * R - D * D / 4));
  }
}

TEST_CASE("hidden and duplicate balls have no contacts, SAS or volume, and leave the others' as they were") {
  const std::vector<Site> alone = {{0, 0, 0, 2}, {3, 0, 0, 1}};
  std::vector<Site> with_hidden = alone;
  with_hidden.push_back({0.5, 0, 0, 1});  // inside ball 0
  with_hidden.push_back({3, 0, 0, 1});    // a duplicate of ball 1
  with_hidden.push_back({1, 0, 0, 1});    // internally tangent to ball 0
  const Contact_measures a = measure_contacts(alone), b = measure_contacts(with_hidden);
  REQUIRE(b.hidden.size() == 3);
  for (Site_index h : {2u, 3u, 4u}) {
    CHECK(b.sas[h] == 0);
    CHECK(b.volume[h] == 0);
  }
  REQUIRE(b.contacts.size() == 1);
  CHECK(b.contacts[0].a == 0);
  CHECK(b.contacts[0].b == 1);
  CHECK(b.contacts[0].area == a.contacts[0].area);
  CHECK(b.sas[0] == a.sas[0]);
  CHECK(b.volume[1] == a.volume[1]);
}

TEST_CASE("random balls against Monte Carlo: SAS by points on each sphere, volumes by points in a box, and "
          "for equal weights each contact by points on its planar disc") {
  // Each Monte Carlo count is binomial: the check allows 5 standard deviations (a false alarm about once
  // in 1.7 million checks) plus the cubature's own estimate.
  constexpr int kInputs = 60, kSamples = 20000;
  for (int seed = 1; seed <= kInputs; ++seed) {
    CAPTURE(seed);
    std::mt19937_64 random(static_cast<std::uint64_t>(seed));
    std::uniform_real_distribution<double> position(0, 6), radius(1, 2), unit(0, 1);
    std::normal_distribution<double> normal;
    const bool equal = seed % 2 == 0;
    std::vector<Site> sites(4 + seed % 7);
    for (Site& s : sites) s = {position(random), position(random), position(random), equal ? 1.5 : radius(random)};
    const double probe = 1.4;
    const Contact_measures m = measure_contacts(sites, {probe, 1e-7});
    for (std::size_t i = 0; i < sites.size(); ++i) {
      if (m.sas[i] == 0 && m.volume[i] == 0) continue;  // hidden
      const double R = sites[i].w + probe, sphere = 4 * kPi * R * R;
      int inside = 0;
      for (int k = 0; k < kSamples; ++k) {
        double u[3] = {normal(random), normal(random), normal(random)};
        const double n = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        const double x = sites[i].x + R * u[0] / n, y = sites[i].y + R * u[1] / n, z = sites[i].z + R * u[2] / n;
        inside += nearest(sites, x, y, z).second == i;
      }
      const double p = static_cast<double>(inside) / kSamples;
      CHECK(std::fabs(m.sas[i] - sphere * p) <= 5 * sphere * std::sqrt(std::max(p * (1 - p), 1.0 / kSamples) / kSamples) + m.sas_error[i]);
    }
    // Volumes: points in the box around every ball; each point within the probe of its nearest ball counts
    // for that ball.
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (const Site& s : sites) {
      const double c[3] = {s.x, s.y, s.z};
      for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], c[a] - s.w - probe), hi[a] = std::max(hi[a], c[a] + s.w + probe);
    }
    const double box = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    std::vector<int> counts(sites.size(), 0);
    const int volume_samples = 5 * kSamples;
    for (int k = 0; k < volume_samples; ++k) {
      const double x = lo[0] + (hi[0] - lo[0]) * unit(random), y = lo[1] + (hi[1] - lo[1]) * unit(random),
                   z = lo[2] + (hi[2] - lo[2]) * unit(random);
      const auto [d, j] = nearest(sites, x, y, z);
      if (d <= probe) ++counts[j];
    }
    for (std::size_t i = 0; i < sites.size(); ++i) {
      const double p = static_cast<double>(counts[i]) / volume_samples;
      CHECK(std::fabs(m.volume[i] - box * p) <= 5 * box * std::sqrt(std::max(p * (1 - p), 1.0 / volume_samples) / volume_samples) + m.volume_error[i]);
    }
    if (!equal) continue;
    // Equal weights: the face of i and j is in their bisector plane, within the disc of radius
    // sqrt(R^2 - D^2 / 4) about their midpoint; a point of that disc is on the face when no other ball is
    // nearer.
    for (std::size_t i = 0; i < sites.size(); ++i)
      for (std::size_t j = i + 1; j < sites.size(); ++j) {
        const double R = sites[i].w + probe;
        const double d[3] = {sites[j].x - sites[i].x, sites[j].y - sites[i].y, sites[j].z - sites[i].z};
        const double D = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const double disc2 = R * R - D * D / 4;
        const Contact* c = find_contact(m, static_cast<Site_index>(i), static_cast<Site_index>(j));
        if (disc2 <= 0) {
          CHECK(c == nullptr);
          continue;
        }
        // An orthonormal basis (e1, e2) of the plane normal to d.
        const double n[3] = {d[0] / D, d[1] / D, d[2] / D};
        double e1[3] = {-n[1], n[0], 0};
        if (std::fabs(n[2]) > 0.9) e1[0] = 0, e1[1] = -n[2], e1[2] = n[1];
        const double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
        for (double& v : e1) v /= l1;
        const double e2[3] = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
        const double mid[3] = {sites[i].x + d[0] / 2, sites[i].y + d[1] / 2, sites[i].z + d[2] / 2};
        int on_face = 0;
        for (int k = 0; k < kSamples; ++k) {
          const double r = std::sqrt(disc2 * unit(random)), phi = 2 * kPi * unit(random);
          const double a = r * std::cos(phi), b = r * std::sin(phi);
          const double x = mid[0] + a * e1[0] + b * e2[0], y = mid[1] + a * e1[1] + b * e2[1], z = mid[2] + a * e1[2] + b * e2[2];
          const double own = std::sqrt(D * D / 4 + r * r) - sites[i].w;  // d_i = d_j here
          bool free = true;
          for (std::size_t k2 = 0; k2 < sites.size() && free; ++k2)
            if (k2 != i && k2 != j)
              free = std::sqrt((x - sites[k2].x) * (x - sites[k2].x) + (y - sites[k2].y) * (y - sites[k2].y) +
                               (z - sites[k2].z) * (z - sites[k2].z)) - sites[k2].w >= own;
          on_face += free;
        }
        const double disc = kPi * disc2, p = static_cast<double>(on_face) / kSamples;
        const double area = c ? c->area : 0, error = c ? c->error : 0;
        CHECK(std::fabs(area - disc * p) <= 5 * disc * std::sqrt(std::max(p * (1 - p), 1.0 / kSamples) / kSamples) + error);
      }
  }
}

TEST_CASE("every thread count gives the same contacts") {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> position(0, 12), radius(1, 2);
  std::vector<Site> sites(200);
  for (Site& s : sites) s = {position(random), position(random), position(random), radius(random)};
  const Contact_measures one = measure_contacts(sites, {1.4, 1e-6, 1}), two = measure_contacts(sites, {1.4, 1e-6, 2});
  REQUIRE(one.contacts.size() == two.contacts.size());
  for (std::size_t k = 0; k < one.contacts.size(); ++k) {
    CHECK(one.contacts[k].a == two.contacts[k].a);
    CHECK(one.contacts[k].b == two.contacts[k].b);
    CHECK(one.contacts[k].area == two.contacts[k].area);
  }
  CHECK(one.sas == two.sas);
  CHECK(one.volume == two.volume);
}

TEST_CASE("bad parameters are refused") {
  CHECK_THROWS_AS(measure_contacts({{0, 0, 0, 1}}, {-1}), std::invalid_argument);
  CHECK_THROWS_AS(measure_contacts({{0, 0, 0, 1}}, {INFINITY}), std::invalid_argument);
  CHECK_THROWS_AS(measure_contacts({{0, 0, 0, 1}}, {1.4, 0}), std::invalid_argument);
}

TEST_CASE("balls within 1e-4 of their radius of each other are refused, whatever the scale") {
  for (double scale : {1e-3, 1.0, 1e4}) {
    CAPTURE(scale);
    const double d = scale * 1e-6;
    const std::vector<Site> sites{{0, 0, 0, scale}, {d, 0, 0, scale}, {3 * scale, 0, 0, scale}};
    CHECK_THROWS_AS(measure_contacts(sites, {0.5 * scale}), Unmeasurable_pair);
    // At 1e-3 of the radius apart they are measured: the face is the disc of the bisector plane.
    const std::vector<Site> apart{{0, 0, 0, scale}, {scale * 1e-3, 0, 0, scale}};
    const Contact_measures m = measure_contacts(apart, {0.5 * scale, 1e-6});
    REQUIRE(m.contacts.size() == 1);
    const double R = 1.5 * scale, half = 0.5 * scale * 1e-3;
    check_estimate(m.contacts[0].area, m.contacts[0].error, kPi * (R * R - half * half));
  }
}

TEST_CASE("regression: contacts_empty_cells_at_7e16_from_a_box_rounded_to_zero; far from the origin as near it") {
  // Two balls at z = 76561193665298448 (an ulp of 16 there) and the same pair at the origin.
  const double far = 76561193665298448.0;
  const std::vector<Site> there{{1, 1, far, 13.999999999999998}, {14.125000000000002, -4, far, 1}};
  const std::vector<Site> here{{1, 1, 0, 13.999999999999998}, {14.125000000000002, -4, 0, 1}};
  for (double probe : {0.0, 1.4}) {
    CAPTURE(probe);
    const Contact_measures a = measure_contacts(there, {probe, 1e-8}), b = measure_contacts(here, {probe, 1e-8});
    REQUIRE(a.contacts.size() == 1);
    REQUIRE(b.contacts.size() == 1);
    CHECK(std::fabs(a.contacts[0].area - b.contacts[0].area) <= a.contacts[0].error + b.contacts[0].error);
    for (std::size_t i = 0; i < 2; ++i) {
      CHECK(a.volume[i] > 0);
      CHECK(std::fabs(a.volume[i] - b.volume[i]) <= a.volume_error[i] + b.volume_error[i]);
      CHECK(std::fabs(a.sas[i] - b.sas[i]) <= a.sas_error[i] + b.sas_error[i]);
    }
  }
}
