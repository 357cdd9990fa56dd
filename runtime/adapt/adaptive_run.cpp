// The adaptive run's phases; see adaptive_run.hpp.
#include "adapt/adaptive_run.hpp"

#include "output/warning_list.hpp"

#include "adapt/interval_width.hpp"
#include "adapt/model_cache.hpp"
#include "adapt/penalty_search.hpp"
#include "adapt/phase_recorder.hpp"
#include "adapt/phase_results.hpp"
#include "adapt/state_transfer.hpp"
#include "contact/deformed_patch.hpp"
#include "contact/impact_estimate.hpp"
#include "isosid/common/number_text.hpp"
#include "isosid/format/atomic_output.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/sid_io.hpp"
#include "output/paraview_series.hpp"
#include "output/recorder.hpp"
#include "output/reference_comparison.hpp"
#include "output/run_report.hpp"
#include "scene/sid_provider.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <tuple>

namespace isosid::run {

namespace {

using nlohmann::json;

/// An impact phase's output samples per Hertz contact time (its force history in results.h5),
/// but at most this many per scene output interval (a contact that stays closed keeps its
/// phase going), and its ParaView frames: one every few samples.
constexpr double kSamplesPerImpact = 100, kMaxSamplesPerOutput = 1000, kSamplesPerFrame = 4;

/// Tries of one impact before the last one is taken as it is.
constexpr int kMaxTries = 4;
/// Errors in one impact run before the next ends the run: the penalty is then down by two
/// decades and more ([R2]'s slow decrease has no limit).
constexpr int kMaxPenaltyLowerings = 20;

/// The output interval of an impact with the Hertz estimate `estimate` at its touch: the
/// scene's [adaptive] impact_output_interval, or a hundredth of the impact's contact time, at
/// most the scene's output interval (a coarse phase's samples are far too sparse for an
/// impact). Without an estimate (flat or conforming surfaces) the scene's own.
double impact_output_interval(const Scene& scene, const std::optional<ImpactEstimate>& estimate) {
  if (scene.adaptive.impact_output_interval > 0) return scene.adaptive.impact_output_interval;
  const double interval = scene.simulation.output_interval;
  if (!estimate || !(estimate->contact_time > 0)) return interval;
  return std::min(interval, std::max(estimate->contact_time / kSamplesPerImpact, interval / kMaxSamplesPerOutput));
}

/// Gives contact k of `scene` a penalty, with where it comes from (summary.json's penalty_source).
void give_penalty(Scene& scene, std::size_t k, double value, std::string source) {
  scene.contacts[k].penalty = value;
  scene.contacts[k].penalty_source = std::move(source);
}

double total_energy(const MultibodySystem& system, const double* y) { return system.energies(y, system.contact_states(y)).total(); }

/// The next phase: `scene` on `sids` from `from`'s state at its time, the bodies' coordinates
/// moved by `maps`; `energy_change` receives the switch's relative change of the total energy.
std::unique_ptr<Simulation> switch_models(const Simulation& from, const Scene& scene, const std::vector<format::Sid>& sids,
                                          const std::vector<ElasticMap>& maps, double& energy_change) {
  const Eigen::VectorXd y = from.state();
  const double before = total_energy(from.system(), y.data());
  double after = 0;
  auto next = std::make_unique<Simulation>(scene, sids, from.time(), [&](const MultibodySystem& to) {
    Eigen::VectorXd moved = transfer_state(from.system(), y.data(), to, maps);
    after = total_energy(to, moved.data());
    return moved;
  });
  energy_change = before != 0 ? (after - before) / std::abs(before) : after - before;
  return next;
}

/// Where the impact of contact k refines: the slave body on its surface at the touch, and a
/// flexible target on its own surface at the touch's parameter there; adaptive bodies only.
struct Refinement {
  std::size_t body;
  RefinementRequest request;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< the request's point, body frame (reference geometry)
};

/// Requests land on a grid, so that impacts at nearly the same place ask for the same model
/// (a cache hit): the point moves by at most 1/32 of the width, the width by at most 4.5 %.
constexpr double kPointGridPerWidth = 16, kWidthStepsPerOctave = 8;

double snapped_width(double width) { return std::exp2(std::round(std::log2(width) * kWidthStepsPerOctave) / kWidthStepsPerOctave); }

/// A contact radius for a model's [contact_resolution], on the same grid but rounded down, so
/// that its elements stay at or below a/8 of the impact (up to 9 % finer) and near-equal
/// impacts ask for the same model.
double snapped_contact_radius(double radius) {
  return std::exp2(std::floor(std::log2(radius) * kWidthStepsPerOctave) / kWidthStepsPerOctave);
}

/// The request for `body`'s `surface` at touch parameter u: u snapped to a grid of width / 16
/// (physical, through the surface's parametric derivatives there), inside the patch, and the
/// snapped point's body-frame position.
Refinement snapped_request(std::size_t index, const FloatingBody& body, const std::string& surface, const Eigen::Vector2d& u, int dim,
                           double width) {
  Refinement out{index, {surface, std::vector<double>(u.data(), u.data() + dim), width}, Eigen::Vector3d::Zero()};
  const format::ContactSurface* s = body.contact_surface(surface);
  const format::MasterPatch* patch = s ? format::find_master_patch(body.sid(), s->master_patch) : nullptr;
  if (!patch) return out;
  const DeformedPatch geometry(*patch, body.sid().dim());
  DeformedPatch::Point point;
  geometry.evaluate(u, point);
  Eigen::Vector2d snapped = u;
  for (int d = 0; d < dim; ++d) {
    const double speed = point.dC[d].norm();  // m per unit parameter
    if (!(speed > 0)) continue;
    const double step = width / kPointGridPerWidth / speed;
    snapped(d) = std::clamp(std::round(u(d) / step) * step, geometry.lower(d), geometry.upper(d));
    out.request.at[std::size_t(d)] = snapped(d);
  }
  geometry.evaluate(snapped, point);
  out.centre = point.C;
  return out;
}

std::vector<Refinement> refinements(const Scene& scene, const MultibodySystem& system, int k, const Touch& touch, double width) {
  const ContactSpec& c = scene.contacts[std::size_t(k)];
  std::vector<Refinement> out;
  auto add = [&](const std::string& body, const std::string& surface, const Eigen::Vector2d& u) {
    const std::size_t i = system.body_index(body);
    if (!scene.bodies[i].adaptive) return;
    out.push_back(snapped_request(i, *system.bodies()[i], surface, u, touch.parameter_dim, width));
  };
  add(c.body, c.surface, touch.slave_parameter);
  if (!c.target_surface.empty()) add(c.target, c.target_surface, touch.target_parameter);
  return out;
}

}  // namespace

AdaptiveRun::AdaptiveRun(Scene scene, RunFolder& folder, bool quiet)
    : scene_(std::move(scene)), folder_(folder), out_dir_(folder.path()), quiet_(quiet) {
  if (!scene_.hertz_contacts.empty())  // the phases' results would be joined without them
    throw format::InputError(scene_.file, "hertz_contact", "Hertz contacts in runs with adaptive bodies are not available yet");
}

AdaptiveRun::Result AdaptiveRun::run(const std::function<bool()>& stop_requested) {
  const auto wall0 = std::chrono::steady_clock::now();
  const RunProvenance provenance = run_provenance(scene_);  // the phases record the SIDs they were built
  const std::clock_t cpu0 = std::clock();
  ModelCache cache(scene_.adaptive.cache, quiet_);
  Scene coarse = scene_;
  for (BodySpec& b : coarse.bodies)
    if (b.adaptive) b.sid_file = cache.coarse(b.model_file).file;
  coarse.simulation.integrator = scene_.adaptive.coarse_integrator;
  coarse.simulation.max_step = scene_.adaptive.coarse_max_step;
  const std::vector<format::Sid> coarse_sids = load_sids(coarse, quiet_);
  check_interval_width_fits(scene_, coarse_sids);
  std::vector<bool> adaptive_contact;
  for (const ContactSpec& c : scene_.contacts) {
    const BodySpec* slave = scene_.body(c.body);
    const BodySpec* target = scene_.body(c.target);
    adaptive_contact.push_back((slave && slave->adaptive) || (target && target->adaptive && !c.target_surface.empty()));
  }
  std::vector<double> width(scene_.contacts.size(), scene_.adaptive.interval_width);  // learned per contact
  // what an impact's accepted width taught, relative to its Hertz estimate's width (the contact
  // diameter over 70 %), per contact: impacts of one contact differ in force, and the contact
  // radius with it (scene E's: 36 to 840 N), so the next impact's width scales with its own estimate
  std::vector<double> width_per_estimate(scene_.contacts.size(), 0.0);
  std::vector<std::optional<PenaltyFactor>> learned_penalty(scene_.contacts.size());  // the penalty search's, per contact
  const bool search = scene_.adaptive.penalty_search;

  std::vector<json> summaries;        // of the phases that make up the run
  std::vector<std::string> files;
  std::vector<format::vtk::CollectionEntry> frames;  // their ParaView frames, relative to out_dir/paraview
  json log = json::array();           // every phase run, tries included
  json searches = json::array();      // the penalty searches ([R2] Fig. 3)
  Result result;
  int phase = 0;
  double probes_cpu = 0;
  // runs one phase and writes its folder
  struct PhaseRun {
    bool over = false;  ///< it ended as the loop asked (a touch, an impact over, an error it stops on)
    RunOutcome outcome;
    json summary;
    std::string file;
    std::optional<PhaseRecorder::Found> found;
    double utilization = 0;
    bool beyond = false;
    std::string error;               ///< PhaseRecorder::error
    PhaseRecorder::Window window;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< impact phases: the region's centre at the end
    std::vector<format::vtk::CollectionEntry> frames;  ///< relative to out_dir/paraview
  };
  auto run_phase = [&](Simulation& simulation, const PhaseRecorder::Impact& impact, const std::string& label, json& entry) {
    PhaseRecorder recorder(simulation, adaptive_contact, impact, stop_requested);
    std::optional<ParaviewSeries> series;  // refuses a flexible body without a viewing mesh
    char name[96];
    std::snprintf(name, sizeof name, "%02d-%s", phase, label.c_str());
    const std::string folder = (std::filesystem::path(out_dir_) / "phases" / name).string();
    if (scene_.output.paraview) series.emplace(simulation.system(), simulation.scene(), folder);
    if (phase++ == 0) {
      // the scene, its models and monitors (the recorder refuses those the models lack) are
      // accepted: the folder now holds this run, and no phases or frames of an earlier one
      folder_.start(scene_.file);
    }
    if (series) recorder.draw_frames(&*series);
    const double start = simulation.time();
    PhaseRun out;
    out.outcome = simulation.run(recorder);
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
  };
  // a phase's results join the run's, unless it failed before its first step: then it holds
  // only its start, where the phase before it ended, and that start may be non-finite (its
  // folder keeps it)
  auto keep = [&](const PhaseRun& run) {
    summaries.push_back(run.summary);
    if (run.summary["status"] == "failed" && run.summary["steps"].get<long>() == 0) return;  // its results and frames stay out
    files.push_back(run.file);
    // a phase starts where the one before it ended: its first frame replaces one there
    if (!run.frames.empty())
      std::erase_if(frames, [&](const format::vtk::CollectionEntry& e) { return e.time >= run.frames.front().time; });
    frames.insert(frames.end(), run.frames.begin(), run.frames.end());
  };
  // the coarse phases' contacts are meant to be coarse: their resolution warnings say nothing
  auto drop_resolution_warnings = [](const MultibodySystem& system, json& summary) {
    for (std::size_t k = 0; k < system.contacts().size(); ++k)
      if (const auto& e = system.impact_estimates()[k]) {
        remove_warning(summary, resolution_warning(system.contacts()[k], *e));
      }
  };

  // One run of an impact on `fine` (scene `fine_scene`, SIDs `fine_sids`), and with the
  // penalty search its continuations after errors ([R2] Fig. 3's slow decrease: the
  // penalty one lower, on from the last good step). `fine` ends as the last part's simulation.
  struct ImpactRun {
    bool over = false;          ///< the impact ended as the loop asks (the last part's, unless it ended on an error)
    RunOutcome outcome;         ///< of the last part (failed, if it ended on an error)
    std::vector<PhaseRun> parts;
    std::vector<json> entries;  ///< the parts' log entries
    double utilization = 0;     ///< the largest of the parts'
    bool beyond = false;
    PenaltyFactor penalty;      ///< of the last part
    bool lowered = false;
  };
  auto run_impact = [&](std::unique_ptr<Simulation>& fine, Scene fine_scene, const std::vector<format::Sid>& fine_sids,
                        PhaseRecorder::Impact impact, const std::string& label, json entry) {
    ImpactRun out;
    const std::size_t k = std::size_t(impact.contact);
    out.penalty = PenaltyFactor(fine->system().contacts()[k].penalty());
    for (int part = 0;; ++part) {
      PhaseRun run = run_phase(*fine, impact, label + (part ? "-lowered" + std::to_string(part) : ""), entry);
      out.utilization = std::max(out.utilization, run.utilization);
      out.beyond = out.beyond || run.beyond;
      // a first part that failed before its first step failed at the impact's start (a continued
      // part's start is the good step of the error before it)
      const bool failed = !run.over && run.outcome.status == "failed" && (part > 0 || run.summary["steps"].get<long>() > 0);
      std::string error = !run.error.empty() ? run.error : failed ? run.outcome.failure : "";
      out.parts.push_back(run);
      if (error.empty() || !search || part == kMaxPenaltyLowerings) {
        out.entries.push_back(entry);
        out.over = run.over && run.error.empty();  // a last error ends the run
        out.outcome = run.error.empty() ? run.outcome : RunOutcome{"failed", run.error};
        return out;
      }
      // the error's step stays; the run goes on from it with the penalty one lower
      const PenaltyFactor lower = out.penalty.lowered();
      entry["penalty_lowered"] = {{"error", error}, {"to_n_m3", lower.value()}};
      out.entries.push_back(entry);
      if (!quiet_)
        std::fprintf(stderr, "isosid-run:   error at %.6g s (%s): penalty %.3g -> %.3g N/m^3, on from there\n", fine->time(), error.c_str(),
                     out.penalty.value(), lower.value());
      out.penalty = lower;
      out.lowered = true;
      give_penalty(fine_scene, k, lower.value(), "penalty search: lowered after an error");
      impact.point = run.centre;
      double change = 0;
      fine = switch_models(*fine, fine_scene, fine_sids, std::vector<ElasticMap>(fine->system().bodies().size()), change);
      entry = {{"kind", "impact"}, {"contact", entry["contact"]}, {"try", entry["try"]}, {"continued", part + 1},
               {"width_m", entry["width_m"]}, {"switch_energy_change", change}};
    }
  };

  auto simulation = std::make_unique<Simulation>(coarse, coarse_sids);
  int last_impact = -1;      // the contact of the impact before the coarse phase about to run
  double switch_energy = 0;  // of the switch into the phase about to run
  std::exception_ptr refusal;  // bad input met between phases: reported after the results so far
  for (;;) try {
    json entry = {{"kind", "coarse"}, {"switch_energy_change", switch_energy}};
    PhaseRecorder::Impact coarse_phase;
    coarse_phase.after = last_impact;
    PhaseRun coarse_run = run_phase(*simulation, coarse_phase, "coarse", entry);
    drop_resolution_warnings(simulation->system(), coarse_run.summary);
    keep(coarse_run);
    log.push_back(entry);
    if (!coarse_run.over) {
      result.outcome = coarse_run.outcome;
      break;
    }

    // a touch: the impact on models refined there, tried until the refined region fits
    const PhaseRecorder::Found found = *coarse_run.found;
    const int k = found.contact;
    const std::string contact = scene_.contacts[std::size_t(k)].name;
    const auto estimate = estimate_impact(simulation->system().contacts()[std::size_t(k)], simulation->state().data());
    const double estimated_width = estimate ? 2 * estimate->contact_radius / kTargetUtilization : 0.0;
    if (estimated_width > 0 && width_per_estimate[std::size_t(k)] > 0)
      width[std::size_t(k)] = snapped_width(width_per_estimate[std::size_t(k)] * estimated_width);
    if (width_per_estimate[std::size_t(k)] == 0)  // the scene's width, not yet one learned
      check_interval_width_reaches(scene_, contact, estimated_width, kMaxTries, kMaxWidening);
    if (!(width[std::size_t(k)] > 0)) {
      if (!(estimated_width > 0))
        throw format::InputError(scene_.file, "adaptive.interval_width", "needed: contact '" + contact + "' has no Hertz estimate at its touch");
      width[std::size_t(k)] = snapped_width(estimated_width);
    }
    // Alg. 2 widens at most to the whole contact surface: the preprocessor refuses wider
    const double widest = widest_interval(scene_, coarse_sids, scene_.contacts[std::size_t(k)]);
    width[std::size_t(k)] = std::min(width[std::size_t(k)], widest);
    const double sample_interval = impact_output_interval(scene_, estimate);
    std::optional<PenaltyFactor> penalty = learned_penalty[std::size_t(k)];  // set by the first try if not learned
    std::string penalty_source = "penalty search: learned at an earlier impact";
    std::unique_ptr<Simulation> fine;
    std::vector<format::Sid> fine_sids;
    std::vector<std::size_t> refined;
    Scene fine_scene;
    std::vector<ElasticMap> maps;
    PhaseRecorder::Impact impact;
    ImpactRun accepted;
    std::size_t accepted_entries = 0;  // where the accepted try's entries start in the log
    bool impact_over = false, interrupted = false;
    for (int attempt = 1; attempt <= kMaxTries; ++attempt) {
      const double w = width[std::size_t(k)];
      fine_scene = coarse;
      fine_scene.simulation = scene_.simulation;  // the impact under the scene's own integrator
      fine_scene.simulation.output_interval = sample_interval;
      // frames every few samples, or at the scene's own interval where that is shorter
      fine_scene.output.paraview_interval =
          std::max(sample_interval, std::min(ParaviewSeries::frame_interval(scene_), kSamplesPerFrame * sample_interval));
      maps.assign(simulation->system().bodies().size(), ElasticMap());
      json requests = json::array();
      refined.clear();
      Eigen::Vector3d centre = found.touch.point;  // the slave's refined region's centre, if it is refined
      const std::size_t slave = simulation->system().body_index(scene_.contacts[std::size_t(k)].body);
      const std::vector<Refinement> wanted = refinements(scene_, simulation->system(), k, found.touch, w);
      std::vector<FineRequest> batch;
      for (const Refinement& r : wanted) {
        if (r.body == slave) {
          const FloatingBody& body = *simulation->system().bodies()[r.body];
          const double* y = simulation->state().data();
          centre = Eigen::Vector3d(body.r(y)) + body.orientation(y) * r.centre;
        }
        FineRequest request{scene_.bodies[r.body].model_file, r.request};
        // a model that sizes its contact elements from a contact radius gets this impact's
        // (its coarse SID records the one it was built for): a/8 at every impact
        if (const auto& d = coarse_sids[r.body].discretization; estimate && d && d->contact_radius > 0)
          request.request.contact_radius = snapped_contact_radius(estimate->contact_radius);
        batch.push_back(request);
      }
      const auto preparation_start = std::chrono::steady_clock::now();
      const std::vector<CachedSid> sids = cache.fine(batch);  // both bodies' models side by side
      const double preparation_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - preparation_start).count();
      for (std::size_t j = 0; j < wanted.size(); ++j) {
        const Refinement& r = wanted[j];
        fine_scene.bodies[r.body].sid_file = sids[j].file;
        refined.push_back(r.body);
        requests.push_back({{"body", scene_.bodies[r.body].name}, {"surface", r.request.surface}, {"at", r.request.at},
                            {"cache_hit", sids[j].hit}, {"preprocessing_s", sids[j].seconds}, {"sid", sids[j].file}});
      }
      fine_sids = load_sids(fine_scene, quiet_);
      for (std::size_t r = 0; r < refined.size(); ++r) {
        const std::size_t i = refined[r];
        const format::Sid& f = fine_sids[i];
        if (!f.transfer || f.transfer->coarse_model_sha256 != coarse_sids[i].provenance.model_sha256 ||
            f.transfer->coarse_to_fine.cols() != coarse_sids[i].nq())
          throw format::ComputationError("the refined SID of '" + scene_.bodies[i].name + "' does not transfer from its coarse model");
        // the coarse modes it was computed against are the coarse SID's: a mode of the other
        // sign, or another basis of a repeated frequency, misses by O(1); the two models'
        // quadratures of the rational basis make 1e-5 (scene D's sphere: 1.6e-5)
        if (const double miss = transfer_mismatch(coarse_sids[i], f, requests[r]["surface"].get<std::string>()); miss > 1e-3)
          throw format::ComputationError("the refined SID " + f.provenance.model_file + " of '" + scene_.bodies[i].name +
                                         "' transfers from other coarse modes than " + scene_.bodies[i].name +
                                         "'s coarse SID (surface displacements differ by " + common::number_text(miss) +
                                         "): clear the model cache " + scene_.adaptive.cache);
        maps[i] = f.transfer->coarse_to_fine;
      }
      if (penalty) give_penalty(fine_scene, std::size_t(k), penalty->value(), penalty_source);
      double into = 0;
      fine = switch_models(*simulation, fine_scene, fine_sids, maps, into);
      if (search && !penalty) {  // the search starts from the scene's penalty, or the one derived at the touch
        penalty = PenaltyFactor(fine->system().contacts()[std::size_t(k)].penalty());
        penalty_source = fine->system().contacts()[std::size_t(k)].penalty_source() + " (the penalty search's start)";
        give_penalty(fine_scene, std::size_t(k), penalty->value(), penalty_source);
      }
      json try_entry = {{"kind", "impact"}, {"contact", contact}, {"try", attempt}, {"touch_s", found.time},
                        {"width_m", w}, {"estimated_width_m", estimated_width}, {"refined", requests}, {"preparation_wall_s", preparation_wall},
                        {"switch_energy_change", into},
                        {"output_interval_s", sample_interval}};
      impact = {k, centre, w, attempt < kMaxTries, -1, PenaltySearch::kContactSteps, search};
      ImpactRun run = run_impact(fine, fine_scene, fine_sids, impact, "impact-" + contact + (attempt > 1 ? "-try" + std::to_string(attempt) : ""),
                                 try_entry);
      if (search) penalty = run.penalty;  // lowered online: later tries start there
      if (run.lowered) penalty_source = "penalty search: lowered after an error";
      IntervalDecision d = decide_interval(run.utilization, run.beyond, w);
      if (!run.over) d = {true, w, "the run ended during the impact"};  // it keeps what it has
      const bool spans_surface = !d.acceptable && d.next_width > w && w >= widest;
      if (spans_surface) d.reason += ", and the region spans its whole surface already";
      const bool accepted_now = d.acceptable || attempt == kMaxTries || spans_surface;
      if (accepted_now && !d.acceptable)  // the last try ran the whole impact, beyond its region or not
        add_warning(run.parts.back().summary,
                    {"adaptive_fit", "contact '" + contact + "': the refined region did not fit after " + std::to_string(attempt) +
                                         " tries (utilization " + common::number_text(100 * run.utilization) + " %, " + d.reason +
                                         "): forces beyond it are not modelled"},
                    scene_.output.expected_warnings);
      if (!quiet_) {  // as [R2] Table 1, one line per try
        bool built = false;
        for (const auto& r : requests) built = built || !r["cache_hit"].get<bool>();
        std::fprintf(stderr, "isosid-run:   try %d: width %.4g mm (%s), penalty %.3g N/m^3, utilization %.0f %%, %s%s\n", attempt, 1e3 * w,
                     built ? "built" : "cached", run.penalty.value(), 100 * run.utilization, d.reason.c_str(), accepted_now ? "" : ": again");
      }
      accepted_entries = log.size();
      for (json& e : run.entries) {
        e.update({{"decision", d.reason}, {"accepted", accepted_now}, {"next_width_m", d.next_width}});
        log.push_back(e);
      }
      width[std::size_t(k)] = std::min(snapped_width(d.next_width), widest);  // the next try starts from it
      if (accepted_now) {
        // the next impact starts from the width asked for next, relative to this one's estimate
        // (none: from the width itself)
        // (a graze teaches nothing: its estimate, from a glancing speed, would scale the next)
        if (d.learned) width_per_estimate[std::size_t(k)] = estimated_width > 0 ? d.next_width / estimated_width : 0.0;
        impact_over = run.over;
        accepted = std::move(run);
        break;
      }
    }

    // [R2] Fig. 3's quick increase, on the contact's first impact that ran without error:
    // probes of the accepted model over the impact's first contact steps, ten times stiffer
    // each, from the touch; a penalty other than the one run runs the impact again
    if (impact_over && search && !learned_penalty[std::size_t(k)] && !accepted.lowered) {
      PenaltySearch trial(*penalty);
      const PhaseRecorder::Window& window = accepted.parts.front().window;
      trial.record({*penalty, window.peak_force, window.steps, ""});
      json probes = json::array({{{"penalty_n_m3", penalty->value()}, {"force_n", window.peak_force}, {"steps", window.steps},
                                  {"from", "the accepted try"}}});
      while (!trial.done()) {
        Scene probe_scene = fine_scene;
        probe_scene.contacts[std::size_t(k)].penalty = trial.next().value();
        probe_scene.simulation.end_time = window.end;
        double unused = 0;
        auto probe = switch_models(*simulation, probe_scene, fine_sids, maps, unused);
        PhaseRecorder::Impact probe_impact = impact;
        probe_impact.stop_beyond = false;
        PhaseRecorder recorder(*probe, adaptive_contact, probe_impact, stop_requested);
        const RunOutcome o = probe->run(recorder);
        if (stop_requested()) {  // a signal: the run ends after the impact it has
          interrupted = true;
          break;
        }
        const PenaltyProbe p{trial.next(), recorder.peak_force(k), probe->stats().steps,
                             o.status == "failed" ? o.failure : recorder.error()};
        trial.record(p);
        probes_cpu += o.cpu_time_s;
        const std::string& error = trial.probes().back().error;  // step growth included
        probes.push_back({{"penalty_n_m3", p.penalty.value()}, {"force_n", p.force}, {"steps", p.steps}, {"cpu_time_s", o.cpu_time_s},
                          {"error", error}});
        if (!quiet_)
          std::fprintf(stderr, "isosid-run:   penalty probe %.3g N/m^3: force %.6g N at %.6g s, %ld steps%s%s\n", p.penalty.value(), p.force,
                       window.end, p.steps, error.empty() ? "" : ", error: ", error.c_str());
      }
      if (trial.done()) {
        searches.push_back({{"contact", contact}, {"touch_s", found.time}, {"window_end_s", window.end}, {"probes", probes},
                            {"penalty_n_m3", trial.result().value()}, {"decision", trial.reason()}});
        if (!quiet_) std::fprintf(stderr, "isosid-run:   penalty %.3g N/m^3: %s\n", trial.result().value(), trial.reason().c_str());
      }
      if (trial.done() && trial.result().value() != penalty->value()) {  // the accepted try gives way to the impact at the found penalty
        for (std::size_t e = accepted_entries; e < log.size(); ++e)
          log[e]["accepted"] = false, log[e]["decision"] = log[e]["decision"].get<std::string>() + "; penalty changed";
        give_penalty(fine_scene, std::size_t(k), trial.result().value(), "penalty search: found by trial");
        double into = 0;
        fine = switch_models(*simulation, fine_scene, fine_sids, maps, into);
        json entry = {{"kind", "impact"}, {"contact", contact}, {"try", "penalty"}, {"touch_s", found.time}, {"width_m", impact.width},
                      {"switch_energy_change", into}};
        impact.stop_beyond = false;  // the width stands
        accepted = run_impact(fine, fine_scene, fine_sids, impact, "impact-" + contact + "-penalty", entry);
        for (json& e : accepted.entries) {
          e.update({{"decision", "the penalty search's"}, {"accepted", true}});
          log.push_back(e);
        }
        impact_over = accepted.over;
      }
    }
    for (const PhaseRun& part : accepted.parts) keep(part);
    if (search) learned_penalty[std::size_t(k)] = accepted.penalty;
    if (interrupted) {
      result.outcome = {"interrupted", ""};
      break;
    }
    if (!impact_over) {
      result.outcome = accepted.outcome;
      break;
    }

    // the impact is over: back to the coarse models
    std::vector<ElasticMap> back(fine->system().bodies().size());
    for (std::size_t i : refined) back[i] = fine_sids[i].transfer->fine_to_coarse;
    simulation = switch_models(*fine, coarse, coarse_sids, back, switch_energy);
    last_impact = k;
  } catch (const format::InputError& e) {  // e.g. a model isosid-prep cannot refine
    if (files.empty()) throw;                  // nothing to keep
    result.outcome = {"failed", e.what()};
    refusal = std::current_exception();
    break;
  } catch (const format::ComputationError& e) {
    if (files.empty()) throw;
    // a signal that stopped isosid-prep stops the run (interrupted, not failed)
    result.outcome = {stop_requested() ? "interrupted" : "failed", e.what()};
    break;
  }
  // the run's results from its phases
  const std::string results = (std::filesystem::path(out_dir_) / "results.h5").string();
  join_phase_results(files, results, scene_.simulation.output_interval, provenance);
  json summary = join_phase_summaries(summaries, results, std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count(),
                                      double(std::clock() - cpu0) / CLOCKS_PER_SEC);
  summary["status"] = result.outcome.status;
  summary["provenance"] = to_json(provenance);
  if (!result.outcome.failure.empty()) summary["failure"] = result.outcome.failure;
  // what refused tries and the wait for isosid-prep took of the run's time (each phase's own
  // times are in its folder and the log)
  double preprocessing = 0, refused_tries = 0;
  for (const auto& p : log) {
    if (p.contains("preparation_wall_s")) preprocessing += p["preparation_wall_s"].get<double>();
    if (p.contains("accepted") && !p["accepted"].get<bool>()) refused_tries += p["cpu_time_s"].get<double>();
  }
  json penalties = json::object();
  for (std::size_t k = 0; k < learned_penalty.size(); ++k)
    if (learned_penalty[k]) penalties[scene_.contacts[k].name] = learned_penalty[k]->value();
  summary["adaptive"] = {{"cache", scene_.adaptive.cache},   {"builds", cache.builds()},
                         {"cache_hits", cache.hits()},       {"preprocessing_wall_s", preprocessing},
                         {"refused_tries_cpu_s", refused_tries}, {"penalty_probes_cpu_s", probes_cpu},
                         {"penalty_search", search},         {"penalties_n_m3", penalties}, {"penalty_searches", searches},
                         {"phases", log}};
  summary["reference"] = compare_with_reference(summary, scene_.reference, scene_.reference_from_hertz);
  format::write_text_atomically((std::filesystem::path(out_dir_) / "summary.json").string(), summary.dump(2) + "\n");
  // one time series over the phases that make up the run; the results are written, so a
  // failure here fails the run with them kept
  if (scene_.output.paraview) ParaviewSeries::write_collection((std::filesystem::path(out_dir_) / "paraview").string(), frames);
  result.summary = summary;
  result.end_time = summary["end_time_s"].get<double>();
  if (refusal) std::rethrow_exception(refusal);  // exit 2, with the results so far written
  return result;
}

}  // namespace isosid::run
