// DeformedPatch against exact circles. The patch: a quarter circle of radius R made of two
// rational quadratic arcs of 45 deg that meet at a double knot (where the second derivative
// jumps), as a curve and extruded along z into a cylinder patch; its one mode scales the
// control net in x and y, so the net deformed by q is the circle of radius R (1 + q). A
// projection's last Newton step is taken by Taylor's formula within a knot span: these tests
// hold that expansion to its order, and a warm-started projection to the exact closest point.
#include "contact/deformed_patch.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace isosid;

namespace {

constexpr double kR = 0.01, kLength = 0.02, kScale = 0.01;  // m, m, the mode's coordinate

/// The quarter circle (dim 2) or the cylinder patch over z in [0, kLength] (dim 3).
format::MasterPatch quarter_circle(int dim) {
  const double t = std::tan(M_PI / 8), w = std::cos(M_PI / 8), c = std::cos(M_PI / 4);
  const double x[5] = {kR, kR, kR * c, kR * t, 0}, y[5] = {0, kR * t, kR * c, kR, kR}, weight[5] = {1, w, 1, w, 1};
  format::MasterPatch patch;
  patch.name = "arc";
  patch.degrees = {2};
  patch.knots = {(Eigen::VectorXd(8) << 0, 0, 0, 0.5, 0.5, 1, 1, 1).finished()};
  const int rows = dim == 3 ? 2 : 1;
  if (dim == 3) patch.degrees.push_back(1), patch.knots.push_back((Eigen::VectorXd(4) << 0, 0, 1, 1).finished());
  patch.weights.resize(5 * rows);
  patch.control_points = Eigen::MatrixXd::Zero(5 * rows, dim);
  patch.Phi = Eigen::MatrixXd::Zero(5 * rows * dim, 1);
  for (int row = 0; row < rows; ++row)
    for (int i = 0; i < 5; ++i) {
      const int k = i + 5 * row;  // the first direction fastest
      patch.weights(k) = weight[i];
      patch.control_points(k, 0) = x[i], patch.control_points(k, 1) = y[i];
      if (dim == 3) patch.control_points(k, 2) = row * kLength;
      patch.Phi(k * dim, 0) = x[i], patch.Phi(k * dim + 1, 0) = y[i];  // the scaling mode
    }
  return patch;
}

/// The largest difference of two points' rational basis values, by control point (at a knot
/// two spans' sets name the point, and those beyond either set are zero there).
double largest_difference(const run::DeformedPatch::Point& a, const run::DeformedPatch::Point& b) {
  std::vector<double> difference(64, 0.0);
  for (std::size_t j = 0; j < a.R.size(); ++j) difference[std::size_t(a.control_points[j])] += a.R[j];
  for (std::size_t j = 0; j < b.R.size(); ++j) difference[std::size_t(b.control_points[j])] -= b.R[j];
  double largest = 0;
  for (double d : difference) largest = std::max(largest, std::abs(d));
  return largest;
}

struct TaylorErrors {
  double position, tangent, basis;
};

/// Point::advance from u by h (1, 0.7) against an evaluation there: the position's error
/// relative to R, the tangents' to |dC| and the basis values' (absolute).
TaylorErrors taylor_errors(const run::DeformedPatch& patch, const Eigen::Vector2d& u, double h) {
  Eigen::Vector2d s(h, patch.parameter_dim() > 1 ? 0.7 * h : 0.0);
  run::DeformedPatch::Point advanced, evaluated;
  patch.evaluate(u, advanced);
  advanced.advance(s);
  patch.evaluate(u + s, evaluated);
  REQUIRE(evaluated.control_points == advanced.control_points);  // the same span
  TaylorErrors e{(advanced.C - evaluated.C).norm() / kR, 0, largest_difference(advanced, evaluated)};
  for (int d = 0; d < patch.parameter_dim(); ++d) e.tangent = std::max(e.tangent, (advanced.dC[d] - evaluated.dC[d]).norm() / evaluated.dC[d].norm());
  return e;
}

}  // namespace

