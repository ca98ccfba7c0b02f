// Which boundary components of one pair's faces bound the same face, and which faces are bounded
// (paper section 4.3: faces may have holes). The bisector sheet of a and b is a graph over the plane
// between them (paper Theorem 3), so it is cut like a plane: by the level sets e . v = y of a rational
// direction e across the pair, at one rational height y in each slab between consecutive critical heights
// (the heights of the vertices and of the edges' extreme points). Along such a line the face of a and b
// alternates with the rest at every crossing of an edge, and its intervals join the components at their
// ends, or reach infinity. Within a slab the crossings keep their order, so the lines see every connection
// of the faces (the argument of the vertical decomposition); an interval in the outermost slabs, or
// reaching the line's end, is part of an unbounded face.
//
// Cost: O(k) heights and O(k) crossings per line for the k edges of the pair's components: O(k^2) exact
// constructions, which is why it runs only where the components do not settle it alone; O(k) for one
// closed cycle alone, which needs one line, and no extreme point when its vertices lie at two heights or
// more and the line between the lowest two touches no edge.
#pragma once

#include <vector>

#include "diagram/cancellation.h"
#include "topology/face_boundaries.h"

namespace apollonius {

struct Face_grouping {
  std::vector<std::vector<std::size_t>> faces;  // positions in `components`, ascending, each once
  std::vector<bool> bounded;                    // per face
};

// fewest: one closed cycle alone is decided by one level line across it (O(k) constructions); every_slab:
// always one line per slab, the general sweep (the tests check that both agree).
enum class Level_lines { fewest, every_slab };

// Precondition: every component is of the same pair, a < b. Checks cancellation (cancellation.h) once
// per edge of the pair while finding the critical heights, and per level line.
Face_grouping group_components(const std::vector<Site>& sites, const Diagram& diagram,
                               const std::vector<Diagram_edge>& edges,
                               const std::vector<const Boundary_component*>& components,
                               const Cancellation* cancellation = nullptr, Level_lines lines = Level_lines::fewest);

}  // namespace apollonius
