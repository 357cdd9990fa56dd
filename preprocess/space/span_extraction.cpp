// 1D and tensor Bezier extraction; see span_extraction.hpp.
#include "space/span_extraction.hpp"

#include "isosid/common/dense_decompositions.hpp"
#include "space/bernstein.hpp"

#include <Eigen/LU>
#include <cmath>

namespace isosid::prep {

std::vector<SpanExtraction> span_extractions(const KnotVector& U, int p) {
  std::vector<SpanExtraction> out;
  const std::vector<double> u = unique_knots(U);
  Eigen::MatrixXd Bmat(p + 1, p + 1), Nmat(p + 1, p + 1);
  Eigen::VectorXd values(p + 1), ders(p + 1);
  for (std::size_t s = 0; s + 1 < u.size(); ++s) {
    const double lo = u[s], hi = u[s + 1];
    const int span = find_span(U, p, 0.5 * (lo + hi));
    for (int k = 0; k <= p; ++k) {
      const double t = 0.5 * (1 - std::cos(M_PI * (k + 0.5) / (p + 1)));
      bernstein(p, t, values.data(), ders.data());
      Bmat.row(k) = values.transpose();
      // the span's p + 1 functions only: a whole basis row per point made this quadratic in the
      // knots, which the hierarchical spaces' fine levels call it with
      double N[format::kMaxDegree + 1];
      basis_functions(U, p, span, lo + t * (hi - lo), N);
      for (int j = 0; j <= p; ++j) Nmat(k, j) = N[j];
    }
    out.push_back({lo, hi, span - p, Eigen::PartialPivLU<Eigen::MatrixXd>(Bmat).solve(Nmat).transpose()});
  }
  return out;
}

Eigen::MatrixXd tensor_extraction(const std::vector<const Eigen::MatrixXd*>& C1d) {
  Eigen::Index rows = 1, cols = 1;
  for (const Eigen::MatrixXd* c : C1d) {
    rows *= c->rows();
    cols *= c->cols();
  }
  Eigen::MatrixXd C(rows, cols);
  for (Eigen::Index f = 0; f < rows; ++f)
    for (Eigen::Index b = 0; b < cols; ++b) {
      double v = 1;
      Eigen::Index fr = f, br = b;
      for (const Eigen::MatrixXd* c : C1d) {
        v *= (*c)(fr % c->rows(), br % c->cols());
        fr /= c->rows();
        br /= c->cols();
      }
      C(f, b) = v;
    }
  return C;
}

}  // namespace isosid::prep
