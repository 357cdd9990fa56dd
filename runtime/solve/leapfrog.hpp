// Fixed-step leapfrog (Stoermer-Verlet, kick-drift-kick) for a MultibodySystem: the semi-explicit
// scheme of [R3] (docs/references.md). Every step evaluates the right-hand side once, which solves
// the static sub-problems (quasistatic modes, massless boundaries, joints) at the new positions;
// the velocities then take half a kick on each side of the drift. For the elastic coordinates of
// a body that does not rotate this is the symplectic Stoermer-Verlet method: energy stays
// bounded (no drift) for steps below 2 / omega_max. Velocity-dependent loads (gyroscopic,
// Coriolis, damping, friction) are taken at the half-step velocity: explicit, first order in
// them. So are those of the static sub-problems: the solution of the step's right-hand side
// stands for the step's end (its gaps and output), which differs only by the closing kick.
// Contact onset and release are found at the step they happen in (no root refinement).
#pragma once
#include "solve/time_integrator.hpp"

#include <Eigen/Dense>
#include <vector>

namespace isosid::run {

class Leapfrog : public TimeIntegrator {
public:
  /// Steps of at most `step`, at most max_steps of them over the run, from y0 at t0.
  Leapfrog(const MultibodySystem& system, double step, Eigen::VectorXd y0, long max_steps, double t0 = 0);

  /// Equal steps of at most the nominal one that end at tout (the output times are sampled),
  /// until tout or a step in which a contact's smallest gap changed sign: its zero is
  /// interpolated linearly between the step's ends.
  std::vector<GapEvent> advance(double tout, double& t) override;
  IntegratorStats stats() const override;

private:
  /// One step of `dt` from (t, y): y and t are updated in place; the contacts whose gap
  /// changed sign are added to `changed`.
  void step(double& t, double dt, std::vector<GapEvent>& changed);

  const MultibodySystem& system_;
  double step_;
  Eigen::VectorXd ydot_;                  ///< right-hand side at the current (t, y)
  std::vector<Eigen::Index> velocities_;  ///< entries of y that are velocities (integrated by kicks)
  std::vector<double> gaps_, new_gaps_;
  long steps_ = 0, evaluations_ = 0;
};

}  // namespace isosid::run
