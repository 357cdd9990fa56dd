// Tensor Gauss rule on the reference element [0,1]^d together with the tensor Bernstein
// values and derivatives at its points: built once per degrees and rule, shared by every
// element of a space (element sizes and geometry are applied per element).
#pragma once
#include "space/analysis_space.hpp"

#include <Eigen/Dense>
#include <array>
#include <vector>

namespace isosid::prep {

/// Tensor Bernstein basis at a set of reference points (Bernstein index first direction fastest).
struct BernsteinTable {
  Eigen::MatrixXd values;                      ///< bernstein_count x points
  std::array<Eigen::MatrixXd, 3> derivatives;  ///< per parametric direction: d/dt_d, bernstein_count x points
};

/// Fills `table` at the columns of `points` (param_dim x n reference coordinates); reuses its storage.
void fill_bernstein_table(const std::vector<int>& degrees, const Eigen::Ref<const Eigen::MatrixXd>& points,
                          BernsteinTable& table);

struct ReferenceRule {
  Eigen::MatrixXd points;   ///< param_dim x n reference coordinates in [0,1]^d (first direction fastest)
  Eigen::VectorXd weights;  ///< n products of the 1D Gauss weights (sum to 1)
  BernsteinTable basis;     ///< the Bernstein basis at the points
  int size() const { return int(weights.size()); }
};

/// p_d + 1 + extra Gauss points in direction d.
ReferenceRule reference_rule(const AnalysisSpace& space, int extra = 0);

}  // namespace isosid::prep
