// libFuzzer target: the whole diagram of a small site set decoded from the bytes (fuzz_sites.h), built
// from the brute-force vertices with every site a candidate, and from the octree's vertices and regions,
// and from the lifted fallback's (no box).
// Both must equal: the same edges as the brute-force edge reference, the same faces and cells, and the
// Euler relation must hold; and the edges through vertices with every tie set of 4 or more sites listed by
// its star of directions (departure_star.h) equal those from every triple. A disagreement prints the sites
// and traps; any exception is a finding (the
// octree's documented overflow near the double range aside), including build_topology's "not decided".
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "fuzz/fuzz_sites.h"
#include "io/write_sites.h"
#include "octree/octree_diagram.h"
#include "reference/brute_force_diagram.h"
#include "reference/brute_force_edges.h"
#include "topology/build_topology.h"
#include "topology/euler_characteristic.h"
#include "topology/trisector_edges.h"
#include "topology/vertex_triples.h"

namespace {

using namespace apollonius;

bool same_edges(const std::vector<Diagram_edge>& a, const std::vector<Diagram_edge>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].tie_set != b[i].tie_set || a[i].start != b[i].start || a[i].end != b[i].end ||
        a[i].closed != b[i].closed || a[i].curve != b[i].curve)
      return false;
  return true;
}

bool same_faces_and_cells(const Diagram_topology& a, const Diagram_topology& b) {
  if (a.faces.size() != b.faces.size() || a.cells.size() != b.cells.size()) return false;
  for (std::size_t i = 0; i < a.faces.size(); ++i)
    if (a.faces[i].a != b.faces[i].a || a.faces[i].b != b.faces[i].b || a.faces[i].boundary != b.faces[i].boundary ||
        a.faces[i].bounded != b.faces[i].bounded)
      return false;
  for (std::size_t i = 0; i < a.cells.size(); ++i)
    if (a.cells[i].site != b.cells[i].site || a.cells[i].faces != b.cells[i].faces || a.cells[i].bounded != b.cells[i].bounded)
      return false;
  return true;
}

[[noreturn]] void report(const char* what, const std::vector<Site>& sites) {
  std::cerr << what << " on these sites:\n";
  write_sites_text(std::cerr, sites, "fuzz_diagram input");
  __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<Site> sites;
  if (!fuzzing::decode_sites(data, size, sites)) return -1;
  static const bool print_sites = std::getenv("APOLLONIUS_FUZZ_PRINT_SITES") != nullptr;
  if (print_sites) {
    write_sites_text(std::cout, sites, "fuzz_diagram input");
    std::cout.flush();
  }
  const Diagram reference = brute_force_diagram(sites);
  const Diagram_topology brute = build_topology(sites, reference, regions_for_every_site(reference));
  if (!same_edges(brute.edges, brute_force_edges(sites, reference))) report("edges differ from the brute-force edges", sites);
  if (euler_defect(brute) != 0) report("the Euler relation fails", sites);
  const std::vector<Diagram_edge> from_stars =
      edges_through_vertices(sites, reference, Vertex_triples(sites, reference, nullptr, 3), 1);
  const std::vector<Diagram_edge> from_every_triple = edges_through_vertices(
      sites, reference, Vertex_triples(sites, reference, nullptr, std::numeric_limits<std::size_t>::max()), 1);
  if (!same_edges(from_stars, from_every_triple)) report("the edges from the vertices' stars differ", sites);

  Octree_regions regions;
  Diagram vertices;
  try {
    vertices = octree_diagram(sites, Octree_options{1, nullptr, Arithmetic::certified, &regions});
  } catch (const std::overflow_error&) {
    if (fuzzing::centres_reach_double_range_limit(sites)) return 0;
    throw;
  }
  const Diagram_topology octree = build_topology(sites, vertices, regions);
  if (!same_edges(octree.edges, brute.edges) || !same_faces_and_cells(octree, brute))
    report("the octree's regions and every-site candidates give different diagrams", sites);

  // The lifted fallback (octree_diagram.h, step 5), forced by a box budget of 0: regions with no box.
  Octree_regions no_boxes;
  Octree_options fallback{1, nullptr, Arithmetic::certified, &no_boxes};
  fallback.box_budget = 0;
  const Diagram_topology lifted = build_topology(sites, octree_diagram(sites, fallback), no_boxes);
  if (!same_edges(lifted.edges, brute.edges) || !same_faces_and_cells(lifted, brute))
    report("the lifted fallback's regions and every-site candidates give different diagrams", sites);
  return 0;
}
