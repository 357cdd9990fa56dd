// Paired points' rows factored through their control points; see control_net_rows.hpp.
#include "condensation/control_net_rows.hpp"

#include <algorithm>

namespace isosid::run {

void ControlNetRows::clear() {
  begin_.assign(1, 0), local_.clear(), basis_.clear();
  rows_.resize(0, 0);
  active_ = formed_ = false;
}

void ControlNetRows::add(const std::vector<int>& control_points, const std::vector<double>& basis) {
  local_.insert(local_.end(), control_points.begin(), control_points.end());
  basis_.insert(basis_.end(), basis.begin(), basis.end());
  begin_.push_back(Eigen::Index(local_.size()));
}

void ControlNetRows::finish(const Eigen::MatrixXd& Phi, int dim, std::size_t direct_entries) {
  dim_ = dim;
  std::vector<Eigen::Index> used = local_;
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  const std::size_t sums = local_.size() * std::size_t(dim);
  const std::size_t factored = used.size() * std::size_t(dim) * std::size_t(Phi.cols()) + sums;
  active_ = added() > 0 && 2 * factored < direct_entries;
  if (!active_) return clear();
  rows_.resize(Eigen::Index(used.size()) * dim, Phi.cols());
  for (std::size_t j = 0; j < used.size(); ++j)
    rows_.middleRows(Eigen::Index(j) * dim, dim) = Phi.middleRows(used[j] * dim, dim);
  for (Eigen::Index& i : local_) i = std::lower_bound(used.begin(), used.end(), i) - used.begin();
}

void ControlNetRows::deform(const Eigen::VectorXd& q) const {
  if (formed_ && q.size() == q_.size() && (q.array() == q_.array()).all()) return;
  q_ = q;
  // up to q's last coordinate that is not zero: the quasistatic modes (q's tail) rest at zero
  // while nothing presses
  Eigen::Index used = q.size();
  while (used > 0 && q(used - 1) == 0) --used;
  displacements_.noalias() = rows_.leftCols(used) * q.head(used);
  formed_ = true;
}

void ControlNetRows::add_displacement(std::size_t k, Eigen::Vector3d& out) const {
  const double* u = displacements_.data();
  if (dim_ == 3) {  // fixed-size sums: the pairs' evaluations run thousands of times per impact
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (Eigen::Index i = begin_[k]; i < begin_[k + 1]; ++i)
      sum += basis_[std::size_t(i)] * Eigen::Map<const Eigen::Vector3d>(u + 3 * local_[std::size_t(i)]);
    out += sum;
    return;
  }
  for (Eigen::Index i = begin_[k]; i < begin_[k + 1]; ++i)
    out.head(dim_) += basis_[std::size_t(i)] * displacements_.segment(local_[std::size_t(i)] * dim_, dim_);
}

}  // namespace isosid::run
