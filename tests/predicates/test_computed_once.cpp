// Computed_once (computed_once.h) and the lazy state built on it (a vertex's exact coordinates, rounding
// and rounding sides; a trisector's rational geometry): threads asking at once all get the one published
// value, equal to what a lone thread computes. Run under the sanitizers' builds too.
#include <doctest/doctest.h>

#include <atomic>
#include <random>
#include <thread>
#include <vector>

#include "predicates/computed_once.h"
#include "predicates/trisector.h"
#include "predicates/vertex_rounding.h"
#include "predicates/vertices_of.h"

using namespace apollonius;

namespace {

constexpr int kThreads = 4;

// Runs body(thread) on kThreads threads released together, so that their first uses overlap.
template <class Body>
void run_together(Body body) {
  std::atomic<int> waiting{kThreads};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      waiting.fetch_sub(1);
      while (waiting.load() > 0) std::this_thread::yield();
      body(t);
    });
  for (std::thread& thread : threads) thread.join();
}

std::vector<Site> random_sites(std::mt19937_64& random) {
  std::uniform_int_distribution<int> coordinate(-16, 16), weight(0, 8);
  std::vector<Site> sites(4);
  for (Site& s : sites) s = {coordinate(random) / 4.0, coordinate(random) / 4.0, coordinate(random) / 4.0, weight(random) / 8.0};
  return sites;
}

// No ball of the first three in another: |c_i - c_j| > |w_i - w_j| (exact in doubles on these dyadics).
bool pairwise_apart(const std::vector<Site>& s) {
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const double dx = s[i].x - s[j].x, dy = s[i].y - s[j].y, dz = s[i].z - s[j].z, dw = s[i].w - s[j].w;
      if (dx * dx + dy * dy + dz * dz <= dw * dw) return false;
    }
  return true;
}

}  // namespace

TEST_CASE("Computed_once: one published value, shared by later copies, not by earlier ones") {
  Computed_once<std::vector<int>> slot;
  CHECK(slot.get() == nullptr);
  const Computed_once<std::vector<int>> earlier = slot;
  std::atomic<int> computations{0};
  std::vector<const std::vector<int>*> seen(kThreads);
  run_together([&](int t) {
    seen[t] = &slot.get_or_compute([&] {
      ++computations;
      return std::vector<int>(1000, 7);
    });
  });
  CHECK(computations.load() >= 1);
  for (const std::vector<int>* value : seen) {
    CHECK(value == slot.get());
    CHECK(*value == std::vector<int>(1000, 7));
  }
  const Computed_once<std::vector<int>> later = slot;
  CHECK(later.get() == slot.get());
  CHECK(earlier.get() == nullptr);
  Computed_once<std::vector<int>> moved = std::move(slot);
  CHECK(moved.get() == later.get());
  Computed_once<std::vector<int>> assigned;
  assigned = later;
  CHECK(assigned.get() == later.get());
  assigned = std::move(moved);
  CHECK(assigned.get() == later.get());
}

TEST_CASE("Computed_once: a computation that throws publishes nothing") {
  Computed_once<int> slot;
  CHECK_THROWS_AS(slot.get_or_compute([]() -> int { throw std::runtime_error("no value"); }), std::runtime_error);
  CHECK(slot.get() == nullptr);
  CHECK(slot.get_or_compute([] { return 3; }) == 3);
}

TEST_CASE("vertices and trisectors shared by threads: their lazy exact state is computed once and equals a lone thread's") {
  std::mt19937_64 random(20261128);
  int vertices = 0, trisectors = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::vector<Site> sites = random_sites(random);
    CAPTURE(trial);
    const Quadruple_vertices made = vertices_of(make_quadruple({0, 1, 2, 3}, sites));
    for (const Vertex& shared : made.vertices) {
      ++vertices;
      const Vertex alone = shared;  // copied before any lazy state exists: computes its own
      const std::array<double, 4> rounded = alone.rounded();
      const std::array<Sign, 3> sides = alone.rounding_sides();
      const Vertex_coordinates<Exact>& exact = alone.coordinates<Exact>();
      std::vector<const Vertex_coordinates<Exact>*> seen(kThreads);
      run_together([&](int t) {
        // Each thread asks in another order, so that all three are computed concurrently somewhere.
        if (t % 2 == 0) {
          seen[t] = &shared.coordinates<Exact>();
          CHECK(shared.rounding_sides() == sides);
        } else {
          CHECK(shared.rounding_sides() == sides);
          seen[t] = &shared.coordinates<Exact>();
        }
        CHECK(shared.rounded() == rounded);
      });
      for (const Vertex_coordinates<Exact>* X : seen) CHECK(X == &shared.coordinates<Exact>());
      const Vertex_coordinates<Exact>& X = shared.coordinates<Exact>();
      CHECK(X.denominator == exact.denominator);
      CHECK(X.discriminant == exact.discriminant);
      for (int j = 0; j < 4; ++j) CHECK((X.scaled[j].a == exact.scaled[j].a && X.scaled[j].b == exact.scaled[j].b));
    }
    if (!pairwise_apart(sites)) continue;  // a trisector's sites are not hidden
    ++trisectors;
    const Trisector shared({0, 1, 2}, {sites[0], sites[1], sites[2]});
    const Trisector alone = shared;
    const Trisector_geometry<Rational>& expected = alone.geometry<Rational>();
    std::vector<const Trisector_geometry<Rational>*> seen(kThreads);
    run_together([&](int t) { seen[t] = &shared.geometry<Rational>(); });
    for (const Trisector_geometry<Rational>* g : seen) CHECK(g == &shared.geometry<Rational>());
    CHECK(shared.geometry<Rational>().kind == expected.kind);
    CHECK(shared.geometry<Rational>().shape == expected.shape);
    CHECK(shared.geometry<Rational>().K == expected.K);
  }
  CHECK(vertices > 100);
  CHECK(trisectors > 100);
}
