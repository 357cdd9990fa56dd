// The scene's integrator; see time_integrator.hpp.
#include "solve/time_integrator.hpp"

#include "solve/arkode_integrator.hpp"
#include "solve/leapfrog.hpp"

namespace isosid::run {

std::unique_ptr<TimeIntegrator> make_integrator(const MultibodySystem& system, const SimulationSettings& s, Eigen::VectorXd y0, double t0) {
  switch (s.integrator) {
    case IntegratorKind::Leapfrog:
      return std::make_unique<Leapfrog>(system, s.step, std::move(y0), s.max_steps, t0);
    case IntegratorKind::Implicit:
    case IntegratorKind::DormandPrince:
      break;
  }
  return make_arkode_integrator(system, s, std::move(y0), t0);
}

}  // namespace isosid::run
