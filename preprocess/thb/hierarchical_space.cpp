// THB space construction; see hierarchical_space.hpp.
#include "thb/hierarchical_space.hpp"

#include "geometry/multi_index.hpp"
#include "space/span_extraction.hpp"
#include "refine/knot_insertion.hpp"

#include <algorithm>
#include <map>
#include <unordered_map>

namespace isosid::prep {
namespace {


void add_scaled(SparseRow& into, const SparseRow& row, double scale) {
  SparseRow out;
  out.reserve(into.size() + row.size());
  std::size_t a = 0, b = 0;
  while (a < into.size() || b < row.size()) {
    if (b == row.size() || (a < into.size() && into[a].first < row[b].first)) {
      out.push_back(into[a++]);
    } else if (a == into.size() || row[b].first < into[a].first) {
      out.emplace_back(row[b].first, scale * row[b].second);
      ++b;
    } else {
      out.emplace_back(into[a].first, into[a].second + scale * row[b].second);
      ++a;
      ++b;
    }
  }
  into.swap(out);
}

/// One level of the hierarchy: its tensor basis, its two-scale relation to the parent level
/// and memoized representations of its functions.
struct Level {
  std::vector<KnotVector> U;
  std::vector<int> n;                               ///< functions per direction
  std::vector<std::vector<SpanExtraction>> spans;   ///< per direction
  std::vector<std::vector<SparseRow>> two_scale;    ///< [dir][function] -> parent functions and coefficients
  ParameterBox domain;
  std::unordered_map<long long, int> active;        ///< flat index -> THB function
  std::unordered_map<long long, SparseRow> truncated, on_patch;

  long long flat(const std::vector<int>& ijk) const {
    long long f = 0, stride = 1;
    for (std::size_t d = 0; d < n.size(); ++d) {
      f += ijk[d] * stride;
      stride *= n[d];
    }
    return f;
  }
  std::vector<int> multi(long long f) const {
    std::vector<int> ijk(n.size());
    for (std::size_t d = 0; d < n.size(); ++d) {
      ijk[d] = int(f % n[d]);
      f /= n[d];
    }
    return ijk;
  }
  /// Support box of a tensor function.
  void support(const std::vector<int>& ijk, int dims, const std::vector<int>& p, std::vector<double>& lo, std::vector<double>& hi) const {
    lo.resize(dims);
    hi.resize(dims);
    for (int d = 0; d < dims; ++d) {
      lo[d] = U[d](ijk[d]);
      hi[d] = U[d](ijk[d] + p[d] + 1);
    }
  }
};

class Builder {
public:
  Builder(const NurbsPatch& patch, const HierarchicalMesh& mesh) : patch_(patch), mesh_(mesh), pd_(patch.param_dim()) {
    for (int l = 0; l < mesh.levels(); ++l) {
      Level lv;
      lv.U = mesh.knots[l];
      lv.domain = mesh.domains[l];
      for (int d = 0; d < pd_; ++d) {
        const int p = mesh.degrees[d];
        lv.n.push_back(basis_count(lv.U[d], p));
        lv.spans.push_back(span_extractions(lv.U[d], p));
        if (l > 0) lv.two_scale.push_back(two_scale(levels_.back().U[d], lv.U[d], p));
      }
      levels_.push_back(std::move(lv));
    }
  }

  HierarchicalSpace build() {
    HierarchicalSpace out;
    AnalysisSpace& s = out.space;
    s.degrees = mesh_.degrees;
    PatchRange& box = s.patch_boxes.emplace_back();
    for (int d = 0; d < pd_; ++d) {
      box.lo(d) = patch_.lower(d);
      box.hi(d) = patch_.upper(d);
    }
    number_active_functions(s, out.functions_per_level);
    for (int l = 0; l < int(levels_.size()); ++l) out.elements_per_level.push_back(add_active_elements(l, s));
    rational_coefficients(s, out.prolongation);
    return out;
  }

private:
  static std::vector<SparseRow> two_scale(const KnotVector& coarse, const KnotVector& fine, int p) {
    std::vector<double> X;
    Eigen::Index c = 0;
    for (Eigen::Index i = 0; i < fine.size(); ++i) {  // fine minus coarse, as a multiset
      if (c < coarse.size() && std::abs(coarse(c) - fine(i)) <= 1e-14 * (1 + std::abs(fine(i)))) ++c;
      else X.push_back(fine(i));
    }
    std::vector<SparseRow> rows = knot_insertion_rows(coarse, p, X);
    for (SparseRow& row : rows)  // exact zeros (a knot of full multiplicity) carry nothing
      row.erase(std::remove_if(row.begin(), row.end(), [](const auto& e) { return e.second == 0.0; }), row.end());
    return rows;
  }

