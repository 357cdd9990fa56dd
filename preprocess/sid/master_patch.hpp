// A body side as a NURBS of one dimension less (curve of a 2D body, surface of a solid) with
// the modal rows of its control points: what another body's contact points are projected on.
// For a hierarchically refined body the side's THB space is not a tensor product; it lies in
// the tensor space whose knots are all its element boundaries, so the side is written there
// (knot insertion for the geometry, collocation at Greville points for the mode shapes, both
// exact).
#pragma once
#include "model/body_model.hpp"
#include "isosid/format/sid.hpp"

#include <string>

namespace isosid::prep {

/// The master patch of side `side` of patch `patch` of the body.
format::MasterPatch master_patch(const BodyModel& body, const std::string& name, int patch, PatchSide side,
                                 const Eigen::MatrixXd& Phi_nodal);

}  // namespace isosid::prep
