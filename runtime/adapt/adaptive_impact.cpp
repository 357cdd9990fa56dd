// One touch's impact of an adaptive run: refined models tried until the refined region fits,
// the impact continued after errors at a lower penalty, and the penalty probes; see
// adaptive_phases.hpp.
#include "adapt/adaptive_phases.hpp"

#include "adapt/interval_width.hpp"
#include "contact/deformed_patch.hpp"
#include "isosid/common/number_text.hpp"
#include "isosid/format/error.hpp"
#include "output/paraview_series.hpp"
#include "output/warning_list.hpp"
#include "scene/sid_provider.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace isosid::run {

namespace {

using nlohmann::json;

/// An impact phase's output samples per Hertz contact time (its force history in results.h5),
/// but at most this many per scene output interval (a contact that stays closed keeps its
/// phase going), and its ParaView frames: one every few samples.
constexpr double kSamplesPerImpact = 100, kMaxSamplesPerOutput = 1000, kSamplesPerFrame = 4;

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

/// Gives contact k a penalty in place of the scene's, with where it comes from (summary.json's
/// penalty_source).
void give_penalty(GivenPenalties& given, std::size_t k, double value, std::string source) {
  if (given.size() <= k) given.resize(k + 1);
  given[k] = ContactPenalty{value, std::move(source)};
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

ImpactRun AdaptivePhases::run_impact(std::unique_ptr<Simulation>& fine, const Scene& fine_scene, GivenPenalties fine_penalties,
                                     const std::vector<format::Sid>& fine_sids,
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
    if (error.empty() || !search_ || part == kMaxPenaltyLowerings) {
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
    give_penalty(fine_penalties, k, lower.value(), "penalty search: lowered after an error");
    impact.point = run.centre;
    double change = 0;
    fine = switch_models(*fine, fine_scene, fine_sids, std::vector<ElasticMap>(fine->system().bodies().size()), change, fine_penalties);
    entry = {{"kind", "impact"}, {"contact", entry["contact"]}, {"try", entry["try"]}, {"continued", part + 1},
             {"width_m", entry["width_m"]}, {"switch_energy_change", change}};
  }
}

TouchImpact AdaptivePhases::start_touch(const Simulation& coarse, const PhaseRecorder::Found& found) {
  TouchImpact t;
  t.found = found;
  t.k = std::size_t(found.contact);
  const std::size_t k = t.k;
  t.contact = scene_.contacts[k].name;
  t.estimate = estimate_impact(coarse.system().contacts()[k], coarse.state().data());
  t.estimated_width = t.estimate ? 2 * t.estimate->contact_radius / kTargetUtilization : 0.0;
  if (t.estimated_width > 0 && width_per_estimate_[k] > 0) width_[k] = snapped_width(width_per_estimate_[k] * t.estimated_width);
  if (width_per_estimate_[k] == 0)  // the scene's width, not yet one learned
    check_interval_width_reaches(scene_, t.contact, t.estimated_width, kMaxTries, kMaxWidening);
  if (!(width_[k] > 0)) {
    if (!(t.estimated_width > 0))
      throw format::InputError(scene_.file, "adaptive.interval_width", "needed: contact '" + t.contact + "' has no Hertz estimate at its touch");
    width_[k] = snapped_width(t.estimated_width);
  }
  // Alg. 2 widens at most to the whole contact surface: the preprocessor refuses wider
  t.widest = widest_interval(scene_, coarse_sids_, scene_.contacts[k]);
  width_[k] = std::min(width_[k], t.widest);
  t.sample_interval = impact_output_interval(scene_, t.estimate);
  t.penalty = learned_penalty_[k];  // set by the first try if not learned
  return t;
}

Eigen::Vector3d AdaptivePhases::refine(TouchImpact& t, const Simulation& coarse, double width, json& requests, double& preparation_wall) {
  t.fine_scene = coarse_;
  t.fine_penalties.clear();  // try_impact gives the search's
  t.fine_scene.simulation = scene_.simulation;  // the impact under the scene's own integrator
  t.fine_scene.simulation.output_interval = t.sample_interval;
  // frames every few samples, or at the scene's own interval where that is shorter
  t.fine_scene.output.paraview_interval =
      std::max(t.sample_interval, std::min(ParaviewSeries::frame_interval(scene_), kSamplesPerFrame * t.sample_interval));
  t.maps.assign(coarse.system().bodies().size(), ElasticMap());
  t.refined.clear();
  Eigen::Vector3d centre = t.found.touch.point;  // the slave's refined region's centre, if it is refined
  const std::size_t slave = coarse.system().body_index(scene_.contacts[t.k].body);
  const std::vector<Refinement> wanted = refinements(scene_, coarse.system(), int(t.k), t.found.touch, width);
  std::vector<FineRequest> batch;
  for (const Refinement& r : wanted) {
    if (r.body == slave) {
      const FloatingBody& body = *coarse.system().bodies()[r.body];
      const double* y = coarse.state().data();
      centre = Eigen::Vector3d(body.r(y)) + body.orientation(y) * r.centre;
    }
    FineRequest request{scene_.bodies[r.body].model_file, r.request};
    // a model that sizes its contact elements from a contact radius gets this impact's
    // (its coarse SID records the one it was built for): a/8 at every impact
    if (const auto& d = coarse_sids_[r.body].discretization; t.estimate && d && d->contact_radius > 0)
      request.request.contact_radius = snapped_contact_radius(t.estimate->contact_radius);
    batch.push_back(request);
  }
  const auto preparation_start = std::chrono::steady_clock::now();
  const std::vector<CachedSid> sids = cache_.fine(batch);  // both bodies' models side by side
  preparation_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - preparation_start).count();
  for (std::size_t j = 0; j < wanted.size(); ++j) {
    const Refinement& r = wanted[j];
    t.fine_scene.bodies[r.body].sid_file = sids[j].file;
    t.refined.push_back(r.body);
    requests.push_back({{"body", scene_.bodies[r.body].name}, {"surface", r.request.surface}, {"at", r.request.at},
                        {"cache_hit", sids[j].hit}, {"preprocessing_s", sids[j].seconds}, {"sid", sids[j].file}});
  }
  t.fine_sids = load_sids(t.fine_scene, quiet_);
  for (std::size_t r = 0; r < t.refined.size(); ++r) {
    const std::size_t i = t.refined[r];
    const format::Sid& f = t.fine_sids[i];
    if (!f.transfer || f.transfer->coarse_model_sha256 != coarse_sids_[i].provenance.model_sha256 ||
        f.transfer->coarse_to_fine.cols() != coarse_sids_[i].nq())
      throw format::ComputationError("the refined SID of '" + scene_.bodies[i].name + "' does not transfer from its coarse model");
    // the coarse modes it was computed against are the coarse SID's: a mode of the other
    // sign, or another basis of a repeated frequency, misses by O(1); the two models'
    // quadratures of the rational basis make 1e-5 (scene D's sphere: 1.6e-5)
    if (const double miss = transfer_mismatch(coarse_sids_[i], f, requests[r]["surface"].get<std::string>()); miss > 1e-3)
      throw format::ComputationError("the refined SID " + f.provenance.model_file + " of '" + scene_.bodies[i].name +
                                     "' transfers from other coarse modes than " + scene_.bodies[i].name +
                                     "'s coarse SID (surface displacements differ by " + common::number_text(miss) +
                                     "): clear the model cache " + scene_.adaptive.cache);
    t.maps[i] = f.transfer->coarse_to_fine;
  }
  return centre;
}

bool AdaptivePhases::try_impact(TouchImpact& t, const Simulation& coarse, int attempt) {
  const std::size_t k = t.k;
  const double w = width_[k];
  json requests = json::array();
  double preparation_wall = 0;
  const Eigen::Vector3d centre = refine(t, coarse, w, requests, preparation_wall);
  if (t.penalty) give_penalty(t.fine_penalties, k, t.penalty->value(), t.penalty_source);
  double into = 0;
  t.fine = switch_models(coarse, t.fine_scene, t.fine_sids, t.maps, into, t.fine_penalties);
  if (search_ && !t.penalty) {  // the search starts from the scene's penalty, or the one derived at the touch
    t.penalty = PenaltyFactor(t.fine->system().contacts()[k].penalty());
    t.penalty_source = t.fine->system().contacts()[k].penalty_source() + " (the penalty search's start)";
    give_penalty(t.fine_penalties, k, t.penalty->value(), t.penalty_source);
  }
  json try_entry = {{"kind", "impact"}, {"contact", t.contact}, {"try", attempt}, {"touch_s", t.found.time},
                    {"width_m", w}, {"estimated_width_m", t.estimated_width}, {"refined", requests}, {"preparation_wall_s", preparation_wall},
                    {"switch_energy_change", into},
                    {"output_interval_s", t.sample_interval}};
  t.impact = {int(k), centre, w, attempt < kMaxTries, -1, PenaltySearch::kContactSteps, search_};
  ImpactRun run = run_impact(t.fine, t.fine_scene, t.fine_penalties, t.fine_sids, t.impact,
                             "impact-" + t.contact + (attempt > 1 ? "-try" + std::to_string(attempt) : ""), try_entry);
  if (search_) t.penalty = run.penalty;  // lowered online: later tries start there
  if (run.lowered) t.penalty_source = "penalty search: lowered after an error";
  IntervalDecision d = decide_interval(run.utilization, run.beyond, w);
  if (!run.over) d = {true, w, "the run ended during the impact"};  // it keeps what it has
  const bool spans_surface = !d.acceptable && d.next_width > w && w >= t.widest;
  if (spans_surface) d.reason += ", and the region spans its whole surface already";
  const bool accepted_now = d.acceptable || attempt == kMaxTries || spans_surface;
  if (accepted_now && !d.acceptable)  // the last try ran the whole impact, beyond its region or not
    add_warning(run.parts.back().summary,
                {"adaptive_fit", "contact '" + t.contact + "': the refined region did not fit after " + std::to_string(attempt) +
                                     " tries (utilization " + common::number_text(100 * run.utilization) + " %, " + d.reason +
                                     "): forces beyond it are not modelled"},
                scene_.output.expected_warnings);
  if (!quiet_) {  // as [R2] Table 1, one line per try
    bool built = false;
    for (const auto& r : requests) built = built || !r["cache_hit"].get<bool>();
    std::fprintf(stderr, "isosid-run:   try %d: width %.4g mm (%s), penalty %.3g N/m^3, utilization %.0f %%, %s%s\n", attempt, 1e3 * w,
                 built ? "built" : "cached", run.penalty.value(), 100 * run.utilization, d.reason.c_str(), accepted_now ? "" : ": again");
  }
  t.accepted_entries = log_.size();
  for (json& e : run.entries) {
    e.update({{"decision", d.reason}, {"accepted", accepted_now}, {"next_width_m", d.next_width}});
    log_.push_back(e);
  }
  width_[k] = std::min(snapped_width(d.next_width), t.widest);  // the next try starts from it
  if (!accepted_now) return false;
  // the next impact starts from the width asked for next, relative to this one's estimate
  // (none: from the width itself; a graze teaches nothing: its estimate, from a glancing
  // speed, would scale the next)
  if (d.learned) width_per_estimate_[k] = t.estimated_width > 0 ? d.next_width / t.estimated_width : 0.0;
  t.over = run.over;
  t.accepted = std::move(run);
  return true;
}

void AdaptivePhases::search_penalty(TouchImpact& t, const Simulation& coarse) {
  // probes of the accepted model over the impact's first contact steps, ten times stiffer
  // each, from the touch; a penalty other than the one run runs the impact again
  const std::size_t k = t.k;
  PenaltySearch trial(*t.penalty);
  const PhaseRecorder::Window& window = t.accepted.parts.front().window;
  trial.record({*t.penalty, window.peak_force, window.steps, ""});
  json probes = json::array({{{"penalty_n_m3", t.penalty->value()}, {"force_n", window.peak_force}, {"steps", window.steps},
                              {"from", "the accepted try"}}});
  while (!trial.done()) {
    Scene probe_scene = t.fine_scene;
    GivenPenalties probe_penalties = t.fine_penalties;
    give_penalty(probe_penalties, k, trial.next().value(), "penalty search: a probe");
    probe_scene.simulation.end_time = window.end;
    double unused = 0;
    auto probe = switch_models(coarse, probe_scene, t.fine_sids, t.maps, unused, probe_penalties);
    PhaseRecorder::Impact probe_impact = t.impact;
    probe_impact.stop_beyond = false;
    PhaseRecorder recorder(*probe, adaptive_contact_, probe_impact, stop_requested_);
    const RunOutcome o = probe->run(recorder);
    if (stop_requested_()) {  // a signal: the run ends after the impact it has
      t.interrupted = true;
      break;
    }
    const PenaltyProbe p{trial.next(), recorder.peak_force(int(k)), probe->stats().steps, o.status == "failed" ? o.failure : recorder.error()};
    trial.record(p);
    probes_cpu_ += o.cpu_time_s;
    const std::string& error = trial.probes().back().error;  // step growth included
    probes.push_back({{"penalty_n_m3", p.penalty.value()}, {"force_n", p.force}, {"steps", p.steps}, {"cpu_time_s", o.cpu_time_s},
                      {"error", error}});
    if (!quiet_)
      std::fprintf(stderr, "isosid-run:   penalty probe %.3g N/m^3: force %.6g N at %.6g s, %ld steps%s%s\n", p.penalty.value(), p.force,
                   window.end, p.steps, error.empty() ? "" : ", error: ", error.c_str());
  }
  if (!trial.done()) return;
  searches_.push_back({{"contact", t.contact}, {"touch_s", t.found.time}, {"window_end_s", window.end}, {"probes", probes},
                       {"penalty_n_m3", trial.result().value()}, {"decision", trial.reason()}});
  if (!quiet_) std::fprintf(stderr, "isosid-run:   penalty %.3g N/m^3: %s\n", trial.result().value(), trial.reason().c_str());
  if (trial.result().value() == t.penalty->value()) return;
  // the accepted try gives way to the impact at the found penalty
  for (std::size_t e = t.accepted_entries; e < log_.size(); ++e)
    log_[e]["accepted"] = false, log_[e]["decision"] = log_[e]["decision"].get<std::string>() + "; penalty changed";
  give_penalty(t.fine_penalties, k, trial.result().value(), "penalty search: found by trial");
  double into = 0;
  t.fine = switch_models(coarse, t.fine_scene, t.fine_sids, t.maps, into, t.fine_penalties);
  json entry = {{"kind", "impact"}, {"contact", t.contact}, {"try", "penalty"}, {"touch_s", t.found.time}, {"width_m", t.impact.width},
                {"switch_energy_change", into}};
  t.impact.stop_beyond = false;  // the width stands
  t.accepted = run_impact(t.fine, t.fine_scene, t.fine_penalties, t.fine_sids, t.impact, "impact-" + t.contact + "-penalty", entry);
  for (json& e : t.accepted.entries) {
    e.update({{"decision", "the penalty search's"}, {"accepted", true}});
    log_.push_back(e);
  }
  t.over = t.accepted.over;
}

}  // namespace isosid::run
