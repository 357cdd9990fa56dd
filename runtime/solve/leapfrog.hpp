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
#include "solve/multibody_system.hpp"

#include <Eigen/Dense>
#include <vector>

namespace isosid::run {

class Leapfrog {
public:
  Leapfrog(const MultibodySystem& system, double step, Eigen::VectorXd& y, double t0 = 0);

  /// One step of at most `dt` from (t, y): y and t are updated in place.
  void step(double& t, double dt);
  /// A contact whose smallest gap changed sign in the last step, and when: the zero of the
  /// gap interpolated linearly between the step's ends.
  struct GapChange {
    int contact;
    bool closing;
    double time;
  };
  const std::vector<GapChange>& gap_changes() const { return gap_changes_; }
  double nominal_step() const { return step_; }
  long steps() const { return steps_; }
  long rhs_evaluations() const { return evaluations_; }

private:
  const MultibodySystem& system_;
  double step_;
  Eigen::VectorXd& y_;
  Eigen::VectorXd ydot_;                  ///< right-hand side at the current (t, y)
  std::vector<Eigen::Index> velocities_;  ///< entries of y that are velocities (integrated by kicks)
  std::vector<double> gaps_, new_gaps_;
  std::vector<GapChange> gap_changes_;
  long steps_ = 0, evaluations_ = 0;
};

}  // namespace isosid::run
