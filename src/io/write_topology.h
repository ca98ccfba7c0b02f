// The whole diagram as JSON (docs/contract.md, "The whole diagram"): vertices, edges, faces and cells by
// id, or only their tie sets in the form the GPU codes' topology experiments compare.
#pragma once

#include <ostream>
#include <vector>

#include "predicates/predicate_counter.h"
#include "topology/topology.h"

namespace apollonius {

// {"format": "apollonius3d-diagram", "version": 1, "sites": N, "vertices": [...], "edges": [...],
//  "faces": [...], "cells": [...], "hidden_sites": [...], "stats": {...}}; stats only when not null.
void write_diagram_json(std::ostream& out, const Diagram_topology& topology, const std::vector<Predicate_statistics>* stats);

// {"bisectors": [...], "trisectors": [...], "quadrisectors": [...]}: the tie sets of the faces, edges and
// vertices, ascending, each set once (a degenerate edge or vertex gives its whole tie set).
void write_diagram_topology(std::ostream& out, const Diagram_topology& topology);

}  // namespace apollonius
