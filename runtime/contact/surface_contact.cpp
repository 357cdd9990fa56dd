// Penalty contact of slave Gauss points against a target; see surface_contact.hpp.
#include "contact/surface_contact.hpp"

#include "contact/surface_edge.hpp"
#include "isosid/format/error.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace isosid::run {

namespace {
/// The gap bounds start over once the slave has moved relative to the target by this fraction
/// of its contact surface's radius: 9 um for a ball of 10 mm, some steps of an impact.
constexpr double kRefreshPerRadius = 2e-3;

/// The round-off of a gap per metre of the positions it is formed from: the slave point and
/// the target point each pass through a frame (rotation and translation) and the difference.
constexpr double kGapRoundoff = 8 * std::numeric_limits<double>::epsilon();

/// A penalty point presses only inside the target: beyond a zero gap it does not matter.
constexpr auto unpressed = [](Eigen::Index) { return 0.0; };
constexpr auto never = [](Eigen::Index) { return false; };

const format::ContactSurface& find_surface(const ContactSpec& spec, const FloatingBody& body) {
  const format::ContactSurface* s = body.contact_surface(spec.surface);
  if (!s) throw format::InputError(spec.name, "surface", "the SID of '" + body.name() + "' has no contact surface '" + spec.surface + "'");
  return *s;
}
}  // namespace

SurfaceContact::SurfaceContact(const ContactSpec& spec, const FloatingBody& body, const ContactTarget& target)
    : spec_(spec), body_(body), target_(target), surface_(find_surface(spec, body)), dim_(body.sid().dim()) {
  edge_ = edge_points(surface_, body.sid().analysis, format::find_master_patch(body.sid(), surface_.master_patch));
  shape_columns_ = surface_.Psi.transpose();
  const Eigen::Index nh = body.n_quasistatic();
  quasistatic_row_norms_.resize(surface_.points());
  for (Eigen::Index g = 0; g < surface_.points(); ++g)
    quasistatic_row_norms_(g) = shape_columns_.block(body.nq() - nh, g * dim_, nh, dim_).norm();
  if (spec_.gap_space) pairing_ = std::make_unique<GapPairing>(body, surface_, target);
  hints_.assign(std::size_t(surface_.points()), Eigen::Vector2d::Constant(NAN));
  recorded_pass_.assign(std::size_t(surface_.points()), -1);
  left_out_.assign(std::size_t(surface_.points()), 0);
  multiplier_.assign(std::size_t(surface_.points()), 0.0);
  updated_ = multiplier_;
  if (surface_.points() == 0) return;
  bound_center_.head(dim_) = surface_.position.colwise().mean().transpose();
  Eigen::VectorXd row_norms(surface_.points());
  for (Eigen::Index g = 0; g < surface_.points(); ++g) {
    bound_radius_ = std::max(bound_radius_, (surface_.position.row(g).transpose() - bound_center_.head(dim_)).norm());
    row_norms(g) = surface_.Psi.middleRows(g * dim_, dim_).norm();
  }
  bounds_ = GapBounds(std::move(row_norms), kRefreshPerRadius * bound_radius_);
}

void SurfaceContact::set_penalty(ContactPenalty penalty) {
  penalty_ = std::move(penalty);
  if (law_) superseded_laws_.push_back(std::move(law_));
  law_ = make_contact_law(spec_.law, {penalty_.value});
  if (!law_) throw format::InputError(spec_.name, "law", "no contact law named '" + spec_.law + "'");
}

template <class F>
double SurfaceContact::for_each_point(const double* y, ContactTarget::Fill fill, F&& f) const {
  return for_each_point(y, fill, std::forward<F>(f), [](Eigen::Index) { return INFINITY; }, [](Eigen::Index) { return false; });
}

