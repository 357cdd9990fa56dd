// A study: one base scene run for many cases, each with values set over it by dotted key
// (common/toml_override), and the quantities of each run to collect into one table.
#pragma once
#include "isosid/common/toml_override.hpp"

#include <string>
#include <vector>

namespace isosid::sweep {

/// How the parameters' values combine into cases.
enum class Sampling {
  Grid,            ///< every combination (the first parameter varies slowest)
  Zip,             ///< the i-th value of every parameter (equal counts)
  LatinHypercube,  ///< `samples` points, one per stratum of each parameter's range, seeded
};

/// One varied quantity: one dotted key, or several keys set together (an impact point that
/// moves the sphere and the beam's contact region at once). A key is into the scene, or
/// `model.<body>.<key>` into the model file of the scene's body <body> (see model_settings).
struct Parameter {
  std::vector<std::string> keys;                 ///< one, or several set together
  std::vector<std::vector<std::string>> values;  ///< per value, one TOML text per key (grid and zip)
  double lo = 0, hi = 0;                         ///< range, one key (Latin hypercube)
  bool log_scale = false;                        ///< range sampled in log (positive ends)
  std::string name() const;                      ///< the key, or the keys joined by " + "
};

struct Study {
  std::string file;        ///< the study file
  std::string scene_file;  ///< the base scene, resolved against the study file
  Sampling sampling = Sampling::Grid;
  int samples = 0;         ///< Latin hypercube
  unsigned long long seed = 1;
  std::vector<Parameter> parameters;
  std::vector<std::string> collect;  ///< dotted paths into summary.json (contacts.<name>.peak_force_n)
};

/// Reads and checks a study file (InputError naming file and field).
Study read_study_file(const std::string& path);

/// One case: its number (from 0) and its values, one per key of every parameter, as TOML text.
struct Case {
  int index = 0;
  std::vector<common::TomlOverride> settings;
};

/// The study's cases, in order; the same on every rank (a Latin hypercube from its seed).
std::vector<Case> plan_cases(const Study& study);

}  // namespace isosid::sweep
