// Rational basis functions, their physical gradients and the geometry map at a point of an
// element, from the element's extraction operator (works for any way C_e was built).
#pragma once
#include "space/analysis_space.hpp"

#include <Eigen/Dense>

namespace isosid::prep {

struct PointValues {
  Eigen::VectorXd R;        ///< rational functions of the element
  Eigen::MatrixXd dR_dxi;   ///< nf x param_dim
  Eigen::VectorXd x;        ///< physical point
  Eigen::MatrixXd J;        ///< phys_dim x param_dim, dx/dxi
  Eigen::VectorXd xi;       ///< patch parameter
};

class ElementEvaluator {
public:
  explicit ElementEvaluator(const AnalysisSpace& space) : space_(space) {}
  /// Evaluates at reference coordinates t in [0,1]^param_dim of element e.
  void evaluate(const Element& e, const double* t, PointValues& out) const;

private:
  const AnalysisSpace& space_;
  mutable Eigen::VectorXd b_[3], db_[3];
};

}  // namespace isosid::prep
