// Cross-section translation shares of modes; see section_translation.hpp.
#include "sid/section_translation.hpp"

#include "isosid/common/dense_decompositions.hpp"
#include "reduce/sparse_products.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace isosid::prep {

SectionTranslation section_translation(const Eigen::MatrixXd& modes, const Eigen::MatrixXd& node_points,
                                       const Eigen::SparseMatrix<double>& scalar_mass, int sections) {
  const Eigen::Index nodes = node_points.rows(), dim = node_points.cols(), n = modes.cols();
  if (nodes == 0 || sections < 1) return {};
  // the mass lumped to the control points (row sums: the functions form a partition of unity)
  const Eigen::VectorXd lumped = scalar_mass * Eigen::VectorXd::Ones(nodes);
  const double mass = lumped.sum();
  const Eigen::VectorXd center = node_points.transpose() * lumped / mass;
  Eigen::MatrixXd spread = Eigen::MatrixXd::Zero(dim, dim);
  for (Eigen::Index i = 0; i < nodes; ++i) {
    const Eigen::VectorXd d = node_points.row(i).transpose() - center;
    spread += lumped(i) * d * d.transpose();
  }
  const common::SymmetricEigen principal = common::symmetric_eigen(spread);
  // without a distinct long axis (a ball, a cube) there are no beam modes, and the axis would be
  // round-off's choice
  const Eigen::VectorXd& moments = principal.values;
  if (dim < 2 || moments(dim - 1) < 1.05 * moments(dim - 2)) return {Eigen::Vector3d::Zero(), Eigen::MatrixXd()};
  const Eigen::VectorXd axis = principal.vectors.col(dim - 1);  // largest second moment
  SectionTranslation out;
  out.shares = Eigen::MatrixXd::Zero(n, 3);
  out.long_axis.setZero();
  out.long_axis.head(dim) = axis;

  // slab j's field: the translation of the control points lying in it (a bump along the axis);
  // nodes x sections, the empty slabs left out
  const Eigen::VectorXd s = (node_points.rowwise() - center.transpose()) * axis;
  const double lo = s.minCoeff(), width = std::max(s.maxCoeff() - lo, 1e-300) / sections;
  std::vector<int> column(std::size_t(sections), -1);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(nodes));
  int used = 0;
  for (Eigen::Index i = 0; i < nodes; ++i) {
    const int slab = std::min(sections - 1, int((s(i) - lo) / width));
    if (column[std::size_t(slab)] < 0) column[std::size_t(slab)] = used++;
    entries.emplace_back(int(i), column[std::size_t(slab)], 1.0);
  }
  Eigen::SparseMatrix<double> fields(nodes, used);
  fields.setFromTriplets(entries.begin(), entries.end());
  // the M-orthogonal projection onto their span: share = b^T G^-1 b / u^T M u with the Gram
  // matrix G = F^T M F and b = F^T M u (per component: the scalar mass couples no components)
  const Eigen::MatrixXd gram = Eigen::MatrixXd(fields.transpose() * scalar_mass * fields);
  const Eigen::LDLT<Eigen::MatrixXd> gram_ldlt(gram);

  Eigen::VectorXd kinetic = Eigen::VectorXd::Zero(n);
  Eigen::MatrixXd u(nodes, n);
  for (Eigen::Index a = 0; a < dim; ++a) {
    // component a on the nodes: every dim-th row of the modes
    u = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>>(
        modes.data() + a, nodes, n, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>(modes.outerStride(), dim));
    const Eigen::MatrixXd Mu = sparse_times(scalar_mass, u);
    kinetic += u.cwiseProduct(Mu).colwise().sum().transpose();
    const Eigen::MatrixXd b = fields.transpose() * Mu;
    out.shares.col(a) = b.cwiseProduct(gram_ldlt.solve(b)).colwise().sum().transpose();
  }
  // shares of projections lie in [0, 1]: clamped against round-off
  for (Eigen::Index k = 0; k < n; ++k)
    out.shares.row(k) = kinetic(k) > 0 ? Eigen::RowVector3d((out.shares.row(k) / kinetic(k)).cwiseMax(0.0).cwiseMin(1.0))
                                       : Eigen::RowVector3d::Zero();
  return out;
}

}  // namespace isosid::prep
