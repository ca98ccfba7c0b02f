#include "mesh/plane_mesher.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_2/Lloyd_move_2.h>
#include <CGAL/Constrained_voronoi_diagram_2.h>
#include <CGAL/Mesh_2/Face_badness.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <utility>

namespace apollonius {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
struct Vertex_info {
  std::int64_t id = -1;  // -1: not an existing mesh point
};
using Vertex_base = CGAL::Triangulation_vertex_base_with_info_2<Vertex_info, Kernel, CGAL::Delaunay_mesh_vertex_base_2<Kernel>>;
using Face_base = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Data_structure = CGAL::Triangulation_data_structure_2<Vertex_base, Face_base>;
// Exact_predicates_tag, the tag for a kernel of inexact constructions: where two constraints cross (edge
// chords meeting at a small angle near a vertex of many tied sites), it inserts their rounded intersection
// as a vertex. Exact_intersections_tag assumes exact constructions, and Epick's rounded point crashed the
// triangulation (tests/data/regression/mesh_crashed_where_edge_chords_cross.balls).
using Triangulation = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Data_structure, CGAL::Exact_predicates_tag>;
using Face_handle = Triangulation::Face_handle;
using Point = Kernel::Point_2;

// The triangulation sees the plane's coordinates times a power of two that brings the largest to [1, 2):
// CGAL's filters then never overflow or underflow (balls scaled by 2^+-300 sent every incircle test to
// Mpzf, minutes for 60 balls), and since scaling by a power of two is exact, every predicate and
// construction gives the scaled result of the unscaled one, bit for bit.
struct Plane_scale {
  double factor = 1;
  Point to_triangulation(const Point2& p) const { return Point(p[0] * factor, p[1] * factor); }
  Point2 to_plane(const Point& p) const { return {p.x() / factor, p.y() / factor}; }
};

Plane_scale scale_of(const Plane_mesh_input& input) {
  double largest = 0;
  for (const Plane_mesh_input::Polyline& line : input.polylines)
    for (const Point2& p : line.points) largest = std::max({largest, std::fabs(p[0]), std::fabs(p[1])});
  if (!(largest > 0) || !std::isfinite(largest)) return {};
  return {std::ldexp(1.0, std::clamp(-std::ilogb(largest), -1022, 1023))};
}

// Delaunay refinement criteria: the lifted triangle's longest edge at most the step, and the sine of its
// least angle at least sqrt(0.125) (20.7 degrees, as CGAL's Delaunay_mesh_size_criteria_2), in the lift or
// in the plane, whichever is better.
//
// Termination: a triangle is refined only where its lifted longest edge exceeds size_factor x step, or it
// is skinny in the plane (circumradius over shortest edge above sqrt(2)). Its circumcentre is then at
// least circumradius from every vertex, and an encroaching one is dropped (no constraint is split), so as
// in Ruppert's argument no new vertex comes nearer to the others than min(the least distance between the
// vertices before refinement, size_factor x step / (2 L)) for L the lift's largest stretch over the region,
// which is finite (the sheet's slope is at most delta / sqrt(f^2 - delta^2), bisector_frame.h): finitely
// many points.
// Measured in the lift alone, the angle criterion looped: over a steep sheet (nearly internally tangent
// balls) the lift stretches one direction up to 6 times, planar circumcentres then never make lifted
// angles of 20.7 degrees, and the points piled up at one spot without end
// (tests/data/regression/mesh_refinement_never_ended_on_a_steep_sheet.balls).
class Lifted_criteria {
 public:
  using Quality = std::pair<double, double>;  // squared least sine, squared longest edge / step^2

  Lifted_criteria(const Plane_mesh_input& input, const Plane_scale& scale) : input_(&input), scale_(scale) {}

