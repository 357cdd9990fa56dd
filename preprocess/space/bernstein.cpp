// Bernstein basis; see bernstein.hpp.
#include "space/bernstein.hpp"

namespace isosid::prep {

namespace {
// de Casteljau-style triangle: B_{b,p} from B_{.,p-1}
Eigen::VectorXd bernstein_values(int p, double t) {
  Eigen::VectorXd B = Eigen::VectorXd::Zero(p + 1);
  B(0) = 1.0;
  const double s = 1.0 - t;
  for (int j = 1; j <= p; ++j) {
    double saved = 0.0;
    for (int k = 0; k < j; ++k) {
      const double temp = B(k);
      B(k) = saved + s * temp;
      saved = t * temp;
    }
    B(j) = saved;
  }
  return B;
}
}  // namespace

void bernstein(int p, double t, Eigen::VectorXd& values, Eigen::VectorXd& derivatives) {
  values = bernstein_values(p, t);
  derivatives = Eigen::VectorXd::Zero(p + 1);
  if (p == 0) return;
  const Eigen::VectorXd lower = bernstein_values(p - 1, t);
  for (int b = 0; b <= p; ++b)
    derivatives(b) = p * ((b > 0 ? lower(b - 1) : 0.0) - (b < p ? lower(b) : 0.0));
}

}  // namespace isosid::prep
