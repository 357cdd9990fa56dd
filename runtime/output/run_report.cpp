// Results folder contents; see run_report.hpp.
#include "output/run_report.hpp"

#include "isosid/format/atomic_output.hpp"

#include <cstdio>
#include <filesystem>

namespace isosid::run {

nlohmann::json write_run_report(const std::string& dir, const Recorder& recorder, const Simulation& simulation,
                                const RunOutcome& outcome) {
  const std::filesystem::path folder(dir);
  // summary.json first: it is small, and on a full disk it is what keeps the run's figures
  nlohmann::json summary = recorder.summary(simulation.stats(), outcome, simulation.state().data());
  format::write_text_atomically((folder / "summary.json").string(), summary.dump(2) + "\n");
  try {
    recorder.write_results((folder / "results.h5").string());
  } catch (const format::ComputationError& e) {
    summary["results_h5_error"] = e.what();
    try {
      format::write_text_atomically((folder / "summary.json").string(), summary.dump(2) + "\n");
    } catch (const format::ComputationError&) {  // the first summary.json stays
    }
    throw format::ComputationError(std::string(e.what()) + " (summary.json in " + dir + " holds the run's figures)");
  }
  return summary;
}

std::string reference_lines(const nlohmann::json& summary) {
  std::string lines;
  for (const auto& [key, entry] : summary["reference"].items()) {
    if (entry["value"].is_null()) continue;
    char line[256];
    if (entry["rel_error"].is_null())
      std::snprintf(line, sizeof line, "  %-30s %.6g (reference %.6g)\n", key.c_str(), entry["value"].get<double>(),
                    entry["reference"].get<double>());
    else
      std::snprintf(line, sizeof line, "  %-30s %.6g (reference %.6g, error %+.2f %%)\n", key.c_str(),
                    entry["value"].get<double>(), entry["reference"].get<double>(), 100 * entry["rel_error"].get<double>());
    lines += line;
  }
  return lines;
}

}  // namespace isosid::run
