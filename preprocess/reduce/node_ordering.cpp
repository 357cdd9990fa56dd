// Fill-reducing ordering on the supervariable graph; see node_ordering.hpp.
#include "reduce/node_ordering.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace isosid::prep {
namespace {

using Eigen::Index;

/// The full symmetric pattern of A (from its lower triangle, diagonal included) as sorted
/// adjacency lists in compressed form.
struct Pattern {
  std::vector<std::int64_t> start;  // column c's rows are rows[start[c] .. start[c + 1])
  std::vector<int> rows;
};

Pattern symmetric_pattern(const Eigen::SparseMatrix<double>& A) {
  const Index n = A.cols();
  Pattern p;
  p.start.assign(std::size_t(n) + 1, 0);
  for (Index c = 0; c < n; ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it) {
      if (it.row() < c) continue;
      ++p.start[std::size_t(c) + 1];
      if (it.row() > c) ++p.start[std::size_t(it.row()) + 1];
    }
  std::partial_sum(p.start.begin(), p.start.end(), p.start.begin());
  p.rows.resize(std::size_t(p.start.back()));
  std::vector<std::int64_t> next(p.start.begin(), p.start.end() - 1);
  // columns in ascending order: each list receives the earlier columns, then its own rows, both ascending
  for (Index c = 0; c < n; ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it) {
      if (it.row() < c) continue;
      p.rows[std::size_t(next[std::size_t(c)]++)] = int(it.row());
      if (it.row() > c) p.rows[std::size_t(next[std::size_t(it.row())]++)] = int(c);
    }
  return p;
}

/// Columns grouped by equal patterns: group[c] for each column, groups numbered by their first column.
std::vector<int> supervariables(const Pattern& p, int& groups) {
  const std::size_t n = p.start.size() - 1;
  std::vector<std::uint64_t> hash(n);
  for (std::size_t c = 0; c < n; ++c) {
    // a sum of mixed row numbers: the same for the same set, rarely for two sets of equal sums
    std::uint64_t h = std::uint64_t(p.start[c + 1] - p.start[c]);
    for (std::int64_t k = p.start[c]; k < p.start[c + 1]; ++k) {
      std::uint64_t z = std::uint64_t(p.rows[std::size_t(k)]) + 0x9E3779B97F4A7C15ull;  // splitmix64's finalizer
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
      h += z ^ (z >> 31);
    }
    hash[c] = h;
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return hash[std::size_t(a)] < hash[std::size_t(b)]; });
  const auto same_pattern = [&](int a, int b) {
    return std::equal(p.rows.begin() + p.start[std::size_t(a)], p.rows.begin() + p.start[std::size_t(a) + 1],
                      p.rows.begin() + p.start[std::size_t(b)], p.rows.begin() + p.start[std::size_t(b) + 1]);
  };
  std::vector<int> first(n, -1);  // each column's group leader: the first column of its pattern
  for (std::size_t i = 0; i < n;) {
    std::size_t end = i + 1;
    while (end < n && hash[std::size_t(order[end])] == hash[std::size_t(order[i])]) ++end;
    // within one hash, columns ascending; each joins the first earlier one with its pattern
    for (std::size_t a = i; a < end; ++a) {
      const int c = order[a];
      if (first[std::size_t(c)] >= 0) continue;
      first[std::size_t(c)] = c;
      for (std::size_t b = a + 1; b < end; ++b)
        if (first[std::size_t(order[b])] < 0 && same_pattern(c, order[b])) first[std::size_t(order[b])] = c;
    }
    i = end;
  }
  std::vector<int> group(n);
  groups = 0;
  std::vector<int> id(n, -1);
  for (std::size_t c = 0; c < n; ++c) {
    const std::size_t leader = std::size_t(first[c]);
    if (id[leader] < 0) id[leader] = groups++;
    group[c] = id[leader];
  }
  return group;
}

}  // namespace

Eigen::Index supervariable_count(const Eigen::SparseMatrix<double>& A) {
  int groups = 0;
  supervariables(symmetric_pattern(A), groups);
  return groups;
}

std::vector<int> node_graph_ordering(const Eigen::SparseMatrix<double>& A, cholmod_common& common) {
  std::vector<std::vector<int>> members;  // each group's columns, ascending
  cholmod_sparse* graph = nullptr;
  {
    const Pattern p = symmetric_pattern(A);
    int groups = 0;
    const std::vector<int> group = supervariables(p, groups);
    members.resize(std::size_t(groups));
    for (std::size_t c = 0; c < group.size(); ++c) members[std::size_t(group[c])].push_back(int(c));
    // the groups' graph, lower triangle (CHOLMOD reads stype -1 as symmetric)
    std::vector<std::int64_t> start(std::size_t(groups) + 1, 0);
    std::vector<int> rows, seen(std::size_t(groups), -1);
    for (int g = 0; g < groups; ++g) {
      const int c = members[std::size_t(g)].front();  // every member has the group's pattern
      const std::size_t first = rows.size();
      for (std::int64_t k = p.start[std::size_t(c)]; k < p.start[std::size_t(c) + 1]; ++k) {
        const int h = group[std::size_t(p.rows[std::size_t(k)])];
        if (h >= g && seen[std::size_t(h)] != g) {
          seen[std::size_t(h)] = g;
          rows.push_back(h);
        }
      }
      std::sort(rows.begin() + std::int64_t(first), rows.end());
      start[std::size_t(g) + 1] = std::int64_t(rows.size());
    }
    graph = cholmod_allocate_sparse(std::size_t(groups), std::size_t(groups), rows.size(), 1, 1, -1, CHOLMOD_PATTERN, &common);
    if (!graph) return {};
    int* gp = static_cast<int*>(graph->p);
    for (std::size_t g = 0; g < start.size(); ++g) gp[g] = int(start[g]);
    std::copy(rows.begin(), rows.end(), static_cast<int*>(graph->i));
  }
  // the default choice between AMD and METIS, on the groups' graph
  const int methods = common.nmethods;
  common.nmethods = 0;
  cholmod_factor* symbolic = cholmod_analyze(graph, &common);
  common.nmethods = methods;
  cholmod_free_sparse(&graph, &common);
  if (!symbolic) return {};
  std::vector<int> perm;
  perm.reserve(std::size_t(A.cols()));
  const int* order = static_cast<const int*>(symbolic->Perm);
  for (std::size_t k = 0; k < members.size(); ++k) {
    const auto& m = members[std::size_t(order[k])];
    perm.insert(perm.end(), m.begin(), m.end());
  }
  cholmod_free_factor(&symbolic, &common);
  return perm;
}

}  // namespace isosid::prep
