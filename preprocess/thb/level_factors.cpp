// [R2] Alg. 3 (docs/references.md); see level_factors.hpp.
#include "thb/level_factors.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace isosid::prep {

std::vector<int> prime_factors(int n) {
  std::vector<int> f;
  for (int d = 2; d * d <= n; ++d)
    while (n % d == 0) {
      f.push_back(d);
      n /= d;
    }
  if (n > 1) f.push_back(n);
  return f;
}

std::vector<int> level_factors(int wanted, const LevelLimits& limits) {
  if (wanted <= 1) return {};
  const int refined_levels = limits.max_levels - 1, largest = limits.max_knots_per_level + 1;
  if (refined_levels < 1) throw std::invalid_argument("a hierarchy needs at least two levels");
  // the largest subdivision the limits allow: every refined level splits by `largest`
  long long ceiling = 1;
  for (int l = 0; l < refined_levels; ++l) ceiling *= largest;
  if (wanted > ceiling)
    throw std::invalid_argument("a subdivision by " + std::to_string(wanted) + " needs more than " +
                                std::to_string(limits.max_levels) + " levels of at most " +
                                std::to_string(limits.max_knots_per_level) + " knots each (at most " +
                                std::to_string(ceiling) + "); refine the coarse model first");
  for (int elements = wanted;; ++elements) {  // Alg. 3 line 2-3: the next guess
    std::vector<int> f = prime_factors(elements);
    // line 5-6: merge the two leading (smallest) factors until the levels fit; [R2]'s
    // "+2" counts the coarse and the contact level, here the finest factor level is the contact level
    while (int(f.size()) > refined_levels) {
      f[1] *= f[0];
      f.erase(f.begin());
    }
    if (std::all_of(f.begin(), f.end(), [&](int x) { return x <= largest; })) return f;
  }
}

}  // namespace isosid::prep
