// Quasistatic high-frequency modes (seed 001): instead of integrating the stiff high modes,
// solve their static equilibrium K_h z = f(z) under the contact forces (and the rotation
// loads of spinning bodies) at every evaluation,
// by Newton's method with the exact contact Jacobian. All bodies are solved together, so a
// contact between two flexible bodies couples their modes. The Jacobian K_h + U V^T (modal
// stiffness plus one rank-one term per active point) is inverted with the Woodbury identity:
// the cost grows with the number of active points, not with the number of modes.
#pragma once
#include "body/floating_body.hpp"
#include "contact/quasistatic_terms.hpp"
#include "contact/surface_contact.hpp"
#include "isosid/format/error.hpp"

#include <memory>
#include <vector>

namespace isosid::run {

/// The quasistatic Newton did not converge at a state. At a trial stage of a step that went too
/// far into contact this is recoverable: the integrator retries the step smaller.
class QuasistaticDivergence : public format::ComputationError {
public:
  using format::ComputationError::ComputationError;
};

class QuasistaticModes {
public:
  /// Augmented-Lagrangian passes of exact contact before the solve gives up.
  static constexpr int kMaxUzawaPasses = 100;

  /// Assigns every body with quasistatic modes its block of the stacked vector z.
  QuasistaticModes(const std::vector<std::unique_ptr<FloatingBody>>& bodies, const std::vector<SurfaceContact>& contacts);

  /// Number of stacked quasistatic modes (0: nothing to solve).
  Eigen::Index size() const { return stiffness_.size(); }
  /// Updates the bodies' quasistatic modes for state y (warm-started from their last values);
  /// returns the Newton iterations. Throws ComputationError (naming the bodies) on failure.
  int solve(const double* y) const;
  /// Power dissipated by friction through the quasistatic modes at the state y just solved:
  /// -f_t . dz/dt, f_t the friction part of their generalized contact force. The equilibrium
  /// R(z, y) = 0 moves z along with y, at dz/dt = -J^-1 (dR/dy) ydot; ydot has n entries.
  /// 0 without friction.
  double friction_power(const double* y, const double* ydot, Eigen::Index n) const;

private:
  void scatter(const Eigen::VectorXd& z) const;
  /// The loads on z at state y that do not depend on z (held while Newton iterates): centrifugal
  /// and Coriolis loads, and the stiffness coupling to the integrated modes.
  void update_held_loads(const double* y) const;
  /// Residual K z - f(z) at the current z_, and the rank-one terms of its Jacobian.
  void residual(const double* y, Eigen::VectorXd& R) const;
  /// Newton's method for z at y with the contacts' current multipliers; returns its iterations.
  int newton(const double* y) const;
  /// Solves (K + U V^T) x = b.
  void solve_jacobian(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  /// Change of the potential energy from z_old_ to z_ (frictionless contact: its gradient is
  /// the residual, so it is Newton's merit); penalty_before: the contacts' energy at z_old_.
  double potential_change(double penalty_before) const;

  std::vector<FloatingBody*> bodies_;            ///< bodies with quasistatic modes
  std::vector<const SurfaceContact*> contacts_;  ///< contacts touching one of them
  Eigen::VectorXd stiffness_;                    ///< diagonal of K_h (the SID's normal form)
  Eigen::MatrixXd dense_stiffness_;              ///< K_h if it is not diagonal (massless boundaries, SIDs from elsewhere)
  Eigen::LLT<Eigen::MatrixXd> dense_factor_;     ///< its Cholesky factor
  bool dense_factor_ok_ = false;                 ///< K_h is positive definite (else the Jacobian is factored each time)
  bool conservative_ = true;
  bool exact_ = false;                           ///< some contact is exact: Uzawa passes around Newton
  double floor_ = 0;                             ///< unresolvable displacement, modal units
  double gap_tolerance_ = 0;                     ///< m: exact contact's gaps close to this
  std::string names_;
  mutable Eigen::VectorXd z_, R_, step_, z_old_, coefficients_;
  mutable Eigen::MatrixXd scaled_U_, small_;
  mutable Eigen::MatrixXd jacobian_;                         ///< K + U V^T, when K is dense or the rank exceeds the size
  mutable Eigen::PartialPivLU<Eigen::MatrixXd> jacobian_lu_;
  mutable QuasistaticTerms terms_;
  mutable double penalty_energy_ = 0;           ///< of the contacts at the last residual
  mutable Eigen::VectorXd held_loads_;           ///< update_held_loads()
  mutable Eigen::VectorXd shifted_y_, friction_, z_rate_;  ///< friction_power's buffers
};

}  // namespace isosid::run
