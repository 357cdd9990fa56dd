// A scene: what isosid-run simulates (bodies from SIDs, fixed surfaces, contacts, gravity,
// monitors, integrator settings) and the reference values the results are compared with.
#pragma once
#include "body/body_spec.hpp"
#include "contact/contact_spec.hpp"
#include "isosid/common/toml_override.hpp"
#include "joint/joint_spec.hpp"
#include "solve/integrator_kind.hpp"

#include <Eigen/Dense>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace isosid::run {

struct SimulationSettings {
  Dimension dimension = Dimension::Solid;
  double end_time = 0;          ///< s
  IntegratorKind integrator = IntegratorKind::DormandPrince;
  double rtol = 1e-6, atol = 1e-9;
  double max_step = 0;          ///< s, 0: unlimited
  double step = 0;              ///< s, the leapfrog's fixed step
  long max_steps = 10'000'000;  ///< a run needing more steps stops with a diagnosis instead of crawling
  double output_interval = 0;   ///< s
  /// Bodies may start interpenetrating (refused otherwise: they would be thrown apart).
  bool allow_initial_penetration = false;
  /// 1/s: joints pull their drift back at this rate (Baumgarte: c'' + 2 a c' + a^2 c = 0)
  double joint_stabilization = 1000;
};

/// At most this many output samples (end_time / output_interval): results.h5 stays bounded.
constexpr double kMaxSamples = 1e7;

/// [adaptive]: how the adaptive bodies' models are found and refined ([R2] Sect. 4).
struct AdaptiveSettings {
  std::string cache;            ///< folder of the SIDs built for the run (default: .isosid-cache beside the scene)
  double interval_width = 0;    ///< m, the first impact's refined region; 0: from the impact's Hertz estimate
  /// the phases between impacts (coarse models, no contact): the scene's integrator and
  /// max_step unless given ([R2] takes an implicit method with larger steps there)
  IntegratorKind coarse_integrator = IntegratorKind::DormandPrince;
  double coarse_max_step = 0;   ///< s
  /// [R2] Sect. 4.1: each contact's first impact tries its penalty ten times stiffer until
  /// the force no longer changes, and errors lower it (adapt/penalty_search); false: the
  /// contact's penalty (given or derived) as it is
  bool penalty_search = true;
  /// s between the output samples (and so the results' force history) of impact phases; 0:
  /// a hundredth of the impact's Hertz contact time, at most the scene's output_interval (an
  /// impact of scene E lasts 65 us, a hundredth of its 1e-4 s output interval)
  double impact_output_interval = 0;
};

/// A monitored point: a SID node, or a parameter on a contact surface's master patch.
struct MonitorSpec {
  std::string name;
  std::string body, node;
  std::string surface;                ///< with `parameter`: the contact surface whose master patch holds the point
  std::vector<double> parameter;      ///< master-patch parameter(s) of the point
  std::string quantity = "velocity";  ///< position | velocity
};

/// The von Mises stress along one of a body's SID stress lines, tracked over the run.
struct StressMonitorSpec {
  std::string name;
  std::string body, line;  ///< a flexible body and a stress recovery line of its SID
};

/// [output]: what the run writes besides results.h5 and summary.json.
struct OutputSettings {
  /// A ParaView collection (paraview/scene.pvd) of the deformed flexible bodies and the
  /// loaded contact points, one frame per `paraview_interval`.
  bool paraview = false;
  double paraview_interval = 0;  ///< s; 0: the output interval, but at most 200 frames (also for --paraview)
  /// Kinds of warning (scene/run_warning.hpp) this scene expects: summary.json lists them under
  /// expected_warnings, apart from the warnings that call for attention.
  std::vector<std::string> expected_warnings;
};

struct Scene {
  /// The scene file; for a scene given as text, the name it was given under (relative paths
  /// are resolved from its folder, and errors name it).
  std::string file;
  /// A scene given as text: its SHA-256, recorded in the run's provenance in place of a file's.
  std::string text_sha256;
  /// Values set over the file's ("key = value", common/toml_override.hpp), in order; recorded
  /// in the run's provenance beside the file's hash.
  std::vector<std::string> overrides;
  SimulationSettings simulation;
  OutputSettings output;
  AdaptiveSettings adaptive;
  std::vector<BodySpec> bodies;        ///< flexible bodies first, then rigid ones
  std::vector<ShapeSpec> fixed_surfaces;
  std::vector<ContactSpec> contacts;
  std::vector<HertzContactSpec> hertz_contacts;
  std::vector<JointSpec> joints;
  std::vector<MonitorSpec> monitors;               ///< points
  std::vector<StressMonitorSpec> stress_monitors;  ///< [[monitor]] tables with `stress`
  const BodySpec* body(const std::string& name) const;
  const ShapeSpec* fixed_surface(const std::string& name) const;
  bool has_adaptive_bodies() const;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  std::map<std::string, double> reference;  ///< [reference] values, e.g. peak_force_n
  /// [reference] source = "hertz": peak force and contact time compared with the run's own
  /// Hertz estimate of its first contact
  bool reference_from_hertz = false;
};

/// Reads and validates a scene file, with `overrides` set over it by dotted key; paths are
/// resolved relative to the file.
Scene read_scene_file(const std::string& path, const std::vector<common::TomlOverride>& overrides = {});
/// Reads and validates a scene held as TOML text, as read_scene_file() a file: `name` stands
/// for the file (errors name it, paths are resolved relative to its folder).
Scene read_scene_text(const std::string& text, const std::string& name, const std::vector<common::TomlOverride>& overrides = {});

}  // namespace isosid::run
