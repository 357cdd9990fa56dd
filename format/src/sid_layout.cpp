// Table of the classic SID terms; see sid_layout.hpp.
#include "sid_layout.hpp"

namespace isosid::format::layout {

const std::vector<TermSpec>& terms() {
  static const std::vector<TermSpec> table = {
      {"mdCM", "kg*m", &Sid::mdCM},        {"J", "kg*m^2", &Sid::J},
      {"Ct", "kg*m/[q]", &Sid::Ct},        {"Cr", "kg*m^2/[q]", &Sid::Cr},
      {"Me", "kg*m^2/[q]^2", &Sid::Me},    {"Gr", "kg*m^2/[q]", &Sid::Gr},
      {"Ge", "kg*m^2/[q]^2", &Sid::Ge},    {"Oe", "kg*m^2/[q]", &Sid::Oe},
      {"ksigma", "N*m/[q]", &Sid::ksigma}, {"Ke", "N*m^2/[q]^2", &Sid::Ke},
      {"De", "N*s*m^2/[q]^2", &Sid::De},
  };
  return table;
}

}  // namespace isosid::format::layout
