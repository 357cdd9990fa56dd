// Lower bounds of the slave points' gaps between full evaluations (temporal coherence): an
// impact of curved surfaces loads a few of thousands of Gauss points, and most of the others
// are far from the target. At a reference state every point's gap is known; at a later state
// a point's gap differs from it by at most how far the point moved relative to the target
// (the gap is a distance to the target's surface, 1-Lipschitz in the point's position)
// plus how far the target's surface moved in its own frame:
//   |gap - gap_ref| <= |db| + |dM|_F |P_ref| + |Psi_g|_F |dq_slave| + d_target |dq_target|
// with the slave's frame relative to the target's, x = b + M P (M = A_t^T A_s,
// b = A_t^T (r_s - r_t)), P = X + Psi q the point in the slave's frame and d_target the
// target's displacement per unit change of its coordinates. A point whose bound stays at or
// beyond what its caller needs (no pressure: gap >= 0) is left out without projecting it;
// once the shared part of the bound exceeds the refresh distance, every point is evaluated
// again and the state becomes the new reference.
#pragma once
#include <Eigen/Dense>

#include <algorithm>
#include <vector>

namespace isosid::run {

class GapBounds {
public:
  GapBounds() = default;  // no points
  /// `row_norms`: |Psi_g|_F per point; `refresh_distance`: how far the shared bound may grow, m.
  GapBounds(Eigen::VectorXd row_norms, double refresh_distance);

  /// Whether the reference bounds the gaps at this state (slave and target poses, world; all
  /// elastic coordinates of each; the target's displacement bound). Prepares lower_bound().
  bool usable(const Eigen::Vector3d& r_slave, const Eigen::Matrix3d& A_slave, const Eigen::VectorXd& q_slave,
              const Eigen::Vector3d& r_target, const Eigen::Matrix3d& A_target, const Eigen::VectorXd& q_target,
              double target_displacement_bound) const;
  /// Makes this state the reference; every point's gap is unknown until record()ed.
  void start(const Eigen::Vector3d& r_slave, const Eigen::Matrix3d& A_slave, const Eigen::VectorXd& q_slave,
             const Eigen::Vector3d& r_target, const Eigen::Matrix3d& A_target, const Eigen::VectorXd& q_target) const;
  /// Point g at the reference: a lower bound of its gap (its gap, or the target's clearance
  /// where it is no candidate) and its distance from the slave frame's origin |P|.
  void record(Eigen::Index g, double gap_lower_bound, double position_norm) const {
    gap_[std::size_t(g)] = gap_lower_bound;
    position_norm_[std::size_t(g)] = position_norm;
    largest_position_ = std::max(largest_position_, position_norm);
  }
  /// A lower bound of point g's gap at the state of the last usable().
  double lower_bound(Eigen::Index g) const {
    return gap_[std::size_t(g)] - (shared_ + rotation_ * position_norm_[std::size_t(g)] + row_norms_(g) * slave_move_);
  }
  void invalidate() const { valid_ = false; }
  /// |Psi_g|_F: no displacement of point g exceeds this times |q|.
  double row_norm(Eigen::Index g) const { return row_norms_(g); }
  double largest_row_norm() const { return largest_row_norm_; }

private:
  Eigen::VectorXd row_norms_;
  double refresh_distance_ = 0;
  double largest_row_norm_ = 0;
  mutable bool valid_ = false;
  mutable Eigen::Matrix3d M_;    ///< reference A_t^T A_s
  mutable Eigen::Vector3d b_;    ///< reference A_t^T (r_s - r_t)
  mutable Eigen::VectorXd q_slave_, q_target_;
  mutable std::vector<double> gap_, position_norm_;
  mutable double largest_position_ = 0;
  // the bound's parts at the last usable() state
  mutable double shared_ = 0, rotation_ = 0, slave_move_ = 0;
};

}  // namespace isosid::run
