// How many elements each hierarchical level splits its parent element into ([R2] Alg. 3,
// docs/references.md): the total subdivision is factorised into integer factors, one per level, so
// that no level inserts more than `max_knots_per_level` knots per span and the hierarchy keeps at
// most `max_levels` levels (the coarse level included).
#pragma once
#include <vector>

namespace isosid::prep {

struct LevelLimits {
  int max_levels = 5;           ///< [R2]: n_lvl^max, coarse level included
  int max_knots_per_level = 10; ///< [R2]: n_knots^max, knots inserted per parent span
};

/// Factors (one per refined level, coarse to fine, each in 2..max_knots_per_level+1) whose
/// product is the smallest admissible subdivision >= `wanted`. Empty if wanted <= 1. Throws
/// std::invalid_argument if no subdivision that large fits the limits.
std::vector<int> level_factors(int wanted, const LevelLimits& limits);

/// Prime factors in ascending order.
std::vector<int> prime_factors(int n);

}  // namespace isosid::prep
