// What a scene says of a body (scene/scene.hpp holds them all): the body room's input, read
// by scene/scene_file and turned into a FloatingBody by the system.
#pragma once
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

namespace isosid::run {

/// The scene's analysis: planar, axisymmetric or 3D solid.
enum class Dimension { Planar, Axisymmetric, Solid };
/// "planar", "axisymmetric" or "3d", as scene files say.
std::string to_string(Dimension d);

/// The shape and inertia of a rigid body (its frame at the centre of mass, on the principal axes).
struct RigidShape {
  enum class Kind { Sphere, Box } kind = Kind::Sphere;
  double radius = 0;                                          ///< m, sphere
  Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();     ///< m, box
  double mass = 0;                                            ///< kg
  Eigen::Vector3d principal_inertia = Eigen::Vector3d::Zero();  ///< kg m^2
};

/// A body of the scene: flexible (from a SID) or rigid (`rigid` set, no SID).
struct BodySpec {
  std::string name;
  std::optional<RigidShape> rigid;
  std::string sid_file;         ///< flexible: absolute or relative to the scene file, resolved
  std::string model_file;       ///< optional: rebuild the SID from it when missing or stale
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d tait_bryan = Eigen::Vector3d::Zero();  ///< rad, x-y-z ([R1] eq. 20, docs/references.md)
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();    ///< m/s, world frame
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< rad/s, body frame
  Eigen::VectorXd q0, qdot0;    ///< initial elastic state (empty: zero)
  std::vector<std::string> locked;  ///< extra locked DOFs: x y z rx ry rz
  /// How the high-frequency modes move: "dynamic" (integrated, damped by De) or
  /// "quasistatic" (solved from the static sub-problem each evaluation; [R2]).
  std::string high_modes = "dynamic";
  double quasistatic_above_hz = -1;  ///< > 0: modes above this frequency are the high ones
  /// "rest": q0 (or zero); "steady": the integrated modes start in equilibrium with the
  /// initial spin (centrifugal deformation), so a spinning body does not start ringing;
  /// "static": in their static deflection under everything acting at the start, the frame
  /// moved with it so that the joints hold (solve/static_start; [R2] Sect. 6)
  std::string elastic_start = "rest";
  /// [R2]'s adaptive impacts: the body runs on its model's coarse model between impacts
  /// and on a model refined around each impact during it (needs `model_file`; no `sid_file`)
  bool adaptive = false;
};

}  // namespace isosid::run
