// Slave points paired once with target points; see gap_pairing.hpp.
#include "condensation/gap_pairing.hpp"

#include "contact/deformed_patch.hpp"

#include <algorithm>
#include <cmath>

namespace isosid::run {

namespace {
/// Largest difference, relative to the surface's largest row entry, between a point's rows and
/// its carrier's sum over the master patch's rows, for the carriers to stand for the rows (the
/// two are the same sums in another order).
constexpr double kCarrierTolerance = 1e-10;

/// The carriers of the surface's points on its master patch (null: none), if the patch's
/// control points' rows give the points' own rows; else empty.
std::vector<ControlNetCarrier> surface_carriers(const format::MasterPatch* patch, const FloatingBody& body, const format::ContactSurface& s,
                                                int dim) {
  if (!patch) return {};
  DeformedPatch deformed(*patch, dim);
  const int pd = deformed.parameter_dim();
  const std::vector<Eigen::Index> free = side_parameters(s, pd);
  if (free.empty()) return {};
  deformed.deform(Eigen::VectorXd::Zero(body.nq()));
  const double floor = kCarrierTolerance * s.Psi.cwiseAbs().maxCoeff();
  std::vector<ControlNetCarrier> carriers(std::size_t(s.points()));
  DeformedPatch::Point point;
  Eigen::MatrixXd rows;
  for (Eigen::Index g = 0; g < s.points(); ++g) {
    Eigen::Vector2d u = Eigen::Vector2d::Zero();
    for (int a = 0; a < pd; ++a) u(a) = s.parameter(g, free[std::size_t(a)]);
    deformed.evaluate(u, point);
    deformed.shape_rows(point, rows);
    if (!((rows - s.Psi.middleRows(g * dim, dim)).cwiseAbs().maxCoeff() <= floor)) return {};
    carriers[std::size_t(g)] = {point.control_points, point.R};
  }
  return carriers;
}

/// Entries below this fraction of a point's largest displacement row entry are round-off of the
/// reduction (a massless boundary's surface points have 1e-17 in the columns of the normal modes).
constexpr double kDroppedEntry = 1e-13;
}  // namespace

SparseRows SparseRows::from(const Eigen::Ref<const Eigen::MatrixXd>& rows) {
  SparseRows s;
  const double floor = kDroppedEntry * rows.cwiseAbs().maxCoeff();
  for (Eigen::Index j = 0; j < rows.cols(); ++j)
    if (rows.col(j).cwiseAbs().maxCoeff() > floor) s.columns.push_back(j);
  s.values = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, Eigen::Index(s.columns.size()));
  for (std::size_t i = 0; i < s.columns.size(); ++i) s.values.col(Eigen::Index(i)).head(rows.rows()) = rows.col(s.columns[i]);
  for (int r = 0; r < 3; ++r) {
    s.row_begin[std::size_t(r)] = s.entry_values.size();
    for (std::size_t i = 0; i < s.columns.size(); ++i)
      if (const double v = s.values(r, Eigen::Index(i)); v != 0) s.entry_columns.push_back(s.columns[i]), s.entry_values.push_back(v);
  }
  s.row_begin[3] = s.entry_values.size();
  return s;
}

void RowsBound::clear() {
  added_.clear(), columns_.clear(), column_norms_.clear();
  frobenius_ = 0;
}

void RowsBound::add(const SparseRows& rows) {
  frobenius_ = std::max(frobenius_, rows.values.norm());
  for (std::size_t i = 0; i < rows.columns.size(); ++i) added_.emplace_back(rows.columns[i], rows.values.col(Eigen::Index(i)).norm());
}

void RowsBound::finish() {
  std::sort(added_.begin(), added_.end());
  columns_.clear(), column_norms_.clear();
  for (const auto& [column, norm] : added_) {
    if (columns_.empty() || columns_.back() != column) columns_.push_back(column), column_norms_.push_back(0);
    column_norms_.back() = std::max(column_norms_.back(), norm);
  }
  added_.clear();
}

