// The simulated system: flexible and rigid bodies, fixed surfaces and contacts, as one
// first-order ODE y' = f(t, y) whose last entry integrates the dissipated energy (modal
// damping + friction), so that the energy balance can be checked to integration accuracy.
#pragma once
#include "body/floating_body.hpp"
#include "condensation/quasistatic_modes.hpp"
#include "contact/contact_target.hpp"
#include "contact/hertz_contact.hpp"
#include "contact/impact_estimate.hpp"
#include "contact/penalty_decision.hpp"
#include "contact/surface_contact.hpp"
#include "contact/surface_touch.hpp"
#include "joint/joint_constraints.hpp"
#include "scene/run_warning.hpp"
#include "scene/scene.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace isosid::run {

struct Energies {
  double kinetic = 0, elastic = 0, gravity = 0, penalty = 0, dissipated = 0;
  double total() const { return kinetic + elastic + gravity + penalty + dissipated; }
};

class MultibodySystem {
public:
  /// `sids`: one per flexible body of the scene, in order (rigid bodies get theirs here).
  /// `given`: penalties a caller gives contacts for this run in place of the scene's.
  MultibodySystem(const Scene& scene, std::vector<format::Sid> sids, GivenPenalties given = {});
  /// Gives up the SIDs of its flexible bodies, in the scene's order; the system is of no use
  /// after.
  std::vector<format::Sid> release_sids() &&;

  Eigen::Index size() const { return size_; }
  void initial_state(double* y) const;
  /// Right-hand side; reuses preallocated force buffers. A call at the state of the call before
  /// returns that call's result: ARKODE's ERKStep evaluates the start of each step again
  /// although its Dormand-Prince stages ended there (about one call in six).
  void rhs(double t, const double* y, double* ydot) const;
  /// One gap function per contact (for event location): the smallest signed gap. Right after
  /// rhs(y) the static solve already holds for y and is not repeated.
  void gaps(const double* y, double* g) const;
  /// Root functions for event location: gaps() (one per contact), then one per contact for
  /// the touch of its exact surfaces (SurfaceTouch) while that is armed, else a constant 1.
  std::size_t root_count() const { return 2 * contacts_.size(); }
  void roots(const double* y, double* g) const;
  /// The closest approach of contact k's exact surfaces at y (quasistatic modes solved for y).
  const Touch& touch(std::size_t k, const double* y) const;
  /// Contact k's touch was found: its root is held until the contact has opened (release())
  /// and its surfaces are apart again, so a later impact is found as well.
  void touched(std::size_t k) const { touch_state_[k] = TouchState::Found; }
  void released(std::size_t k) const {
    if (touch_state_[k] == TouchState::Found) touch_state_[k] = TouchState::Separating;
  }
  /// At an accepted step (never inside the root finder's search, which goes back and forth in
  /// time): released contacts whose surfaces are apart at y are armed again.
  void rearm_touches(const double* y) const;
  /// Contact k waits for its next touch (its last impact, if any, is over: opened and apart).
  bool touch_armed(std::size_t k) const { return touch_state_[k] == TouchState::Armed; }
  /// y differs from the state of the last right-hand side in velocities only (the leapfrog's
  /// closing kick): the static solution of that evaluation is kept as the one at y, as the
  /// scheme takes velocity-dependent loads at the half-step velocity (Leapfrog). The step's
  /// gaps and output then read the solution its accelerations came from, without a second solve.
  void keep_static_solution(const double* y) const;
  /// Contact states at y (for output); also brings the quasistatic modes up to date for y.
  std::vector<ContactState> contact_states(const double* y) const;
  /// Energies at y, given `states` = contact_states(y) (evaluated once for both); the Hertz
  /// contacts' energies are added here.
  Energies energies(const double* y, const std::vector<ContactState>& states) const;
  /// Hertz's law between rigid spheres, each contact's state at y.
  const std::vector<HertzContact>& hertz_contacts() const { return hertz_; }
  std::vector<ContactState> hertz_states(const double* y) const;

