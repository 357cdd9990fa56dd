// Scene file parsing and validation; see scene.hpp. The sections' readers are in
// scene_simulation.cpp, scene_bodies.cpp and scene_interactions.cpp (scene_reading.hpp).
#include "scene/scene.hpp"

#include "scene/run_warning.hpp"
#include "scene/scene_reading.hpp"

#include "isosid/common/number_text.hpp"
#include "isosid/common/sha256.hpp"

#include <filesystem>
#include <algorithm>
#include <iterator>

namespace isosid::run {
namespace scene_reading {

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

std::string resolve(const std::string& scene_file, const std::string& path) {
  if (path.empty() || fs::path(path).is_absolute()) return path;
  return (fs::path(scene_file).parent_path() / path).lexically_normal().string();
}

std::string ItemNames::take(const TomlView& t) {
  const std::string name = t.name("name");
  if (!taken_.insert(name).second) t.fail("name", "duplicate name '" + name + "'");
  return name;
}

}  // namespace scene_reading

namespace {

using namespace scene_reading;

/// The strongest gravity, m/s^2: ten times an ultracentrifuge's 1e6 g.
constexpr double kMaxGravity = 1e8;

void read_output(const TomlView& top, Scene& scene) {
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
}

void read_reference(const TomlView& top, const std::vector<common::TomlOverride>& overrides, Scene& scene) {
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
}

void read_adaptive(const TomlView& top, Scene& scene) {
  scene.adaptive.coarse_integrator = scene.simulation.integrator;  // unless [adaptive] says otherwise
  scene.adaptive.coarse_max_step = scene.simulation.max_step;
  if (auto a = top.optional_table("adaptive")) {
    a->allow_only({"cache", "interval_width", "coarse_integrator", "coarse_max_step", "penalty_search", "impact_output_interval"});
    scene.adaptive.cache = resolve(scene.file, a->string("cache", ""));
    scene.adaptive.interval_width = a->positive("interval_width", 0);
    scene.adaptive.coarse_integrator = read_integrator(*a, "coarse_integrator", scene.adaptive.coarse_integrator);
    if (fixed_step(scene.adaptive.coarse_integrator) != fixed_step(scene.simulation.integrator))
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
  if (scene.adaptive.cache.empty()) scene.adaptive.cache = resolve(scene.file, ".isosid-cache");
}

}  // namespace

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

namespace {

/// The scene of a parsed file or text `path`, with `overrides` set over it.
Scene read_scene(toml::table root, const std::string& path, const std::vector<common::TomlOverride>& overrides) {
  common::apply_overrides(root, overrides, path);
  const TomlView top(root, path);
  top.allow_only({"simulation", "flexible_body", "rigid_body", "fixed_plane", "fixed_sphere", "fixed_cylinder", "contact",
                  "hertz_contact", "joint", "monitor", "reference", "output", "adaptive"});
  Scene scene;
  scene.file = path;
  for (const common::TomlOverride& o : overrides) scene.overrides.push_back(o.text());
  scene.simulation = read_simulation(top.table("simulation"));
  read_output(top, scene);
  ItemNames names;
  read_bodies(top, names, scene);
  read_interactions(top, names, scene);
  scene.gravity = vec3(top.table("simulation"), "gravity", scene.gravity);
  if (scene.gravity.stableNorm() > kMaxGravity)
    top.table("simulation").fail("gravity", common::number_text(scene.gravity.stableNorm()) + " m/s^2 exceeds 1e8 m/s^2 (1e7 g)");
  read_reference(top, overrides, scene);
  read_adaptive(top, scene);
  return scene;
}

}  // namespace

Scene read_scene_file(const std::string& path, const std::vector<common::TomlOverride>& overrides) {
  return read_scene(common::parse_toml_file(path), path, overrides);
}

Scene read_scene_text(const std::string& text, const std::string& name, const std::vector<common::TomlOverride>& overrides) {
  Scene scene = read_scene(common::parse_toml_text(text, name), name, overrides);
  scene.text_sha256 = common::sha256_hex(text);
  return scene;
}

bool Scene::has_adaptive_bodies() const {
  return std::any_of(bodies.begin(), bodies.end(), [](const BodySpec& b) { return b.adaptive; });
}

}  // namespace isosid::run
