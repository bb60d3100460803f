// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/spectrum.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "../geometry/threads.h"
#include "disktune/errors.h"

// Not under ThreadSanitizer: the clones' resolver runs while the program is being loaded,
// before the sanitizer's runtime, and its instrumented code crashes there.
#if defined(__GNUC__) && defined(__x86_64__) && defined(__linux__) && !defined(__SANITIZE_THREAD__)
#define DISKTUNE_SIMD_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define DISKTUNE_SIMD_CLONES
#endif

namespace disktune {
namespace {

constexpr double kTwoPi = 6.283185307179586476925;
constexpr double kNormalisedReach = 3;  // the automatic window's reach (normalised)
constexpr double kZeroRegionPower = 0.1;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::size_t kBlock = 256;  // points per block: eight arrays of it stay in L1
constexpr std::size_t kLanes = 8;    // independent partial sums, so the compiler vectorises

/// exp(-2 pi i t), with t reduced to [-0.5, 0.5] first so large k stay accurate.
inline void unit_phase(double t, double& re, double& im) {
  const double a = kTwoPi * (t - std::round(t));
  re = std::cos(a);
  im = -std::sin(a);
}

/// The points in box units ([0, 1)), and each one's step exp(-2 pi i u) = (wr, wi).
struct Points {
  std::vector<double> u, v, wr, wi;
};

/// F(kx, ky) for kx = -(K-1) .. K-1 of one row ky, added into fr, fi (2K-1 each). Each
/// point's terms follow by the recurrence z(kx + 1) = z(kx) exp(-2 pi i u), restarted
/// per row, so a row costs one sin/cos pair per point and 2K - 1 complex multiplies.
/// Built for AVX2 and for any x86-64, the loader picking one (-std=c++17 keeps fused
/// multiply-adds off, so both give the same bits; AVX-512 measured no faster).
DISKTUNE_SIMD_CLONES
void transform_row(const Points& p, int K, int ky, std::vector<double>& fr,
                   std::vector<double>& fi) {
  const std::size_t n = p.u.size(), m = fr.size();
  alignas(64) double zr[kBlock], zi[kBlock], wr[kBlock], wi[kBlock];
  for (std::size_t b = 0; b < n; b += kBlock) {
    const std::size_t len = std::min(kBlock, n - b);
    const std::size_t padded = (len + kLanes - 1) / kLanes * kLanes;
    for (std::size_t j = 0; j < padded; ++j) {
      if (j < len) {
        unit_phase(ky * p.v[b + j] - (K - 1) * p.u[b + j], zr[j], zi[j]);
        wr[j] = p.wr[b + j];
        wi[j] = p.wi[b + j];
      } else {  // padding contributes nothing
        zr[j] = zi[j] = wr[j] = wi[j] = 0;
      }
    }
    for (std::size_t k = 0; k < m; ++k) {
      double sr[kLanes] = {}, si[kLanes] = {};
      for (std::size_t j = 0; j < padded; j += kLanes) {
        for (std::size_t l = 0; l < kLanes; ++l) {
          const double a = zr[j + l], c = zi[j + l];
          sr[l] += a;
          si[l] += c;
          zr[j + l] = a * wr[j + l] - c * wi[j + l];
          zi[j + l] = a * wi[j + l] + c * wr[j + l];
        }
      }
      double tr = 0, ti = 0;
      for (std::size_t l = 0; l < kLanes; ++l) tr += sr[l], ti += si[l];
      fr[k] += tr;
      fi[k] += ti;
    }
  }
}

/// Fills s.power: rows ky = 0 .. K-1 are computed (shared among threads, parallel_for;
/// each row is computed the same way whoever takes it), and rows ky < 0 mirror them, as
/// P(-k) = P(k) for real points.
void periodogram(const Points& points, Spectrum& s, unsigned cores) {
  const int K = s.window, side = s.side();
  const double n = static_cast<double>(points.u.size());
  s.power.assign(static_cast<std::size_t>(side) * side, 0.0);
  const unsigned threads = std::min(detail::thread_count(cores), 4096u);
  std::vector<std::vector<double>> re(threads, std::vector<double>(side)), im = re;
  detail::parallel_for(static_cast<std::size_t>(K), threads, [&](std::size_t row, unsigned thread) {
    const int ky = static_cast<int>(row);
    std::vector<double>& fr = re[thread];
    std::vector<double>& fi = im[thread];
    std::fill(fr.begin(), fr.end(), 0.0);
    std::fill(fi.begin(), fi.end(), 0.0);
    transform_row(points, K, ky, fr, fi);
    for (int i = 0; i < side; ++i) {
      const double p = (fr[i] * fr[i] + fi[i] * fi[i]) / n;
      s.power[static_cast<std::size_t>(ky + K - 1) * side + i] = p;
      s.power[static_cast<std::size_t>(K - 1 - ky) * side + (side - 1 - i)] = p;
    }
  });
  s.power[static_cast<std::size_t>(K - 1) * side + (K - 1)] = 0;  // DC removed
}

/// Radial mean, anisotropy, peak and effective Nyquist frequency from s.power. Rings
/// are one frequency step wide (the coarser of 1/W, 1/H), centred on its multiples;
/// only rings that lie wholly inside the window are kept.
void radial_statistics(Spectrum& s) {
  const int K = s.window;
  const double step = std::max(1 / s.width, 1 / s.height);
  const double reach = (K - 1) / std::max(s.width, s.height);
  const int bins = std::max(1, static_cast<int>(std::floor(reach / step - 0.5)) + 1);
  std::vector<double> sum(bins, 0.0), sum2(bins, 0.0);
  std::vector<std::size_t> count(bins, 0);
  for (int ky = 1 - K; ky < K; ++ky) {
    for (int kx = 1 - K; kx < K; ++kx) {
      if (kx == 0 && ky == 0) continue;
      const double f = std::hypot(kx / s.width, ky / s.height);
      const double p = s.at(kx, ky);
      s.peak_power = std::max(s.peak_power, p);
      const int b = static_cast<int>(std::lround(f / step));
      if (b >= bins) continue;
      sum[b] += p;
      sum2[b] += p * p;
      ++count[b];
    }
  }
  // The peak's frequency: the lowest where P is within rounding of the peak (a
  // lattice's peaks are all N).
  s.peak_frequency = kInf;
  for (int ky = 1 - K; ky < K; ++ky) {
    for (int kx = 1 - K; kx < K; ++kx) {
      if (s.at(kx, ky) >= s.peak_power * (1 - 1e-9) && (kx != 0 || ky != 0)) {
        s.peak_frequency = std::min(s.peak_frequency, std::hypot(kx / s.width, ky / s.height));
      }
    }
  }
  s.peak_frequency *= s.frequency_unit;
  s.effective_nyquist = -1;
  for (int b = 1; b < bins; ++b) {
    if (count[b] == 0) continue;
    const double nb = static_cast<double>(count[b]);
    const double f = b * step * s.frequency_unit, mean = sum[b] / nb;
    s.radial_mean.push_back({f, mean});
    if (s.effective_nyquist < 0 && mean >= kZeroRegionPower) {
      s.effective_nyquist = (b - 0.5) * step * s.frequency_unit;
    }
    if (count[b] < 2 || mean <= 0) continue;  // no variance, or a ring of zeros
    const double var = std::max(0.0, (sum2[b] - nb * mean * mean) / (nb - 1));
    if (var > 0) s.anisotropy_db.push_back({f, 10 * std::log10(var / (mean * mean))});
  }
  if (s.effective_nyquist < 0) s.effective_nyquist = (bins - 0.5) * step * s.frequency_unit;
}

}  // namespace

int default_spectrum_window(std::size_t n, double width, double height, double max_cost) {
  const double per_length = std::sqrt(static_cast<double>(n) / (width * height));
  int K =
      static_cast<int>(std::ceil(kNormalisedReach / 2 * per_length * std::max(width, height))) + 1;
  // The largest K with n K (2K - 1) <= max_cost.
  const double cap = (1 + std::sqrt(1 + 8 * max_cost / static_cast<double>(n))) / 4;
  return std::max(std::min(K, static_cast<int>(cap)), 2);
}

Spectrum measure_spectrum(const Packing& packing, const SpectrumOptions& options) {
  const Frame& frame = packing.frame();
  if (!frame.periodic) {
    throw InvalidInput("the spectrum needs a periodic box; this packing's frame is not periodic");
  }
  if (packing.empty()) throw InvalidInput("the spectrum of an empty packing is not defined");
  if (options.window == 1 || options.window < 0) {
    std::ostringstream msg;
    msg << "spectrum window " << options.window
        << " is too small: give 2 or more (frequencies |kx|, |ky| < K), or 0 for automatic";
    throw InvalidInput(msg.str());
  }
  if (options.window > kMaxSpectrumWindow) {
    throw InvalidInput("spectrum window " + std::to_string(options.window) + " is too large: its " +
                       std::to_string(2 * options.window - 1) + "^2 powers would not fit in memory; give at most " +
                       std::to_string(kMaxSpectrumWindow) + ", or 0 for automatic");
  }
  Spectrum s;
  s.count = packing.size();
  s.width = frame.extent.x;
  s.height = frame.extent.y;
  s.window = options.window > 0
                 ? options.window
                 : default_spectrum_window(s.count, s.width, s.height, options.max_cost);
  s.frequency_unit = 2 * std::sqrt(s.width * s.height / static_cast<double>(s.count));
  Points points;
  for (DiskId id : packing.ids()) {
    const Vec2 c = packing.center(id);
    double wr, wi;
    points.u.push_back((c.x - frame.origin.x) / s.width);
    points.v.push_back((c.y - frame.origin.y) / s.height);
    unit_phase(points.u.back(), wr, wi);
    points.wr.push_back(wr);
    points.wi.push_back(wi);
  }
  periodogram(points, s, options.threads);
  radial_statistics(s);
  return s;
}

}  // namespace disktune