  const std::vector<std::unique_ptr<FloatingBody>>& bodies() const { return bodies_; }
  const std::vector<SurfaceContact>& contacts() const { return contacts_; }
  const JointConstraints& joints() const { return *joints_; }
  /// Joint reactions at y (world force and torque on each joint's first side), with the
  /// joints' position and orientation errors: runs the right-hand side once.
  struct JointState {
    Eigen::Vector3d force, torque;
    double position_error = 0, angle_error = 0;
  };
  std::vector<JointState> joint_states(const double* y) const;
  /// The Hertz estimate of each contact's impact from the initial state (none where the
  /// bodies do not approach or the contact is not of Hertz type).
  const std::vector<std::optional<ImpactEstimate>>& impact_estimates() const { return impact_estimates_; }
  const FloatingBody& body(const std::string& name) const;
  /// Position of a body in bodies() (refused as input if the scene has none of that name).
  std::size_t body_index(const std::string& name) const;
  /// What the user should know about the set-up (e.g. hundreds of dynamically integrated modes).
  std::vector<RunWarning> warnings() const;
  /// The Hertz estimate of every contact at state y (impact_estimates()), each contact's
  /// penalty decided from it (contact/penalty_decision.hpp) and the resolution warnings: at the
  /// initial state, and again where a later phase of a run starts (an impact long after t = 0).
  void estimate_impacts(const double* y);
  /// Newton iterations of the quasistatic modes so far.
  long quasistatic_iterations() const { return quasistatic_iterations_; }
  /// Their passes over the contact points so far (QuasistaticModes::passes()).
  long quasistatic_passes() const { return quasistatic_ ? quasistatic_->passes() : 0; }
  /// Where the right-hand side's time went so far (bench/cost_model.py sets it against the
  /// work the evaluations cannot avoid).
  struct RhsCost {
    long evaluations = 0;
    long repeated = 0;       ///< evaluations at the state of the one before, answered from it
    long active_points = 0;  ///< contact points carrying load, summed over the evaluations
    long kept_contact_loads = 0;  ///< contact evaluations loaded from the static solve's points (ContactState)
    double static_solve_s = 0, contacts_s = 0, joints_s = 0, floating_frame_s = 0;
  };
  const RhsCost& rhs_cost() const { return cost_; }

  /// More dynamically integrated modes than this in one body draw a warning.
  static constexpr Eigen::Index kManyDynamicModes = 200;

private:
  /// Refuses a contact on a massless-boundary body whose surface the boundary does not carry alone.
  static void require_boundary_covers(const SurfaceContact& c, const FloatingBody* target, const std::string& target_surface);
  /// Refuses exact contact on a surface whose points move with integrated coordinates.
  static void require_massless_points(const SurfaceContact& c);
  void warn_of_many_dynamic_modes(const FloatingBody& body, const BodySpec& spec);
  /// Solves every body's quasistatic modes for state y (they depend on the contacts).
  void update_quasistatic(const double* y) const;

  std::vector<std::unique_ptr<FloatingBody>> bodies_;
  std::vector<std::unique_ptr<ContactTarget>> targets_;
  std::vector<SurfaceContact> contacts_;
  std::vector<HertzContact> hertz_;
  std::vector<std::array<std::size_t, 2>> hertz_bodies_;  ///< body indices of each Hertz contact's spheres
  std::vector<SurfaceTouch> touches_;         ///< per contact: its exact surfaces
  /// Armed: the touch gap is a root function; Found: held at 1 until the contact opens;
  /// Separating: opened, held at 1 until the surfaces are apart (then armed without a jump
  /// through zero); Unavailable: no exact slave surface.
  enum class TouchState { Armed, Found, Separating, Unavailable };
  mutable std::vector<TouchState> touch_state_;
  std::vector<std::size_t> slave_body_;    ///< body index of each contact's slave
  std::vector<long> target_body_;          ///< body index of each contact's target, -1: fixed
  std::unique_ptr<QuasistaticModes> quasistatic_;
  std::unique_ptr<JointConstraints> joints_;
  Eigen::Vector3d gravity_;
  Eigen::Index size_ = 0;
  mutable std::vector<GeneralizedForce> forces_;
  mutable long quasistatic_iterations_ = 0;
  mutable RhsCost cost_;
  mutable Eigen::VectorXd rhs_y_, rhs_ydot_;  ///< the last rhs() call's state and result
  mutable long rhs_active_points_ = 0;        ///< and its loaded contact points
  mutable bool rhs_valid_ = false;            ///< the call completed
  mutable Eigen::VectorXd solved_y_;          ///< the state the quasistatic modes were last solved for
  mutable bool solved_valid_ = false;         ///< that solve completed
  std::vector<RunWarning> warnings_;
  std::vector<RunWarning> resolution_warnings_;  ///< of the last estimate_impacts
  std::vector<std::optional<ImpactEstimate>> impact_estimates_;
  std::string scene_file_;  ///< for the penalty's errors
  GivenPenalties given_penalties_;
  std::vector<double> penalty_contact_radius_;  ///< per contact: of its latest estimate, m (0: none yet)
};

}  // namespace isosid::run
