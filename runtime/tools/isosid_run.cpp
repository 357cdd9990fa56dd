// isosid-run: simulates a scene of reduced flexible bodies (SIDs) with Gauss-point penalty
// contact and writes results.h5 and summary.json.
#include "isosid/format/atomic_output.hpp"
#include "isosid/common/cli_parse.hpp"
#include "output/recorder.hpp"
#include "solve/multibody_system.hpp"
#include "solve/time_integrator.hpp"
#include "tools/sid_provider.hpp"

#include <chrono>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace {
using namespace isosid;
using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

/// The body whose state holds a non-finite value, for divergence messages.
std::string diverged_body(const run::MultibodySystem& system, const Eigen::VectorXd& y) {
  for (const auto& b : system.bodies())
    for (Eigen::Index i = 0; i < b->state_size(); ++i)
      if (!std::isfinite(y(b->offset() + i))) return b->name();
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  return common::run_guarded("isosid-run", [&] {
    CLI::App app{"Simulates impacts of reduced flexible bodies (SIDs) described by a scene file.", "isosid-run"};
    std::string scene_file, out_dir;
    bool as_json = false, quiet = false;
    app.add_option("scene", scene_file, "scene file (*.scene.toml)")->required();
    app.add_option("-o,--output", out_dir, "results folder (default: out/<scene name>)");
    app.add_flag("--json", as_json, "print summary.json to stdout");
    app.add_flag("-q,--quiet", quiet, "no progress on stderr");
    if (auto status = common::parse_command_line(app, argc, argv)) return *status;

    const run::Scene scene = run::read_scene_file(scene_file);
    if (out_dir.empty()) {
      std::string stem = fs::path(scene_file).filename().string();
      stem = stem.substr(0, stem.find('.'));
      out_dir = (fs::path("out") / stem).string();
    }
    fs::create_directories(out_dir);
    const run::MultibodySystem system(scene, run::load_sids(scene, quiet));
    Eigen::VectorXd y0(system.size());
    system.initial_state(y0.data());

    run::Recorder recorder(system, scene);
    run::TimeIntegrator integrator(system, scene.simulation, y0);
    integrator.on_step([&](double t, const double* y) { recorder.step(t, y); });
    const double end = scene.simulation.end_time, dt_out = scene.simulation.output_interval;
    double t = 0;
    recorder.sample(0, integrator.y().data());
    std::vector<double> gap(system.contacts().size());
    system.gaps(integrator.y().data(), gap.data());
    for (std::size_t k = 0; k < gap.size(); ++k)
      if (gap[k] < 0) recorder.contact_event(int(k), true, 0.0);  // starts in contact

    const auto t0 = Clock::now();
    const std::clock_t cpu0 = std::clock();
    auto last_progress = t0;
    std::string status = "completed", failure;
    int next = 1;
    try {
      while (t < end * (1 - 1e-12)) {
        const double tout = std::min(end, next * dt_out);
        const auto events = integrator.advance(tout, t);
        if (!integrator.y().allFinite())
          throw format::ComputationError("the state of body '" + diverged_body(system, integrator.y()) + "' is not finite");
        for (const auto& e : events) recorder.contact_event(e.contact, e.closing, t);
        recorder.sample(t, integrator.y().data());
        if (events.empty()) ++next;
        if (!quiet && std::chrono::duration<double>(Clock::now() - last_progress).count() > 1.0) {
          last_progress = Clock::now();
          std::fprintf(stderr, "isosid-run: t = %.4g s (%.0f %%), %ld steps\n", t, 100 * t / end, integrator.stats().steps);
        }
      }
    } catch (const format::ComputationError& e) {
      status = "failed";
      char when[64];
      std::snprintf(when, sizeof when, " (at t = %.6g s)", t);
      failure = e.what() + std::string(when);
    }
    const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
    recorder.write_results((fs::path(out_dir) / "results.h5").string());
    nlohmann::json summary = recorder.summary(integrator.stats(), wall, integrator.y().data(), status);
    summary["cpu_time_s"] = double(std::clock() - cpu0) / CLOCKS_PER_SEC;  // of the integration, like wall_time_s
    if (!failure.empty()) summary["failure"] = failure;
    format::write_text_atomically((fs::path(out_dir) / "summary.json").string(), summary.dump(2) + "\n");
    if (as_json) std::cout << summary.dump(2) << "\n";
    if (!quiet) {
      std::fprintf(stderr, "isosid-run: %s in %.3f s wall, %ld steps -> %s\n", status.c_str(), wall,
                   summary["steps"].get<long>(), out_dir.c_str());
      for (const auto& [key, entry] : summary["reference"].items())
        if (!entry["value"].is_null())
          std::fprintf(stderr, "  %-30s %.6g (reference %.6g, error %.2f %%)\n", key.c_str(), entry["value"].get<double>(),
                       entry["reference"].get<double>(),
                       entry["rel_error"].is_null() ? 0.0 : 100 * entry["rel_error"].get<double>());
    }
    if (!failure.empty()) {
      std::cerr << "isosid-run: failed: " << failure << "; results so far are in " << out_dir << "\n";
      return common::kExitFailure;
    }
    return 0;
  });
}
