// Degrees of freedom of a body: coincident control points (collapsed edges, axes of bodies
// of revolution, seams) merged into one node, `dim` displacement components per node, and
// constrained components eliminated from the free numbering.
#pragma once
#include "space/analysis_space.hpp"

#include <vector>

namespace isosid::prep {

class DofMap {
public:
  /// Merges functions whose control points lie within `tolerance` of each other: within a
  /// hierarchical level always, across levels only if both functions live on one of the
  /// `point_sides` (sides collapsed to a point, where every function's trace is one value).
  /// Elsewhere a coarse and a fine function may share a control point by accident, e.g. at
  /// Greville points of odd degree, and must stay apart.
  /// Merging across patches joins conforming interfaces. `point_sides` are (patch, side).
  DofMap(const AnalysisSpace& space, int dim, double tolerance, const std::vector<std::pair<int, PatchSide>>& point_sides = {});

  int dim() const { return dim_; }
  int node_count() const { return int(node_points_.rows()); }
  int node_of(int function) const { return node_of_function_[function]; }
  const Eigen::MatrixXd& node_points() const { return node_points_; }

  /// Fixes component a of a node (clamped or symmetry conditions, the radial DOF on an axis).
  void fix(int node, int component);
  bool is_fixed(int node, int component) const { return fixed_[node * dim_ + component]; }
  /// Free index of (node, component), or -1 if fixed. Valid after any fix().
  int free_index(int node, int component) const { return free_[node * dim_ + component]; }
  int free_count() const { return n_free_; }
  /// Free index of every nodal DOF (node-major), -1 where fixed.
  const std::vector<int>& free_indices() const { return free_; }
  int total_dofs() const { return node_count() * dim_; }
  /// Node of each function of the element, in the element's order.
  void element_nodes(const Element& element, std::vector<int>& nodes) const;
  /// Free index of each DOF of the element (f*dim + a), -1 where fixed.
  void element_free_dofs(const Element& element, std::vector<int>& free) const;

private:
  void renumber();
  int dim_;
  std::vector<int> node_of_function_;
  Eigen::MatrixXd node_points_;
  std::vector<bool> fixed_;
  std::vector<int> free_;
  int n_free_ = 0;
};

}  // namespace isosid::prep
