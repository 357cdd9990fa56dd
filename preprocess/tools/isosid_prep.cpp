// isosid-prep: builds an isogeometric body from a model file, assembles it, reduces it and
// writes its SID (or, with --modes, reports its size and natural frequencies).
#include "assemble/assembly.hpp"
#include "isosid/common/cli_parse.hpp"
#include "isosid/format/sid_io.hpp"
#include "model/body_model.hpp"
#include "reduce/modal_analysis.hpp"
#include "sid/sid_builder.hpp"
#include "sid/transfer.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

namespace {
using namespace isosid;
using Clock = std::chrono::steady_clock;

/// Runs named stages with progress on stderr and records their times.
class StageTimer {
public:
  explicit StageTimer(bool quiet) : quiet_(quiet) {}
  template <class F>
  auto run(const std::string& stage, const std::string& what, F&& f) {
    if (!quiet_) std::fprintf(stderr, "isosid-prep: %s ...\n", what.c_str());
    const auto t0 = Clock::now();
    auto result = f();
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    timings_.emplace_back(stage, s);
    if (!quiet_) std::fprintf(stderr, "isosid-prep: %s done in %.3f s\n", stage.c_str(), s);
    return result;
  }
  const std::vector<std::pair<std::string, double>>& timings() const { return timings_; }
  nlohmann::json json() const {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [k, v] : timings_) j[k] = v;
    return j;
  }

private:
  bool quiet_;
  std::vector<std::pair<std::string, double>> timings_;
};

std::string default_output(const std::string& model) {
  const std::string suffix = ".model.toml";
  if (model.size() > suffix.size() && model.compare(model.size() - suffix.size(), suffix.size(), suffix) == 0)
    return model.substr(0, model.size() - suffix.size()) + ".sid.h5";
  return model + ".sid.h5";
}

