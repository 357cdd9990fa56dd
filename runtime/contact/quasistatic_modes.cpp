// Newton solve of the quasistatic modes; see quasistatic_modes.hpp.
#include "contact/quasistatic_modes.hpp"

#include "isosid/format/error.hpp"

#include <cmath>

namespace isosid::run {

QuasistaticModes::QuasistaticModes(const std::vector<std::unique_ptr<FloatingBody>>& bodies,
                                   const std::vector<SurfaceContact>& contacts) {
  Eigen::Index n = 0;
  std::vector<Eigen::MatrixXd> blocks;
  bool diagonal = true;
  for (const auto& b : bodies) {
    if (b->n_quasistatic() == 0) continue;
    b->set_quasistatic_offset(n);
    n += b->n_quasistatic();
    bodies_.push_back(b.get());
    names_ += (names_.empty() ? "'" : ", '") + b->name() + "'";
    blocks.push_back(b->sid().Ke.M0.bottomRightCorner(b->n_quasistatic(), b->n_quasistatic()));
    diagonal = diagonal && b->stiffness().is_diagonal();
    // Displacements below eps x the body's size are not resolved by the geometry: in modal
    // units (sqrt(kg) m for mass-normalized modes) that is about 1e-16 sqrt(m) L. Without this
    // floor Newton stalls at a kink of the penalty law when the solution is zero to round-off.
    const double m = b->sid().refmod.mass;
    floor_ = std::max(floor_, 1e-16 * std::sqrt(m) * std::sqrt(b->sid().J.M0.trace() / m));
    // exact contact closes gaps to 1e-12 of the body's size: a thousand times the resolution of
    // a gap between positions of that size, far below any elastic displacement
    gap_tolerance_ = std::max(gap_tolerance_, 1e-12 * std::sqrt(b->sid().J.M0.trace() / m));
  }
  stiffness_.resize(n);
  Eigen::Index at = 0;
  for (const Eigen::MatrixXd& K : blocks) stiffness_.segment(at, K.rows()) = K.diagonal(), at += K.rows();
  if (!diagonal) {
    dense_stiffness_ = Eigen::MatrixXd::Zero(n, n);
    at = 0;
    for (const Eigen::MatrixXd& K : blocks) dense_stiffness_.block(at, at, K.rows(), K.rows()) = K, at += K.rows();
    // K_h does not change: factored once, it serves every Woodbury solve (a massless boundary
    // without contact then costs two triangular solves per Newton step, not a factorization)
    dense_factor_.compute(dense_stiffness_);
    dense_factor_ok_ = dense_factor_.info() == Eigen::Success;
  }
  if (n > 0 && stiffness_.minCoeff() <= 0)
    throw format::InputError(names_, "quasistatic modes", "the high modes must have positive stiffness (rigid-body modes cannot be quasistatic)");
  for (const SurfaceContact& c : contacts) {
    const bool touches = c.body().n_quasistatic() > 0 || (c.target().body() && c.target().body()->n_quasistatic() > 0);
    if (!touches) continue;
    contacts_.push_back(&c);
    conservative_ = conservative_ && c.frictionless();
    exact_ = exact_ || c.exact();
  }
  z_.setZero(n);
}

void QuasistaticModes::scatter(const Eigen::VectorXd& z) const {
  for (FloatingBody* b : bodies_) b->quasistatic_modes() = z.segment(b->quasistatic_offset(), b->n_quasistatic());
}

void QuasistaticModes::residual(const double* y, Eigen::VectorXd& R) const {
  scatter(z_);
  terms_.reset(size());
  penalty_energy_ = 0;
  for (const SurfaceContact* c : contacts_) penalty_energy_ += c->add_quasistatic_terms(y, terms_);
  if (dense_stiffness_.size())
    R.noalias() = dense_stiffness_ * z_;
  else
    R = stiffness_.cwiseProduct(z_);
  R -= terms_.force;
  R -= held_loads_;
}

namespace {
/// Solves A x = b in place for the leading r x r block of A (overwritten by its LU factors,
/// partial pivoting) and the first r entries of b (overwritten by x). Eigen's decompositions
/// would allocate per call for a size that changes with the active set; this runs in the
/// right-hand side, which must not.
void solve_leading_block(Eigen::MatrixXd& A, Eigen::Index r, Eigen::VectorXd& b) {
  for (Eigen::Index k = 0; k < r; ++k) {
    Eigen::Index pivot = k;
    A.col(k).segment(k, r - k).cwiseAbs().maxCoeff(&pivot);
    pivot += k;
    if (pivot != k) {
      A.row(k).head(r).swap(A.row(pivot).head(r));
      std::swap(b(k), b(pivot));
    }
    for (Eigen::Index i = k + 1; i < r; ++i) {
      const double f = A(i, k) / A(k, k);
      A.row(i).segment(k + 1, r - k - 1) -= f * A.row(k).segment(k + 1, r - k - 1);
      b(i) -= f * b(k);
    }
  }
  for (Eigen::Index k = r - 1; k >= 0; --k) b(k) = (b(k) - A.row(k).segment(k + 1, r - k - 1).dot(b.segment(k + 1, r - k - 1))) / A(k, k);
}
}  // namespace

void QuasistaticModes::solve_jacobian(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  const Eigen::Index r = terms_.rank;
  const auto U = terms_.U.leftCols(r), V = terms_.V.leftCols(r);
  // the n x n Jacobian itself (forming and factoring it: n^2 r + n^3 / 3) when that is cheaper
  // than Woodbury's r x r capacitance: with a diagonal K_h (n r^2 + r^3 / 3) once more contact
  // terms are active than there are modes; with a dense K_h and its kept Cholesky factor
  // (2 n^2 r + n r^2) once r passes about n / 4
  const bool dense = dense_stiffness_.size() > 0;
  if (dense ? (!dense_factor_ok_ || 4 * r > size()) : r > size()) {
    if (jacobian_.rows() != size()) jacobian_.resize(size(), size()), jacobian_lu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(size());
    jacobian_.noalias() = U * V.transpose();
    if (dense_stiffness_.size()) jacobian_ += dense_stiffness_;
    else jacobian_.diagonal() += stiffness_;
    jacobian_lu_.compute(jacobian_);
    x = jacobian_lu_.solve(b);
    return;
  }
  // Woodbury: (K + U V^T)^-1 b = K^-1 b - K^-1 U (I + V^T K^-1 U)^-1 V^T K^-1 b, in buffers
  // sized to the terms' capacity (no allocation once the largest active set has been seen)
  const Eigen::Index capacity = terms_.U.cols();
  if (scaled_U_.cols() != capacity) scaled_U_.resize(size(), capacity), small_.resize(capacity, capacity), coefficients_.resize(capacity);
  if (dense) {
    x = b;
    dense_factor_.solveInPlace(x);
  } else {
    x = b.cwiseQuotient(stiffness_);
  }
  if (r == 0) return;
  auto scaled_U = scaled_U_.leftCols(r);
  if (dense) {
    scaled_U = U;
    dense_factor_.solveInPlace(scaled_U);
  } else {
    scaled_U = U.array().colwise() / stiffness_.array();
  }
  small_.topLeftCorner(r, r).setIdentity();
  small_.topLeftCorner(r, r).noalias() += V.transpose() * scaled_U_.leftCols(r);
  coefficients_.head(r).noalias() = V.transpose() * x;
  solve_leading_block(small_, r, coefficients_);
  x.noalias() -= scaled_U_.leftCols(r) * coefficients_.head(r);
}

double QuasistaticModes::potential_change(double penalty_before) const {
  // Pi(z) - Pi(z_old) with Pi = 1/2 z^T K z - z . loads + penalty energy, formed from the
  // difference d = z - z_old: Pi itself can be 1e6 times larger than its change (the
  // centrifugal deformation of a spinning body), and subtracting two values of it would
  // leave round-off where the line search needs the change
  double change = penalty_energy_ - penalty_before;
  if (dense_stiffness_.size()) return change + (z_ - z_old_).dot(0.5 * dense_stiffness_ * (z_ + z_old_) - held_loads_);
  for (Eigen::Index i = 0; i < z_.size(); ++i)
    change += (z_(i) - z_old_(i)) * (0.5 * stiffness_(i) * (z_(i) + z_old_(i)) - held_loads_(i));
  return change;
}

void QuasistaticModes::update_held_loads(const double* y) const {
  held_loads_.setZero(size());
  // held during the Newton iterations: the rotation loads depend on z only through the small
  // Oe1 terms, the coupling not at all
  for (FloatingBody* b : bodies_) b->add_quasistatic_loads(y, held_loads_.segment(b->quasistatic_offset(), b->n_quasistatic()));
}

int QuasistaticModes::solve(const double* y) const {
  if (size() == 0) return 0;
  for (FloatingBody* b : bodies_) z_.segment(b->quasistatic_offset(), b->n_quasistatic()) = b->quasistatic_modes();
  update_held_loads(y);
  int iterations = newton(y);
  if (!exact_) return iterations;
  // exact contact: Uzawa passes on the multipliers, each followed by Newton, until the forces
  // settle (the gaps of the active points then close); a pass contracts the error by about
  // k / (k + c_p w), the boundary's stiffness against the augmentation's
  for (int pass = 1; pass <= kMaxUzawaPasses; ++pass) {
    double violation = 0;
    for (const SurfaceContact* c : contacts_)
      if (c->exact()) violation = std::max(violation, c->update_multipliers(y));
    if (violation <= gap_tolerance_) return iterations;
    iterations += newton(y);
  }
  throw QuasistaticDivergence("the exact contact of " + names_ + " did not settle in " + std::to_string(kMaxUzawaPasses) +
                              " augmented-Lagrangian passes: raise its penalty (the augmentation) toward the boundary's stiffness or above");
}

int QuasistaticModes::newton(const double* y) const {
  // Without friction the equilibrium minimizes the convex energy
  // Pi(z) = 1/2 z^T K z - z . loads + sum 1/2 c_p g^2 w, whose gradient is the residual R: Newton steps
  // with an Armijo line search on Pi converge across active-set changes, where a line search
  // on |R| stalls. With friction (not a potential) the search falls back to |R|.
  residual(y, R_);
  for (int iteration = 1; iteration <= 60; ++iteration) {
    solve_jacobian(R_, step_);
    z_old_ = z_;
    const double penalty_before = penalty_energy_, residual_before = R_.norm(), slope = -R_.dot(step_);
    if (step_.norm() <= 1e-11 * z_.norm() + floor_) {
      // converged: an update below the resolution of the gaps, whose energy change is
      // round-off that the line search would halve against thirty times (scene A: a third of
      // all residual evaluations)
      z_ -= step_;
      residual(y, R_);
      scatter(z_);
      return iteration;
    }
    double alpha = 1.0;
    for (int halving = 0; halving < 30; ++halving) {
      z_ = z_old_ - alpha * step_;
      residual(y, R_);
      const bool accept = conservative_ ? potential_change(penalty_before) <= 1e-4 * alpha * slope : R_.norm() <= residual_before;
      if (accept || halving == 29) break;
      alpha *= 0.5;
    }
    // R_ and the Jacobian terms are those of the accepted z_ (the last trial)
    // converged when the update or the residual is at round-off relative to the solution
    // (an absolute tolerance would feed solver noise into the right-hand side, and the
    // step-size control would chase it)
    const double force = dense_stiffness_.size() ? (dense_stiffness_ * z_).norm() : stiffness_.cwiseProduct(z_).norm();
    if (alpha * step_.norm() <= 1e-11 * z_.norm() + floor_ || R_.norm() <= 1e-10 * force || (force == 0 && R_.norm() == 0)) {
      scatter(z_);
      return iteration;
    }
  }
  throw QuasistaticDivergence("the quasistatic modes of " + names_ +
                                 " did not converge (Newton, 60 iterations): penalty too stiff for the contact resolution?");
}

double QuasistaticModes::friction_power(const double* y, const double* ydot, Eigen::Index n) const {
  if (size() == 0 || conservative_) return 0;
  friction_ = terms_.friction;  // of the converged z_ at y (solve's last residual)
  if (friction_.isZero(0.0)) return 0;
  // dR/dy ydot by a forward difference at fixed z, with the step of a Jacobian-vector product
  // (sqrt(eps) relative to the state); its error only blurs the energy bookkeeping, never the motion
  const Eigen::Map<const Eigen::VectorXd> state(y, n), rate(ydot, n);
  const double rate_norm = rate.norm();
  if (rate_norm == 0) return 0;
  const double h = 1.5e-8 * (1.0 + state.norm()) / rate_norm;
  shifted_y_ = state + h * rate;
  const Eigen::VectorXd R0 = R_;
  update_held_loads(shifted_y_.data());
  residual(shifted_y_.data(), R_);
  // the Jacobian of the shifted state: it differs from that at y by O(h)
  solve_jacobian((R0 - R_) / h, z_rate_);
  update_held_loads(y);
  residual(y, R_);  // leaves R_, the terms and the penalty energy those of y again
  return -friction_.dot(z_rate_);
}

}  // namespace isosid::run
