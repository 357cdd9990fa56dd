// The scene's [simulation] table; see scene_reading.hpp.
#include "scene/scene_reading.hpp"

#include "isosid/common/number_text.hpp"

#include <cstdio>

namespace isosid::run::scene_reading {

/// Bounds of the step-size control's tolerances. Above a relative tolerance of 0.1 the
/// error estimate of an embedded pair no longer describes the solution (its asymptotic
/// expansion needs small errors): the steps grow until contacts are stepped over. Below
/// 1e-12 it asks for less than the round-off of the sums over contact points and modes, and
/// the step collapses. The absolute tolerance is the error allowed where a component is near
/// zero: the state holds positions in metres and mass-normalized elastic coordinates, whose
/// size is the elastic displacement (micrometres in an impact) times the root of the mass;
/// above 1e-6 an impact's deformation would go uncontrolled (the shipped scenes use 1e-12
/// to 1e-9).
namespace {
constexpr double kMinRtol = 1e-12, kMaxRtol = 0.1, kMaxAtol = 1e-6;

void read_tolerances(const TomlView& s, SimulationSettings& out) {
  out.rtol = s.positive("rtol", out.rtol);
  if (out.rtol < kMinRtol || out.rtol > kMaxRtol) s.fail("rtol", "must lie in [1e-12, 0.1], is " + common::number_text(out.rtol));
  out.atol = s.positive("atol", out.atol);
  if (out.atol > kMaxAtol)
    s.fail("atol", "must lie in (0, 1e-6] (metres and elastic coordinates of micrometre deformations), is " + common::number_text(out.atol));
}
}  // namespace

void check_step_count(const TomlView& t, const char* key, double step, const SimulationSettings& sim) {
  if (const double steps = sim.end_time / step; steps > double(sim.max_steps)) {
    char count[64];
    std::snprintf(count, sizeof count, "%.3g steps", steps);
    t.fail(key, std::string("end_time / ") + key + " needs at least " + count + ", more than max_steps = " + std::to_string(sim.max_steps));
  }
}

IntegratorKind read_integrator(const TomlView& t, const std::string& key, IntegratorKind fallback) {
  if (!t.has(key)) return fallback;
  const std::string name = t.string(key);
  if (const std::optional<IntegratorKind> kind = integrator_named(name)) return *kind;
  t.fail(key, "unknown integrator '" + name + "' (" + integrator_names() + ")");
}

SimulationSettings read_simulation(const TomlView& s) {
  s.allow_only({"dimension", "end_time", "integrator", "step", "rtol", "atol", "max_step", "max_steps", "output_interval", "gravity",
                "allow_initial_penetration", "joint_stabilization"});
  SimulationSettings out;
  const std::string dim = s.string("dimension");
  if (dim == "planar")
    out.dimension = Dimension::Planar;
  else if (dim == "axisymmetric")
    out.dimension = Dimension::Axisymmetric;
  else if (dim == "3d")
    out.dimension = Dimension::Solid;
  else
    s.fail("dimension", "unknown dimension '" + dim + "' (planar, axisymmetric, 3d)");
  out.end_time = s.positive("end_time");
  out.integrator = read_integrator(s, "integrator", IntegratorKind::DormandPrince);
  if (fixed_step(out.integrator)) {
    // fixed steps: the step-size control's keys have nothing to control
    out.step = s.positive("step");
    if (out.step > out.end_time) s.fail("step", "exceeds end_time");
    for (const char* key : {"rtol", "atol", "max_step"})
      if (s.has(key)) s.fail(key, std::string("not used by the ") + integrator_name(out.integrator) + " integrator (its step is fixed: step)");
  } else if (s.has("step")) {
    s.fail("step", "only used by integrator = \"leapfrog\" (dopri5 and implicit choose their steps; see max_step)");
  }
  read_tolerances(s, out);
  out.max_step = s.positive("max_step", out.end_time);
  out.max_steps = long(s.integer("max_steps", out.max_steps));
  if (out.max_steps < 1) s.fail("max_steps", "must be at least 1");
  out.output_interval = s.positive("output_interval", out.end_time / 1000);
  out.joint_stabilization = s.positive("joint_stabilization", out.joint_stabilization);
  if (out.output_interval > out.end_time) s.fail("output_interval", "exceeds end_time");
  // work that could never finish is refused before it starts
  char count[64];
  if (const double samples = out.end_time / out.output_interval; samples > kMaxSamples) {
    std::snprintf(count, sizeof count, "%.3g samples", samples);
    s.fail("output_interval", std::string("end_time / output_interval asks for ") + count + ", more than the limit of 1e7");
  }
  const bool fixed = fixed_step(out.integrator);
  check_step_count(s, fixed ? "step" : "max_step", fixed ? out.step : out.max_step, out);
  out.allow_initial_penetration = s.boolean("allow_initial_penetration", false);
  return out;
}

}  // namespace isosid::run::scene_reading
