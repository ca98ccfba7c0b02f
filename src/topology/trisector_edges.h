// Edges from the vertices on their curves (paper section 5.3): every edge with a vertex leaves one of its
// ends forward along the trisector of its three smallest sites, and arrives at the next vertex on that
// curve whose edges leave it backward, or goes to infinity; on a closed curve the next vertex comes
// around. Why the next one: an arc in the diagram keeps its tie set until a vertex, and a vertex where an
// arc of the curve in the diagram ends has that arc among its departures; so between a departure and the
// next departure on the curve no vertex ends it, and the vertices on the curve with no departure along it
// have no arc of it in the diagram on either side.
#pragma once

#include <vector>

#include "diagram/cancellation.h"
#include "topology/topology.h"
#include "topology/vertex_fan.h"
#include "topology/vertex_triples.h"

namespace apollonius {

// The edges through the vertices of `diagram`: the departures of every vertex (vertex_fan.h), paired along
// their curves; sorted as Diagram_topology's. Throws std::logic_error if the departures along some curve
// do not alternate (leaving, arriving), which would be a defect. Checks cancellation (cancellation.h) once
// per curve and per 4096 vertices.
std::vector<Diagram_edge> edges_through_vertices(const std::vector<Site>& sites, const Diagram& diagram,
                                                 const Vertex_triples& triples, int threads,
                                                 const Cancellation* cancellation = nullptr);
// The same, with the vertices' triples built for it.
std::vector<Diagram_edge> edges_through_vertices(const std::vector<Site>& sites, const Diagram& diagram, int threads,
                                                 const Cancellation* cancellation = nullptr);

}  // namespace apollonius