double RowsBound::of(const Eigen::VectorXd& x) const {
  double squares = 0, weighted = 0;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    const double xi = x(columns_[i]);
    squares += xi * xi, weighted += column_norms_[i] * std::abs(xi);
  }
  return std::min(frobenius_ * std::sqrt(squares), weighted);
}

double RowsBound::of_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  double squares = 0, weighted = 0;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    const double d = a(columns_[i]) - b(columns_[i]);
    squares += d * d, weighted += column_norms_[i] * std::abs(d);
  }
  return std::min(frobenius_ * std::sqrt(squares), weighted);
}

GapPairing::GapPairing(const FloatingBody& slave, const format::ContactSurface& surface, const ContactTarget& target)
    : slave_(slave), surface_(surface), target_(target), dim_(slave.sid().dim()),
      slave_patch_(format::find_master_patch(slave.sid(), surface.master_patch)) {
  // the spacing of the points: each point's distance to its nearest neighbour
  const Eigen::Index n = surface_.points();
  spacing_ = Eigen::VectorXd::Constant(n, INFINITY);
  for (Eigen::Index g = 0; g < n; ++g)
    for (Eigen::Index h = g + 1; h < n; ++h) {
      const double d = (surface_.position.row(g) - surface_.position.row(h)).norm();
      spacing_(g) = std::min(spacing_(g), d), spacing_(h) = std::min(spacing_(h), d);
    }
  const Eigen::RowVectorXd centroid = n ? Eigen::RowVectorXd(surface_.position.colwise().mean()) : Eigen::RowVectorXd();
  for (Eigen::Index g = 0; g < n; ++g) {
    if (!std::isfinite(spacing_(g))) spacing_(g) = 0;
    extent_ = std::max(extent_, (surface_.position.row(g) - centroid).norm());
  }
}

void GapPairing::pair(const double* y) {
  if (paired_) ++repairings_;
  pairs_.clear();
  ++pairings_;
  paired_ = true;
  watching_ = false;
  watched_.valid = evaluated_at_.valid = false;
  slave_reach_ = target_reach_ = 0;
  slave_rows_.clear(), target_rows_.clear();
  slave_net_.clear(), target_net_.clear();
  target_.update(y);
  const FloatingBody* master = target_.body();
  const Eigen::Matrix3d A = slave_.orientation(y).toRotationMatrix();
  const Eigen::Matrix3d A_target = master ? master->orientation(y).toRotationMatrix() : Eigen::Matrix3d::Identity();
  const Eigen::Vector3d r = slave_.r(y);
  const Eigen::VectorXd& q = slave_.q(y);
  TargetPoint t;
  double smallest = INFINITY;
  for (Eigen::Index g = 0; g < surface_.points(); ++g) {
    const auto rows = surface_.Psi.middleRows(g * dim_, dim_);
    Eigen::Vector3d P = Eigen::Vector3d::Zero();
    P.head(dim_) = surface_.position.row(g).transpose() + rows * q;
    Eigen::Vector2d hint = Eigen::Vector2d::Constant(NAN);
    if (!target_.project(r + A * P, y, t, hint, ContactTarget::Fill::Loads)) continue;  // beside the target
    target_.fill_loads(y, t);
    Pair p;
    p.g = g;
    p.slave_rows = SparseRows::from(rows);
    p.normal = A_target.transpose() * t.normal;
    p.target_point = t.body_point;
    if (master && t.Psi.cols() > 0) {
      p.target_rows = SparseRows::from(t.Psi);
      Eigen::Vector3d displacement = Eigen::Vector3d::Zero();
      p.target_rows.add_product(master->q(y), displacement);
      p.target_point -= displacement;
    }
    p.spacing = spacing_(g);
    p.offset = t.gap;  // the gap for now; the offset once the smallest is known
    smallest = std::min(smallest, t.gap);
    slave_reach_ = std::max(slave_reach_, surface_.position.row(g).norm());
    target_reach_ = std::max(target_reach_, p.target_point.norm());
    slave_rows_.add(p.slave_rows), target_rows_.add(p.target_rows);
    if (master && target_.carriers(target_carrier_.control_points, target_carrier_.basis))
      target_net_.add(target_carrier_.control_points, target_carrier_.basis);
    pairs_.push_back(std::move(p));
  }
  slave_rows_.finish(), target_rows_.finish();
  // rows that fill most of the modes are evaluated through the control points that carry them
  std::size_t slave_entries = 0, target_entries = 0;
  for (const Pair& p : pairs_) slave_entries += p.slave_rows.entry_values.size(), target_entries += p.target_rows.entry_values.size();
  if (2 * slave_entries > pairs_.size() * std::size_t(dim_ * slave_.nq()) && !slave_carriers().empty()) {
    for (const Pair& p : pairs_) slave_net_.add(slave_carriers_[std::size_t(p.g)].control_points, slave_carriers_[std::size_t(p.g)].basis);
    slave_net_.finish(slave_patch_->Phi, dim_, slave_entries);
  }
  if (const format::MasterPatch* patch = target_.master_patch(); master && patch && target_net_.added() == pairs_.size())
    target_net_.finish(patch->Phi, dim_, target_entries);
  else
    target_net_.clear();
  for (Pair& p : pairs_) p.offset -= smallest;
  largest_ = std::max(largest_, pairs_.size());
  forget_solution();
  pressed_pairs_.reserve(pairs_.size());  // the solves record into them without allocating
  pressed_evaluations_.reserve(pairs_.size());
  count_condensed();
  // no point found the target from where it stands: the contact stays unpaired (projected)
  if (pairs_.empty()) paired_ = false;
}

