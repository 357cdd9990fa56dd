// isosid-run: simulates a scene of reduced flexible bodies (SIDs) with Gauss-point penalty
// contact and writes results.h5 and summary.json (the work is run::Simulation's).
#include "isosid/common/cli_parse.hpp"
#include "isosid/common/progress_line.hpp"
#include "adapt/adaptive_run.hpp"
#include "output/paraview_series.hpp"
#include "output/recorder.hpp"
#include "output/run_folder.hpp"
#include "output/run_report.hpp"
#include "scene/sid_provider.hpp"
#include "solve/contact_resolution.hpp"
#include "solve/run_checks.hpp"
#include "solve/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>

namespace {
using namespace isosid;

/// The signal that asked the run to stop (SIGINT, SIGTERM, SIGHUP), 0 while none did.
volatile std::sig_atomic_t g_stop_signal = 0;

void request_stop(int signal) { g_stop_signal = signal; }

/// The recorder, with its progress on stderr about once a second unless quiet (one updating
/// line on a terminal).
class ReportingRecorder : public run::Recorder {
public:
  ReportingRecorder(const run::Simulation& simulation, bool quiet) : Recorder(simulation.system(), simulation.scene()), quiet_(quiet) {}
  /// Ends the progress line before the run's report.
  void end_progress() { line_.finish(); }
  void progress(double t, double end_time, long steps) override {
    if (quiet_) return;
    const double fraction = t / end_time;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    char text[160];
    std::snprintf(text, sizeof text, "%3.0f %%, t = %.4g s, %ld steps", 100 * fraction, t, steps);
    const std::string left = common::ProgressLine::time_left(fraction, elapsed);
    line_.show(left.empty() ? text : std::string(text) + ", " + left);
  }
  bool stop_requested() const override { return g_stop_signal != 0; }
  bool interrupt_requested() const override { return g_stop_signal != 0; }

private:
  bool quiet_;
  common::ProgressLine line_{"isosid-run"};
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

/// out/<scene name> for scene files named <name>.scene.toml.
std::string default_output(const std::string& scene_file) {
  const std::string name = std::filesystem::path(scene_file).filename().string();
  return (std::filesystem::path("out") / name.substr(0, name.find('.'))).string();
}

/// The end of a run: summary.json on stdout if asked, warnings, the one-line report with the
/// reference values, and the exit code (an interruption's shell code, 1 for a failure).
int report(const nlohmann::json& summary, const run::RunOutcome& outcome, double end_time, const std::string& out_dir, bool as_json,
           bool quiet) {
  if (as_json) std::cout << summary.dump(2) << "\n";
  // after the run: a refusal or a failure stays the one line; summary.json always holds them
  if (!quiet && outcome.completed()) {
    for (const auto& warning : summary["warnings"]) std::cerr << "isosid-run: warning: " << warning.get<std::string>() << "\n";
    for (const auto& warning : summary["expected_warnings"]) std::cerr << "isosid-run: expected warning: " << warning.get<std::string>() << "\n";
  }
  const std::string phases = summary.contains("adaptive") ? ", " + std::to_string(summary["adaptive"]["phases"].size()) + " phases" : "";
  if (!quiet)
    std::fprintf(stderr, "isosid-run: %s in %.3f s wall, %lld steps%s -> %s\n%s", outcome.status.c_str(), summary["wall_time_s"].get<double>(),
                 summary["steps"].get<long long>(), phases.c_str(), out_dir.c_str(), run::reference_lines(summary).c_str());
  if (outcome.status == "interrupted") {
    std::fprintf(stderr, "isosid-run: interrupted by %s at t = %.6g s; results so far are in %s\n", strsignal(g_stop_signal), end_time,
                 out_dir.c_str());
    return 128 + int(g_stop_signal);  // the shell's convention: 130 SIGINT, 143 SIGTERM, 129 SIGHUP
  }
  if (!outcome.completed()) {
    std::cerr << "isosid-run: failed: " << outcome.failure << "; results so far are in " << out_dir << "\n";
    return common::kExitFailure;
  }
  return 0;
}

/// A scene with adaptive bodies: phase by phase (run::AdaptiveRun), reported like a plain run.
int run_adaptive(run::Scene scene, run::RunFolder& folder, bool as_json, bool quiet) {
  run::AdaptiveRun adaptive(std::move(scene), folder, quiet);  // starts the folder once its first phase is accepted
  const run::AdaptiveRun::Result result = adaptive.run([] { return g_stop_signal != 0; });
  return report(result.summary, result.outcome, result.end_time, folder.path(), as_json, quiet);
}

}  // namespace

int main(int argc, char** argv) {
  return common::run_guarded("isosid-run", [&] {
    CLI::App app{"Simulates impacts of reduced flexible bodies (SIDs) described by a scene file.", "isosid-run"};
    std::string scene_file, out_dir;
    bool as_json = false, quiet = false, paraview_flag = false;
    app.add_option("scene", scene_file, "scene file (*.scene.toml)")->required();
    app.add_option("-o,--output", out_dir, "results folder (default: out/<scene name>)");
    app.add_flag("--json", as_json, "print summary.json to stdout");
    app.add_flag("-q,--quiet", quiet, "no progress on stderr");
    app.add_flag("--paraview", paraview_flag, "write ParaView frames as with [output] paraview = true");
    if (auto status = common::parse_command_line(app, argc, argv)) return *status;
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, request_stop);  // stop at a sample, keep results

    run::Scene scene = run::read_scene_file(scene_file);
    if (paraview_flag) scene.output.paraview = true;
    if (out_dir.empty()) out_dir = default_output(scene_file);
    run::RunFolder folder(out_dir, scene);  // before any work: a results folder this run may write, and only this run
    if (scene.has_adaptive_bodies()) return run_adaptive(std::move(scene), folder, as_json, quiet);
    std::vector<format::Sid> sids = run::load_sids(scene, quiet);
    run::fit_contact_resolution(scene, sids, quiet);
    run::Simulation simulation(std::move(scene), std::move(sids));
    const std::vector<std::string>& expected = simulation.scene().output.expected_warnings;
    if (!quiet && std::find(expected.begin(), expected.end(), "closed_at_end") == expected.end())
      for (const std::string& w : run::closed_at_end_predictions(simulation.system(), simulation.time(), simulation.scene().simulation.end_time))
        std::cerr << "isosid-run: warning: " << w << "\n";

    std::optional<run::ParaviewSeries> paraview;
    if (simulation.scene().output.paraview) paraview.emplace(simulation.system(), simulation.scene(), out_dir);
    ReportingRecorder recorder(simulation, quiet);
    if (paraview) recorder.draw_frames(&*paraview);
    if (g_stop_signal) {
      std::cerr << "isosid-run: interrupted by " << strsignal(g_stop_signal) << " before the run started\n";
      return 128 + int(g_stop_signal);
    }
    folder.start(scene_file);  // only once the scene, its SIDs and monitors are accepted
    const run::RunOutcome outcome = simulation.run(recorder);
    recorder.end_progress();
    const nlohmann::json summary = run::write_run_report(out_dir, recorder, simulation, outcome);
    if (paraview) {
      const std::string collection = paraview->write_collection();
      if (!quiet) std::fprintf(stderr, "isosid-run: %d ParaView frames -> %s\n", paraview->frames(), collection.c_str());
    }

    return report(summary, outcome, simulation.time(), out_dir, as_json, quiet);
  });
}
