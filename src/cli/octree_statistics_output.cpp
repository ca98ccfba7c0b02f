#include "cli/octree_statistics_output.h"

namespace apollonius {

void print_octree_statistics(std::ostream& err, const Octree_statistics& s) {
  err << "phase seconds\n"
      << "partition " << s.partition_seconds << "\npropagation " << s.propagation_seconds << "\nrefinement "
      << s.refinement_seconds << "\nfar_field " << s.far_field_seconds << "\nassembly " << s.assembly_seconds << '\n'
      << "octree count\n"
      << "seed_boxes " << s.seed_boxes << "\nseed_candidates " << s.seed_candidates << "\nescaping_sites "
      << s.escaping_sites << "\nboxes " << s.boxes << "\nbox_candidates " << s.box_candidates << "\nleaves "
      << s.leaves << "\nleaf_candidates "
      << s.leaf_candidates << "\nlifted_leaves " << s.lifted_leaves << "\nquadruples " << s.quadruples << "\ndistinct_quadruples " << s.distinct_quadruples
      << "\nfar_field_quadruples " << s.far_field_quadruples << '\n';
  // The lifted fallback (octree_diagram.h, step 5), only when it ran.
  if (s.lifted_fallback)
    err << "lifted fallback\nlifted_reason "
        << (s.lifted_small_input  ? "small_input"
            : s.lifted_one_weight ? "one_weight"
            : s.lifted_deep_input ? "deep_input"
            : s.lifted_seed_candidates ? "seed_candidates"
                                  : "box_budget")
        << "\nlifted_seconds " << s.lifted_seconds << "\nlifted_quadruples " << s.lifted_quadruples << '\n';
}

}  // namespace apollonius
