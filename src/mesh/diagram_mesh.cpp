#include "mesh/diagram_mesh.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "diagram/threads.h"
#include "mesh/edge_samples.h"
#include "mesh/plane_mesher.h"
#include "predicates/weighted_distance_at_point.h"

namespace apollonius {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

constexpr double kPi = 3.14159265358979323846;

double weighted_distance(const Point3& x, const Site& s) {
  return distance(x, Point3{s.x, s.y, s.z}) - s.w;
}

std::pair<std::uint32_t, std::uint32_t> key_of(std::uint32_t u, std::uint32_t v) { return {std::min(u, v), std::max(u, v)}; }

// An edge's samples: point ids and their parameters along its curve, in forward order.
struct Edge_polyline {
  std::vector<std::uint32_t> ids;
  std::vector<double> parameters;
};

// A chord between two consecutive samples of an edge: where the box planes cut it is found on the curve.
struct Edge_chord {
  std::size_t edge;
  double first, second;  // the parameters of the chord's smaller and larger id
};

struct Builder {
  const std::vector<Site>& sites;
  const Diagram_topology& topology;
  Mesh_options options;
  Axis_box box;
  double step = 0;
  Point3 centre{};
  double cut_radius = 0;  // the disc of this radius about the box centre's projection covers the box's

  std::vector<bool> active;
  std::vector<Site_index> active_sites;
  std::vector<Point3> points;
  std::vector<std::uint8_t> walls;  // per point: bit w when it lies on wall w
  std::vector<std::uint8_t> kinds;  // per point: 0 a sample or a point made by meshing or cutting a face,
                                    // 1 a diagram vertex, 2 where a wall cuts an edge
  std::vector<std::int64_t> vertex_point;
  std::vector<Edge_polyline> polylines;  // per edge id, for the edges sampled
  std::map<std::pair<std::uint32_t, std::uint32_t>, Edge_chord> chords;
  std::vector<Mesh_triangle> triangles;
  Mesh_statistics statistics;

  Builder(const std::vector<Site>& s, const Diagram_topology& t, const Mesh_options& o)
      : sites(s), topology(t), options(o) {}

  std::uint32_t add_point(const Point3& x, std::uint8_t on_walls = 0) {
    points.push_back(x);
    walls.push_back(on_walls);
    kinds.push_back(0);
    return static_cast<std::uint32_t>(points.size() - 1);
  }

  std::uint32_t vertex_id(std::size_t v) {
    if (vertex_point[v] < 0) {
      const auto& r = topology.vertices.vertices[v].rounded;
      vertex_point[v] = add_point({r[0], r[1], r[2]});
      kinds.back() = 1;
    }
    return static_cast<std::uint32_t>(vertex_point[v]);
  }

  double local_step(const Point3& x) const { return step + 0.25 * std::max(0.0, distance(x, centre) - cut_radius); }

  // Whether every face through the edge sees x outside its cut disc.
  bool far_for_edge(const std::vector<Bisector_frame>& frames, const Point3& x) const {
    for (const Bisector_frame& f : frames) {
      const Point2 p = f.project(x), c = f.project(centre);
      if (std::hypot(p[0] - c[0], p[1] - c[1]) <= cut_radius * 1.05) return false;
    }
    return true;
  }

  void sample_edge(std::size_t e) {
    const Diagram_edge& edge = topology.edges[e];
    const std::array<Site_index, 3> triple{edge.tie_set[0], edge.tie_set[1], edge.tie_set[2]};
    const Trisector trisector(triple, {sites[triple[0]], sites[triple[1]], sites[triple[2]]});
    const Conic_curve curve(trisector);
    std::vector<Bisector_frame> frames;
    for (std::size_t i = 0; i < edge.tie_set.size(); ++i)
      for (std::size_t j = i + 1; j < edge.tie_set.size(); ++j)
        frames.emplace_back(sites[edge.tie_set[i]], sites[edge.tie_set[j]]);
    const Local_step h = [this](const Point3& x) { return local_step(x); };
    const auto far = [&](const Point3& x) { return far_for_edge(frames, x); };
    double t0 = 0, t1 = 0;
    if (edge.closed) {
      t0 = 0;
      t1 = 2 * kPi;
    } else {
      if (edge.start) t0 = curve.parameter(topology.vertices.vertices[*edge.start].rounded);
      if (edge.end) t1 = curve.parameter(topology.vertices.vertices[*edge.end].rounded);
      if (edge.start && edge.end) {
        if (curve.closed()) {
          t1 = t0 + std::fmod(t1 - t0 + 4 * kPi, 2 * kPi);
          if (*edge.start == *edge.end || t1 <= t0) t1 = t0 + 2 * kPi;
        } else if (t1 < t0) {
          t1 = t0;
        }
      } else if (edge.start) {
        t1 = walk_until(curve, t0, +1, h, far);
      } else if (edge.end) {
        t0 = walk_until(curve, t1, -1, h, far);
      } else {
        t0 = walk_until(curve, 0, -1, h, far);
        t1 = walk_until(curve, 0, +1, h, far);
      }
    }
    Edge_polyline& polyline = polylines[e];
    // A closed curve, or a loop from a vertex back to it, needs a polygon of some area: 8 chords at least.
    const bool round = edge.closed || (edge.start && edge.end && *edge.start == *edge.end);
    polyline.parameters = sample_parameters(curve, t0, t1, h, round ? 8 : 1);
    const std::size_t n = polyline.parameters.size();
    for (std::size_t k = 0; k < n; ++k) {
      if (k == 0 && edge.start)
        polyline.ids.push_back(vertex_id(*edge.start));
      else if (k + 1 == n && edge.end)
        polyline.ids.push_back(vertex_id(*edge.end));
      else if (k + 1 == n && edge.closed)
        polyline.ids.push_back(polyline.ids.front());
      else
        polyline.ids.push_back(add_point(curve.position(polyline.parameters[k])));
    }
    statistics.edge_samples += n;
  }

  // The box pieces of the topology-sampled edges: chord -> edge.
  void index_chords() {
    for (std::size_t e = 0; e < polylines.size(); ++e) {
      const Edge_polyline& p = polylines[e];
      for (std::size_t k = 0; k + 1 < p.ids.size(); ++k) {
        if (p.ids[k] == p.ids[k + 1]) continue;
        const bool ordered = p.ids[k] < p.ids[k + 1];
        chords[key_of(p.ids[k], p.ids[k + 1])] =
            Edge_chord{e, ordered ? p.parameters[k] : p.parameters[k + 1], ordered ? p.parameters[k + 1] : p.parameters[k]};
      }
    }
  }

