#include "octree/equal_weight_lifts.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "diagram/cancellable_steps.h"

namespace apollonius {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vertex_base = CGAL::Triangulation_vertex_base_with_info_3<Site_index, Kernel>;
// A cell's info: its position in the sorted quadruples.
using Cell_base =
    CGAL::Triangulation_cell_base_with_info_3<std::uint32_t, Kernel, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Data_structure = CGAL::Triangulation_data_structure_3<Vertex_base, Cell_base>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Data_structure>;

// Centres are inserted this many at a time (each batch spatially sorted), between cancellation checks.
constexpr std::size_t kBatch = 1 << 14;

}  // namespace

bool has_one_weight(const std::vector<Site>& sites, const std::vector<Site_index>& subset) {
  return std::all_of(subset.begin(), subset.end(), [&](Site_index s) { return sites[s].w == sites[subset.front()].w; });
}

Lifted_triangulation equal_weight_lifted_triangulation(const std::vector<Site>& sites,
                                                       const std::vector<Site_index>& subset,
                                                       const Cancellation* cancellation) {
  Lifted_triangulation result;
  result.sites = subset;
  std::sort(result.sites.begin(), result.sites.end());
  result.neighbours.resize(result.sites.size());

  // By centre, then index: the first of each centre is placed, the repeats after it are not.
  std::vector<Site_index> order = result.sites;
  const auto centre = [&](Site_index s) { return std::make_tuple(sites[s].x, sites[s].y, sites[s].z); };
  cancellable_sort(order.begin(), order.end(), cancellation, [&](Site_index a, Site_index b) {
    return std::make_pair(centre(a), a) < std::make_pair(centre(b), b);
  });
  std::vector<std::pair<Kernel::Point_3, Site_index>> centres;
  centres.reserve(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k > 0 && centre(order[k]) == centre(order[k - 1])) {
      result.unplaced.push_back(order[k]);
      continue;
    }
    const Site& s = sites[order[k]];
    centres.emplace_back(Kernel::Point_3(s.x, s.y, s.z), order[k]);
  }
  std::sort(result.unplaced.begin(), result.unplaced.end());

  Delaunay triangulation;
  for (std::size_t begin = 0; begin < centres.size(); begin += kBatch) {
    throw_if_cancelled(cancellation);
    triangulation.insert(centres.begin() + static_cast<std::ptrdiff_t>(begin),
                         centres.begin() + static_cast<std::ptrdiff_t>(std::min(centres.size(), begin + kBatch)));
  }

  std::vector<Delaunay::Vertex_handle> adjacent;
  std::size_t visited = 0;
  for (auto v = triangulation.finite_vertices_begin(); v != triangulation.finite_vertices_end(); ++v) {
    if (++visited % 4096 == 0) throw_if_cancelled(cancellation);
    adjacent.clear();
    triangulation.finite_adjacent_vertices(v, std::back_inserter(adjacent));
    std::vector<Site_index>& list = result.neighbours[result.position_of(v->info())];
    for (const Delaunay::Vertex_handle& w : adjacent) list.push_back(w->info());
    std::sort(list.begin(), list.end());
  }
  if (triangulation.dimension() < 3) return result;  // coplanar centres: no vertex

  // The cells are distinct 4-sets; as the R^4 triangulation's 3-faces in three dimensions, no apexes.
  std::vector<std::pair<std::array<Site_index, 4>, Delaunay::Cell_handle>> cells;
  cells.reserve(triangulation.number_of_finite_cells());
  for (auto cell = triangulation.finite_cells_begin(); cell != triangulation.finite_cells_end(); ++cell) {
    if (++visited % 4096 == 0) throw_if_cancelled(cancellation);
    std::array<Site_index, 4> quadruple;
    for (int i = 0; i < 4; ++i) quadruple[i] = cell->vertex(i)->info();
    std::sort(quadruple.begin(), quadruple.end());
    cells.emplace_back(quadruple, cell);
  }
  cancellable_sort(cells.begin(), cells.end(), cancellation,
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  if (cells.size() >= Lifted_triangulation::kNoCell) throw std::length_error("more Delaunay cells than 32 bits count");
  result.quadruples.reserve(cells.size());
  for (std::size_t q = 0; q < cells.size(); ++q) {
    result.quadruples.push_back(cells[q].first);
    cells[q].second->info() = static_cast<std::uint32_t>(q);
  }
  result.apexes.assign(cells.size(), {Lifted_triangulation::kNoSite, Lifted_triangulation::kNoSite});
  result.across_facets.resize(cells.size());
  for (std::size_t q = 0; q < cells.size(); ++q) {
    if (q % 4096 == 0) throw_if_cancelled(cancellation);
    const Delaunay::Cell_handle cell = cells[q].second;
    for (int i = 0; i < 4; ++i) {
      const Delaunay::Cell_handle beyond = cell->neighbor(i);
      if (triangulation.is_infinite(beyond)) continue;
      const Delaunay::Vertex_handle far = beyond->vertex(beyond->index(cell));
      const bool same_sphere = triangulation.side_of_sphere(cell, far->point()) == CGAL::ON_BOUNDARY;
      result.across_facets[q][i] = {beyond->info(), far->info(), same_sphere};
    }
  }
  return result;
}

}  // namespace apollonius
