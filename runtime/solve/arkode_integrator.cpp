// ARKODE behind the integrator interface; see arkode_integrator.hpp.
#include "solve/arkode_integrator.hpp"

#include "condensation/quasistatic_modes.hpp"
#include "isosid/common/number_text.hpp"
#include "isosid/format/error.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <utility>

namespace isosid::run {

namespace {

class ArkodeIntegrator : public TimeIntegrator {
public:
  ArkodeIntegrator(const MultibodySystem& system, const SimulationSettings& settings, Eigen::VectorXd y0, double t0);
  std::vector<GapEvent> advance(double tout, double& t) override;
  IntegratorStats stats() const override;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace

struct ArkodeIntegrator::Impl {
  const MultibodySystem& system;
  bool implicit;
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  void* memory = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver linear_solver = nullptr;
  ArkodeIntegrator* owner = nullptr;
  /// An exception from the right-hand side: it must not unwind through SUNDIALS' C frames,
  /// so the callback stores it, fails the step, and advance() rethrows it.
  mutable std::exception_ptr pending;
  mutable std::string recoverable_failure;  ///< the last right-hand side that asked for a smaller step
  long restarts = 0;                         ///< restarts from an accepted state with a smaller step
  mutable double accepted_t = 0;             ///< the last accepted step (the initial state before any)
  double restart_t = -1, restart_step = 0;   ///< where the last restart went back to, and its step
  int restarts_in_a_row = 0;                 ///< restarts from restart_t so far
  mutable Eigen::VectorXd accepted_y;
  /// ARKODE's last error message: kept for the failure message instead of printed, so that a
  /// failed run still says what went wrong in one line.
  std::string last_message;

  Impl(const MultibodySystem& s, bool imp) : system(s), implicit(imp) {}
  ~Impl() {
    if (memory) implicit ? ARKStepFree(&memory) : ERKStepFree(&memory);
    if (linear_solver) SUNLinSolFree(linear_solver);
    if (matrix) SUNMatDestroy(matrix);
    if (y) N_VDestroy(y);
    if (context) SUNContext_Free(&context);
  }

