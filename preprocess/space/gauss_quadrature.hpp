// Gauss-Legendre rules on [0, 1].
#pragma once
#include <Eigen/Dense>

namespace isosid::prep {

struct QuadratureRule {
  Eigen::VectorXd points;   ///< in (0, 1)
  Eigen::VectorXd weights;  ///< sum to 1
};

/// The n-point rule (exact for polynomials of degree 2n-1); n = 1..30.
QuadratureRule gauss_legendre(int n);

}  // namespace isosid::prep