template <class F, class Beyond, class Skip>
double SurfaceContact::for_each_point(const double* y, ContactTarget::Fill fill, F&& f, Beyond&& beyond, Skip&& skip) const {
  target_.update(y);
  const Eigen::Matrix3d A = body_.orientation(y).toRotationMatrix();
  const Eigen::Vector3d r = body_.r(y);
  // broad phase: |Psi_g q| <= |Psi_g|_F |q| bounds every point's displacement
  const Eigen::VectorXd& q = body_.q(y);
  const double clearance = target_.clearance(r + A * bound_center_, bound_radius_ + bounds_.largest_row_norm() * q.norm());
  if (clearance > 0) {
    bounds_.invalidate();  // the points were not evaluated
    return clearance;
  }
  Eigen::Vector3d P = Eigen::Vector3d::Zero();
  Eigen::Vector3d plane_normal;
  double plane_offset = 0;
  if (target_.fixed_plane(plane_normal, plane_offset)) {
    // a fixed plane: every gap is n . (r + A P) - offset, from the body-frame normal; the
    // target point is the projection (what ShapeTarget::project gives, without its dispatch)
    const Eigen::Vector3d n_body = A.transpose() * plane_normal;
    const double base = plane_normal.dot(r) - plane_offset;
    // A gap is at least the undeformed point's less |Psi_g|_F |q|: a point that bound places
    // beyond what the caller needs is left out unplaced (exact contact's multipliers can press
    // a point at a positive gap: none is). The others are placed in one product where they
    // are most of the surface (a rod's end face), else each by its own rows (a disk's rim
    // arc, of which the plane's neighbourhood holds a third to a half).
    const double q_norm = q.norm();
    auto left_out = [&](Eigen::Index g) {
      if (skip(g)) return true;
      if (spec_.exact) return false;
      double undeformed = base;
      for (int a = 0; a < dim_; ++a) undeformed += n_body(a) * surface_.position(g, a);
      // less the sums' round-off: the gap itself adds the same terms in another order
      return undeformed - bounds_.row_norm(g) * q_norm - kGapRoundoff * (std::abs(base) + bound_radius_) >= beyond(g);
    };
    // counted to more than half, or else over every point (whose verdicts are then kept)
    Eigen::Index placed = 0;
    for (Eigen::Index g = 0; g < surface_.points() && 2 * placed <= surface_.points(); ++g) {
      left_out_[std::size_t(g)] = left_out(g);
      placed += !left_out_[std::size_t(g)];
    }
    const bool one_product = 2 * placed > surface_.points();  // then every point, as the callers' own tests leave them out
    if (one_product) displacement_.noalias() = surface_.Psi * q;
    point_.normal = plane_normal;
    point_.velocity.setZero();
    point_.Psi.resize(dim_, 0);
    for (Eigen::Index g = 0; g < surface_.points(); ++g) {
      if (!one_product && left_out_[std::size_t(g)]) continue;
      if (one_product) P.head(dim_) = surface_.position.row(g).transpose() + displacement_.segment(g * dim_, dim_);
      else place(g, q, P);
      point_.gap = base + n_body.dot(P);
      if (point_.gap < 0) point_.body_point = r + A * P - point_.gap * plane_normal;  // filled where it presses (TargetPoint)
      f(g, surface_.Psi.middleRows(g * dim_, dim_), P, A, point_);
    }
    return clearance;
  }
  const FloatingBody* master = target_.body();
  const Eigen::Matrix3d A_target = master ? master->orientation(y).toRotationMatrix() : Eigen::Matrix3d::Identity();
  const Eigen::Vector3d r_target = master ? Eigen::Vector3d(master->r(y)) : Eigen::Vector3d::Zero();
  static const Eigen::VectorXd kNone;
  const Eigen::VectorXd& q_target = master ? master->q(y) : kNone;
  if (!spec_.exact && bounds_.usable(r, A, q, r_target, A_target, q_target, target_.displacement_bound())) {
    // the points the bounds cannot place beyond what the caller needs, each with its own rows
    for (Eigen::Index g = 0; g < surface_.points(); ++g) {
      if (bounds_.lower_bound(g) >= beyond(g) || skip(g)) continue;
      place(g, q, P);
      if (target_.project(r + A * P, y, point_, hints_[std::size_t(g)], fill)) f(g, surface_.Psi.middleRows(g * dim_, dim_), P, A, point_);
    }
    return clearance;
  }
  // every point, in one product; their gaps bound them at the next states
  displacement_.noalias() = surface_.Psi * q;  // all points in one product (row blocks would be strided)
  bounds_.start(r, A, q, r_target, A_target, q_target);
  for (Eigen::Index g = 0; g < surface_.points(); ++g) {
    if (skip(g)) continue;  // its gap stays unknown: it is evaluated at every state until the next reference
    const auto Psi = surface_.Psi.middleRows(g * dim_, dim_);
    P.head(dim_) = surface_.position.row(g).transpose() + displacement_.segment(g * dim_, dim_);
    const Eigen::Vector3d x = r + A * P;
    if (target_.project(x, y, point_, hints_[std::size_t(g)], fill)) {
      bounds_.record(g, point_.gap, P.norm());
      f(g, Psi, P, A, point_);
    } else {
      bounds_.record(g, target_.clearance(x, 0), P.norm());  // beside the target: at least this far from it
    }
  }
  return clearance;
}

