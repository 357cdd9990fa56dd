// Evaluation of rational element functions; see element_evaluator.hpp.
#include "space/element_evaluator.hpp"

#include "space/bernstein.hpp"

namespace isosid::prep {

void ElementEvaluator::evaluate(const Element& e, const double* t, PointValues& out) const {
  const int pd = space_.param_dim(), nb = int(e.C.cols()), nf = int(e.functions.size());
  for (int d = 0; d < pd; ++d) bernstein(space_.degrees[std::size_t(d)], t[d], b_[d], db_[d]);
  // tensor Bernstein values and parametric gradients (first direction fastest)
  Eigen::VectorXd B(nb);
  Eigen::MatrixXd dB(nb, pd);
  for (int b = 0; b < nb; ++b) {
    int rest = b;
    int digit[3] = {0, 0, 0};
    for (int d = 0; d < pd; ++d) {
      digit[d] = rest % (space_.degrees[std::size_t(d)] + 1);
      rest /= space_.degrees[std::size_t(d)] + 1;
    }
    double v = 1;
    for (int d = 0; d < pd; ++d) v *= b_[d](digit[d]);
    B(b) = v;
    for (int g = 0; g < pd; ++g) {
      double dv = 1;
      for (int d = 0; d < pd; ++d) dv *= d == g ? db_[d](digit[d]) / (e.hi(d) - e.lo(d)) : b_[d](digit[d]);
      dB(b, g) = dv;
    }
  }
  const Eigen::VectorXd N = e.C * B;
  const Eigen::MatrixXd dN = e.C * dB;
  Eigen::VectorXd w(nf);
  for (int f = 0; f < nf; ++f) w(f) = space_.weights(e.functions[std::size_t(f)]);
  const double W = w.dot(N);
  const Eigen::RowVectorXd dW = w.transpose() * dN;
  out.R = w.cwiseProduct(N) / W;
  out.dR_dxi = (w.asDiagonal() * dN - out.R * dW) / W;
  const int phys = space_.phys_dim();
  out.x = Eigen::VectorXd::Zero(phys);
  out.J = Eigen::MatrixXd::Zero(phys, pd);
  for (int f = 0; f < nf; ++f) {
    const auto P = space_.control_points.row(e.functions[std::size_t(f)]).transpose();
    out.x += out.R(f) * P;
    out.J += P * out.dR_dxi.row(f);
  }
  out.xi.resize(pd);
  for (int d = 0; d < pd; ++d) out.xi(d) = e.lo(d) + t[d] * (e.hi(d) - e.lo(d));
}

}  // namespace isosid::prep