GapPairing::Poses GapPairing::poses(const double* y) const {
  Poses at;
  at.r_slave = slave_.r(y);
  at.A_slave = slave_.orientation(y).toRotationMatrix();
  at.q_slave = &slave_.q(y);
  if (const FloatingBody* master = target_.body()) {
    at.r_target = master->r(y);
    at.A_target = master->orientation(y).toRotationMatrix();
    if (master->nq() > 0) at.q_target = &master->q(y);
  }
  return at;
}

const std::vector<ControlNetCarrier>& GapPairing::slave_carriers() {
  if (!slave_carriers_found_) slave_carriers_ = surface_carriers(slave_patch_, slave_, surface_, dim_), slave_carriers_found_ = true;
  return slave_carriers_;
}

void GapPairing::deform_nets(const Poses& at) const {
  if (slave_net_.active()) slave_net_.deform(*at.q_slave);
  if (target_net_.active() && at.q_target) target_net_.deform(*at.q_target);
}

void GapPairing::evaluate(const Poses& at, std::size_t k, Evaluation& e) const {
  deform_nets(at);
  evaluate_deformed(at, k, e);
}

void GapPairing::evaluate_deformed(const Poses& at, std::size_t k, Evaluation& e) const {
  const Pair& p = pairs_[k];
  e.slave_point.setZero();
  e.slave_point.head(dim_) = surface_.position.row(p.g).transpose();
  if (slave_net_.active())
    slave_net_.add_displacement(k, e.slave_point);
  else
    p.slave_rows.add_product(*at.q_slave, e.slave_point);
  e.target_point = p.target_point;
  if (at.q_target) {
    if (target_net_.active())
      target_net_.add_displacement(k, e.target_point);
    else
      p.target_rows.add_product(*at.q_target, e.target_point);
  }
  // a fixed target's frame is the world's (identity poses)
  const Eigen::Vector3d x_target = at.r_target + at.A_target * e.target_point;
  e.normal = at.A_target * p.normal;
  const Eigen::Vector3d d = at.r_slave + at.A_slave * e.slave_point - x_target;
  e.gap = e.normal.dot(d);
  e.slip = (d - e.gap * e.normal).norm();
}

void GapPairing::PosesCopy::assign(const Poses& at) {
  // in place: the vectors keep their storage from one state to the next
  valid = true;
  r_slave = at.r_slave, r_target = at.r_target;
  A_slave = at.A_slave, A_target = at.A_target;
  q_slave = *at.q_slave;
  if (at.q_target) q_target = *at.q_target;
}

