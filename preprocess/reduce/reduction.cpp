// Dispatch of the reduction methods; see reduction.hpp.
#include "reduce/reduction.hpp"

#include "isosid/format/error.hpp"
#include "reduce/craig_bampton.hpp"
#include "reduce/macneal.hpp"
#include "reduce/modal_analysis.hpp"


namespace isosid::prep {

ReducedBasis reduce(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, const Eigen::MatrixXd& rigid,
                    const ReductionRequest& r, double lambda_scale) {
  const int n_rigid = int(rigid.cols());
  if (format::traits(r.method).massless_boundary) {
    // not M-orthonormal bases by design: their boundary is massless, their stiffness coupled
    if (r.extra_vectors.cols() > 0) throw format::ComputationError("a massless-boundary reduction cannot carry a coarse model's modes");
    ReducedBasis out = massless_boundary_basis(r.method == format::ReductionMethod::MacNeal
                                                   ? macneal_reduction(K, M, rigid, r.interface_dofs, r.normal_modes)
                                                   : massless_craig_bampton(K, M, rigid, r.interface_dofs, r.normal_modes));
    out.method = r.method;
    out.interface = r.interface_description;
    return out;
  }
  ReducedBasis out;
  out.method = r.method;
  out.interface = r.interface_description;
  switch (r.method) {
    case format::ReductionMethod::Modal: {
      if (r.normal_modes < 1) throw format::ComputationError("modal reduction needs at least one mode");
      const ModalResult m = lowest_modes(K, M, r.normal_modes + n_rigid, lambda_scale);
      out.Phi = m.modes.rightCols(r.normal_modes);
      break;
    }
    case format::ReductionMethod::CraigBampton:
      out.Phi = craig_bampton_basis(K, M, r.interface_dofs, r.normal_modes);
      out.interface_dofs = r.interface_dofs;
      break;
    case format::ReductionMethod::Full:
      out.Phi = lowest_modes(K, M, int(K.rows()), lambda_scale).modes;
      break;
    case format::ReductionMethod::MacNeal:
    case format::ReductionMethod::CraigBamptonMassless:
      break;  // above
  }
  if (r.extra_vectors.cols() > 0) {
    out.Phi.conservativeResize(Eigen::NoChange, out.Phi.cols() + r.extra_vectors.cols());
    out.Phi.rightCols(r.extra_vectors.cols()) = r.extra_vectors;
  }
  const Eigen::Index raw = out.Phi.cols();
  remove_rigid_content(out.Phi, M, rigid);
  out.omega2 = orthonormalize(out.Phi, K, M);
  out.removed_rigid = int(raw - out.Phi.cols());
  out.n_low = format::traits(r.method).interface_nodes ? std::min<int>(r.normal_modes, int(out.Phi.cols())) : int(out.Phi.cols());
  return out;
}

}  // namespace isosid::prep
