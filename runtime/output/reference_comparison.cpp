// Reference comparison; see reference_comparison.hpp.
#include "output/reference_comparison.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <optional>
#include <set>

namespace isosid::run {

namespace {

using nlohmann::json;

/// The first monitor entry that has `key` (point monitors come before stress monitors).
const json* first_monitor_with(const json& summary, const std::string& key) {
  for (const json& m : summary["monitors"])
    if (m.contains(key)) return &m;
  return nullptr;
}

std::optional<double> measured(const json& j, const std::string& key) {
  const json& c = j["contacts"];
  const json& b = j["bodies"][0];
  const auto number = [](const json& v) { return v.is_null() ? std::nullopt : std::optional<double>(v.get<double>()); };
  if (key == "peak_force_n" && !c.empty()) return c[0]["peak_force_n"].get<double>();
  if (key == "contact_time_s" && !c.empty()) return number(c[0]["duration_s"]);
  if (key == "contact_end_s" && !c.empty()) return number(c[0]["end_s"]);
  if (key == "rebound_velocity_m_s") {
    // a rebound only once the impact is over: not while the contact is still closed at the
    // end of the run, nor for a body that never touched
    if (!c.empty() && (c[0]["start_s"].is_null() || c[0]["end_s"].is_null())) return std::nullopt;
    return Eigen::Vector3d(b["final_velocity"][0], b["final_velocity"][1], b["final_velocity"][2]).norm();
  }
  if (key == "final_velocity_x_m_s") return b["final_velocity"][0].get<double>();
  if (key == "final_velocity_y_m_s") return b["final_velocity"][1].get<double>();
  if (key == "final_velocity_z_m_s") return b["final_velocity"][2].get<double>();
  if (key == "final_angular_velocity_rad_s") return b["final_angular_velocity"][2].get<double>();
  if (key == "wave_arrival_s")
    if (const json* m = first_monitor_with(j, "arrival_s")) return number((*m)["arrival_s"]);
  if (key == "peak_von_mises_pa")
    if (const json* m = first_monitor_with(j, "peak_von_mises_pa")) return (*m)["peak_von_mises_pa"].get<double>();
  if (key == "peak_von_mises_depth_m")
    if (const json* m = first_monitor_with(j, "peak_von_mises_pa"); m && m->contains("peak_depth_m")) return (*m)["peak_depth_m"].get<double>();
  return std::nullopt;
}

}  // namespace

json compare_with_reference(const json& summary, const std::map<std::string, double>& given, bool from_hertz) {
  std::map<std::string, double> reference = given;
  std::set<std::string> from_estimate;  // the summary's estimate names its figures as [reference] does
  if (from_hertz && !summary["contacts"].empty() && summary["contacts"][0].contains("hertz_estimate")) {
    const json& e = summary["contacts"][0]["hertz_estimate"];
    for (const char* key : {"peak_force_n", "contact_time_s"})
      if (e.contains(key) && e[key].is_number()) reference[key] = e[key].get<double>(), from_estimate.insert(key);
  }
  json cmp = json::object();
  for (const auto& [key, ref] : reference) {
    const auto value = measured(summary, key);
    json entry = {{"reference", ref}};
    entry["value"] = value ? json(*value) : json(nullptr);
    entry["rel_error"] = value && ref != 0 ? json((*value - ref) / std::abs(ref)) : json(nullptr);
    if (value && ref == 0) entry["abs_error"] = *value;
    if (from_estimate.count(key)) entry["source"] = "hertz";
    cmp[key] = entry;
  }
  return cmp;
}

}  // namespace isosid::run