bool GapPairing::PosesCopy::same(const Poses& at, const std::vector<Eigen::Index>& slave_columns,
                                 const std::vector<Eigen::Index>& target_columns) const {
  if (!valid || r_slave != at.r_slave || r_target != at.r_target || A_slave != at.A_slave || A_target != at.A_target) return false;
  for (const Eigen::Index i : slave_columns)
    if (q_slave(i) != (*at.q_slave)(i)) return false;
  if (at.q_target)
    for (const Eigen::Index i : target_columns)
      if (q_target(i) != (*at.q_target)(i)) return false;
  return true;
}

const std::vector<GapPairing::Evaluation>& GapPairing::evaluations(const Poses& at) const {
  if (same_poses(evaluated_at_, at) && evaluations_.size() == pairs_.size()) return evaluations_;
  evaluations_.resize(pairs_.size());
  deform_nets(at);
  for (std::size_t k = 0; k < pairs_.size(); ++k) evaluate_deformed(at, k, evaluations_[k]);
  evaluated_at_.assign(at);
  return evaluations_;
}

const std::vector<GapPairing::Evaluation>* GapPairing::pressed_evaluations(const Poses& at) const {
  if (!same_poses(solved_at_, at)) return nullptr;
  if (!pressed_evaluated_) {
    pressed_evaluations_.resize(pressed_pairs_.size());  // within the capacity pair() reserved
    deform_nets(at);
    for (std::size_t i = 0; i < pressed_pairs_.size(); ++i) evaluate_deformed(at, pressed_pairs_[i], pressed_evaluations_[i]);
    pressed_evaluated_ = true;
  }
  return &pressed_evaluations_;
}

std::pair<double, double> GapPairing::watched_change(const Poses& at) const {
  const WatchedState& w = watched_;
  // A pair's separation d = r_s + A_s (X + S q_s) - r_t - A_t (Y + T q_t) moves by at most
  // |dr| + |dA_s| |X + S q_s| + |S dq_s| + (the same for the target), each |S x| bounded over
  // the columns the rows read (RowsBound). For the difference of two rotations the Frobenius
  // norm is sqrt(2) times the spectral norm.
  const double slave_deformation_change = slave_rows_.of_difference(*at.q_slave, w.q_slave);
  double target_deformation_change = 0, target_radius = target_reach_;
  if (at.q_target) {
    target_deformation_change = target_rows_.of_difference(*at.q_target, w.q_target);
    target_radius += target_rows_.of(*at.q_target);
  }
  const double slave_radius = slave_reach_ + slave_rows_.of(*at.q_slave);
  const double slave_turn = (at.A_slave - w.A_slave).norm() / std::sqrt(2.0);
  const double target_turn = (at.A_target - w.A_target).norm() / std::sqrt(2.0);
  const double separation_change = ((at.r_slave - w.r_slave) - (at.r_target - w.r_target)).norm() + slave_turn * slave_radius +
                                   slave_deformation_change + target_turn * target_radius + target_deformation_change;
  // gap' - gap = n' . (d' - d) + (n' - n) . d with the normal n = A_t n0 turning by |dA_t|; the
  // slip, d less its normal part, changes by |d' - d| and by the projection's turn, 2 |dn| |d|
  const double turned = target_turn * w.separation;
  return {separation_change + turned, separation_change + 2 * turned};
}

double GapPairing::watched_gap(const double* y) {
  if (!watching_) return NAN;
  const Poses at = poses(y);
  const double distance = pairing_distance();
  if (watched_.valid) {
    const auto [gap_change, slip_change] = watched_change(at);
    // the bound has the gap's sign, and the gap is evaluated before it could come within 2 d
    if (watched_.gap - gap_change > 2 * distance && watched_.slip + slip_change <= distance) return watched_.gap - gap_change;
  }
  Evaluation e;
  double smallest = INFINITY, slip = 0, separation = 0;
  deform_nets(at);
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    evaluate_deformed(at, k, e);
    // a point that slid by d past its pair is off by about its target's curvature times d^2
    // at most, far less than the 2 d kept in hand: beyond, the pairs no longer tell
    if (e.slip > distance) return watching_ = false, NAN;
    smallest = std::min(smallest, e.gap);
    slip = std::max(slip, e.slip);
    separation = std::max(separation, std::hypot(e.gap, e.slip));
  }
  if (!(smallest > 2 * distance)) return watching_ = false, NAN;
  watched_.assign(at);
  watched_.gap = smallest, watched_.slip = slip, watched_.separation = separation;
  return smallest;
}