void SurfaceContact::place(Eigen::Index g, const Eigen::VectorXd& q, Eigen::Vector3d& P) const {
  for (int a = 0; a < dim_; ++a) P(a) = surface_.position(g, a) + shape_columns_.col(g * dim_ + a).dot(q);
}

Eigen::Vector3d SurfaceContact::friction_per_normal_force(const Eigen::Vector3d& vt) const {
  return -spec_.friction * vt / std::sqrt(vt.squaredNorm() + spec_.regularization * spec_.regularization);
}

Eigen::Vector3d SurfaceContact::sliding_velocity(const Eigen::Vector3d& P, const Eigen::Ref<const Eigen::MatrixXd>& Psi,
                                                 const double* y, const TargetPoint& t) const {
  const Eigen::Vector3d v = (Psi.cols() ? body_.point_velocity(P, Psi, y) : body_.rigid_point_velocity(P, y)) - t.velocity;
  return v - t.normal.dot(v) * t.normal;
}

Eigen::Vector3d SurfaceContact::point_force(Eigen::Index g, double p, const Eigen::Ref<const Eigen::MatrixXd>& Psi,
                                            const Eigen::Vector3d& P, const double* y, const TargetPoint& t, Eigen::Vector3d& vt) const {
  const double fn = p * surface_.weight(g);
  vt.setZero();
  if (spec_.friction == 0) return fn * t.normal;
  vt = sliding_velocity(P, Psi, y, t);
  return fn * t.normal + fn * friction_per_normal_force(vt);
}

template <class F>
void SurfaceContact::for_each_pressed_pair(const double* y, F&& f) const {
  const GapPairing::Poses at = pairing_->poses(y);
  const auto load = [&](std::size_t k, const GapPairing::Evaluation& e) {
    const Eigen::Index g = pairing_->pairs()[k].g;
    if (pressure(g, e.gap) <= 0) return;
    pairing_->target_point(y, k, e, spec_.friction > 0, point_);  // the velocity only for friction's sliding
    f(g, surface_.Psi.middleRows(g * dim_, dim_), e.slave_point, at.A_slave, point_);
  };
  if (const std::vector<GapPairing::Evaluation>* pressed = pairing_->pressed_evaluations(at)) {
    // the static solve's forces press these pairs at this state and no others: only they are
    // evaluated (about half the pairs at the peak, fewer before and after), once per state
    for (std::size_t i = 0; i < pressed->size(); ++i) load(pairing_->pressed_pairs()[i], (*pressed)[i]);
    return;
  }
  const std::vector<GapPairing::Evaluation>& evaluations = pairing_->evaluations(at);
  for (std::size_t k = 0; k < evaluations.size(); ++k) load(k, evaluations[k]);
}

template <class F>
bool SurfaceContact::for_each_pressed(const double* y, F&& f) const {
  if (pairing_ && pairing_->paired()) {
    for_each_pressed_pair(y, f);
    return true;
  }
  // a watched contact is open by twice its pairing distance (the static solve at y found it so)
  if (pairing_ && pairing_->watching()) return true;
  solution_key(y, current_key_);
  if (!recorded_valid_ || current_key_ != recorded_key_) {
    for_each_point(y, ContactTarget::Fill::Loads, [&](Eigen::Index g, const auto& Psi, const Eigen::Vector3d& P, const Eigen::Matrix3d& A,
                                                      const TargetPoint& t) {
      if (pressure(g, t.gap) > 0) f(g, Psi, P, A, t);
    }, unpressed, never);
    return false;
  }
  // the static solve's points at this solution: only the pressed ones are placed again
  const Eigen::Matrix3d A = body_.orientation(y).toRotationMatrix();
  const Eigen::VectorXd& q = body_.q(y);
  Eigen::Vector3d P = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < recorded_count_; ++i) {
    const RecordedPoint& point = recorded_[i];
    if (pressure(point.g, point.target.gap) <= 0) continue;
    place(point.g, q, P);
    f(point.g, surface_.Psi.middleRows(point.g * dim_, dim_), P, A, point.target);
  }
  return true;
}

