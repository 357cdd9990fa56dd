// Massless-boundary models as bases; see massless_boundary.hpp.
#include "reduce/massless_boundary.hpp"

namespace isosid::prep {

ReducedBasis massless_boundary_basis(const MasslessBoundaryModel& m) {
  const Eigen::Index nb = m.boundary(), nm = m.Phi.cols();
  ReducedBasis out;
  out.Phi.resize(m.T.rows(), nm + nb);
  out.Phi << m.T.rightCols(nm), m.T.leftCols(nb);
  out.inertial = Eigen::MatrixXd::Zero(m.T.rows(), nm + nb);
  out.inertial.leftCols(nm) = m.Phi;
  out.omega2 = Eigen::VectorXd::Zero(nm + nb);
  out.omega2.head(nm) = m.omega2;
  out.n_low = int(nm);
  out.massless_dofs = m.boundary_dofs;
  // m.K in the basis' order: [eta; u_b] from [u_b; eta]
  out.stiffness.resize(nm + nb, nm + nb);
  out.stiffness << m.K.bottomRightCorner(nm, nm), m.K.bottomLeftCorner(nm, nb), m.K.topRightCorner(nb, nm), m.K.topLeftCorner(nb, nb);
  return out;
}

}  // namespace isosid::prep
