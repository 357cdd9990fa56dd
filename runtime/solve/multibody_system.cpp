// Assembly of the system ODE; see multibody_system.hpp.
#include "solve/multibody_system.hpp"

#include "contact/quasistatic_modes.hpp"
#include "isosid/format/error.hpp"


namespace isosid::run {

MultibodySystem::MultibodySystem(const Scene& scene, std::vector<format::Sid> sids) : gravity_(scene.gravity) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    auto b = std::make_unique<FlexibleBody>(scene.bodies[i], std::move(sids[i]), scene.simulation.dimension);
    b->set_offset(size_);
    size_ += b->state_size();
    bodies_.push_back(std::move(b));
  }
  size_ += 1;  // dissipated energy
  for (const ContactSpec& c : scene.contacts) {
    const PlaneSpec* plane = nullptr;
    for (const PlaneSpec& p : scene.planes)
      if (p.name == c.target) plane = &p;
    contacts_.emplace_back(c, body(c.body), *plane);
  }
  forces_.resize(bodies_.size());
  body_contacts_.resize(bodies_.size());
  for (const PlaneContact& c : contacts_)
    for (std::size_t i = 0; i < bodies_.size(); ++i)
      if (bodies_[i].get() == &c.body()) {
        body_contacts_[i].push_back(&c);
        contact_body_.push_back(i);
      }
}

void MultibodySystem::update_quasistatic(const double* y) const {
  for (std::size_t i = 0; i < bodies_.size(); ++i)
    if (bodies_[i]->n_quasistatic() > 0) quasistatic_iterations_ += solve_quasistatic_modes(*bodies_[i], body_contacts_[i], y);
}

const FlexibleBody& MultibodySystem::body(const std::string& name) const {
  for (const auto& b : bodies_)
    if (b->name() == name) return *b;
  throw format::InputError("scene", name, "no such body");
}

void MultibodySystem::initial_state(double* y) const {
  for (const auto& b : bodies_) b->initial_state(y);
  y[size_ - 1] = 0;
}

void MultibodySystem::rhs(double, const double* y, double* ydot) const {
  update_quasistatic(y);
  for (std::size_t i = 0; i < bodies_.size(); ++i) forces_[i].reset(bodies_[i]->nq());
  double dissipation = 0;
  for (std::size_t k = 0; k < contacts_.size(); ++k)
    dissipation += contacts_[k].apply(y, forces_[contact_body_[k]]).friction_power;
  for (std::size_t i = 0; i < bodies_.size(); ++i) dissipation += bodies_[i]->derivatives(y, forces_[i], gravity_, ydot);
  ydot[size_ - 1] = dissipation;
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

std::vector<ContactState> MultibodySystem::contact_states(const double* y) const {
  update_quasistatic(y);
  std::vector<ContactState> out;
  GeneralizedForce scratch;
  for (const PlaneContact& c : contacts_) {
    scratch.reset(c.body().nq());
    out.push_back(c.apply(y, scratch));
  }
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
  e.dissipated = y[size_ - 1];
  return e;
}

}  // namespace isosid::run
