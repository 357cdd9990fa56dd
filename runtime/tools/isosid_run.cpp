// isosid-run: simulates a scene of reduced flexible bodies (SIDs) and writes results.h5 and
// summary.json (the work is run::run_scene's); this file is the command line and the report.
#include "isosid/common/cli_parse.hpp"
#include "isosid/common/heap_reuse.hpp"
#include "output/output_layout.hpp"
#include "output/run_folder.hpp"
#include "output/run_report.hpp"
#include "pipeline/run_scene.hpp"

#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>

namespace {
using namespace isosid;

/// The signal that asked the run to stop (SIGINT, SIGTERM, SIGHUP), 0 while none did.
volatile std::sig_atomic_t g_stop_signal = 0;

void request_stop(int signal) { g_stop_signal = signal; }

/// out/<scene name> for scene files named <name>.scene.toml.
std::string default_output(const std::string& scene_file) {
  const std::string name = std::filesystem::path(scene_file).filename().string();
  return (std::filesystem::path("out") / name.substr(0, name.find('.'))).string();
}

/// The end of a run: summary.json on stdout if asked, warnings, the one-line report with the
/// reference values, and the exit code (an interruption's shell code, 1 for a failure).
int report(const run::RunResult& run, const std::string& out_dir, bool as_json, bool quiet) {
  if (!run.started) {
    std::cerr << "isosid-run: interrupted by " << strsignal(g_stop_signal) << " before the run started\n";
    return 128 + int(g_stop_signal);
  }
  const nlohmann::json& summary = run.summary;
  if (as_json) std::cout << summary.dump(2) << "\n";
  // after the run: a refusal or a failure stays the one line; summary.json always holds them
  if (!quiet && run.outcome.completed()) {
    for (const auto& warning : summary["warnings"]) std::cerr << "isosid-run: warning: " << warning.get<std::string>() << "\n";
    for (const auto& warning : summary["expected_warnings"]) std::cerr << "isosid-run: expected warning: " << warning.get<std::string>() << "\n";
  }
  const std::string phases = summary.contains("adaptive") ? ", " + std::to_string(summary["adaptive"]["phases"].size()) + " phases" : "";
  if (!quiet)
    std::fprintf(stderr, "isosid-run: %s in %.3f s wall, %lld steps%s -> %s\n%s", run.outcome.status.c_str(), summary["wall_time_s"].get<double>(),
                 summary["steps"].get<long long>(), phases.c_str(), out_dir.c_str(), run::reference_lines(summary).c_str());
  if (run.outcome.status == "interrupted") {
    std::fprintf(stderr, "isosid-run: interrupted by %s at t = %.6g s; results so far are in %s\n", strsignal(g_stop_signal), run.end_time,
                 out_dir.c_str());
    return 128 + int(g_stop_signal);  // the shell's convention: 130 SIGINT, 143 SIGTERM, 129 SIGHUP
  }
  if (!run.outcome.completed()) {
    std::cerr << "isosid-run: failed: " << run.outcome.failure << "; results so far are in " << out_dir << "\n";
    return common::kExitFailure;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // reading SIDs and the solvers' blocks reuse pages instead of faulting anew (a run's memory is small)
  const isosid::common::HeapReuse heap_reuse;
  return common::run_guarded("isosid-run", [&] {
    CLI::App app{"Simulates impacts of reduced flexible bodies (SIDs) described by a scene file.", "isosid-run"};
    std::string scene_file, out_dir;
    bool as_json = false, quiet = false, paraview_flag = false, describe_outputs = false;
    std::vector<std::string> settings;
    app.add_option("scene", scene_file, "scene file (*.scene.toml)");
    app.add_flag("--describe-outputs", describe_outputs, "print what results.h5 and summary.json hold (docs/outputs.md) and exit");
    app.add_option("--set", settings, "KEY=VALUE: a value over the scene file's, by dotted key (flexible_body.0.velocity=[0,-0.2,0])");
    app.add_option("-o,--output", out_dir, "results folder (default: out/<scene name>)");
    app.add_flag("--json", as_json, "print summary.json to stdout");
    app.add_flag("-q,--quiet", quiet, "no progress on stderr");
    app.add_flag("--paraview", paraview_flag, "write ParaView frames as with [output] paraview = true");
    if (auto status = common::parse_command_line(app, argc, argv)) return *status;
    if (describe_outputs) {
      std::cout << run::outputs::markdown();
      return 0;
    }
    if (scene_file.empty()) {
      std::cerr << "isosid-run: error: scene is required (see --help)\n";
      return common::kExitBadInput;
    }
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, request_stop);  // stop at a step, keep results

    run::Scene scene = run::read_scene_file(scene_file, common::parse_overrides(settings, "--set"));
    if (paraview_flag) scene.output.paraview = true;
    if (out_dir.empty()) out_dir = default_output(scene_file);
    run::RunFolder folder(out_dir, scene);  // before any work: a results folder this run may write, and only this run
    const run::RunResult result = run::run_scene(std::move(scene), folder, {quiet, [] { return g_stop_signal != 0; }});
    return report(result, out_dir, as_json, quiet);
  });
}
