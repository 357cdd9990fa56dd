// SpanPolynomials against The NURBS Book's A2.3 (format::basis_derivatives): the values and
// first and second derivatives of the basis functions on every span of open knot vectors of
// degrees 1 to 4, with uneven spans and a double and a triple interior knot.
#include "contact/span_polynomials.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace isosid;

TEST_CASE("SpanPolynomials: the basis and its derivatives equal A2.3's on every span", "[runtime][unit]") {
  for (int p = 1; p <= 4; ++p) {
    // interior knots 0.1, 0.35 twice, 0.5, 0.8 three times (at most p of them: C^-1 is not a patch)
    std::vector<double> knots(std::size_t(p + 1), 0.0);
    for (const auto& [value, multiplicity] : {std::pair{0.1, 1}, {0.35, 2}, {0.5, 1}, {0.8, 3}})
      for (int k = 0; k < std::min(multiplicity, p); ++k) knots.push_back(value);
    knots.insert(knots.end(), std::size_t(p + 1), 1.0);
    const format::KnotVector U = Eigen::Map<const Eigen::VectorXd>(knots.data(), Eigen::Index(knots.size()));
    const run::SpanPolynomials polynomials(U, p);
    format::BasisDerivatives N;
    double largest = 0;
    for (int i = 0; i <= 1000; ++i) {
      const double u = i / 1000.0;
      const int span = format::find_span(U, p, u);
      polynomials.evaluate(span, u, N);
      const format::BasisDerivatives expected = format::basis_derivatives(U, p, span, u, 2);
      for (int k = 0; k < 3; ++k) {
        // each row against its own magnitude (the derivatives grow as 1 / span length^k)
        const double scale = std::max(1.0, expected.row(k).cwiseAbs().maxCoeff());
        for (int j = 0; j <= p; ++j) largest = std::max(largest, std::abs(N(k, j) - (k <= p ? expected(k, j) : 0.0)) / scale);
      }
    }
    INFO("degree " << p << ": largest difference " << largest);
    // round-off of Horner's rule on coefficients of order one over [0, 1]
    CHECK(largest < 1e-12);
  }
}