std::vector<double> as_vector(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

std::string format_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  return common::run_guarded("isosid-prep", [&] {
    CLI::App app{"Builds an isogeometric body from MODEL.toml, reduces it and writes its SID file.\n"
                 "With --modes N it only reports the model size and the N lowest frequencies.",
                 "isosid-prep"};
    std::string model_file, output;
    int n_modes = 0;
    bool as_json = false, quiet = false;
    app.add_option("model", model_file, "model file (*.model.toml)")->required();
    app.add_option("-o,--output", output, "SID file to write (default: MODEL with .sid.h5 instead of .model.toml)");
    app.add_option("--modes", n_modes, "modal analysis only: number of lowest modes (rigid-body modes included)")
        ->check(CLI::Range(1, 100000));
    app.add_flag("--json", as_json, "print the result as JSON");
    app.add_flag("-q,--quiet", quiet, "no progress on stderr");
    bool coarse = false;
    app.add_flag("--coarse", coarse,
                 "build the coarse model of a hierarchically refined body instead: the model without its "
                 "[refinement.hierarchical], reduced to its normal modes (what the refined SID's transfer maps from)");
    if (auto status = common::parse_command_line(app, argc, argv)) return *status;

    StageTimer timer(quiet);
    const prep::ModelSpec spec = coarse ? prep::coarse_model_spec(prep::read_model_file(model_file))
                                        : prep::read_model_file(model_file);  // instant; progress starts on valid input
    const prep::BodyModel body = timer.run("refine", "refining the geometry", [&] { return prep::build_body(spec); });
    const auto system = timer.run("assembly", "assembling " + std::to_string(body.space.elements.size()) + " elements, " +
                                                  std::to_string(body.dofs.free_count()) + " DOFs",
                                  [&] { return prep::assemble_system(body.space, body.dofs, body.elasticity, spec.extra_quadrature_points); });
    const auto scalar_mass = timer.run("mass", "integrating the mass", [&] {
      return prep::assemble_scalar_mass(body.space, body.dofs, body.elasticity, spec.extra_quadrature_points);
    });

    nlohmann::json j;
    j["body"] = spec.body_name;
    j["analysis"] = format::to_string(spec.analysis);
    j["degrees"] = body.space.degrees;
    j["elements"] = body.space.elements.size();
    j["control_points"] = body.space.n_functions();
    j["nodes"] = body.dofs.node_count();
    j["dofs"] = body.dofs.free_count();
    j["mass_kg"] = scalar_mass.sum();
    std::string levels_text;
    if (body.hierarchy) {
      const prep::Hierarchy& h = *body.hierarchy;
      j["levels"] = nlohmann::json::array();
      for (int l = 0; l < h.mesh.levels(); ++l) {
        const prep::ParameterBox& d = h.mesh.domains[std::size_t(l)];
        nlohmann::json box = nlohmann::json::array();
        for (std::size_t k = 0; k < d.lo.size(); ++k) box.push_back({d.lo[k], d.hi[k]});
        j["levels"].push_back({{"level", l}, {"functions", h.functions_per_level[std::size_t(l)]},
                               {"elements", h.elements_per_level[std::size_t(l)]}, {"split", h.mesh.factors[std::size_t(l)]},
                               {"domain", box}});
        levels_text += "  level " + std::to_string(l) + ": " + std::to_string(h.elements_per_level[std::size_t(l)]) +
                       " elements, " + std::to_string(h.functions_per_level[std::size_t(l)]) + " functions, split";
        for (int f : h.mesh.factors[std::size_t(l)]) levels_text += " " + std::to_string(f);
        levels_text += ", domain";
        for (std::size_t k = 0; k < d.lo.size(); ++k) levels_text += " [" + format_number(d.lo[k]) + ", " + format_number(d.hi[k]) + "]";
        levels_text += "\n";
      }
    }

    if (n_modes > 0) {
      const auto modes = timer.run("eigen", "solving for " + std::to_string(n_modes) + " modes", [&] {
        const double scale = prep::eigenvalue_scale(spec.material.youngs_modulus, spec.material.density, prep::body_size(body));
        return prep::lowest_modes(system.K, system.M, std::min(n_modes, body.dofs.free_count() - 1), scale);
      });
      const Eigen::VectorXd f = modes.frequencies_hz();
      j["rigid_body_modes"] = modes.rigid_body_modes;
      j["frequencies_hz"] = as_vector(f);
      j["timings_s"] = timer.json();
      if (as_json) {
        std::cout << j.dump(2) << "\n";
        return 0;
      }
      std::printf("%s (%s): %zu elements, degrees", spec.body_name.c_str(), format::to_string(spec.analysis).c_str(),
                  body.space.elements.size());
      for (int p : body.space.degrees) std::printf(" %d", p);
      std::printf(", %d free DOFs, mass %.6g kg\n%s", body.dofs.free_count(), scalar_mass.sum(), levels_text.c_str());
      std::printf("%d rigid-body modes; frequencies [Hz]:", modes.rigid_body_modes);
      for (Eigen::Index i = 0; i < f.size(); ++i) std::printf("%s%.6g", i % 6 ? "  " : "\n  ", f(i));
      std::printf("\n");
      return 0;
    }

    if (output.empty()) output = default_output(model_file);
    // a hierarchical body carries its coarse model's modes, so states transfer exactly
    std::optional<prep::CoarseModel> coarse_model;
    std::optional<prep::NodalTransfer> nodal;
    Eigen::MatrixXd coarse_modes;
    if (body.hierarchy)
      timer.run("coarse_model", "coarse model and nodal transfer", [&] {
        coarse_model.emplace(prep::coarse_model(body));
        nodal = prep::nodal_transfer(coarse_model->body, body);
        coarse_modes = prep::prolongated_modes(*coarse_model, body, *nodal);
        return 0;
      });
    const prep::ReducedBasis basis = timer.run("reduction", spec.reduction.method + " reduction",
                                               [&] { return prep::reduce_body(body, system, coarse_modes); });
    format::Sid sid = timer.run("sid_terms", "SID terms, contact data, nodes and stress rows",
                                [&] { return prep::build_sid(body, system, scalar_mass, basis); });
    if (coarse_model) {
      sid.transfer = prep::reduced_transfer({coarse_model->body, coarse_model->system, coarse_model->basis}, {body, system, basis}, *nodal);
      sid.transfer->coarse_model_sha256 = sid.provenance.model_sha256;  // the coarse SID comes from the same file (--coarse)
    }
    sid.provenance.timings_s = timer.timings();
    timer.run("write", "writing " + output, [&] {
      format::write_sid(sid, output);
      return 0;
    });

    j["nq"] = sid.nq();
    j["n_low"] = sid.refmod.n_low;
    j["n_high"] = sid.refmod.n_high();
    j["reduction"] = basis.method;
    j["removed_rigid_directions"] = basis.removed_rigid;
    j["frequencies_hz"] = as_vector(sid.refmod.frequencies_hz);
    j["contact_points"] = nlohmann::json::object();
    for (const auto& c : sid.contact_surfaces) j["contact_points"][c.name] = c.points();
    j["output"] = output;
    j["timings_s"] = timer.json();
    if (as_json) {
      std::cout << j.dump(2) << "\n";
    } else {
      std::printf("%s: %s reduction, nq = %lld (%d low + %d high), %d free DOFs -> %s\n", spec.body_name.c_str(),
                  basis.method.c_str(), static_cast<long long>(sid.nq()), sid.refmod.n_low, sid.refmod.n_high(),
                  body.dofs.free_count(), output.c_str());
      std::printf("%s", levels_text.c_str());
    }
    return 0;
  });
}
