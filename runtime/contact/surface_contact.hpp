// Gauss-point penalty contact ([R1] eq. 22-25, docs/references.md) of a flexible body's contact
// surface (the slave) against a target: a fixed surface, a rigid body or another flexible body's
// master patch. Each slave point that penetrates the target carries its contact law's pressure
// (contact/contact_law.hpp; the penalty law's c_p |g|) over its weight w along the target's
// normal plus regularized Coulomb friction against the relative sliding velocity; body targets
// receive the reaction. A bounding-sphere broad phase skips the whole surface while it is clear
// of the target. Exact contact on a massless boundary ([R3]) is the augmented Lagrangian: each
// point carries the pressure max(0, lambda - c_p g) with a multiplier lambda that the static
// solve updates (Uzawa) until the active gaps close.
#pragma once
#include "body/floating_body.hpp"
#include "condensation/gap_pairing.hpp"
#include "condensation/quasistatic_terms.hpp"
#include "contact/contact_law.hpp"
#include "contact/contact_target.hpp"
#include "contact/gap_bounds.hpp"
#include "contact/contact_spec.hpp"

#include <algorithm>
#include <memory>
#include <vector>

namespace isosid::run {

/// What one evaluation of a contact found.
struct ContactState {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  ///< total force on the slave body, world frame, N
  int active_points = 0;
  double max_penetration = 0;   ///< m (positive)
  double penalty_energy = 0;    ///< J, the contact law's energy of the penetration over active points
  double friction_power = 0;    ///< W dissipated by friction (>= 0)
  int edge_points = 0;          ///< active points in the surface's edge elements (surface_edge.hpp)
  int outside_interface = 0;    ///< active points a Craig-Bampton interface does not cover (normal modes alone move them)
  bool from_static_solve = false;  ///< loaded from the static solve's points, without a pass over the surface
};

/// One loaded contact point (for viewing): where it is and what it carries, world frame.
struct PointLoad {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< the deformed slave point, m
  Eigen::Vector3d force = Eigen::Vector3d::Zero();     ///< on the slave, N (normal and friction)
  double pressure = 0;                                 ///< Pa
  double gap = 0;                                      ///< m (negative: penetration)
};

class SurfaceContact {
public:
  SurfaceContact(const ContactSpec& spec, const FloatingBody& body, const ContactTarget& target);

  const std::string& name() const { return spec_.name; }
  const FloatingBody& body() const { return body_; }
  const ContactTarget& target() const { return target_; }
  const format::ContactSurface& surface() const { return surface_; }
  /// Adds the contact forces to the slave's generalized forces and their reactions to the
  /// target body's (`target_force`, unused for fixed targets); returns what was found.
  ContactState apply(const double* y, GeneralizedForce& slave_force, GeneralizedForce* target_force) const;
  /// Records every point of this contact that presses on the quasistatic modes of the slave
  /// or target body at y, or is free by less than what terms.window and terms.reach allow,
  /// with its gap linearized in those modes (nothing if neither body has quasistatic modes).
  /// Penalty contact keeps the recorded points with their target points: apply() at the same
  /// state and quasistatic coordinates loads them without another pass over the surface.
  void add_quasistatic_terms(const double* y, QuasistaticTerms& terms) const;
  /// The static solve moved the quasistatic coordinates to the solution of the linear model
  /// of `terms`, which is exact against fixed planes: the kept points take the model's gaps
  /// and hold for the coordinates now set.
  void take_model_gaps(const double* y, const QuasistaticTerms& terms) const;
  /// The points that carry load at y, as apply() loads them (from the static solve's
  /// recorded points where they hold, as apply() does).
  std::vector<PointLoad> point_loads(const double* y) const;
  bool frictionless() const { return spec_.friction == 0; }
  /// What the scene gave for this contact.
  const ContactSpec& spec() const { return spec_; }
  /// Penalty factor, N/m^3, as the system decided it (contact/penalty_decision.hpp).
  double penalty() const { return penalty_.value; }
  /// Where the penalty came from: "scene", the rule that derived it, or the caller's reason.
  const std::string& penalty_source() const { return penalty_.source; }
  /// Takes the penalty the system decided and builds the law of it. A contact has no law until
  /// then: the decision needs the impact's estimate, which needs the contact.
  void set_penalty(ContactPenalty penalty);
  /// The normal law, of the penalty's stiffness.
  const ContactLaw& law() const { return *law_; }
  /// Its name in the table of laws (the scene's `law`).
  const std::string& law_name() const { return spec_.law; }
  /// Smallest signed gap over the contact points (negative: penetration; exact contact: the
  /// gap less lambda / c_p, negative while pressed), for event location; while the broad phase
  /// finds the surface clear, a positive lower bound.
  double min_gap(const double* y) const;

