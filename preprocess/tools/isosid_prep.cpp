// isosid-prep: builds an isogeometric body from a model file, assembles it and reports its
// size and natural frequencies (modal analysis).
#include "assemble/assembly.hpp"
#include "isosid/format/cli_parse.hpp"
#include "model/body_model.hpp"
#include "reduce/modal_analysis.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

namespace {
using namespace isosid;
using Clock = std::chrono::steady_clock;

class StageTimer {
public:
  explicit StageTimer(bool quiet) : quiet_(quiet) {}
  template <class F>
  auto run(const std::string& stage, const std::string& what, F&& f) {
    if (!quiet_) std::fprintf(stderr, "isosid-prep: %s ...\n", what.c_str());
    const auto t0 = Clock::now();
    auto result = f();
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    timings_[stage] = s;
    if (!quiet_) std::fprintf(stderr, "isosid-prep: %s done in %.3f s\n", stage.c_str(), s);
    return result;
  }
  const nlohmann::json& timings() const { return timings_; }

private:
  bool quiet_;
  nlohmann::json timings_ = nlohmann::json::object();
};

}  // namespace

int main(int argc, char** argv) {
  return format::run_guarded("isosid-prep", [&] {
    CLI::App app{"Builds an isogeometric body from MODEL.toml, assembles mass and stiffness and computes its modes.",
                 "isosid-prep"};
    std::string model_file;
    int n_modes = 10;
    bool as_json = false, quiet = false;
    app.add_option("model", model_file, "model file (*.model.toml)")->required();
    app.add_option("--modes", n_modes, "number of lowest modes to compute (rigid-body modes included)")
        ->check(CLI::Range(1, 100000));
    app.add_flag("--json", as_json, "print the result as JSON");
    app.add_flag("-q,--quiet", quiet, "no progress on stderr");
    if (auto status = format::parse_command_line(app, argc, argv)) return *status;

    StageTimer timer(quiet);
    const prep::ModelSpec spec = prep::read_model_file(model_file);  // instant; progress starts on valid input
    const prep::BodyModel body = timer.run("refine", "refining the geometry", [&] { return prep::build_body(spec); });
    const auto system = timer.run("assembly", "assembling " + std::to_string(body.space.elements.size()) + " elements, " +
                                                  std::to_string(body.dofs.free_count()) + " DOFs",
                                  [&] { return prep::assemble_system(body.space, body.dofs, body.elasticity, spec.extra_quadrature_points); });
    const auto mass_matrix = timer.run("mass", "integrating the mass", [&] {
      return prep::assemble_scalar_mass(body.space, body.dofs, body.elasticity, spec.extra_quadrature_points);
    });
    const double mass = mass_matrix.sum();
    const auto modes = timer.run("eigen", "solving for " + std::to_string(n_modes) + " modes",
                                 [&] {
      const double size = (body.refined.points.colwise().maxCoeff() - body.refined.points.colwise().minCoeff()).norm();
      const double scale = prep::eigenvalue_scale(spec.material.youngs_modulus, spec.material.density, size);
      return prep::lowest_modes(system.K, system.M, std::min(n_modes, body.dofs.free_count() - 1), scale);
    });
    const Eigen::VectorXd f = modes.frequencies_hz();

    nlohmann::json j;
    j["body"] = spec.body_name;
    j["analysis"] = format::to_string(spec.analysis);
    j["degrees"] = body.space.degrees;
    j["elements"] = body.space.elements.size();
    j["control_points"] = body.space.n_functions();
    j["nodes"] = body.dofs.node_count();
    j["dofs"] = body.dofs.free_count();
    j["mass_kg"] = mass;
    j["rigid_body_modes"] = modes.rigid_body_modes;
    j["frequencies_hz"] = std::vector<double>(f.data(), f.data() + f.size());
    j["timings_s"] = timer.timings();
    if (as_json) {
      std::cout << j.dump(2) << "\n";
    } else {
      std::printf("%s (%s): %zu elements, degrees", spec.body_name.c_str(), format::to_string(spec.analysis).c_str(),
                  body.space.elements.size());
      for (int p : body.space.degrees) std::printf(" %d", p);
      std::printf(", %d free DOFs, mass %.6g kg\n", body.dofs.free_count(), mass);
      std::printf("%d rigid-body modes; frequencies [Hz]:", modes.rigid_body_modes);
      for (Eigen::Index i = 0; i < f.size(); ++i) std::printf("%s%.6g", i % 6 ? "  " : "\n  ", f(i));
      std::printf("\n");
    }
    return 0;
  });
}
