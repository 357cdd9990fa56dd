// The master side of a contact: what the slave's Gauss points are projected on. A fixed
// analytic surface, the surface of a rigid body, or the deformed master patch of a flexible
// body; body targets receive the reaction of every contact force.
#pragma once
#include "body/floating_body.hpp"

#include <vector>

namespace isosid::run {

/// The closest point of a target to a slave point. Velocity, body point and Psi are filled
/// for a caller that applies loads, where the point penetrates (gap < 0: only there does a
/// force act); ContactTarget::fill_loads() adds them for a free point that needs them.
struct TargetPoint {
  double gap = 0;                                       ///< signed distance, m (negative: penetration)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();    ///< world unit normal, out of the target
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();   ///< world velocity of the target's material point
  Eigen::Vector3d body_point = Eigen::Vector3d::Zero(); ///< body targets: the point in the body frame
  Eigen::MatrixXd Psi;                                  ///< body targets: dim x nq shape rows at the point
};

class ContactTarget {
public:
  /// What a projection is for: the gap and normal alone (onset checks, multipliers), also
  /// what the loads of a penetrating point need (velocity, body point, Psi), or the gap alone
  /// of points that may be as far again as the target's size beyond it (the touch search,
  /// whose start points lie up to a grid cell from the surfaces' closest approach).
  enum class Fill { Gap, Loads, Approach };

  virtual ~ContactTarget() = default;
  virtual const std::string& name() const = 0;
  /// The body carrying the target (it receives the reactions), or nullptr for a fixed surface.
  virtual const FloatingBody* body() const { return nullptr; }
  /// Prepares the evaluations at state y (pose, deformed geometry, bounds).
  virtual void update(const double* y) const = 0;
  /// A lower bound of the gap of every point within `radius` of the world point `center`:
  /// > 0 means none of them can touch (the broad phase).
  virtual double clearance(const Eigen::Vector3d& center, double radius) const = 0;
  /// Closest point to the world point x at the state of the last update(). `hint` holds the
  /// warm start of iterative projections (NaN: none yet) and is updated. Returns false when
  /// x is no candidate (far from the target, or beside its edge).
  virtual bool project(const Eigen::Vector3d& x, const double* y, TargetPoint& out, Eigen::Vector2d& hint, Fill fill) const = 0;
  /// Fills the velocity, body point and Psi of `out`, the point of the last project() (a
  /// free point of Fill::Loads, which has them only where it penetrates: the quasistatic
  /// model's points that may close). Targets whose Fill::Loads fills every point do nothing.
  virtual void fill_loads(const double* y, TargetPoint& out) const { (void)y, (void)out; }
  /// Principal curvatures (1/m, positive where convex) of the target at its point nearest
  /// the world point x, at the state of the last update(): for the Hertz estimate of an impact.
  virtual Eigen::Vector2d curvatures(const Eigen::Vector3d& x) const = 0;
  /// How far a target point can move per unit (Euclidean) change of its body's elastic
  /// coordinates, m per [q]; 0 for targets that do not deform.
  virtual double displacement_bound() const { return 0; }
  /// A fixed plane {x : n . x = offset} (n its unit normal out of the target): a slave point's
  /// gap is linear in its position, so the static solve's linearized gaps are exact and the
  /// gaps of all points are one product. False for every other target.
  virtual bool fixed_plane(Eigen::Vector3d& normal, double& offset) const { return (void)normal, (void)offset, false; }
  /// The master patch a flexible target is, or nullptr for targets that are none.
  virtual const format::MasterPatch* master_patch() const { return nullptr; }
  /// The control points of master_patch() that carry the point of the last project() and their
  /// rational basis values there (its Psi = sum basis_i Phi_i). False, the vectors untouched,
  /// for targets without a master patch.
  virtual bool carriers(std::vector<int>& control_points, std::vector<double>& basis) const {
    return (void)control_points, (void)basis, false;
  }
};

}  // namespace isosid::run
