// Phases of a run; see simulation.hpp.
#include "solve/simulation.hpp"

#include "isosid/common/number_text.hpp"
#include "isosid/format/error.hpp"
#include "solve/event_chatter.hpp"
#include "solve/run_checks.hpp"
#include "solve/static_start.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace isosid::run {
namespace {

using Clock = std::chrono::steady_clock;

Eigen::VectorXd initial_state(const MultibodySystem& system, const Scene& scene) {
  Eigen::VectorXd y0(system.size());
  system.initial_state(y0.data());
  std::vector<bool> static_start;
  for (const BodySpec& b : scene.bodies) static_start.push_back(b.elastic_start == "static");
  settle_static_start(system, static_start, y0.data());
  return y0;
}

/// The body whose state holds a non-finite value, for divergence messages.
std::string diverged_body(const MultibodySystem& system, const Eigen::VectorXd& y) {
  for (const auto& b : system.bodies())
    for (Eigen::Index i = 0; i < b->state_size(); ++i)
      if (!std::isfinite(y(b->offset() + i))) return b->name();
  return "";
}

}  // namespace

Simulation::Simulation(Scene scene, std::vector<format::Sid> sids)
    : scene_(std::move(scene)),
      system_(scene_, std::move(sids)),
      integrator_(make_integrator(system_, scene_.simulation, initial_state(system_, scene_))) {
  report_steps();
  refuse_implausible_penalties(system_, scene_);
  refuse_unstable_leapfrog_step(system_, scene_);
  refuse_unsteady_spin(system_, scene_);
  if (!scene_.simulation.allow_initial_penetration) refuse_initial_penetration();
}

Simulation::Simulation(Scene scene, std::vector<format::Sid> sids, double t0, const StartState& start_state, GivenPenalties given)
    : scene_(std::move(scene)), system_(scene_, std::move(sids), std::move(given)), integrator_(make_integrator(system_, scene_.simulation, estimated(start_state(system_)), t0)),
      t_(t0), continued_(true) {
  if (integrator_->y().size() != system_.size())
    throw format::ComputationError("a phase's start state has " + std::to_string(integrator_->y().size()) + " entries, its system " +
                                   std::to_string(system_.size()));
  // the next output time after t0 (outputs stay on the scene's grid of multiples of the interval)
  const double dt_out = scene_.simulation.output_interval;
  next_output_ = std::max(1L, long(std::floor(t0 / dt_out * (1 + 1e-12))) + 1);
  report_steps();
}

Eigen::VectorXd Simulation::estimated(Eigen::VectorXd y) {
  if (y.size() == system_.size()) system_.estimate_impacts(y.data());  // (a wrong size is refused below)
  return y;
}

void Simulation::report_steps() {
  integrator_->on_step([this](double t, const double* y) {
    system_.rearm_touches(y);
    if (collapse_) collapse_->observe(t);
    if (!observer_) return;
    observer_->step(t, y);
    if (observer_->interrupt_requested()) throw StepInterrupt{};
  });
}

void Simulation::refuse_initial_penetration() const {
  // bodies placed into each other are thrown apart by the penalty force at km/s: almost
  // always a mistake in the positions. The depth is geometric: the quasistatic modes have not
  // been solved yet (their elastic response would hide most of it).
  for (const SurfaceContact& c : system_.contacts()) {
    const double gap = c.min_gap(state().data());
    if (gap >= 0) continue;
    char depth[32];
    std::snprintf(depth, sizeof depth, "%.3g m", -gap);
    throw format::InputError(scene_.file, "contact " + c.name(),
                             "'" + c.body().name() + "' starts " + depth + " deep in '" + c.target().name() +
                                 "' (move the bodies apart, or set simulation.allow_initial_penetration = true)");
  }
}

void Simulation::start(SimulationObserver& observer) {
  observer.sample(t_, state().data());
  std::vector<double> gap(system_.contacts().size());
  system_.gaps(state().data(), gap.data());
  closed_.assign(gap.size(), 0);
  for (std::size_t k = 0; k < gap.size(); ++k)
    if (gap[k] < 0) {
      observer.contact_event(int(k), true, t_);  // starts in contact
      closed_[k] = 1;
    }
  if (continued_) return;  // the phase before saw its touches; the caller sets their state
  for (std::size_t k = 0; k < gap.size(); ++k) {
    const Touch& touch = system_.touch(k, state().data());
    if (!(touch.gap < 0)) continue;
    observer.touch(int(k), t_, touch);  // starts touching
    system_.touched(k);
  }
}

