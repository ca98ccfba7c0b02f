// The floating path against the certified one (`apollonius3d crosscheck`): the float diagram is judged as
// a claim (judge_claims.h) against the certified diagram of the same sites, and each disagreement is
// classified:
//  - missing: a certified vertex that no float vertex represents;
//  - spurious: a float vertex that is no certified vertex (not a vertex, the wrong root, or a second report
//    of one vertex);
//  - moved: a float vertex at a certified vertex, but with coordinates beyond the tolerance, or with only
//    part of its tie set (a degenerate vertex whose ties the doubles did not see).
#pragma once

#include <array>
#include <ostream>
#include <vector>

#include "certify/coordinate_tolerance.h"
#include "diagram/diagram.h"

namespace apollonius {

enum class Disagreement_kind { missing, spurious, moved };

const char* name_of(Disagreement_kind kind);  // "missing", "spurious", "moved"

struct Disagreement {
  Disagreement_kind kind;
  std::vector<Site_index> sites;           // the certified tie set (missing), or the float vertex's sites
  std::array<double, 4> point;             // the certified point (missing) or the float one
  std::array<double, 4> certified_point;   // moved only: where the certified vertex is
  Coordinate_error error;                  // moved only
};

struct Crosscheck {
  std::vector<Disagreement> disagreements;  // missing first (certified order), then float order
  std::size_t certified_vertices = 0, float_vertices = 0, agreeing = 0;
};

// `certified` must be the certified diagram of sites, `floating` the floating path's.
Crosscheck crosscheck(const std::vector<Site>& sites, const Diagram& certified, const Diagram& floating,
                      const Coordinate_tolerance& tolerance);

// One line per disagreement: KIND sites... x y z r, and for moved "certified x y z r" and the errors.
void write_disagreements(std::ostream& out, const Crosscheck& check);

}  // namespace apollonius
