// What isosid-prep prints on stdout, as text or JSON: the body's size and levels, then its
// modes (--modes) or its SID with where its nodes and stress lines lie.
#pragma once
#include "pipeline/prepare.hpp"

#include <string>

namespace isosid::prep {

void print_modal_report(const ModalAnalysis& analysis, bool as_json);
void print_sid_report(const PreparedBody& prepared, const std::string& output, bool as_json);

}  // namespace isosid::prep
