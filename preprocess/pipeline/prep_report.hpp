// What isosid-prep prints on stdout (and the Python package returns), as text or JSON: the body's size and levels, then its
// modes (--modes) or its SID with where its nodes and stress lines lie.
#pragma once
#include "pipeline/prepare.hpp"

#include <nlohmann/json.hpp>
#include <string>

namespace isosid::prep {

/// The reports as JSON (what --json prints): the body's size, mass and levels, its modes'
/// frequencies and the stages' times; the SID's adds its reduction, nq, contact points,
/// placement of nodes and stress lines, and `output`.
nlohmann::json modal_report(const ModalAnalysis& analysis);
nlohmann::json sid_report(const PreparedBody& prepared, const std::string& output);

void print_modal_report(const ModalAnalysis& analysis, bool as_json);
void print_sid_report(const PreparedBody& prepared, const std::string& output, bool as_json);

}  // namespace isosid::prep