  /// Solved in gap space (condensation/gap_space_solve.hpp): its points paired once per impact.
  bool gap_space() const { return spec_.gap_space; }
  /// The pairing of a gap-space contact (its solve pairs and releases it); while paired, the
  /// loads, points and gaps come from its pairs.
  GapPairing& gap_pairing() const { return *pairing_; }

  /// Exact contact (augmented Lagrangian) rather than penalty.
  bool exact() const { return spec_.exact; }
  /// Uzawa update of the exact contact's multipliers at y: lambda <- max(0, lambda - c_p g)
  /// per point. Returns how far the constraints were from holding at y, m: the largest gap of
  /// a pressed point or penetration of a free one.
  double update_multipliers(const double* y) const;

private:
  /// Exact contact's multiplier of point g, Pa (penalty contact: 0).
  double multiplier(Eigen::Index g) const { return spec_.exact ? multiplier_[std::size_t(g)] : 0.0; }
  /// Contact pressure of point g at gap `gap`, Pa: the law's, with its multiplier.
  double pressure(Eigen::Index g, double gap) const { return law_->pressure(gap, multiplier(g)); }

  /// Calls f(g, Psi_g, P, A, target point) for every slave point that is a candidate:
  /// Psi_g its shape rows, P its body-frame position, A the slave's rotation; the target
  /// point filled as `fill` asks. Returns the broad-phase clearance (> 0: no point was visited).
  /// Every candidate: for callers that need all gaps (the root functions must be continuous).
  template <class F>
  double for_each_point(const double* y, ContactTarget::Fill fill, F&& f) const;
  /// The candidates that matter to a caller that ignores a point whose gap is at or beyond
  /// `beyond(g)` (penalty loads: 0): points the gap bounds put there are left out unprojected
  /// (contact/gap_bounds.hpp, or against a fixed plane the undeformed gap less |Psi_g| |q|;
  /// not for exact contact, whose multipliers press at positive gaps), and so are those for
  /// which skip(g) holds. Where leaving them out would cost more than placing them (most of a
  /// plane's points), they are passed all the same: f must apply its own test.
  template <class F, class Beyond, class Skip>
  double for_each_point(const double* y, ContactTarget::Fill fill, F&& f, Beyond&& beyond, Skip&& skip) const;
  /// Calls f(g, Psi_g, P, A, target point) as for_each_point() does, for the points that press
  /// at y: from the static solve's recorded points where they hold for y and the quasistatic
  /// coordinates now set (then returns true), else from a pass over the surface.
  template <class F>
  bool for_each_pressed(const double* y, F&& f) const;
  /// What the poses and integrated coordinates of both bodies are at y: the quasistatic solve
  /// evaluates its terms many times at one y, changing only the quasistatic coordinates.
  void pose_key(const double* y, Eigen::VectorXd& key) const;
  /// Both bodies' states at y (poses, velocities, integrated coordinates) followed by their
  /// quasistatic coordinates as set now.
  void solution_key(const double* y, Eigen::VectorXd& key) const;
  /// The world force on slave point g at pressure p: normal, plus friction against the
  /// sliding velocity `vt` it returns (zero without friction).
  Eigen::Vector3d point_force(Eigen::Index g, double p, const Eigen::Ref<const Eigen::MatrixXd>& Psi, const Eigen::Vector3d& P,
                              const double* y, const TargetPoint& t, Eigen::Vector3d& vt) const;
  /// Regularized Coulomb friction force per unit normal force: -mu vt / sqrt(|vt|^2 + eps^2).
  Eigen::Vector3d friction_per_normal_force(const Eigen::Vector3d& vt) const;
  /// P (body frame, its first dim components) = point g's position X_g + Psi_g q, from its
  /// transposed rows.
  void place(Eigen::Index g, const Eigen::VectorXd& q, Eigen::Vector3d& P) const;
  /// World velocity of a slave point relative to the target, along the target's surface; with
  /// Psi of no columns, of the slave's frame motion only (its rigid-body sliding).
  Eigen::Vector3d sliding_velocity(const Eigen::Vector3d& P, const Eigen::Ref<const Eigen::MatrixXd>& Psi, const double* y,
                                   const TargetPoint& t) const;

