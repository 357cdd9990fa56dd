// The scene's bodies and fixed surfaces; see scene_reading.hpp.
#include "scene/scene_reading.hpp"

#include "body/floating_body.hpp"
#include "isosid/common/number_text.hpp"
#include "isosid/format/file_kind.hpp"

#include <array>
#include <cmath>

namespace isosid::run::scene_reading {
namespace {

/// The fastest initial speed of a body, m/s: no solid carries elastic waves faster than about
/// 13 km/s (beryllium, diamond), and an impact at the wave speed is a shock, outside the
/// linear elasticity of SIDs; faster values are typing errors, and would overflow the Hertz
/// estimate (its contact radius grows as v^(2/5), its energy as v^2).
constexpr double kMaxSpeed = 2e4;

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

}  // namespace

void read_bodies(const TomlView& top, ItemNames& names, Scene& scene) {
  for (const TomlView& b : top.tables("flexible_body")) {
    b.allow_only({"name", "sid", "model", "position", "orientation", "velocity", "angular_velocity", "q0", "qdot0", "locked",
                  "high_modes", "quasistatic_above_hz", "elastic_start", "adaptive"});
    BodySpec f = read_motion(b, names.take(b), scene.simulation.dimension);
    f.adaptive = b.boolean("adaptive", false);
    if (f.adaptive && b.has("sid")) b.fail("sid", "an adaptive body's SIDs are built from its model (drop sid)");
    f.sid_file = f.adaptive ? "" : resolve(scene.file, b.string("sid"));
    f.model_file = resolve(scene.file, b.string("model", ""));
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
    BodySpec r = read_motion(b, names.take(b), scene.simulation.dimension);
    r.rigid = read_rigid_shape(b, scene.simulation.dimension);
    scene.bodies.push_back(r);
  }
  for (const TomlView& p : top.tables("fixed_plane")) {
    p.allow_only({"name", "point", "normal"});
    ShapeSpec s{ShapeSpec::Kind::Plane, names.take(p)};
    s.point = vec3(p, "point", s.point);
    s.normal = unit_vector(p, "normal", s.normal);
    scene.fixed_surfaces.push_back(s);
  }
  for (const TomlView& p : top.tables("fixed_sphere")) {
    p.allow_only({"name", "center", "radius"});
    ShapeSpec s{ShapeSpec::Kind::Sphere, names.take(p)};
    s.point = vec3(p, "center", s.point);
    s.radius = p.positive("radius");
    scene.fixed_surfaces.push_back(s);
  }
  for (const TomlView& p : top.tables("fixed_cylinder")) {
    p.allow_only({"name", "point", "axis", "radius"});
    ShapeSpec s{ShapeSpec::Kind::Cylinder, names.take(p)};
    s.point = vec3(p, "point", s.point);
    s.normal = unit_vector(p, "axis", Eigen::Vector3d::UnitZ());
    s.radius = p.positive("radius");
    scene.fixed_surfaces.push_back(s);
  }
  for (const ShapeSpec& s : scene.fixed_surfaces) check_fits_dimension(s, scene.simulation.dimension, top);
}

}  // namespace isosid::run::scene_reading
