// Assembly of the system ODE; see multibody_system.hpp.
#include "solve/multibody_system.hpp"

#include "body/rigid_body_sid.hpp"
#include "contact/master_patch_target.hpp"
#include "contact/shape_target.hpp"
#include "isosid/common/number_text.hpp"
#include "isosid/format/error.hpp"

#include <chrono>

namespace isosid::run {

MultibodySystem::MultibodySystem(const Scene& scene, std::vector<format::Sid> sids, GivenPenalties given)
    : gravity_(scene.gravity), scene_file_(scene.file), given_penalties_(std::move(given)) {
  std::size_t next_sid = 0;
  for (const BodySpec& spec : scene.bodies) {
    format::Sid sid = spec.rigid ? rigid_body_sid(spec, scene.simulation.dimension) : std::move(sids.at(next_sid++));
    auto b = std::make_unique<FloatingBody>(spec, std::move(sid), scene.simulation.dimension);
    b->set_offset(size_);
    size_ += b->state_size();
    bodies_.push_back(std::move(b));
  }
  size_ += 1;  // dissipated energy
  contacts_.reserve(scene.contacts.size());
  for (const ContactSpec& c : scene.contacts) try {
    if (const ShapeSpec* fixed = scene.fixed_surface(c.target)) {
      targets_.push_back(std::make_unique<ShapeTarget>(*fixed));
      target_body_.push_back(-1);
    } else {
      const std::size_t m = body_index(c.target);
      const BodySpec& spec = *scene.body(c.target);
      if (spec.rigid)
        targets_.push_back(std::make_unique<ShapeTarget>(rigid_body_shape(spec), *bodies_[m]));
      else
        targets_.push_back(std::make_unique<MasterPatchTarget>(*bodies_[m], c.target_surface, c.name));
      target_body_.push_back(long(m));
    }
    slave_body_.push_back(body_index(c.body));
    contacts_.emplace_back(c, *bodies_[slave_body_.back()], *targets_.back());
    require_boundary_covers(contacts_.back(), targets_.back()->body(), c.target_surface);
    if (c.exact) require_massless_points(contacts_.back());
    const FloatingBody* target_body = targets_.back()->body();
    if (c.gap_space && bodies_[slave_body_.back()]->n_quasistatic() == 0 && !(target_body && target_body->n_quasistatic() > 0))
      throw format::InputError(c.name, "formulation",
                               "gap-space contact condenses quasistatic modes (a massless boundary), and neither body has them");
  } catch (const format::InputError& e) {  // a surface the SID does not have: name the scene file
    throw format::InputError(scene.file, "contact " + c.name + "." + e.field(), e.problem());
  }
  hertz_.reserve(scene.hertz_contacts.size());
  for (const HertzContactSpec& h : scene.hertz_contacts) {
    const std::size_t a = body_index(h.body), b = body_index(h.target);
    hertz_.emplace_back(h, *bodies_[a], scene.body(h.body)->rigid->radius, *bodies_[b], scene.body(h.target)->rigid->radius);
    hertz_bodies_.push_back({a, b});
  }
  touches_.reserve(contacts_.size());
  for (const SurfaceContact& c : contacts_) {
    touches_.emplace_back(c);
    touch_state_.push_back(touches_.back().available() ? TouchState::Armed : TouchState::Unavailable);
  }
  quasistatic_ = std::make_unique<QuasistaticModes>(bodies_, contacts_, gravity_);
  forces_.resize(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i) warn_of_many_dynamic_modes(*bodies_[i], scene.bodies[i]);
  std::vector<double> y0(size_);
  initial_state(y0.data());
  joints_ = std::make_unique<JointConstraints>(scene.joints, scene.simulation.joint_stabilization, scene.gravity, scene.file, bodies_, size_,
                                               y0.data());
  given_penalties_.resize(contacts_.size());
  penalty_contact_radius_.assign(contacts_.size(), 0.0);
  estimate_impacts(y0.data());
}

std::vector<format::Sid> MultibodySystem::release_sids() && {
  std::vector<format::Sid> sids;
  for (std::unique_ptr<FloatingBody>& b : bodies_)
    if (!b->rigid()) sids.push_back(std::move(*b).release_sid());
  return sids;
}

void MultibodySystem::estimate_impacts(const double* y) {
  impact_estimates_.clear();
  resolution_warnings_.clear();
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    SurfaceContact& c = contacts_[k];
    impact_estimates_.push_back(estimate_impact(c, y));
    const auto& estimate = impact_estimates_.back();
    if (estimate) penalty_contact_radius_[k] = estimate->contact_radius;
    try {
      c.set_penalty(decide_penalty(c, given_penalties_[k], penalty_contact_radius_[k]));
    } catch (const format::InputError& e) {  // a penalty that cannot be derived: name the scene file
      throw format::InputError(scene_file_, "contact " + c.name() + "." + e.field(), e.problem());
    }
    if (!estimate) continue;
    if (std::string w = resolution_warning(c, *estimate); !w.empty()) resolution_warnings_.push_back({"resolution", w});
  }
}

