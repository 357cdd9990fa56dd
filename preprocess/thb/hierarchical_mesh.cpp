// Levels and nested domains of a THB refinement; see hierarchical_mesh.hpp.
#include "thb/hierarchical_mesh.hpp"

#include "isosid/format/error.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace isosid::prep {
namespace {

constexpr const char* kField = "refinement.hierarchical";

double tolerance(const ParameterBox& b, std::size_t d) { return 1e-12 * (1.0 + std::abs(b.hi[d] - b.lo[d])); }

KnotVector subdivide(const KnotVector& U, int parts) {
  if (parts <= 1) return U;
  std::vector<double> out;
  for (Eigen::Index i = 0; i < U.size(); ++i) {
    out.push_back(U(i));
    if (i + 1 < U.size() && U(i + 1) > U(i))
      for (int k = 1; k < parts; ++k) out.push_back(U(i) + (U(i + 1) - U(i)) * k / parts);
  }
  return Eigen::Map<const KnotVector>(out.data(), Eigen::Index(out.size()));
}

/// Physical distance from the point to the point moved to parameter t along direction d.
double chord(const NurbsPatch& p, const std::vector<double>& point, int d, double t) {
  Eigen::VectorXd a = Eigen::Map<const Eigen::VectorXd>(point.data(), Eigen::Index(point.size())), b = a;
  b(d) = t;
  return (p.point(b) - p.point(a)).norm();
}

/// Parameter reached from `point` along direction d when the chord grows to `length`
/// (the parameter bound if it never does).
double walk(const NurbsPatch& p, const std::vector<double>& point, int d, double length, double bound) {
  if (chord(p, point, d, bound) <= length) return bound;
  double near = point[d], far = bound;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (near + far);
    (chord(p, point, d, mid) < length ? near : far) = mid;
  }
  return 0.5 * (near + far);
}

/// The request's box in parameter space.
ParameterBox request_box(const NurbsPatch& base, const HierarchicalRequest& r, const std::string& file) {
  const int pd = base.param_dim();
  ParameterBox box;
  if (!r.box.empty()) {
    for (int d = 0; d < pd; ++d) {
      box.lo.push_back(r.box[d][0]);
      box.hi.push_back(r.box[d][1]);
    }
    return box;
  }
  const double size = (base.points.colwise().maxCoeff() - base.points.colwise().minCoeff()).norm();
  for (int d = 0; d < pd; ++d) {
    const double range = base.upper(d) - base.lower(d), step = 1e-6 * range;
    const double t = std::min(r.point[d] + step, base.upper(d)), s = std::max(r.point[d] - step, base.lower(d));
    const double speed = std::max(chord(base, r.point, d, t), chord(base, r.point, d, s)) / step;
    if (speed < 1e-9 * size / range)
      throw format::InputError(file, std::string(kField) + ".point",
                               std::string("the parametrization collapses at the point along ") + direction_name(d) +
                                   ", so a physical width cannot be measured there; give a parameter box");
    box.lo.push_back(walk(base, r.point, d, 0.5 * r.width, base.lower(d)));
    box.hi.push_back(walk(base, r.point, d, 0.5 * r.width, base.upper(d)));
  }
  return box;
}

/// Largest |dx/dxi_d| over the box corners and centre: element sizes are measured with it,
/// so no element in the box is longer than requested.
double largest_speed(const NurbsPatch& base, const ParameterBox& box, int d) {
  const int pd = base.param_dim();
  double speed = 0;
  Eigen::VectorXd xi(pd), x;
  Eigen::MatrixXd J;
  for (int corner = 0; corner <= (1 << pd); ++corner) {
    for (int k = 0; k < pd; ++k)
      xi(k) = corner == (1 << pd) ? 0.5 * (box.lo[k] + box.hi[k])
                                  : ((corner >> k) & 1 ? box.hi[k] : box.lo[k]);
    base.evaluate(xi, x, &J);
    speed = std::max(speed, J.col(d).norm());
  }
  return speed;
}

/// Longest span of U overlapping [lo, hi].
double longest_span(const KnotVector& U, double lo, double hi) {
  double longest = 0;
  for (Eigen::Index i = 0; i + 1 < U.size(); ++i)
    if (U(i + 1) > U(i) && U(i + 1) > lo && U(i) < hi) longest = std::max(longest, U(i + 1) - U(i));
  return longest;
}

/// Largest unique knot <= x (snap down) or smallest >= x (snap up), within round-off.
double snap(const std::vector<double>& u, double x, bool down) {
  const double tol = 1e-12 * (u.back() - u.front());
  if (down) {
    auto it = std::upper_bound(u.begin(), u.end(), x + tol);
    return it == u.begin() ? u.front() : *(it - 1);
  }
  auto it = std::lower_bound(u.begin(), u.end(), x - tol);
  return it == u.end() ? u.back() : *it;
}

/// Moves x by `cells` unique knots of u (down from the knot at or below x, or up from the
/// knot at or above it), stopping at the ends.
double step_knots(const std::vector<double>& u, double x, int cells, bool down) {
  const double tol = 1e-12 * (u.back() - u.front());
  if (down) {
    const auto k = std::distance(u.begin(), std::upper_bound(u.begin(), u.end(), x + tol)) - 1;
    return u[std::size_t(std::max<std::ptrdiff_t>(0, k - cells))];
  }
  const auto k = std::distance(u.begin(), std::lower_bound(u.begin(), u.end(), x - tol));
  return u[std::size_t(std::min<std::ptrdiff_t>(std::ptrdiff_t(u.size()) - 1, k + cells))];
}

}  // namespace

