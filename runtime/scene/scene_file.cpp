// Scene file parsing and validation; see scene.hpp.
#include "scene/scene.hpp"

#include "scene/run_warning.hpp"

#include "body/floating_body.hpp"
#include "isosid/common/number_text.hpp"
#include "isosid/common/toml_fields.hpp"
#include "isosid/format/file_kind.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <set>

namespace isosid::run {
namespace {

using common::TomlView;
namespace fs = std::filesystem;

Eigen::Vector3d vec3(const TomlView& t, const std::string& key, const Eigen::Vector3d& fallback) {
  if (!t.has(key)) return fallback;
  const auto v = t.numbers(key);
  if (v.size() != 3) t.fail(key, "needs three components");
  return {v[0], v[1], v[2]};
}

Eigen::Vector3d unit_vector(const TomlView& t, const std::string& key, const Eigen::Vector3d& fallback) {
  const Eigen::Vector3d n = vec3(t, key, fallback);
  if (n.norm() < 1e-12) t.fail(key, "must not be zero");
  return n.normalized();
}

/// The fastest initial speed of a body, m/s: no solid carries elastic waves faster than about
/// 13 km/s (beryllium, diamond), and an impact at the wave speed is a shock, outside the
/// linear elasticity of SIDs; faster values are typing errors, and would overflow the Hertz
/// estimate (its contact radius grows as v^(2/5), its energy as v^2).
constexpr double kMaxSpeed = 2e4;
/// The strongest gravity, m/s^2: ten times an ultracentrifuge's 1e6 g.
constexpr double kMaxGravity = 1e8;

/// Refuses initial motion the bodies cannot take: a planar or axisymmetric scene locks the
/// DOFs that leave its symmetry, and a body's `locked` list more; the runtime holds those
/// DOFs at zero, so a velocity or orientation there would be dropped without a word.
void check_motion_fits(const TomlView& b, const BodySpec& f, Dimension dimension) {
  if (dimension == Dimension::Axisymmetric && (f.position.x() != 0 || f.position.z() != 0))
    b.fail("position", "an axisymmetric scene needs its bodies on the axis (x = z = 0)");
  // what the dimension leaves free: axisymmetric y only, planar x, y and rz
  const std::array<bool, 6> locked = locked_dofs(dimension, {});
  const std::string why = dimension == Dimension::Axisymmetric ? "an axisymmetric scene moves its bodies along the axis only"
                          : dimension == Dimension::Planar     ? "a planar scene moves its bodies in the x-y plane only"
                                                               : "";
  // an orientation may turn the body over (pi about x or z) but must keep its section in the
  // plane: the body's z axis on the world's (both), and its y axis on the world's (axisymmetric)
  const Eigen::Matrix3d A = tait_bryan_matrix(f.tait_bryan);
  const double tilt_z = Eigen::Vector2d(A(0, 2), A(1, 2)).norm(), tilt_y = Eigen::Vector2d(A(0, 1), A(2, 1)).norm();
  if ((dimension != Dimension::Solid && tilt_z > 1e-12) || (dimension == Dimension::Axisymmetric && tilt_y > 1e-12))
    b.fail("orientation", why + " (it may turn a body over, by pi about x or z, but not tilt it)");
  for (int a = 0; a < 3; ++a) {
    const auto i = std::size_t(a);
    if (locked[i] && f.velocity(a) != 0) b.fail("velocity", why + " (no " + kFrameDofNames[i] + " component)");
    if (locked[3 + i] && f.angular_velocity(a) != 0) b.fail("angular_velocity", why + " (no " + kFrameDofNames[3 + i] + " component)");
  }
  for (const std::string& l : f.locked)
    for (int a = 0; a < 3; ++a) {
      const auto i = std::size_t(a);
      if (l == kFrameDofNames[i] && f.velocity(a) != 0) b.fail("velocity", "moves along the locked DOF '" + l + "'");
      if (l == kFrameDofNames[3 + i] && f.angular_velocity(a) != 0) b.fail("angular_velocity", "turns about the locked DOF '" + l + "'");
    }
}

/// Name, initial motion and locked DOFs, common to flexible and rigid bodies.
BodySpec read_motion(const TomlView& b, const std::string& name, Dimension dimension) {
  BodySpec f;
  f.name = name;
  f.position = vec3(b, "position", f.position);
  f.tait_bryan = vec3(b, "orientation", f.tait_bryan);
  f.velocity = vec3(b, "velocity", f.velocity);
  f.angular_velocity = vec3(b, "angular_velocity", f.angular_velocity);
  if (b.has("locked"))
    for (const std::string& l : b.strings("locked")) {
      if (l != "x" && l != "y" && l != "z" && l != "rx" && l != "ry" && l != "rz") b.fail("locked", "unknown DOF '" + l + "'");
      f.locked.push_back(l);
    }
  if (f.velocity.stableNorm() > kMaxSpeed)
    b.fail("velocity", "a speed of " + common::number_text(f.velocity.stableNorm()) + " m/s exceeds 2e4 m/s, beyond the wave speed of any solid");
  check_motion_fits(b, f, dimension);
  return f;
}

/// Shape, mass (from `mass` or `density`) and principal inertia (given, or of the solid shape).
RigidShape read_rigid_shape(const TomlView& b, Dimension dimension) {
  RigidShape r;
  const std::string shape = b.string("shape");
  double volume = 0;
  Eigen::Vector3d unit_inertia;  // per unit mass
  if (shape == "sphere") {
    r.kind = RigidShape::Kind::Sphere;
    r.radius = b.positive("radius");
    if (b.has("size")) b.fail("size", "a sphere has a radius, not a size");
    volume = 4.0 / 3.0 * M_PI * std::pow(r.radius, 3);
    unit_inertia.setConstant(0.4 * r.radius * r.radius);
  } else if (shape == "box") {
    if (dimension == Dimension::Axisymmetric) b.fail("shape", "a box is not axisymmetric");
    if (b.has("radius")) b.fail("radius", "a box has a size, not a radius");
    const Eigen::Vector3d size = vec3(b, "size", Eigen::Vector3d::Zero());
    if (size.minCoeff() <= 0) b.fail("size", "all three edge lengths must be > 0");
    r.kind = RigidShape::Kind::Box;
    r.half_extents = size / 2;
    volume = size.prod();
    const Eigen::Vector3d s2 = size.cwiseAbs2();
    unit_inertia = Eigen::Vector3d(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y()) / 12.0;
  } else {
    b.fail("shape", "unknown shape '" + shape + "' (sphere, box)");
  }
  if (b.has("mass") == b.has("density")) b.fail("mass", "give either a mass or a density");
  r.mass = b.has("mass") ? b.positive("mass") : b.positive("density") * volume;
  r.principal_inertia = r.mass * unit_inertia;
  if (b.has("inertia")) {
    r.principal_inertia = vec3(b, "inertia", r.principal_inertia);
    const Eigen::Vector3d& I = r.principal_inertia;
    if (I.minCoeff() <= 0 || I.x() > I.y() + I.z() || I.y() > I.x() + I.z() || I.z() > I.x() + I.y())
      b.fail("inertia", "principal moments must be > 0 and satisfy the triangle inequality");
  }
  return r;
}

/// Fixed surfaces a planar or axisymmetric scene can hold: its bodies stay in the x-y plane
/// (planar) or on the y axis (axisymmetric), so a surface must keep that symmetry.
void check_fits_dimension(const ShapeSpec& s, Dimension dimension, const TomlView& top) {
  const Eigen::Vector3d &p = s.point, &n = s.normal;
  std::string problem;
  if (dimension == Dimension::Axisymmetric) {
    if (s.kind == ShapeSpec::Kind::Plane && std::abs(std::abs(n.y()) - 1) > 1e-12) problem = "a plane must be normal to the axis (y)";
    if (s.kind == ShapeSpec::Kind::Sphere && (p.x() != 0 || p.z() != 0)) problem = "a sphere must be centred on the axis (x = z = 0)";
    if (s.kind == ShapeSpec::Kind::Cylinder) problem = "a cylinder across the axis is not axisymmetric";
  } else if (dimension == Dimension::Planar) {
    if (s.kind == ShapeSpec::Kind::Plane && std::abs(n.z()) > 1e-12) problem = "a plane must be normal to the x-y plane";
    if (s.kind == ShapeSpec::Kind::Sphere && p.z() != 0) problem = "a sphere must be centred in the x-y plane";
    if (s.kind == ShapeSpec::Kind::Cylinder && std::abs(std::abs(n.z()) - 1) > 1e-12) problem = "a cylinder axis must be z";
  }
  if (!problem.empty()) throw format::InputError(top.file(), s.name, problem + " in a " + to_string(dimension) + " scene");
}

std::string resolve(const std::string& scene_file, const std::string& path) {
  if (path.empty() || fs::path(path).is_absolute()) return path;
  return (fs::path(scene_file).parent_path() / path).lexically_normal().string();
}

/// Bounds of the step-size control's tolerances. Above a relative tolerance of 0.1 the
/// error estimate of an embedded pair no longer describes the solution (its asymptotic
/// expansion needs small errors): the steps grow until contacts are stepped over. Below
/// 1e-12 it asks for less than the round-off of the sums over contact points and modes, and
/// the step collapses. The absolute tolerance is the error allowed where a component is near
/// zero: the state holds positions in metres and mass-normalized elastic coordinates, whose
/// size is the elastic displacement (micrometres in an impact) times the root of the mass;
/// above 1e-6 an impact's deformation would go uncontrolled (the shipped scenes use 1e-12
/// to 1e-9).
constexpr double kMinRtol = 1e-12, kMaxRtol = 0.1, kMaxAtol = 1e-6;

void read_tolerances(const TomlView& s, SimulationSettings& out) {
  out.rtol = s.positive("rtol", out.rtol);
  if (out.rtol < kMinRtol || out.rtol > kMaxRtol) s.fail("rtol", "must lie in [1e-12, 0.1], is " + common::number_text(out.rtol));
  out.atol = s.positive("atol", out.atol);
  if (out.atol > kMaxAtol)
    s.fail("atol", "must lie in (0, 1e-6] (metres and elastic coordinates of micrometre deformations), is " + common::number_text(out.atol));
}

/// A step limit that needs more than max_steps steps to reach end_time could never finish.
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
  if (name == "dopri5") return IntegratorKind::DormandPrince;
  if (name == "implicit") return IntegratorKind::Implicit;
  if (name == "leapfrog") return IntegratorKind::Leapfrog;
  t.fail(key, "unknown integrator '" + name + "' (dopri5, implicit, leapfrog)");
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
  if (out.integrator == IntegratorKind::Leapfrog) {
    // fixed steps: the step-size control's keys have nothing to control
    out.step = s.positive("step");
    if (out.step > out.end_time) s.fail("step", "exceeds end_time");
    for (const char* key : {"rtol", "atol", "max_step"})
      if (s.has(key)) s.fail(key, "not used by the leapfrog (its step is fixed: step)");
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
  const bool leapfrog = out.integrator == IntegratorKind::Leapfrog;
  check_step_count(s, leapfrog ? "step" : "max_step", leapfrog ? out.step : out.max_step, out);
  out.allow_initial_penetration = s.boolean("allow_initial_penetration", false);
  return out;
}

}  // namespace

std::string to_string(Dimension d) {
  switch (d) {
    case Dimension::Planar: return "planar";
    case Dimension::Axisymmetric: return "axisymmetric";
    case Dimension::Solid: return "3d";
  }
  return "?";
}

const BodySpec* Scene::body(const std::string& name) const {
  for (const BodySpec& b : bodies)
    if (b.name == name) return &b;
  return nullptr;
}

const ShapeSpec* Scene::fixed_surface(const std::string& name) const {
  for (const ShapeSpec& s : fixed_surfaces)
    if (s.name == name) return &s;
  return nullptr;
}

Scene read_scene_file(const std::string& path, const std::vector<common::TomlOverride>& overrides) {
  toml::table root = common::parse_toml_file(path);
  common::apply_overrides(root, overrides, path);
  const TomlView top(root, path);
  top.allow_only({"simulation", "flexible_body", "rigid_body", "fixed_plane", "fixed_sphere", "fixed_cylinder", "contact",
                  "hertz_contact", "joint", "monitor", "reference", "output", "adaptive"});
  Scene scene;
  scene.file = path;
  for (const common::TomlOverride& o : overrides) scene.overrides.push_back(o.text());
  scene.simulation = read_simulation(top.table("simulation"));
  if (auto o = top.optional_table("output")) {
    o->allow_only({"paraview", "paraview_interval", "expected_warnings"});
    scene.output.paraview = o->boolean("paraview", false);
    if (o->has("paraview_interval")) {
      scene.output.paraview_interval = o->positive("paraview_interval");
      if (scene.output.paraview_interval < scene.simulation.output_interval)
        o->fail("paraview_interval", "is shorter than the output interval (frames are written at output samples)");
      if (scene.output.paraview_interval > scene.simulation.end_time) o->fail("paraview_interval", "exceeds end_time");
    }
    if (o->has("expected_warnings")) scene.output.expected_warnings = o->strings("expected_warnings");
    for (const std::string& kind : scene.output.expected_warnings)
      if (!is_warning_kind(kind)) {
        std::string kinds;
        for (const std::string_view k : kWarningKinds) kinds += (kinds.empty() ? "" : ", ") + std::string(k);
        o->fail("expected_warnings", "'" + kind + "' is no kind of warning (" + kinds + ")");
      }
  }
  std::set<std::string> names;
  auto unique = [&](const TomlView& t) {
    // names become HDF5 groups of results.h5 and keys of summary.json
    const std::string name = t.name("name");
    if (!names.insert(name).second) t.fail("name", "duplicate name '" + name + "'");
    return name;
  };
  for (const TomlView& b : top.tables("flexible_body")) {
    b.allow_only({"name", "sid", "model", "position", "orientation", "velocity", "angular_velocity", "q0", "qdot0", "locked",
                  "high_modes", "quasistatic_above_hz", "elastic_start", "adaptive"});
    BodySpec f = read_motion(b, unique(b), scene.simulation.dimension);
    f.adaptive = b.boolean("adaptive", false);
    if (f.adaptive && b.has("sid")) b.fail("sid", "an adaptive body's SIDs are built from its model (drop sid)");
    f.sid_file = f.adaptive ? "" : resolve(path, b.string("sid"));
    f.model_file = resolve(path, b.string("model", ""));
    if (f.adaptive && f.model_file.empty()) b.fail("model", "an adaptive body needs its model file (with [refinement.hierarchical])");
    for (const char* key : {"q0", "qdot0"})
      if (f.adaptive && b.has(key)) b.fail(key, "an adaptive body changes its model (and its coordinates) at each impact: start it at rest");
    const auto require_file = [&](const char* key, const std::string& file) {
      if (const std::string problem = format::input_file_problem(file); !problem.empty()) b.fail(key, problem + ": " + file);
    };
    if (!f.model_file.empty()) require_file("model", f.model_file);
    if (!f.adaptive && f.model_file.empty()) require_file("sid", f.sid_file);
    if (b.has("q0")) {
      const auto v = b.numbers("q0");
      f.q0 = Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(v.size()));
    }
    if (b.has("qdot0")) {
      const auto v = b.numbers("qdot0");
      f.qdot0 = Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(v.size()));
    }
    f.elastic_start = b.string("elastic_start", f.elastic_start);
    if (f.elastic_start != "rest" && f.elastic_start != "steady" && f.elastic_start != "static")
      b.fail("elastic_start", "must be rest, steady or static");
    if (f.elastic_start != "rest" && (b.has("q0") || b.has("qdot0"))) b.fail("elastic_start", f.elastic_start + " replaces q0 and qdot0");
    f.high_modes = b.string("high_modes", f.high_modes);
    if (f.high_modes != "dynamic" && f.high_modes != "quasistatic") b.fail("high_modes", "must be dynamic or quasistatic");
    f.quasistatic_above_hz = b.positive("quasistatic_above_hz", -1);
    if (b.has("quasistatic_above_hz") && f.high_modes != "quasistatic")
      b.fail("quasistatic_above_hz", "only used with high_modes = \"quasistatic\"");
    scene.bodies.push_back(f);
  }
  for (const TomlView& b : top.tables("rigid_body")) {
    b.allow_only({"name", "shape", "radius", "size", "density", "mass", "inertia", "position", "orientation", "velocity",
                  "angular_velocity", "locked"});
    BodySpec r = read_motion(b, unique(b), scene.simulation.dimension);
    r.rigid = read_rigid_shape(b, scene.simulation.dimension);
    scene.bodies.push_back(r);
  }
  for (const TomlView& p : top.tables("fixed_plane")) {
    p.allow_only({"name", "point", "normal"});
    ShapeSpec s{ShapeSpec::Kind::Plane, unique(p)};
    s.point = vec3(p, "point", s.point);
    s.normal = unit_vector(p, "normal", s.normal);
    scene.fixed_surfaces.push_back(s);
  }
  for (const TomlView& p : top.tables("fixed_sphere")) {
    p.allow_only({"name", "center", "radius"});
    ShapeSpec s{ShapeSpec::Kind::Sphere, unique(p)};
    s.point = vec3(p, "center", s.point);
    s.radius = p.positive("radius");
    scene.fixed_surfaces.push_back(s);
  }
  for (const TomlView& p : top.tables("fixed_cylinder")) {
    p.allow_only({"name", "point", "axis", "radius"});
    ShapeSpec s{ShapeSpec::Kind::Cylinder, unique(p)};
    s.point = vec3(p, "point", s.point);
    s.normal = unit_vector(p, "axis", Eigen::Vector3d::UnitZ());
    s.radius = p.positive("radius");
    scene.fixed_surfaces.push_back(s);
  }
  for (const ShapeSpec& s : scene.fixed_surfaces) check_fits_dimension(s, scene.simulation.dimension, top);
  for (const TomlView& c : top.tables("contact")) {
    c.allow_only({"name", "body", "surface", "target", "target_surface", "penalty", "friction", "regularization", "enforcement"});
    ContactSpec s;
    s.name = unique(c);
    s.body = c.string("body");
    s.surface = c.string("surface");
    s.target = c.string("target");
    s.target_surface = c.string("target_surface", "");
    s.penalty = c.positive("penalty", 0.0);  // 0: derived from the bodies (contact/default_penalty.hpp)
    s.friction = c.number("friction", 0.0);
    if (s.friction < 0 || s.friction > 10) c.fail("friction", "must lie in [0, 10]");
    s.regularization = c.positive("regularization", s.regularization);
    // the friction law's slope at rest is friction x normal force / regularization: below 1e-9
    // m/s it is a step no solver resolves, above 1 m/s friction hardly acts in an impact
    if (s.regularization < 1e-9 || s.regularization > 1)
      c.fail("regularization", "must lie in [1e-9, 1] m/s (the sliding speed below which friction is smoothed)");
    const std::string enforcement = c.string("enforcement", "penalty");
    if (enforcement != "penalty" && enforcement != "exact") c.fail("enforcement", "must be penalty or exact");
    s.exact = enforcement == "exact";
    // the augmented Lagrangian solves the boundary at the start of each fixed step; under an
    // adaptive integrator its contact set switches inside the stages and the steps chatter
    if (s.exact && scene.simulation.integrator != IntegratorKind::Leapfrog)
      c.fail("enforcement", "exact contact needs integrator = \"leapfrog\"");
    const BodySpec* slave = scene.body(s.body);
    if (!slave || slave->rigid) c.fail("body", "no flexible_body named '" + s.body + "' (the slave side carries the contact points)");
    const BodySpec* master = scene.body(s.target);
    if (!master && !scene.fixed_surface(s.target)) c.fail("target", "no fixed surface or body named '" + s.target + "'");
    if (master == slave) c.fail("target", "a body cannot be its own contact target");
    if (master && !master->rigid && s.target_surface.empty())
      c.fail("target_surface", "a flexible target needs the contact surface whose master patch it offers");
    if ((!master || master->rigid) && !s.target_surface.empty())
      c.fail("target_surface", "only a flexible target has contact surfaces");
    scene.contacts.push_back(s);
  }
  for (const TomlView& c : top.tables("hertz_contact")) {
    c.allow_only({"name", "body", "target", "youngs_modulus", "poisson_ratio", "target_youngs_modulus", "target_poisson_ratio"});
    HertzContactSpec s;
    s.name = unique(c);
    s.body = c.string("body");
    s.target = c.string("target");
    for (const char* key : {"body", "target"}) {
      const BodySpec* b = scene.body(c.string(key));
      if (!b || !b->rigid || b->rigid->kind != RigidShape::Kind::Sphere)
        c.fail(key, "no rigid_body sphere named '" + c.string(key) + "' (Hertz's law is between rigid spheres)");
    }
    if (s.body == s.target) c.fail("target", "a sphere cannot touch itself");
    s.youngs_modulus[0] = c.positive("youngs_modulus");
    s.poisson_ratio[0] = c.number("poisson_ratio");
    s.youngs_modulus[1] = c.positive("target_youngs_modulus", s.youngs_modulus[0]);
    s.poisson_ratio[1] = c.number("target_poisson_ratio", s.poisson_ratio[0]);
    for (int side = 0; side < 2; ++side)
      if (!(s.poisson_ratio[std::size_t(side)] > -1 && s.poisson_ratio[std::size_t(side)] < 0.5))
        c.fail(side ? "target_poisson_ratio" : "poisson_ratio", "must lie in (-1, 0.5)");
    scene.hertz_contacts.push_back(s);
  }
  for (const TomlView& j : top.tables("joint")) {
    j.allow_only({"name", "type", "body", "node", "other", "other_node", "point", "axis"});
    JointSpec s;
    s.name = unique(j);
    const std::string type = j.string("type");
    if (type == "spherical") s.kind = JointSpec::Kind::Spherical;
    else if (type == "revolute") s.kind = JointSpec::Kind::Revolute;
    else if (type == "fixed") s.kind = JointSpec::Kind::Fixed;
    else j.fail("type", "unknown joint type '" + type + "' (spherical, revolute, fixed)");
    if (scene.simulation.dimension == Dimension::Axisymmetric) j.fail("type", "an axisymmetric scene has no joints");
    s.body = j.string("body");
    s.node = j.string("node", "");
    s.other = j.string("other", "");
    s.other_node = j.string("other_node", "");
    // each side: a flexible body at one of its SID nodes, a rigid body, or (second side) the ground
    auto side = [&](const std::string& body, const std::string& node, const char* body_key, const char* node_key) {
      const BodySpec* b = scene.body(body);
      if (!b) j.fail(body_key, "no body named '" + body + "'");
      if (!b->rigid && node.empty()) j.fail(node_key, "a flexible body attaches at one of its SID nodes: name it");
      if (b->rigid && !node.empty()) j.fail(node_key, "a rigid body has no nodes: give the joint's point");
      return b->rigid.has_value();
    };
    bool rigid_side = side(s.body, s.node, "body", "node");
    if (!s.other.empty()) {
      if (s.other == s.body) j.fail("other", "a body cannot be jointed to itself");
      rigid_side = side(s.other, s.other_node, "other", "other_node") || rigid_side;
    } else if (!s.other_node.empty()) {
      j.fail("other_node", "the ground has no nodes");
    }
    // without a point the joint sits at the (first) node: the ground holds on to it there
    if (j.has("point")) s.point = vec3(j, "point", Eigen::Vector3d::Zero());
    else if (rigid_side) j.fail("point", "a rigid body attaches at the joint's point: give it (world, at t = 0)");
    if (j.has("axis") && s.kind != JointSpec::Kind::Revolute) j.fail("axis", "only a revolute joint has an axis");
    s.axis = unit_vector(j, "axis", s.axis);
    scene.joints.push_back(s);
  }
  if (std::none_of(scene.bodies.begin(), scene.bodies.end(), [](const BodySpec& b) { return !b.rigid; }) && scene.joints.empty() &&
      scene.hertz_contacts.empty())
    top.fail("flexible_body", "a scene needs at least one flexible body (or rigid bodies in joints or Hertz contacts)");
  for (const TomlView& m : top.tables("monitor")) {
    m.allow_only({"name", "body", "node", "surface", "parameter", "quantity", "stress"});
    const std::string name = unique(m);
    const BodySpec* body = scene.body(m.string("body"));
    if (!body || body->rigid) m.fail("body", "no flexible_body named '" + m.string("body") + "'");
    if (m.has("stress")) {
      for (const char* other : {"node", "surface", "parameter", "quantity"})
        if (m.has(other)) m.fail(other, "a stress monitor takes only name, body and stress");
      scene.stress_monitors.push_back({name, body->name, m.string("stress")});
      continue;
    }
    MonitorSpec s;
    s.name = name;
    s.body = body->name;
    if (m.has("node") == m.has("surface")) m.fail("node", "give either a node or a surface and a parameter");
    s.node = m.string("node", "");
    s.surface = m.string("surface", "");
    if (!s.surface.empty()) {
      s.parameter = m.numbers("parameter");
      if (s.parameter.empty() || s.parameter.size() > 2) m.fail("parameter", "needs one or two master-patch parameters");
    } else if (m.has("parameter")) {
      m.fail("parameter", "only used with a surface");
    }
    s.quantity = m.string("quantity", s.quantity);
    if (s.quantity != "velocity" && s.quantity != "position") m.fail("quantity", "must be velocity or position");
    scene.monitors.push_back(s);
  }
  scene.gravity = vec3(top.table("simulation"), "gravity", scene.gravity);
  if (scene.gravity.stableNorm() > kMaxGravity)
    top.table("simulation").fail("gravity", common::number_text(scene.gravity.stableNorm()) + " m/s^2 exceeds 1e8 m/s^2 (1e7 g)");
  if (auto r = top.optional_table("reference")) {
    r->allow_only({"source", "peak_force_n", "contact_time_s", "rebound_velocity_m_s", "final_velocity_m_s", "final_angular_velocity_rad_s",
                   "wave_arrival_s", "contact_end_s", "peak_von_mises_pa", "peak_von_mises_depth_m"});
    if (r->has("source")) {
      if (r->string("source") != "hertz") r->fail("source", "must be \"hertz\" (the run's own Hertz estimate), is \"" + r->string("source") + "\"");
      if (r->has("peak_force_n") || r->has("contact_time_s"))
        r->fail("source", "\"hertz\" gives peak_force_n and contact_time_s: drop them or the source");
      scene.reference_from_hertz = true;
    }
    for (const char* key : {"peak_force_n", "contact_time_s", "rebound_velocity_m_s", "final_angular_velocity_rad_s",
                            "wave_arrival_s", "contact_end_s", "peak_von_mises_pa", "peak_von_mises_depth_m"})
      if (r->has(key)) scene.reference[key] = r->number(key);
    if (r->has("final_velocity_m_s")) {
      const Eigen::Vector3d v = vec3(*r, "final_velocity_m_s", Eigen::Vector3d::Zero());
      scene.reference["final_velocity_x_m_s"] = v.x();
      scene.reference["final_velocity_y_m_s"] = v.y();
      scene.reference["final_velocity_z_m_s"] = v.z();
    }
    // the file's values belong to the file's scene: a run with other values set over it compares
    // only the reference values it sets itself (the Hertz source follows the run by itself)
    if (!overrides.empty()) {
      std::set<std::string> set_keys;
      bool whole_table = false;
      for (const common::TomlOverride& o : overrides) {
        whole_table = whole_table || o.key == "reference";
        if (o.key.rfind("reference.", 0) == 0) set_keys.insert(o.key.substr(10, o.key.find('.', 10) - 10));
      }
      for (auto it = scene.reference.begin(); !whole_table && it != scene.reference.end();) {
        const bool velocity_part = it->first.rfind("final_velocity_", 0) == 0 && it->first != "final_angular_velocity_rad_s";
        it = set_keys.count(velocity_part ? "final_velocity_m_s" : it->first) ? std::next(it) : scene.reference.erase(it);
      }
    }
  }
  scene.adaptive.coarse_integrator = scene.simulation.integrator;  // unless [adaptive] says otherwise
  scene.adaptive.coarse_max_step = scene.simulation.max_step;
  if (auto a = top.optional_table("adaptive")) {
    a->allow_only({"cache", "interval_width", "coarse_integrator", "coarse_max_step", "penalty_search", "impact_output_interval"});
    scene.adaptive.cache = resolve(path, a->string("cache", ""));
    scene.adaptive.interval_width = a->positive("interval_width", 0);
    scene.adaptive.coarse_integrator = read_integrator(*a, "coarse_integrator", scene.adaptive.coarse_integrator);
    if ((scene.adaptive.coarse_integrator == IntegratorKind::Leapfrog) != (scene.simulation.integrator == IntegratorKind::Leapfrog))
      a->fail("coarse_integrator", "the leapfrog's fixed step and the adaptive integrators' tolerances do not mix between phases");
    scene.adaptive.coarse_max_step = a->positive("coarse_max_step", scene.adaptive.coarse_max_step);
    check_step_count(*a, "coarse_max_step", scene.adaptive.coarse_max_step, scene.simulation);
    scene.adaptive.penalty_search = a->boolean("penalty_search", true);
    scene.adaptive.impact_output_interval = a->positive("impact_output_interval", 0);
    if (scene.adaptive.impact_output_interval > scene.simulation.output_interval)
      a->fail("impact_output_interval", "exceeds simulation.output_interval (impact phases sample at least as often as the run)");
    if (scene.adaptive.impact_output_interval > 0 && scene.simulation.end_time / scene.adaptive.impact_output_interval > kMaxSamples)
      a->fail("impact_output_interval", "end_time / impact_output_interval exceeds the limit of 1e7 samples");
    if (!scene.has_adaptive_bodies()) top.fail("adaptive", "no flexible_body is adaptive");
  }
  if (scene.adaptive.cache.empty()) scene.adaptive.cache = resolve(path, ".isosid-cache");
  return scene;
}

bool Scene::has_adaptive_bodies() const {
  return std::any_of(bodies.begin(), bodies.end(), [](const BodySpec& b) { return b.adaptive; });
}

}  // namespace isosid::run