std::vector<RunWarning> MultibodySystem::warnings() const {
  std::vector<RunWarning> all = warnings_;
  all.insert(all.end(), resolution_warnings_.begin(), resolution_warnings_.end());
  return all;
}

void MultibodySystem::warn_of_many_dynamic_modes(const FloatingBody& body, const BodySpec& spec) {
  // an explicit integrator's step follows the highest integrated frequency: hundreds of
  // dynamic modes of a full model turn a sub-second run into tens of minutes
  if (body.n_dynamic() <= kManyDynamicModes) return;
  const format::RefMod& modes = body.sid().refmod;
  std::string advice;
  if (spec.high_modes != "quasistatic")
    advice = "set high_modes = \"quasistatic\" (with quasistatic_above_hz for a SID without high modes)";
  else if (spec.quasistatic_above_hz > 0)
    advice = "lower quasistatic_above_hz";
  else
    advice = "its SID marks no high modes (" + modes.reduction_method + " reduction); set quasistatic_above_hz";
  warnings_.push_back({"many_dynamic_modes", "body '" + body.name() + "' integrates " + std::to_string(body.n_dynamic()) +
                                                 " modes dynamically (up to " + common::number_text(modes.frequencies_hz(body.n_dynamic() - 1)) +
                                                 " Hz), which makes small steps: " + advice});
}

namespace {
/// Contact points' shape rows that move with their leading `columns` coordinates, beyond the
/// round-off of shape functions that vanish on the side (1e-12 of the largest row entry).
bool moves_with_leading(const Eigen::MatrixXd& rows, Eigen::Index columns) {
  if (columns == 0 || rows.size() == 0) return false;
  return rows.leftCols(columns).cwiseAbs().maxCoeff() > 1e-12 * rows.cwiseAbs().maxCoeff();
}
}  // namespace

void MultibodySystem::require_boundary_covers(const SurfaceContact& c, const FloatingBody* target, const std::string& target_surface) {
  // a massless boundary is [R3]'s contact model only where it carries the whole surface:
  // points that also move with mass-carrying modes would hit with mass again
  auto check = [&](const FloatingBody& b, const format::ContactSurface& surface, const char* field) {
    const format::RefMod& r = b.sid().refmod;
    if (!r.massless_boundary() || !moves_with_leading(surface.Psi, r.nq() - r.n_massless())) return;
    throw format::InputError(c.name(), field,
                             "the massless boundary of '" + b.name() + "' does not cover its surface '" + surface.name +
                                 "' (its points move with the mass-carrying modes too; make it the model's boundary_surface)");
  };
  check(c.body(), c.surface(), "surface");
  if (target)
    if (const format::ContactSurface* surface = target->contact_surface(target_surface)) check(*target, *surface, "target_surface");
}

