// SUNDIALS ARKODE behind the TimeIntegrator interface: explicit Dormand-Prince 5(4) (ERKStep)
// or an implicit DIRK method with a dense Newton solver (ARKStep), both adaptive with a
// maximum step, with root finding on the contact gaps so that contact onset and release are
// located, and restarts from the last accepted step where a stage's static solve fails.
#pragma once
#include "solve/time_integrator.hpp"

namespace isosid::run {

/// ARKODE for settings.integrator (dopri5 or implicit), starting at y0 at time t0.
std::unique_ptr<TimeIntegrator> make_arkode_integrator(const MultibodySystem& system, const SimulationSettings& settings,
                                                       Eigen::VectorXd y0, double t0);

}  // namespace isosid::run
