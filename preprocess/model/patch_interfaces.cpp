// Interfaces between patches; see patch_interfaces.hpp.
#include "model/patch_interfaces.hpp"

#include "model/body_model.hpp"
#include "geometry/multi_index.hpp"
#include "model/placement.hpp"
#include "refine/patch_refinement.hpp"
#include "isosid/format/error.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace isosid::prep {
namespace {

/// The control net of one side: tangential directions (ascending), their control-point counts,
/// and the control points (NurbsPatch::side_points, first tangential direction fastest).
struct Face {
  PatchSide side;
  std::vector<int> directions, counts;
  std::vector<int> index;
  int at(const std::vector<int>& j) const {
    int k = 0, stride = 1;
    for (std::size_t t = 0; t < j.size(); ++t) {
      k += j[t] * stride;
      stride *= counts[t];
    }
    return index[std::size_t(k)];
  }
};

/// The faces of every side of a patch, in the order xi0, xi1, eta0, ...
std::vector<Face> faces_of(const NurbsPatch& p) {
  std::vector<Face> out;
  const std::vector<int> n = p.counts();
  for (int d = 0; d < p.param_dim(); ++d)
    for (int end = 0; end < 2; ++end) {
      Face& f = out.emplace_back();
      f.side = {d, end};
      for (int t = 0; t < p.param_dim(); ++t)
        if (t != d) {
          f.directions.push_back(t);
          f.counts.push_back(n[std::size_t(t)]);
        }
      f.index = p.side_points(f.side);
    }
  return out;
}

/// The knot vector of direction d mapped onto [0, 1], reversed if asked.
Eigen::VectorXd unit_knots(const NurbsPatch& p, int d, bool reversed) {
  const Eigen::VectorXd& U = p.knots[std::size_t(d)];
  Eigen::VectorXd u = (U.array() - U(0)) / (U(U.size() - 1) - U(0));
  if (reversed) u = (1.0 - u.reverse().array()).matrix();
  return u;
}

/// Whether face fa of A and face fb of B carry the same control net, and how their directions pair.
bool faces_match(const NurbsPatch& A, const Face& fa, const NurbsPatch& B, const Face& fb, double tol, PatchInterface& out) {
  const std::size_t nt = fa.directions.size();
  std::vector<int> perm(nt);
  for (std::size_t t = 0; t < nt; ++t) perm[t] = int(t);
  do {  // tangential direction t of A runs along direction perm[t] of B's face
    for (int flips = 0; flips < (1 << nt); ++flips) {
      bool ok = true;
      for (std::size_t t = 0; t < nt && ok; ++t) ok = fa.counts[t] == fb.counts[std::size_t(perm[t])];
      if (!ok) continue;
      MultiIndex j(int(nt), fa.counts);
      std::vector<int> ja(nt, 0), jb(nt, 0);
      double ratio = 0;
      do {
        for (std::size_t t = 0; t < nt; ++t) {
          ja[t] = j[int(t)];
          jb[std::size_t(perm[t])] = (flips >> t & 1) ? fa.counts[t] - 1 - ja[t] : ja[t];
        }
        const int ia = fa.at(ja), ib = fb.at(jb);
        ok = (A.points.row(ia) - B.points.row(ib)).norm() <= tol;
        // NURBS weights of one patch may be scaled as a whole: equal up to one factor
        if (ok && ratio == 0) ratio = A.weights(ia) / B.weights(ib);
        ok = ok && std::abs(A.weights(ia) - ratio * B.weights(ib)) <= 1e-12 * A.weights(ia);
      } while (ok && j.next());
      if (!ok) continue;
      out.b_direction.clear();
      out.reversed.clear();
      for (std::size_t t = 0; t < nt; ++t) {
        out.b_direction.push_back(fb.directions[std::size_t(perm[t])]);
        out.reversed.push_back(flips >> t & 1);
      }
      return true;
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return false;
}

/// Whether two sides are flat in one common coordinate and overlap over an area in the others
/// (their control-net boxes), i.e. touch face to face.
bool touch_over_area(const NurbsPatch& A, const Face& fa, const NurbsPatch& B, const Face& fb, double tol) {
  auto box = [](const NurbsPatch& p, const Face& f, Eigen::VectorXd& lo, Eigen::VectorXd& hi) {
    lo = hi = p.points.row(f.index[0]).transpose();
    for (int i : f.index) {
      lo = lo.cwiseMin(p.points.row(i).transpose());
      hi = hi.cwiseMax(p.points.row(i).transpose());
    }
  };
  Eigen::VectorXd la, ha, lb, hb;
  box(A, fa, la, ha);
  box(B, fb, lb, hb);
  const Eigen::VectorXd lo = la.cwiseMax(lb), hi = ha.cwiseMin(hb);
  int flat = 0, spread = 0;
  for (Eigen::Index c = 0; c < lo.size(); ++c) {
    if (hi(c) < lo(c) - tol) return false;  // apart
    if (ha(c) - la(c) <= tol && hb(c) - lb(c) <= tol) ++flat;
    else if (hi(c) - lo(c) > tol) ++spread;
  }
  return flat >= 1 && spread == lo.size() - 1;
}

/// A point strictly inside patch B (not on its boundary) that is also a point of patch A:
/// the patches overlap. Samples A at 1/4, 1/2 and 3/4 of each knot span in each direction
/// (a span's centre alone can sit on B's boundary when B is offset by half a span).
bool overlaps(const NurbsPatch& A, const NurbsPatch& B, double tol) {
  const int pd = A.param_dim();
  std::vector<std::vector<double>> centres(static_cast<std::size_t>(pd));
  for (int d = 0; d < pd; ++d) {
    const std::vector<double> u = unique_knots(A.knots[std::size_t(d)]);
    for (std::size_t k = 0; k + 1 < u.size(); ++k)
      for (double t : {0.25, 0.5, 0.75}) centres[std::size_t(d)].push_back(u[k] + t * (u[k + 1] - u[k]));
  }
  std::vector<std::size_t> sizes;
  for (const auto& c : centres) sizes.push_back(c.size());
  MultiIndex j(pd, sizes);
  do {
    Eigen::VectorXd xi(pd);
    for (int d = 0; d < pd; ++d) xi(d) = centres[std::size_t(d)][std::size_t(j[d])];
    const BodyPoint p = nearest_point(B, A.point(xi));
    bool inside = p.distance <= tol;
    for (int d = 0; d < pd && inside; ++d) {
      const double w = B.upper(d) - B.lower(d);
      inside = p.parameter(d) > B.lower(d) + 1e-6 * w && p.parameter(d) < B.upper(d) - 1e-6 * w;
    }
    if (inside) return true;
  } while (j.next());
  return false;
}

std::string side_text(const std::vector<PatchSpec>& patches, int patch, PatchSide side) {
  return patches[std::size_t(patch)].name + "." + side_name(side);
}

/// Refuses a body whose patches, joined by their interfaces, form more than one piece: the
/// pieces' relative rigid motions would pass for elastic modes of near-zero frequency. Names
/// the first patch and one it is not joined to, saying whether they still touch at a point or
/// an edge (a hinge, not a solid).
void check_connected(const std::vector<PatchSpec>& patches, const std::vector<PatchInterface>& interfaces, const std::string& file,
                     double tol) {
  std::vector<int> piece(patches.size());
  for (std::size_t k = 0; k < piece.size(); ++k) piece[k] = int(k);
  const auto root = [&](int k) {
    while (piece[std::size_t(k)] != k) k = piece[std::size_t(k)];
    return k;
  };
  for (const PatchInterface& i : interfaces) piece[std::size_t(root(i.b))] = root(i.a);
  for (int b = 1; b < int(patches.size()); ++b) {
    if (root(b) == root(0)) continue;
    // touching: a control point of the piece of patch 0 on one of patch b (corners and edges
    // of patches interpolate their control points)
    bool touch = false;
    for (int a = 0; a < int(patches.size()) && !touch; ++a) {
      if (root(a) != root(0)) continue;
      const Eigen::MatrixXd &P = patches[std::size_t(a)].patch.points, &Q = patches[std::size_t(b)].patch.points;
      for (Eigen::Index i = 0; i < P.rows() && !touch; ++i)
        for (Eigen::Index j = 0; j < Q.rows() && !touch; ++j) touch = (P.row(i) - Q.row(j)).norm() <= tol;
    }
    throw format::InputError(file, "patch", "patches '" + patches[0].name + "' and '" + patches[std::size_t(b)].name + "' " +
                                                (touch ? "meet at a point or an edge only" : "share no side") +
                                                " (a body must be one connected solid)");
  }
}

}  // namespace

std::vector<PatchInterface> find_interfaces(const std::vector<PatchSpec>& patches, const std::string& file) {
  std::vector<PatchInterface> out;
  if (patches.size() < 2) return out;
  double size = 0;
  for (const PatchSpec& p : patches) size = std::max(size, patch_size(p.patch));
  const double tol = 1e-10 * size;
  std::vector<std::vector<Face>> faces;
  for (const PatchSpec& p : patches) faces.push_back(faces_of(p.patch));
  for (int a = 0; a < int(patches.size()); ++a)
    for (int b = a + 1; b < int(patches.size()); ++b) {
      const NurbsPatch &A = patches[std::size_t(a)].patch, &B = patches[std::size_t(b)].patch;
      if (overlaps(A, B, tol) || overlaps(B, A, tol))
        throw format::InputError(file, "patch", "patches '" + patches[std::size_t(a)].name + "' and '" +
                                                    patches[std::size_t(b)].name + "' overlap");
      for (const Face& fa : faces[std::size_t(a)])
        for (const Face& fb : faces[std::size_t(b)]) {
          auto between = [&] {
            return "non-matching interface between " + side_text(patches, a, fa.side) + " and " + side_text(patches, b, fb.side);
          };
          PatchInterface i{a, b, fa.side, fb.side, {}, {}};
          if (faces_match(A, fa, B, fb, tol, i)) {
            // the two sides' knot vectors must agree up to an affine map, or the merged
            // control points carry different functions
            for (std::size_t t = 0; t < fa.directions.size(); ++t) {
              const int da = fa.directions[t], db = i.b_direction[t];
              const Eigen::VectorXd ua = unit_knots(A, da, false), ub = unit_knots(B, db, i.reversed[t]);
              if (ua.size() != ub.size() || (ua - ub).cwiseAbs().maxCoeff() > 1e-12 ||
                  A.degrees[std::size_t(da)] != B.degrees[std::size_t(db)])
                throw format::InputError(file, "patch", between() + ": the control points coincide but the knots or degrees differ");
            }
            out.push_back(i);
          } else if (touch_over_area(A, fa, B, fb, tol)) {
            throw format::InputError(file, "patch", between() + ": the sides touch but their control points differ (split the "
                                                              "larger patch so that the sides match)");
          }
        }
    }
  check_connected(patches, out, file, tol);
  return out;
}

std::vector<PatchInterface> find_mesh_interfaces(const std::vector<PatchSpec>& patches) {
  std::vector<PatchInterface> out;
  if (patches.empty()) return out;
  double size = 0;
  for (const PatchSpec& p : patches) size = std::max(size, patch_size(p.patch));
  const double tol = 1e-10 * size;
  // a side's key: its first and last control points, rounded to a grid coarser than tol and
  // sorted (neighbours run their common side either way)
  auto rounded = [&](const Eigen::VectorXd& x) {
    std::vector<long long> k;
    for (Eigen::Index i = 0; i < x.size(); ++i) k.push_back(std::llround(x(i) / (1e3 * tol)));
    return k;
  };
  std::map<std::pair<std::vector<long long>, std::vector<long long>>, std::vector<std::pair<int, Face>>> sides;
  for (int a = 0; a < int(patches.size()); ++a)
    for (const Face& f : faces_of(patches[std::size_t(a)].patch)) {
      const Eigen::MatrixXd& P = patches[std::size_t(a)].patch.points;
      auto first = rounded(P.row(f.index.front()).transpose()), last = rounded(P.row(f.index.back()).transpose());
      if (last < first) std::swap(first, last);
      sides[{first, last}].push_back({a, f});
    }
  for (const auto& [key, list] : sides)
    for (std::size_t i = 0; i < list.size(); ++i)
      for (std::size_t j = i + 1; j < list.size(); ++j) {
        auto [a, fa] = list[i];
        auto [b, fb] = list[j];
        if (a > b) std::swap(a, b), std::swap(fa, fb);
        PatchInterface interface{a, b, fa.side, fb.side, {}, {}};
        if (a != b && faces_match(patches[std::size_t(a)].patch, fa, patches[std::size_t(b)].patch, fb, tol, interface))
          out.push_back(interface);
      }
  return out;
}

void make_conforming(std::vector<NurbsPatch>& refined, const std::vector<PatchInterface>& interfaces) {
  for (bool changed = true; changed;) {
    changed = false;
    for (const PatchInterface& i : interfaces) {
      NurbsPatch &A = refined[std::size_t(i.a)], &B = refined[std::size_t(i.b)];
      int t = 0;
      for (int da = 0; da < A.param_dim(); ++da) {
        if (da == i.side_a.direction) continue;
        const int db = i.b_direction[std::size_t(t)];
        const bool rev = i.reversed[std::size_t(t++)];
        const int p = std::max(A.degrees[std::size_t(da)], B.degrees[std::size_t(db)]);
        for (auto [P, d] : {std::pair<NurbsPatch*, int>{&A, da}, {&B, db}})
          if (P->degrees[std::size_t(d)] < p) {
            elevate_degree(*P, d, p);
            changed = true;
          }
        // knots (with multiplicity) of each side that the other lacks, mapped across
        auto missing = [](const Eigen::VectorXd& have, const Eigen::VectorXd& want) {
          std::vector<double> add;
          std::size_t k = 0;
          for (Eigen::Index w = 0; w < want.size(); ++w) {
            while (k < std::size_t(have.size()) && have(Eigen::Index(k)) < want(w) - 1e-12) ++k;
            if (k < std::size_t(have.size()) && std::abs(have(Eigen::Index(k)) - want(w)) <= 1e-12) ++k;
            else add.push_back(want(w));
          }
          return add;
        };
        const Eigen::VectorXd ua = unit_knots(A, da, false), ub = unit_knots(B, db, rev);
        auto to_patch = [](const NurbsPatch& P, int d, bool reversed, double u) {
          const double v = reversed ? 1.0 - u : u;
          return P.lower(d) + v * (P.upper(d) - P.lower(d));
        };
        std::vector<double> into_a, into_b;
        for (double u : missing(ua, ub)) into_a.push_back(to_patch(A, da, false, u));
        for (double u : missing(ub, ua)) into_b.push_back(to_patch(B, db, rev, u));
        if (!into_a.empty()) insert_knots(A, da, into_a);
        if (!into_b.empty()) insert_knots(B, db, into_b);
        changed = changed || !into_a.empty() || !into_b.empty();
      }
    }
    if (changed) continue;
    // one degree per direction for the whole body: raise every patch to the highest
    for (int d = 0; d < refined[0].param_dim(); ++d) {
      int p = 0;
      for (const NurbsPatch& P : refined) p = std::max(p, P.degrees[std::size_t(d)]);
      for (NurbsPatch& P : refined)
        if (P.degrees[std::size_t(d)] < p) {
          elevate_degree(P, d, p);
          changed = true;
        }
    }
  }
}

}  // namespace isosid::prep
