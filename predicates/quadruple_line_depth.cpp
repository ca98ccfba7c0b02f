#include "predicates/quadruple_line.h"

namespace apollonius {

// quadruple_line on any four sites, counting depths only (Depth_count): its discriminant is its deepest
// value (docs/ERROR_BOUNDS.md, "Doubles with magnitude").
const int kQuadrupleLineDepth = quadruple_line<Depth_count>({Site{}, Site{}, Site{}, Site{}}).discriminant.depth;

}  // namespace apollonius