  /// Level-l functions whose support overlaps Omega^l, in flat-index order.
  std::vector<long long> overlapping_functions(int l) const {
    const Level& lv = levels_[l];
    std::vector<int> first(pd_), last(pd_);
    for (int d = 0; d < pd_; ++d) {
      const KnotVector& U = lv.U[d];
      const int p = mesh_.degrees[d];
      const double lo = lv.domain.lo[d], hi = lv.domain.hi[d];
      first[d] = lv.n[d];
      last[d] = -1;
      for (int i = 0; i < lv.n[d]; ++i)
        if (U(i) < hi && U(i + p + 1) > lo) {
          first[d] = std::min(first[d], i);
          last[d] = i;
        }
    }
    std::vector<long long> out;
    std::vector<int> extent(pd_), ijk(pd_);
    for (int d = 0; d < pd_; ++d) {
      if (last[d] < first[d]) return out;
      extent[d] = last[d] - first[d] + 1;
    }
    MultiIndex box(pd_, extent);
    do {
      for (int d = 0; d < pd_; ++d) ijk[d] = first[d] + box[d];
      out.push_back(lv.flat(ijk));
    } while (box.next());
    return out;
  }

  bool inside(int l, const Level& lv, long long f) const {
    if (l >= int(levels_.size())) return false;
    std::vector<double> lo, hi;
    lv.support(lv.multi(f), pd_, mesh_.degrees, lo, hi);
    return levels_[l].domain.contains(lo, hi);
  }

  void number_active_functions(AnalysisSpace& s, std::vector<int>& per_level) {
    int next = 0;
    for (int l = 0; l < int(levels_.size()); ++l) {
      Level& lv = levels_[l];
      int count = 0;
      for (long long f : overlapping_functions(l))
        if (inside(l, lv, f) && !inside(l + 1, lv, f)) {
          lv.active.emplace(f, next++);
          s.function_level.push_back(l);
          ++count;
        }
      per_level.push_back(count);
    }
  }

  /// Coefficients of level-l function f on the THB functions: itself if active, nothing if
  /// its support lies in Omega^l (truncated away or represented at finer levels), else its
  /// refinement of the parent level's representation.
  const SparseRow& truncated(int l, long long f) {
    Level& lv = levels_[l];
    if (auto it = lv.truncated.find(f); it != lv.truncated.end()) return it->second;
    SparseRow row;
    if (auto a = lv.active.find(f); a != lv.active.end()) row.emplace_back(a->second, 1.0);
    else if (l > 0 && !inside(l, lv, f)) row = refine(l, f, [&](long long g) -> const SparseRow& { return truncated(l - 1, g); });
    return lv.truncated.emplace(f, std::move(row)).first->second;
  }

  /// Coefficients of level-l function f on the patch's (level-0) functions: B^0 = T^T B^l.
  const SparseRow& on_patch(int l, long long f) {
    Level& lv = levels_[l];
    if (auto it = lv.on_patch.find(f); it != lv.on_patch.end()) return it->second;
    SparseRow row;
    if (l == 0) row.emplace_back(int(f), 1.0);
    else row = refine(l, f, [&](long long g) -> const SparseRow& { return on_patch(l - 1, g); });
    return lv.on_patch.emplace(f, std::move(row)).first->second;
  }

  /// sum_k T(f, k) parent(k): the two-scale relation applied to rows of the parent level.
  template <class ParentRow>
  SparseRow refine(int l, long long f, ParentRow parent) {
    const Level& lv = levels_[l];
    const Level& up = levels_[l - 1];
    const std::vector<int> ijk = lv.multi(f);
    SparseRow row;
    std::vector<int> parent_count(pd_), parent_ijk(pd_);
    for (int d = 0; d < pd_; ++d) parent_count[d] = int(lv.two_scale[d][ijk[d]].size());
    MultiIndex k(pd_, parent_count);
    do {
      double c = 1;
      for (int d = 0; d < pd_; ++d) {
        const auto& entry = lv.two_scale[d][ijk[d]][k[d]];
        parent_ijk[d] = entry.first;
        c *= entry.second;
      }
      add_scaled(row, parent(up.flat(parent_ijk)), c);
    } while (k.next());
    return row;
  }