std::vector<PointLoad> SurfaceContact::point_loads(const double* y) const {
  std::vector<PointLoad> loads;
  const Eigen::Vector3d r = body_.r(y);
  for_each_pressed(y, [&](Eigen::Index g, const auto& Psi, const Eigen::Vector3d& P, const Eigen::Matrix3d& A, const TargetPoint& t) {
    const double p = pressure(g, t.gap);
    Eigen::Vector3d vt;
    loads.push_back({r + A * P, point_force(g, p, Psi, P, y, t, vt), p, t.gap});
  });
  return loads;
}

ContactState SurfaceContact::apply(const double* y, GeneralizedForce& slave_force, GeneralizedForce* target_force) const {
  ContactState s;
  const FloatingBody* master = target_.body();
  const Eigen::Matrix3d A_master = master ? master->orientation(y).toRotationMatrix() : Eigen::Matrix3d::Identity();
  auto load = [&](Eigen::Index g, const auto& Psi, const Eigen::Vector3d& P, const Eigen::Matrix3d& A, const TargetPoint& t) {
    const double p = pressure(g, t.gap);
    const double w = surface_.weight(g);
    Eigen::Vector3d vt;
    const Eigen::Vector3d F = point_force(g, p, Psi, P, y, t, vt);
    s.friction_power -= (F - p * w * t.normal).dot(vt);
    body_.apply_force(F, P, Psi, A, slave_force);
    if (master && target_force) master->apply_force(-F, t.body_point, t.Psi, A_master, *target_force);
    s.force += F;
    ++s.active_points;
    s.edge_points += edge_[std::size_t(g)];
    s.outside_interface += surface_.in_interface.size() > 0 && surface_.in_interface(g) == 0;  // Craig-Bampton SIDs mark them
    s.max_penetration = std::max(s.max_penetration, -t.gap);
    // the energy of the actual penetration (exact contact: none once the gaps have closed)
    s.penalty_energy += law_->energy(t.gap) * w;
  };
  s.from_static_solve = for_each_pressed(y, load);
  return s;
}

