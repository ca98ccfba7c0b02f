// The vertex list of a Diagram as text or JSON (docs/contract.md).
#pragma once

#include <ostream>
#include <vector>

#include "diagram/diagram.h"
#include "predicates/predicate_counter.h"

namespace apollonius {

// One line per vertex, in the Diagram's order: the tie-set indices, then x y z r, each printed "%.17g"
// so that it reads back as the same double; non-finite values print as inf or -inf. With threads > 1,
// blocks of lines are formatted in parallel and written in order: the same bytes for every count.
void write_vertices_text(std::ostream& out, const Diagram& diagram, int threads = 1);

// The same vertices as a JSON document, with the hidden sites, the sites without a vertex and, when
// stats is not null, the predicate statistics. Non-finite values, which JSON lacks, are the strings
// "inf" and "-inf".
void write_vertices_json(std::ostream& out, const Diagram& diagram, const std::vector<Predicate_statistics>* stats);

}  // namespace apollonius
