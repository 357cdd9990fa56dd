// Graded knot placement; see graded_knots.hpp.
#include "refine/graded_knots.hpp"

#include <algorithm>
#include <cmath>

namespace isosid::prep {
namespace {

/// max over sample lines of |dx/dxi_dir| at parameter u of direction dir.
double max_speed(const NurbsPatch& patch, int dir, double u) {
  const int pd = patch.param_dim();
  const int samples = 9;
  std::vector<int> idx(static_cast<std::size_t>(pd), 0);
  double best = 0;
  Eigen::VectorXd xi(pd), x;
  Eigen::MatrixXd J;
  while (true) {
    for (int d = 0; d < pd; ++d)
      xi(d) = d == dir ? u : patch.lower(d) + (patch.upper(d) - patch.lower(d)) * idx[std::size_t(d)] / (samples - 1);
    patch.evaluate(xi, x, &J);
    best = std::max(best, J.col(dir).norm());
    int d = 0;
    while (d < pd && (d == dir || ++idx[std::size_t(d)] >= samples)) {
      if (d != dir) idx[std::size_t(d)] = 0;
      ++d;
    }
    if (d == pd) break;
  }
  return best;
}

/// Steps from `from` toward `limit` (either side), returning knots strictly between them.
std::vector<double> march(const NurbsPatch& patch, const GradingRequest& r, double from, double limit,
                          double max_step) {
  std::vector<double> out;
  const double sign = limit > from ? 1.0 : -1.0;
  double u = from, h = r.smallest;
  while (true) {
    // parameter step for physical length h, speed taken at the step's midpoint (one correction)
    double du = h / std::max(max_speed(patch, r.direction, u), 1e-300);
    const double mid = std::clamp(u + sign * 0.5 * du, std::min(from, limit), std::max(from, limit));
    du = h / std::max(max_speed(patch, r.direction, mid), 1e-300);
    du = std::min(du, max_step);
    const double next = u + sign * du;
    if (sign * (limit - next) < 0.5 * du) break;  // the rest fits into the last element
    out.push_back(next);
    u = next;
    h *= r.growth;
    if (du >= max_step) break;  // spans are as large as the existing ones: stop grading
  }
  return out;
}

/// The largest knot span of a direction: grading stops once its elements are that large.
double largest_span(const std::vector<double>& u) {
  double out = 0;
  for (std::size_t s = 0; s + 1 < u.size(); ++s) out = std::max(out, u[s + 1] - u[s]);
  return out;
}

}  // namespace

double graded_knot_count_bound(const NurbsPatch& patch, const GradingRequest& r) {
  const std::vector<double> u = unique_knots(patch.knots[std::size_t(r.direction)]);
  // the march's parameter steps are at least h / (largest speed): sample it along the direction
  const int samples = 33;
  double speed = 0;
  for (int i = 0; i < samples; ++i) speed = std::max(speed, max_speed(patch, r.direction, u.front() + (u.back() - u.front()) * i / (samples - 1)));
  const double log_growth = std::log1p(r.growth - 1), largest = speed * largest_span(u);
  double count = 0;
  for (const double distance : {u.back() - r.toward, r.toward - u.front()}) {
    if (distance <= 0) continue;
    // to cover the side: smallest (growth^n - 1) / (growth - 1) = length; to reach the largest span: smallest growth^n = largest
    const double cover = std::log1p(speed * distance * (r.growth - 1) / r.smallest) / log_growth;
    const double reach = std::log(std::max(1.0, largest / r.smallest)) / log_growth;
    count += std::min(cover, reach) + 1;
  }
  return count;
}

std::vector<double> graded_knots(const NurbsPatch& patch, const GradingRequest& r) {
  const std::vector<double> u = unique_knots(patch.knots[std::size_t(r.direction)]);
  const double max_step = largest_span(u);

  std::vector<double> knots = march(patch, r, r.toward, u.back(), max_step);
  const std::vector<double> down = march(patch, r, r.toward, u.front(), max_step);
  knots.insert(knots.end(), down.begin(), down.end());
  if (r.toward > u.front() && r.toward < u.back()) knots.push_back(r.toward);
  std::sort(knots.begin(), knots.end());
  const double eps = 1e-12 * (u.back() - u.front());
  knots.erase(std::remove_if(knots.begin(), knots.end(),
                             [&](double k) {
                               return std::any_of(u.begin(), u.end(), [&](double e) { return std::abs(e - k) < eps; });
                             }),
              knots.end());
  return knots;
}

}  // namespace isosid::prep
