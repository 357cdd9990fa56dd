// Nodes of the SID; see node_data.hpp.
#include "sid/node_data.hpp"

#include "assemble/point_operator.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/skew.hpp"

namespace isosid::prep {

format::Node node_at(const BodyModel& body, const NodeSpec& spec, const Eigen::MatrixXd& Phi_nodal) {
  const auto at = point_operator_at(body.space, body.dofs, body.elasticity, place(body.spec.patch, spec.at).parameter);
  if (!at) throw format::InputError(body.spec.file, "node " + spec.name, "parameter outside the patch");
  const PointOperator& op = *at;
  const int dim = body.dofs.dim();
  const Eigen::Index nq = Phi_nodal.cols();
  // local modal matrices: rows f*dim + a
  const Eigen::MatrixXd local = op.gather(Phi_nodal);
  // gradient of mode k: grad(a, b) = d u_a / d x_b
  format::Node n;
  n.name = spec.name;
  n.origin.M0 = Eigen::Vector3d::Zero();
  n.origin.M0.topRows(dim) = op.x;
  n.phi = Eigen::MatrixXd::Zero(3, nq);
  n.phi.topRows(dim) = op.N * local;
  n.psi = Eigen::MatrixXd::Zero(3, nq);
  for (Eigen::Index k = 0; k < nq; ++k) {
    Eigen::Matrix3d grad = Eigen::Matrix3d::Zero();
    for (std::size_t f = 0; f < op.nodes.size(); ++f)
      for (int a = 0; a < dim; ++a)
        for (int b = 0; b < dim; ++b) grad(a, b) += local(Eigen::Index(f) * dim + a, k) * op.dR_dx(Eigen::Index(f), b);
    // omega = 1/2 curl u; planar and axisymmetric (at theta = 0) fields rotate about z only
    n.psi.col(k) = 0.5 * Eigen::Vector3d(grad(2, 1) - grad(1, 2), grad(0, 2) - grad(2, 0), grad(1, 0) - grad(0, 1));
    n.origin.M1.push_back(n.phi.col(k));
  }
  n.AP.M0 = Eigen::Matrix3d::Identity();
  for (Eigen::Index k = 0; k < nq; ++k) n.AP.M1.push_back(format::skew(n.psi.col(k)));
  return n;
}

}  // namespace isosid::prep
