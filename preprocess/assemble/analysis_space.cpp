// Element extraction for tensor B-spline spaces; see analysis_space.hpp.
#include "assemble/analysis_space.hpp"

#include "assemble/bernstein.hpp"

#include <Eigen/LU>
#include <cmath>

namespace isosid::prep {

int AnalysisSpace::bernstein_count() const {
  int n = 1;
  for (int p : degrees) n *= p + 1;
  return n;
}

bool AnalysisSpace::on_side(const Element& e, PatchSide side) const {
  const auto d = side.direction;
  return side.end == 0 ? e.lo(d) == param_lo(d) : e.hi(d) == param_hi(d);
}

namespace {

struct Span1D {
  double lo, hi;
  int first_function;     ///< span - p
  Eigen::MatrixXd C;      ///< (p+1) x (p+1): N_{first+j}(t) = sum_b C(j, b) B_b(t)
};

/// 1D extraction by collocation: N(t_k) = C B(t_k) at p+1 Chebyshev points of the span.
std::vector<Span1D> spans_1d(const KnotVector& U, int p) {
  std::vector<Span1D> out;
  const std::vector<double> u = unique_knots(U);
  Eigen::MatrixXd Bmat(p + 1, p + 1), Nmat(p + 1, p + 1);
  Eigen::VectorXd values, ders;
  for (std::size_t s = 0; s + 1 < u.size(); ++s) {
    const double lo = u[s], hi = u[s + 1];
    const int span = find_span(U, p, 0.5 * (lo + hi));
    for (int k = 0; k <= p; ++k) {
      const double t = 0.5 * (1 - std::cos(M_PI * (k + 0.5) / (p + 1)));
      bernstein(p, t, values, ders);
      Bmat.row(k) = values.transpose();
      double N[16];
      basis_functions(U, p, span, lo + t * (hi - lo), N);
      for (int j = 0; j <= p; ++j) Nmat(k, j) = N[j];
    }
    Span1D sp{lo, hi, span - p, Eigen::PartialPivLU<Eigen::MatrixXd>(Bmat).solve(Nmat).transpose()};
    out.push_back(std::move(sp));
  }
  return out;
}

}  // namespace

AnalysisSpace tensor_space(const NurbsPatch& patch) {
  AnalysisSpace space;
  space.degrees = patch.degrees;
  space.control_points = patch.points;
  space.weights = patch.weights;
  const int pd = patch.param_dim();
  for (int d = 0; d < pd; ++d) {
    space.param_lo(d) = patch.lower(d);
    space.param_hi(d) = patch.upper(d);
  }
  std::vector<std::vector<Span1D>> spans;
  for (int d = 0; d < pd; ++d) spans.push_back(spans_1d(patch.knots[std::size_t(d)], patch.degrees[std::size_t(d)]));
  const std::vector<int> counts = patch.counts();

  std::vector<int> e(static_cast<std::size_t>(pd), 0);
  while (true) {
    Element el;
    Eigen::MatrixXd C = Eigen::MatrixXd::Ones(1, 1);
    std::vector<int> first(static_cast<std::size_t>(pd));
    for (int d = 0; d < pd; ++d) {
      const Span1D& s = spans[std::size_t(d)][std::size_t(e[std::size_t(d)])];
      el.lo(d) = s.lo;
      el.hi(d) = s.hi;
      first[std::size_t(d)] = s.first_function;
      // kron with the first direction fastest: C_new(j + (p+1) J, b + (p+1) B) = C_d(j, b) * C(J, B)
      Eigen::MatrixXd K(C.rows() * s.C.rows(), C.cols() * s.C.cols());
      for (Eigen::Index J = 0; J < C.rows(); ++J)
        for (Eigen::Index B = 0; B < C.cols(); ++B) K.block(J * s.C.rows(), B * s.C.cols(), s.C.rows(), s.C.cols()) = C(J, B) * s.C;
      C = K;
    }
    // C was built with the *last* direction fastest; reorder rows/cols to first-fastest
    const int nb = int(C.rows());
    std::vector<int> perm(static_cast<std::size_t>(nb));
    for (int i = 0; i < nb; ++i) {
      int rest = i, index = 0, stride = 1;
      std::vector<int> digits(static_cast<std::size_t>(pd));
      for (int d = pd - 1; d >= 0; --d) {  // i: last direction fastest
        digits[std::size_t(d)] = rest % (patch.degrees[std::size_t(d)] + 1);
        rest /= patch.degrees[std::size_t(d)] + 1;
      }
      for (int d = 0; d < pd; ++d) {
        index += digits[std::size_t(d)] * stride;
        stride *= patch.degrees[std::size_t(d)] + 1;
      }
      perm[std::size_t(i)] = index;
    }
    el.C.resize(nb, nb);
    for (int i = 0; i < nb; ++i)
      for (int j = 0; j < nb; ++j) el.C(perm[std::size_t(i)], perm[std::size_t(j)]) = C(i, j);
    el.functions.resize(std::size_t(nb));
    for (int f = 0; f < nb; ++f) {
      int rest = f;
      std::vector<int> ijk(static_cast<std::size_t>(pd));
      for (int d = 0; d < pd; ++d) {
        ijk[std::size_t(d)] = first[std::size_t(d)] + rest % (patch.degrees[std::size_t(d)] + 1);
        rest /= patch.degrees[std::size_t(d)] + 1;
      }
      el.functions[std::size_t(f)] = flat_index(counts, ijk);
    }
    space.elements.push_back(std::move(el));
    int d = 0;
    while (d < pd && ++e[std::size_t(d)] >= int(spans[std::size_t(d)].size())) e[std::size_t(d++)] = 0;
    if (d == pd) break;
  }
  return space;
}

}  // namespace isosid::prep
