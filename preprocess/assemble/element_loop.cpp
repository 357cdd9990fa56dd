// The element loop; see element_loop.hpp.
#include "assemble/element_loop.hpp"

#include "isosid/common/dense_decompositions.hpp"
#include "isosid/common/progress_line.hpp"
#include "space/reference_rule.hpp"

#include <atomic>

#include <omp.h>

namespace isosid::prep {
namespace {

/// Physical gradients dR/dx = dR/dxi J^-1 and quadrature weights of the evaluated points of an
/// element of parametric size `size`.
void map_to_physical(double size, const ReferenceRule& rule, const Elasticity& elasticity, ElementPoints& p) {
  const ElementValues& v = p.values;
  const int pd = int(v.x.rows()), nf = int(v.R.rows()), n = rule.size();
  p.weight.resize(n);
  for (int k = 0; k < pd; ++k) p.dR_dx[k].resize(nf, n);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3> J(pd, pd);
  for (int q = 0; q < n; ++q) {
    for (int d = 0; d < pd; ++d) J.col(d) = v.dx_dxi[d].col(q);
    const auto J_inv = J.inverse().eval();
    p.weight(q) = rule.weights(q) * size * std::abs(J.determinant()) * elasticity.measure(v.x.col(q));
    for (int k = 0; k < pd; ++k) {
      auto column = p.dR_dx[k].col(q);
      column = J_inv(0, k) * v.dR_dxi[0].col(q);
      for (int d = 1; d < pd; ++d) column += J_inv(d, k) * v.dR_dxi[d].col(q);
    }
  }
}

/// Spreads a scalar element matrix over the displacement components: (f*dim + a, g*dim + a).
void spread_over_components(const Eigen::MatrixXd& scalar, int dim, Eigen::MatrixXd& local) {
  const Eigen::Index nf = scalar.rows();
  local.setZero(nf * dim, nf * dim);
  for (Eigen::Index g = 0; g < nf; ++g)
    for (Eigen::Index f = 0; f < nf; ++f)
      for (int a = 0; a < dim; ++a) local(f * dim + a, g * dim + a) = scalar(f, g);
}

}  // namespace

std::vector<SparseMatrix> assemble_matrices(const AnalysisSpace& space, const BodyElasticity& elasticity,
                                            const std::vector<MatrixTerm>& terms, int extra_points) {
  const ReferenceRule rule = reference_rule(space, extra_points);
  const int n_elements = int(space.elements.size()), dim = elasticity.dim();
  // per thread, per term: the summed values of the term's pattern; the first thread sums
  // straight into the matrices' values, the others into their own, added to them after the loop
  // (the sum of a million DOFs' stiffness takes gigabytes: one copy per thread, no more)
  std::vector<SparseMatrix> out;
  for (const MatrixTerm& t : terms) out.push_back(t.pattern.zero_matrix());
  const int threads = omp_get_max_threads();
  std::vector<std::vector<PatternAccumulator>> sums(static_cast<std::size_t>(threads));
  std::atomic<int> done{0};  // elements assembled, for progress
#pragma omp parallel
  {
    const int thread = omp_get_thread_num();
    std::vector<PatternAccumulator>& mine = sums[std::size_t(thread)];
    mine.reserve(terms.size());
    for (std::size_t k = 0; k < terms.size(); ++k) {
      if (thread == 0)
        mine.emplace_back(terms[k].pattern, out[k].valuePtr());
      else
        mine.emplace_back(terms[k].pattern);
    }
    const ElementEvaluator evaluator(space);
    ElementPoints points;
    Eigen::MatrixXd local, spread;
    // static chunks: each thread sums the same elements in the same order every run, so the
    // matrices (and the SIDs, their cache and the runs on them) are bitwise reproducible for
    // a given thread count (dynamic chunks made them differ by 1e-11 from run to run)
#pragma omp for schedule(static, 8)
    for (int e = 0; e < n_elements; ++e) {
      if (const int d = done.fetch_add(1, std::memory_order_relaxed); d % 256 == 0) common::set_work_fraction(double(d) / n_elements);
      const Element& el = space.elements[e];
      evaluator.evaluate(el, rule.basis, points.values);
      points.patch = el.patch;
      map_to_physical(space.parametric_size(el), rule, elasticity.of(el), points);
      for (std::size_t k = 0; k < terms.size(); ++k) {
        const MatrixTerm& t = terms[k];
        t.integrand.element_matrix(points, local);
        if (t.integrand.components() == 1 && t.pattern.unknowns() == Unknowns::FreeDofs && dim > 1) {
          spread_over_components(local, dim, spread);
          mine[k].add(el, spread);
        } else {
          mine[k].add(el, local);
        }
      }
    }
  }
  // in thread order: the sums, and so the SIDs, are bitwise reproducible for a thread count
  for (std::size_t t = 1; t < sums.size(); ++t)
    for (std::size_t k = 0; k < sums[t].size(); ++k) sums[t][k].add_into_and_release(out[k].valuePtr());
  return out;
}

}  // namespace isosid::prep
