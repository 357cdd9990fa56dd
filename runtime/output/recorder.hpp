// Everything a run reports: time series at the output interval (states, contact forces and
// their spectra, energies, monitors), per-step contact statistics (onset, release, peak force, impulse),
// monitor reversals, and the comparison with the scene's reference values.
#pragma once
#include "scene/scene.hpp"
#include "solve/multibody_system.hpp"
#include "output/hertz_contact_log.hpp"
#include "output/impact_modes.hpp"
#include "output/run_provenance.hpp"
#include "output/stress_monitor.hpp"
#include "output/velocity_events.hpp"
#include "solve/simulation.hpp"
#include "solve/time_integrator.hpp"

#include <array>
#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace isosid::run {


struct ContactInterval {
  double start = 0, end = -1;  ///< end < 0: still in contact
};

/// The observer of a simulation that keeps what results.h5 and summary.json report.
class Recorder : public SimulationObserver {
public:
  Recorder(const MultibodySystem& system, const Scene& scene);

  /// Time-series sample (called at output times and at events); it leaves the system's
  /// quasistatic coordinates those of y (observers after it, the ParaView frames, draw them).
  void sample(double t, const double* y) override;
  /// Per accepted step: peak force, impulse, monitor reversals.
  void step(double t, const double* y) override;
  /// A contact's gap changed sign at t: closing (onset) or opening (release).
  void contact_event(int contact, bool closing, double t) override;
  /// A contact's exact surfaces touched at t: kept for summary.json.
  void touch(int contact, double t, const Touch& touch) override;

  /// results.h5: written to a temporary file and renamed (never half-written).
  void write_results(const std::string& path) const;
  /// summary.json: outcome, warnings, integrator statistics, contacts, bodies at y_final,
  /// energy balance, monitors and the signed relative errors against the scene's reference values.
  nlohmann::json summary(const IntegratorStats& stats, const RunOutcome& outcome, const double* y_final) const;
  double max_relative_energy_error() const;
  /// The largest drift of the total energy over the largest kinetic + elastic + penalty energy
  /// of the run (0 if nothing moved): unlike the error relative to the initial total, it does
  /// not depend on where gravity's potential is zero.
  double energy_error_per_motion() const;
  /// Beyond this energy error the run's forces and velocities are flagged as questionable: the
  /// shipped scenes A-C, A', H and F stay below 2e-5, an unresolved integration lands far above.
  static constexpr double kMaxEnergyError = 0.05;
  /// Contact k's largest force over the accepted steps so far, N.
  double peak_force(int k) const { return peak_force_[std::size_t(k)]; }
  /// The system's warnings, then what the run showed: contacts that reached the edge of
  /// their surface, penetrated too far, stayed closed at the end or never closed, an energy
  /// balance that drifted.
  std::vector<RunWarning> warnings() const;
  /// The warning of a contact that never closed in the run (summary.json: never_closed).
  static std::string never_closed_warning(const std::string& contact);

private:
  /// summary.json's parts: contact k's entry, joint k's, body's (final state y) and
  /// velocity monitor m's.
  nlohmann::json contact_summary(std::size_t k) const;
  nlohmann::json joint_summary(std::size_t k) const;
  nlohmann::json body_summary(std::size_t body, const double* y) const;
  nlohmann::json monitor_summary(std::size_t m) const;
  /// Contact k closed and did not open again before the last step.
  bool closed_at_end(std::size_t k) const;
  /// Monitor m's node velocity at y, the quasistatic coordinates moving at their last rate.
  Eigen::Vector3d monitor_value(std::size_t m, const double* y) const;
  /// Updates the quasistatic rates at an accepted step (the coordinates solved for y).
  void update_quasistatic_rates(double t, const double* y);

  const MultibodySystem& system_;
  const Scene& scene_;
  RunProvenance provenance_;  ///< gathered when the run starts: the inputs as it found them
  // time series
  std::vector<double> time_;
  std::vector<std::vector<double>> body_states_;  ///< per sample: all states
  /// per body: its nq elastic coordinates of every sample, the quasistatic ones as solved for
  /// that sample (they are not part of the state)
  std::vector<std::vector<double>> body_q_;
  std::vector<std::vector<double>> contact_force_, contact_points_, contact_penetration_;
  std::vector<std::vector<double>> joint_force_, joint_torque_, joint_error_;  ///< per joint: 3, 3, 2 per sample
  std::vector<HertzContactLog> hertz_logs_;
  std::vector<std::array<double, 6>> energies_;   ///< kinetic, elastic, gravity, penalty, dissipated, total
  std::vector<std::vector<double>> monitor_values_;  ///< per monitor: 3 per sample
  // per-step statistics
  std::vector<std::vector<ContactInterval>> intervals_;
  std::vector<std::vector<std::pair<double, Touch>>> touches_;  ///< per contact: time and where
  std::vector<double> peak_force_, impulse_, max_penetration_;
  std::vector<int> points_at_peak_;
  std::vector<double> edge_reached_;  ///< first step time with load in an edge element, or -1
  std::vector<double> interface_left_;  ///< first step time with load beyond a Craig-Bampton interface, or -1
  std::vector<bool> active_;
  double last_step_t_ = 0;
  std::vector<double> last_force_;
  std::vector<VelocityEvents> monitor_events_;     ///< arrival and reversal of velocity monitors
  std::vector<format::Node> monitor_nodes_;         ///< SID nodes, or master-patch points as nodes
  std::vector<const FloatingBody*> monitor_bodies_;
  std::vector<std::size_t> monitor_body_index_;
  /// per body: its quasistatic coordinates at the last step and their rate over it (backward
  /// difference: they are solved, not integrated, so the state holds no velocity for them)
  std::vector<Eigen::VectorXd> quasistatic_last_, quasistatic_rate_;
  double quasistatic_last_t_ = 0;
  std::vector<StressMonitor> stress_monitors_;
  std::vector<std::optional<ImpactModes>> impact_modes_;  ///< per contact with a flexible target
  double output_s_ = 0;  ///< time spent in sample() and step()
  /// Wall time of the accepted steps, each from the step() before (or the first sample) to its
  /// own, split by whether a contact carried load at the step's end: a contact's steps cost
  /// its static problem, the others little more than the floating frames.
  struct StepTime {
    std::chrono::steady_clock::time_point last;
    bool started = false;
    double loaded_s = 0, unloaded_s = 0;
    long loaded_steps = 0, unloaded_steps = 0;
    void start() { last = std::chrono::steady_clock::now(), started = true; }
    void add(bool loaded);
  } step_time_;

  /// Adds the time of its scope to a total.
  class OutputClock {
  public:
    explicit OutputClock(double& total) : total_(total) {}
    ~OutputClock() { total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

  private:
    double& total_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  };
};

}  // namespace isosid::run
