// Signed distance to an analytic solid (half-space, ball, infinite cylinder, box): the gap of
// a contact point, the outward normal and the closest surface point, all in the shape's frame.
#pragma once
#include "contact/contact_spec.hpp"

namespace isosid::run {

struct ShapeDistance {
  double gap = 0;                                       ///< signed: negative inside the solid, m
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();    ///< outward unit normal at the closest point
  Eigen::Vector3d point = Eigen::Vector3d::Zero();      ///< closest surface point
};

/// Signed distance of x to the solid described by `shape` (same frame). The distance is
/// 1-Lipschitz in x, which the broad phase relies on.
ShapeDistance shape_distance(const ShapeSpec& shape, const Eigen::Vector3d& x);

}  // namespace isosid::run
