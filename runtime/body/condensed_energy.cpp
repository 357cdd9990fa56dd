// Elastic energy through the held coordinates' static condensation; see condensed_energy.hpp.
#include "body/condensed_energy.hpp"

#include <cmath>

namespace isosid::run {

std::optional<CondensedEnergy> CondensedEnergy::of(const Eigen::MatrixXd& K, Eigen::Index n_dynamic) {
  const Eigen::Index d = n_dynamic, h = K.rows() - n_dynamic;
  if (d <= 0 || h <= 0) return std::nullopt;
  const auto coupling = K.bottomLeftCorner(h, d);
  if (coupling.isZero(0.0)) return std::nullopt;
  Eigen::LLT<Eigen::MatrixXd> held(K.bottomRightCorner(h, h));
  if (held.info() != Eigen::Success) return std::nullopt;
  CondensedEnergy out;
  out.held_ = K.bottomRightCorner(h, h);
  out.held_norm_ = out.held_.norm();
  out.follow_ = held.solve(Eigen::MatrixXd(coupling));
  out.schur_ = K.topLeftCorner(d, d) - K.topRightCorner(d, h) * out.follow_;
  out.schur_ = 0.5 * (out.schur_ + out.schur_.transpose()).eval();
  out.modal_product_.resize(d);
  out.r_.resize(h);
  out.product_.resize(h);
  return out;
}

double CondensedEnergy::operator()(const Eigen::VectorXd& q) const {
  const Eigen::Index d = schur_.rows();
  const auto qd = q.head(d);
  modal_product_.noalias() = schur_ * qd;
  const double condensed = qd.dot(modal_product_);
  r_ = q.tail(q.size() - d);
  r_.noalias() += follow_ * qd;
  if (held_norm_ * r_.squaredNorm() <= 1e-15 * std::abs(condensed)) return 0.5 * condensed;
  product_.noalias() = held_ * r_;
  return 0.5 * (condensed + r_.dot(product_));
}

}  // namespace isosid::run