void SurfaceContact::add_quasistatic_terms(const double* y, QuasistaticTerms& terms) const {
  const FloatingBody* master = target_.body();
  const bool slave_qs = body_.n_quasistatic() > 0, master_qs = master && master->n_quasistatic() > 0;
  if (!slave_qs && !master_qs) return;
  const Eigen::Matrix3d A_master = master ? master->orientation(y).toRotationMatrix() : Eigen::Matrix3d::Identity();
  // the target's block of the gap gradient v = dgap/dz and of the friction direction t: -Psi^T
  // A^T (its displacement closes the gap, and it takes the reaction)
  auto add_target_side = [&](const Eigen::Ref<const Eigen::MatrixXd>& Psi, const Eigen::Vector3d& n, const Eigen::Vector3d& direction,
                             Eigen::Index k) {
    const Eigen::Index nh = master->n_quasistatic(), at = master->quasistatic_offset();
    const auto Psi_h = Psi.rightCols(nh);
    add_elastic_force(Psi_h, -(A_master.transpose() * n), terms.V.col(k).segment(at, nh));
    if (spec_.friction > 0) add_elastic_force(Psi_h, -(A_master.transpose() * direction), terms.T.col(k).segment(at, nh));
  };
  const Eigen::Index nh = body_.n_quasistatic(), at = body_.quasistatic_offset();
  // at the y of the previous evaluation, a free point moves only with the quasistatic
  // coordinates: skip it while their change cannot bring it where it would be recorded
  // (exact contact's multipliers change between evaluations: no skipping there)
  pose_key(y, key_);
  const bool same_pose = !spec_.exact && key_.size() == free_key_.size() && key_ == free_key_;
  recorded_valid_ = false;  // until this recording is complete
  recorded_count_ = 0;
  ++pass_;
  const auto z_slave = body_.q(y).tail(nh);
  double slave_move = 0, target_move = 0;
  if (same_pose) {
    slave_move = (z_slave - free_z_slave_).norm();
    if (master_qs) target_move = target_.displacement_bound() * (master->q(y).tail(master->n_quasistatic()) - free_z_target_).norm();
  } else {
    free_key_ = key_;
    free_z_slave_ = z_slave;
    if (master_qs) free_z_target_ = master->q(y).tail(master->n_quasistatic());
    free_gap_.assign(std::size_t(surface_.points()), -INFINITY);
    pressed_at_pose_.assign(std::size_t(surface_.points()), 0);
  }
  // a free point is left out where its gap (less lambda / c_p) reaches the window plus what a
  // change of z by terms.reach could close (|Psi_h u| <= |Psi_h|_F |u|); against a target
  // with quasistatic modes beyond the window alone: the target's rows must be formed for each
  // recorded point, and the reach of a massless boundary's large coordinates records most of
  // a beam's face (the sphere on the free-free beam took twice as long)
  // A point that pressed at some z of this pose is recorded at every later z of it, free or
  // not: it lies where the solve's steps go, and a model without it oversteps there again (two
  // balls at first touch: a point at zero gap beyond the window made the line search halve
  // each step nine times over).
  auto left_out_from = [&](Eigen::Index g) {
    if (pressed_at_pose_[std::size_t(g)]) return std::numeric_limits<double>::infinity();
    return master_qs ? terms.window : terms.window + terms.reach * quasistatic_row_norms_(g);
  };
  auto skip = [&](Eigen::Index g) {
    return same_pose && free_gap_[std::size_t(g)] - quasistatic_row_norms_(g) * slave_move - target_move >= left_out_from(g);
  };
  // a gap is n . (x - c), its points some distance from the origins of the world and of both
  // bodies' frames: it is known to a few eps of those distances
  const double origins = body_.r(y).norm() + (master ? master->r(y).norm() : 0.0);
  const double clearance = for_each_point(y, ContactTarget::Fill::Loads, [&](Eigen::Index g, const auto& Psi, const Eigen::Vector3d& P, const Eigen::Matrix3d& A, TargetPoint& t) {
    const double lambda = multiplier(g);
    if (pressure(g, t.gap) <= 0) {
      if (!same_pose) free_gap_[std::size_t(g)] = t.gap;
      if (law_->effective_gap(t.gap, lambda) >= left_out_from(g)) return;
      target_.fill_loads(y, t);  // recorded free: its rows on the target too
    } else {
      terms.gap_resolution = std::max(terms.gap_resolution, kGapRoundoff * (origins + P.norm() + t.body_point.norm()));
      // unknown to the model of the pass before (a penalty point not recorded there)
      if (!spec_.exact && recorded_pass_[std::size_t(g)] != pass_ - 1) ++terms.newly_pressed;
      pressed_at_pose_[std::size_t(g)] = 1;
    }
    const Eigen::Index k = terms.add_point(t.gap, lambda, *law_, surface_.weight(g));
    recorded_pass_[std::size_t(g)] = pass_;
    if (!spec_.exact) {
      if (recorded_count_ == recorded_.size()) recorded_.emplace_back();
      RecordedPoint& kept = recorded_[recorded_count_++];
      kept.g = g, kept.k = k, kept.target = t;
    }
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    if (spec_.friction > 0) {
      // Along the point's rigid-body sliding, held during the Newton iterations. The quasistatic
      // modes carry no velocity, and a direction set by the dynamic modes' vibration alone pumps
      // energy into them where the bodies do not slide (a disk dropped without spin rebounded
      // 0.6-2.9 % faster than it came); where they slide, the two directions agree.
      direction = friction_per_normal_force(sliding_velocity(P, Psi.leftCols(0), y, t));
      terms.friction = true;
    }
    if (slave_qs) {
      // the slave's block from its transposed quasistatic shape rows: contiguous per point
      const Eigen::Vector3d n_body = A.transpose() * t.normal, direction_body = A.transpose() * direction;
      for (int a = 0; a < dim_; ++a) {
        const auto column = shape_columns_.col(g * dim_ + a).tail(nh);
        terms.V.col(k).segment(at, nh).noalias() += n_body(a) * column;
        if (spec_.friction > 0) terms.T.col(k).segment(at, nh).noalias() += direction_body(a) * column;
      }
    }
    if (master_qs) add_target_side(t.Psi, t.normal, direction, k);
  }, left_out_from, skip);
  if (clearance > 0) terms.unseen = true;
  // exact contact's multipliers change after the solve: its loads are found anew
  if (!spec_.exact) solution_key(y, recorded_key_), recorded_valid_ = true;
}

