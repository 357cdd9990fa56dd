// Nearest-point projection and line sampling on a body; see placement.hpp.
#include "model/placement.hpp"

#include "geometry/multi_index.hpp"
#include "isosid/common/dense_decompositions.hpp"
#include "model/body_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace isosid::prep {
namespace {

/// Sample parameters per direction: four per degree and knot span (at most 32 intervals),
/// close enough that Gauss-Newton starts inside the basin of the nearest point.
std::vector<Eigen::VectorXd> sample_axes(const NurbsPatch& patch) {
  std::vector<Eigen::VectorXd> axes;
  for (int d = 0; d < patch.param_dim(); ++d) {
    const auto spans = Eigen::Index(unique_knots(patch.knots[std::size_t(d)]).size()) - 1;
    const Eigen::Index intervals = std::min<Eigen::Index>(32, 4 * patch.degrees[std::size_t(d)] * spans);
    axes.push_back(Eigen::VectorXd::LinSpaced(intervals + 1, patch.lower(d), patch.upper(d)));
  }
  return axes;
}

Eigen::VectorXd best_sample(const NurbsPatch& patch, const Eigen::VectorXd& target) {
  const std::vector<Eigen::VectorXd> axes = sample_axes(patch);
  std::array<Eigen::Index, 3> extents{1, 1, 1};
  for (int d = 0; d < patch.param_dim(); ++d) extents[std::size_t(d)] = axes[std::size_t(d)].size();
  Eigen::VectorXd xi(patch.param_dim()), best, x;
  double best_d2 = std::numeric_limits<double>::infinity();
  MultiIndex sample(patch.param_dim(), extents);
  do {
    for (int d = 0; d < patch.param_dim(); ++d) xi(d) = axes[std::size_t(d)](sample[d]);
    patch.evaluate(xi, x);
    if (const double d2 = (x - target).squaredNorm(); d2 < best_d2) {
      best_d2 = d2;
      best = xi;
    }
  } while (sample.next());
  return best;
}

}  // namespace

BodyPoint nearest_point(const NurbsPatch& patch, const Eigen::VectorXd& target) {
  const int pd = patch.param_dim();
  Eigen::VectorXd lo(pd), hi(pd);
  for (int d = 0; d < pd; ++d) {
    lo(d) = patch.lower(d);
    hi(d) = patch.upper(d);
  }
  BodyPoint p{best_sample(patch, target), {}, 0};
  Eigen::MatrixXd J;
  patch.evaluate(p.parameter, p.x, &J);
  double d2 = (target - p.x).squaredNorm();
  for (int iteration = 0; iteration < 50 && d2 > 0; ++iteration) {
    const Eigen::VectorXd r = target - p.x;
    const Eigen::VectorXd descent = J.transpose() * r;  // minus the gradient of |r|^2 / 2
    std::vector<Eigen::Index> free;
    for (int d = 0; d < pd; ++d)
      if (!(p.parameter(d) <= lo(d) && descent(d) < 0) && !(p.parameter(d) >= hi(d) && descent(d) > 0)) free.push_back(d);
    if (free.empty()) break;  // a corner of the box, pushed outward along every direction
    // least squares: a singular Jacobian (a collapsed side) takes the shortest step
    const Eigen::VectorXd free_step = common::minimum_norm_solve(J(Eigen::all, free), r);
    Eigen::VectorXd step = Eigen::VectorXd::Zero(pd);
    step(free) = free_step;
    bool improved = false;
    for (double t = 1; t > 1e-6 && !improved; t *= 0.5) {  // halve until the distance drops
      BodyPoint trial{(p.parameter + t * step).cwiseMax(lo).cwiseMin(hi), {}, 0};
      Eigen::MatrixXd J_trial;
      patch.evaluate(trial.parameter, trial.x, &J_trial);
      if (const double d2_trial = (target - trial.x).squaredNorm(); d2_trial < d2) {
        improved = true;
        d2 = d2_trial;
        p = std::move(trial);
        J = std::move(J_trial);
      }
    }
    if (!improved) break;  // converged to round-off
  }
  p.distance = std::sqrt(d2);
  return p;
}

BodyPoint place(const NurbsPatch& patch, const GivenPoint& given) {
  if (given.physical) return nearest_point(patch, given.value);
  return {given.value, patch.point(given.value), 0};
}

double placement_tolerance(const NurbsPatch& patch) { return 1e-6 * patch_size(patch); }

std::vector<BodyPoint> line_points(const NurbsPatch& patch, const GivenPoint& from, const GivenPoint& to, int points) {
  std::vector<BodyPoint> out;
  for (int i = 0; i < points; ++i) {
    const double u = points == 1 ? 0.0 : double(i) / (points - 1);
    out.push_back(place(patch, {from.value + u * (to.value - from.value), from.physical}));
  }
  return out;
}

}  // namespace isosid::prep
