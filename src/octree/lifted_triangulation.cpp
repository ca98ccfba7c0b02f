#include "octree/lifted_triangulation.h"

#include <CGAL/Epick_d.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Regular_triangulation.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <tuple>

#include "diagram/cancellable_steps.h"
#include "octree/equal_weight_lifts.h"

namespace apollonius {
namespace {

// The lifts' power weights 2 w^2 are rarely doubles (w = 1.7 squares to 106 bits; w = 1e200 overflows).
// So the weighted point's weight slot holds w itself, and the kernels that decide (intervals, then Mpzf or
// mpq) read it as 2 w^2: exact on the exact kernels, certified on intervals. The double kernel, which
// decides nothing here, keeps w: the triangulation compares its weights only for equality, between lifts
// at one point of R^4 and so of one w (Regular_triangulation::insert, ON_VERTEX).
template <class R_>
struct Power_weight_of_lift {
  CGAL_FUNCTOR_INIT_IGNORE(Power_weight_of_lift)
  using argument_type = typename CGAL::Get_type<R_, CGAL::Weighted_point_tag>::type;
  using result_type = typename CGAL::Get_type<R_, CGAL::FT_tag>::type;
  result_type operator()(const argument_type& lift) const {
    const result_type& w = lift.weight();
    return result_type(2) * w * w;
  }
};
template <class FT>
struct Power_weight_kernel : CGAL::Cartesian_base_d<FT, CGAL::Dimension_tag<4>> {
  using Base = CGAL::Cartesian_base_d<FT, CGAL::Dimension_tag<4>>;
  template <class Tag, class D = void>
  struct Functor : CGAL::Inherit_functor<Base, Tag, D> {};
  template <class D>
  struct Functor<CGAL::Point_weight_tag, D> {
    using type = Power_weight_of_lift<Power_weight_kernel>;
  };
};

// Epick_d<4> with its power test, a 5 x 5 determinant and so division-free, decided on CGAL::Mpzf where
// the interval filter fails, as Epick_d already does its orientation; Epick_d falls back to mpq there,
// whose every operation reduces a fraction (the lifts of nearly cospherical sites fail the filter often).
using Dimension_4 = CGAL::Dimension_tag<4>;
using Lift_kernel_fields =
    CGAL::Cartesian_filter_K<CGAL::Cartesian_base_d<double, Dimension_4>, Power_weight_kernel<CGAL::Interval_nt_advanced>,
                             Power_weight_kernel<CGAL::internal::Exact_field_selector<double>::Type>>;
using Division_free_lift_predicates =
    CGAL::typeset<CGAL::Orientation_of_points_tag, CGAL::Side_of_oriented_sphere_tag, CGAL::Power_side_of_power_sphere_tag>;
struct Lift_kernel_rings
    : CGAL::Cartesian_filter_K<Lift_kernel_fields, Power_weight_kernel<CGAL::Interval_nt_advanced>,
                               Power_weight_kernel<CGAL::Mpzf>, Division_free_lift_predicates> {};
struct Lift_kernel : CGAL::Kernel_d_interface<CGAL::Cartesian_wrap<Lift_kernel_rings, Lift_kernel>> {};

struct Lifted_site {
  std::int64_t index = -1;     // the site's index, -1 until set
  std::size_t position = 0;    // its position in the sorted subset, once every site is inserted
};
using Triangulation = CGAL::Regular_triangulation<
    Lift_kernel,
    CGAL::Triangulation_data_structure<
        CGAL::Dimension_tag<4>,
        CGAL::Triangulation_vertex<CGAL::Regular_triangulation_traits_adapter<Lift_kernel>, Lifted_site>,
        CGAL::Triangulation_full_cell<CGAL::Regular_triangulation_traits_adapter<Lift_kernel>>>>;

}  // namespace

std::size_t Lifted_triangulation::position_of(Site_index s) const {
  return static_cast<std::size_t>(std::lower_bound(sites.begin(), sites.end(), s) - sites.begin());
}

const std::vector<Site_index>& Lifted_triangulation::neighbours_of(Site_index s) const {
  return neighbours[position_of(s)];
}

Lifted_triangulation lifted_triangulation(const std::vector<Site>& sites, const std::vector<Site_index>& subset,
                                          const Cancellation* cancellation) {
  if (!subset.empty() && has_one_weight(sites, subset)) return equal_weight_lifted_triangulation(sites, subset, cancellation);
  using FT = Lift_kernel::FT;
  Triangulation triangulation(4);

  for (std::size_t k = 0; k < subset.size(); ++k) {
    if (k % 256 == 0) throw_if_cancelled(cancellation);
    const Site& s = sites[subset[k]];
    const FT w(s.w);  // the power weight 2 w^2 (Power_weight_kernel)
    const Triangulation::Weighted_point lift(Lift_kernel::Point_d(FT(s.x), FT(s.y), FT(s.z), w), w);
    const Triangulation::Vertex_handle v = triangulation.insert(lift);
    // A repeated lift is a repeated site: the first keeps the vertex (tie sets are completed by the caller).
    if (v != Triangulation::Vertex_handle() && v->data().index < 0) v->data().index = subset[k];
  }
  Lifted_triangulation result;
  result.sites = subset;
  std::sort(result.sites.begin(), result.sites.end());
  result.neighbours.resize(result.sites.size());
  std::vector<bool> placed(result.sites.size(), false);
  for (auto v = triangulation.finite_vertices_begin(); v != triangulation.finite_vertices_end(); ++v) {
    v->data().position = result.position_of(static_cast<Site_index>(v->data().index));
    placed[v->data().position] = true;
  }
  for (std::size_t i = 0; i < placed.size(); ++i)
    if (!placed[i]) result.unplaced.push_back(result.sites[i]);
  const int dimension = triangulation.current_dimension();
  // Each vertex's neighbours from its incident cells, repeats dropped by a stamp per site as they come:
  // O(incident cells) per vertex, and no list longer than the neighbours (each edge lies in many cells).
  if (dimension >= 1) {
    std::vector<std::size_t> stamp(result.sites.size(), result.sites.size());
    std::vector<Triangulation::Full_cell_const_handle> incident;
    for (auto v = triangulation.vertices_begin(); v != triangulation.vertices_end(); ++v) {
      if (triangulation.is_infinite(v)) continue;
      const std::size_t a = v->data().position;
      if (a % 256 == 0) throw_if_cancelled(cancellation);
      incident.clear();
      triangulation.incident_full_cells(Triangulation::Vertex_const_handle(v), std::back_inserter(incident));
      std::vector<Site_index>& list = result.neighbours[a];
      for (const auto& cell : incident)
        for (int j = 0; j <= dimension; ++j) {
          const auto w = cell->vertex(j);
          if (triangulation.is_infinite(w) || w->data().position == a || stamp[w->data().position] == a) continue;
          stamp[w->data().position] = a;
          list.push_back(static_cast<Site_index>(w->data().index));
        }
      std::sort(list.begin(), list.end());
    }
  }
  if (dimension < 3) return result;
  // Each 3-face with the apex of the full cell it came from: twice for a facet of two full cells.
  struct Face {
    std::array<Site_index, 4> quadruple;
    Site_index apex;
    bool operator<(const Face& f) const { return std::tie(quadruple, apex) < std::tie(f.quadruple, f.apex); }
  };
  std::vector<Face> faces;
  std::size_t visited = 0;
  for (auto cell = triangulation.full_cells_begin(); cell != triangulation.full_cells_end(); ++cell) {
    if (++visited % 4096 == 0) throw_if_cancelled(cancellation);
    // Dimension 3: the finite cells are the 3-simplices; dimension 4: their facets, finite cells' or not.
    for (int omitted = dimension == 4 ? 0 : 4; omitted <= 4; ++omitted) {
      Face face{{}, Lifted_triangulation::kNoSite};
      int size = 0;
      bool finite = true;
      for (int i = 0; i <= dimension && finite; ++i) {
        const auto v = cell->vertex(i);
        if (i == omitted) {
          if (!triangulation.is_infinite(v)) face.apex = static_cast<Site_index>(v->data().index);
          continue;
        }
        if (triangulation.is_infinite(v)) finite = false;
        else face.quadruple[size++] = static_cast<Site_index>(v->data().index);
      }
      if (!finite || size != 4) continue;
      std::sort(face.quadruple.begin(), face.quadruple.end());
      faces.push_back(face);
    }
  }
  cancellable_sort(faces.begin(), faces.end(), cancellation);
  for (std::size_t f = 0; f < faces.size();) {
    result.quadruples.push_back(faces[f].quadruple);
    std::array<Site_index, 2> apexes{Lifted_triangulation::kNoSite, Lifted_triangulation::kNoSite};
    for (int k = 0; f < faces.size() && faces[f].quadruple == result.quadruples.back(); ++f)
      if (k < 2) apexes[k++] = faces[f].apex;
    result.apexes.push_back(apexes);
  }
  return result;
}

}  // namespace apollonius
