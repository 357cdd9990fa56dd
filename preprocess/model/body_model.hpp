// A body ready for analysis: the refined patch, its analysis space, elasticity and DOFs
// with boundary conditions applied (axis conditions of axisymmetric bodies included).
#pragma once
#include "assemble/analysis_space.hpp"
#include "assemble/dof_map.hpp"
#include "assemble/elasticity.hpp"
#include "model/model_file.hpp"

#include <memory>

namespace isosid::prep {

struct BodyModel {
  ModelSpec spec;
  NurbsPatch refined;
  AnalysisSpace space;
  Elasticity elasticity;
  DofMap dofs;
};

/// Refines the spec's patch (elevate, subdivide, grade), builds the space and the DOF map.
BodyModel build_body(const ModelSpec& spec);

/// Applies the refinement of a spec to a patch (elevation first, then knot insertion).
NurbsPatch refine_patch(const NurbsPatch& coarse, const RefinementSpec& refinement);

/// Diagonal of a control net's bounding box: a body's size for scales and tolerances.
double patch_size(const NurbsPatch& patch);
inline double body_size(const BodyModel& body) { return patch_size(body.refined); }

/// Nodes whose functions do not vanish on the side.
std::vector<int> side_nodes(const BodyModel& body, PatchSide side);

}  // namespace isosid::prep
