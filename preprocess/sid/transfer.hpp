// Transfer of deformation states between a coarse model and its hierarchical refinement
// ([R2] Sect. 4.4, docs/references.md). Nodal: coarse -> fine is exact (the coarse space is nested
// in the THB space); fine -> coarse solves, on every coarse element, for the element's
// control-point displacements from the fine displacements at its (p+1)^d Gauss points and averages
// control points shared by elements. Reduced: q_fine = T q_coarse and back by mass-weighted
// projection of the transferred nodal field onto the other basis ([R2]'s pseudo-inverse weighted
// with M, so dense control nets near the contact do not outweigh the rest of the body). The
// refined model's basis holds the prolongated coarse modes, so coarse -> fine -> coarse is
// the identity and a coarse state keeps its elastic energy.
#pragma once
#include "assemble/assembly.hpp"
#include "model/body_model.hpp"
#include "reduce/mode_basis.hpp"
#include "isosid/format/sid.hpp"

#include <Eigen/Sparse>

namespace isosid::prep {

struct NodalTransfer {
  Eigen::SparseMatrix<double> coarse_to_fine;  ///< fine nodal DOFs x coarse nodal DOFs
  Eigen::SparseMatrix<double> fine_to_coarse;  ///< coarse nodal DOFs x fine nodal DOFs
};

/// `fine` must be a hierarchical refinement of `coarse` (the same refined patch at level 0).
NodalTransfer nodal_transfer(const BodyModel& coarse, const BodyModel& fine);

struct ReducedModel {
  const BodyModel& body;
  const SystemMatrices& system;
  const ReducedBasis& basis;  ///< M-orthonormal on the free DOFs
};

/// The reduced operators q_fine = coarse_to_fine q_coarse, q_coarse = fine_to_coarse q_fine.
format::TransferOperator reduced_transfer(const ReducedModel& coarse, const ReducedModel& fine, const NodalTransfer& nodal);

/// The coarse model's modes on the fine model's free DOFs (exact prolongation). Added to the
/// refined model's basis they make the reduced transfer exact both ways for coarse states.
Eigen::MatrixXd prolongated_modes(const ReducedModel& coarse, const BodyModel& fine, const NodalTransfer& nodal);

}  // namespace isosid::prep