  // Whether no other active site is nearer than both a and b at x (a point of their sheet). Exact on x.
  bool pair_nearest(Site_index a, Site_index b, const Point3& x) const {
    for (Site_index s : active_sites)
      if (s != a && s != b && compare_weighted_distances(x, sites[s], sites[a]) == Sign::NEGATIVE &&
          compare_weighted_distances(x, sites[s], sites[b]) == Sign::NEGATIVE)
        return false;
    return true;
  }

  // The nearest active site at x, the first in order on a tie. Exact on x.
  Site_index nearest_site(const Point3& x) const {
    Site_index best = active_sites.front();
    for (Site_index s : active_sites)
      if (compare_weighted_distances(x, sites[s], sites[best]) == Sign::NEGATIVE) best = s;
    return best;
  }

  struct Pair_result {
    Site_index a, b;
    Plane_mesh_output output;
  };

  Pair_result mesh_pair(Site_index a, Site_index b, const std::vector<std::size_t>& face_ids) const {
    const Bisector_frame frame(sites[a], sites[b]);
    const Point2 c = frame.project(centre);
    Plane_mesh_input input;
    // The cut disc, as a circumscribed polygon.
    const int n = std::max(16, static_cast<int>(std::ceil(2 * kPi * cut_radius / step)));
    const double radius = cut_radius * 1.05 / std::cos(kPi / n);
    Plane_mesh_input::Polyline disc;
    for (int k = 0; k <= n; ++k) {
      const double angle = 2 * kPi * (k % n) / n;
      disc.points.push_back({c[0] + radius * std::cos(angle), c[1] + radius * std::sin(angle)});
      disc.ids.push_back(-1);
    }
    input.polylines.push_back(disc);
    std::map<std::size_t, std::size_t> face_of_edge;
    std::int64_t default_label = static_cast<std::int64_t>(face_ids.front());
    for (std::size_t f : face_ids) {
      if (topology.faces[f].boundary.empty()) default_label = static_cast<std::int64_t>(f);
      for (const auto& component : topology.faces[f].boundary)
        for (std::size_t e : component) {
          face_of_edge[e] = f;
          Plane_mesh_input::Polyline line;
          for (std::uint32_t id : polylines[e].ids) {
            line.points.push_back(frame.project(points[id]));
            line.ids.push_back(id);
          }
          input.polylines.push_back(std::move(line));
        }
    }
    // A bounded face is the inside of its boundary polylines (odd crossing parity): decided on the
    // polylines themselves, so a thin face whose chords miss its interior is still meshed. The rest of an
    // unbounded face's plane is judged by the nearest sites at the region's witness point.
    std::vector<std::vector<std::pair<Point2, Point2>>> bounded_segments;
    bool any_unbounded = false;
    for (std::size_t f : face_ids) {
      if (!topology.faces[f].bounded) {
        any_unbounded = true;
        continue;
      }
      std::vector<std::pair<Point2, Point2>> segments;
      for (const auto& component : topology.faces[f].boundary)
        for (std::size_t e : component)
          for (std::size_t k = 0; k + 1 < polylines[e].ids.size(); ++k)
            segments.push_back({frame.project(points[polylines[e].ids[k]]), frame.project(points[polylines[e].ids[k + 1]])});
      bounded_segments.push_back(std::move(segments));
    }
    input.inside = [&, c, any_unbounded](const Point2& p) {
      if (std::hypot(p[0] - c[0], p[1] - c[1]) >= cut_radius * 1.05) return false;
      for (const auto& segments : bounded_segments)
        if (odd_crossings(segments, p)) return true;
      return any_unbounded && pair_nearest(a, b, frame.lift(p));
    };
    input.lift = [&frame](const Point2& p) { return frame.lift(p); };
    input.density = [&frame](const Point2& p) { return frame.area_ratio(p); };
    input.segment_label = [&](std::int64_t u, std::int64_t v) -> std::int64_t {
      auto it = chords.find(key_of(static_cast<std::uint32_t>(u), static_cast<std::uint32_t>(v)));
      if (it == chords.end()) return -1;
      auto f = face_of_edge.find(it->second.edge);
      return f == face_of_edge.end() ? -1 : static_cast<std::int64_t>(f->second);
    };
    input.default_label = default_label;
    input.step = step;
    input.lloyd_iterations = options.lloyd_iterations;
    return {a, b, mesh_plane_region(input)};
  }

