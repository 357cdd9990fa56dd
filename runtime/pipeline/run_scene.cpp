// The run of a scene; see run_scene.hpp.
#include "pipeline/run_scene.hpp"

#include "adapt/adaptive_run.hpp"
#include "isosid/common/progress_line.hpp"
#include "output/paraview_series.hpp"
#include "output/recorder.hpp"
#include "output/run_report.hpp"
#include "output/warning_list.hpp"
#include "scene/sid_provider.hpp"
#include "solve/contact_resolution.hpp"
#include "solve/observer_list.hpp"
#include "solve/run_checks.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>

namespace isosid::run {
namespace {

/// The run's progress on stderr about once a second unless quiet (one updating line on a
/// terminal), and the caller's stop request asked at every step.
class ProgressReport : public SimulationObserver {
public:
  explicit ProgressReport(const RunOptions& options) : options_(options) {}
  /// Ends the progress line before the run's report.
  void end() { line_.finish(); }
  void sample(double, const double*) override {}
  void step(double, const double*) override {}
  void contact_event(int, bool, double) override {}
  void progress(double t, double end_time, long steps) override {
    if (options_.quiet) return;
    const double fraction = t / end_time;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    char text[160];
    std::snprintf(text, sizeof text, "%3.0f %%, t = %.4g s, %ld steps", 100 * fraction, t, steps);
    const std::string left = common::ProgressLine::time_left(fraction, elapsed);
    line_.show(left.empty() ? text : std::string(text) + ", " + left);
  }
  bool stop_requested() const override { return options_.stop_requested(); }
  bool interrupt_requested() const override { return options_.stop_requested(); }

private:
  const RunOptions& options_;
  common::ProgressLine line_{"isosid-run"};
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

/// Before the run: contacts the Hertz estimate sees still closed at end_time, unless expected.
void announce_predictions(const Simulation& simulation) {
  if (is_expected(simulation.scene().output.expected_warnings, "closed_at_end")) return;
  for (const std::string& w : closed_at_end_predictions(simulation.system(), simulation.time(), simulation.scene().simulation.end_time))
    std::cerr << "isosid-run: warning: " << w << "\n";
}

/// A scene without adaptive bodies: one simulation from t = 0 to end_time.
RunResult run_plain(Scene scene, RunFolder& folder, const RunOptions& options) {
  const std::string scene_file = scene.file;
  std::vector<format::Sid> sids = load_sids(scene, options.quiet);
  fit_contact_resolution(scene, sids, options.quiet);
  Simulation simulation(std::move(scene), std::move(sids));
  if (!options.quiet) announce_predictions(simulation);
  std::optional<ParaviewSeries> paraview;
  if (simulation.scene().output.paraview) paraview.emplace(simulation.system(), simulation.scene(), folder.path());
  Recorder recorder(simulation.system(), simulation.scene());
  ProgressReport progress(options);
  ObserverList observers;  // the recorder first: the frames draw the static solution its samples leave
  observers.add(recorder);
  if (paraview) observers.add(*paraview);
  observers.add(progress);
  if (options.stop_requested()) return {{"interrupted", ""}, {}, 0.0, false};
  folder.start(scene_file);  // only once the scene, its SIDs and monitors are accepted
  const RunOutcome outcome = simulation.run(observers);
  progress.end();
  RunResult result{outcome, write_run_report(folder.path(), recorder, simulation, outcome), simulation.time(), true};
  if (paraview) {
    const std::string collection = paraview->write_collection();
    if (!options.quiet) std::fprintf(stderr, "isosid-run: %d ParaView frames -> %s\n", paraview->frames(), collection.c_str());
  }
  return result;
}

}  // namespace

RunResult run_scene(Scene scene, RunFolder& folder, const RunOptions& options) {
  if (!scene.has_adaptive_bodies()) return run_plain(std::move(scene), folder, options);
  AdaptiveRun adaptive(std::move(scene), folder, options.quiet);  // starts the folder once its first phase is accepted
  AdaptiveRun::Result r = adaptive.run(options.stop_requested);
  return {r.outcome, std::move(r.summary), r.end_time, true};
}

}  // namespace isosid::run
