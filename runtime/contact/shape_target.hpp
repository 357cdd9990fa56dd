// A contact target with an analytic surface: fixed in the world (plane, sphere, cylinder) or
// carried by a rigid body (sphere, box in the body frame).
#pragma once
#include "contact/contact_target.hpp"
#include "contact/shape.hpp"

namespace isosid::run {

class ShapeTarget : public ContactTarget {
public:
  /// A fixed surface (shape in world coordinates).
  explicit ShapeTarget(const ShapeSpec& shape) : shape_(shape) {}
  /// The surface of a rigid body (shape in the body frame).
  ShapeTarget(const ShapeSpec& shape, const FloatingBody& body) : shape_(shape), body_(&body) {}

  const std::string& name() const override { return shape_.name; }
  const FloatingBody* body() const override { return body_; }
  void update(const double* y) const override;
  double clearance(const Eigen::Vector3d& center, double radius) const override;
  bool project(const Eigen::Vector3d& x, const double* y, TargetPoint& out, Eigen::Vector2d& hint, Fill fill) const override;
  Eigen::Vector2d curvatures(const Eigen::Vector3d& x) const override;
  bool fixed_plane(Eigen::Vector3d& normal, double& offset) const override;

private:
  ShapeSpec shape_;
  const FloatingBody* body_ = nullptr;
  mutable Eigen::Matrix3d A_ = Eigen::Matrix3d::Identity();  ///< pose at the last update
  mutable Eigen::Vector3d r_ = Eigen::Vector3d::Zero();
};

/// The surface of a rigid body as a shape in its frame.
ShapeSpec rigid_body_shape(const BodySpec& body);

}  // namespace isosid::run