  void orient_face_triangle(Mesh_triangle& t) const {
    const Point3 &p = points[t.vertices[0]], &q = points[t.vertices[1]], &r = points[t.vertices[2]];
    const Point3 u{q[0] - p[0], q[1] - p[1], q[2] - p[2]}, v{r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const Point3 normal{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const Point3 h{(p[0] + q[0] + r[0]) / 3, (p[1] + q[1] + r[1]) / 3, (p[2] + q[2] + r[2]) / 3};
    const Site &a = sites[t.site_a], &b = sites[t.site_b];
    const double da = distance(h, {a.x, a.y, a.z}), db = distance(h, {b.x, b.y, b.z});
    double dot = 0;
    const std::array<double, 3> ha{h[0] - a.x, h[1] - a.y, h[2] - a.z}, hb{h[0] - b.x, h[1] - b.y, h[2] - b.z};
    for (int k = 0; k < 3; ++k) dot += normal[k] * (ha[k] / da - hb[k] / db);
    if (dot < 0) std::swap(t.vertices[1], t.vertices[2]);
  }

  void mesh_faces() {
    std::map<std::pair<Site_index, Site_index>, std::vector<std::size_t>> pairs;
    std::vector<bool> selected(sites.size(), options.sites.empty());
    for (Site_index s : options.sites) selected[s] = true;
    for (std::size_t f = 0; f < topology.faces.size(); ++f) {
      const Diagram_face& face = topology.faces[f];
      if (selected[face.a] || selected[face.b]) pairs[{face.a, face.b}].push_back(f);
    }
    auto start = Clock::now();
    for (const auto& [pair, faces] : pairs)
      for (std::size_t f : faces)
        for (const auto& component : topology.faces[f].boundary)
          for (std::size_t e : component)
            if (polylines[e].ids.empty()) sample_edge(e);
    index_chords();
    statistics.sampling_seconds = seconds_since(start);
    start = Clock::now();
    std::vector<std::pair<std::pair<Site_index, Site_index>, const std::vector<std::size_t>*>> work;
    for (const auto& [pair, faces] : pairs) work.push_back({pair, &faces});
    std::vector<Pair_result> results(work.size());
    tbb::task_arena arena(usable_threads(options.threads));
    arena.execute([&] {
      tbb::parallel_for(std::size_t(0), work.size(), [&](std::size_t k) {
        results[k] = mesh_pair(work[k].first.first, work[k].first.second, *work[k].second);
      });
    });
    for (const Pair_result& r : results) {
      const std::uint32_t base = static_cast<std::uint32_t>(points.size());
      for (const Point3& x : r.output.new_points) add_point(x);
      for (std::size_t k = 0; k < r.output.triangles.size(); ++k) {
        Mesh_triangle t;
        for (int i = 0; i < 3; ++i) {
          const std::int64_t id = r.output.triangles[k][i];
          t.vertices[i] = id >= 0 ? static_cast<std::uint32_t>(id) : base + static_cast<std::uint32_t>(-1 - id);
        }
        t.site_a = static_cast<std::int32_t>(r.a);
        t.site_b = static_cast<std::int32_t>(r.b);
        t.face_id = r.output.labels[k];
        orient_face_triangle(t);
        triangles.push_back(t);
      }
      if (!r.output.triangles.empty()) ++statistics.faces_meshed;
      statistics.lloyd_iterations += r.output.lloyd_iterations;
    }
    statistics.faces_seconds = seconds_since(start);
  }

  // ---- The cut by the box's planes --------------------------------------------------------------------

  // Cuts 0 to 5 are the box's planes; cut 6 (kProbe) the probe-expanded ball of the site concerned.
  static constexpr int kProbe = 6;
  static int axis_of(int wall) { return wall / 2; }
  double bound_of(int wall) const { return wall % 2 ? box.hi[wall / 2] : box.lo[wall / 2]; }
  // Which side of the wall's plane, or of site s's sphere of radius w_s + P, x lies on: positive outside.
  // Exact on x (a difference of two doubles has the sign of their comparison).
  Sign side(const Point3& x, int wall, Site_index s = 0) const {
    if (wall == kProbe) return side_of_grown_ball(x, sites[s], options.probe);
    const double d = outside(x, wall);
    return d > 0 ? Sign::POSITIVE : d < 0 ? Sign::NEGATIVE : Sign::ZERO;
  }

  // Positive outside the wall's half-space, or outside site s's ball of radius w_s + P: the level that
  // the constructions (Gauss-Newton) follow; side() decides.
  double outside(const Point3& x, int wall, Site_index s = 0) const {
    if (wall == kProbe) return distance(x, Point3{sites[s].x, sites[s].y, sites[s].z}) - sites[s].w - options.probe;
    return wall % 2 ? x[wall / 2] - box.hi[wall / 2] : box.lo[wall / 2] - x[wall / 2];
  }

  std::map<std::tuple<std::uint32_t, std::uint32_t, int>, std::uint32_t> crossings;

  // The point where the mesh edge (u, v), one side of the wall's plane each, crosses it: on the edge's
  // curve, on the sheet's curve in another wall, or on the sheet along the chord's projection.
  std::uint32_t crossing(std::uint32_t u, std::uint32_t v, int wall, Site_index a, Site_index b) {
    const auto key = std::make_tuple(std::min(u, v), std::max(u, v), wall);
    if (auto it = crossings.find(key); it != crossings.end()) return it->second;
    const int k = wall == kProbe ? 0 : axis_of(wall);
    const double bound = wall == kProbe ? 0 : bound_of(wall);
    Point3 x;
    std::uint8_t on = static_cast<std::uint8_t>(1u << wall);
    auto chord = chords.find(key_of(u, v));
    const std::uint8_t common = walls[u] & walls[v];
    if (chord != chords.end()) {
      const Edge_chord c = chord->second;
      const Diagram_edge& edge = topology.edges[c.edge];
      const std::array<Site_index, 3> triple{edge.tie_set[0], edge.tie_set[1], edge.tie_set[2]};
      const Trisector trisector(triple, {sites[triple[0]], sites[triple[1]], sites[triple[2]]});
      const Conic_curve curve(trisector);
      double lo = c.first, hi = c.second;
      const Site_index s = edge.tie_set[0];  // on the edge every site of its tie set is as near
      const bool lo_outside = side(points[std::min(u, v)], wall, s) == Sign::POSITIVE;
      for (int i = 0; i < 200 && lo != hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        ((side(curve.position(mid), wall, s) == Sign::POSITIVE) == lo_outside ? lo : hi) = mid;
      }
      const double t = 0.5 * (lo + hi);
      x = curve.position(t);
      if (wall != kProbe) x[k] = bound;
      const std::uint32_t id = add_point(x, on);
      kinds[id] = 2;
      crossings[key] = id;
      chords[key_of(std::min(u, v), id)] = std::min(u, v) < id ? Edge_chord{c.edge, c.first, t} : Edge_chord{c.edge, t, c.first};
      chords[key_of(std::max(u, v), id)] = std::max(u, v) < id ? Edge_chord{c.edge, c.second, t} : Edge_chord{c.edge, t, c.second};
      return id;
    }
    const Bisector_frame frame(sites[a], sites[b]);
    const Point2 pu = frame.project(points[u]), pv = frame.project(points[v]);
    // Along the chord's projection: the crossing of the sheet with the plane.
    double lo = 0, hi = 1;
    const bool u_outside = side(points[u], wall, a) == Sign::POSITIVE;
    auto at = [&](double l) { return frame.lift({pu[0] + l * (pv[0] - pu[0]), pu[1] + l * (pv[1] - pu[1])}); };
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;
      ((side(at(mid), wall, a) == Sign::POSITIVE) == u_outside ? lo : hi) = mid;
    }
    Point2 p{pu[0] + 0.5 * (lo + hi) * (pv[0] - pu[0]), pu[1] + 0.5 * (lo + hi) * (pv[1] - pu[1])};
    int other = -1;
    for (int w = 0; w < 6 && wall != kProbe; ++w)
      if ((common >> w) & 1u) other = w;
    if (other >= 0) {
      // Both ends on another wall: Newton in the plane for the point of the sheet on both walls.
      const int k2 = axis_of(other);
      const double bound2 = bound_of(other);
      const double scale = std::max(step, std::hypot(p[0], p[1]));  // in the input's units, as the tolerances
      for (int i = 0; i < 30; ++i) {
        const Point3 y = frame.lift(p);
        const double f1 = y[k] - bound, f2 = y[k2] - bound2;
        if (std::abs(f1) + std::abs(f2) <= 1e-15 * scale) break;
        const double d = 1e-7 * scale;
        const Point3 ys = frame.lift({p[0] + d, p[1]}), yt = frame.lift({p[0], p[1] + d});
        const double j11 = (ys[k] - y[k]) / d, j12 = (yt[k] - y[k]) / d, j21 = (ys[k2] - y[k2]) / d, j22 = (yt[k2] - y[k2]) / d;
        const double det = j11 * j22 - j12 * j21;
        if (det == 0) break;
        p = {p[0] - (j22 * f1 - j12 * f2) / det, p[1] - (-j21 * f1 + j11 * f2) / det};
      }
      x = frame.lift(p);
      x[k2] = bound2;
      on = static_cast<std::uint8_t>(on | (1u << other));
    } else {
      x = frame.lift(p);
    }
    if (wall != kProbe) x[k] = bound;
    const std::uint32_t id = add_point(x, on);
    crossings[key] = id;
    return id;
  }

  void cut_by_wall(int wall) {
    std::vector<Mesh_triangle> kept;
    if (wall != kProbe)
      for (std::size_t i = 0; i < points.size(); ++i)
        if (side(points[i], wall) == Sign::ZERO) walls[i] = static_cast<std::uint8_t>(walls[i] | (1u << wall));
    for (const Mesh_triangle& t : triangles) {
      std::array<int, 3> s;
      for (int k = 0; k < 3; ++k) s[k] = to_int(side(points[t.vertices[k]], wall, static_cast<Site_index>(t.site_a)));
      if (s[0] <= 0 && s[1] <= 0 && s[2] <= 0) {
        kept.push_back(t);
        continue;
      }
      if (s[0] >= 0 && s[1] >= 0 && s[2] >= 0) continue;
      std::vector<std::uint32_t> polygon;
      for (int k = 0; k < 3; ++k) {
        const int m = (k + 1) % 3;
        if (s[k] <= 0) polygon.push_back(t.vertices[k]);
        if ((s[k] < 0 && s[m] > 0) || (s[k] > 0 && s[m] < 0))
          polygon.push_back(crossing(t.vertices[k], t.vertices[m], wall, static_cast<Site_index>(t.site_a),
                                     static_cast<Site_index>(t.site_b)));
      }
      for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
        Mesh_triangle piece = t;
        piece.vertices = {polygon[0], polygon[k], polygon[k + 1]};
        if (piece.vertices[0] == piece.vertices[1] || piece.vertices[1] == piece.vertices[2] ||
            piece.vertices[0] == piece.vertices[2])
          continue;
        kept.push_back(piece);
      }
    }
    triangles = std::move(kept);
  }

