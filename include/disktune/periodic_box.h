// SPDX-License-Identifier: GPL-3.0-or-later
// The periodic box [0,W) x [0,H): a flat torus, the domain of the paper's section 5.
#pragma once

#include "disktune/errors.h"
#include "disktune/frame.h"
#include "disktune/geometry.h"
#include "disktune/random.h"

namespace disktune {

class PeriodicBox {
 public:
  /// Throws InvalidInput unless both sides are finite and positive.
  explicit PeriodicBox(double width = 1.0, double height = 1.0);

  double width() const { return frame_.extent.x; }
  double height() const { return frame_.extent.y; }
  double area() const { return width() * height(); }
  const Frame& frame() const { return frame_; }

  /// The canonical representative of `p` in [0,W) x [0,H).
  Vec2 wrap(Vec2 p) const { return frame_.wrap(p); }
  /// A point uniformly distributed over the box.
  Vec2 random_point(Rng& rng) const;

  /// Throws InvalidInput unless `r` is finite, positive and small enough that a disk
  /// does not meet its own periodic image (2r < min(W, H)).
  void validate_radius(double r) const;

 private:
  Frame frame_;
};

}  // namespace disktune
