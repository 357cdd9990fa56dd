// Bernstein polynomials on [0, 1] and their first derivatives: the reference basis every
// element's extraction operator maps from.
#pragma once
#include <Eigen/Dense>

namespace isosid::prep {

/// values(b) = B_{b,p}(t), derivatives(b) = dB_{b,p}/dt for b = 0..p.
void bernstein(int p, double t, Eigen::VectorXd& values, Eigen::VectorXd& derivatives);

}  // namespace isosid::prep