  // ---- Faces cut by the box, meshed again inside it ------------------------------------------------
  // The cut leaves slivers along the walls. A cut face is meshed again from its new boundary: its edges'
  // pieces as they are (shared with the other faces on them), and its rims on the walls resampled at the
  // step between the points it shares (edge crossings, the box's edges). An edge sample closer than 0.4
  // step to a crossing is dropped by every face on the edge alike.

  // The point of the sheet on the wall nearest p (Gauss-Newton in the plane).
  Point3 onto_wall(const Bisector_frame& frame, Point2 p, int wall, Site_index a) const {
    const int k = wall == kProbe ? 0 : axis_of(wall);
    const double bound = wall == kProbe ? 0 : bound_of(wall);
    const double scale = std::max({step, std::abs(bound), std::hypot(p[0], p[1])});  // in the input's units
    auto level = [&](const Point3& y) { return wall == kProbe ? outside(y, kProbe, a) : y[k] - bound; };
    for (int i = 0; i < 40; ++i) {
      const Point3 y = frame.lift(p);
      const double g = level(y);
      if (std::abs(g) <= 1e-15 * scale) break;
      const double d = 1e-7 * scale;
      const double gs = (level(frame.lift({p[0] + d, p[1]})) - g) / d, gt = (level(frame.lift({p[0], p[1] + d})) - g) / d;
      const double norm = gs * gs + gt * gt;
      if (norm == 0) break;
      p = {p[0] - g * gs / norm, p[1] - g * gt / norm};
    }
    Point3 x = frame.lift(p);
    if (wall != kProbe) x[k] = bound;
    return x;
  }

  static int lowest_wall(std::uint8_t bits) {
    for (int w = 0; w <= kProbe; ++w)
      if ((bits >> w) & 1u) return w;
    return -1;
  }

  std::vector<char> dropped_points() const {
    std::vector<char> dropped(points.size(), 0);
    for (const auto& [key, chord] : chords) {
      const auto [u, v] = key;
      if (u >= points.size() || v >= points.size()) continue;
      const bool u_cut = kinds[u] == 2, v_cut = kinds[v] == 2;
      if (u_cut == v_cut) continue;
      const std::uint32_t plain = u_cut ? v : u, cut = u_cut ? u : v;
      if (kinds[plain] == 0 && walls[plain] == 0 && distance(points[plain], points[cut]) < 0.4 * step) dropped[plain] = 1;
    }
    return dropped;
  }

