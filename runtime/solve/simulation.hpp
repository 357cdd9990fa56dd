// The simulation as a library call: a scene and its SIDs become a multibody system and an
// integrator; the run advances phase by phase and reports samples, accepted steps and
// contact events to an observer (the Recorder, or a test). isosid-run is a thin shell over it.
#pragma once
#include "scene/scene.hpp"
#include "solve/multibody_system.hpp"
#include "solve/step_collapse.hpp"
#include "solve/time_integrator.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace isosid::run {

/// What a run reports while it advances. Every call has the whole system state y.
class SimulationObserver {
public:
  virtual ~SimulationObserver() = default;
  /// A time-series sample: at the start, at every output time and at every contact event.
  virtual void sample(double t, const double* y) = 0;
  /// After every accepted integration step.
  virtual void step(double t, const double* y) = 0;
  /// A contact's gap changed sign at t: closing (onset) or opening (release).
  virtual void contact_event(int contact, bool closing, double t) = 0;
  /// A contact's exact surfaces touched at t (an impact's first instant), where `touch` says.
  virtual void touch(int /*contact*/, double /*t*/, const Touch& /*touch*/) {}
  /// Roughly once a second of wall time: how far the run is.
  virtual void progress(double /*t*/, double /*end_time*/, long /*steps*/) {}
  /// Asked between output samples: true ends the phase there (e.g. on a signal).
  virtual bool stop_requested() const { return false; }
  /// Asked at every accepted step: true ends the phase at that step (a signal, which must act
  /// within a second however small the steps).
  virtual bool interrupt_requested() const { return false; }
};

/// How a run (or a phase) ended.
struct RunOutcome {
  std::string status = "completed";  ///< "completed", "interrupted" (stop requested) or "failed"
  std::string failure;               ///< what failed and when (status "failed")
  double wall_time_s = 0, cpu_time_s = 0;  ///< of the integration
  bool completed() const { return status == "completed"; }
};

class Simulation {
public:
  /// `sids`: one per flexible body of the scene, in order. The scene is kept by value.
  /// Bodies that start interpenetrating are refused (InputError) unless the scene allows it.
  Simulation(Scene scene, std::vector<format::Sid> sids);
  /// A later phase of a run ([R2]'s phases on other models of the bodies): starts at time
  /// t0 in the state `start_state` makes for this scene's system, without a static start, and
  /// takes contacts that are closed there as they are. Its start reports no touches: where
  /// surfaces touch there, the phase before has seen it (MultibodySystem::touched/released
  /// set what the new phase should expect).
  /// `given`: penalties the caller gives contacts for this phase in place of the scene's.
  using StartState = std::function<Eigen::VectorXd(const MultibodySystem&)>;
  Simulation(Scene scene, std::vector<format::Sid> sids, double t0, const StartState& start_state, GivenPenalties given = {});

  const Scene& scene() const { return scene_; }
  const MultibodySystem& system() const { return system_; }
  double time() const { return t_; }
  /// The whole system state at time().
  const Eigen::VectorXd& state() const { return integrator_->y(); }
  IntegratorStats stats() const { return integrator_->stats(); }

  /// Reports the initial sample and the contacts that start closed; call once before advancing.
  void start(SimulationObserver& observer);
  /// Advances to t_end (at most the scene's end time), one phase: samples at the scene's
  /// output interval and at contact events. Returns false if the observer asked to stop
  /// before t_end. Throws ComputationError on failure (state and time stay at the last good
  /// step).
  bool advance_to(double t_end, SimulationObserver& observer);
  /// The whole run: start, then advance to the scene's end time; a failure or a stop ends
  /// the run with status "failed" or "interrupted" instead of throwing, so the results so far
  /// can be written.
  RunOutcome run(SimulationObserver& observer);

private:
  /// A continued phase's start state, with the contacts' impact estimates (and derived
  /// penalties) taken there.
  Eigen::VectorXd estimated(Eigen::VectorXd y);
  /// Accepted steps rearm the touches, go to the observer of advance_to and are watched for a
  /// collapse; an interrupt the observer asks for ends advance_to there.
  void report_steps();
  /// InputError naming the contact, the bodies and the depth if any contact starts closed.
  void refuse_initial_penetration() const;
  /// Tells the observer about the contacts whose gap changed sign within the step an interrupt
  /// stopped at: that step's root search never ran, so its events would be lost.
  void report_gap_changes_at_interrupt(SimulationObserver& observer);

  Scene scene_;
  MultibodySystem system_;
  std::unique_ptr<TimeIntegrator> integrator_;
  double t_ = 0;
  long next_output_ = 1;   ///< index of the next output time (multiples of output_interval)
  SimulationObserver* observer_ = nullptr;  ///< receives the accepted steps of advance_to
  std::optional<StepCollapse> collapse_;    ///< watches the accepted steps of advance_to (not the leapfrog's fixed ones)
  bool continued_ = false;  ///< a later phase of a run
  std::vector<char> closed_;  ///< each contact as the observer last heard of it (closed or open)
};

}  // namespace isosid::run
