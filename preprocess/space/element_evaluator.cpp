// Evaluation of rational element functions; see element_evaluator.hpp.
#include "space/element_evaluator.hpp"

namespace isosid::prep {

void ElementEvaluator::evaluate(const Element& e, const BernsteinTable& table, ElementValues& out) const {
  const int pd = space_.param_dim(), nf = int(e.functions.size());
  w_.resize(nf);
  P_.resize(nf, space_.phys_dim());
  for (int f = 0; f < nf; ++f) {
    w_(f) = space_.weights(e.functions[f]);
    P_.row(f) = space_.control_points.row(e.functions[f]);
  }
  N_.noalias() = e.C * table.values;
  W_.noalias() = w_.transpose() * N_;
  // R = w N / W
  out.R = N_;
  out.R.array().colwise() *= w_.array();
  out.R.array().rowwise() /= W_.array();
  out.x.noalias() = P_.transpose() * out.R;
  for (int d = 0; d < pd; ++d) {
    // dR/dxi_d = (w dN - R dW) / W, with dN/dxi_d = C dB/dt_d / (element size in d)
    dN_.noalias() = e.C * table.derivatives[d];
    dN_ /= e.hi(d) - e.lo(d);
    dW_.noalias() = w_.transpose() * dN_;
    Eigen::MatrixXd& dR = out.dR_dxi[d];
    dR = dN_;
    dR.array().colwise() *= w_.array();
    dR.array() -= out.R.array().rowwise() * dW_.array();
    dR.array().rowwise() /= W_.array();
    out.dx_dxi[d].noalias() = P_.transpose() * dR;
  }
}

void ElementEvaluator::evaluate(const Element& e, const double* t, PointValues& out) const {
  const int pd = space_.param_dim();
  fill_bernstein_table(space_.degrees, Eigen::Map<const Eigen::VectorXd>(t, pd), point_table_);
  evaluate(e, point_table_, point_values_);
  out.R = point_values_.R.col(0);
  out.x = point_values_.x.col(0);
  out.dR_dxi.resize(out.R.size(), pd);
  out.J.resize(out.x.size(), pd);
  out.xi.resize(pd);
  for (int d = 0; d < pd; ++d) {
    out.dR_dxi.col(d) = point_values_.dR_dxi[d].col(0);
    out.J.col(d) = point_values_.dx_dxi[d].col(0);
    out.xi(d) = e.lo(d) + t[d] * (e.hi(d) - e.lo(d));
  }
}

}  // namespace isosid::prep
