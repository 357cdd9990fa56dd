// The integrators' table and the scene's integrator; see time_integrator.hpp.
#include "solve/time_integrator.hpp"

#include "solve/arkode_integrator.hpp"
#include "solve/leapfrog.hpp"

#include <stdexcept>

namespace isosid::run {

namespace {

using Factory = std::unique_ptr<TimeIntegrator> (*)(const MultibodySystem&, const SimulationSettings&, Eigen::VectorXd, double);

struct IntegratorRow {
  IntegratorKind kind;
  const char* name;
  bool fixed_step;
  Factory make;
};

std::unique_ptr<TimeIntegrator> make_leapfrog(const MultibodySystem& system, const SimulationSettings& s, Eigen::VectorXd y0, double t0) {
  return std::make_unique<Leapfrog>(system, s.step, std::move(y0), s.max_steps, t0);
}

/// Every integrator: a new scheme is its class and one row here (with its enumerator).
constexpr IntegratorRow kIntegrators[] = {
    {IntegratorKind::DormandPrince, "dopri5", false, make_arkode_integrator},
    {IntegratorKind::Implicit, "implicit", false, make_arkode_integrator},
    {IntegratorKind::Leapfrog, "leapfrog", true, make_leapfrog},
};

const IntegratorRow& row(IntegratorKind kind) {
  for (const IntegratorRow& r : kIntegrators)
    if (r.kind == kind) return r;
  throw std::logic_error("an integrator kind without a row in the integrators' table");
}

}  // namespace

std::optional<IntegratorKind> integrator_named(std::string_view name) {
  for (const IntegratorRow& r : kIntegrators)
    if (name == r.name) return r.kind;
  return std::nullopt;
}

const char* integrator_name(IntegratorKind kind) { return row(kind).name; }

std::string integrator_names() {
  std::string out;
  for (const IntegratorRow& r : kIntegrators) out += (out.empty() ? "" : ", ") + std::string(r.name);
  return out;
}

bool fixed_step(IntegratorKind kind) { return row(kind).fixed_step; }

std::unique_ptr<TimeIntegrator> make_integrator(const MultibodySystem& system, const SimulationSettings& s, Eigen::VectorXd y0, double t0) {
  return row(s.integrator).make(system, s, std::move(y0), t0);
}

}  // namespace isosid::run