void GapPairing::set_condensation_reach(double reach) { condensation_reach_ = reach; }

void GapPairing::widen() {
  condensation_reach_ *= 2;
  ++widenings_;
  count_condensed();
}

void GapPairing::count_condensed() {
  std::size_t within = 0;
  for (std::size_t k = 0; k < pairs_.size(); ++k) within += condensed(k);
  largest_condensed_ = std::max(largest_condensed_, within);
}

double GapPairing::min_gap(const double* y) const {
  const Poses at = poses(y);
  if (same_poses(solved_at_, at)) return solved_min_gap_;
  double smallest = INFINITY;
  for (const Evaluation& e : evaluations(at)) smallest = std::min(smallest, e.gap);
  return smallest;
}

void GapPairing::add_gradient(const double* y, std::size_t k, Eigen::Ref<Eigen::VectorXd> v) const {
  const Pair& p = pairs_[k];
  const FloatingBody* master = target_.body();
  const Eigen::Matrix3d A_target = master ? master->orientation(y).toRotationMatrix() : Eigen::Matrix3d::Identity();
  // the slave's displacement opens the gap along n, the target's closes it
  auto add = [&](const FloatingBody& body, const SparseRows& rows, const Eigen::Vector3d& n_body, double sign) {
    const Eigen::Index first = body.n_dynamic(), at = body.quasistatic_offset();
    for (std::size_t i = 0; i < rows.columns.size(); ++i)
      if (rows.columns[i] >= first) v(at + rows.columns[i] - first) += sign * n_body.dot(rows.values.col(Eigen::Index(i)));
  };
  if (slave_.n_quasistatic() > 0)
    add(slave_, p.slave_rows, slave_.orientation(y).toRotationMatrix().transpose() * (A_target * p.normal), 1.0);
  if (master && master->n_quasistatic() > 0) add(*master, p.target_rows, p.normal, -1.0);
}

void GapPairing::target_point(const double* y, std::size_t k, const Evaluation& e, bool with_velocity, TargetPoint& t) const {
  const Pair& p = pairs_[k];
  const FloatingBody* master = target_.body();
  t.gap = e.gap;
  t.normal = e.normal;
  t.body_point = e.target_point;
  t.velocity.setZero();
  if (!master) {
    t.Psi.resize(dim_, 0);
    return;
  }
  // the integrated columns only: a point load reads no others (FloatingBody::apply_force); the
  // columns ascend, the integrated ones first. Always this size, so the loads allocate nothing.
  const Eigen::Index nd = master->n_dynamic();
  const std::vector<Eigen::Index>& columns = p.target_rows.columns;
  if (nd > 0 && Eigen::Index(columns.size()) >= nd && columns[std::size_t(nd - 1)] == nd - 1) {
    t.Psi = p.target_rows.values.topLeftCorner(dim_, nd);  // rows that read every integrated column: one block
  } else {
    t.Psi.setZero(dim_, nd);
    for (std::size_t i = 0; i < columns.size() && columns[i] < nd; ++i) t.Psi.col(columns[i]) = p.target_rows.values.col(Eigen::Index(i)).head(dim_);
  }
  if (!with_velocity) return;
  Eigen::Vector3d rate = Eigen::Vector3d::Zero();
  p.target_rows.add_product(master->qdot(y), rate);
  t.velocity = master->v(y) + master->orientation(y).toRotationMatrix() * (master->omega(y).cross(e.target_point) + rate);
}

}  // namespace isosid::run
