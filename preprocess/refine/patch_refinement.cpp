// Direction-wise refinement of NURBS patches; see patch_refinement.hpp.
#include "refine/patch_refinement.hpp"

#include "refine/degree_elevation.hpp"
#include "refine/knot_insertion.hpp"

#include <algorithm>

namespace isosid::prep {

void refine_direction(NurbsPatch& patch, int dir, const Eigen::MatrixXd& T, const KnotVector& new_knots,
                      int new_degree) {
  const std::vector<int> n_old = patch.counts();
  std::vector<int> n_new = n_old;
  n_new[std::size_t(dir)] = int(T.rows());
  const int cols = patch.phys_dim();
  // homogeneous coordinates [w x, w]
  Eigen::MatrixXd Pw(patch.count(), cols + 1);
  Pw.leftCols(cols) = patch.weights.asDiagonal() * patch.points;
  Pw.col(cols) = patch.weights;

  int lines = 1;
  for (std::size_t d = 0; d < n_old.size(); ++d)
    if (int(d) != dir) lines *= n_old[d];
  int total_new = 1;
  for (int c : n_new) total_new *= c;
  Eigen::MatrixXd Qw(total_new, cols + 1);
  std::vector<int> ijk(n_old.size(), 0);
  const int n_line = n_old[std::size_t(dir)];
  Eigen::MatrixXd line(n_line, cols + 1);
  for (int l = 0; l < lines; ++l) {
    // multi-index of the other directions from l
    int rest = l;
    for (std::size_t d = 0; d < n_old.size(); ++d) {
      if (int(d) == dir) continue;
      ijk[d] = rest % n_old[d];
      rest /= n_old[d];
    }
    for (int i = 0; i < n_line; ++i) {
      ijk[std::size_t(dir)] = i;
      line.row(i) = Pw.row(flat_index(n_old, ijk));
    }
    const Eigen::MatrixXd refined = T * line;
    for (int i = 0; i < refined.rows(); ++i) {
      ijk[std::size_t(dir)] = i;
      Qw.row(flat_index(n_new, ijk)) = refined.row(i);
    }
  }
  patch.weights = Qw.col(cols);
  patch.points = Qw.leftCols(cols).array().colwise() / patch.weights.array();
  patch.knots[std::size_t(dir)] = new_knots;
  patch.degrees[std::size_t(dir)] = new_degree;
}

void elevate_degree(NurbsPatch& patch, int dir, int target) {
  const int p = patch.degrees[std::size_t(dir)];
  if (target <= p) return;
  const KnotVector& U = patch.knots[std::size_t(dir)];
  refine_direction(patch, dir, degree_elevation_matrix(U, p, target - p), elevated_knots(U, p, target - p), target);
}

void insert_knots(NurbsPatch& patch, int dir, std::vector<double> X) {
  if (X.empty()) return;
  std::sort(X.begin(), X.end());
  const int p = patch.degrees[std::size_t(dir)];
  const KnotVector& U = patch.knots[std::size_t(dir)];
  const int n = basis_count(U, p);
  const RefinedCurve r = prep::insert_knots(U, p, Eigen::MatrixXd::Identity(n, n), X);
  refine_direction(patch, dir, r.points, r.knots, p);
}

void subdivide_uniformly(NurbsPatch& patch, int dir, int parts) {
  if (parts <= 1) return;
  const std::vector<double> u = unique_knots(patch.knots[std::size_t(dir)]);
  std::vector<double> X;
  for (std::size_t s = 0; s + 1 < u.size(); ++s)
    for (int k = 1; k < parts; ++k) X.push_back(u[s] + (u[s + 1] - u[s]) * k / parts);
  insert_knots(patch, dir, X);
}

}  // namespace isosid::prep
