// Rational basis functions, their parametric gradients and the geometry map of an element,
// from the element's extraction operator (works for any way C_e was built): at all points of
// a precomputed Bernstein table at once, or at one point.
#pragma once
#include "space/analysis_space.hpp"
#include "space/reference_rule.hpp"

#include <Eigen/Dense>
#include <array>

namespace isosid::prep {

/// Values at the points of a table, one column per point.
struct ElementValues {
  Eigen::MatrixXd R;                       ///< nf x points: rational functions of the element
  std::array<Eigen::MatrixXd, 3> dR_dxi;   ///< per parametric direction: nf x points
  Eigen::MatrixXd x;                       ///< phys_dim x points: physical points
  std::array<Eigen::MatrixXd, 3> dx_dxi;   ///< per parametric direction: phys_dim x points (columns of J)
};

/// Values at one point.
struct PointValues {
  Eigen::VectorXd R;        ///< rational functions of the element
  Eigen::MatrixXd dR_dxi;   ///< nf x param_dim
  Eigen::VectorXd x;        ///< physical point
  Eigen::MatrixXd J;        ///< phys_dim x param_dim, dx/dxi
  Eigen::VectorXd xi;       ///< patch parameter
};

/// Keeps its work buffers between calls (one evaluator per thread): no allocation once warm.
class ElementEvaluator {
public:
  explicit ElementEvaluator(const AnalysisSpace& space) : space_(space) {}
  /// Evaluates element e at every point of `table` (reference coordinates of the element).
  void evaluate(const Element& e, const BernsteinTable& table, ElementValues& out) const;
  /// Evaluates at reference coordinates t in [0,1]^param_dim of element e.
  void evaluate(const Element& e, const double* t, PointValues& out) const;

private:
  const AnalysisSpace& space_;
  mutable Eigen::VectorXd w_;           ///< weights of the element's functions
  mutable Eigen::MatrixXd P_;           ///< control points of the element's functions, nf x phys_dim
  mutable Eigen::MatrixXd N_, dN_;      ///< polynomial functions and one direction's derivatives
  mutable Eigen::RowVectorXd W_, dW_;   ///< weight function and one direction's derivative
  mutable BernsteinTable point_table_;  ///< for single points
  mutable ElementValues point_values_;
};

}  // namespace isosid::prep