TEST_CASE("DeformedPatch: a point's Taylor step equals its evaluation to the step's order", "[runtime][unit]") {
  for (int dim : {2, 3}) {
    const format::MasterPatch source = quarter_circle(dim);
    run::DeformedPatch patch(source, dim);
    patch.deform(Eigen::VectorXd::Constant(1, kScale));
    for (const Eigen::Vector2d& u : {Eigen::Vector2d(0.2, 0.4), Eigen::Vector2d(0.7, 0.1)}) {
      INFO("dim " << dim << ", u (" << u.transpose() << ")");
      // a decade of step: the position's error falls by 1000 (third order), the tangents' and
      // the basis values' by 100 (second); a factor of two is left for the next term
      const TaylorErrors coarse = taylor_errors(patch, u, 1e-2), fine = taylor_errors(patch, u, 1e-3);
      INFO("errors at 1e-2: " << coarse.position << " " << coarse.tangent << " " << coarse.basis << "; at 1e-3: " << fine.position << " "
                              << fine.tangent << " " << fine.basis);
      CHECK(fine.position < 2e-3 * coarse.position);
      CHECK(fine.tangent < 2e-2 * coarse.tangent);
      CHECK(fine.basis < 2e-2 * coarse.basis);
      // at the largest step a projection takes this way (3e-5 of the span, here 0.5 of the
      // range): second-order errors of order 1e-9 (the arc's curvature over its span is of
      // order one; the quadratic basis functions' second derivatives are about 8 per span
      // squared: 1.8e-9 measured)
      const TaylorErrors largest = taylor_errors(patch, u, 1.5e-5);
      CHECK(largest.position < 1e-14);
      CHECK(largest.tangent < 1e-9);
      CHECK(largest.basis < 5e-9);
    }
  }
}

TEST_CASE("DeformedPatch: a warm-started projection finds the closest point of the deformed circle", "[runtime][unit]") {
  const double radius = kR * (1 + kScale);
  for (int dim : {2, 3}) {
    const format::MasterPatch source = quarter_circle(dim);
    run::DeformedPatch patch(source, dim);
    patch.deform(Eigen::VectorXd::Constant(1, kScale));
    // angles on either arc, at the double knot (45 deg) and a hair beside it, where the steps
    // from the hints below cross the knot; points outside and inside the circle
    for (double degrees : {10.0, 45.0 - 1e-5, 45.0, 45.0 + 1e-5, 80.0})
      for (double lift : {1e-4, -1e-4}) {
        const double angle = degrees * M_PI / 180;
        const Eigen::Vector3d radial(std::cos(angle), std::sin(angle), 0);
        const Eigen::Vector3d along_z = dim == 3 ? Eigen::Vector3d(0, 0, 0.3 * kLength) : Eigen::Vector3d::Zero();
        const Eigen::Vector3d x = radius * (1 + lift) * radial + along_z;
        const Eigen::Vector3d closest = radius * radial + along_z;
        run::DeformedPatch::Point point, evaluated;
        Eigen::Vector2d cold = Eigen::Vector2d::Constant(NAN);
        REQUIRE(patch.closest_point(x, cold, point));
        // hints from well inside Taylor's range of steps (1.5e-5 here) to far outside it, both sides
        for (double offset : {1e-7, -1e-7, 1e-6, -1e-6, 5e-6, -5e-6, 1e-4, -1e-4, 1e-2, -1e-2}) {
          Eigen::Vector2d u = cold;
          u(0) += offset;
          if (dim == 3) u(1) += 0.5 * offset;
          INFO("dim " << dim << ", " << degrees << " deg, lift " << lift << ", hint offset " << offset);
          REQUIRE(patch.closest_point(x, u, point));
          // the closest point to 1e-10 of R; the tangents normal to the radius to 1e-10 (the
          // parameter's error after a Taylor step is O(step^2), 1e-10 of the span here)
          CHECK((point.C - closest).norm() < 1e-10 * kR);
          for (int d = 0; d < dim - 1; ++d) CHECK(std::abs(point.dC[d].normalized().dot(radial)) < 1e-10);
          // and the point agrees with an evaluation at the parameter returned
          patch.evaluate(u, evaluated);
          CHECK((point.C - evaluated.C).norm() < 1e-14 * kR);
          for (int d = 0; d < dim - 1; ++d) CHECK((point.dC[d] - evaluated.dC[d]).norm() < 1e-9 * evaluated.dC[d].norm());
          CHECK(largest_difference(point, evaluated) < 1e-9);
        }
      }
  }
}
