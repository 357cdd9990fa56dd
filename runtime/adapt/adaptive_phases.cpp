// The loop of an adaptive run's phases; see adaptive_phases.hpp.
#include "adapt/adaptive_phases.hpp"

#include "adapt/interval_width.hpp"
#include "adapt/phase_results.hpp"
#include "isosid/common/number_text.hpp"
#include "isosid/format/atomic_output.hpp"
#include "isosid/format/error.hpp"
#include "output/paraview_series.hpp"
#include "output/reference_comparison.hpp"
#include "output/run_report.hpp"
#include "output/warning_list.hpp"
#include "scene/sid_provider.hpp"
#include "solve/observer_list.hpp"

#include <cstdio>
#include <exception>
#include <filesystem>

namespace isosid::run {

namespace {

using nlohmann::json;

double total_energy(const MultibodySystem& system, const double* y) { return system.energies(y, system.contact_states(y)).total(); }

/// The coarse phases' contacts are meant to be coarse: their resolution warnings say nothing.
void drop_resolution_warnings(const MultibodySystem& system, json& summary) {
  for (std::size_t k = 0; k < system.contacts().size(); ++k)
    if (const auto& e = system.impact_estimates()[k]) remove_warning(summary, resolution_warning(system.contacts()[k], *e));
}

/// The scene with its adaptive bodies on their coarse models, under the coarse integrator.
Scene coarse_scene(const Scene& scene, ModelCache& cache) {
  Scene coarse = scene;
  for (BodySpec& b : coarse.bodies)
    if (b.adaptive) b.sid_file = cache.coarse(b.model_file).file;
  coarse.simulation.integrator = scene.adaptive.coarse_integrator;
  coarse.simulation.max_step = scene.adaptive.coarse_max_step;
  return coarse;
}

}  // namespace

std::unique_ptr<Simulation> switch_models(const Simulation& from, const Scene& scene, const std::vector<format::Sid>& sids,
                                          const std::vector<ElasticMap>& maps, double& energy_change, GivenPenalties given) {
  const Eigen::VectorXd y = from.state();
  const double before = total_energy(from.system(), y.data());
  double after = 0;
  auto next = std::make_unique<Simulation>(scene, sids, from.time(), [&](const MultibodySystem& to) {
    Eigen::VectorXd moved = transfer_state(from.system(), y.data(), to, maps);
    after = total_energy(to, moved.data());
    return moved;
  }, std::move(given));
  energy_change = before != 0 ? (after - before) / std::abs(before) : after - before;
  return next;
}

AdaptivePhases::AdaptivePhases(const Scene& scene, RunFolder& folder, const std::string& out_dir, bool quiet,
                               const std::function<bool()>& stop_requested)
    : scene_(scene), folder_(folder), out_dir_(out_dir), quiet_(quiet), stop_requested_(stop_requested),
      wall0_(std::chrono::steady_clock::now()), cpu0_(std::clock()),
      provenance_(run_provenance(scene)),  // the phases record the SIDs they were built
      cache_(scene.adaptive.cache, quiet), coarse_(coarse_scene(scene, cache_)), coarse_sids_(load_sids(coarse_, quiet)),
      width_(scene.contacts.size(), scene.adaptive.interval_width), width_per_estimate_(scene.contacts.size(), 0.0),
      learned_penalty_(scene.contacts.size()), search_(scene.adaptive.penalty_search) {
  check_interval_width_fits(scene_, coarse_sids_);
  for (const ContactSpec& c : scene_.contacts) {
    const BodySpec* slave = scene_.body(c.body);
    const BodySpec* target = scene_.body(c.target);
    adaptive_contact_.push_back((slave && slave->adaptive) || (target && target->adaptive && !c.target_surface.empty()));
  }
}

PhaseRun AdaptivePhases::run_phase(Simulation& simulation, const PhaseRecorder::Impact& impact, const std::string& label, json& entry) {
  PhaseRecorder recorder(simulation, adaptive_contact_, impact, stop_requested_);
  std::optional<ParaviewSeries> series;  // refuses a flexible body without a viewing mesh
  char name[96];
  std::snprintf(name, sizeof name, "%02d-%s", phase_, label.c_str());
  const std::string folder = (std::filesystem::path(out_dir_) / "phases" / name).string();
  if (scene_.output.paraview) series.emplace(simulation.system(), simulation.scene(), folder);
  if (phase_++ == 0) {
    // the scene, its models and monitors (the recorder refuses those the models lack) are
    // accepted: the folder now holds this run, and no phases or frames of an earlier one
    folder_.start(scene_.file);
  }
  ObserverList observers;  // the recorder first: the frames draw the static solution its samples leave
  observers.add(recorder);
  if (series) observers.add(*series);
  const double start = simulation.time();
  PhaseRun out;
  out.outcome = simulation.run(observers);
  out.over = recorder.phase_over() && out.outcome.status == "interrupted";
  if (out.over) out.outcome.status = "completed";
  std::filesystem::create_directories(folder);
  out.summary = write_run_report(folder, recorder, simulation, out.outcome);
  for (const PhaseRecorder::Found& other : recorder.overlapping())
    add_warning(out.summary,
                {"adaptive_overlap", "contact '" + scene_.contacts[std::size_t(other.contact)].name + "' touched at t = " +
                                         common::number_text(other.time) + " s during the impact of '" +
                                         scene_.contacts[std::size_t(impact.contact)].name + "': it ran on that impact's models, not refined for it"},
                scene_.output.expected_warnings);
  entry.update({{"folder", folder}, {"start_s", start}, {"end_s", simulation.time()}, {"status", out.outcome.status},
                {"steps", out.summary["steps"]}, {"cpu_time_s", out.outcome.cpu_time_s},
                {"energy_start_j", out.summary["energy"]["initial_j"]}, {"energy_end_j", out.summary["energy"]["final_j"]}});
  if (impact.contact >= 0) {
    entry["utilization"] = recorder.utilization();
    entry["penalty_n_m3"] = simulation.system().contacts()[std::size_t(impact.contact)].penalty();
    out.centre = recorder.region_centre(simulation.state().data());
  }
  if (!recorder.error().empty()) entry["error"] = recorder.error();
  if (!quiet_)
    std::fprintf(stderr, "isosid-run: phase %s from %.6g to %.6g s: %s, %ld steps\n", name, start, simulation.time(),
                 out.outcome.status.c_str(), out.summary["steps"].get<long>());
  out.file = (std::filesystem::path(folder) / "results.h5").string();
  out.found = recorder.found();
  out.utilization = recorder.utilization();
  out.beyond = recorder.beyond();
  out.error = recorder.error();
  out.window = recorder.window();
  if (series) {
    series->write_collection();
    for (format::vtk::CollectionEntry e : series->entries()) {
      e.file = (std::filesystem::path("..") / "phases" / name / "paraview" / e.file).generic_string();
      out.frames.push_back(std::move(e));
    }
  }
  return out;
}

void AdaptivePhases::keep(const PhaseRun& run) {
  summaries_.push_back(run.summary);
  // a phase that failed before its first step holds only its start, where the phase before
  // it ended, and that start may be non-finite: its results and frames stay in its folder
  if (run.summary["status"] == "failed" && run.summary["steps"].get<long>() == 0) return;
  files_.push_back(run.file);
  // a phase starts where the one before it ended: its first frame replaces one there
  if (!run.frames.empty())
    std::erase_if(frames_, [&](const format::vtk::CollectionEntry& e) { return e.time >= run.frames.front().time; });
  frames_.insert(frames_.end(), run.frames.begin(), run.frames.end());
}

AdaptiveRun::Result AdaptivePhases::run() {
  auto simulation = std::make_unique<Simulation>(coarse_, coarse_sids_);
  int last_impact = -1;      // the contact of the impact before the coarse phase about to run
  double switch_energy = 0;  // of the switch into the phase about to run
  for (;;) try {
    json entry = {{"kind", "coarse"}, {"switch_energy_change", switch_energy}};
    PhaseRecorder::Impact coarse_phase;
    coarse_phase.after = last_impact;
    PhaseRun coarse_run = run_phase(*simulation, coarse_phase, "coarse", entry);
    drop_resolution_warnings(simulation->system(), coarse_run.summary);
    keep(coarse_run);
    log_.push_back(entry);
    if (!coarse_run.over) return finish(coarse_run.outcome, nullptr);

    // a touch: the impact on models refined there, tried until the refined region fits
    TouchImpact t = start_touch(*simulation, *coarse_run.found);
    for (int attempt = 1; attempt <= kMaxTries; ++attempt)
      if (try_impact(t, *simulation, attempt)) break;
    if (t.over && search_ && !learned_penalty_[t.k] && !t.accepted.lowered) search_penalty(t, *simulation);
    for (const PhaseRun& part : t.accepted.parts) keep(part);
    if (search_) learned_penalty_[t.k] = t.accepted.penalty;
    if (t.interrupted) return finish({"interrupted", ""}, nullptr);
    if (!t.over) return finish(t.accepted.outcome, nullptr);

    // the impact is over: back to the coarse models
    std::vector<ElasticMap> back(t.fine->system().bodies().size());
    for (std::size_t i : t.refined) back[i] = t.fine_sids[i].transfer->fine_to_coarse;
    simulation = switch_models(*t.fine, coarse_, coarse_sids_, back, switch_energy);
    last_impact = int(t.k);
  } catch (const format::InputError& e) {  // e.g. a model isosid-prep cannot refine
    if (files_.empty()) throw;                 // nothing to keep
    return finish({"failed", e.what()}, std::current_exception());
  } catch (const format::ComputationError& e) {
    if (files_.empty()) throw;
    // a signal that stopped isosid-prep stops the run (interrupted, not failed)
    return finish({stop_requested_() ? "interrupted" : "failed", e.what()}, nullptr);
  }
}

AdaptiveRun::Result AdaptivePhases::finish(RunOutcome outcome, std::exception_ptr refusal) {
  const std::string results = (std::filesystem::path(out_dir_) / "results.h5").string();
  join_phase_results(files_, results, scene_.simulation.output_interval, provenance_);
  json summary = join_phase_summaries(summaries_, results, std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0_).count(),
                                      double(std::clock() - cpu0_) / CLOCKS_PER_SEC);
  summary["status"] = outcome.status;
  summary["provenance"] = to_json(provenance_);
  if (!outcome.failure.empty()) summary["failure"] = outcome.failure;
  // what refused tries and the wait for isosid-prep took of the run's time (each phase's own
  // times are in its folder and the log)
  double preprocessing = 0, refused_tries = 0;
  for (const auto& p : log_) {
    if (p.contains("preparation_wall_s")) preprocessing += p["preparation_wall_s"].get<double>();
    if (p.contains("accepted") && !p["accepted"].get<bool>()) refused_tries += p["cpu_time_s"].get<double>();
  }
  json penalties = json::object();
  for (std::size_t k = 0; k < learned_penalty_.size(); ++k)
    if (learned_penalty_[k]) penalties[scene_.contacts[k].name] = learned_penalty_[k]->value();
  summary["adaptive"] = {{"cache", scene_.adaptive.cache},    {"builds", cache_.builds()},
                         {"cache_hits", cache_.hits()},        {"preprocessing_wall_s", preprocessing},
                         {"refused_tries_cpu_s", refused_tries}, {"penalty_probes_cpu_s", probes_cpu_},
                         {"penalty_search", search_},          {"penalties_n_m3", penalties}, {"penalty_searches", searches_},
                         {"phases", log_}};
  summary["reference"] = compare_with_reference(summary, scene_.reference, scene_.reference_from_hertz);
  format::write_text_atomically((std::filesystem::path(out_dir_) / "summary.json").string(), summary.dump(2) + "\n");
  // one time series over the phases that make up the run; the results are written, so a
  // failure here fails the run with them kept
  if (scene_.output.paraview) ParaviewSeries::write_collection((std::filesystem::path(out_dir_) / "paraview").string(), frames_);
  AdaptiveRun::Result result{outcome, summary, summary["end_time_s"].get<double>()};
  if (refusal) std::rethrow_exception(refusal);  // exit 2, with the results so far written
  return result;
}

}  // namespace isosid::run
