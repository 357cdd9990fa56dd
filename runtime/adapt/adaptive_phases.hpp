// The machinery of an adaptive run (adaptive_run.hpp; private to it): the loop of coarse
// phases and impacts (adaptive_phases.cpp) and one touch's impact, tried on refined models
// until the refined region fits and, on a contact's first impact, probed for its penalty
// (adaptive_impact.cpp). The decisions themselves are pure functions elsewhere:
// interval_width (the region's width, [R2] Alg. 2) and penalty_search ([R2] Fig. 3).
#pragma once
#include "adapt/model_cache.hpp"
#include "adapt/adaptive_run.hpp"
#include "adapt/penalty_search.hpp"
#include "adapt/phase_recorder.hpp"
#include "adapt/state_transfer.hpp"
#include "contact/impact_estimate.hpp"
#include "isosid/format/vtk_xml.hpp"
#include "output/run_provenance.hpp"

#include <chrono>
#include <ctime>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace isosid::run {

/// The next phase: `scene` on `sids` from `from`'s state at its time, the bodies' coordinates
/// moved by `maps`, with the penalties `given` in place of the scene's; `energy_change` receives
/// the switch's relative change of the total energy.
std::unique_ptr<Simulation> switch_models(const Simulation& from, const Scene& scene, const std::vector<format::Sid>& sids,
                                          const std::vector<ElasticMap>& maps, double& energy_change, GivenPenalties given = {});

/// One phase run, its folder written.
struct PhaseRun {
  bool over = false;  ///< it ended as the loop asked (a touch, an impact over, an error it stops on)
  RunOutcome outcome;
  nlohmann::json summary;
  std::string file;   ///< its results.h5
  std::optional<PhaseRecorder::Found> found;
  double utilization = 0;
  bool beyond = false;
  std::string error;  ///< PhaseRecorder::error
  PhaseRecorder::Window window;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< impact phases: the region's centre at the end
  std::vector<format::vtk::CollectionEntry> frames;  ///< relative to out_dir/paraview
};

/// One run of an impact on refined models, and with the penalty search its continuations
/// after errors ([R2] Fig. 3's slow decrease: the penalty one lower, on from the last good step).
struct ImpactRun {
  bool over = false;          ///< the impact ended as the loop asks (the last part's, unless it ended on an error)
  RunOutcome outcome;         ///< of the last part (failed, if it ended on an error)
  std::vector<PhaseRun> parts;
  std::vector<nlohmann::json> entries;  ///< the parts' log entries
  double utilization = 0;     ///< the largest of the parts'
  bool beyond = false;
  PenaltyFactor penalty;      ///< of the last part
  bool lowered = false;
};

/// One touch's impact, carried between its steps (tries, penalty probes, the way back).
struct TouchImpact {
  PhaseRecorder::Found found;
  std::size_t k = 0;                     ///< the contact
  std::string contact;                   ///< its name
  std::optional<ImpactEstimate> estimate;  ///< Hertz's, at the touch
  double estimated_width = 0;            ///< the region's width from the estimate (0: none)
  double widest = 0;                     ///< the whole contact surface's
  double sample_interval = 0;            ///< the impact's output interval
  std::optional<PenaltyFactor> penalty;  ///< the penalty the next run takes (unset: the scene's or derived)
  std::string penalty_source = "penalty search: learned at an earlier impact";
  Scene fine_scene;                      ///< the scene on the refined models
  GivenPenalties fine_penalties;         ///< what the runs on them take in place of the scene's penalties
  std::vector<format::Sid> fine_sids;
  std::vector<std::size_t> refined;      ///< the bodies on refined models
  std::vector<ElasticMap> maps;          ///< coarse to fine, per body
  std::unique_ptr<Simulation> fine;      ///< the impact's last simulation
  PhaseRecorder::Impact impact;
  ImpactRun accepted;
  std::size_t accepted_entries = 0;      ///< where the accepted try's entries start in the log
  bool over = false;                     ///< the impact ended as the loop asks
  bool interrupted = false;              ///< a signal stopped the penalty probes
};

