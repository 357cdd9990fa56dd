// isosid-prep: builds an isogeometric body from a model file, assembles it, reduces it and
// writes its SID (or, with --modes, reports its size and natural frequencies).
#include "isosid/format/atomic_output.hpp"
#include "isosid/common/cli_parse.hpp"
#include "pipeline/prepare.hpp"
#include "reduce/blas_kernels.hpp"
#include "reduce/memory_budget.hpp"
#include "pipeline/prep_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

namespace {

/// "SURFACE:U[,V]" -> the surface's name and its tangential parameter(s).
std::pair<std::string, std::vector<double>> parse_refinement_point(const std::string& text, const std::string& model_file) {
  const std::size_t colon = text.rfind(':');
  const auto refuse = [&] { throw isosid::format::InputError(model_file, "--refine-at", "must be SURFACE:U or SURFACE:U,V, not '" + text + "'"); };
  if (colon == std::string::npos || colon == 0) refuse();
  std::vector<double> at;
  std::size_t begin = colon + 1;
  while (true) {
    const std::size_t comma = text.find(',', begin);
    const std::string number = text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
    char* end = nullptr;
    const double u = std::strtod(number.c_str(), &end);
    if (number.empty() || *end != '\0' || !std::isfinite(u)) refuse();
    at.push_back(u);
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  return {text.substr(0, colon), at};
}

}  // namespace

int main(int argc, char** argv) {
  using namespace isosid;
  prep::rerun_with_better_blas_kernels(argv);  // before any work: OpenBLAS reads its kernel choice at load
  // a preprocessing run killed midway leaves nothing behind, not even its temporary SID
  format::remove_temporaries_on_signals("isosid-prep");
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
    double contact_radius = 0;
    app.add_option("--contact-radius", contact_radius,
                   "expected contact radius in metres, for a model with [contact_resolution] (isosid-run passes its "
                   "Hertz estimate for the scene)");
    bool coarse = false;
    app.add_flag("--coarse", coarse,
                 "build the coarse model of a hierarchically refined body instead: the model without its "
                 "[refinement.hierarchical], reduced to its normal modes (what the refined SID's transfer maps from)");
    std::string refine_at;
    double refine_width = 0;
    app.add_option("--refine-at", refine_at,
                   "SURFACE:U[,V]: centre the model's [refinement.hierarchical] (and a Craig-Bampton interface on that "
                   "surface) at tangential parameter(s) U[,V] of contact surface SURFACE (isosid-run asks so at an impact)");
    app.add_option("--refine-width", refine_width, "with --refine-at: physical width of the refined region, m");
    bool check_only = false;
    app.add_flag("--check", check_only, "only read and check the model file (and the options above): builds and writes nothing");
    double memory_limit_gib = 0;
    app.add_option("--memory-limit", memory_limit_gib,
                   "GiB the preparation may use (default: what the machine has available); a model whose factorization or "
                   "reduction is estimated above it is refused before that stage (exit 2)")
        ->check(CLI::PositiveNumber);
    if (auto status = common::parse_command_line(app, argc, argv)) return *status;
    // flags that cannot all be honoured are refused, not some of them silently dropped
    if (n_modes > 0 && app.count("--output")) throw format::InputError(model_file, "--modes", "reports only; it writes no SID (drop -o)");
    if (coarse && app.count("--refine-at")) throw format::InputError(model_file, "--coarse", "and --refine-at exclude each other");
    if (check_only && (n_modes > 0 || app.count("--output")))
      throw format::InputError(model_file, "--check", "builds nothing: drop " + std::string(n_modes > 0 ? "--modes" : "-o"));
    if (n_modes == 0 && !check_only) output = prep::sid_output(model_file, output, "-o");  // checked before any work

    if (memory_limit_gib > 0) prep::set_memory_limit(memory_limit_gib * 1024.0 * 1024.0 * 1024.0);
    prep::ModelSpec spec = prep::read_model_file(model_file);  // progress starts on valid input (a meshed body is meshed here: gmsh takes well under a second)
    if (app.count("--contact-radius")) prep::set_contact_radius(spec, contact_radius, "--contact-radius");
    if (app.count("--refine-at") != app.count("--refine-width"))
      throw format::InputError(model_file, "--refine-at", "goes with --refine-width (the refined region's width, m)");
    if (app.count("--refine-at")) {
      if (format::traits(spec.reduction.method).massless_boundary)
        throw format::InputError(model_file, "--refine-at",
                                 "an impact's refined model takes its state through a transfer, which a " + format::name(spec.reduction.method) +
                                     " reduction does not carry (adaptive bodies need a Craig-Bampton or modal reduction)");
      const auto [surface, at] = parse_refinement_point(refine_at, model_file);
      prep::set_refinement_point(spec, surface, at, refine_width, "--refine-at");
    }
    if (coarse) {
      if (std::none_of(spec.patches.begin(), spec.patches.end(), [](const prep::PatchSpec& p) { return p.refinement.hierarchical.has_value(); }))
        throw format::InputError(model_file, "--coarse", "the model has no [refinement.hierarchical]");
      spec = prep::coarse_model_spec(std::move(spec));
    }
    if (check_only) return 0;
    prep::StderrProgress progress("isosid-prep");
    prep::StageObserver& observer = quiet ? prep::no_progress() : progress;
    if (n_modes > 0) {
      prep::print_modal_report(prep::analyse_modes(spec, n_modes, observer), as_json);
      return 0;
    }
    prep::print_sid_report(prep::prepare(spec, {.build_sid = true, .output = output}, observer), output, as_json);
    return 0;
  });
}
