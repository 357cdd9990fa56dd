// Gauss-Legendre nodes by Newton's method on P_n (converges from the Chebyshev-like guess).
#include "space/gauss_quadrature.hpp"

#include <cmath>
#include <stdexcept>

namespace isosid::prep {

QuadratureRule gauss_legendre(int n) {
  if (n < 1 || n > 30) throw std::invalid_argument("gauss_legendre: n outside 1..30");
  QuadratureRule rule{Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (int i = 0; i < n; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = x;  // Legendre recurrence
      for (int k = 2; k <= n; ++k) {
        const double pk = ((2.0 * k - 1) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    rule.points(i) = 0.5 * (1.0 - x);
    rule.weights(i) = 1.0 / ((1.0 - x * x) * dp * dp);  // (2/((1-x^2)P'^2)) / 2 for [0,1]
  }
  return rule;
}

}  // namespace isosid::prep
