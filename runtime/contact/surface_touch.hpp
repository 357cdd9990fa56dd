// Where and when two bodies first touch ([R2] eq. 7, docs/references.md): the closest approach of a
// contact's exact slave surface, the NURBS of its master patch on the deformed control net, to the
// target, minimizing the target's signed distance over the patch's parameters. Unlike the
// contact's Gauss points, the exact surfaces touch at one point at one time: the impact's
// time and its location in each body's parameter space (the root of this gap in time).
#pragma once
#include "contact/deformed_patch.hpp"
#include "contact/surface_contact.hpp"

#include <array>
#include <memory>

namespace isosid::run {

/// The closest approach of the two surfaces at one state.
struct Touch {
  double gap = INFINITY;  ///< m, signed: negative where the slave surface reaches into the target
  Eigen::Vector2d slave_parameter = Eigen::Vector2d::Constant(NAN);   ///< on the slave's master patch
  Eigen::Vector2d target_parameter = Eigen::Vector2d::Constant(NAN);  ///< on a flexible target's patch (else NaN)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();                    ///< world point of the slave surface, m
  int parameter_dim = 0;  ///< parameters of the patches (1: curves of 2D sections, 2: surfaces)
};

class SurfaceTouch {
public:
  /// The slave surface of `contact`: the master patch its SID gives for the contact surface
  /// (available() is false without one), searched over the parameters of the surface's Gauss
  /// points where it is an interval of one patch side.
  explicit SurfaceTouch(const SurfaceContact& contact);

  bool available() const { return patch_ != nullptr; }
  /// The closest approach at state y (the bodies' quasistatic modes as last solved), by
  /// Newton's method on the distance's parametric gradient, warm-started from the last call.
  const Touch& evaluate(const double* y) const;
  /// A lower bound of the closest approach at state y, from the slave patch's bounding sphere
  /// (its control net's, grown by its displacement bound) and the target's broad phase:
  /// where it is positive, the exact search need not run to know the surfaces are apart. The
  /// search has then lost track of its minimum: its next evaluate() starts from its grid.
  double clearance(const double* y) const;

private:
  /// Brings the target and the deformed slave patch to state y, and the slave's frame (A_, r_).
  void place(const double* y) const;
  /// The target's signed distance to the slave surface at parameter u, with its gradient
  /// along u; false where the target sees no candidate there.
  bool distance(const double* y, const Eigen::Vector2d& u, double& gap, Eigen::Vector2d& gradient) const;
  /// The start grid's parameter of least gap; false where the target sees none of them.
  bool grid_start(const double* y, Eigen::Vector2d& u) const;
  /// Newton's method from u to the nearest minimum of the gap within the search's bounds;
  /// returns the gap there (INFINITY if the target does not see it), u and its gradient.
  double descend(const double* y, Eigen::Vector2d& u, Eigen::Vector2d& gradient) const;
  /// u lies on a bound of the search and the gap falls beyond it.
  bool held_by_bound(const Eigen::Vector2d& u, const Eigen::Vector2d& gradient) const;

  const SurfaceContact& contact_;
  std::unique_ptr<DeformedPatch> patch_;
  int dim_ = 3;
  std::array<int, 2> grid_{9, 9};  ///< the start grid's points per parameter direction
  Eigen::Vector2d lower_ = Eigen::Vector2d::Zero(), upper_ = Eigen::Vector2d::Ones();  ///< the parameters searched
  mutable DeformedPatch::Point point_;
  mutable TargetPoint target_point_;
  mutable Eigen::Vector2d target_hint_ = Eigen::Vector2d::Constant(NAN);  ///< the target's projection warm start
  mutable Eigen::Vector2d last_parameter_ = Eigen::Vector2d::Constant(NAN);  ///< the slave's, from the last call
  mutable Eigen::Matrix3d A_ = Eigen::Matrix3d::Identity();
  mutable Eigen::Vector3d r_ = Eigen::Vector3d::Zero();
  mutable Touch touch_;
};

}  // namespace isosid::run
