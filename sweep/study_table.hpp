// A study's results folder: cases/NNNNNN/ holds each case's results.h5, summary.json and
// row.json (written last, atomically: a case with a row is done and never run again), and
// study.csv and study.h5 join the rows into one table, rewritten as rows arrive.
#pragma once
#include "study_file.hpp"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace isosid::sweep {

/// The results folder of case `index` in the study folder `dir`.
std::string case_folder(const std::string& dir, int index);

/// The case's row, once its run (or its refusal) has been recorded.
std::optional<nlohmann::json> read_row(const std::string& dir, int index);
void write_row(const std::string& dir, const nlohmann::json& row);

/// study.csv and study.h5 of every case that has a row, in case order: case, status,
/// exit_class, message, one column per parameter (its value text) and per collected path
/// (numbers; other values as JSON text), wall and CPU time, program version, and the SHA-256
/// of the case's inputs.
void write_table(const std::string& dir, const Study& study, const std::vector<std::string>& collect,
                 const std::vector<nlohmann::json>& rows);

}  // namespace isosid::sweep