  static int rhs(realtype t, N_Vector y, N_Vector ydot, void* data) {
    const Impl* self = static_cast<const Impl*>(data);
    const double* yy = N_VGetArrayPointer(y);
    for (Eigen::Index i = 0; i < N_VGetLength(y); ++i)
      if (!std::isfinite(yy[i])) {  // recoverable: advance() restarts the step smaller
        self->recoverable_failure = "the state became non-finite at a trial stage";
        return 1;
      }
    return self->guarded([&] { self->system.rhs(t, yy, N_VGetArrayPointer(ydot)); }, true);
  }
  static int roots(realtype, N_Vector y, realtype* g, void* data) {
    const Impl* self = static_cast<const Impl*>(data);
    return self->guarded([&] { self->system.roots(N_VGetArrayPointer(y), g); });
  }
  static int post_step(realtype t, N_Vector y, void* data) {
    const Impl* self = static_cast<const Impl*>(data);
    return self->guarded([&] {
      self->accepted_t = t;
      self->accepted_y = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(y), N_VGetLength(y));
      if (self->owner->step_callback_) self->owner->step_callback_(t, N_VGetArrayPointer(y));
    });
  }
  static void record_message(int, const char*, const char*, char* message, void* data) {
    std::string& text = static_cast<Impl*>(data)->last_message;
    text = message;
    for (char& c : text)
      if (c == '\n') c = ' ';
  }
  /// Runs f for ARKODE: an exception is kept for advance() to rethrow. With
  /// `divergence_recoverable` (the right-hand side), a quasistatic Newton that did not converge
  /// asks for a smaller step instead: a trial stage that went too deep into contact.
  template <class F>
  int guarded(F&& f, bool divergence_recoverable = false) const {
    try {
      f();
      return 0;
    } catch (const QuasistaticDivergence& e) {
      if (divergence_recoverable) {
        recoverable_failure = e.what();  // explains a final failure if smaller steps do not help
        return 1;
      }
      pending = std::current_exception();
      return -1;
    } catch (...) {
      pending = std::current_exception();
      return -1;  // unrecoverable: ARKODE returns at once
    }
  }
  /// Where steps collapse, a hint at the penalty if a contact is closed at y (before any
  /// contact the penalty cannot be the cause), else "".
  std::string penalty_hint(const char* hint) const {
    std::vector<double> gap(system.contacts().size());
    system.gaps(N_VGetArrayPointer(y), gap.data());
    return std::any_of(gap.begin(), gap.end(), [](double g) { return g < 0; }) ? hint : "";
  }
  /// The body whose state carries the largest weighted local error estimate of the last
  /// attempted step: where a failing step size control has been looking.
  std::string worst_body() const {
    N_Vector error = N_VClone(y), weight = N_VClone(y);
    const bool ok = implicit ? ARKStepGetEstLocalErrors(memory, error) == 0 && ARKStepGetErrWeights(memory, weight) == 0
                             : ERKStepGetEstLocalErrors(memory, error) == 0 && ERKStepGetErrWeights(memory, weight) == 0;
    std::string name;
    double worst = -1;
    if (ok)
      for (const auto& b : system.bodies())
        for (Eigen::Index i = b->offset(); i < b->offset() + b->state_size(); ++i) {
          const double e = std::abs(N_VGetArrayPointer(error)[i] * N_VGetArrayPointer(weight)[i]);
          if (e > worst) worst = e, name = b->name();
        }
    N_VDestroy(error);
    N_VDestroy(weight);
    return name;
  }
};

namespace {
void check(int flag, const char* what) {
  if (flag < 0) throw format::ComputationError(std::string("SUNDIALS: ") + what + " failed (flag " + std::to_string(flag) + ")");
}
}  // namespace

ArkodeIntegrator::ArkodeIntegrator(const MultibodySystem& system, const SimulationSettings& s, Eigen::VectorXd y0, double t0)
    : TimeIntegrator(std::move(y0), s.max_steps), impl_(std::make_unique<Impl>(system, s.integrator == IntegratorKind::Implicit)) {
  Impl& m = *impl_;
  m.owner = this;
  check(SUNContext_Create(nullptr, &m.context), "context");
  m.y = N_VMake_Serial(y_.size(), y_.data(), m.context);  // shares y_'s storage
  m.accepted_y = y_;  // restarts go back to the initial state until a step is accepted
  m.accepted_t = t0;
  const int n_roots = int(system.root_count());
  if (m.implicit) {
    m.memory = ARKStepCreate(nullptr, Impl::rhs, t0, m.y, m.context);
    if (!m.memory) throw format::ComputationError("SUNDIALS: ARKStepCreate failed");
    check(ARKStepSetUserData(m.memory, &m), "user data");
    check(ARKStepSetErrHandlerFn(m.memory, Impl::record_message, &m), "error handler");
    check(ARKStepSStolerances(m.memory, s.rtol, s.atol), "tolerances");
    check(ARKStepSetMaxStep(m.memory, s.max_step), "max step");
    check(ARKStepSetMaxNumSteps(m.memory, s.max_steps), "max steps");
    check(ARKStepSetStopTime(m.memory, s.end_time), "stop time");
    // a stiffly accurate, L-stable ESDIRK of order 3: damps the high Craig-Bampton modes
    check(ARKStepSetTableNum(m.memory, ARKODE_ESDIRK324L2SA_4_2_3, ARKODE_ERK_NONE), "table");
    m.matrix = SUNDenseMatrix(y_.size(), y_.size(), m.context);
    m.linear_solver = SUNLinSol_Dense(m.y, m.matrix, m.context);
    check(ARKStepSetLinearSolver(m.memory, m.linear_solver, m.matrix), "linear solver");
    check(ARKStepSetPostprocessStepFn(m.memory, Impl::post_step), "post-step hook");
    if (n_roots) {
      check(ARKStepRootInit(m.memory, n_roots, Impl::roots), "root finding");
      check(ARKStepSetNoInactiveRootWarn(m.memory), "root warnings");
    }
  } else {
    m.memory = ERKStepCreate(Impl::rhs, t0, m.y, m.context);
    if (!m.memory) throw format::ComputationError("SUNDIALS: ERKStepCreate failed");
    check(ERKStepSetUserData(m.memory, &m), "user data");
    check(ERKStepSetErrHandlerFn(m.memory, Impl::record_message, &m), "error handler");
    check(ERKStepSetTableNum(m.memory, ARKODE_DORMAND_PRINCE_7_4_5), "Dormand-Prince table");
    check(ERKStepSStolerances(m.memory, s.rtol, s.atol), "tolerances");
    check(ERKStepSetMaxStep(m.memory, s.max_step), "max step");
    check(ERKStepSetMaxNumSteps(m.memory, s.max_steps), "max steps");
    check(ERKStepSetStopTime(m.memory, s.end_time), "stop time");
    check(ERKStepSetPostprocessStepFn(m.memory, Impl::post_step), "post-step hook");
    if (n_roots) {
      check(ERKStepRootInit(m.memory, n_roots, Impl::roots), "root finding");
      check(ERKStepSetNoInactiveRootWarn(m.memory), "root warnings");
    }
  }
}

std::vector<TimeIntegrator::GapEvent> ArkodeIntegrator::advance(double tout, double& t) {
  Impl& m = *impl_;
  realtype reached = t;
  int flag = 0;
  // ERKStep gives up on a right-hand side that asks for a smaller step (ARKStep retries it in
  // its nonlinear solver): restart it from the last accepted step with a tenth of the step
  // that failed, as long as the step stays resolvable in time. (On failure ARKODE returns the
  // time and state of the failed stage, not of the last accepted step.)
  for (;;) {
    flag = m.implicit ? ARKStepEvolve(m.memory, tout, m.y, &reached, ARK_NORMAL)
                      : ERKStepEvolve(m.memory, tout, m.y, &reached, ARK_NORMAL);
    if (m.pending) break;
    const bool rhs_failed = flag == ARK_RHSFUNC_FAIL || flag == ARK_REPTD_RHSFUNC_ERR || flag == ARK_UNREC_RHSFUNC_ERR;
    if (flag >= 0 || !rhs_failed || m.recoverable_failure.empty()) break;
    // failures in a row from the same accepted step shrink the step tenfold each
    if (m.accepted_t != m.restart_t) {
      m.restart_t = m.accepted_t;
      m.restarts_in_a_row = 0;
      m.implicit ? ARKStepGetCurrentStep(m.memory, &m.restart_step) : ERKStepGetCurrentStep(m.memory, &m.restart_step);
    }
    m.restart_step *= 0.1;
    if (++m.restarts_in_a_row > kMaxStepRetries || !(m.restart_step > 1e-14 * (1 + std::abs(m.accepted_t)))) {
      y_ = m.accepted_y;
      t = m.accepted_t;
      throw format::ComputationError(m.recoverable_failure + ", and steps down to " + common::number_text(10 * m.restart_step) +
                                     " s did not help");
    }
    y_ = m.accepted_y;  // m.y wraps y_'s storage
    reached = m.accepted_t;
    check(m.implicit ? ARKStepReset(m.memory, reached, m.y) : ERKStepReset(m.memory, reached, m.y), "restart after a failed stage");
    check(m.implicit ? ARKStepSetInitStep(m.memory, m.restart_step) : ERKStepSetInitStep(m.memory, m.restart_step), "initial step");
    // ARKODE lets the first step after a start grow 10^4-fold, straight back into the failure
    check(m.implicit ? ARKStepSetMaxFirstGrowth(m.memory, 2.0) : ERKStepSetMaxFirstGrowth(m.memory, 2.0), "first growth");
    m.recoverable_failure.clear();
    ++m.restarts;
  }
  t = reached;
  if (m.pending) {
    try {
      std::rethrow_exception(std::exchange(m.pending, nullptr));
    } catch (const StepInterrupt&) {  // ARKODE returned from the step the callback stopped at
      y_ = m.accepted_y;
      t = m.accepted_t;
      throw;
    }
  }
  if (flag < 0) {
    const std::string body = m.worst_body();
    throw format::ComputationError(
        "time integration failed" + (body.empty() ? "" : " in body '" + body + "'") +
        " (SUNDIALS flag " + std::to_string(flag) +
        (flag == -4 ? ": error test failed repeatedly, the step size fell to its minimum" + m.penalty_hint(" (penalty too stiff?)") : "") +
        (flag == -1 ? ": the step limit max_steps was reached" : "") +
        (flag != -4 && flag != -1 && !m.last_message.empty() ? ": " + m.last_message : "") + ")");
  }
  if (stats().steps > max_steps_) {
    const std::string body = m.worst_body();
    throw format::ComputationError("the step limit max_steps = " + std::to_string(max_steps_) + " was reached" +
                                   (body.empty() ? "" : ", steps limited by body '" + body + "'") +
                                   m.penalty_hint(" (penalty too stiff for the contact resolution?)"));
  }
  std::vector<GapEvent> changed;
  if (flag == ARK_ROOT_RETURN) {
    std::vector<int> info(m.system.root_count());  // +1: gap increasing, -1: decreasing
    m.implicit ? ARKStepGetRootInfo(m.memory, info.data()) : ERKStepGetRootInfo(m.memory, info.data());
    const std::size_t n = m.system.contacts().size();
    for (std::size_t k = 0; k < info.size(); ++k)
      if (info[k] != 0) changed.push_back({int(k % n), info[k] < 0, reached, k >= n});
  }
  return changed;
}

IntegratorStats ArkodeIntegrator::stats() const {
  const Impl& m = *impl_;
  IntegratorStats s;
  long fe = 0, fi = 0;
  if (m.implicit) {
    ARKStepGetNumSteps(m.memory, &s.steps);
    ARKStepGetNumStepAttempts(m.memory, &s.attempts);
    ARKStepGetNumRhsEvals(m.memory, &fe, &fi);
    s.rhs_evaluations = fe + fi;
    ARKStepGetNumErrTestFails(m.memory, &s.error_test_failures);
    ARKStepGetNumNonlinSolvIters(m.memory, &s.newton_iterations);
    ARKStepGetNumLinSolvSetups(m.memory, &s.jacobian_setups);
  } else {
    ERKStepGetNumSteps(m.memory, &s.steps);
    ERKStepGetNumStepAttempts(m.memory, &s.attempts);
    ERKStepGetNumRhsEvals(m.memory, &s.rhs_evaluations);
    ERKStepGetNumErrTestFails(m.memory, &s.error_test_failures);
  }
  s.restarts = m.restarts;
  return s;
}

std::unique_ptr<TimeIntegrator> make_arkode_integrator(const MultibodySystem& system, const SimulationSettings& settings, Eigen::VectorXd y0,
                                                       double t0) {
  return std::make_unique<ArkodeIntegrator>(system, settings, std::move(y0), t0);
}

}  // namespace isosid::run
