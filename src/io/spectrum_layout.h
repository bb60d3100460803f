// SPDX-License-Identifier: GPL-3.0-or-later
// Where spectrum.png draws the power spectrum (internal; tests read the powers back from
// it): each frequency (kx, ky) a zoom x zoom block, kx growing to the right and ky
// upward, the block of (-(K-1), K-1) at (left, top).
#pragma once

#include "disktune/spectrum.h"

namespace disktune::detail {

struct SpectrumLayout {
  int left = 80, top = 40, zoom = 1;
};

inline SpectrumLayout spectrum_layout(const Spectrum& s) {
  SpectrumLayout out;
  out.zoom = (512 + s.side() - 1) / s.side();  // at least 512 pixels: small windows in blocks
  return out;
}

}  // namespace disktune::detail
