// A multi-index running over a tensor lattice with the first direction fastest: the one
// odometer behind loops over Gauss points, tensor Bernstein products and lattice boxes.
#pragma once
#include <array>
#include <cassert>

namespace isosid::prep {

class MultiIndex {
public:
  /// The lattice extents[0] x ... x extents[dims-1] (at most three directions), starting at 0.
  template <class Extents>
  MultiIndex(int dims, const Extents& extents) : dims_(dims) {
    assert(dims >= 0 && dims <= 3);
    for (int d = 0; d < dims; ++d) extent_[d] = int(extents[d]);
  }

  int operator[](int d) const { return index_[d]; }
  /// Steps to the next index; false (and back at the start) after the last one.
  bool next() {
    for (int d = 0; d < dims_; ++d) {
      if (++index_[d] < extent_[d]) return true;
      index_[d] = 0;
    }
    return false;
  }

private:
  int dims_;
  std::array<int, 3> extent_{1, 1, 1};
  std::array<int, 3> index_{0, 0, 0};
};

}  // namespace isosid::prep
