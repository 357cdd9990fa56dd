// Newton solve of the quasistatic modes; see quasistatic_modes.hpp.
#include "contact/quasistatic_modes.hpp"

#include "isosid/format/error.hpp"

namespace isosid::run {

int solve_quasistatic_modes(const FlexibleBody& body, const std::vector<const PlaneContact*>& contacts, const double* y) {
  const Eigen::Index first = body.n_dynamic(), nh = body.n_quasistatic();
  if (nh == 0) return 0;
  Eigen::VectorXd& qh = body.quasistatic_modes();
  const Eigen::MatrixXd Khh = body.sid().Ke.M0.bottomRightCorner(nh, nh);
  auto residual = [&](Eigen::VectorXd& R, Eigen::MatrixXd* J) {
    Eigen::VectorXd F = Eigen::VectorXd::Zero(nh);
    Eigen::MatrixXd Kc = Eigen::MatrixXd::Zero(nh, nh);
    for (const PlaneContact* c : contacts) c->add_quasistatic_terms(y, first, F, Kc);
    R = Khh * qh - F;
    if (J) *J = Khh + Kc;
  };
  Eigen::VectorXd R;
  Eigen::MatrixXd J;
  residual(R, &J);
  const double scale = std::max(1.0, (Khh.diagonal().cwiseSqrt().asDiagonal() * qh).norm());
  for (int iteration = 1; iteration <= 60; ++iteration) {
    const Eigen::VectorXd step = J.partialPivLu().solve(R);
    const Eigen::VectorXd q_old = qh;
    const double r_old = R.norm();
    // damped Newton: halve the step while the residual grows (penalty contact is only
    // piecewise smooth, so a full step may jump across an active-set change)
    double alpha = 1.0;
    for (int halving = 0; halving < 12; ++halving) {
      qh = q_old - alpha * step;
      residual(R, nullptr);
      if (R.norm() <= r_old || halving == 11) break;
      alpha *= 0.5;
    }
    residual(R, &J);
    if (alpha * step.norm() <= 1e-12 * std::max(qh.norm(), 1e-300) || R.norm() <= 1e-12 * scale * Khh.diagonal().maxCoeff())
      return iteration;
  }
  throw format::ComputationError("the quasistatic modes of '" + body.name() +
                                 "' did not converge (Newton, 60 iterations): penalty too stiff for the contact resolution?");
}

}  // namespace isosid::run
