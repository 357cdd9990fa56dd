// Scene file parsing and validation; see scene.hpp.
#include "scene/scene.hpp"

#include "isosid/format/toml_fields.hpp"

#include <filesystem>
#include <set>

namespace isosid::run {
namespace {

using format::TomlView;
namespace fs = std::filesystem;

Eigen::Vector3d vec3(const TomlView& t, const std::string& key, const Eigen::Vector3d& fallback) {
  if (!t.has(key)) return fallback;
  const auto v = t.numbers(key);
  if (v.size() != 3) t.fail(key, "needs three components");
  return {v[0], v[1], v[2]};
}

std::string resolve(const std::string& scene_file, const std::string& path) {
  if (path.empty() || fs::path(path).is_absolute()) return path;
  return (fs::path(scene_file).parent_path() / path).lexically_normal().string();
}

SimulationSettings read_simulation(const TomlView& s) {
  s.allow_only({"dimension", "end_time", "integrator", "rtol", "atol", "max_step", "output_interval", "gravity"});
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
  const std::string integrator = s.string("integrator", "dopri5");
  if (integrator == "dopri5")
    out.integrator = IntegratorKind::DormandPrince;
  else if (integrator == "implicit")
    out.integrator = IntegratorKind::Implicit;
  else
    s.fail("integrator", "unknown integrator '" + integrator + "' (dopri5, implicit)");
  out.rtol = s.positive("rtol", 1e-6);
  out.atol = s.positive("atol", 1e-9);
  out.max_step = s.positive("max_step", out.end_time);
  out.output_interval = s.positive("output_interval", out.end_time / 1000);
  if (out.output_interval > out.end_time) s.fail("output_interval", "exceeds end_time");
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

Scene read_scene_file(const std::string& path) {
  const toml::table root = format::parse_toml_file(path);
  const TomlView top(root, path);
  top.allow_only({"simulation", "flexible_body", "fixed_plane", "contact", "monitor", "reference"});
  Scene scene;
  scene.file = path;
  scene.simulation = read_simulation(top.table("simulation"));
  std::set<std::string> names;
  auto unique = [&](const TomlView& t) {
    const std::string name = t.string("name");
    if (name.empty()) t.fail("name", "must not be empty");
    if (!names.insert(name).second) t.fail("name", "duplicate name '" + name + "'");
    return name;
  };
  for (const TomlView& b : top.tables("flexible_body")) {
    b.allow_only({"name", "sid", "model", "position", "orientation", "velocity", "angular_velocity", "q0", "qdot0", "locked",
                  "high_modes", "quasistatic_above_hz"});
    FlexibleBodySpec f;
    f.name = unique(b);
    f.sid_file = resolve(path, b.string("sid"));
    f.model_file = resolve(path, b.string("model", ""));
    if (!f.model_file.empty() && !fs::is_regular_file(f.model_file)) b.fail("model", "file not found: " + f.model_file);
    if (f.model_file.empty() && !fs::is_regular_file(f.sid_file)) b.fail("sid", "file not found: " + f.sid_file);
    f.position = vec3(b, "position", f.position);
    f.tait_bryan = vec3(b, "orientation", f.tait_bryan);
    f.velocity = vec3(b, "velocity", f.velocity);
    f.angular_velocity = vec3(b, "angular_velocity", f.angular_velocity);
    if (b.has("q0")) {
      const auto v = b.numbers("q0");
      f.q0 = Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(v.size()));
    }
    if (b.has("qdot0")) {
      const auto v = b.numbers("qdot0");
      f.qdot0 = Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(v.size()));
    }
    if (b.has("locked"))
      for (const std::string& l : b.strings("locked")) {
        if (l != "x" && l != "y" && l != "z" && l != "rx" && l != "ry" && l != "rz") b.fail("locked", "unknown DOF '" + l + "'");
        f.locked.push_back(l);
      }
    f.high_modes = b.string("high_modes", f.high_modes);
    if (f.high_modes != "dynamic" && f.high_modes != "quasistatic") b.fail("high_modes", "must be dynamic or quasistatic");
    f.quasistatic_above_hz = b.positive("quasistatic_above_hz", -1);
    if (b.has("quasistatic_above_hz") && f.high_modes != "quasistatic")
      b.fail("quasistatic_above_hz", "only used with high_modes = \"quasistatic\"");
    scene.bodies.push_back(f);
  }
  if (scene.bodies.empty()) top.fail("flexible_body", "a scene needs at least one flexible body");
  for (const TomlView& p : top.tables("fixed_plane")) {
    p.allow_only({"name", "point", "normal"});
    PlaneSpec s;
    s.name = unique(p);
    s.point = vec3(p, "point", s.point);
    const Eigen::Vector3d n = vec3(p, "normal", s.normal);
    if (n.norm() < 1e-12) p.fail("normal", "must not be zero");
    s.normal = n.normalized();
    scene.planes.push_back(s);
  }
  for (const TomlView& c : top.tables("contact")) {
    c.allow_only({"name", "body", "surface", "target", "penalty", "friction", "regularization"});
    ContactSpec s;
    s.name = unique(c);
    s.body = c.string("body");
    s.surface = c.string("surface");
    s.target = c.string("target");
    s.penalty = c.positive("penalty");
    s.friction = c.number("friction", 0.0);
    if (s.friction < 0 || s.friction > 10) c.fail("friction", "must lie in [0, 10]");
    s.regularization = c.positive("regularization", s.regularization);
    bool body_found = false, target_found = false;
    for (const auto& b : scene.bodies) body_found = body_found || b.name == s.body;
    for (const auto& p : scene.planes) target_found = target_found || p.name == s.target;
    if (!body_found) c.fail("body", "no flexible_body named '" + s.body + "'");
    if (!target_found) c.fail("target", "no fixed_plane named '" + s.target + "'");
    scene.contacts.push_back(s);
  }
  for (const TomlView& m : top.tables("monitor")) {
    m.allow_only({"name", "body", "node", "quantity"});
    MonitorSpec s;
    s.name = unique(m);
    s.body = m.string("body");
    s.node = m.string("node");
    s.quantity = m.string("quantity", s.quantity);
    if (s.quantity != "velocity" && s.quantity != "position") m.fail("quantity", "must be velocity or position");
    bool found = false;
    for (const auto& b : scene.bodies) found = found || b.name == s.body;
    if (!found) m.fail("body", "no flexible_body named '" + s.body + "'");
    scene.monitors.push_back(s);
  }
  scene.gravity = vec3(top.table("simulation"), "gravity", scene.gravity);
  if (auto r = top.optional_table("reference")) {
    r->allow_only({"peak_force_n", "contact_time_s", "rebound_velocity_m_s", "final_velocity_m_s", "final_angular_velocity_rad_s",
                   "wave_arrival_s", "contact_end_s"});
    for (const char* key : {"peak_force_n", "contact_time_s", "rebound_velocity_m_s", "final_angular_velocity_rad_s",
                            "wave_arrival_s", "contact_end_s"})
      if (r->has(key)) scene.reference[key] = r->number(key);
    if (r->has("final_velocity_m_s")) {
      const Eigen::Vector3d v = vec3(*r, "final_velocity_m_s", Eigen::Vector3d::Zero());
      scene.reference["final_velocity_x_m_s"] = v.x();
      scene.reference["final_velocity_y_m_s"] = v.y();
      scene.reference["final_velocity_z_m_s"] = v.z();
    }
  }
  return scene;
}

}  // namespace isosid::run
