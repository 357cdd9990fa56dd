// The joints of a scene solved together at every evaluation: their reactions are the
// Lagrange multipliers that make every joint row's stabilized acceleration vanish. The
// bodies' accelerations are linear in the loads on them, so each row's unit load is pushed
// through the body's own equations of motion (FloatingBody::derivatives) once, giving the
// rows' response W = G M^-1 G^T, and W lambda = -(the rows' acceleration without reactions).
#pragma once
#include "isosid/common/dense_decompositions.hpp"
#include "joint/joint.hpp"

namespace isosid::run {

class JointConstraints {
public:
  /// The scene's `joints` with its Baumgarte `rate` (1/s); `gravity` and `scene_file` for the
  /// start's checks. Refuses (InputError) an over-constrained mechanism at y0.
  JointConstraints(const std::vector<JointSpec>& joints, double rate, const Eigen::Vector3d& gravity, const std::string& scene_file,
                   const std::vector<std::unique_ptr<FloatingBody>>& bodies, Eigen::Index state_size, const double* y0);

  bool empty() const { return joints_.empty(); }
  const std::vector<Joint>& joints() const { return joints_; }
  /// Adds the reactions that hold every joint at y to `forces` (which hold all other loads).
  void apply(const double* y, const Eigen::Vector3d& gravity, std::vector<GeneralizedForce>& forces) const;
  /// Joint k's reaction from the last apply(): world force and torque on its first side (N, N m).
  std::pair<Eigen::Vector3d, Eigen::Vector3d> reaction(std::size_t k, const double* y) const;

private:
  /// Every jointed body's accelerations at y under `forces` (its other loads) into base_, each
  /// body once however many joints hold it; and each joint's pose at y into poses_.
  void prepare(const double* y, const Eigen::Vector3d& gravity, const std::vector<GeneralizedForce>& forces) const;
  /// response_ = the rows' accelerations per unit reaction of each row, through the mass
  /// matrices of the jointed bodies' derivatives and at the poses of the last prepare().
  void assemble_response() const;
  /// InputError naming the joints if, at the start, some rows repeat what others impose (a
  /// rank-deficient constraint Jacobian: an over-constrained mechanism, reactions not unique).
  /// Returns the rows some body can move (a planar scene's out-of-plane rows none can).
  std::vector<Eigen::Index> refuse_redundant_rows(const std::vector<std::unique_ptr<FloatingBody>>& bodies, const double* y0,
                                                  const Eigen::Vector3d& gravity, const std::string& scene_file) const;

  std::vector<Joint> joints_;
  std::vector<Eigen::Index> first_row_;   ///< joint k's rows start here in the stacked multipliers
  Eigen::Index rows_ = 0;
  double rate_;                           ///< Baumgarte rate, 1/s
  /// the bodies some joint holds, each once, with their indices in the system
  std::vector<std::pair<const FloatingBody*, std::size_t>> jointed_;
  mutable std::vector<JointPose> poses_;  ///< per joint, at the state of the last prepare()
  mutable Eigen::VectorXd base_, loaded_, lambda_, residual_;
  mutable Eigen::MatrixXd response_;
  mutable std::vector<GeneralizedForce> unit_;  ///< per body of the system: a row's unit load
  /// the rows some body can move, fixed at the start, and their response's LU factors
  std::vector<Eigen::Index> moving_;
  mutable Eigen::MatrixXd moving_response_;
  mutable Eigen::VectorXd moving_residual_, moving_lambda_;
  mutable Eigen::PartialPivLU<Eigen::MatrixXd> moving_lu_;
};

}  // namespace isosid::run
