#include "predicates/vertex_ball.h"

#include "predicates/exact_quadruple_line.h"
#include "predicates/quadruple_line.h"
#include "predicates/rounding_guard.h"
#include "predicates/vertex.h"
#include "predicates/vertices_of.h"

namespace apollonius {
namespace {

using Ball = Double_double_ball;

// lambda of the root (line_roots.h): (-B + sigma sqrt(D)) / A, or C / (-B - sigma sqrt(D)) where -B and
// sigma sqrt(D) have opposite signs (no cancellation; valid for A near 0); -B / A for a single root with A
// certainly nonzero (then D = 0). An unusable ball where the balls cannot tell.
Ball root_parameter(const Quadruple_line<Ball>& line, Root root) {
  if (root == Root::SINGLE) {
    if (!sign_if_certain(line.A)) return Ball(0, 0, INFINITY);  // A = 0 gives -C / 2B instead
    return quotient(-line.B, line.A);
  }
  const Ball root_term = square_root(line.discriminant);
  const Ball signed_root = root == Root::PLUS ? root_term : -root_term;
  const std::optional<Sign> b = sign_if_certain(line.B);
  if (b && static_cast<int>(*b) == static_cast<int>(root)) return quotient(line.C, -line.B - signed_root);
  return quotient(signed_root - line.B, line.A);
}

// X = (Q + lambda n) / n_k for the root, or nothing.
std::optional<Ball_coordinates> coordinates_of_root(const Quadruple_line<Ball>& line, Root root) {
  const Ball lambda = root_parameter(line, root);
  if (!lambda.usable()) return std::nullopt;
  const Ball reciprocal = quotient(Ball(1), line.n[line.pivot]);
  Ball_coordinates X;
  for (int j = 0; j < 4; ++j) {
    X[j] = j == line.pivot ? lambda : (line.Q[j] + lambda * line.n[j]) * reciprocal;
    if (!X[j].usable()) return std::nullopt;
  }
  return X;
}

// Where a box of X stays well inside the double range (else vertex.cpp's scaled boxes are needed).
constexpr double kLargestCoordinate = 0x1p500;

// An interval holding every number of the ball (outward rounding).
Interval enclosing_interval(const Ball& x) {
  const Rounding_guard upward;
  return Interval(x.hi) + Interval(x.lo) + Interval(-x.error, x.error);
}

// Whether r + w_m >= 0 for the four sites (vertices_of.h's is_valid_root), or nothing where a ball
// cannot tell.
std::optional<bool> certainly_valid(const Ball_coordinates& X, const Quadruple& q) {
  const std::optional<Sign> r = sign_if_certain(X[3]);
  if (!r) return std::nullopt;
  if (*r == Sign::NEGATIVE) return false;
  bool valid = true;
  for (int m = 1; m < 4; ++m) {
    const Ball twice_b = ball_difference(q.sites[m].w, q.sites[0].w);
    const std::optional<Sign> s = sign_if_certain(X[3] + (twice_b + twice_b));
    if (!s) return std::nullopt;
    valid = valid && *s == Sign::POSITIVE;
  }
  return valid;
}

}  // namespace

std::optional<Ball_coordinates> ball_coordinates_of(const Quadruple& q, Root root) {
  const Nearest_rounding_guard nearest;
  const Quadruple_line<Ball> line = quadruple_line<Ball>(q.sites, Pivot_exact_where_uncertain{});
  if (line.pivot < 0) return std::nullopt;
  return coordinates_of_root(line, root);
}

std::optional<Quadruple_vertices> vertices_from_balls(const Quadruple& q) {
  const Nearest_rounding_guard nearest;
  const Quadruple_line<Ball> line = quadruple_line<Ball>(q.sites, Pivot_exact_where_uncertain{});
  Quadruple_vertices result;
  if (line.pivot < 0) {  // every n_k is exactly 0
    result.rank_deficient = true;
    return result;
  }
  if (!sign_if_certain(line.A)) return std::nullopt;
  const std::optional<Sign> discriminant = sign_if_certain(line.discriminant);
  if (!discriminant) return std::nullopt;
  if (*discriminant == Sign::NEGATIVE) return result;
  for (Root root : {Root::MINUS, Root::PLUS}) {
    const std::optional<Ball_coordinates> X = coordinates_of_root(line, root);
    if (!X) return std::nullopt;
    const std::optional<bool> valid = certainly_valid(*X, q);
    if (!valid) return std::nullopt;
    if (!*valid) continue;
    std::array<Interval, 4> box;
    for (int j = 0; j < 4; ++j) {
      if (!(std::fabs((*X)[j].hi) <= kLargestCoordinate)) return std::nullopt;
      box[j] = enclosing_interval((*X)[j]);
    }
    result.vertices.push_back(Vertex(q, root, box, *X));
  }
  return result;
}

const Ball_coordinates* Vertex::ball_coordinates() const {
  const std::optional<Ball_coordinates>& X = ball_.get_or_compute([&] { return ball_coordinates_of(quadruple_, root_); });
  return X ? &*X : nullptr;
}

}  // namespace apollonius