void MultibodySystem::require_massless_points(const SurfaceContact& c) {
  // the static solve sees only the quasistatic coordinates: exact contact needs every contact
  // point to move with them alone
  const FloatingBody& slave = c.body();
  if (slave.n_quasistatic() == 0 || moves_with_leading(c.surface().Psi, slave.n_dynamic()))
    throw format::InputError(c.name(), "enforcement",
                             "exact contact needs a massless boundary under surface '" + c.surface().name + "' of '" + slave.name() +
                                 "' (a macneal or craig-bampton-massless SID with boundary_surface = \"" + c.surface().name + "\")");
  // a target may move with anything: the static solve holds it where the step put it
}

std::size_t MultibodySystem::body_index(const std::string& name) const {
  for (std::size_t i = 0; i < bodies_.size(); ++i)
    if (bodies_[i]->name() == name) return i;
  throw format::InputError("scene", name, "no such body");
}

const FloatingBody& MultibodySystem::body(const std::string& name) const { return *bodies_[body_index(name)]; }

namespace {
/// y (n entries) equals the stored state exactly.
bool same_state(bool valid, const Eigen::VectorXd& stored, const double* y, Eigen::Index n) {
  return valid && stored.size() == n && Eigen::Map<const Eigen::VectorXd>(y, n) == stored;
}
}  // namespace

void MultibodySystem::update_quasistatic(const double* y) const {
  // the gaps at the end of a step follow the step's last stage, at the same state
  if (quasistatic_->size() == 0 || same_state(solved_valid_, solved_y_, y, size_)) return;
  solved_valid_ = false;  // a failed solve leaves the modes half-way
  quasistatic_iterations_ += quasistatic_->solve(y);
  solved_y_ = Eigen::Map<const Eigen::VectorXd>(y, size_);
  solved_valid_ = true;
}

void MultibodySystem::keep_static_solution(const double* y) const {
  // only a solution of the last right-hand side's own state (one answered from the cache may
  // have left the modes at another state's)
  if (rhs_valid_ && same_state(solved_valid_, solved_y_, rhs_y_.data(), size_)) solved_y_ = Eigen::Map<const Eigen::VectorXd>(y, size_);
}

void MultibodySystem::initial_state(double* y) const {
  for (const auto& b : bodies_) b->initial_state(y);
  y[size_ - 1] = 0;
}

void MultibodySystem::rhs(double, const double* y, double* ydot) const {
  // a clock read costs about 20 ns, against tens of microseconds per evaluation
  using Clock = std::chrono::steady_clock;
  auto lap = [last = Clock::now()](double& total) mutable {
    const Clock::time_point now = Clock::now();
    total += std::chrono::duration<double>(now - last).count();
    last = now;
  };
  ++cost_.evaluations;
  if (same_state(rhs_valid_, rhs_y_, y, size_)) {
    Eigen::Map<Eigen::VectorXd>(ydot, size_) = rhs_ydot_;
    ++cost_.repeated;
    cost_.active_points += rhs_active_points_;
    return;
  }
  rhs_valid_ = false;  // until this evaluation completes
  const long active_before = cost_.active_points;
  update_quasistatic(y);
  lap(cost_.static_solve_s);
  for (std::size_t i = 0; i < bodies_.size(); ++i) forces_[i].reset(bodies_[i]->nq());
  double dissipation = 0;
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    GeneralizedForce* reaction = target_body_[k] >= 0 ? &forces_[std::size_t(target_body_[k])] : nullptr;
    const ContactState state = contacts_[k].apply(y, forces_[slave_body_[k]], reaction);
    dissipation += state.friction_power;
    cost_.active_points += state.active_points;
    cost_.kept_contact_loads += state.from_static_solve;
  }
  for (std::size_t k = 0; k < hertz_.size(); ++k)
    cost_.active_points += hertz_[k].apply(y, forces_[hertz_bodies_[k][0]], forces_[hertz_bodies_[k][1]]).active_points;
  lap(cost_.contacts_s);
  joints_->apply(y, gravity_, forces_);
  lap(cost_.joints_s);
  for (std::size_t i = 0; i < bodies_.size(); ++i) dissipation += bodies_[i]->derivatives(y, forces_[i], gravity_, ydot);
  ydot[size_ - 1] = 0;
  lap(cost_.floating_frame_s);
  dissipation += quasistatic_->friction_power(y, ydot, Eigen::Index(size_));
  lap(cost_.static_solve_s);
  ydot[size_ - 1] = dissipation;
  rhs_y_ = Eigen::Map<const Eigen::VectorXd>(y, size_);
  rhs_ydot_ = Eigen::Map<const Eigen::VectorXd>(ydot, size_);
  rhs_active_points_ = cost_.active_points - active_before;
  rhs_valid_ = true;
}

