// The modal view of an impact on a flexible body, after [R3] (docs/references.md). At the end of a
// contact's first interval (t_E) it reports, for each integrated mode k of the target:
//   E_k / E_0 with E_k = 1/2 (eta_dot_k^2 + omega_k^2 eta_k^2) and E_0 = 1/2 m v_S(t_S)^2;
//   r_k = -(v_S(t_E) - phi_k(P) eta_dot_k(t_E)) / v_S(t_S), the modal coefficient of restitution;
//   v_S the slave's frame velocity along the impact direction d (world; [R3]'s target is at
//   rest before the impact), d the direction of the slave's approach relative to the target's
//   frame at t_S, t_S the last step before the onset; P the target's contact point nearest the
//   force centroid at the peak force, phi_k(P) the mode's displacement there along d with the
//   target's quasistatic or massless coordinates following it statically;
// and labels the target's bending modes in d 1F, 2F, ... in ascending frequency: modes whose
// cross-sections translate along d with at least half their kinetic energy (the SID's shares
// per body axis, weighted by d's components: exact for d along a body axis; d across the
// target's long axis). SIDs without the shares get no labels.
#pragma once
#include "isosid/format/hdf5_file.hpp"
#include "solve/multibody_system.hpp"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace isosid::run {

class ImpactModes {
public:
  /// Contact `contact` of `system`, whose target is the flexible body `target` (its contact
  /// surface `target_surface`).
  ImpactModes(const MultibodySystem& system, int contact, const FloatingBody& target, std::string target_surface);

  /// At the start and per accepted step, with the contact's total force at y: keeps the state of the last step
  /// before the first onset, of the first interval's peak force and of its first step after release.
  void step(double t, const double* y, double force, bool new_peak);

  struct Mode {
    int index = 0;              ///< elastic coordinate of the target
    double frequency_hz = 0;
    std::string label;          ///< "3F", or empty
    double energy_ratio = 0;    ///< E_k(t_E) / E_0
    double restitution = 0;     ///< r_k
  };
  struct Report {
    std::string target;
    double start_s = 0, end_s = 0;      ///< the steps bracketing the contact (t_S before, t_E after)
    double kinetic_energy_j = 0;        ///< E_0
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();  ///< d, world
    double approach_speed = 0, separation_velocity = 0;   ///< v_S(t_S) > 0 and v_S(t_E) along d
    Eigen::Vector3d point = Eigen::Vector3d::Zero();      ///< P, target body frame (reference)
    std::vector<Mode> modes;
  };
  /// Once the first contact has ended: evaluated from the kept states at the first call
  /// (solving their quasistatic coordinates again), then kept; none if that solve fails or the
  /// slave did not approach.
  const std::optional<Report>& report() const;

private:
  const MultibodySystem& system_;
  int contact_;
  const FloatingBody& target_;
  std::string target_surface_;
  enum class Phase { Before, In, Done } phase_ = Phase::Before;
  std::vector<double> before_, peak_, after_;
  double t_before_ = 0, t_after_ = 0;
  mutable bool evaluated_ = false;
  mutable std::optional<Report> report_;
  /// The report from the kept states (throws where their quasistatic solve fails).
  std::optional<Report> evaluate() const;
};

/// summary.json's "impact_modes" of a contact.
nlohmann::json impact_modes_summary(const ImpactModes::Report& report);
/// results.h5: the report as a group (per-mode vectors, labels, scalars).
void write_impact_modes(format::h5::Writer& w, const std::string& group, const ImpactModes::Report& report);

}  // namespace isosid::run
