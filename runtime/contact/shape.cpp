// Signed distances to analytic solids; see shape.hpp.
#include "contact/shape.hpp"

#include <cmath>

namespace isosid::run {

namespace {

ShapeDistance to_round_surface(const Eigen::Vector3d& radial, const Eigen::Vector3d& x, double radius,
                               const Eigen::Vector3d& fallback_normal) {
  // radial: x minus its closest point on the centre (point or axis)
  ShapeDistance d;
  const double r = radial.norm();
  d.normal = r > 0 ? Eigen::Vector3d(radial / r) : fallback_normal;  // at the centre any direction is closest
  d.gap = r - radius;
  d.point = x - d.gap * d.normal;
  return d;
}

ShapeDistance to_box(const ShapeSpec& box, const Eigen::Vector3d& x) {
  ShapeDistance d;
  const Eigen::Vector3d local = x - box.point, h = box.half_extents;
  const Eigen::Vector3d outside = (local.cwiseAbs() - h).cwiseMax(0.0);
  if (outside.squaredNorm() > 0) {  // outside: the clamped point is the closest one
    const Eigen::Vector3d clamped = local.cwiseMax(-h).cwiseMin(h);
    d.gap = (local - clamped).norm();
    d.normal = (local - clamped) / d.gap;
    d.point = box.point + clamped;
    return d;
  }
  // inside: the nearest face
  Eigen::Index axis = 0;
  (h - local.cwiseAbs()).minCoeff(&axis);
  const double side = local(axis) >= 0 ? 1.0 : -1.0;
  d.gap = std::abs(local(axis)) - h(axis);
  d.normal = Eigen::Vector3d::Unit(axis) * side;
  d.point = x - d.gap * d.normal;
  return d;
}

}  // namespace

ShapeDistance shape_distance(const ShapeSpec& shape, const Eigen::Vector3d& x) {
  switch (shape.kind) {
    case ShapeSpec::Kind::Plane: {
      ShapeDistance d;
      d.normal = shape.normal;
      d.gap = shape.normal.dot(x - shape.point);
      d.point = x - d.gap * d.normal;
      return d;
    }
    case ShapeSpec::Kind::Sphere: return to_round_surface(x - shape.point, x, shape.radius, Eigen::Vector3d::UnitY());
    case ShapeSpec::Kind::Cylinder: {
      const Eigen::Vector3d rel = x - shape.point;
      const Eigen::Vector3d radial = rel - shape.normal.dot(rel) * shape.normal;
      return to_round_surface(radial, x, shape.radius, shape.normal.unitOrthogonal());
    }
    case ShapeSpec::Kind::Box: return to_box(shape, x);
  }
  return {};
}

}  // namespace isosid::run