class AdaptivePhases {
public:
  /// Tries of one impact before the last one is taken as it is.
  static constexpr int kMaxTries = 4;
  /// Errors in one impact run before the next ends the run: the penalty is then down by two
  /// decades and more ([R2]'s slow decrease has no limit).
  static constexpr int kMaxPenaltyLowerings = 20;

  AdaptivePhases(const Scene& scene, RunFolder& folder, const std::string& out_dir, bool quiet,
                 const std::function<bool()>& stop_requested);
  /// Every phase, then the run's results.h5, summary.json and ParaView collection.
  AdaptiveRun::Result run();

private:
  /// Runs one phase of `simulation` and writes its folder phases/NN-label; `entry` is its log
  /// entry, completed here.
  PhaseRun run_phase(Simulation& simulation, const PhaseRecorder::Impact& impact, const std::string& label, nlohmann::json& entry);
  /// A phase's results join the run's, unless it failed before its first step.
  void keep(const PhaseRun& run);
  /// Runs the impact on `fine`, continuing after errors with a lower penalty while the search
  /// allows; `fine` ends as the last part's simulation.
  ImpactRun run_impact(std::unique_ptr<Simulation>& fine, const Scene& fine_scene, GivenPenalties fine_penalties,
                       const std::vector<format::Sid>& fine_sids, PhaseRecorder::Impact impact, const std::string& label, nlohmann::json entry);
  /// The touch that ended the coarse phase of `coarse`: the refined region's first width.
  TouchImpact start_touch(const Simulation& coarse, const PhaseRecorder::Found& found);
  /// Try `attempt` of the touch's impact: refined models for the current width, the impact
  /// run on them and the width's decision; true when the try is accepted.
  bool try_impact(TouchImpact& t, const Simulation& coarse, int attempt);
  /// The refined models of try `attempt` loaded into t (fine_scene, fine_sids, refined, maps),
  /// with the log's record of the requests; returns the slave's region centre (world).
  Eigen::Vector3d refine(TouchImpact& t, const Simulation& coarse, double width, nlohmann::json& requests, double& preparation_wall);
  /// [R2] Fig. 3's quick increase on the contact's first impact that ran without error.
  void search_penalty(TouchImpact& t, const Simulation& coarse);
  /// The run's results from its phases; rethrows `refusal` after writing them.
  AdaptiveRun::Result finish(RunOutcome outcome, std::exception_ptr refusal);

  const Scene& scene_;
  RunFolder& folder_;
  std::string out_dir_;
  bool quiet_;
  const std::function<bool()>& stop_requested_;
  std::chrono::steady_clock::time_point wall0_;
  std::clock_t cpu0_;
  RunProvenance provenance_;
  ModelCache cache_;
  Scene coarse_;                            ///< the scene on the coarse models
  std::vector<format::Sid> coarse_sids_;
  std::vector<bool> adaptive_contact_;      ///< per contact: an adaptive body takes part
  std::vector<double> width_;               ///< learned per contact
  /// What an impact's accepted width taught, relative to its Hertz estimate's width (the
  /// contact diameter over 70 %), per contact: impacts of one contact differ in force, and the
  /// contact radius with it (scene E's: 36 to 840 N), so the next impact's width scales with
  /// its own estimate.
  std::vector<double> width_per_estimate_;
  std::vector<std::optional<PenaltyFactor>> learned_penalty_;  ///< the penalty search's, per contact
  bool search_;

  std::vector<nlohmann::json> summaries_;   ///< of the phases that make up the run
  std::vector<std::string> files_;
  std::vector<format::vtk::CollectionEntry> frames_;  ///< their ParaView frames, relative to out_dir/paraview
  nlohmann::json log_ = nlohmann::json::array();       ///< every phase run, tries included
  nlohmann::json searches_ = nlohmann::json::array();  ///< the penalty searches ([R2] Fig. 3)
  int phase_ = 0;
  double probes_cpu_ = 0;
};

}  // namespace isosid::run
