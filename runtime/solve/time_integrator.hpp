// Time integration of a MultibodySystem. SUNDIALS ARKODE: explicit Dormand-Prince 5(4)
// (ERKStep) or an implicit DIRK method with a dense Newton solver (ARKStep), both adaptive
// with a maximum step, and with root finding on the contact gaps so that contact onset and
// release are located. Or the fixed-step leapfrog of solve/leapfrog ([R3] in docs/references.md).
#pragma once
#include "scene/scene.hpp"
#include "solve/leapfrog.hpp"
#include "solve/multibody_system.hpp"

#include <functional>
#include <memory>

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
  /// Starts at y0 at time t0 (a later phase of a run starts where the one before ended).
  TimeIntegrator(const MultibodySystem& system, const SimulationSettings& settings, Eigen::VectorXd y0, double t0 = 0);
  ~TimeIntegrator();
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
  /// reached); t and y() hold the state reached. Throws ComputationError on failure.
  std::vector<GapEvent> advance(double tout, double& t);
  const Eigen::VectorXd& y() const { return y_; }
  IntegratorStats stats() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;  ///< ARKODE (dopri5, implicit)
  Eigen::VectorXd y_;
  std::unique_ptr<Leapfrog> leapfrog_;  ///< or the leapfrog
  long max_steps_;  ///< over the whole run (ARKODE counts per advance)
  std::function<void(double, const double*)> step_callback_;
};

}  // namespace isosid::run
