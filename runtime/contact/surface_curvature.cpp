// Principal curvatures of a patch point; see surface_curvature.hpp.
#include "contact/surface_curvature.hpp"

#include <cmath>

namespace isosid::run {

Eigen::Vector2d principal_curvatures(const DeformedPatch::Point& point, const Eigen::Vector3d& outward, int parameter_dim,
                                     bool axisymmetric) {
  if (parameter_dim == 1) {
    // C'' = s'' T + kappa |C'|^2 N with N the inward normal
    const double meridional = -point.ddC[0].dot(outward) / point.dC[0].squaredNorm();
    if (!axisymmetric) return {meridional, 0.0};
    const double radius = std::abs(point.C.x());
    const double circumferential = radius > 1e-9 * point.dC[0].norm() ? outward.x() / radius : meridional;
    return {meridional, circumferential};
  }
  const Eigen::Vector3d& Cu = point.dC[0];
  const Eigen::Vector3d& Cv = point.dC[1];
  const double E = Cu.dot(Cu), F = Cu.dot(Cv), G = Cv.dot(Cv);
  const double L = -point.ddC[0].dot(outward), M = -point.ddC[1].dot(outward), N = -point.ddC[2].dot(outward);
  const double area = E * G - F * F;
  const double gauss = (L * N - M * M) / area, mean = (E * N - 2 * F * M + G * L) / (2 * area);
  const double split = std::sqrt(std::max(mean * mean - gauss, 0.0));
  return {mean + split, mean - split};
}

}  // namespace isosid::run
