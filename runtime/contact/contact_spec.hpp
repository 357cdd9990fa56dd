// What a scene says of its contacts and fixed surfaces (scene/scene.hpp holds them all): the
// contact room's input, read by scene/scene_interactions and turned into contacts by the system.
#pragma once
#include <Eigen/Dense>
#include <array>
#include <string>

namespace isosid::run {

/// An analytic surface: fixed in the world, or the surface of a rigid body (in its frame).
struct ShapeSpec {
  enum class Kind { Plane, Sphere, Cylinder, Box } kind = Kind::Plane;
  std::string name;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    ///< plane: a point; sphere: centre; cylinder: a point on the axis
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  ///< plane: unit, pointing out of the solid; cylinder: unit axis
  double radius = 0;                                  ///< sphere, cylinder, m
  Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();  ///< box (centred on point, axis-aligned), m
};

/// A contact's penalty factor and where it comes from (summary.json's penalty_source). The
/// system decides it once per run (contact/penalty_decision.hpp); a caller may give one for a
/// run in place of the scene's (the adaptive loop's penalty search).
struct ContactPenalty {
  double value = 0;    ///< N/m^3
  std::string source;  ///< "scene", the rule that derived it, or the caller's reason
};

struct ContactSpec {
  std::string name;
  std::string body, surface;    ///< slave: a flexible body and a contact surface of its SID
  std::string target;           ///< master: a fixed surface, a rigid body or a flexible body
  std::string target_surface;   ///< flexible master: the contact surface whose master patch is used
  double penalty = 0;           ///< N/m^3 (the law's stiffness); 0: derived (default_penalty)
  double friction = 0;          ///< Coulomb coefficient
  double regularization = 1e-6; ///< m/s, velocity below which friction is regularized
  /// The contact on a massless boundary solved exactly (augmented Lagrangian: the penalty
  /// becomes the augmentation, the gap of every active point closes); else penalty contact.
  bool exact = false;
  /// Solved in gap space (condensation/gap_space_solve.hpp): the points paired once per impact,
  /// the quasistatic modes condensed onto their gaps; else every point projected at every pass.
  bool gap_space = false;
  std::string law = "penalty";  ///< the normal law's name in contact/contact_law.cpp's table
};

/// Hertz's law between two rigid spheres (contact/hertz_contact.hpp): [R2]'s reference
/// for sphere impacts, with each sphere's material.
struct HertzContactSpec {
  std::string name;
  std::string body, target;  ///< rigid spheres
  std::array<double, 2> youngs_modulus{}, poisson_ratio{};  ///< Pa, 1: of body and target
};

}  // namespace isosid::run
