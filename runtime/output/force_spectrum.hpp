// The Fourier spectrum of a contact force pulse ([R3] in docs/references.md reports it next to the
// pulse): the magnitude |F(nu)| = |int f(t) exp(-2 pi i nu t) dt| of the force sampled at the
// output times (uneven where contact events add samples), integrated exactly for the
// piecewise-linear force through the samples, at nu = 0, 1/(4T), 2/(4T), ... up to the Nyquist
// frequency of the output interval (T: the sampled span). |F(0)| is the impulse.
#pragma once
#include <Eigen/Dense>
#include <vector>

namespace isosid::run {

struct Spectrum {
  Eigen::VectorXd frequency_hz;
  Eigen::VectorXd amplitude_ns;  ///< N s
};

/// At most `max_frequencies` frequencies (the grid coarsens beyond); empty below two samples.
Spectrum force_spectrum(const std::vector<double>& t, const std::vector<double>& force, double output_interval,
                        int max_frequencies = 4096);

}  // namespace isosid::run
