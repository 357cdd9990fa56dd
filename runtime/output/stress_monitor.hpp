// von Mises stress along a SID stress line (sigma = S q at each point), tracked over a run:
// the values at every output sample (for results.h5) and the peak over all accepted steps,
// with where and when it occurred. Sphere on sphere (A, docs/references.md) compares the peak on
// the axis below the contact with Hertz (0.530 GPa at a depth of 0.49 a).
#pragma once
#include "body/floating_body.hpp"
#include "scene/scene.hpp"

#include <nlohmann/json.hpp>
#include <vector>

namespace isosid::run {

/// von Mises stress of one point from the SID's stress components (names as stored: xx yy
/// zz xy yz xz, or rr zz tt rz for axisymmetric bodies); plane strain adds its out-of-plane
/// normal stress nu (s1 + s2), plane stress has none.
double von_mises(const std::vector<std::string>& components, const double* sigma, format::AnalysisType analysis, double nu);

class StressMonitor {
public:
  StressMonitor(const StressMonitorSpec& spec, const FloatingBody& body, const std::string& scene_file);

  const std::string& name() const { return spec_.name; }
  Eigen::Index points() const { return line_.position.rows(); }
  /// Appends the von Mises stress of every point at state y.
  void sample(const double* y);
  /// Tracks the peak at an accepted step.
  void step(double t, const double* y);
  /// Samples x points (row-major), Pa.
  const std::vector<double>& samples() const { return samples_; }
  /// Peak stress, its time, the point's body-frame position and its depth below the body's
  /// contact surfaces (distance to the nearest master patch, reference geometry; absent
  /// where the SID has no master patch).
  nlohmann::json summary() const;

private:
  /// von Mises of every point at y, into values_.
  void evaluate(const double* y);

  StressMonitorSpec spec_;
  const FloatingBody& body_;
  const format::StressRecovery& line_;
  Eigen::VectorXd depth_;  ///< per point: depth below the contact surfaces, m (empty: none)
  Eigen::VectorXd sigma_, values_;
  std::vector<double> samples_;
  double peak_ = 0, peak_time_ = 0;
  Eigen::Index peak_point_ = 0;
};

}  // namespace isosid::run