  /// min_gap() over the points as the general path finds them.
  double unpaired_min_gap(const double* y) const;
  /// Calls f as for_each_pressed() does for the pressed pairs of the gap-space pairing.
  template <class F>
  void for_each_pressed_pair(const double* y, F&& f) const;

  ContactSpec spec_;            ///< as the scene gave it (the penalty's state is penalty_)
  std::unique_ptr<ContactLaw> law_;
  /// Laws a later decision replaced: a recording of the quasistatic terms points at its points'
  /// laws until its next pass, so they stay alive (the system decides again where a later phase
  /// of a run starts).
  std::vector<std::unique_ptr<ContactLaw>> superseded_laws_;
  std::unique_ptr<GapPairing> pairing_;  ///< gap-space contacts
  mutable Eigen::VectorXd min_gap_key_, last_min_gap_key_;  ///< gap space: solution_key() of the last unpaired min_gap()
  mutable double last_min_gap_ = 0;
  ContactPenalty penalty_;      ///< as the system decided it
  const FloatingBody& body_;
  const ContactTarget& target_;
  const format::ContactSurface& surface_;
  int dim_;
  Eigen::Vector3d bound_center_ = Eigen::Vector3d::Zero();  ///< slave bounding sphere (reference, body frame)
  double bound_radius_ = 0;
  std::vector<char> edge_;                       ///< per point: in an edge element of the surface
  mutable std::vector<Eigen::Vector2d> hints_;  ///< warm starts of the target projections
  mutable std::vector<double> multiplier_, updated_;  ///< exact contact: lambda per point, Pa
  mutable TargetPoint point_;
  mutable Eigen::VectorXd displacement_;         ///< Psi q of all points
  mutable std::vector<char> left_out_;           ///< per point: left out of the last pass against a fixed plane
  /// Free points of the quasistatic solve at one y: each point's gap at its first evaluation
  /// (-inf: pressed, or not seen), and the poses and quasistatic coordinates it was taken at.
  /// Later evaluations at that y skip a point that the change of the quasistatic coordinates
  /// since cannot close (gaps move by at most the points' displacement bounds).
  mutable std::vector<double> free_gap_;
  mutable std::vector<char> pressed_at_pose_;    ///< per point: pressed at some evaluation of this pose
  mutable std::vector<long> recorded_pass_;      ///< per point: the last add_quasistatic_terms() (pass_) that recorded it
  mutable long pass_ = 0;
  mutable Eigen::VectorXd free_key_, key_, free_z_slave_, free_z_target_;
  /// The points of the last add_quasistatic_terms() (penalty contact), in the order of g:
  /// every point that pressed there or was free within the model's window and reach, so
  /// every point that can press at the solution; if recorded_valid_, at `recorded_key_`
  /// (solution_key()).
  struct RecordedPoint {
    Eigen::Index g = 0;  ///< the slave point
    Eigen::Index k = 0;  ///< its column in the quasistatic terms
    TargetPoint target;  ///< a plane's body_point is that of the recording (no body takes a reaction)
  };
  mutable std::vector<RecordedPoint> recorded_;  ///< the first recorded_count_ are current (capacity kept)
  mutable std::size_t recorded_count_ = 0;
  mutable Eigen::VectorXd recorded_key_, current_key_;
  mutable bool recorded_valid_ = false;
  Eigen::MatrixXd shape_columns_;                ///< Psi transposed (nq x dim points): each point's rows contiguous
  Eigen::VectorXd quasistatic_row_norms_;        ///< per point: the Frobenius norm of its quasistatic rows
  GapBounds bounds_;                             ///< between full evaluations of the points; |Psi_g|_F per point
};

}  // namespace isosid::run
