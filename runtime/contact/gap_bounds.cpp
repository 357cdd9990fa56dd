// Gap bounds between full evaluations; see gap_bounds.hpp.
#include "contact/gap_bounds.hpp"

#include <cmath>

namespace isosid::run {

GapBounds::GapBounds(Eigen::VectorXd row_norms, double refresh_distance)
    : row_norms_(std::move(row_norms)), refresh_distance_(refresh_distance) {
  largest_row_norm_ = row_norms_.size() ? row_norms_.maxCoeff() : 0.0;
  gap_.assign(std::size_t(row_norms_.size()), -INFINITY);
  position_norm_.assign(std::size_t(row_norms_.size()), 0.0);
}

bool GapBounds::usable(const Eigen::Vector3d& r_slave, const Eigen::Matrix3d& A_slave, const Eigen::VectorXd& q_slave,
                       const Eigen::Vector3d& r_target, const Eigen::Matrix3d& A_target, const Eigen::VectorXd& q_target,
                       double target_displacement_bound) const {
  if (!valid_ || q_slave.size() != q_slave_.size() || q_target.size() != q_target_.size()) return false;
  const Eigen::Matrix3d M = A_target.transpose() * A_slave;
  const Eigen::Vector3d b = A_target.transpose() * (r_slave - r_target);
  rotation_ = (M - M_).norm();
  slave_move_ = (q_slave - q_slave_).norm();
  const double target_move = q_target.size() ? target_displacement_bound * (q_target - q_target_).norm() : 0.0;
  shared_ = (b - b_).norm() + target_move;
  // the bound of the point that moves most: past the refresh distance, a new reference
  if (!std::isfinite(shared_ + rotation_ + slave_move_)) return false;
  return shared_ + rotation_ * largest_position_ + largest_row_norm_ * slave_move_ <= refresh_distance_;
}

void GapBounds::start(const Eigen::Vector3d& r_slave, const Eigen::Matrix3d& A_slave, const Eigen::VectorXd& q_slave,
                      const Eigen::Vector3d& r_target, const Eigen::Matrix3d& A_target, const Eigen::VectorXd& q_target) const {
  M_ = A_target.transpose() * A_slave;
  b_ = A_target.transpose() * (r_slave - r_target);
  q_slave_ = q_slave;
  q_target_ = q_target;
  std::fill(gap_.begin(), gap_.end(), -INFINITY);
  std::fill(position_norm_.begin(), position_norm_.end(), 0.0);
  largest_position_ = 0;
  valid_ = true;
}

}  // namespace isosid::run