void SurfaceContact::take_model_gaps(const double* y, const QuasistaticTerms& terms) const {
  if (!recorded_valid_) return;
  for (std::size_t i = 0; i < recorded_count_; ++i) recorded_[i].target.gap = terms.gap(recorded_[i].k);
  solution_key(y, recorded_key_);
}

void SurfaceContact::solution_key(const double* y, Eigen::VectorXd& key) const {
  // both bodies' whole states (the recorded target points carry the target's velocity)
  const FloatingBody* master = target_.body();
  const Eigen::Index ns = body_.state_size(), nm = master ? master->state_size() : 0;
  const Eigen::Index hs = body_.n_quasistatic(), hm = master ? master->n_quasistatic() : 0;
  key.resize(ns + nm + hs + hm);
  key.head(ns) = Eigen::Map<const Eigen::VectorXd>(y + body_.offset(), ns);
  key.segment(ns, hs) = body_.quasistatic_modes();
  if (!master) return;
  key.segment(ns + hs, nm) = Eigen::Map<const Eigen::VectorXd>(y + master->offset(), nm);
  key.tail(hm) = master->quasistatic_modes();
}

void SurfaceContact::pose_key(const double* y, Eigen::VectorXd& key) const {
  // each body's position, orientation and integrated coordinates: the leading 7 + n_dynamic of its state
  const FloatingBody* master = target_.body();
  const Eigen::Index ns = 7 + body_.n_dynamic(), nm = master ? 7 + master->n_dynamic() : 0;
  key.resize(ns + nm);
  key.head(ns) = Eigen::Map<const Eigen::VectorXd>(y + body_.offset(), ns);
  if (master) key.tail(nm) = Eigen::Map<const Eigen::VectorXd>(y + master->offset(), nm);
}

double SurfaceContact::update_multipliers(const double* y) const {
  std::fill(updated_.begin(), updated_.end(), 0.0);  // points the target does not see carry none
  double violation = 0;
  for_each_point(y, ContactTarget::Fill::Gap, [&](Eigen::Index g, const auto&, const Eigen::Vector3d&, const Eigen::Matrix3d&, const TargetPoint& t) {
    const double p = pressure(g, t.gap);
    updated_[std::size_t(g)] = p;
    // pressed points should touch, free ones not penetrate
    violation = std::max(violation, p > 0 ? std::abs(t.gap) : -t.gap);
  });
  std::swap(multiplier_, updated_);
  return violation;
}

double SurfaceContact::min_gap(const double* y) const {
  if (!pairing_) return unpaired_min_gap(y);
  if (pairing_->paired() && !pairing_->pairs().empty()) return pairing_->min_gap(y);
  // an unpaired gap-space contact: its solve asks before the step's gap function does, at the
  // same state; the second asking is the first's answer
  solution_key(y, min_gap_key_);
  if (min_gap_key_.size() == last_min_gap_key_.size() && min_gap_key_ == last_min_gap_key_) return last_min_gap_;
  std::swap(min_gap_key_, last_min_gap_key_);
  // watched from its last pairing's pairs while clearly apart, else projected
  const double watched = pairing_->watching() ? pairing_->watched_gap(y) : NAN;
  return last_min_gap_ = std::isnan(watched) ? unpaired_min_gap(y) : watched;
}

double SurfaceContact::unpaired_min_gap(const double* y) const {
  double smallest = INFINITY;
  // Exact contact presses a point at a gap that closes to round-off, of either sign: its
  // effective gap g - lambda / c_p is negative exactly while it carries pressure. A point whose
  // gap bound is at or beyond the smallest gap found so far cannot be the smallest: the bounds
  // leave it out unprojected (the event functions evaluate this at every step, and a refined
  // ball has thousands of points).
  const double clearance = for_each_point(y, ContactTarget::Fill::Gap, [&](Eigen::Index g, const auto&, const Eigen::Vector3d&, const Eigen::Matrix3d&, const TargetPoint& t) {
    smallest = std::min(smallest, law_->effective_gap(t.gap, multiplier(g)));
  }, [&](Eigen::Index) { return smallest; }, never);
  if (clearance > 0) return clearance;
  // no point is a candidate of the target (all beside it): clear, by an unknown positive gap
  return std::isinf(smallest) ? std::max(bound_radius_, 1e-3) : smallest;
}

}  // namespace isosid::run