bool Simulation::advance_to(double t_end, SimulationObserver& observer) {
  observer_ = &observer;
  const double end = std::min(t_end, scene_.simulation.end_time), dt_out = scene_.simulation.output_interval;
  if (!fixed_step(scene_.simulation.integrator)) {
    double time_scale = dt_out;
    for (const auto& e : system_.impact_estimates())
      if (e && e->contact_time > 0) time_scale = std::min(time_scale, e->contact_time);
    collapse_.emplace(time_scale);
  }
  auto last_progress = Clock::now();
  EventChatter chatter(system_.contacts().size());
  try {
    while (t_ < end * (1 - 1e-12)) {
      if (observer.stop_requested()) break;
      const double tout = std::min(end, double(next_output_) * dt_out);
      std::vector<TimeIntegrator::GapEvent> events;
      try {
        events = integrator_->advance(tout, t_);
      } catch (const StepInterrupt&) {
        report_gap_changes_at_interrupt(observer);
        observer.sample(t_, state().data());  // the results end at the step it stopped at
        break;
      }
      if (!state().allFinite())
        throw format::ComputationError("the state of body '" + diverged_body(system_, state()) + "' is not finite");
      for (const auto& e : events) {
        const std::size_t k = std::size_t(e.contact);
        if (chatter.observe(e.contact, e.time)) {
          const SurfaceContact& c = system_.contacts()[std::size_t(chatter.worst())];
          throw format::ComputationError("contact '" + c.name() + "' changed " + std::to_string(EventChatter::kLimit) +
                                         " times between open and closed within " + common::number_text(EventChatter::kSpan) +
                                         " s: its points chatter, no contact the steps can resolve (bodies meeting at the edge of, or beyond, "
                                         "the contact surface of '" + c.body().name() + "'?)");
        }
        if (!e.touch) {
          observer.contact_event(e.contact, e.closing, e.time);
          closed_[k] = e.closing;
          if (!e.closing) system_.released(k);
        } else if (e.closing) {
          observer.touch(e.contact, e.time, system_.touch(k, state().data()));
          system_.touched(k);
        }
      }
      observer.sample(t_, state().data());
      if (events.empty() && t_ >= double(next_output_) * dt_out * (1 - 1e-12)) ++next_output_;
      if (std::chrono::duration<double>(Clock::now() - last_progress).count() > 1.0) {
        last_progress = Clock::now();
        observer.progress(t_, scene_.simulation.end_time, stats().steps);
      }
    }
  } catch (...) {
    observer_ = nullptr;
    collapse_.reset();
    throw;
  }
  observer_ = nullptr;
  collapse_.reset();
  return t_ >= end * (1 - 1e-12);
}

void Simulation::report_gap_changes_at_interrupt(SimulationObserver& observer) {
  std::vector<double> gap(system_.contacts().size());
  system_.gaps(state().data(), gap.data());
  for (std::size_t k = 0; k < gap.size(); ++k) {
    const bool closed = gap[k] < 0;
    if (closed == bool(closed_[k])) continue;
    observer.contact_event(int(k), closed, t_);  // within the last step: its end is the best time known
    closed_[k] = closed;
    if (!closed) system_.released(k);
  }
}

RunOutcome Simulation::run(SimulationObserver& observer) {
  RunOutcome outcome;
  const auto wall0 = Clock::now();
  const std::clock_t cpu0 = std::clock();
  try {
    start(observer);
    if (!advance_to(scene_.simulation.end_time, observer)) outcome.status = "interrupted";
  } catch (const format::ComputationError& e) {
    outcome.status = "failed";
    char when[64];
    std::snprintf(when, sizeof when, " (at t = %.6g s)", t_);
    outcome.failure = e.what() + std::string(when);
  }
  outcome.wall_time_s = std::chrono::duration<double>(Clock::now() - wall0).count();
  outcome.cpu_time_s = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return outcome;
}

}  // namespace isosid::run
