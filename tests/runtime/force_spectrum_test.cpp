// The force spectrum against closed forms: a triangular pulse (height H, half-width tau) is
// piecewise linear, so its transform is integrated exactly: |F(nu)| = H tau sinc^2(nu tau)
// with sinc(x) = sin(pi x) / (pi x), also when extra (event) samples make the sampling uneven;
// |F(0)| is the impulse H tau.
#include "output/force_spectrum.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace isosid;

namespace {
double triangle(double t, double t0, double tau, double H) { return std::max(0.0, H * (1 - std::abs(t - t0) / tau)); }
double sinc(double x) { return x == 0 ? 1.0 : std::sin(M_PI * x) / (M_PI * x); }
}  // namespace

TEST_CASE("force spectrum: a triangular pulse's transform, exactly, on even and uneven samples", "[runtime][spectrum]") {
  const double H = 50, tau = 40e-6, t0 = 60e-6, dt = 0.5e-6;
  std::vector<double> t, f;
  for (int k = 0; k <= 400; ++k) {
    t.push_back(k * dt);
    if (k == 57) t.back() += 0.17 * dt, t.push_back(k * dt + 0.41 * dt);  // samples off the grid on the rising flank, as contact events add
  }
  std::sort(t.begin(), t.end());
  for (double x : t) f.push_back(triangle(x, t0, tau, H));
  // the triangle's kinks at t0 - tau, t0, t0 + tau fall on samples (multiples of dt)
  const run::Spectrum s = run::force_spectrum(t, f, dt);
  REQUIRE(s.frequency_hz.size() > 100);
  CHECK(s.frequency_hz(0) == 0);
  CHECK(s.frequency_hz(s.frequency_hz.size() - 1) <= 0.5 / dt * (1 + 1e-12));  // up to the Nyquist frequency
  for (Eigen::Index k = 0; k < s.frequency_hz.size(); ++k) {
    const double expected = H * tau * std::pow(sinc(s.frequency_hz(k) * tau), 2);
    INFO("nu = " << s.frequency_hz(k) << " Hz");
    // exact up to round-off of the sums (about 400 terms of size H dt): 1e-12 of the impulse
    CHECK(std::abs(s.amplitude_ns(k) - expected) < 1e-12 * H * tau);
  }
}

TEST_CASE("force spectrum: two pulses apart add with the phase of their distance", "[runtime][spectrum]") {
  // two equal triangles delta apart, free flight between and around them (the sums run over
  // the loaded segments only, and take the phase afresh after each gap): |F(nu)| =
  // H tau sinc^2(nu tau) |1 + exp(-2 pi i nu delta)| = 2 H tau sinc^2(nu tau) |cos(pi nu delta)|
  const double H = 50, tau = 40e-6, t0 = 60e-6, delta = 1.3e-3, dt = 0.5e-6;
  std::vector<double> t, f;
  for (int k = 0; k <= 3000; ++k) {
    t.push_back(k * dt);
    f.push_back(triangle(t.back(), t0, tau, H) + triangle(t.back(), t0 + delta, tau, H));
  }
  const run::Spectrum s = run::force_spectrum(t, f, dt);
  REQUIRE(s.frequency_hz.size() > 100);
  for (Eigen::Index k = 0; k < s.frequency_hz.size(); ++k) {
    const double nu = s.frequency_hz(k);
    const double expected = 2 * H * tau * std::pow(sinc(nu * tau), 2) * std::abs(std::cos(M_PI * nu * delta));
    INFO("nu = " << nu << " Hz");
    CHECK(std::abs(s.amplitude_ns(k) - expected) < 1e-12 * H * tau);  // as above: round-off of the sums
  }
}

TEST_CASE("force spectrum: too few samples give none", "[runtime][spectrum]") {
  CHECK(run::force_spectrum({0.0}, {1.0}, 1e-6).frequency_hz.size() == 0);
  CHECK(run::force_spectrum({}, {}, 1e-6).frequency_hz.size() == 0);
}
