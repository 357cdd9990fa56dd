// von Mises monitors on SID stress lines; see stress_monitor.hpp.
#include "output/stress_monitor.hpp"

#include "contact/deformed_patch.hpp"
#include "isosid/format/error.hpp"

#include <cmath>

namespace isosid::run {

double von_mises(const std::vector<std::string>& components, const double* sigma, format::AnalysisType analysis, double nu) {
  // normal components carry a repeated letter (xx, rr, tt), shear components two letters
  double normal[3] = {0, 0, 0}, shear2 = 0;
  int n_normal = 0;
  for (std::size_t c = 0; c < components.size(); ++c) {
    const std::string& name = components[c];
    if (name.size() == 2 && name[0] == name[1]) {
      if (n_normal < 3) normal[n_normal++] = sigma[c];
    } else {
      shear2 += sigma[c] * sigma[c];
    }
  }
  if (n_normal == 2 && analysis == format::AnalysisType::PlaneStrain) normal[2] = nu * (normal[0] + normal[1]);
  const double d01 = normal[0] - normal[1], d12 = normal[1] - normal[2], d20 = normal[2] - normal[0];
  return std::sqrt(0.5 * (d01 * d01 + d12 * d12 + d20 * d20) + 3 * shear2);
}

namespace {
const format::StressRecovery& find_line(const StressMonitorSpec& spec, const FloatingBody& body, const std::string& scene_file) {
  for (const format::StressRecovery& s : body.sid().stress_recovery)
    if (s.name == spec.line) return s;
  throw format::InputError(scene_file, "monitor " + spec.name + ".stress", "the SID of '" + spec.body + "' has no stress line '" + spec.line + "'");
}

/// Distance of every point of the line below the body's contact surfaces: to the closest
/// point of any of its master patches, in the reference geometry. Empty if it has none.
Eigen::VectorXd depths_below_contact_surfaces(const format::StressRecovery& line, const format::Sid& sid) {
  if (sid.master_patches.empty()) return {};
  Eigen::VectorXd depth = Eigen::VectorXd::Constant(line.position.rows(), INFINITY);
  for (const format::MasterPatch& m : sid.master_patches) {
    const DeformedPatch patch(m, sid.dim());  // undeformed: the reference geometry
    DeformedPatch::Point point;
    for (Eigen::Index i = 0; i < line.position.rows(); ++i) {
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      x.head(line.position.cols()) = line.position.row(i).transpose();
      Eigen::Vector2d u = Eigen::Vector2d::Constant(NAN);
      if (patch.closest_point(x, u, point)) depth(i) = std::min(depth(i), (point.C - x).norm());
    }
  }
  return depth;
}
}  // namespace

StressMonitor::StressMonitor(const StressMonitorSpec& spec, const FloatingBody& body, const std::string& scene_file)
    : spec_(spec),
      body_(body),
      line_(find_line(spec, body, scene_file)),
      depth_(depths_below_contact_surfaces(line_, body.sid())),
      sigma_(line_.S.rows()),
      values_(line_.position.rows()) {}

void StressMonitor::evaluate(const double* y) {
  sigma_.noalias() = line_.S * body_.q(y);
  const auto nc = Eigen::Index(line_.components.size());
  for (Eigen::Index i = 0; i < points(); ++i)
    values_(i) = von_mises(line_.components, sigma_.data() + i * nc, body_.sid().analysis,
                          format::material_of(body_.sid(), line_.patch).poisson_ratio);
}

void StressMonitor::sample(const double* y) {
  evaluate(y);
  samples_.insert(samples_.end(), values_.data(), values_.data() + values_.size());
}

void StressMonitor::step(double t, const double* y) {
  evaluate(y);
  Eigen::Index at = 0;
  const double peak = points() ? values_.maxCoeff(&at) : 0.0;
  if (peak > peak_) peak_ = peak, peak_time_ = t, peak_point_ = at;
}

nlohmann::json StressMonitor::summary() const {
  nlohmann::json j = {{"name", spec_.name}, {"quantity", "von_mises"}, {"line", spec_.line}};
  j["peak_von_mises_pa"] = peak_;
  j["peak_time_s"] = peak_time_;
  if (points()) {
    const Eigen::VectorXd p = line_.position.row(peak_point_).transpose();
    j["peak_position_m"] = std::vector<double>(p.data(), p.data() + p.size());
    if (depth_.size() && std::isfinite(depth_(peak_point_))) j["peak_depth_m"] = depth_(peak_point_);
  }
  return j;
}

}  // namespace isosid::run
