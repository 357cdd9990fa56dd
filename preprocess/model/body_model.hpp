// A body ready for analysis: the refined patch, its analysis space, elasticity and DOFs
// with boundary conditions applied (axis conditions of axisymmetric bodies included).
#pragma once
#include "space/analysis_space.hpp"
#include "thb/hierarchical_space.hpp"
#include "space/dof_map.hpp"
#include "assemble/body_elasticity.hpp"
#include "model/model_file.hpp"
#include "model/patch_interfaces.hpp"

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
  /// the globally refined tensor patches, as spec.patches (level 0 of a hierarchy)
  std::vector<NurbsPatch> refined;
  std::vector<PatchInterface> interfaces;
  AnalysisSpace space;             ///< all patches: elements carry their patch index
  std::optional<Hierarchy> hierarchy;
  BodyElasticity elasticity;       ///< per patch
  DofMap dofs;                     ///< coincident control points merged: interfaces join here
};

/// Refines the spec's patches (elevate, subdivide, grade, then hierarchically if requested),
/// makes them conform on their interfaces, builds the space and the DOF map.
BodyModel build_body(const ModelSpec& spec);

/// The coarse model a THB model refines ([R2], docs/references.md): the spec without its
/// hierarchical refinement, reduced by modal truncation to the same number of normal modes.
ModelSpec coarse_model_spec(const ModelSpec& spec);

/// Applies the refinement of a spec to a patch (elevation first, then knot insertion); a
/// refinement beyond kMaxControlPoints is an InputError naming `file` and the field.
NurbsPatch refine_patch(const NurbsPatch& coarse, const RefinementSpec& refinement, const std::string& file);

/// Diagonal of a control net's bounding box: a body's size for scales and tolerances.
double patch_size(const NurbsPatch& patch);
/// The same over all patches of a body.
double patches_size(const std::vector<NurbsPatch>& patches);
inline double body_size(const BodyModel& body) { return patches_size(body.refined); }

/// Nodes whose functions do not vanish on the side of the patch.
std::vector<int> side_nodes(const BodyModel& body, int patch, PatchSide side);

}  // namespace isosid::prep
