// Reference Gauss rules and Bernstein tables; see reference_rule.hpp.
#include "space/reference_rule.hpp"

#include "space/bernstein.hpp"
#include "space/gauss_quadrature.hpp"
#include "geometry/multi_index.hpp"

namespace isosid::prep {

void fill_bernstein_table(const std::vector<int>& degrees, const Eigen::Ref<const Eigen::MatrixXd>& points,
                          BernsteinTable& table) {
  const int pd = int(degrees.size()), n = int(points.cols());
  std::array<int, 3> count{1, 1, 1};
  int nb = 1;
  for (int d = 0; d < pd; ++d) nb *= count[d] = degrees[d] + 1;
  table.values.resize(nb, n);
  for (int d = 0; d < pd; ++d) table.derivatives[d].resize(nb, n);
  // 1D values and derivatives of every direction; degrees stay far below this bound
  constexpr int max_count = 32;
  double b1[3][max_count], db1[3][max_count];
  for (int q = 0; q < n; ++q) {
    for (int d = 0; d < pd; ++d) bernstein(degrees[d], points(d, q), b1[d], db1[d]);
    MultiIndex digit(pd, count);
    for (int b = 0; b < nb; ++b, digit.next()) {
      double v = 1;
      for (int d = 0; d < pd; ++d) v *= b1[d][digit[d]];
      table.values(b, q) = v;
      for (int g = 0; g < pd; ++g) {
        double dv = 1;
        for (int d = 0; d < pd; ++d) dv *= d == g ? db1[d][digit[d]] : b1[d][digit[d]];
        table.derivatives[g](b, q) = dv;
      }
    }
  }
}

ReferenceRule reference_rule(const AnalysisSpace& space, int extra) {
  const int pd = space.param_dim();
  std::array<QuadratureRule, 3> rules;
  std::array<int, 3> count{1, 1, 1};
  int n = 1;
  for (int d = 0; d < pd; ++d) {
    rules[d] = gauss_legendre(space.degrees[d] + 1 + extra);
    n *= count[d] = int(rules[d].points.size());
  }
  ReferenceRule rule{Eigen::MatrixXd(pd, n), Eigen::VectorXd(n), {}};
  MultiIndex g(pd, count);
  for (int q = 0; q < n; ++q, g.next()) {
    rule.weights(q) = 1;
    for (int d = 0; d < pd; ++d) {
      rule.points(d, q) = rules[d].points(g[d]);
      rule.weights(q) *= rules[d].weights(g[d]);
    }
  }
  fill_bernstein_table(space.degrees, rule.points, rule.basis);
  return rule;
}

}  // namespace isosid::prep
