// A flexible body's master patch as a contact target: slave points are projected onto the
// deformed NURBS (closest point by Newton's method, warm-started per slave point from its
// last projection), and the reaction goes to the master's frame and elastic coordinates.
#pragma once
#include "contact/contact_target.hpp"
#include "contact/deformed_patch.hpp"

namespace isosid::run {

class MasterPatchTarget : public ContactTarget {
public:
  /// `surface`: the contact surface of `body`'s SID whose master patch is the target.
  MasterPatchTarget(const FloatingBody& body, const std::string& surface, const std::string& contact_name);

  const std::string& name() const override { return name_; }
  const FloatingBody* body() const override { return &body_; }
  void update(const double* y) const override;
  double clearance(const Eigen::Vector3d& center, double radius) const override;
  bool project(const Eigen::Vector3d& x, const double* y, TargetPoint& out, Eigen::Vector2d& hint, Fill fill) const override;
  void fill_loads(const double* y, TargetPoint& out) const override;
  Eigen::Vector2d curvatures(const Eigen::Vector3d& x) const override;
  /// max_i |Phi_i|_F: the patch lies in its control net's convex hull
  double displacement_bound() const override { return patch_.largest_row_norm(); }
  const format::MasterPatch* master_patch() const override { return &patch_.patch(); }
  bool carriers(std::vector<int>& control_points, std::vector<double>& basis) const override;

private:
  /// The outward unit normal at an evaluated point (body frame).
  Eigen::Vector3d normal(const DeformedPatch::Point& point, const Eigen::Vector2d& u) const;

  const FloatingBody& body_;
  std::string name_;
  int dim_;
  double orientation_ = 1;    ///< +1 or -1: makes the parametric normal point out of the body
  mutable DeformedPatch patch_;
  mutable DeformedPatch::Point point_;
  mutable Eigen::Matrix3d A_ = Eigen::Matrix3d::Identity();
  mutable Eigen::Vector3d r_ = Eigen::Vector3d::Zero();
  mutable Eigen::Vector3d center_ = Eigen::Vector3d::Zero();  ///< bounding sphere of the net, body frame
  mutable double radius_ = 0;
};

}  // namespace isosid::run
