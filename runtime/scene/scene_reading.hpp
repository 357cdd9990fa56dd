// The scene reader's sections (scene_file.cpp reads the file and calls them in order): each
// reads its tables of the parsed scene into the Scene, checking them against what was read
// before (a contact's bodies, a joint's nodes). Private to the scene reader.
#pragma once
#include "scene/scene.hpp"

#include "isosid/common/toml_fields.hpp"

#include <set>
#include <string>

namespace isosid::run::scene_reading {

using common::TomlView;

/// A three-component vector at `key`, or `fallback` where the key is absent.
Eigen::Vector3d vec3(const TomlView& t, const std::string& key, const Eigen::Vector3d& fallback);
/// vec3() normalized; zero is refused.
Eigen::Vector3d unit_vector(const TomlView& t, const std::string& key, const Eigen::Vector3d& fallback);
/// `path` relative to the scene file's folder (absolute and empty paths as they are).
std::string resolve(const std::string& scene_file, const std::string& path);

/// The names of a scene's items: they become HDF5 groups of results.h5 and keys of
/// summary.json, so each may be taken once.
class ItemNames {
public:
  /// The table's `name`, refused if an item before took it.
  std::string take(const TomlView& t);

private:
  std::set<std::string> taken_;
};

/// [simulation] (scene_simulation.cpp).
SimulationSettings read_simulation(const TomlView& s);
/// An integrator's name at `key`, or `fallback` where the key is absent.
IntegratorKind read_integrator(const TomlView& t, const std::string& key, IntegratorKind fallback);
/// A step limit that needs more than max_steps steps to reach end_time could never finish.
void check_step_count(const TomlView& t, const char* key, double step, const SimulationSettings& sim);

/// [[flexible_body]], [[rigid_body]] and the fixed surfaces (scene_bodies.cpp).
void read_bodies(const TomlView& top, ItemNames& names, Scene& scene);
/// [[contact]], [[hertz_contact]], [[joint]] and [[monitor]], which refer to the bodies
/// (scene_interactions.cpp).
void read_interactions(const TomlView& top, ItemNames& names, Scene& scene);

}  // namespace isosid::run::scene_reading
