// Newton solve of the quasistatic modes; see quasistatic_modes.hpp.
#include "condensation/quasistatic_modes.hpp"

#include "isosid/format/error.hpp"

#include <algorithm>
#include <cmath>

namespace isosid::run {

QuasistaticModes::QuasistaticModes(const std::vector<std::unique_ptr<FloatingBody>>& bodies,
                                   const std::vector<SurfaceContact>& contacts, const Eigen::Vector3d& gravity)
    : gravity_(gravity) {
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
  jacobian_ = QuasistaticJacobian(blocks, diagonal);
  if (n > 0 && jacobian_.smallest_diagonal() <= 0)
    throw format::InputError(names_, "quasistatic modes", "the high modes must have positive stiffness (rigid-body modes cannot be quasistatic)");
  for (const SurfaceContact& c : contacts) {
    const bool touches = c.body().n_quasistatic() > 0 || (c.target().body() && c.target().body()->n_quasistatic() > 0);
    if (!touches) continue;
    contacts_.push_back(&c);
    conservative_ = conservative_ && c.frictionless();
    Eigen::Vector3d normal;
    double offset = 0;
    flat_ = flat_ && c.target().fixed_plane(normal, offset);
    exact_ = exact_ || c.exact();
  }
  z_.setZero(n);
  // gap space condenses all the quasistatic modes onto the gaps: every contact on them must be in it
  const auto in_gap_space = [](const SurfaceContact* c) { return c->gap_space(); };
  if (std::any_of(contacts_.begin(), contacts_.end(), in_gap_space)) {
    for (const SurfaceContact* c : contacts_)
      if (!c->gap_space())
        throw format::InputError(c->name(), "formulation",
                                 "must be gap-space like the other contacts on the quasistatic modes of " + names_);
    gap_space_ = std::make_unique<GapSpaceSolve>(contacts_, jacobian_);
    for (const FloatingBody* b : bodies_) {
      const Eigen::MatrixXd& coupling = b->quasistatic_coupling();
      Eigen::MatrixXd response(coupling.rows(), coupling.cols());
      if (coupling.size()) jacobian_.solve_stiffness_block(b->quasistatic_offset(), coupling, response);
      coupled_response_.push_back(std::move(response));
    }
  }
}

void QuasistaticModes::scatter(const Eigen::VectorXd& z) const {
  for (FloatingBody* b : bodies_) b->quasistatic_modes() = z.segment(b->quasistatic_offset(), b->n_quasistatic());
}

void QuasistaticModes::residual(const double* y, Eigen::VectorXd& R) const {
  scatter(z_);
  ++passes_;
  terms_.reset(size());
  // the model knows the free points that its step could close: within twice the deepest
  // penetration of the last solution (where new points enter as the contact grows), or within
  // reach of a change of z by twice its size (where the model releases the deformation)
  terms_.window = window_;
  terms_.reach = 2 * z_.norm();
  for (const SurfaceContact* c : contacts_) c->add_quasistatic_terms(y, terms_);
  model_.start(jacobian_, terms_, z_, held_loads_);
  penalty_energy_ = model_.energy();
  force_ = model_.force();
  friction_force_ = model_.friction();
  R = model_.residual();
}

double QuasistaticModes::potential_change(double penalty_before) const {
  // Pi(z) - Pi(z_old) with Pi = 1/2 z^T K z - z . loads + penalty energy, formed from the
  // difference d = z - z_old: Pi itself can be 1e6 times larger than its change (the
  // centrifugal deformation of a spinning body), and subtracting two values of it would
  // leave round-off where the line search needs the change
  step_ = z_ - z_old_;
  z_sum_ = z_ + z_old_;
  return penalty_energy_ - penalty_before + 0.5 * jacobian_.product(step_, z_sum_) - step_.dot(held_loads_);
}

void QuasistaticModes::update_held_loads(const double* y) const {
  held_loads_.setZero(size());
  // held during the Newton iterations: the rotation loads depend on z only through the small
  // Oe1 terms, the coupling not at all
  for (FloatingBody* b : bodies_) b->add_quasistatic_loads(y, gravity_, held_loads_.segment(b->quasistatic_offset(), b->n_quasistatic()));
}

void QuasistaticModes::solve_held_response(const double* y) const {
  held_loads_.resize(size());
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const FloatingBody& b = *bodies_[i];
    auto z = z_.segment(b.quasistatic_offset(), b.n_quasistatic());
    auto loads = held_loads_.segment(b.quasistatic_offset(), b.n_quasistatic());
    loads.setZero();
    if (b.add_uncoupled_quasistatic_loads(y, gravity_, loads)) jacobian_.solve_stiffness_block(b.quasistatic_offset(), loads, z);
    else z.setZero();
    if (coupled_response_[i].size()) z.noalias() -= coupled_response_[i] * b.q(y).head(b.n_dynamic());
  }
}

