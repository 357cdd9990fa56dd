// Spectra of sampled forces; see force_spectrum.hpp.
#include "output/force_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace isosid::run {

Spectrum force_spectrum(const std::vector<double>& t, const std::vector<double>& force, double output_interval, int max_frequencies) {
  Spectrum s;
  const std::size_t n = std::min(t.size(), force.size());
  if (n < 2 || !(t[n - 1] > t[0]) || !(output_interval > 0)) return s;
  const double span = t[n - 1] - t[0];
  const double nyquist = 0.5 / output_interval;
  // the transform of the interpolated pulse is defined at every frequency: a quarter of the
  // record's resolution 1/T resolves the lobes of a pulse much shorter than the record
  const double step = std::max(0.25 / span, nyquist / std::max(1, max_frequencies - 1));
  const auto m = Eigen::Index(std::floor(nyquist / step)) + 1;
  s.frequency_hz = Eigen::VectorXd::LinSpaced(m, 0.0, step * double(m - 1));
  s.amplitude_ns.resize(m);
  using C = std::complex<double>;
  const C i(0.0, 1.0);
  // the segments that carry force: a run's record is mostly free flight (scene E: four impacts
  // in 10 000 samples), and every frequency sums over them alone
  std::vector<std::size_t> loaded;
  for (std::size_t j = 0; j + 1 < n; ++j)
    if (t[j + 1] > t[j] && (force[j] != 0 || force[j + 1] != 0)) loaded.push_back(j);
  for (Eigen::Index k = 0; k < m; ++k) {
    const double w = 2 * M_PI * s.frequency_hz(k);
    // exp(-i w (t_j - t_0)) by rotation from segment to segment, with one exponential per
    // distinct step (the samples are evenly spaced but for events); afresh after a gap in the
    // loaded segments, and every 256th segment as rotations drift by round-off
    C sum = 0, phase = 1, e = 1;
    double last_h = -1;
    for (std::size_t l = 0; l < loaded.size(); ++l) {
      const std::size_t j = loaded[l];
      if (l % 256 == 0 || loaded[l - 1] != j - 1) phase = std::exp(-i * w * (t[j] - t[0]));
      const double h = t[j + 1] - t[j];
      if (h != last_h) e = std::exp(-i * w * h), last_h = h;
      const double a = force[j], b = (force[j + 1] - force[j]) / h;  // f = a + b s on s in [0, h]
      const double wh = w * h;
      C segment;
      if (std::abs(wh) < 1e-4) {  // series of the closed form: no cancellation at small w h
        segment = h * (a + b * h / 2) - i * w * h * h * (a / 2 + b * h / 3);
      } else {
        // int_0^h (a + b s) exp(-i w s) ds, with 1 / (i w) = -i / w
        segment = a * (1.0 - e) * (-i / w) - b * (1.0 - e * (1.0 + i * wh)) / (w * w);
      }
      sum += phase * segment;
      phase *= e;
    }
    s.amplitude_ns(k) = std::abs(sum);
  }
  return s;
}

}  // namespace isosid::run