std::vector<MultibodySystem::JointState> MultibodySystem::joint_states(const double* y) const {
  std::vector<JointState> out;
  if (joints_->empty()) return out;
  std::vector<double> ydot(static_cast<std::size_t>(size_));
  rhs(0, y, ydot.data());
  for (std::size_t k = 0; k < joints_->joints().size(); ++k) {
    JointState s;
    std::tie(s.force, s.torque) = joints_->reaction(k, y);
    std::tie(s.position_error, s.angle_error) = joints_->joints()[k].errors(y);
    out.push_back(s);
  }
  return out;
}

void MultibodySystem::gaps(const double* y, double* g) const {
  // The gap cancels two positions of the body's size, so it is resolved only to eps * size,
  // far coarser than the root finder's time tolerance: at a located root it can be exactly
  // 0.0 on both sides, which ARKODE rejects ("root found at and very near t"). An exactly
  // zero gap therefore counts as touching: -1e-30 m, far below any physical gap yet far
  // above the denormals that would overflow the root finder's secant step.
  update_quasistatic(y);
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    const double gap = contacts_[k].min_gap(y);
    g[k] = gap != 0.0 ? gap : -1e-30;
  }
}

void MultibodySystem::roots(const double* y, double* g) const {
  gaps(y, g);
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    double& root = g[contacts_.size() + k];
    root = 1.0;
    if (touch_state_[k] != TouchState::Armed) continue;
    // apart by the bounding spheres: that positive lower bound has the exact gap's sign, and
    // the root lies where the exact gap vanishes, which the exact search finds
    const double bound = touches_[k].clearance(y);
    const double gap = bound > 0 ? bound : touches_[k].evaluate(y).gap;
    root = std::isfinite(gap) ? (gap != 0.0 ? gap : -1e-30) : 1.0;
  }
}

void MultibodySystem::rearm_touches(const double* y) const {
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    if (touch_state_[k] != TouchState::Separating) continue;
    // the surfaces cannot be apart while a Gauss point (on the slave surface) is still inside;
    // armed at a positive gap, the root goes from 1 to it without a sign change
    if (contacts_[k].min_gap(y) > 0 && touch(k, y).gap > 0) touch_state_[k] = TouchState::Armed;
  }
}

const Touch& MultibodySystem::touch(std::size_t k, const double* y) const {
  update_quasistatic(y);
  return touches_[k].evaluate(y);
}

std::vector<ContactState> MultibodySystem::contact_states(const double* y) const {
  update_quasistatic(y);
  std::vector<ContactState> out;
  GeneralizedForce scratch;
  for (const SurfaceContact& c : contacts_) {
    scratch.reset(c.body().nq());
    out.push_back(c.apply(y, scratch, nullptr));
  }
  return out;
}

std::vector<ContactState> MultibodySystem::hertz_states(const double* y) const {
  std::vector<ContactState> out;
  GeneralizedForce a, b;
  for (const HertzContact& h : hertz_) out.push_back(h.apply(y, a, b));
  return out;
}

Energies MultibodySystem::energies(const double* y, const std::vector<ContactState>& states) const {
  Energies e;
  for (const auto& b : bodies_) {
    e.kinetic += b->kinetic_energy(y);
    e.elastic += b->elastic_energy(y);
    e.gravity += b->gravity_potential(y, gravity_);
  }
  for (const ContactState& s : states) e.penalty += s.penalty_energy;
  for (const ContactState& s : hertz_states(y)) e.penalty += s.penalty_energy;
  e.dissipated = y[size_ - 1];
  return e;
}

}  // namespace isosid::run
