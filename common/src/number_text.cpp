// Number formatting for reports; see number_text.hpp.
#include "isosid/common/number_text.hpp"

#include <cstdio>

namespace isosid::common {

std::string number_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

std::string list_text(const Eigen::VectorXd& v, const char* open, const char* close) {
  std::string s = open;
  for (Eigen::Index i = 0; i < v.size(); ++i) s += (i ? ", " : "") + number_text(v(i));
  return s + close;
}

}  // namespace isosid::common
