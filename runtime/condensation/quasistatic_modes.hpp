// Quasistatic high-frequency modes ([R2], docs/references.md): instead of integrating the stiff
// high modes, solve their static equilibrium K_h z = f(z) under the contact forces (and the
// rotation loads of spinning bodies) at every evaluation, by Newton's method with the exact contact
// Jacobian. All bodies are solved together, so a contact between two flexible bodies couples
// their modes. Each Newton step solves the contact problem with the points' gaps linearized
// where it stands (ContactModel, active set included), so a step costs one pass over the
// contact points however many of them enter or leave contact; the Jacobian K_h + U V^T is
// solved by Woodbury or directly, whichever is cheaper (QuasistaticJacobian).
#pragma once
#include "body/floating_body.hpp"
#include "condensation/contact_model.hpp"
#include "condensation/gap_space_solve.hpp"
#include "condensation/quasistatic_jacobian.hpp"
#include "condensation/quasistatic_terms.hpp"
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
  /// New linear models per Newton solve after full steps that pressed points the model did
  /// not know (then the step is halved instead).
  static constexpr int kMaxRemodels = 8;

  /// Assigns every body with quasistatic modes its block of the stacked vector z; `gravity`
  /// (world, m/s^2) loads the modes of bodies whose frame is held.
  QuasistaticModes(const std::vector<std::unique_ptr<FloatingBody>>& bodies, const std::vector<SurfaceContact>& contacts,
                   const Eigen::Vector3d& gravity);

  /// Number of stacked quasistatic modes (0: nothing to solve).
  Eigen::Index size() const { return jacobian_.size(); }
  /// Updates the bodies' quasistatic modes for state y (warm-started from their last values);
  /// returns the Newton iterations. Throws ComputationError (naming the bodies) on failure.
  int solve(const double* y) const;
  /// Passes over the contact points so far (residual evaluations: Newton steps and their
  /// line-search trials); what a static solve costs grows with them.
  long passes() const { return passes_; }
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
  /// z_ = K_h^-1 times the held loads at y, each body's coupling to its integrated modes
  /// through K_h^-1 K_hd formed once (gap space: nothing in free flight then grows with the
  /// square of a massless boundary's coordinates).
  void solve_held_response(const double* y) const;
  /// Records the contact points' linearization at the current z_ and the residual
  /// K z - f(z) - held loads into R.
  void residual(const double* y, Eigen::VectorXd& R) const;
  /// Newton's method for z at y with the contacts' current multipliers; returns its iterations.
  int newton(const double* y) const;
  /// The free-point window of the next solve's recording from the solution just found.
  void update_window() const;
  /// Change of the potential energy from z_old_ to z_ (frictionless contact: its gradient is
  /// the residual, so it is Newton's merit); penalty_before: the contacts' energy at z_old_.
  double potential_change(double penalty_before) const;

  std::vector<FloatingBody*> bodies_;            ///< bodies with quasistatic modes
  std::vector<const SurfaceContact*> contacts_;  ///< contacts touching one of them
  QuasistaticJacobian jacobian_;
  ContactModel model_;
  std::unique_ptr<GapSpaceSolve> gap_space_;     ///< every contact in gap space: solves in place of Newton
  std::vector<Eigen::MatrixXd> coupled_response_;  ///< gap space, per body: K_b^-1 K_hd (empty without coupling)
  bool conservative_ = true;
  bool flat_ = true;                             ///< every contact's target is a fixed plane
  bool exact_ = false;                           ///< some contact is exact: Uzawa passes around Newton
  double floor_ = 0;                             ///< unresolvable displacement, modal units
  double gap_tolerance_ = 0;                     ///< m: exact contact's gaps close to this
  std::string names_;
  mutable Eigen::VectorXd z_, R_, move_, step_, z_old_, z_sum_, force_, friction_force_, predicted_force_;
  mutable QuasistaticTerms terms_;
  mutable long passes_ = 0;
  mutable double window_ = 0;                    ///< QuasistaticTerms::window of the next solve, m
  mutable double penalty_energy_ = 0;           ///< of the contacts at the last residual
  mutable Eigen::VectorXd held_loads_;           ///< update_held_loads(); in gap space the loads besides the coupling
  Eigen::Vector3d gravity_ = Eigen::Vector3d::Zero();
  mutable Eigen::VectorXd shifted_y_, friction_, z_rate_;  ///< friction_power's buffers
};

}  // namespace isosid::run
