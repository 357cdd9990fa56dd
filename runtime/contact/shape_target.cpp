// Analytic contact targets; see shape_target.hpp.
#include "contact/shape_target.hpp"

namespace isosid::run {

void ShapeTarget::update(const double* y) const {
  if (!body_) return;
  A_ = body_->orientation(y).toRotationMatrix();
  r_ = body_->r(y);
}

double ShapeTarget::clearance(const Eigen::Vector3d& center, double radius) const {
  // the signed distance is 1-Lipschitz: no point of the ball comes closer than this
  return shape_distance(shape_, A_.transpose() * (center - r_)).gap - radius;
}

bool ShapeTarget::project(const Eigen::Vector3d& x, const double* y, TargetPoint& out, Eigen::Vector2d&, Fill fill) const {
  const ShapeDistance d = shape_distance(shape_, A_.transpose() * (x - r_));
  out.gap = d.gap;
  out.normal = A_ * d.normal;
  if (fill != Fill::Loads) return true;
  out.body_point = d.point;
  if (body_) {
    out.Psi.resize(body_->sid().dim(), 0);
    out.velocity = body_->point_velocity(d.point, out.Psi, y);
  } else {
    out.velocity.setZero();
  }
  return true;
}

bool ShapeTarget::fixed_plane(Eigen::Vector3d& normal, double& offset) const {
  if (body_ || shape_.kind != ShapeSpec::Kind::Plane) return false;
  normal = shape_.normal;
  offset = shape_.normal.dot(shape_.point);
  return true;
}

Eigen::Vector2d ShapeTarget::curvatures(const Eigen::Vector3d&) const {
  switch (shape_.kind) {
    case ShapeSpec::Kind::Sphere: return Eigen::Vector2d::Constant(1 / shape_.radius);
    case ShapeSpec::Kind::Cylinder: return {1 / shape_.radius, 0.0};  // across its axis, and along it
    case ShapeSpec::Kind::Plane:
    case ShapeSpec::Kind::Box: break;  // flat faces
  }
  return Eigen::Vector2d::Zero();
}

ShapeSpec rigid_body_shape(const BodySpec& body) {
  ShapeSpec s;
  s.name = body.name;
  s.kind = body.rigid->kind == RigidShape::Kind::Sphere ? ShapeSpec::Kind::Sphere : ShapeSpec::Kind::Box;
  s.radius = body.rigid->radius;
  s.half_extents = body.rigid->half_extents;
  return s;
}

}  // namespace isosid::run
