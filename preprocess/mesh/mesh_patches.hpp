// Quadrilateral mesh elements as patches: a 9-node Lagrange element spans the tensor
// polynomials of degree (2, 2), which its Bezier form (degrees 2, 2, one span, unit weights)
// spans too; the Bezier control points follow from the nodes by b_mid = 2 x_mid - (x_0 + x_2)/2
// along each direction. Neighbours computing a shared edge from the same nodes get the same
// control points, which the DofMap merges: the body is the C0 Lagrange space.
#pragma once
#include "mesh/gmsh_mesh.hpp"
#include "geometry/nurbs_patch.hpp"

#include <utility>
#include <vector>

namespace isosid::prep {

/// An element edge: the element and its local edge k (corners k, k+1 counter-clockwise).
struct ElementEdge {
  int element = 0;
  int edge = 0;
};

/// The boundary edges `edges` (3-node lines) as element edges, ordered along the boundary in
/// the mesh's counter-clockwise sense (each element's own edge direction). InputError(file,
/// field) if an edge belongs to no element or the edges do not form one chain.
std::vector<ElementEdge> boundary_chain(const QuadMesh& mesh, const std::vector<std::array<int, 3>>& edges,
                                        const std::string& file, const std::string& field);

/// Element e in Bezier form, its local numbering turned by `turn` quarter turns so that its
/// edge `turn` is the patch's eta0 side, running with xi.
NurbsPatch bezier_patch(const QuadMesh& mesh, int element, int turn);

}  // namespace isosid::prep
