// Gauss-point penalty contact of a flexible body's contact surface against a fixed plane
// (seed 000 eq. 22-25): each point below the plane carries the force c_p |g| w n, with
// regularized Coulomb friction opposing its sliding velocity.
#pragma once
#include "body/flexible_body.hpp"
#include "scene/scene.hpp"

namespace isosid::run {

/// What one evaluation of a contact found.
struct ContactState {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  ///< total force on the body, world frame, N
  int active_points = 0;
  double max_penetration = 0;   ///< m (positive)
  double penalty_energy = 0;    ///< J, sum of 1/2 c_p g^2 w over active points
  double friction_power = 0;    ///< W dissipated by friction (>= 0)
};

class PlaneContact {
public:
  PlaneContact(const ContactSpec& spec, const FlexibleBody& body, const PlaneSpec& plane);

  const std::string& name() const { return spec_.name; }
  const FlexibleBody& body() const { return body_; }
  /// Adds the contact forces to the body's generalized forces; returns what was found.
  ContactState apply(const double* y, GeneralizedForce& f) const;
  /// For the body's quasistatic modes (indices first..nq-1): adds their generalized contact
  /// forces Psi_h^T F_K to `force` and -d(Psi_h^T F_K)/dq_h (the contact stiffness, incl. the
  /// normal-force dependence of friction) to `stiffness`, at the body's current mode values.
  void add_quasistatic_terms(const double* y, Eigen::Index first, Eigen::VectorXd& force, Eigen::MatrixXd& stiffness) const;
  /// Penalty energy sum 1/2 c_p g^2 w at y (with the body's current quasistatic modes).
  double penalty_energy(const double* y) const;
  bool frictionless() const { return spec_.friction == 0; }
  /// Smallest signed gap over the contact points (negative: penetration), for event location.
  double min_gap(const double* y) const;

private:
  /// Calls f(g, Psi_g, P, gap, A) for every contact point: body-frame position P, signed gap.
  template <class F>
  void for_each_point(const double* y, F&& f) const;
  /// World velocity of a contact point along the plane.
  Eigen::Vector3d sliding_velocity(const Eigen::Vector3d& P, const Eigen::Ref<const Eigen::MatrixXd>& Psi, const double* y) const;
  /// Regularized Coulomb friction force per unit normal force: -mu vt / sqrt(|vt|^2 + eps^2),
  /// mu in the direction opposing sliding, linear below the regularization velocity eps.
  Eigen::Vector3d friction_per_normal_force(const Eigen::Vector3d& vt) const;

  ContactSpec spec_;
  const FlexibleBody& body_;
  const format::ContactSurface& surface_;
  PlaneSpec plane_;
  int dim_;
};

}  // namespace isosid::run