bool ParameterBox::contains(const std::vector<double>& inner_lo, const std::vector<double>& inner_hi) const {
  for (std::size_t d = 0; d < lo.size(); ++d) {
    const double tol = tolerance(*this, d);
    if (inner_lo[d] < lo[d] - tol || inner_hi[d] > hi[d] + tol) return false;
  }
  return true;
}

HierarchicalMesh HierarchicalMesh::single_level(const NurbsPatch& patch) {
  HierarchicalMesh m;
  m.degrees = patch.degrees;
  m.knots.push_back(patch.knots);
  m.factors.push_back(std::vector<int>(std::size_t(patch.param_dim()), 1));
  ParameterBox whole;
  for (int d = 0; d < patch.param_dim(); ++d) {
    whole.lo.push_back(patch.lower(d));
    whole.hi.push_back(patch.upper(d));
  }
  m.domains.push_back(whole);
  return m;
}

HierarchicalMesh hierarchical_mesh(const NurbsPatch& base, const HierarchicalRequest& r, const std::string& file) {
  HierarchicalMesh m = HierarchicalMesh::single_level(base);
  const int pd = base.param_dim();
  const ParameterBox box = request_box(base, r, file);
  // on a side collapsed along some but not all directions (the axis of a revolved solid) a
  // node gathers the functions of one level only, so a box touching it must cover the
  // collapsed directions whole (then truncation keeps every level's trace single-valued)
  for (int d = 0; d < pd; ++d)
    for (int end = 0; end < 2; ++end) {
      const double bound = end ? base.upper(d) : base.lower(d);
      if (std::abs((end ? box.hi : box.lo)[d] - bound) > 1e-12 * (base.upper(d) - base.lower(d))) continue;
      const std::vector<int> collapsed = base.collapsed_directions({d, end});
      if (int(collapsed.size()) == pd - 1) continue;  // collapsed to a point: nodes merge across levels
      for (int c : collapsed)
        if (box.lo[c] > base.lower(c) || box.hi[c] < base.upper(c))
          throw format::InputError(file, std::string(kField) + (r.box.empty() ? ".width" : ".box"),
                                   std::string("touches side ") + side_name({d, end}) + ", which collapses along " +
                                       direction_name(c) + ", so it must span " + direction_name(c) + " whole");
    }

  // factors per direction (Alg. 3), padded with 1 at the coarse end to a common level count
  std::vector<std::vector<int>> factors(pd);
  std::size_t refined_levels = 0;
  for (int d = 0; d < pd; ++d) {
    const double extent = box.hi[d] - box.lo[d];
    const double finest = r.smallest > 0 ? r.smallest / largest_speed(base, box, d) : extent / r.elements_across;
    const double ratio = longest_span(base.knots[d], box.lo[d], box.hi[d]) / finest;
    if (ratio > 1e7)
      throw format::InputError(file, std::string(kField) + (r.smallest > 0 ? ".smallest" : ".elements_across"),
                               std::string("asks for a subdivision by ") + std::to_string(std::llround(ratio)) + " along " +
                                   direction_name(d) + "; refine the coarse model or ask for larger elements");
    try {
      factors[d] = level_factors(int(std::ceil(ratio - 1e-9)), r.limits);
    } catch (const std::invalid_argument& e) {
      throw format::InputError(file, kField, std::string(direction_name(d)) + ": " + e.what());
    }
    refined_levels = std::max(refined_levels, factors[d].size());
  }
  // the largest splits go to the coarsest levels: the jumps in element size next to the
  // contact stay small (measured on scene A: ascending order, as Alg. 3 lists them, puts a
  // 7x jump at the edge of the finest box and stiffens the contact by 1-2 %)
  for (auto& f : factors) {
    std::sort(f.rbegin(), f.rend());
    f.insert(f.begin(), refined_levels - f.size(), 1);
  }

  for (std::size_t l = 0; l < refined_levels; ++l) {
    std::vector<KnotVector> U;
    std::vector<int> f;
    for (int d = 0; d < pd; ++d) {
      f.push_back(factors[d][l]);
      U.push_back(subdivide(m.knots.back()[d], f.back()));
    }
    m.knots.push_back(std::move(U));
    m.factors.push_back(std::move(f));
  }

  // nested domains, finest first: the box snapped outward to the parent level's knots; each
  // coarser domain holds the next finer one and, for admissibility of class m, the domain
  // m - 1 levels finer grown by p elements of its own level (then no truncated function of
  // a level below l - m + 1 reaches an element of level l)
  const int L = m.levels() - 1, reach = r.admissibility - 1;
  m.domains.resize(std::size_t(L + 1));
  for (int l = L; l >= 1; --l) {
    ParameterBox& dom = m.domains[l];
    dom.lo.resize(pd);
    dom.hi.resize(pd);
    for (int d = 0; d < pd; ++d) {
      const std::vector<double> parent = unique_knots(m.knots[l - 1][d]);
      double lo = box.lo[d], hi = box.hi[d];
      if (l < L) {
        lo = m.domains[l + 1].lo[d];
        hi = m.domains[l + 1].hi[d];
        if (l + reach <= L) {
          const std::vector<double> own = unique_knots(m.knots[l][d]);
          const int p = m.degrees[d];
          lo = std::min(lo, step_knots(own, m.domains[l + reach].lo[d], p, true));
          hi = std::max(hi, step_knots(own, m.domains[l + reach].hi[d], p, false));
        }
      }
      dom.lo[d] = snap(parent, lo, true);
      dom.hi[d] = snap(parent, hi, false);
    }
  }
  return m;
}

}  // namespace isosid::prep