  class Is_bad {
   public:
    Is_bad(const Plane_mesh_input* input, const Plane_scale& scale) : input_(input), scale_(scale) {}
    CGAL::Mesh_2::Face_badness operator()(const Quality& q) const {
      if (q.second > 1) return CGAL::Mesh_2::IMPERATIVELY_BAD;
      return q.first < kSquaredSineBound ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }
    CGAL::Mesh_2::Face_badness operator()(const Face_handle& f, Quality& q) const {
      std::array<Point3, 3> lifted, planar;
      for (int k = 0; k < 3; ++k) {
        const Point& p = f->vertex(k)->point();
        lifted[k] = input_->lift(scale_.to_plane(p));
        planar[k] = {p.x(), p.y(), 0};
      }
      int exponent = 0, unused = 0;
      const std::array<Point3, 3> edges = scaled_edges(lifted, exponent);
      const double step = std::ldexp(input_->step, -exponent);  // the step in the edges' scale
      double longest_squared = 0;
      q.first = std::max(squared_least_sine(edges, longest_squared), squared_least_sine(scaled_edges(planar, unused)));
      q.second = longest_squared / (step * step * input_->size_factor * input_->size_factor);
      return operator()(q);
    }

   private:
    static double squared_norm(const Point3& x) { return x[0] * x[0] + x[1] * x[1] + x[2] * x[2]; }

    // The edges x1 - x2, x2 - x0, x1 - x0 times 2^-exponent, a power of two that brings their largest
    // coordinate to [1, 2): exact, so no square underflows where the sites are scaled by 2^-300.
    static std::array<Point3, 3> scaled_edges(const std::array<Point3, 3>& x, int& exponent) {
      std::array<Point3, 3> e;
      const std::array<std::array<int, 2>, 3> ends{{{1, 2}, {2, 0}, {1, 0}}};
      double largest = 0;
      for (int k = 0; k < 3; ++k)
        for (int a = 0; a < 3; ++a) {
          e[k][a] = x[ends[k][0]][a] - x[ends[k][1]][a];
          largest = std::max(largest, std::fabs(e[k][a]));
        }
      exponent = largest > 0 && std::isfinite(largest) ? std::ilogb(largest) : 0;
      for (Point3& edge : e)
        for (double& c : edge) c = std::ldexp(c, -exponent);
      return e;
    }

    // The squared sine of a triangle's least angle (0 for a degenerate one) from its edges (scaled_edges),
    // and its longest edge squared.
    static double squared_least_sine(const std::array<Point3, 3>& e, double& longest_squared) {
      std::array<double, 3> l{squared_norm(e[0]), squared_norm(e[1]), squared_norm(e[2])};
      std::sort(l.begin(), l.end());
      longest_squared = l[2];
      const Point3& u = e[2];  // x1 - x0
      const Point3& v = e[1];  // x2 - x0
      const Point3 c{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      return l[1] * l[2] > 0 ? squared_norm(c) / (l[1] * l[2]) : 0;
    }
    static double squared_least_sine(const std::array<Point3, 3>& e) {
      double unused = 0;
      return squared_least_sine(e, unused);
    }

    static constexpr double kSquaredSineBound = 0.125;
    const Plane_mesh_input* input_;
    Plane_scale scale_;
  };

  Is_bad is_bad_object() const { return Is_bad(input_, scale_); }

