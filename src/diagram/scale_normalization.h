// The diagram commutes with scaling every coordinate and weight by a power of two: the tie sets stay,
// and so does the root of each vertex (A, B, C and the discriminant of quadruple_line.h all scale by
// positive factors). Sites whose extent is far from 1 are scaled before the octree runs, so that its
// double filters neither overflow nor underflow; the vertices found are then moved back to the input.
#pragma once

#include <vector>

#include "predicates/vertex.h"

namespace apollonius {

// k such that the active sites scaled by 2^-k have an extent (largest spread of a centre coordinate, or
// largest |weight|) in [1, 2); 0 when the extent already lies within [2^-32, 2^32], or when scaling would
// not be exact for every coordinate and weight of an active site.
int normalizing_exponent(const std::vector<Site>& sites, const std::vector<Site_index>& active);

// Every site scaled by 2^-exponent.
std::vector<Site> scaled_sites(const std::vector<Site>& sites, int exponent);

// The vertex of the same quadruple and root on the input sites, from one found on the sites scaled by
// 2^-exponent.
Vertex unscaled_vertex(const Vertex& scaled, const std::vector<Site>& sites, int exponent);

}  // namespace apollonius
