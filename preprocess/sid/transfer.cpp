// Coarse <-> fine transfer; see transfer.hpp.
#include "sid/transfer.hpp"

#include "isosid/common/dense_decompositions.hpp"
#include "space/gauss_quadrature.hpp"
#include "assemble/point_operator.hpp"
#include "sid/sid_builder.hpp"
#include "reduce/sparse_products.hpp"

#include <Eigen/LU>

namespace isosid::prep {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

/// Restriction of nodal fields (columns) to free DOFs.
Eigen::MatrixXd free_rows(const DofMap& dofs, const Eigen::MatrixXd& nodal) {
  Eigen::MatrixXd out(dofs.free_count(), nodal.cols());
  for (int i = 0; i < dofs.total_dofs(); ++i)
    if (const int f = dofs.free_indices()[std::size_t(i)]; f >= 0) out.row(f) = nodal.row(i);
  return out;
}

}  // namespace

NodalTransfer nodal_transfer(const BodyModel& coarse, const BodyModel& fine) {
  const int dim = fine.dofs.dim();
  NodalTransfer out;
  // coarse -> fine: the prolongation of functions, read at one function of every fine node
  // (functions merged into a node carry equal values)
  const Eigen::SparseMatrix<double, Eigen::RowMajor> P = fine.hierarchy->prolongation;
  std::vector<bool> done(std::size_t(fine.dofs.node_count()), false);
  Triplets t;
  for (int f = 0; f < P.rows(); ++f) {
    const int node = fine.dofs.node_of(f);
    if (done[std::size_t(node)]) continue;
    done[std::size_t(node)] = true;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(P, f); it; ++it)
      for (int a = 0; a < dim; ++a) t.emplace_back(node * dim + a, coarse.dofs.node_of(int(it.col())) * dim + a, it.value());
  }
  out.coarse_to_fine.resize(fine.dofs.total_dofs(), coarse.dofs.total_dofs());
  out.coarse_to_fine.setFromTriplets(t.begin(), t.end());

  // fine -> coarse: per coarse element, coefficients from the fine field at its Gauss points
  t.clear();
  std::vector<double> shares(std::size_t(coarse.dofs.node_count()), 0.0);
  const int pd = coarse.space.param_dim();
  std::vector<QuadratureRule> rules;
  for (int d = 0; d < pd; ++d) rules.push_back(gauss_legendre(coarse.space.degrees[std::size_t(d)] + 1));
  std::vector<int> slot(std::size_t(fine.dofs.node_count()), -1);  // a fine node's column in the element's W
  std::vector<int> local_nodes;
  for (const Element& el : coarse.space.elements) {
    const int nf = int(el.functions.size());
    Eigen::MatrixXd Rc(nf, nf);
    std::vector<PointOperator> at_fine;
    for (int g = 0; g < nf; ++g) {
      double tt[3];
      Eigen::VectorXd xi(pd);
      int rest = g;
      for (int d = 0; d < pd; ++d) {
        const int n = int(rules[std::size_t(d)].points.size());
        tt[d] = rules[std::size_t(d)].points(rest % n);
        rest /= n;
        xi(d) = el.lo(d) + tt[d] * (el.hi(d) - el.lo(d));
      }
      Rc.row(g) = point_operator(coarse.space, coarse.dofs, coarse.elasticity, el, tt).R.transpose();
      at_fine.push_back(*point_operator_at(fine.space, fine.dofs, fine.elasticity, el.patch, xi));  // inside: same patch
    }
    const Eigen::MatrixXd Rinv = Eigen::PartialPivLU<Eigen::MatrixXd>(Rc).inverse();  // functions x Gauss points
    // the element's coefficients from the fine nodes at its Gauss points, summed per fine node
    // before they become triplets: a triplet per Gauss point and node pair, summed only by
    // setFromTriplets, made scene E's refined ball spend 21 of its 27 s in page faults
    local_nodes.clear();
    for (const PointOperator& op : at_fine)
      for (const int node : op.nodes)
        if (slot[std::size_t(node)] < 0) slot[std::size_t(node)] = int(local_nodes.size()), local_nodes.push_back(node);
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(nf, Eigen::Index(local_nodes.size()));  // functions x fine nodes
    for (int g = 0; g < nf; ++g) {
      const PointOperator& op = at_fine[std::size_t(g)];
      for (std::size_t k = 0; k < op.nodes.size(); ++k) W.col(slot[std::size_t(op.nodes[k])]) += Rinv.col(g) * op.R(Eigen::Index(k));
    }
    for (int f = 0; f < nf; ++f) {
      const int node = coarse.dofs.node_of(el.functions[std::size_t(f)]);
      shares[std::size_t(node)] += 1.0;
      for (std::size_t j = 0; j < local_nodes.size(); ++j)
        for (int a = 0; a < dim; ++a) t.emplace_back(node * dim + a, local_nodes[j] * dim + a, W(f, Eigen::Index(j)));
    }
    for (const int node : local_nodes) slot[std::size_t(node)] = -1;
  }
  for (auto& x : t) x = {x.row(), x.col(), x.value() / shares[std::size_t(x.row() / dim)]};  // average over elements
  out.fine_to_coarse.resize(coarse.dofs.total_dofs(), fine.dofs.total_dofs());
  out.fine_to_coarse.setFromTriplets(t.begin(), t.end());
  return out;
}

format::TransferOperator reduced_transfer(const ReducedModel& coarse, const ReducedModel& fine, const NodalTransfer& nodal) {
  // q_to = Phi_to^T M_to u_to (Phi_to is M-orthonormal), u_to = free part of N u_from
  auto project = [](const ReducedModel& from, const ReducedModel& to, const Eigen::SparseMatrix<double>& N) {
    const Eigen::MatrixXd moved = free_rows(to.body.dofs, N * nodal_modes(from.body.dofs, from.basis.Phi));
    return Eigen::MatrixXd(to.basis.Phi.transpose() * sparse_times(to.system.M, moved));
  };
  format::TransferOperator t;
  t.coarse_to_fine = project(coarse, fine, nodal.coarse_to_fine);
  t.fine_to_coarse = project(fine, coarse, nodal.fine_to_coarse);
  return t;
}

Eigen::MatrixXd prolongated_modes(const ReducedModel& coarse, const BodyModel& fine, const NodalTransfer& nodal) {
  return free_rows(fine.dofs, nodal.coarse_to_fine * nodal_modes(coarse.body.dofs, coarse.basis.Phi));
}

}  // namespace isosid::prep
