// Joining phase results; see phase_results.hpp.
#include "adapt/phase_results.hpp"

#include "isosid/format/atomic_output.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/hdf5_file.hpp"
#include "output/force_spectrum.hpp"
#include "output/recorder.hpp"
#include "output/warning_list.hpp"
#include "output/velocity_events.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>

namespace isosid::run {

namespace {

using nlohmann::json;

/// Every dataset under `group` whose first dimension is the file's sample count (a time series).
void series_in(const format::h5::Reader& r, const std::string& group, hsize_t samples, std::vector<std::string>& out) {
  for (const std::string& name : r.children(group)) {
    const std::string path = (group == "/" ? "" : group) + "/" + name;
    bool is_group = true;
    try {
      r.children(path);
    } catch (const format::InputError&) {
      is_group = false;
    }
    if (is_group) {
      if (path == "/provenance") continue;  // the run's own, written by the caller
      series_in(r, path, samples, out);
      continue;
    }
    if (name.rfind("spectrum_", 0) == 0) continue;  // over frequencies (computed again for the joined force)
    const std::vector<hsize_t> shape = r.shape(path);
    if (!shape.empty() && shape.size() <= 2 && shape[0] == samples) out.push_back(path);
  }
}

double add_nullable(const json& a, const json& b) { return (a.is_null() ? 0.0 : a.get<double>()) + (b.is_null() ? 0.0 : b.get<double>()); }

}  // namespace

void join_phase_results(const std::vector<std::string>& phase_files, const std::string& path, double output_interval,
                        const RunProvenance& provenance) {
  if (phase_files.empty()) throw format::ComputationError("no phase results to join");
  std::vector<format::h5::Reader> files;
  for (const std::string& f : phase_files) files.emplace_back(f);
  std::vector<std::string> series;
  series_in(files.front(), "/", files.front().shape("/time")[0], series);
  format::AtomicOutput out(path);
  {
    format::h5::Writer w(out.temp_path());
    write_provenance(w, provenance);
    std::vector<std::string> groups;
    for (const std::string& s : series) {
      std::vector<Eigen::MatrixXd> parts;
      bool same_width = true;
      for (std::size_t p = 0; p < files.size() && same_width; ++p) {
        if (!files[p].exists(s)) {
          same_width = false;
          break;
        }
        Eigen::MatrixXd m = files[p].shape(s).size() == 1 ? Eigen::MatrixXd(files[p].vector(s)) : files[p].matrix(s);
        if (!parts.empty() && m.cols() != parts.front().cols()) same_width = false;
        if (p > 0) m = m.bottomRows(m.rows() - 1).eval();  // the phase's start: the last sample before
        parts.push_back(std::move(m));
      }
      if (!same_width) continue;
      Eigen::Index rows = 0;
      for (const auto& m : parts) rows += m.rows();
      Eigen::MatrixXd joined(rows, parts.front().cols());
      rows = 0;
      for (const auto& m : parts) joined.middleRows(rows, m.rows()) = m, rows += m.rows();
      // parent groups first
      for (std::size_t slash = s.find('/', 1); slash != std::string::npos; slash = s.find('/', slash + 1)) {
        const std::string g = s.substr(0, slash);
        if (std::find(groups.begin(), groups.end(), g) == groups.end()) w.group(g), groups.push_back(g);
      }
      const std::string units = files.front().has_attribute(s, "units") ? files.front().string_attribute(s, "units") : "";
      const std::vector<hsize_t> shape = files.front().shape(s);
      if (shape.size() == 1)
        w.vector(s, joined.col(0), units);
      else
        w.matrix(s, joined, units);
      // a contact's spectrum over the whole run
      const std::string suffix = "/force";
      if (s.rfind("/contacts/", 0) == 0 && s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0) {
        const std::string g = s.substr(0, s.size() - suffix.size());
        Eigen::VectorXd time(rows);
        Eigen::Index at = 0;
        for (std::size_t p = 0; p < files.size(); ++p) {
          const Eigen::VectorXd t = files[p].vector("/time");
          const Eigen::Index skip = p > 0 ? 1 : 0;
          time.segment(at, t.size() - skip) = t.tail(t.size() - skip);
          at += t.size() - skip;
        }
        const std::vector<double> t(time.data(), time.data() + time.size());
        std::vector<double> magnitude(static_cast<std::size_t>(rows));
        for (Eigen::Index i = 0; i < rows; ++i) magnitude[std::size_t(i)] = joined.row(i).norm();
        const Spectrum spectrum = force_spectrum(t, magnitude, output_interval);
        w.vector(g + "/spectrum_frequency", spectrum.frequency_hz, "Hz");
        w.vector(g + "/spectrum_amplitude", spectrum.amplitude_ns, "N s");
      }
    }
    w.close();
  }
  out.commit();
}

json join_phase_summaries(const std::vector<json>& phases, const std::string& joined_results, double wall_time_s, double cpu_time_s) {
  if (phases.empty()) throw format::ComputationError("no phase summaries to join");
  const json& first = phases.front();
  const json& last = phases.back();
  json j = last;  // scene, status, failure, bodies (the final state); the rest is joined below
  for (const char* key : {"steps", "rejected_steps", "restarted_steps", "rhs_evaluations", "newton_iterations", "jacobian_setups"}) {
    long long sum = 0;
    for (const json& p : phases) sum += p[key].get<long long>();
    j[key] = sum;
  }
  j["wall_time_s"] = wall_time_s;
  j["cpu_time_s"] = cpu_time_s;
  j["time_per_step_s"] = j["steps"].get<long long>() ? wall_time_s / double(j["steps"].get<long long>()) : 0.0;
  long long evaluations = 0, repeated = 0;
  double active = 0;
  for (const json& p : phases) {
    const long long n = p["rhs_cost"]["evaluations"].get<long long>();
    evaluations += n;
    repeated += p["rhs_cost"]["repeated"].get<long long>();
    active += p["rhs_cost"]["mean_active_points"].get<double>() * double(n);
  }
  j["rhs_cost"] = {{"evaluations", evaluations}, {"repeated", repeated}, {"mean_active_points", evaluations ? active / double(evaluations) : 0.0}};
  for (auto& [part, value] : j["time_split_s"].items()) {
    double sum = 0;
    for (const json& p : phases) sum += p["time_split_s"][part].get<double>();
    value = sum;
  }
  for (const char* part : {"loaded", "unloaded"}) {
    double seconds = 0;
    long long steps = 0;
    for (const json& p : phases) {
      seconds += p["step_time_s"][part].get<double>();
      steps += p["step_time_s"][std::string(part) + "_steps"].get<long long>();
    }
    j["step_time_s"][part] = seconds;
    j["step_time_s"][std::string(part) + "_steps"] = steps;
  }
  json warnings = {{"warnings", json::array()}, {"expected_warnings", json::array()}};  // both lists, each text once
  for (const json& p : phases)
    for (const char* key : {"warnings", "expected_warnings"})
      for (const json& w : p.value(key, json::array()))
        if (std::find(warnings[key].begin(), warnings[key].end(), w) == warnings[key].end()) warnings[key].push_back(w);
  for (std::size_t k = 0; k < j["contacts"].size(); ++k) {
    json& c = j["contacts"][k];
    json start = nullptr, end = nullptr;
    double peak = 0, impulse = 0, penetration = 0;
    long long intervals = 0;
    json touches = json::array(), at_peak = 0, edge = nullptr, interface_left = nullptr;
    const json* loudest = &last["contacts"][k];  // the phase of the largest force: its penalty and estimate
    for (std::size_t i = 0; i < phases.size(); ++i) {
      const json& pc = phases[i]["contacts"][k];
      if (start.is_null()) start = pc["start_s"];
      if (!pc["end_s"].is_null()) end = pc["end_s"];
      if (pc["peak_force_n"].get<double>() > peak) peak = pc["peak_force_n"], at_peak = pc["points_at_peak"], loudest = &pc;
      impulse = add_nullable(impulse, pc["impulse_ns"]);
      penetration = std::max(penetration, pc["max_penetration_m"].get<double>());
      intervals += pc["intervals"].get<long long>();
      // a contact closed across a switch: the later phase reports it as starting at its start
      if (i > 0 && !pc["start_s"].is_null() && pc["start_s"] == phases[i - 1]["end_time_s"]) --intervals;
      for (const json& t : pc["touches"]) touches.push_back(t);
      if (edge.is_null()) edge = pc["edge_reached_s"];
      if (interface_left.is_null()) interface_left = pc["interface_left_s"];
    }
    // a release before the last onset leaves the contact open at the end
    if (!end.is_null() && !last["contacts"][k]["start_s"].is_null() && last["contacts"][k]["end_s"].is_null()) end = nullptr;
    c["start_s"] = start;
    c["end_s"] = end;
    // a phase without the contact says nothing of the run, which warns only if none had it
    c["never_closed"] = start.is_null();
    if (!start.is_null()) remove_warning(warnings, Recorder::never_closed_warning(c["name"].get<std::string>()));
    c["duration_s"] = start.is_null() || end.is_null() ? json(nullptr) : json(end.get<double>() - start.get<double>());
    c["intervals"] = intervals;
    c["touches"] = touches;
    c["peak_force_n"] = peak;
    c["points_at_peak"] = at_peak;
    c["impulse_ns"] = impulse;
    c["max_penetration_m"] = penetration;
    c["edge_reached_s"] = edge;
    c["interface_left_s"] = interface_left;
    for (const char* key : {"penalty_n_m3", "penalty_source", "hertz_estimate"})
      if (loudest->contains(key)) c[key] = (*loudest)[key];
    c.erase("impact_modes");  // a report of one phase's model: in that phase's summary
  }
  j["warnings"] = warnings["warnings"];
  j["expected_warnings"] = warnings["expected_warnings"];
  for (std::size_t k = 0; k < j["joints"].size(); ++k)
    for (const char* key : {"peak_force_n", "peak_torque_n_m", "max_position_error_m", "max_angle_error_rad"}) {
      double most = 0;
      for (const json& p : phases) most = std::max(most, p["joints"][k][key].get<double>());
      j["joints"][k][key] = most;
    }
  format::h5::Reader joined(joined_results);
  const Eigen::VectorXd time = joined.vector("/time");
  for (std::size_t m = 0; m < j["monitors"].size(); ++m) {
    json& mon = j["monitors"][m];
    // arrival and reversal against the run's start, over the joined samples (each phase's own
    // are measured against its start)
    if (mon.value("quantity", "") == "velocity" && joined.exists("/monitors/" + mon["name"].get<std::string>())) {
      const Eigen::MatrixXd v = joined.matrix("/monitors/" + mon["name"].get<std::string>());
      VelocityEvents events;
      events.start(time(0), v.row(0).transpose());
      for (Eigen::Index i = 1; i < v.rows(); ++i) events.add(time(i), v.row(i).transpose());
      mon["arrival_s"] = events.arrival() >= 0 ? json(events.arrival()) : json(nullptr);
      mon["reversal_s"] = events.reversal() >= 0 ? json(events.reversal()) : json(nullptr);
    }
    if (mon.contains("peak_von_mises_pa"))
      for (const json& p : phases)
        if (p["monitors"][m]["peak_von_mises_pa"].get<double>() > mon["peak_von_mises_pa"].get<double>()) mon = p["monitors"][m];
  }
  const double e0 = first["energy"]["initial_j"].get<double>();
  double worst = 0;
  const Eigen::VectorXd total = joined.vector("/energy/total");
  for (double e : total) worst = std::max(worst, std::abs(e - e0));
  j["energy"] = {{"initial_j", e0}, {"final_j", last["energy"]["final_j"]}, {"max_rel_error", e0 != 0 ? worst / std::abs(e0) : worst},
                 {"dissipated_j", last["energy"]["dissipated_j"]}};
  return j;
}

}  // namespace isosid::run
