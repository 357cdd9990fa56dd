// One case of a study: its scene read with the case's values, run in-process through the
// library's pipeline (run::run_scene) into its own results folder, and its row of the table.
#pragma once
#include "study_file.hpp"

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace isosid::sweep {

/// What a case's scene file reading says, and isosid-prep's check of each model its model keys
/// make (once per model): "" if its values make a valid scene and models, else the one-line
/// message of the command line's exit 2. Writes the case's model copies into `study_dir`.
std::string case_input_problem(const Study& study, const Case& c, const std::string& study_dir);

/// Runs a case into its folder, case_folder(study_dir, c.index), and returns its row: "case",
/// "settings" {key: value text}, "status" (completed, failed, bad input or interrupted),
/// "exit_class" (0, 1, 2 as isosid-run's exit status), "message", "collected" {path: value or
/// null}, "wall_time_s", "cpu_time_s", "program_version" and "inputs" (each input file's role,
/// path and SHA-256, from the run's provenance).
nlohmann::json run_case(const Study& study, const Case& c, const std::string& study_dir, const std::vector<std::string>& collect,
                        const std::function<bool()>& stop_requested);

/// A case refused before it ran (bad input), as a row.
nlohmann::json refused_case(const Case& c, const std::string& message);

/// The value at a dotted path in a summary (contacts.impact.peak_force_n): object keys, list
/// entries by number or by their "name" or "label" (impact_modes.1F.energy_ratio); null if absent.
nlohmann::json value_at(const nlohmann::json& summary, const std::string& path);

/// The quantities collected when a study names none: each contact's peak force, duration and
/// impulse in the base scene.
std::vector<std::string> default_collect(const Study& study);

}  // namespace isosid::sweep
