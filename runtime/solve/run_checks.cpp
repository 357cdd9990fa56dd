// Checks of a scene against its loaded bodies; see run_checks.hpp.
#include "solve/run_checks.hpp"

#include "contact/default_penalty.hpp"
#include "contact/impact_estimate.hpp"
#include "isosid/common/number_text.hpp"
#include "isosid/format/error.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace isosid::run {

namespace {

using common::number_text;

/// The scene's name of body k of the system: flexible_body[i] or rigid_body[i].
std::string body_field(const Scene& scene, std::size_t k) {
  std::size_t index = 0;
  for (std::size_t j = 0; j < k; ++j) index += scene.bodies[j].rigid.has_value() == scene.bodies[k].rigid.has_value();
  return std::string(scene.bodies[k].rigid ? "rigid_body[" : "flexible_body[") + std::to_string(index) + "]";
}

/// The lowest and highest natural frequency (Hz) of a body's integrated modes that carry mass
/// (a massless boundary lists 0); both 0 without any.
std::pair<double, double> integrated_frequencies(const FloatingBody& body) {
  double lowest = 0, highest = 0;
  const Eigen::VectorXd& f = body.sid().refmod.frequencies_hz;
  for (Eigen::Index i = 0; i < body.n_dynamic() && i < f.size(); ++i) {
    if (!(f(i) > 0)) continue;
    lowest = lowest > 0 ? std::min(lowest, f(i)) : f(i);
    highest = std::max(highest, f(i));
  }
  return {lowest, highest};
}

}  // namespace

void refuse_implausible_penalties(const MultibodySystem& system, const Scene& scene) {
  for (std::size_t k = 0; k < system.contacts().size(); ++k) {
    const SurfaceContact& c = system.contacts()[k];
    if (c.exact() || c.penalty_source() != "scene") continue;  // exact contact: any augmentation converges
    // an adaptive body's penalty is meant for its refined models, not the coarse one here
    const BodySpec* body = scene.body(c.body().name());
    if (body && body->adaptive) continue;
    const double derived = derived_penalty(c, 0);
    const std::string field = "contact[" + std::to_string(k) + "].penalty";
    if (c.penalty() < kMinPenaltyRatio * derived)
      throw format::InputError(scene.file, field,
                               number_text(c.penalty()) + " N/m^3 is below 1e-8 of the penalty derived from the contact elements (" +
                                   number_text(derived) +
                                   " N/m^3, 1000 E*/h): so soft a layer, not the bodies, would take the impact and let them pass into each "
                                   "other (leave penalty out to have it derived)");
    if (c.penalty() > kMaxPenaltyRatio * derived)
      throw format::InputError(scene.file, field,
                               number_text(c.penalty()) + " N/m^3 is above 1e6 times the penalty derived from the contact elements (" +
                                   number_text(derived) +
                                   " N/m^3, 1000 E*/h): so stiff a layer changes no force, only shortens the steps until the run crawls "
                                   "(leave penalty out to have it derived)");
  }
}

void refuse_unstable_leapfrog_step(const MultibodySystem& system, const Scene& scene) {
  if (scene.simulation.integrator != IntegratorKind::Leapfrog) return;
  for (const auto& body : system.bodies()) {
    const double highest = integrated_frequencies(*body).second;
    if (!(highest > 0)) continue;
    const double limit = 2 / (2 * std::numbers::pi * highest);
    if (scene.simulation.step < limit) continue;
    throw format::InputError(scene.file, "simulation.step",
                             number_text(scene.simulation.step) + " s exceeds the leapfrog's stability limit 2/omega_max = " + number_text(limit) +
                                 " s of body '" + body->name() + "' (its highest integrated mode, " + number_text(highest) +
                                 " Hz; make the modes above quasistatic, or the step shorter)");
  }
}

void refuse_unsteady_spin(const MultibodySystem& system, const Scene& scene) {
  for (std::size_t k = 0; k < system.bodies().size(); ++k) {
    const FloatingBody& body = *system.bodies()[k];
    if (scene.bodies[k].elastic_start != "steady") continue;
    const double lowest = integrated_frequencies(body).first, spin = scene.bodies[k].angular_velocity.norm();
    if (!(lowest > 0) || spin < 2 * std::numbers::pi * lowest) continue;
    throw format::InputError(scene.file, body_field(scene, k) + ".angular_velocity",
                             number_text(spin) + " rad/s exceeds the lowest natural frequency of '" + body.name() + "' (" +
                                 number_text(2 * std::numbers::pi * lowest) + " rad/s, " + number_text(lowest) +
                                 " Hz): a body spinning faster has no steady state for elastic_start = \"steady\"");
  }
}

std::vector<std::string> closed_at_end_predictions(const MultibodySystem& system, double t0, double end_time) {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < system.contacts().size(); ++k)
    if (const auto& estimate = system.impact_estimates()[k])
      if (std::string w = closed_at_end_prediction(system.contacts()[k], *estimate, t0, end_time); !w.empty()) out.push_back(w);
  return out;
}

}  // namespace isosid::run