int QuasistaticModes::solve(const double* y) const {
  if (size() == 0) return 0;
  if (gap_space_) {
    solve_held_response(y);
    return gap_space_->solve(y, z_, [&](const Eigen::VectorXd& z) { scatter(z); });
  }
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
  // Pi(z) = 1/2 z^T K z - z . loads + sum 1/2 c_p g^2 w, whose gradient is the residual R: each
  // step solves the contact problem with linearized gaps (exact for a plane) and an Armijo
  // search on Pi guards it where the gaps curve. With friction (not a potential) the search
  // falls back to |R|.
  residual(y, R_);
  int remodels = 0;
  for (int iteration = 1; iteration <= 60; ++iteration) {
    model_.solve(jacobian_, terms_, held_loads_, conservative_, move_);
    // converged when the update is at round-off relative to the solution (an absolute
    // tolerance would feed solver noise into the right-hand side, and the step-size control
    // would chase it; the residual itself stalls at the solve's round-off, K's condition times eps)
    const double resolution = 1e-11 * z_.norm() + floor_;
    if (flat_ && model_.solved() && !terms_.unseen && move_.norm() <= terms_.reach) {
      // against planes the model is the problem itself, and a move within the reach closes no
      // point it left out: its solution is the solution, without another pass over the points
      z_ += move_;
      terms_.gap.head(terms_.count) = model_.gaps().head(terms_.count);
      force_ = model_.force();
      friction_force_ = model_.friction();
      R_ = model_.residual();
      penalty_energy_ = model_.energy();
      scatter(z_);
      for (const SurfaceContact* c : contacts_) c->take_model_gaps(y, terms_);
      update_window();
      return iteration;
    }
    if (move_.norm() <= resolution) {
      // an update below the resolution of the gaps: the recorded points stay those of z_,
      // and their energy change is round-off that a line search would halve against
      z_ += move_;
      scatter(z_);
      update_window();
      return iteration;
    }
    z_old_ = z_;
    predicted_force_ = model_.force();  // the trials below restart the model
    const bool model_solved = model_.solved();
    const double penalty_before = penalty_energy_, residual_before = R_.norm(), slope = R_.dot(move_);
    // A full step on a solved model whose forces there are the real ones converged: the next
    // update, J^-1 (f_model - f), is at most |f_model - f| / min K (J is K plus a positive
    // semidefinite part without friction) on top of the model's round-off. "The real ones"
    // to the round-off of the gaps, which both forces carry: below it the energy test would
    // compare noise (near the solution the gaps' round-off outweighs a step's energy change,
    // and the search halved such steps to nothing, 30 times over).
    auto model_held = [&] {
      return conservative_ && model_solved &&
             (predicted_force_ - force_).norm() <= jacobian_.smallest_eigenvalue() * resolution + 2 * terms_.force_resolution();
    };
    double alpha = 1.0;
    bool held = false, remodel = false;
    for (int halving = 0; halving < 30; ++halving) {
      z_ = z_old_ + alpha * move_;
      residual(y, R_);
      held = halving == 0 && model_held();
      const bool accept = held || (conservative_ ? potential_change(penalty_before) <= 1e-4 * alpha * slope : R_.norm() <= residual_before);
      if (accept || halving == 29) break;
      // The full step pressed points its model did not know, and they are recorded from now
      // on: the model at z_old with them makes a better step than the halvings of this one
      // (one pass instead of about nine). A point is unknown once per state; a contact that
      // grows ring by ring gets a few new models, then halvings.
      if (halving == 0 && terms_.newly_pressed > 0 && remodels < kMaxRemodels) {
        remodel = true;
        ++remodels;
        break;
      }
      alpha *= 0.5;
    }
    if (remodel) {
      z_ = z_old_;
      residual(y, R_);
      continue;
    }
    // R_ and the recorded points are those of the accepted z_ (the last trial)
    if (held || alpha * move_.norm() <= resolution) {
      scatter(z_);
      update_window();
      return iteration;
    }
  }
  throw QuasistaticDivergence("the quasistatic modes of " + names_ +
                              " did not converge (Newton, 60 iterations): penalty too stiff for the contact resolution?");
}

void QuasistaticModes::update_window() const {
  window_ = 0;
  for (Eigen::Index k = 0; k < terms_.count; ++k) window_ = std::max(window_, -2 * terms_.law[std::size_t(k)]->effective_gap(terms_.gap(k), terms_.multiplier(k)));
}

double QuasistaticModes::friction_power(const double* y, const double* ydot, Eigen::Index n) const {
  if (size() == 0 || conservative_) return 0;
  friction_ = friction_force_;  // of the converged z_ at y (solve's last residual)
  if (friction_.isZero(0.0)) return 0;
  // dR/dy ydot by a forward difference at fixed z, with the step of a Jacobian-vector product
  // (sqrt(eps) relative to the state); its error only blurs the energy bookkeeping, never the motion
  const Eigen::Map<const Eigen::VectorXd> state(y, n), rate(ydot, n);
  const double rate_norm = rate.norm();
  if (rate_norm == 0) return 0;
  const double h = 1.5e-8 * (1.0 + state.norm()) / rate_norm;
  // the Jacobian at y rather than at the shifted state (they differ by O(h)): its factorization
  // is kept from the solve's last step, where the shifted terms would be factored anew
  const Eigen::Index r = model_.jacobian_terms(terms_, terms_.gap);
  shifted_y_ = state + h * rate;
  const Eigen::VectorXd R0 = R_;
  update_held_loads(shifted_y_.data());
  residual(shifted_y_.data(), R_);  // leaves the model's Jacobian terms alone
  jacobian_.solve(model_.U(), model_.V(), r, (R0 - R_) / h, z_rate_);
  // R_, the terms, the model's gaps and the held loads stay those of the shifted state (its
  // Jacobian terms those of y): the next solve sets them all anew before it reads any (z_ is
  // still the solution at y)
  return -friction_.dot(z_rate_);
}

}  // namespace isosid::run