  // Meshes the pair's cut face again; false (and nothing changed) when its boundary is not as expected.
  bool remesh_pair(Site_index a, Site_index b, const std::vector<std::size_t>& mine, const std::vector<char>& dropped,
                   std::vector<Mesh_triangle>& added) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::int64_t> label_of_edge;
    for (std::size_t i : mine)
      for (int k = 0; k < 3; ++k) {
        const auto e = key_of(triangles[i].vertices[k], triangles[i].vertices[(k + 1) % 3]);
        ++uses[e];
        label_of_edge[e] = triangles[i].face_id;
      }
    std::map<std::uint32_t, std::vector<std::uint32_t>> around;  // boundary adjacency
    for (const auto& [e, n] : uses) {
      if (n != 1) continue;
      around[e.first].push_back(e.second);
      around[e.second].push_back(e.first);
    }
    // Merge through dropped samples.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::int64_t> fixed;  // edge pieces -> face label
    std::vector<std::pair<std::uint32_t, std::uint32_t>> rims;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::int64_t> rim_label;
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    for (const auto& [e, n] : uses) {
      if (n != 1 || seen.count(e)) continue;
      seen.insert(e);
      if (chords.count(e)) {
        std::uint32_t u = e.first, v = e.second;
        // Extend across dropped points on either side.
        for (std::uint32_t* end : {&u, &v}) {
          std::uint32_t from = *end == u ? v : u;
          while (dropped[*end] && around[*end].size() == 2) {
            const std::uint32_t next = around[*end][0] == from ? around[*end][1] : around[*end][0];
            seen.insert(key_of(*end, next));
            from = *end;
            *end = next;
          }
        }
        if (u == v) return false;
        const auto merged = key_of(u, v);
        if (!chords.count(merged)) chords[merged] = chords[e];
        fixed[merged] = label_of_edge[e];
        continue;
      }
      if (lowest_wall(walls[e.first] & walls[e.second]) < 0) return false;
      rims.push_back(e);
      rim_label[e] = label_of_edge[e];
    }
    // Rim chains between shared points.
    std::map<std::uint32_t, std::vector<std::uint32_t>> rim_around;
    for (const auto& [u, v] : rims) rim_around[u].push_back(v), rim_around[v].push_back(u);
    std::set<std::uint32_t> fixed_points;
    for (const auto& [e, l] : fixed) fixed_points.insert(e.first), fixed_points.insert(e.second);
    auto is_break = [&](std::uint32_t p) {
      const std::uint8_t w = walls[p];
      return rim_around[p].size() != 2 || kinds[p] != 0 || fixed_points.count(p) || (w & (w - 1)) != 0;
    };
    const Bisector_frame frame(sites[a], sites[b]);
    Plane_mesh_input input;
    std::set<std::pair<std::uint32_t, std::uint32_t>> walked;
    std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> chain_label;
    auto walk = [&](std::uint32_t start, std::uint32_t next) {
      std::vector<std::uint32_t> chain{start};
      std::uint32_t from = start, at = next;
      walked.insert(key_of(start, next));
      while (true) {
        chain.push_back(at);
        if (at == start || is_break(at)) break;
        const std::uint32_t after = rim_around[at][0] == from ? rim_around[at][1] : rim_around[at][0];
        walked.insert(key_of(at, after));
        from = at;
        at = after;
      }
      const int wall = lowest_wall(walls[chain[0]] & walls[chain[1]]);
      const std::int64_t label = rim_label[key_of(chain[0], chain[1])];
      double length = 0;
      std::vector<double> at_length{0};
      for (std::size_t k = 1; k < chain.size(); ++k)
        at_length.push_back(length += distance(points[chain[k - 1]], points[chain[k]]));
      const bool loop = chain.front() == chain.back();
      const std::size_t n = std::max<std::size_t>(loop ? 3 : 1, static_cast<std::size_t>(std::lround(length / step)));
      Plane_mesh_input::Polyline line;
      std::vector<std::uint32_t> ids{chain.front()};
      std::size_t segment = 0;
      for (std::size_t i = 1; i < n; ++i) {
        const double target = length * static_cast<double>(i) / static_cast<double>(n);
        while (at_length[segment + 1] < target) ++segment;
        const double f = (target - at_length[segment]) / (at_length[segment + 1] - at_length[segment]);
        const Point3 &p = points[chain[segment]], &q = points[chain[segment + 1]];
        const Point3 x{p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1]), p[2] + f * (q[2] - p[2])};
        const std::uint32_t id = add_point(onto_wall(frame, frame.project(x), wall, a), static_cast<std::uint8_t>(1u << wall));
        ids.push_back(id);
      }
      ids.push_back(chain.back());
      for (std::size_t i = 0; i < ids.size(); ++i) {
        line.points.push_back(frame.project(points[ids[i]]));
        line.ids.push_back(ids[i]);
        if (i > 0) chain_label[{std::min(ids[i - 1], ids[i]), std::max(ids[i - 1], ids[i])}] = label;
      }
      input.polylines.push_back(std::move(line));
    };
    for (const auto& [p, list] : rim_around)
      if (is_break(p))
        for (std::uint32_t q : list)
          if (!walked.count(key_of(p, q))) walk(p, q);
    for (const auto& [u, v] : rims)
      if (!walked.count(key_of(u, v))) walk(u, v);  // closed rims with no shared point
    for (const auto& [e, label] : fixed) {
      Plane_mesh_input::Polyline line;
      for (std::uint32_t id : {e.first, e.second}) {
        line.points.push_back(frame.project(points[id]));
        line.ids.push_back(id);
      }
      input.polylines.push_back(std::move(line));
    }
    input.inside = [&](const Point2& p) {
      const Point3 x = frame.lift(p);
      if (options.has_probe) {
        if (side(x, kProbe, a) != Sign::NEGATIVE) return false;
      } else {
        for (int k = 0; k < 3; ++k)
          if (!(x[k] > box.lo[k] && x[k] < box.hi[k])) return false;
      }
      return pair_nearest(a, b, x);
    };
    input.lift = [&frame](const Point2& p) { return frame.lift(p); };
    input.density = [&frame](const Point2& p) { return frame.area_ratio(p); };
    input.segment_label = [&](std::int64_t u, std::int64_t v) -> std::int64_t {
      const auto key = std::make_pair(std::min(u, v), std::max(u, v));
      if (auto it = fixed.find({static_cast<std::uint32_t>(key.first), static_cast<std::uint32_t>(key.second)}); it != fixed.end())
        return it->second;
      auto it = chain_label.find(key);
      return it == chain_label.end() ? -1 : it->second;
    };
    input.default_label = triangles[mine.front()].face_id;
    input.step = step;
    input.lloyd_iterations = options.lloyd_iterations;
    const Plane_mesh_output output = mesh_plane_region(input);
    if (output.triangles.empty()) return false;
    // The new mesh's boundary must be exactly the constraints given (else a region was misjudged).
    std::map<std::pair<std::int64_t, std::int64_t>, int> new_uses;
    for (const auto& t : output.triangles)
      for (int k = 0; k < 3; ++k) ++new_uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
    std::set<std::pair<std::int64_t, std::int64_t>> boundary, expected;
    for (const auto& [e, n] : new_uses)
      if (n == 1) boundary.insert(e);
    for (const Plane_mesh_input::Polyline& line : input.polylines)
      for (std::size_t k = 0; k + 1 < line.ids.size(); ++k)
        expected.insert({std::min(line.ids[k], line.ids[k + 1]), std::max(line.ids[k], line.ids[k + 1])});
    if (boundary != expected) return false;
    const std::uint32_t base = static_cast<std::uint32_t>(points.size());
    for (const Point3& x : output.new_points) add_point(x);
    for (std::size_t k = 0; k < output.triangles.size(); ++k) {
      Mesh_triangle t;
      for (int i = 0; i < 3; ++i) {
        const std::int64_t id = output.triangles[k][i];
        t.vertices[i] = id >= 0 ? static_cast<std::uint32_t>(id) : base + static_cast<std::uint32_t>(-1 - id);
      }
      t.site_a = static_cast<std::int32_t>(a);
      t.site_b = static_cast<std::int32_t>(b);
      t.face_id = output.labels[k];
      orient_face_triangle(t);
      added.push_back(t);
    }
    return true;
  }

  void remesh_cut_faces() {
    std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::size_t>> by_pair;
    for (std::size_t i = 0; i < triangles.size(); ++i) by_pair[{triangles[i].site_a, triangles[i].site_b}].push_back(i);
    // Samples are dropped near crossings only if every cut face can be meshed again with them dropped:
    // the faces on one edge must agree. Otherwise none is, and a face that still fails keeps its cut mesh.
    for (int attempt = 0; attempt < 2; ++attempt) {
      const std::vector<char> dropped = attempt == 0 ? dropped_points() : std::vector<char>(points.size(), 0);
      const std::size_t point_count = points.size();
      std::vector<char> replaced(triangles.size(), 0);
      std::vector<Mesh_triangle> added;
      std::size_t failed = 0;
      for (const auto& [pair, mine] : by_pair) {
        bool cut = false;
        for (std::size_t i : mine)
          for (std::uint32_t v : triangles[i].vertices) cut = cut || walls[v] != 0;
        if (!cut) continue;
        if (remesh_pair(static_cast<Site_index>(pair.first), static_cast<Site_index>(pair.second), mine, dropped, added))
          for (std::size_t i : mine) replaced[i] = 1;
        else
          ++failed;
      }
      if (failed > 0 && attempt == 0) {
        points.resize(point_count);
        walls.resize(point_count);
        kinds.resize(point_count);
        continue;
      }
      statistics.faces_not_remeshed = failed;
      std::vector<Mesh_triangle> kept;
      for (std::size_t i = 0; i < triangles.size(); ++i)
        if (!replaced[i]) kept.push_back(triangles[i]);
      kept.insert(kept.end(), added.begin(), added.end());
      triangles = std::move(kept);
      return;
    }
  }

  // ---- The probe spheres ---------------------------------------------------------------------------
  // With --probe, cell i is cut by its ball of radius R = w_i + P and closed by the piece of that ball's
  // sphere inside the cell, meshed in a stereographic chart from a point of the sphere outside the cell
  // (or, when the whole sphere is inside, as a subdivided icosahedron).

  void add_cap_triangle(std::array<std::uint32_t, 3> v, Site_index cell) {
    const Site& c = sites[cell];
    const Point3 &p = points[v[0]], &q = points[v[1]], &r = points[v[2]];
    const Point3 u{q[0] - p[0], q[1] - p[1], q[2] - p[2]}, w{r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const Point3 n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double out = n[0] * (p[0] - c.x) + n[1] * (p[1] - c.y) + n[2] * (p[2] - c.z);
    if (out < 0) std::swap(v[1], v[2]);
    Mesh_triangle t;
    t.vertices = v;
    t.site_a = -1 - kProbe;
    t.site_b = static_cast<std::int32_t>(cell);
    t.face_id = -1;
    triangles.push_back(t);
  }

  void mesh_whole_sphere(Site_index cell, double radius) {
    const Site& c = sites[cell];
    const double g = (1 + std::sqrt(5.0)) / 2;
    std::vector<Point3> v{{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                          {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    std::vector<std::array<std::size_t, 3>> f{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                              {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                              {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                              {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (Point3& x : v) {
      const double l = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
      x = {x[0] / l, x[1] / l, x[2] / l};
    }
    // Halve every edge until the edges on the sphere are at most the step.
    while (radius * distance(v[f[0][0]], v[f[0][1]]) > step && f.size() < 2000000) {
      std::map<std::pair<std::size_t, std::size_t>, std::size_t> middle;
      auto mid = [&](std::size_t a, std::size_t b) {
        auto [it, fresh] = middle.emplace(std::make_pair(std::min(a, b), std::max(a, b)), v.size());
        if (fresh) {
          Point3 m{(v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2};
          const double l = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
          v.push_back({m[0] / l, m[1] / l, m[2] / l});
        }
        return it->second;
      };
      std::vector<std::array<std::size_t, 3>> finer;
      for (const auto& t : f) {
        const std::size_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
        finer.push_back({t[0], ab, ca});
        finer.push_back({t[1], bc, ab});
        finer.push_back({t[2], ca, bc});
        finer.push_back({ab, bc, ca});
      }
      f = std::move(finer);
    }
    std::vector<std::uint32_t> ids;
    for (const Point3& x : v)
      ids.push_back(add_point({c.x + radius * x[0], c.y + radius * x[1], c.z + radius * x[2]},
                              static_cast<std::uint8_t>(1u << kProbe)));
    for (const auto& t : f) add_cap_triangle({ids[t[0]], ids[t[1]], ids[t[2]]}, cell);
  }

  void mesh_cap_of_cell(Site_index cell) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const Mesh_triangle& t : triangles) {
      if (t.is_wall() || (t.site_a != static_cast<std::int32_t>(cell) && t.site_b != static_cast<std::int32_t>(cell))) continue;
      for (int k = 0; k < 3; ++k) ++uses[key_of(t.vertices[k], t.vertices[(k + 1) % 3])];
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> rims;
    for (const auto& [edge, count] : uses) {
      if (count != 1) continue;
      if (!((walls[edge.first] & walls[edge.second]) >> kProbe & 1u)) {
        ++statistics.open_rims;
        continue;
      }
      rims.push_back(edge);
    }
    const Site& c = sites[cell];
    const double radius = c.w + options.probe;
    if (!(radius > 0)) return;
    auto on_sphere = [&](const Point3& u) { return Point3{c.x + radius * u[0], c.y + radius * u[1], c.z + radius * u[2]}; };
    // The point of the sphere farthest outside the cell: the pole of the chart.
    const double golden = kPi * (3 - std::sqrt(5.0));
    Point3 pole{0, 0, 1};
    double best = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < 512; ++k) {
      const double z = 1 - (2 * k + 1) / 512.0, r = std::sqrt(1 - z * z);
      const Point3 u{r * std::cos(golden * k), r * std::sin(golden * k), z};
      const Point3 x = on_sphere(u);
      double margin = -std::numeric_limits<double>::infinity();
      const double own = weighted_distance(x, c);
      for (Site_index s : active_sites)
        if (s != cell) margin = std::max(margin, own - weighted_distance(x, sites[s]));
      if (margin > best) best = margin, pole = u;
    }
    // Exactly, at the chosen point: whether another site is strictly nearer there than the cell's.
    const auto outside_cell = [&](const Point3& x) {
      for (Site_index s : active_sites)
        if (s != cell && compare_weighted_distances(x, sites[s], c) == Sign::NEGATIVE) return true;
      return false;
    };
    if (rims.empty()) {  // no face meets the sphere: it lies wholly in the cell or wholly out, as any point
      if (!outside_cell(on_sphere(pole))) mesh_whole_sphere(cell, radius);
      return;
    }
    // The chart needs its pole outside the cap; never assumed.
    if (!outside_cell(on_sphere(pole)))
      throw std::logic_error("mesh: no sample of the sphere of site " + std::to_string(cell) +
                             " lies outside its cell, yet faces cross the sphere");
    // A right-handed frame (e1, e2, pole); the chart q = R (v.e1, v.e2) / (1 - v.pole), v the unit vector.
    const std::pair<Point3, Point3> frame = orthonormal_complement(pole);
    const Point3 e1 = frame.first, e2 = frame.second;
    auto chart = [&](const Point3& x) {
      const Point3 v{(x[0] - c.x) / radius, (x[1] - c.y) / radius, (x[2] - c.z) / radius};
      const double d = 1 - (v[0] * pole[0] + v[1] * pole[1] + v[2] * pole[2]);
      return Point2{radius * (v[0] * e1[0] + v[1] * e1[1] + v[2] * e1[2]) / d,
                    radius * (v[0] * e2[0] + v[1] * e2[1] + v[2] * e2[2]) / d};
    };
    auto lift = [&](const Point2& q) {
      const double a = q[0] / radius, b = q[1] / radius, s2 = a * a + b * b;
      Point3 v;
      for (int k = 0; k < 3; ++k) v[k] = (2 * (a * e1[k] + b * e2[k]) + (s2 - 1) * pole[k]) / (s2 + 1);
      return on_sphere(v);
    };
    Plane_mesh_input input;
    for (const auto& [u, v] : rims) {
      Plane_mesh_input::Polyline line;
      for (std::uint32_t id : {u, v}) {
        line.points.push_back(chart(points[id]));
        line.ids.push_back(id);
      }
      input.polylines.push_back(std::move(line));
    }
    // The rims bound the cap, and the pole is outside it: the cap is the odd-parity side of the rims.
    std::vector<std::pair<Point2, Point2>> segments;
    for (const auto& line : input.polylines) segments.push_back({line.points[0], line.points[1]});
    input.inside = [&segments](const Point2& p) { return odd_crossings(segments, p); };
    input.lift = lift;
    input.density = [&](const Point2& q) {
      const double s2 = (q[0] * q[0] + q[1] * q[1]) / (radius * radius), f = 2 / (1 + s2);
      return f * f;
    };
    input.segment_label = [](std::int64_t, std::int64_t) -> std::int64_t { return -1; };
    input.step = step;
    input.lloyd_iterations = options.lloyd_iterations;
    const Plane_mesh_output output = mesh_plane_region(input);
    const std::uint32_t base = static_cast<std::uint32_t>(points.size());
    for (const Point3& x : output.new_points) add_point(x, static_cast<std::uint8_t>(1u << kProbe));
    for (const auto& tri : output.triangles) {
      std::array<std::uint32_t, 3> v;
      for (int i = 0; i < 3; ++i) v[i] = tri[i] >= 0 ? static_cast<std::uint32_t>(tri[i]) : base + static_cast<std::uint32_t>(-1 - tri[i]);
      add_cap_triangle(v, cell);
    }
  }

  // ---- The walls -----------------------------------------------------------------------------------

  std::array<std::uint32_t, 8> corners{};

  Point3 corner_point(int mask) const {
    return {mask & 1 ? box.hi[0] : box.lo[0], mask & 2 ? box.hi[1] : box.lo[1], mask & 4 ? box.hi[2] : box.lo[2]};
  }

  void make_corners() {
    for (int mask = 0; mask < 8; ++mask) {
      std::uint8_t on = 0;
      for (int k = 0; k < 3; ++k) on = static_cast<std::uint8_t>(on | (1u << (2 * k + ((mask >> k) & 1))));
      corners[mask] = add_point(corner_point(mask), on);
    }
  }

  void mesh_walls_of_cell(Site_index cell) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const Mesh_triangle& t : triangles) {
      if (t.is_wall() || (t.site_a != static_cast<std::int32_t>(cell) && t.site_b != static_cast<std::int32_t>(cell))) continue;
      for (int k = 0; k < 3; ++k) ++uses[key_of(t.vertices[k], t.vertices[(k + 1) % 3])];
    }
    std::array<std::vector<std::pair<std::uint32_t, std::uint32_t>>, 6> rims;
    std::vector<std::uint32_t> rim_points;
    for (const auto& [edge, count] : uses) {
      if (count != 1) continue;
      const std::uint8_t common = walls[edge.first] & walls[edge.second];
      int wall = -1;
      for (int w = 0; w < 6 && wall < 0; ++w)
        if ((common >> w) & 1u) wall = w;
      if (wall < 0) {
        ++statistics.open_rims;
        continue;
      }
      rims[wall].push_back(edge);
      rim_points.push_back(edge.first);
      rim_points.push_back(edge.second);
    }
    std::sort(rim_points.begin(), rim_points.end());
    rim_points.erase(std::unique(rim_points.begin(), rim_points.end()), rim_points.end());
    for (int wall = 0; wall < 6; ++wall) {
      const int k = axis_of(wall), k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      const double bound = bound_of(wall);
      auto embed = [&](const Point2& p) {
        Point3 x;
        x[k] = bound;
        x[k1] = p[0];
        x[k2] = p[1];
        return x;
      };
      if (rims[wall].empty()) {
        const Point2 middle{(box.lo[k1] + box.hi[k1]) / 2, (box.lo[k2] + box.hi[k2]) / 2};
        if (nearest_site(embed(middle)) != cell) continue;
      }
      Plane_mesh_input input;
      for (const auto& [u, v] : rims[wall]) {
        Plane_mesh_input::Polyline line;
        for (std::uint32_t id : {u, v}) {
          line.points.push_back({points[id][k1], points[id][k2]});
          line.ids.push_back(id);
        }
        input.polylines.push_back(std::move(line));
      }
      // The wall's four sides, through the rims' points on them.
      for (int side = 0; side < 4; ++side) {
        const int fixed_axis = side < 2 ? k1 : k2, free_axis = side < 2 ? k2 : k1;
        const int other_wall = 2 * fixed_axis + (side % 2);
        std::vector<std::uint32_t> on_side;
        for (int mask = 0; mask < 8; ++mask) {
          const std::uint32_t id = corners[mask];
          if (((walls[id] >> wall) & 1u) && ((walls[id] >> other_wall) & 1u)) on_side.push_back(id);
        }
        for (std::uint32_t id : rim_points)
          if (((walls[id] >> wall) & 1u) && ((walls[id] >> other_wall) & 1u)) on_side.push_back(id);
        std::sort(on_side.begin(), on_side.end(),
                  [&](std::uint32_t x, std::uint32_t y) { return points[x][free_axis] < points[y][free_axis]; });
        Plane_mesh_input::Polyline line;
        for (std::uint32_t id : on_side) {
          line.points.push_back({points[id][k1], points[id][k2]});
          line.ids.push_back(id);
        }
        input.polylines.push_back(std::move(line));
      }
      input.inside = [&](const Point2& p) { return nearest_site(embed(p)) == cell; };
      input.lift = embed;
      input.density = [](const Point2&) { return 1.0; };
      input.segment_label = [](std::int64_t, std::int64_t) -> std::int64_t { return -1; };
      input.default_label = -1;
      input.step = step;
      input.lloyd_iterations = options.lloyd_iterations;
      const Plane_mesh_output output = mesh_plane_region(input);
      const std::uint32_t base = static_cast<std::uint32_t>(points.size());
      for (const Point3& x : output.new_points) add_point(x, static_cast<std::uint8_t>(1u << wall));
      // Counterclockwise in (k1, k2) has its normal along +e_k; the outer normal is +e_k on a high wall.
      for (const auto& tri : output.triangles) {
        Mesh_triangle t;
        for (int i = 0; i < 3; ++i)
          t.vertices[i] = tri[i] >= 0 ? static_cast<std::uint32_t>(tri[i]) : base + static_cast<std::uint32_t>(-1 - tri[i]);
        if (wall % 2 == 0) std::swap(t.vertices[1], t.vertices[2]);
        t.site_a = -1 - wall;
        t.site_b = static_cast<std::int32_t>(cell);
        t.face_id = -1;
        triangles.push_back(t);
      }
    }
  }

  // Whether each cell's triangles use every edge twice.
  bool every_cell_closed(const std::vector<Site_index>& cells) const { return open_cells(cells) == 0; }

  // How many of the cells have an edge not used twice by their triangles.
  std::size_t open_cells(const std::vector<Site_index>& cells) const {
    std::map<std::int32_t, std::map<std::pair<std::uint32_t, std::uint32_t>, int>> uses;
    std::vector<bool> wanted(sites.size(), false);
    for (Site_index c : cells) wanted[c] = true;
    for (const Mesh_triangle& t : triangles)
      for (std::int32_t c : {t.site_a, t.site_b})
        if (c >= 0 && wanted[static_cast<std::size_t>(c)])
          for (int k = 0; k < 3; ++k) ++uses[c][key_of(t.vertices[k], t.vertices[(k + 1) % 3])];
    std::size_t open = 0;
    for (const auto& [cell, edges] : uses)
      for (const auto& [edge, n] : edges)
        if (n != 2) {
          ++open;
          break;
        }
    return open;
  }

  Diagram_mesh run() {
    if (!(step > 0) || !std::isfinite(step)) throw std::invalid_argument("mesh: the step must be positive and finite");
    for (int k = 0; k < 3; ++k)
      if (!(box.lo[k] < box.hi[k])) throw std::invalid_argument("mesh: the box has no volume");
    active.assign(sites.size(), true);
    for (const Hidden_site& h : topology.vertices.hidden) active[h.site] = false;
    for (Site_index s = 0; s < sites.size(); ++s)
      if (active[s]) active_sites.push_back(s);
    if (active_sites.empty()) return {};
    for (int k = 0; k < 3; ++k) centre[k] = (box.lo[k] + box.hi[k]) / 2;
    cut_radius = distance(Point3{box.lo[0], box.lo[1], box.lo[2]}, Point3{box.hi[0], box.hi[1], box.hi[2]}) / 2 + 2 * step;
    vertex_point.assign(topology.vertices.vertices.size(), -1);
    polylines.assign(topology.edges.size(), {});
    mesh_faces();
    const auto start = Clock::now();
    if (options.has_probe) {
      cut_by_wall(kProbe);
    } else {
      for (int wall = 0; wall < 6; ++wall) cut_by_wall(wall);
      make_corners();
    }
    std::vector<Site_index> cells = options.sites;
    if (cells.empty())
      for (const Diagram_cell& c : topology.cells) cells.push_back(c.site);
    auto close_cells = [&] {
      for (Site_index cell : cells)
        if (active[cell]) options.has_probe ? mesh_cap_of_cell(cell) : mesh_walls_of_cell(cell);
    };
    if (options.remesh_cut_faces) {
      // Meshing the cut faces again is checked face by face; should a cell still come out open, the cut
      // meshes are kept instead (statistics.remesh_abandoned).
      const std::vector<Point3> points_before = points;
      const std::vector<std::uint8_t> walls_before = walls, kinds_before = kinds;
      const std::vector<Mesh_triangle> triangles_before = triangles;
      remesh_cut_faces();
      close_cells();
      if (statistics.open_rims > 0 || !every_cell_closed(cells)) {
        points = points_before;
        walls = walls_before;
        kinds = kinds_before;
        triangles = triangles_before;
        statistics.open_rims = 0;
        statistics.remesh_abandoned = true;
        close_cells();
      }
    } else {
      close_cells();
    }
    statistics.open_cells = open_cells(cells);
    statistics.cut_seconds = seconds_since(start);
    // Keep the points in use, in order.
    std::vector<std::int64_t> renumber(points.size(), -1);
    Diagram_mesh mesh;
    for (Mesh_triangle& t : triangles)
      for (std::uint32_t& v : t.vertices) {
        if (renumber[v] < 0) {
          renumber[v] = static_cast<std::int64_t>(mesh.points.size());
          mesh.points.push_back(points[v]);
        }
        v = static_cast<std::uint32_t>(renumber[v]);
      }
    mesh.triangles = std::move(triangles);
    mesh.box = box;
    mesh.step = step;
    mesh.statistics = statistics;
    return mesh;
  }
};

}  // namespace

Axis_box default_mesh_box(const std::vector<Site>& sites, const Diagram& diagram) {
  std::vector<bool> hidden(sites.size(), false);
  for (const Hidden_site& h : diagram.hidden) hidden[h.site] = true;
  Axis_box box{{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                std::numeric_limits<double>::infinity()},
               {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                -std::numeric_limits<double>::infinity()}};
  double grow = 0;
  for (Site_index s = 0; s < sites.size(); ++s) {
    if (hidden[s]) continue;
    const std::array<double, 3> x{sites[s].x, sites[s].y, sites[s].z};
    for (int k = 0; k < 3; ++k) box.lo[k] = std::min(box.lo[k], x[k]), box.hi[k] = std::max(box.hi[k], x[k]);
    grow = std::max(grow, sites[s].w);
  }
  if (!(box.lo[0] <= box.hi[0])) return Axis_box{{-1, -1, -1}, {1, 1, 1}};
  double extent = 0;
  for (int k = 0; k < 3; ++k) box.lo[k] -= grow, box.hi[k] += grow, extent = std::max(extent, box.hi[k] - box.lo[k]);
  if (extent == 0) extent = 2;
  for (int k = 0; k < 3; ++k)
    if (box.hi[k] - box.lo[k] == 0) box.lo[k] -= extent / 2, box.hi[k] += extent / 2;
  return box;
}

Diagram_mesh mesh_diagram(const std::vector<Site>& sites, const Diagram_topology& topology, const Mesh_options& options) {
  Builder builder(sites, topology, options);
  if (options.has_probe && options.has_box) throw std::invalid_argument("mesh: a box or a probe, not both");
  if (options.has_probe && !(options.probe >= 0 && std::isfinite(options.probe)))
    throw std::invalid_argument("mesh: the probe must be a finite number >= 0");
  builder.box = options.has_box ? options.box : default_mesh_box(sites, topology.vertices);
  if (options.has_probe)  // the region meshed: every probe-expanded ball
    for (int k = 0; k < 3; ++k) builder.box.lo[k] -= options.probe, builder.box.hi[k] += options.probe;
  const double diagonal = distance(Point3{builder.box.lo[0], builder.box.lo[1], builder.box.lo[2]},
                                   Point3{builder.box.hi[0], builder.box.hi[1], builder.box.hi[2]});
  builder.step = options.step > 0 ? options.step : 0.02 * diagonal;
  if (options.step < 0 || !std::isfinite(options.step)) builder.step = options.step;
  return builder.run();
}

}  // namespace apollonius
