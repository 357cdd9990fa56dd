// Time integration of a MultibodySystem behind one interface: SUNDIALS ARKODE's adaptive
// Dormand-Prince 5(4) and ESDIRK, with root finding on the contact gaps
// (solve/arkode_integrator), or the fixed-step leapfrog of [R3] in docs/references.md
// (solve/leapfrog). make_integrator gives the scene's from the integrators' table in
// time_integrator.cpp; a new scheme is one more class, its enumerator and one row there.
#pragma once
#include "scene/scene.hpp"
#include "solve/multibody_system.hpp"

#include <functional>
#include <memory>
#include <vector>

namespace isosid::run {

struct IntegratorStats {
  long steps = 0, attempts = 0, rhs_evaluations = 0, error_test_failures = 0;
  long newton_iterations = 0, jacobian_setups = 0;
  long restarts = 0;  ///< steps retried from the last accepted state, smaller (a stage's quasistatic solve failed)
};

/// How often in a row a step is retried a tenth smaller before the run fails.
constexpr int kMaxStepRetries = 8;

/// Thrown by a step callback to end advance() at the step just accepted: t and y() then hold
/// that step (a signal must act within a step, not only when the integrator returns).
struct StepInterrupt {};

class TimeIntegrator {
public:
  virtual ~TimeIntegrator() = default;
  TimeIntegrator(const TimeIntegrator&) = delete;
  TimeIntegrator& operator=(const TimeIntegrator&) = delete;

  /// Called after every accepted step with (t, y); it may throw StepInterrupt.
  void on_step(std::function<void(double, const double*)> callback) { step_callback_ = std::move(callback); }

  /// A contact whose gap changed sign: closing (onset) or opening (release).
  struct GapEvent {
    int contact;
    bool closing;
    double time;         ///< s: located by the root finder, or interpolated within a leapfrog step
    bool touch = false;  ///< the contact's exact surfaces (MultibodySystem::touch), not its Gauss points
  };
  /// Advances toward tout. Returns the contacts whose gap changed sign (empty if tout was
  /// reached); t and y() hold the state reached. Throws ComputationError on failure, with t
  /// and y() at the last accepted step.
  virtual std::vector<GapEvent> advance(double tout, double& t) = 0;
  const Eigen::VectorXd& y() const { return y_; }
  virtual IntegratorStats stats() const = 0;

protected:
  TimeIntegrator(Eigen::VectorXd y0, long max_steps) : y_(std::move(y0)), max_steps_(max_steps) {}
  Eigen::VectorXd y_;
  long max_steps_;  ///< over the whole run
  std::function<void(double, const double*)> step_callback_;
};

/// The scene's integrator, starting at y0 at time t0 (a later phase of a run starts where the
/// one before ended).
std::unique_ptr<TimeIntegrator> make_integrator(const MultibodySystem& system, const SimulationSettings& settings, Eigen::VectorXd y0,
                                                double t0 = 0);

}  // namespace isosid::run
