// The brute-force diagram on configurations with known answers, on CGAL's Delaunay circumcentres for equal
// weights, and on every generator family under the exact validator.
#include <doctest/doctest.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <map>

#include "reference/brute_force_diagram.h"
#include "support/diagram_checks.h"
#include "io/read_sites.h"
#include "reference/site_generators.h"

using namespace apollonius;
using namespace apollonius::testing;

TEST_CASE("hidden and duplicate sites are excluded and listed") {
  const std::vector<Site> sites = {
      {0, 0, 0, 3},     // 0
      {1, 0, 0, 1},     // 1: inside 0
      {2, 0, 0, 1},     // 2: tangent inside 0
      {10, 0, 0, 1},    // 3
      {0, 10, 0, 1},    // 4
      {0, 0, 10, 1},    // 5
      {10, 0, 0, 1},    // 6: duplicate of 3
      {-10, -10, -10, 2},  // 7
  };
  const Diagram d = brute_force_diagram(sites);
  validate_diagram(d, sites);
  REQUIRE(d.hidden.size() == 3);
  CHECK(d.hidden[0].site == 1);
  CHECK(d.hidden[0].hidden_by == 0);
  CHECK_FALSE(d.hidden[0].duplicate);
  CHECK(d.hidden[1].site == 2);
  CHECK(d.hidden[1].hidden_by == 0);
  CHECK(d.hidden[2].site == 6);
  CHECK(d.hidden[2].hidden_by == 3);
  CHECK(d.hidden[2].duplicate);
  for (const Diagram_vertex& v : d.vertices)
    for (Site_index s : v.tie_set) CHECK((s != 1 && s != 2 && s != 6));
}

TEST_CASE("five sites tangent to one sphere: a single vertex with five sites") {
  // Each site is at weighted distance 1 from the origin: |p| - w = 1.
  const std::vector<Site> sites = {{2, 0, 0, 1}, {0, 3, 0, 2}, {0, 0, 4, 3}, {-5, 0, 0, 4}, {0, 0, -2, 1}};
  const Diagram d = brute_force_diagram(sites);
  validate_diagram(d, sites);
  std::size_t five = 0;
  for (const Diagram_vertex& v : d.vertices) {
    if (v.tie_set.size() != 5) continue;
    ++five;
    CHECK(v.tie_set == std::vector<Site_index>{0, 1, 2, 3, 4});
    CHECK(v.rounded == std::array<double, 4>{0, 0, 0, 1});
  }
  CHECK(five == 1);
}

TEST_CASE("eight cospherical cube corners with equal weights: one vertex with all eight sites") {
  std::vector<Site> sites;
  for (int i = 0; i < 8; ++i) sites.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0, 0.5});
  const Diagram d = brute_force_diagram(sites);
  validate_diagram(d, sites);
  REQUIRE(d.vertices.size() == 1);
  CHECK(d.vertices[0].tie_set.size() == 8);
  CHECK(exactly_equal(exact_point(d.vertices[0].vertex)[3], root_number(-0.5, 1, 3, 1)));
}

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;

Root_number<Exact> as_root_number(const Kernel::FT& value) {
  const auto q = CGAL::exact(value);  // a GMP rational
  return {exact_integer(CGAL::Gmpz(q.get_num().get_mpz_t())), Exact(0), Exact(0), exact_integer(CGAL::Gmpz(q.get_den().get_mpz_t()))};
}

}  // namespace

