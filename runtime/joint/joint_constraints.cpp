// Joint reactions by Lagrange multipliers; see joint_constraints.hpp.
#include "joint/joint_constraints.hpp"

#include "isosid/common/dense_decompositions.hpp"
#include "isosid/common/number_text.hpp"
#include "isosid/format/error.hpp"


#include <algorithm>

namespace isosid::run {

JointConstraints::JointConstraints(const std::vector<JointSpec>& joints, double rate, const Eigen::Vector3d& gravity,
                                   const std::string& scene_file, const std::vector<std::unique_ptr<FloatingBody>>& bodies,
                                   Eigen::Index state_size, const double* y0)
    : rate_(rate) {
  for (const JointSpec& spec : joints) {
    joints_.emplace_back(spec, bodies, y0, scene_file);
    first_row_.push_back(rows_);
    rows_ += joints_.back().rows();
    for (int s = 0; s < 2; ++s) {
      const JointAttachment& a = joints_.back().side(s);
      const bool seen = std::any_of(jointed_.begin(), jointed_.end(), [&](const auto& j) { return j.first == a.body; });
      if (a.body && !seen) jointed_.emplace_back(a.body, a.index);
    }
    // a joint holds positions and velocities: attachments that move apart at the start are refused
    const Joint& j = joints_.back();
    const AttachmentMotion m0 = j.motion(0, y0), m1 = j.motion(1, y0);
    const double apart = (m0.v - m1.v).norm(), speed = std::max(m0.v.norm(), m1.v.norm());
    if (apart > 1e-9 * (1 + speed))
      throw format::InputError(scene_file, "joint " + spec.name,
                               "its attachments move apart at " + common::number_text(apart) +
                                   " m/s at t = 0: give the bodies velocities the joint allows");
  }
  base_.setZero(state_size);
  loaded_.setZero(state_size);
  lambda_.setZero(rows_);
  residual_.setZero(rows_);
  response_.setZero(rows_, rows_);
  unit_.resize(bodies.size());
  for (const auto& [body, index] : jointed_) unit_[index].reset(body->nq());
  moving_ = refuse_redundant_rows(bodies, y0, gravity, scene_file);
  const auto m = Eigen::Index(moving_.size());
  moving_response_.setZero(m, m);
  moving_lambda_.setZero(m);
  moving_residual_.setZero(m);
  moving_lu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(m);
}

std::vector<Eigen::Index> JointConstraints::refuse_redundant_rows(const std::vector<std::unique_ptr<FloatingBody>>& bodies,
                                                                 const double* y0, const Eigen::Vector3d& gravity,
                                                                 const std::string& scene_file) const {
  if (joints_.empty()) return {};
  std::vector<GeneralizedForce> none(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) none[i].reset(bodies[i]->nq());
  prepare(y0, gravity, none);
  assemble_response();
  // rows no body can move (a planar scene's out-of-plane rows) are left out; among the others a
  // dependent row is one the other joints already impose: their reactions would not be unique
  const double largest = response_.diagonal().cwiseAbs().maxCoeff();
  std::vector<Eigen::Index> moving;
  for (Eigen::Index r = 0; r < rows_; ++r)
    if (std::abs(response_(r, r)) > 1e-12 * largest) moving.push_back(r);
  Eigen::MatrixXd W(Eigen::Index(moving.size()), Eigen::Index(moving.size()));
  for (std::size_t a = 0; a < moving.size(); ++a)
    for (std::size_t b = 0; b < moving.size(); ++b) W(Eigen::Index(a), Eigen::Index(b)) = response_(moving[a], moving[b]);
  // scaled to unit diagonal: rows of forces and of torques compare alike
  const Eigen::VectorXd scale = W.diagonal().cwiseAbs().cwiseSqrt().cwiseInverse();
  const common::SymmetricEigen eig = common::symmetric_eigen(scale.asDiagonal() * (0.5 * (W + W.transpose())) * scale.asDiagonal());
  const Eigen::VectorXd& values = eig.values;
  if (values.size() == 0 || values(0) > 1e-9 * values(values.size() - 1)) return moving;
  // the joints with a share in the dependent combination
  const Eigen::VectorXd null = eig.vectors.col(0).cwiseAbs();
  std::string names, first;
  for (std::size_t k = 0; k < joints_.size(); ++k) {
    double share = 0;
    for (std::size_t a = 0; a < moving.size(); ++a)
      if (moving[a] >= first_row_[k] && moving[a] < first_row_[k] + joints_[k].rows()) share = std::max(share, null(Eigen::Index(a)));
    if (share <= 1e-3) continue;
    names += (names.empty() ? "'" : ", '") + joints_[k].name() + "'";
    if (first.empty()) first = joints_[k].name();
  }
  Eigen::Index rank = 0;
  for (Eigen::Index i = 0; i < values.size(); ++i) rank += values(i) > 1e-9 * values(values.size() - 1);
  throw format::InputError(scene_file, "joint " + first,
                           "the mechanism is over-constrained: joints " + names + " impose the same motion twice (their " +
                               std::to_string(values.size()) + " constraint rows have rank " + std::to_string(rank) +
                               " at the start); drop or loosen one");
}

void JointConstraints::prepare(const double* y, const Eigen::Vector3d& gravity, const std::vector<GeneralizedForce>& forces) const {
  // each body once: its accelerations do not depend on the joint that holds it
  for (const auto& [body, index] : jointed_) body->derivatives(y, forces[index], gravity, base_.data());
  poses_.clear();
  for (const Joint& j : joints_) poses_.push_back(j.pose(y));
}

void JointConstraints::apply(const double* y, const Eigen::Vector3d& gravity, std::vector<GeneralizedForce>& forces) const {
  if (joints_.empty()) return;
  prepare(y, gravity, forces);  // every jointed body's accelerations under its other loads
  for (std::size_t k = 0; k < joints_.size(); ++k)
    residual_.segment(first_row_[k], joints_[k].rows()) = joints_[k].stabilized_acceleration(y, poses_[k], base_.data(), rate_);
  assemble_response();
  // Rows no body can move (a planar scene's out-of-plane rows) have no response and carry no
  // reaction; the others' response was of full rank at the start (refuse_redundant_rows):
  // LU factors of it. A pose where it is singular after all takes the least-squares solve.
  lambda_.setZero();
  const auto m = Eigen::Index(moving_.size());
  for (Eigen::Index a = 0; a < m; ++a) {
    for (Eigen::Index b = 0; b < m; ++b) moving_response_(a, b) = response_(moving_[std::size_t(a)], moving_[std::size_t(b)]);
    moving_residual_(a) = -residual_(moving_[std::size_t(a)]);
  }
  moving_lu_.compute(moving_response_);
  moving_lambda_ = moving_lu_.solve(moving_residual_);
  if (moving_lambda_.allFinite())
    for (Eigen::Index a = 0; a < m; ++a) lambda_(moving_[std::size_t(a)]) = moving_lambda_(a);
  else
    lambda_ = common::minimum_norm_solve(response_, -residual_);
  for (std::size_t k = 0; k < joints_.size(); ++k)
    for (int row = 0; row < joints_[k].rows(); ++row)
      for (int s = 0; s < 2; ++s)
        if (joints_[k].side(s).body) joints_[k].add_load(s, row, lambda_(first_row_[k] + row), poses_[k], forces[joints_[k].side(s).index]);
}

void JointConstraints::assemble_response() const {
  // the rows' response to each row's unit reaction, through the bodies it loads
  response_.setZero();
  for (std::size_t k = 0; k < joints_.size(); ++k)
    for (int row = 0; row < joints_[k].rows(); ++row)
      for (int s = 0; s < 2; ++s) {
        const FloatingBody* b = joints_[k].side(s).body;
        if (!b) continue;
        GeneralizedForce& unit = unit_[joints_[k].side(s).index];
        unit.reset(b->nq());
        joints_[k].add_load(s, row, 1.0, poses_[k], unit);
        b->load_response(unit, loaded_.data());  // the mass matrix of the derivatives at y above
        // every joint row that moves with this body
        for (std::size_t i = 0; i < joints_.size(); ++i)
          for (int t = 0; t < 2; ++t)
            if (joints_[i].side(t).body == b)
              response_.block(first_row_[i], first_row_[k] + row, joints_[i].rows(), 1) +=
                  (t == 0 ? 1.0 : -1.0) * joints_[i].row_acceleration(t, poses_[i], loaded_.data());
      }
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> JointConstraints::reaction(std::size_t k, const double* y) const {
  const Joint& j = joints_[k];
  const auto D = j.directions(y);
  const Eigen::VectorXd l = lambda_.segment(first_row_[k], j.rows());
  const Eigen::Vector3d torque = j.rows() > 3 ? Eigen::Vector3d(D.rightCols(j.rows() - 3) * l.tail(j.rows() - 3)) : Eigen::Vector3d::Zero();
  return {l.head<3>(), torque};
}

}  // namespace isosid::run
