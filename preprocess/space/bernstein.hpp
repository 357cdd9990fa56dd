// Bernstein polynomials on [0, 1] and their first derivatives: the reference basis every
// element's extraction operator maps from.
#pragma once

namespace isosid::prep {

/// values[b] = B_{b,p}(t), derivatives[b] = dB_{b,p}/dt for b = 0..p (both p+1 long).
void bernstein(int p, double t, double* values, double* derivatives);

}  // namespace isosid::prep
