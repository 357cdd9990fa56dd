// What a scene says of a joint (scene/scene.hpp holds them all): the joint room's input.
#pragma once
#include <Eigen/Dense>
#include <optional>
#include <string>

namespace isosid::run {

/// A joint between a body and another body or the ground ([R2]): both attachments
/// coincide at the joint point; a revolute joint also keeps an axis aligned, a fixed joint the
/// relative orientation.
struct JointSpec {
  enum class Kind { Spherical, Revolute, Fixed } kind = Kind::Spherical;
  std::string name;
  std::string body, node;          ///< first side; a flexible body attaches at a SID node
  std::string other, other_node;   ///< second side; empty `other`: the ground
  std::optional<Eigen::Vector3d> point;  ///< m, world position at t = 0 (needed for a rigid side; default: the node)
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< revolute: unit axis, world, at t = 0
};

}  // namespace isosid::run
