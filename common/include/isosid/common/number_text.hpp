// Numbers as the programs print them for people: six significant digits, lists of them in
// brackets; one spelling for isosid-prep's and isosid-info's reports.
#pragma once
#include <Eigen/Dense>
#include <string>

namespace isosid::common {

/// "%.6g"
std::string number_text(double x);
/// The entries of v as number_text, comma separated, between `open` and `close`.
std::string list_text(const Eigen::VectorXd& v, const char* open = "[", const char* close = "]");

}  // namespace isosid::common