 private:
  const Plane_mesh_input* input_;
  Plane_scale scale_;
};

// The Lloyd density, through Lloyd_move_2's sizing field: density 1 / s^4 (CGAL's convention, d = 2).
thread_local const std::function<double(const Point2&)>* current_density = nullptr;
thread_local Plane_scale current_scale;
struct Density_sizing {
  static const bool is_vertex_update_needed = false;
  explicit Density_sizing(Triangulation&) {}
  double operator()(const Point& p) const { return std::pow((*current_density)(current_scale.to_plane(p)), -0.25); }
};

// Regions: the classes of finite faces joined across unconstrained edges.
std::vector<std::vector<Face_handle>> regions_of(const Triangulation& cdt) {
  std::map<Face_handle, int> region;
  std::vector<std::vector<Face_handle>> out;
  for (Face_handle f : cdt.finite_face_handles()) {
    if (region.count(f)) continue;
    const int r = static_cast<int>(out.size());
    out.emplace_back();
    std::vector<Face_handle> stack{f};
    region[f] = r;
    while (!stack.empty()) {
      Face_handle g = stack.back();
      stack.pop_back();
      out[r].push_back(g);
      for (int i = 0; i < 3; ++i) {
        Face_handle h = g->neighbor(i);
        if (cdt.is_infinite(h) || cdt.is_constrained({g, i}) || region.count(h)) continue;
        region[h] = r;
        stack.push_back(h);
      }
    }
  }
  return out;
}

Point centroid(const Face_handle& f) {
  return CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
}

double area(const Face_handle& f) {
  return std::abs(CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
}


using Marker = CGAL::Delaunay_mesher_2<Triangulation, CGAL::Delaunay_mesh_size_criteria_2<Triangulation>>;

double squared_distance_to_segment(const Point2& p, const Point2& a, const Point2& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double length = dx * dx + dy * dy;
  double t = length > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length : 0;
  t = std::max(0.0, std::min(1.0, t));
  const double ex = a[0] + t * dx - p[0], ey = a[1] + t * dy - p[1];
  return ex * ex + ey * ey;
}

// Starts the interior from a triangular lattice of spacing `step` on the sheet (measured with the density
// at the domain's centre), keeping the points at least 0.55 step from every constraint: the Lloyd
// iterations then only have the layer along the boundary to settle.
void seed_lattice(Triangulation& cdt, const Plane_mesh_input& input, const Plane_scale& scale,
                  const std::vector<Point>& seeds) {
  Marker::mark_facets(cdt, seeds.begin(), seeds.end(), false);
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for (Face_handle f : cdt.finite_face_handles()) {
    if (!f->is_in_domain()) continue;
    for (int k = 0; k < 3; ++k) {
      const Point& p = f->vertex(k)->point();
      lo[0] = std::min(lo[0], p.x()), lo[1] = std::min(lo[1], p.y());
      hi[0] = std::max(hi[0], p.x()), hi[1] = std::max(hi[1], p.y());
    }
  }
  if (!(lo[0] <= hi[0])) return;
  const Point middle((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2);
  const double spacing = input.step / std::sqrt(input.density(scale.to_plane(middle))) * scale.factor;
  if ((hi[0] - lo[0]) * (hi[1] - lo[1]) > 4e6 * spacing * spacing) return;  // a huge domain: refinement alone
  std::vector<std::pair<Point2, Point2>> segments;
  for (const Plane_mesh_input::Polyline& line : input.polylines)
    for (std::size_t k = 0; k + 1 < line.points.size(); ++k) {
      const Point a = scale.to_triangulation(line.points[k]), b = scale.to_triangulation(line.points[k + 1]);
      segments.push_back({{a.x(), a.y()}, {b.x(), b.y()}});
    }
  const double clearance = 0.55 * spacing, row = spacing * std::sqrt(3.0) / 2;
  std::vector<Point> lattice;
  int parity = 0;
  for (double y = lo[1] + row / 2; y < hi[1]; y += row, parity ^= 1) {
    for (double x = lo[0] + (parity ? spacing / 2 : 0); x < hi[0]; x += spacing) {
      const Point p(x, y);
      const Face_handle f = cdt.locate(p);
      if (f == nullptr || cdt.is_infinite(f) || !f->is_in_domain()) continue;
      bool clear = true;
      for (const auto& [a, b] : segments)
        if (squared_distance_to_segment({x, y}, a, b) < clearance * clearance) {
          clear = false;
          break;
        }
      if (clear) lattice.push_back(p);
    }
  }
  for (const Point& p : lattice) cdt.insert(p);
  Marker::mark_facets(cdt, seeds.begin(), seeds.end(), false);
}

// Lloyd iterations under the density (current_density, current_scale), as CGAL's Mesh_global_optimizer_2
// with Lloyd_move_2 computes them: each free vertex moves to its dual cell's centroid unless the move is
// below `lloyd_freeze` of its least incident circumradius (it is then frozen), and the iterations stop
// once the largest 1% of the moves average below `lloyd_convergence` of those radii. The optimizer itself
// is not used: it keeps the moving vertices in a std::set of handles and so moves them in the order of
// their addresses, which differ with the thread that meshes the face, and a move's sum over its dual cell
// starts where that history left the vertex: rounding-level differences, a different mesh for each
// --threads. (CGAL 5.5's optimizer also leaves its time limit uninitialized: the iterations stopped after
// whatever the stack held, in CPU seconds.) Here the vertices move in the order of their positions.
// Returns the iterations done; each costs O(moving vertices x their dual cells) and a re-insertion each.
int smooth_by_lloyd(Triangulation& cdt, const Plane_mesh_input& input, const std::vector<Point>& seeds) {
  using Vertex_handle = Triangulation::Vertex_handle;
  const CGAL::Mesh_2::Lloyd_move_2<Triangulation, Density_sizing> move_of;
  const Density_sizing sizing(cdt);
  const auto by_position = [](const Vertex_handle& a, const Vertex_handle& b) {
    return a->point().x() < b->point().x() || (a->point().x() == b->point().x() && a->point().y() < b->point().y());
  };
  std::vector<Vertex_handle> moving;
  for (Vertex_handle v : cdt.finite_vertex_handles())
    if (!cdt.are_there_incident_constraints(v)) moving.push_back(v);
  const std::size_t initial = moving.size(), big_moves = std::max<std::size_t>(1, initial / 100);
  const double squared_freeze = input.lloyd_freeze * input.lloyd_freeze;
  std::size_t moving_before = std::numeric_limits<std::size_t>::max();
  int iteration = 0;
  for (; iteration < input.lloyd_iterations; ++iteration) {
    CGAL::Constrained_voronoi_diagram_2<Triangulation>(cdt).tag_faces_blind();
    std::sort(moving.begin(), moving.end(), by_position);
    std::vector<std::pair<Vertex_handle, Point>> moves;
    std::vector<double> ratios;  // squared move over least squared circumradius, of the moves made
    for (const Vertex_handle& v : moving) {
      const Kernel::Vector_2 move = move_of(v, cdt, sizing);
      double least = std::numeric_limits<double>::max();
      auto face = cdt.incident_faces(v), end = face;
      do
        if (!cdt.is_infinite(face))
          least = std::min(least, CGAL::squared_distance(cdt.circumcenter(face), face->vertex(0)->point()));
      while (++face != end);
      const double ratio = least > 0 ? move.squared_length() / least : 0;
      if (move == CGAL::NULL_VECTOR || least == 0 || ratio < squared_freeze) continue;  // frozen
      moves.push_back({v, v->point() + move});
      ratios.push_back(ratio);
    }
    if (squared_freeze > 0 && moving_before < 0.01 * static_cast<double>(initial) && moving_before == moves.size())
      break;
    std::sort(ratios.begin(), ratios.end(), std::greater<>());
    double sum = 0;
    for (std::size_t k = 0; k < std::min(big_moves, ratios.size()); ++k) sum += std::sqrt(ratios[k]);
    if (sum / static_cast<double>(big_moves) < input.lloyd_convergence) break;
    moving.clear();
    for (const auto& [v, position] : moves) {
      const std::size_t vertices = cdt.number_of_vertices();
      cdt.remove(v);
      const Vertex_handle moved = cdt.insert(position);
      if (cdt.number_of_vertices() == vertices) moving.push_back(moved);  // else it met another vertex
    }
    moving_before = moving.size();
    Marker::mark_facets(cdt, seeds.begin(), seeds.end(), false);
  }
  return iteration;
}

}  // namespace

Plane_mesh_output mesh_plane_region(const Plane_mesh_input& input) {
  const Plane_scale scale = scale_of(input);
  Triangulation cdt;
  for (const Plane_mesh_input::Polyline& polyline : input.polylines) {
    std::vector<Triangulation::Vertex_handle> handles;
    for (std::size_t k = 0; k < polyline.points.size(); ++k) {
      auto v = cdt.insert(scale.to_triangulation(polyline.points[k]));
      if (polyline.ids[k] >= 0) v->info().id = polyline.ids[k];
      handles.push_back(v);
    }
    for (std::size_t k = 0; k + 1 < handles.size(); ++k)
      if (handles[k] != handles[k + 1]) cdt.insert_constraint(handles[k], handles[k + 1]);
  }
  Plane_mesh_output output;
  if (cdt.dimension() < 2) return output;

  // Which regions to mesh: decided at the centroid of each region's largest triangle. The others become
  // seeds, which CGAL marks as outside the domain.
  std::vector<Point> seeds;
  bool any_inside = false;
  for (const std::vector<Face_handle>& region : regions_of(cdt)) {
    Face_handle largest = region.front();
    for (Face_handle f : region)
      if (area(f) > area(largest)) largest = f;
    const Point c = centroid(largest);
    if (input.inside(scale.to_plane(c)))
      any_inside = true;
    else
      seeds.push_back(c);
  }
  if (!any_inside) return output;

  if (input.lattice) seed_lattice(cdt, input, scale, seeds);

  Lifted_criteria criteria(input, scale);
  CGAL::Delaunay_mesher_no_edge_refinement_2<Triangulation, Lifted_criteria> mesher(cdt, criteria);
  mesher.set_seeds(seeds.begin(), seeds.end(), false);
  mesher.refine_mesh();

  // A region with no vertex of its own would lie flat on its boundary's chords (two faces on one closed
  // edge would then coincide): it gets its largest triangle's centroid.
  bool inserted = false;
  for (const std::vector<Face_handle>& region : regions_of(cdt)) {
    if (!region.front()->is_in_domain()) continue;
    bool own_vertex = false;
    Face_handle largest = region.front();
    for (Face_handle f : region) {
      for (int k = 0; k < 3 && !own_vertex; ++k) own_vertex = !cdt.are_there_incident_constraints(f->vertex(k));
      if (area(f) > area(largest)) largest = f;
    }
    if (own_vertex) continue;
    cdt.insert(centroid(largest), largest);
    inserted = true;
  }
  if (inserted) CGAL::Delaunay_mesher_2<Triangulation, CGAL::Delaunay_mesh_size_criteria_2<Triangulation>>::mark_facets(cdt, seeds.begin(), seeds.end(), false);

  if (input.lloyd_iterations > 0) {
    current_density = &input.density;
    current_scale = scale;
    output.lloyd_iterations = smooth_by_lloyd(cdt, input, seeds);
    current_density = nullptr;
  }

  // Labels: from a constraint around each region whose two points tell one.
  for (const std::vector<Face_handle>& region : regions_of(cdt)) {
    if (!region.front()->is_in_domain()) continue;
    std::int64_t label = -1;
    for (Face_handle f : region) {
      for (int i = 0; i < 3 && label < 0; ++i) {
        if (!cdt.is_constrained({f, i})) continue;
        const std::int64_t u = f->vertex(Triangulation::cw(i))->info().id, v = f->vertex(Triangulation::ccw(i))->info().id;
        if (u >= 0 && v >= 0) label = input.segment_label(u, v);
      }
      if (label >= 0) break;
    }
    if (label < 0) label = input.default_label;
    for (Face_handle f : region) {
      std::array<std::int64_t, 3> t;
      for (int k = 0; k < 3; ++k) {
        auto v = f->vertex(k);
        if (v->info().id == -1) {
          output.new_points.push_back(input.lift(scale.to_plane(v->point())));
          v->info().id = -1 - static_cast<std::int64_t>(output.new_points.size());  // -2 - k for new point k
        }
        t[k] = v->info().id;
      }
      output.triangles.push_back(t);
      output.labels.push_back(label);
    }
  }
  // New point k was tagged -2 - k while filling (-1 meant "none yet"); it is -1 - k in the output.
  for (auto& t : output.triangles)
    for (auto& id : t)
      if (id < 0) id += 1;
  return output;
}

bool odd_crossings(const std::vector<std::pair<Point2, Point2>>& segments, const Point2& p) {
  const Point q(p[0], p[1]);
  bool odd = false;
  for (const auto& [u, v] : segments) {
    const bool u_above = u[1] > p[1], v_above = v[1] > p[1];
    if (u_above == v_above) continue;
    // The segment crosses the line y = p[1]: right of p when p lies left of it going upwards.
    const CGAL::Orientation side = CGAL::orientation(Point(u[0], u[1]), Point(v[0], v[1]), q);
    if (side == (v_above ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN)) odd = !odd;
  }
  return odd;
}

}  // namespace apollonius