TEST_CASE("equal weights: the vertices are the circumcentres of the Delaunay cells (CGAL, exact)") {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    CAPTURE(seed);
    const std::vector<Site> sites = generate_sites(Site_family::equal_weights, 5 + seed % 7, seed);
    const Diagram d = brute_force_diagram(sites);
    validate_diagram(d, sites);

    std::vector<std::pair<Kernel::Point_3, Site_index>> points;
    for (Site_index i = 0; i < sites.size(); ++i) points.push_back({{sites[i].x, sites[i].y, sites[i].z}, i});
    CGAL::Delaunay_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<
                                               CGAL::Triangulation_vertex_base_with_info_3<Site_index, Kernel>,
                                               CGAL::Delaunay_triangulation_cell_base_3<Kernel>>>
        dt(points.begin(), points.end());
    if (dt.dimension() < 3) continue;
    // Circumcentre -> union of the cells' vertices (cospherical cells share a circumcentre).
    std::map<Kernel::Point_3, std::set<Site_index>> circumcentres;
    for (auto cell = dt.finite_cells_begin(); cell != dt.finite_cells_end(); ++cell) {
      auto& tie = circumcentres[cell->circumcenter()];
      for (int k = 0; k < 4; ++k) tie.insert(cell->vertex(k)->info());
    }
    REQUIRE(d.vertices.size() == circumcentres.size());
    for (const auto& [centre, tie] : circumcentres) {
      const std::vector<Site_index> tie_set(tie.begin(), tie.end());
      const auto match = std::find_if(d.vertices.begin(), d.vertices.end(),
                                      [&](const Diagram_vertex& v) { return v.tie_set == tie_set; });
      REQUIRE(match != d.vertices.end());
      const auto p = exact_point(match->vertex);
      CHECK(exactly_equal(p[0], as_root_number(centre.x())));
      CHECK(exactly_equal(p[1], as_root_number(centre.y())));
      CHECK(exactly_equal(p[2], as_root_number(centre.z())));
    }
  }
}

TEST_CASE("vdrc anomaly sets: every vertex is reported") {
  const std::string vdrc = std::string(APOLLONIUS_TEST_DATA) + "/vdrc/";
  SUBCASE("ANO1_0CONNECT") {
    const std::vector<Site> sites = read_sites(vdrc + "ANO1_0CONNECT.txt", {}).sites;
    const Diagram d = brute_force_diagram(sites);
    validate_diagram(d, sites);
    CHECK(d.vertices.size() == 4);
  }
  SUBCASE("ANO3_3CONNECT") {
    const std::vector<Site> sites = read_sites(vdrc + "ANO3_3CONNECT.txt", {}).sites;
    const Diagram d = brute_force_diagram(sites);
    validate_diagram(d, sites);
    CHECK(d.vertices.size() == 8);
  }
}

TEST_CASE("every generator family, thousands of inputs, validated exactly") {
  std::size_t inputs = 0, vertices = 0, degenerate = 0;
  for (const std::string& name : site_family_names()) {
    const Site_family family = site_family_from_name(name);
    for (std::uint64_t seed = 1; seed <= 150; ++seed) {
      const std::size_t n = 5 + seed % 6;
      CAPTURE(name);
      CAPTURE(seed);
      CAPTURE(n);
      const std::vector<Site> sites = generate_sites(family, n, seed);
      const Diagram d = brute_force_diagram(sites);
      validate_diagram(d, sites);
      ++inputs;
      vertices += d.vertices.size();
      for (const Diagram_vertex& v : d.vertices) degenerate += v.tie_set.size() > 4 ? 1 : 0;
    }
  }
  MESSAGE(inputs << " inputs, " << vertices << " vertices, " << degenerate << " with 5 or more tied sites");
  CHECK(inputs == 150 * site_family_names().size());
  CHECK(degenerate > 0);
}

TEST_CASE("regression: gmpzf_to_interval_beyond_double_range") {
  const std::string file = std::string(APOLLONIUS_TEST_DATA) + "/regression/gmpzf_to_interval_beyond_double_range.balls";
  const std::vector<Site> sites = read_sites(file, {}).sites;
  const Diagram d = brute_force_diagram(sites);
  validate_diagram(d, sites);
  REQUIRE(d.vertices.size() == 3);
  CHECK(d.vertices[0].tie_set == std::vector<Site_index>{1, 3, 4, 6, 7, 8});
  CHECK(d.vertices[0].rounded == std::array<double, 4>{0, 0, 0, std::ldexp(2.0, 200)});
}
