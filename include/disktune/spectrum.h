// SPDX-License-Identifier: GPL-3.0-or-later
// The blue-noise spectrum of a packing in its periodic box: the periodogram of the
// centers at the box's integer frequencies (exact for a periodic set, no window), its
// radial mean and anisotropy, as the point-set analysis tool PSA (Schloemer, Heck)
// reports them. Definitions in docs/quality.md.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "disktune/packing.h"

namespace disktune {

/// The largest window K: (2K - 1)^2 powers, about half a gigabyte at this size.
inline constexpr int kMaxSpectrumWindow = 4096;

struct SpectrumOptions {
  /// The window |kx|, |ky| < K, 2 <= K <= kMaxSpectrumWindow. 0 chooses K so that the
  /// window reaches normalised frequency 3 along both axes, capped by `max_cost`.
  int window = 0;
  /// Largest automatic cost N * K * (2K - 1) (complex multiply-adds; ~1e9 take about
  /// a second on one core). An explicit `window` is not capped.
  double max_cost = 1e10;
  /// Threads that share the frequency rows; 0: one per core.
  unsigned threads = 0;
};

struct Spectrum {
  int window = 0;                // K: kx, ky in (-K, K)
  std::size_t count = 0;         // N points
  double width = 0, height = 0;  // the periodic box
  /// Normalised frequency of |k| = 1 (physical, cycles per unit length): 2 sqrt(W H / N),
  /// so 1.0 is sqrt(N / (W H)) / 2, the Nyquist frequency of a grid of N points (PSA).
  double frequency_unit = 0;
  /// P(k) = |sum_j exp(-2 pi i (kx x_j / W + ky y_j / H))|^2 / N, row-major over
  /// ky = -(K-1) .. K-1 (rows), kx = -(K-1) .. K-1; the DC term P(0) = N is set to 0.
  std::vector<double> power;
  std::vector<std::array<double, 2>> radial_mean;    // [normalised frequency, mean P]
  std::vector<std::array<double, 2>> anisotropy_db;  // [frequency, 10 log10(var / mean^2)]
  double peak_power = 0;                             // largest P(k), k != 0
  double peak_frequency = 0;                         // normalised |k| of that peak
  /// The lower edge of the first radial bin whose mean reaches 0.1 (the end of the
  /// low-power region), normalised; the end of the window if none does.
  double effective_nyquist = 0;

  int side() const { return 2 * window - 1; }
  /// The normalised frequency up to which whole rings fit in the window.
  double reach() const { return (window - 1) / std::max(width, height) * frequency_unit; }
  double at(int kx, int ky) const {
    return power[static_cast<std::size_t>(ky + window - 1) * side() + (kx + window - 1)];
  }
};

/// The window K that SpectrumOptions{} chooses for n points in a W x H box.
int default_spectrum_window(std::size_t n, double width, double height, double max_cost = 1e10);

/// The spectrum of the live centers of `packing` (its frame must be periodic). Throws
/// InvalidInput when the packing is empty, the frame is not periodic or the window is
/// below 2. Rows of frequencies are shared among the hardware threads; the result does
/// not depend on their number.
Spectrum measure_spectrum(const Packing& packing, const SpectrumOptions& options = {});

}  // namespace disktune
