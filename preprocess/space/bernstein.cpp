// Bernstein basis; see bernstein.hpp.
#include "space/bernstein.hpp"

namespace isosid::prep {

namespace {
// de Casteljau-style triangle: B_{b,p} from B_{.,p-1}
void bernstein_values(int p, double t, double* B) {
  B[0] = 1.0;
  const double s = 1.0 - t;
  for (int j = 1; j <= p; ++j) {
    double saved = 0.0;
    for (int k = 0; k < j; ++k) {
      const double temp = B[k];
      B[k] = saved + s * temp;
      saved = t * temp;
    }
    B[j] = saved;
  }
}
}  // namespace

void bernstein(int p, double t, double* values, double* derivatives) {
  bernstein_values(p, t, values);
  if (p == 0) {
    derivatives[0] = 0.0;
    return;
  }
  // degree p-1 values in place, then dB_b = p (B_{b-1,p-1} - B_{b,p-1}) from the top down
  bernstein_values(p - 1, t, derivatives);
  derivatives[p] = p * derivatives[p - 1];
  for (int b = p - 1; b > 0; --b) derivatives[b] = p * (derivatives[b - 1] - derivatives[b]);
  derivatives[0] = p * (0.0 - derivatives[0]);
}

}  // namespace isosid::prep
