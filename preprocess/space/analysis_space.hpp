// The discrete space of an isogeometric body: elements with their extraction operators.
// On element e the functions living there are N = C_e B(xi_hat) with B the tensor Bernstein
// basis on the element; the rational analysis functions are R_i = w_i N_i / W. Uniform,
// graded and hierarchical (THB) refinement differ only in how C_e is built.
#pragma once
#include "geometry/nurbs_patch.hpp"

#include <Eigen/Dense>
#include <vector>

namespace isosid::prep {

struct Element {
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();  ///< parametric box
  std::vector<int> functions;   ///< global function indices of the functions living on the element
  Eigen::MatrixXd C;            ///< functions.size() x prod(p+1): Bernstein -> functions
  int level = 0;                ///< hierarchical level (0 for tensor spaces)
  int patch = 0;                ///< the patch of a multi-patch body it belongs to
};

/// The parameter range of a patch.
struct PatchRange {
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
};

struct AnalysisSpace {
  std::vector<int> degrees;
  std::vector<Element> elements;
  Eigen::MatrixXd control_points;  ///< n_functions x phys_dim: the exact geometry x = sum R_i P_i
  Eigen::VectorXd weights;         ///< n_functions: W = sum w_i N_i
  std::vector<int> function_level; ///< n_functions: hierarchical level of each function (0 for tensor spaces)
  std::vector<PatchRange> patch_boxes;  ///< one per patch; elements' boxes lie in their patch's
  /// per patch: its first function (a tensor patch's control point i is function first + i)
  std::vector<int> patch_first_function{0};

  int param_dim() const { return int(degrees.size()); }
  int phys_dim() const { return int(control_points.cols()); }
  int n_functions() const { return int(weights.size()); }
  int bernstein_count() const;
  /// Product of the element's parametric extents (length, area or volume in xi).
  double parametric_size(const Element& e) const;
  /// True if the element touches the side of its own patch.
  bool on_side(const Element& e, PatchSide side) const;
  int patch_count() const { return int(patch_boxes.size()); }
};

/// Tensor-product space of a NURBS patch: one element per non-empty knot span box (first
/// direction fastest), functions numbered as the patch's control points.
AnalysisSpace tensor_space(const NurbsPatch& patch);

/// The space of a multi-patch body: the patches' spaces side by side, functions and elements
/// numbered patch after patch, each element tagged with its patch. All need the same degrees
/// (one reference rule); coincident control points are merged later, by the DofMap.
AnalysisSpace join_spaces(std::vector<AnalysisSpace> spaces);

}  // namespace isosid::prep
