// A body ready for analysis: the refined patch, its analysis space, elasticity and DOFs
// with boundary conditions applied (axis conditions of axisymmetric bodies included).
#pragma once
#include "space/analysis_space.hpp"
#include "thb/hierarchical_space.hpp"
#include "space/dof_map.hpp"
#include "assemble/elasticity.hpp"
#include "model/model_file.hpp"

#include <memory>
#include <optional>

namespace isosid::prep {

/// What a hierarchical (THB) refinement added on top of the refined tensor patch.
struct Hierarchy {
  HierarchicalMesh mesh;
  std::vector<int> functions_per_level, elements_per_level;
  Eigen::SparseMatrix<double> prolongation;  ///< THB functions x patch functions (exact)
};

struct BodyModel {
  ModelSpec spec;
  NurbsPatch refined;              ///< the globally refined tensor patch (level 0 of a hierarchy)
  AnalysisSpace space;
  std::optional<Hierarchy> hierarchy;
  Elasticity elasticity;
  DofMap dofs;
};

/// Refines the spec's patch (elevate, subdivide, grade, then hierarchically if requested),
/// builds the space and the DOF map.
BodyModel build_body(const ModelSpec& spec);

/// The coarse model a THB model refines (seed 001): the spec without its hierarchical
/// refinement, reduced by modal truncation to the same number of normal modes.
ModelSpec coarse_model_spec(const ModelSpec& spec);

/// Most control points a refined patch may have (3D: 6 million DOFs, beyond any eigen solve
/// this machine class takes in memory).
constexpr double kMaxControlPoints = 2e6;

/// Applies the refinement of a spec to a patch (elevation first, then knot insertion); a
/// refinement beyond kMaxControlPoints is an InputError naming `file` and the field.
NurbsPatch refine_patch(const NurbsPatch& coarse, const RefinementSpec& refinement, const std::string& file);

/// Diagonal of a control net's bounding box: a body's size for scales and tolerances.
double patch_size(const NurbsPatch& patch);
inline double body_size(const BodyModel& body) { return patch_size(body.refined); }

/// Nodes whose functions do not vanish on the side.
std::vector<int> side_nodes(const BodyModel& body, PatchSide side);

}  // namespace isosid::prep
