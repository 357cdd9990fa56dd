// Nodes of the SID; see node_data.hpp.
#include "sid/node_data.hpp"

#include "assemble/point_operator.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/skew.hpp"

#include <optional>

namespace isosid::prep {

format::Node node_at(const BodyModel& body, const NodeSpec& spec, const Eigen::MatrixXd& Phi_nodal) {
  const NurbsPatch& patch = body.spec.patches[std::size_t(spec.patch)].patch;
  const Eigen::VectorXd parameter = place(patch, spec.at).parameter;
  const auto at = point_operator_at(body.space, body.dofs, body.elasticity, spec.patch, parameter);
  if (!at) throw format::InputError(body.spec.file, "node " + spec.name, "parameter outside the patch");
  const PointOperator& op = *at;
  // where the parametrization collapses (a pole or a corner on the axis) the gradients are not
  // defined at the point itself: the rotations are taken a hair inside the patch, where they
  // are, and tend to the point's own value as the hair shrinks
  std::optional<PointOperator> inside;
  if (!op.dR_dx.allFinite()) {
    Eigen::VectorXd nudged = parameter;
    for (Eigen::Index d = 0; d < nudged.size(); ++d) {
      const double lo = patch.lower(int(d)), hi = patch.upper(int(d));
      nudged(d) += 1e-7 * (hi - lo) * (nudged(d) >= 0.5 * (lo + hi) ? -1 : 1);
    }
    inside = point_operator_at(body.space, body.dofs, body.elasticity, spec.patch, nudged);
    if (!inside || !inside->dR_dx.allFinite() || inside->nodes != op.nodes)
      throw format::InputError(body.spec.file, "node " + spec.name, "the body's mapping is singular there and around it");
  }
  const Eigen::MatrixXd& dR_dx = inside ? inside->dR_dx : op.dR_dx;
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
        for (int b = 0; b < dim; ++b) grad(a, b) += local(Eigen::Index(f) * dim + a, k) * dR_dx(Eigen::Index(f), b);
    // omega = 1/2 curl u; planar and axisymmetric (at theta = 0) fields rotate about z only
    n.psi.col(k) = 0.5 * Eigen::Vector3d(grad(2, 1) - grad(1, 2), grad(0, 2) - grad(2, 0), grad(1, 0) - grad(0, 1));
    n.origin.M1.push_back(n.phi.col(k));
  }
  n.AP.M0 = Eigen::Matrix3d::Identity();
  for (Eigen::Index k = 0; k < nq; ++k) n.AP.M1.push_back(format::skew(n.psi.col(k)));
  return n;
}

}  // namespace isosid::prep
