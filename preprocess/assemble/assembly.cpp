// Element loops for K, M and loads; see assembly.hpp.
#include "assemble/assembly.hpp"

#include "assemble/boundary_quadrature.hpp"
#include "space/element_evaluator.hpp"
#include "space/element_quadrature.hpp"

#include <omp.h>

namespace isosid::prep {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

/// Calls f(values, weight) at every Gauss point of element e; weight includes det J and measure.
template <class F>
void for_each_gauss_point(const AnalysisSpace& space, const Elasticity& el, const Element& e, int extra,
                          const ElementEvaluator& evaluator, PointValues& v, F&& f) {
  for (const QuadPoint& q : element_quadrature(space, e, extra)) {
    evaluator.evaluate(e, q.t, v);
    f(v, q.weight * std::abs(v.J.determinant()) * el.measure(v.x));
  }
}

SparseMatrix from_thread_triplets(std::vector<Triplets>& parts, int n) {
  Triplets all;
  std::size_t total = 0;
  for (auto& p : parts) total += p.size();
  all.reserve(total);
  for (auto& p : parts) all.insert(all.end(), p.begin(), p.end());
  SparseMatrix A(n, n);
  A.setFromTriplets(all.begin(), all.end());
  return A;
}

}  // namespace

SystemMatrices assemble_system(const AnalysisSpace& space, const DofMap& dofs, const Elasticity& elasticity,
                               int extra_points) {
  const int n = dofs.free_count(), dim = dofs.dim();
  std::vector<Triplets> kt(static_cast<std::size_t>(omp_get_max_threads())), mt(kt.size());
  const int n_el = int(space.elements.size());
#pragma omp parallel
  {
    const ElementEvaluator evaluator(space);
    PointValues v;
    Eigen::MatrixXd B, dR_dx;
    Triplets& kl = kt[std::size_t(omp_get_thread_num())];
    Triplets& ml = mt[std::size_t(omp_get_thread_num())];
#pragma omp for schedule(dynamic, 8)
    for (int e = 0; e < n_el; ++e) {
      const Element& el = space.elements[std::size_t(e)];
      const int nf = int(el.functions.size());
      Eigen::MatrixXd Ke = Eigen::MatrixXd::Zero(nf * dim, nf * dim), Ms = Eigen::MatrixXd::Zero(nf, nf);
      for_each_gauss_point(space, elasticity, el, extra_points, evaluator, v, [&](const PointValues& p, double w) {
        dR_dx = p.dR_dxi * p.J.inverse();
        elasticity.strain_operator(p.R, dR_dx, p.x, B);
        Ke.noalias() += w * B.transpose() * elasticity.D() * B;
        Ms.noalias() += (w * elasticity.density()) * p.R * p.R.transpose();
      });
      std::vector<int> dof(std::size_t(nf * dim));
      for (int f = 0; f < nf; ++f)
        for (int a = 0; a < dim; ++a) dof[std::size_t(f * dim + a)] = dofs.free_index(dofs.node_of(el.functions[std::size_t(f)]), a);
      for (int i = 0; i < nf * dim; ++i) {
        if (dof[std::size_t(i)] < 0) continue;
        for (int j = 0; j < nf * dim; ++j) {
          if (dof[std::size_t(j)] < 0) continue;
          kl.emplace_back(dof[std::size_t(i)], dof[std::size_t(j)], Ke(i, j));
          if (i % dim == j % dim) ml.emplace_back(dof[std::size_t(i)], dof[std::size_t(j)], Ms(i / dim, j / dim));
        }
      }
    }
  }
  SystemMatrices s{from_thread_triplets(kt, n), from_thread_triplets(mt, n)};
  return s;
}

SparseMatrix assemble_scalar_mass(const AnalysisSpace& space, const DofMap& dofs, const Elasticity& elasticity,
                                  int extra_points) {
  std::vector<Triplets> mt(static_cast<std::size_t>(omp_get_max_threads()));
  const int n_el = int(space.elements.size());
#pragma omp parallel
  {
    const ElementEvaluator evaluator(space);
    PointValues v;
    Triplets& ml = mt[std::size_t(omp_get_thread_num())];
#pragma omp for schedule(dynamic, 8)
    for (int e = 0; e < n_el; ++e) {
      const Element& el = space.elements[std::size_t(e)];
      const int nf = int(el.functions.size());
      Eigen::MatrixXd Ms = Eigen::MatrixXd::Zero(nf, nf);
      for_each_gauss_point(space, elasticity, el, extra_points, evaluator, v, [&](const PointValues& p, double w) {
        Ms.noalias() += (w * elasticity.density()) * p.R * p.R.transpose();
      });
      for (int i = 0; i < nf; ++i)
        for (int j = 0; j < nf; ++j)
          ml.emplace_back(dofs.node_of(el.functions[std::size_t(i)]), dofs.node_of(el.functions[std::size_t(j)]), Ms(i, j));
    }
  }
  return from_thread_triplets(mt, dofs.node_count());
}

Eigen::VectorXd assemble_traction(const AnalysisSpace& space, const DofMap& dofs, const Elasticity& elasticity,
                                  PatchSide side,
                                  const std::function<Eigen::VectorXd(const Eigen::VectorXd&, const Eigen::VectorXd&)>& t) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.free_count());
  const int dim = dofs.dim();
  for (const BoundaryPoint& bp : boundary_points(space, elasticity, side)) {
    const Eigen::VectorXd traction = t(bp.x, bp.normal);
    const Element& el = space.elements[std::size_t(bp.element)];
    for (std::size_t k = 0; k < el.functions.size(); ++k)
      for (int a = 0; a < dim; ++a) {
        const int i = dofs.free_index(dofs.node_of(el.functions[k]), a);
        if (i >= 0) f(i) += bp.weight * bp.R(Eigen::Index(k)) * traction(a);
      }
  }
  return f;
}

}  // namespace isosid::prep
