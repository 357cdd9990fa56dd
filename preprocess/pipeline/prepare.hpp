// The preprocessing pipeline as one call: model -> refined body -> assembled system -> scalar
// mass -> (coarse model and transfer for a hierarchical body) -> reduced basis -> SID. Used by
// isosid-prep, by tests, and for the coarse model of a hierarchical body.
#pragma once
#include "assemble/assembly.hpp"
#include "model/body_model.hpp"
#include "pipeline/stages.hpp"
#include "reduce/modal_analysis.hpp"
#include "reduce/mode_basis.hpp"
#include "isosid/format/sid.hpp"

#include <string>

namespace isosid::prep {

struct PrepareOptions {
  bool build_sid = true;   ///< false: stop after the reduction (no scalar mass, no SID), as a coarse model needs
  std::string output;      ///< write the SID there (stage "write"); empty: do not write
};

struct PreparedBody {
  BodyModel body;
  SystemMatrices system;
  SparseMatrix scalar_mass;  ///< empty without build_sid
  ReducedBasis basis;
  format::Sid sid;           ///< provenance timings: the stages before "write"; empty without build_sid
  StageTimings timings;      ///< every stage run, in order
};

/// Where a model's SID goes: `output`, or the model file's name with .sid.h5 for .model.toml
/// where it is empty; checked before any work (an existing output must be a regular file, and
/// never the model itself: InputError naming `field`, the option that gave it).
std::string sid_output(const std::string& model_file, std::string output, const std::string& field);

/// Stages refine, assembly, mass, coarse_model (hierarchical bodies), reduction, sid_terms, write.
PreparedBody prepare(const ModelSpec& spec, const PrepareOptions& options = {}, StageObserver& observer = no_progress());

struct ModalAnalysis {
  BodyModel body;
  double mass = 0;           ///< kg
  ModalResult modes;         ///< the lowest ones, rigid-body modes included
  StageTimings timings;
};

/// Stages refine, assembly, mass, eigen: the body's size, mass and its `n_modes` lowest modes
/// (at most the free DOFs less one).
ModalAnalysis analyse_modes(const ModelSpec& spec, int n_modes, StageObserver& observer = no_progress());

}  // namespace isosid::prep
