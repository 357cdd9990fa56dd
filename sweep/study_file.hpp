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

struct Parameter {
  std::string key;                  ///< dotted key into the scene
  std::vector<std::string> values;  ///< TOML value texts (grid and zip)
  double lo = 0, hi = 0;            ///< range (Latin hypercube)
  bool log_scale = false;           ///< range sampled in log (positive ends)
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

/// One case: its number (from 0) and its values, one per parameter, as TOML text.
struct Case {
  int index = 0;
  std::vector<common::TomlOverride> settings;
};

/// The study's cases, in order; the same on every rank (a Latin hypercube from its seed).
std::vector<Case> plan_cases(const Study& study);

}  // namespace isosid::sweep
