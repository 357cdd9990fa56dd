// The preprocessing pipeline; see prepare.hpp.
#include "pipeline/prepare.hpp"

#include "assemble/element_pattern.hpp"
#include "isosid/common/heap_reuse.hpp"
#include "isosid/common/progress_line.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/file_kind.hpp"
#include "isosid/format/sid_io.hpp"
#include "reduce/body_reduction.hpp"
#include "reduce/memory_budget.hpp"
#include "reduce/sparse_cholesky.hpp"
#include "sid/sid_builder.hpp"
#include "sid/transfer.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>

namespace isosid::prep {
namespace {

struct AssembledBody {
  BodyModel body;
  SystemMatrices system;
  SparseMatrix scalar_mass;
};

/// Refuses, before any value is integrated, a body whose stiffness factor (every reduction
/// factors it, or its interior) exceeds CHOLMOD's indices or the memory even with nothing else
/// held: its analysis needs the matrix's pattern only. The factorizations check again when they
/// come, with what is held by then.
void refuse_oversized_factor(const BodyModel& b) {
  common::set_work_step("estimating the stiffness's factor");
  SparseCholesky::check_fits(ElementPattern(b.space, b.dofs, Unknowns::FreeDofs, Coupling::AllComponents).zero_matrix(),
                             "the stiffness's factorization");
  common::set_work_step("");
}

/// Stages refine, assembly and, if asked, mass: what every use of a model starts with.
AssembledBody assemble(const ModelSpec& spec, bool with_mass, StageClock& clock) {
  AssembledBody a{clock.run("refine", "refining the geometry", [&] { return build_body(spec); }), {}, {}};
  const BodyModel& b = a.body;
  a.system = clock.run("assembly",
                       "assembling " + std::to_string(b.space.elements.size()) + " elements, " + std::to_string(b.dofs.free_count()) + " DOFs",
                       [&] {
                         refuse_oversized_factor(b);
                         return assemble_system(b.space, b.dofs, b.elasticity, spec.extra_quadrature_points);
                       });
  if (with_mass)
    a.scalar_mass = clock.run("mass", "integrating the mass",
                              [&] { return assemble_scalar_mass(b.space, b.dofs, b.elasticity, spec.extra_quadrature_points); });
  return a;
}

/// f(), one preparation, with a stage's memory refusal as the input error it is: the model asks
/// for more than fits.
template <class F>
auto refusing_oversize(const ModelSpec& spec, F&& f) {
  const PreparationMemory span;  // what its stages reserve on the machine ends with it
  try {
    return f();
  } catch (const MemoryRefusal& e) {
    throw format::InputError(spec.file, e.field(), std::string(e.what()) + ": coarsen the model or prepare it where more memory is free");
  }
}

PreparedBody prepare_body(const ModelSpec& spec, const PrepareOptions& options, StageObserver& observer) {
  StageClock clock(observer);
  AssembledBody a = assemble(spec, options.build_sid, clock);
  // a hierarchical body carries its coarse model's modes, so states transfer exactly; not
  // under a massless boundary, whose coordinates are the fine model's boundary control points
  // (its mass matrix keeps no room for further vectors): such a body is prepared once, with no
  // transfer, for plain runs
  std::optional<PreparedBody> coarse;
  std::optional<NodalTransfer> nodal;
  Eigen::MatrixXd coarse_modes;
  if (a.body.hierarchy && !format::traits(spec.reduction.method).massless_boundary)
    clock.run("coarse_model", "coarse model and nodal transfer", [&] {
      coarse.emplace(prepare_body(coarse_model_spec(spec), {.build_sid = false, .output = ""}, no_progress()));
      nodal = nodal_transfer(coarse->body, a.body);
      coarse_modes = prolongated_modes({coarse->body, coarse->system, coarse->basis}, a.body, *nodal);
    });
  // the reduction's and the SID terms' dense blocks come and go by the hundred; the assembly
  // before, whose arrays are the largest, keeps to glibc's default
  const common::HeapReuse heap_reuse;
  ReducedBasis basis = clock.run("reduction", format::name(spec.reduction.method) + " reduction", [&] { return reduce_body(a.body, a.system, coarse_modes); });
  PreparedBody out{std::move(a.body), std::move(a.system), std::move(a.scalar_mass), std::move(basis), {}, {}};
  if (options.build_sid) {
    out.sid = clock.run("sid_terms", "SID terms, contact data, nodes and stress rows",
                        [&] { return build_sid(out.body, out.system, out.scalar_mass, out.basis); });
    if (coarse) {
      out.sid.transfer = reduced_transfer({coarse->body, coarse->system, coarse->basis}, {out.body, out.system, out.basis}, *nodal);
      out.sid.transfer->coarse_model_sha256 = out.sid.provenance.model_sha256;  // the coarse SID comes from the same file (--coarse)
    }
    out.sid.provenance.timings_s = clock.timings();
    if (!options.output.empty()) clock.run("write", "writing " + options.output, [&] { format::write_sid(out.sid, options.output); });
  }
  out.timings = clock.timings();
  return out;
}

ModalAnalysis analyse_body(const ModelSpec& spec, int n_modes, StageObserver& observer) {
  StageClock clock(observer);
  AssembledBody a = assemble(spec, true, clock);
  // the eigen solver finds fewer modes than DOFs; more is a request this model cannot meet
  const int most = a.body.dofs.free_count() - 1;
  if (n_modes > most)
    throw format::InputError("", "--modes", "asks for " + std::to_string(n_modes) + " modes, but " + spec.file + " refines to " +
                                                std::to_string(most + 1) + " free DOFs (at most " + std::to_string(most) + " modes)");
  ModalResult modes = clock.run("eigen", "solving for " + std::to_string(n_modes) + " modes", [&] {
    const format::Material& fastest = fastest_material(spec);
    const double scale = eigenvalue_scale(fastest.youngs_modulus, fastest.density, body_size(a.body));
    return lowest_modes(a.system.K, a.system.M, n_modes, scale);
  });
  return {std::move(a.body), a.scalar_mass.sum(), std::move(modes), clock.timings()};
}

}  // namespace

std::string sid_output(const std::string& model_file, std::string output, const std::string& field) {
  if (output.empty()) {
    const std::string suffix = ".model.toml";
    const bool named = model_file.size() > suffix.size() && model_file.compare(model_file.size() - suffix.size(), suffix.size(), suffix) == 0;
    output = (named ? model_file.substr(0, model_file.size() - suffix.size()) : model_file) + ".sid.h5";
  }
  format::require_output_file(output);
  std::error_code same_error;
  if (std::filesystem::equivalent(model_file, output, same_error))
    throw format::InputError(output, field, "is the model file itself; the SID would overwrite it");
  return output;
}

PreparedBody prepare(const ModelSpec& spec, const PrepareOptions& options, StageObserver& observer) {
  return refusing_oversize(spec, [&] { return prepare_body(spec, options, observer); });
}

ModalAnalysis analyse_modes(const ModelSpec& spec, int n_modes, StageObserver& observer) {
  return refusing_oversize(spec, [&] { return analyse_body(spec, n_modes, observer); });
}

}  // namespace isosid::prep
