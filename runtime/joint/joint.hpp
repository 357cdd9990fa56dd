// One joint of the scene as constraint rows on the bodies' accelerations ([R2],
// docs/references.md): the two attachments coincide (3 translational rows); a revolute joint keeps
// its axis aligned (2 rotational rows across the axis), a fixed joint the relative orientation (3
// rows). Each row is held at the acceleration level with Baumgarte stabilization,
// c'' + 2 a c' + a^2 c = 0, so drift decays at the rate a instead of growing.
//
// On a body with quasistatic modes the joint sees the integrated modes only: the quasistatic
// ones are solved from the contacts each evaluation and carry no inertia, so a joint load on
// them would turn the constraint rows into algebraic loops. They are the high modes and the
// contact interval's constraint modes of an adaptive body ([R2]): local to the contact,
// while the joint sits away from it. Their displacement at the node is left out.
#pragma once
#include "body/floating_body.hpp"
#include "joint/joint_spec.hpp"

#include <array>
#include <memory>
#include <vector>

namespace isosid::run {

/// Where a joint holds on to a body: a point of its frame (a SID node's position and its
/// translational and rotational mode shapes for a flexible body), or a world point (ground).
struct JointAttachment {
  const FloatingBody* body = nullptr;  ///< null: the ground
  std::size_t index = 0;               ///< the body's index in the system
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< body frame reference position (ground: world)
  Eigen::MatrixXd phi, psi;            ///< 3 x nq translational and rotational shapes at the point
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< revolute: the axis in the attachment's frame
};

/// Kinematics of one attachment at a state: world position, velocity, the part of the
/// acceleration that does not depend on the body's accelerations, angular velocity and the
/// analogous part of the angular acceleration, and the attachment's rotation.
struct AttachmentMotion {
  Eigen::Vector3d x, v, a_known, w, alpha_known;
  Eigen::Matrix3d R;  ///< world orientation of the attachment's frame (body frame and small node rotation)
};

/// A joint's row directions (world, 3 x rows()) and a value per row: at most six rows, on the
/// stack (the joints are solved at every evaluation, which must not allocate).
using JointDirections = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 6>;
using JointRows = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;

/// What a joint's rows need of a state, formed once per evaluation (the reactions' assembly
/// asks for the rows of every side many times at one state): each side's body rotation and
/// attachment point in the body frame, and the row directions (world, 3 x rows()).
struct JointPose {
  std::array<Eigen::Matrix3d, 2> A{Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity()};
  std::array<Eigen::Vector3d, 2> s_now{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  JointDirections D;
};

class Joint {
public:
  /// `bodies` in system order, `y0` the initial state (fixes the attachments and, for a fixed
  /// joint, the relative orientation to keep). Throws InputError (naming `scene_file`) when the
  /// attachments do not coincide at t = 0 or a body has quasistatic modes.
  Joint(const JointSpec& spec, const std::vector<std::unique_ptr<FloatingBody>>& bodies, const double* y0,
        const std::string& scene_file);

  const std::string& name() const { return name_; }
  int rows() const { return 3 + int(rotation_rows_); }
  const JointAttachment& side(int s) const { return sides_[std::size_t(s)]; }
  bool grounded() const { return sides_[1].body == nullptr; }

  AttachmentMotion motion(int s, const double* y) const;
  /// The sides' rotations, attachment points and row directions at y.
  JointPose pose(const double* y) const;
  /// Row directions at y (world, 3 x rows(): translational rows first, then rotational).
  JointDirections directions(const double* y) const;
  /// The rows' accelerations with the bodies' accelerations from ydot, plus their
  /// stabilization 2 a c' + a^2 c: zero when the joint holds (`pose`: this joint's pose(y)).
  JointRows stabilized_acceleration(const double* y, const JointPose& pose, const double* ydot, double rate) const;
  /// The rows' acceleration of side s that is linear in its body's accelerations, taken from
  /// the state derivative `delta` (zero for the ground).
  JointRows row_acceleration(int s, const JointPose& pose, const double* delta) const;
  /// Adds row j's unit load (force or torque along its direction, of sign +1 on side 0 and -1
  /// on side 1) times `amount` to the generalized force `f` of side s's body.
  void add_load(int s, int row, double amount, const JointPose& pose, GeneralizedForce& f) const;
  /// The rows' position-level residuals at y: the attachments' separation (m, world), then
  /// the orientation error along the rotational rows (rad); zero where the joint holds.
  JointRows residual(const double* y) const;
  /// Position error (m) and orientation error (rad) at y.
  std::pair<double, double> errors(const double* y) const;

private:
  Eigen::Vector3d rotation_error(const AttachmentMotion& a, const AttachmentMotion& b) const;

  std::string name_;
  JointSpec::Kind kind_;
  std::array<JointAttachment, 2> sides_;
  Eigen::Index rotation_rows_ = 0;
  Eigen::Matrix3d relative_ = Eigen::Matrix3d::Identity();  ///< fixed: R1 = R2 relative_ at t = 0
};

}  // namespace isosid::run