  /// Active elements of level l: its cells in Omega^l and not in Omega^{l+1}.
  int add_active_elements(int l, AnalysisSpace& s) {
    const Level& lv = levels_[l];
    std::vector<std::vector<int>> cells(pd_);
    for (int d = 0; d < pd_; ++d)
      for (int c = 0; c < int(lv.spans[d].size()); ++c) {
        const SpanExtraction& sp = lv.spans[d][c];
        ParameterBox line{{lv.domain.lo[d]}, {lv.domain.hi[d]}};
        if (line.contains({sp.lo}, {sp.hi})) cells[d].push_back(c);
      }
    int count = 0;
    std::vector<int> cell_count(pd_);
    for (int d = 0; d < pd_; ++d) {
      if (cells[d].empty()) return 0;
      cell_count[d] = int(cells[d].size());
    }
    MultiIndex e(pd_, cell_count);
    std::vector<double> lo(pd_), hi(pd_);
    do {
      for (int d = 0; d < pd_; ++d) {
        const SpanExtraction& sp = lv.spans[d][cells[d][e[d]]];
        lo[d] = sp.lo;
        hi[d] = sp.hi;
      }
      if (l + 1 >= int(levels_.size()) || !levels_[l + 1].domain.contains(lo, hi)) {
        s.elements.push_back(element(l, e, cells));
        ++count;
      }
    } while (e.next());
    return count;
  }

  Element element(int l, const MultiIndex& e, const std::vector<std::vector<int>>& cells) {
    const Level& lv = levels_[l];
    Element el;
    el.level = l;
    std::vector<const Eigen::MatrixXd*> C1d;
    std::vector<int> first(pd_);
    for (int d = 0; d < pd_; ++d) {
      const SpanExtraction& sp = lv.spans[d][cells[d][e[d]]];
      el.lo(d) = sp.lo;
      el.hi(d) = sp.hi;
      first[d] = sp.first_function;
      C1d.push_back(&sp.C);
    }
    const Eigen::MatrixXd tensor = tensor_extraction(C1d);  // local level-l functions x Bernstein
    // THB functions on the element: C_e = sum over local functions of their truncated rows
    std::map<int, Eigen::RowVectorXd> rows;
    std::vector<int> local_count(pd_), ijk(pd_);
    for (int d = 0; d < pd_; ++d) local_count[d] = mesh_.degrees[d] + 1;
    MultiIndex local(pd_, local_count);
    for (Eigen::Index j = 0; j < tensor.rows(); ++j, local.next()) {
      for (int d = 0; d < pd_; ++d) ijk[d] = first[d] + local[d];
      for (const auto& [thb, c] : truncated(l, lv.flat(ijk))) {
        auto [it, fresh] = rows.try_emplace(thb, Eigen::RowVectorXd::Zero(tensor.cols()));
        it->second += c * tensor.row(j);
      }
    }
    el.C.resize(Eigen::Index(rows.size()), tensor.cols());
    Eigen::Index r = 0;
    for (const auto& [thb, row] : rows) {
      el.functions.push_back(thb);
      el.C.row(r++) = row;
    }
    return el;
  }

  /// Weights, control points and the prolongation from the patch's coefficients: a THB
  /// function of level l takes the level-l coefficient of the patch's homogeneous field
  /// (THB preserves coefficients), then R = w N / W with W the patch's weight function.
  void rational_coefficients(AnalysisSpace& s, Eigen::SparseMatrix<double>& prolongation) {
    const int n = int(s.function_level.size()), cols = patch_.phys_dim();
    s.weights.resize(n);
    s.control_points.resize(n, cols);
    std::vector<Eigen::Triplet<double>> t;
    for (int l = 0; l < int(levels_.size()); ++l) {
      for (const auto& [f, thb] : levels_[l].active) {  // on_patch fills only the on_patch memos
        const SparseRow& row = on_patch(l, f);
        double w = 0;
        Eigen::RowVectorXd wx = Eigen::RowVectorXd::Zero(cols);
        for (const auto& [i, c] : row) {
          w += c * patch_.weights(i);
          wx += c * patch_.weights(i) * patch_.points.row(i);
        }
        s.weights(thb) = w;
        s.control_points.row(thb) = wx / w;
        for (const auto& [i, c] : row) t.emplace_back(thb, i, c * patch_.weights(i) / w);
      }
    }
    prolongation.resize(n, patch_.count());
    prolongation.setFromTriplets(t.begin(), t.end());
  }

  const NurbsPatch& patch_;
  const HierarchicalMesh& mesh_;
  const int pd_;
  std::vector<Level> levels_;
};

}  // namespace

HierarchicalSpace hierarchical_space(const NurbsPatch& patch, const HierarchicalMesh& mesh) {
  return Builder(patch, mesh).build();
}

}  // namespace isosid::prep
