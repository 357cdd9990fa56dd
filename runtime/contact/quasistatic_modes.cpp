// Newton solve of the quasistatic modes; see quasistatic_modes.hpp.
#include "contact/quasistatic_modes.hpp"

#include "isosid/format/error.hpp"

#include <cmath>

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
  // Without friction the equilibrium minimizes the convex energy
  // Pi(q_h) = 1/2 q_h^T Khh q_h + sum 1/2 c_p g^2 w, whose gradient is the residual R: Newton
  // steps with an Armijo line search on Pi converge across active-set changes, where a line
  // search on |R| stalls. With friction (not a potential) the search falls back to |R|.
  bool conservative = true;
  for (const PlaneContact* c : contacts) conservative = conservative && c->frictionless();
  auto merit = [&](const Eigen::VectorXd& R) {
    if (!conservative) return R.norm();
    double pi = 0.5 * qh.dot(Khh * qh);
    for (const PlaneContact* c : contacts) pi += c->penalty_energy(y);
    return pi;
  };
  // Displacements below eps x the body's size are not resolved by the geometry: in modal
  // units (sqrt(kg) m for mass-normalized modes) that is about 1e-16 sqrt(m) L. Without this
  // floor Newton stalls at a kink of the penalty law when the solution is zero to round-off.
  const double m = body.sid().refmod.mass;
  const double floor = 1e-16 * std::sqrt(m) * std::sqrt(body.sid().J.M0.trace() / m);
  Eigen::VectorXd R;
  Eigen::MatrixXd J;
  residual(R, &J);
  for (int iteration = 1; iteration <= 60; ++iteration) {
    const Eigen::VectorXd step = J.partialPivLu().solve(R);
    const Eigen::VectorXd q_old = qh;
    const double m_old = merit(R), slope = -R.dot(step);
    double alpha = 1.0;
    for (int halving = 0; halving < 30; ++halving) {
      qh = q_old - alpha * step;
      residual(R, nullptr);
      const double m_new = merit(R);
      if ((conservative ? m_new <= m_old + 1e-4 * alpha * slope : m_new <= m_old) || halving == 29) break;
      alpha *= 0.5;
    }
    residual(R, &J);
    // converged when the update or the residual is at round-off relative to the solution
    // (an absolute tolerance would feed solver noise into the right-hand side, and the
    // step-size control would chase it)
    const double force = (Khh * qh).norm();
    if (alpha * step.norm() <= 1e-11 * qh.norm() + floor || R.norm() <= 1e-10 * force || (force == 0 && R.norm() == 0))
      return iteration;
  }
  throw format::ComputationError("the quasistatic modes of '" + body.name() +
                                 "' did not converge (Newton, 60 iterations): penalty too stiff for the contact resolution?");
}

}  // namespace isosid::run
