// The skew-symmetric (cross-product) matrix: skew(a) b = a x b. The SID's node orientation
// term AP uses it (M1[k] = skew(psi_k)); the runtime uses it for the FFRF terms.
#pragma once
#include <Eigen/Dense>

namespace isosid::format {

inline Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

}  // namespace isosid::format
