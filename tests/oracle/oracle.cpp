// SPDX-License-Identifier: GPL-3.0-or-later
//
// Why the maximality check is exact (up to tol).
//
// Let U be the union of the N > 0 closed disks (all periodic images) on the torus T;
// disk i has radius r_i. A "corner" is an intersection point of two distinct circles
// (two disks, or a disk and another image of itself), a tangent point included, from
// outside or inside; a circle is "isolated" if it meets no other circle.
//
// (a) If U != T, take an uncovered point and its component V of T \ U. V is open and
//     V != T, so some circle C_i touches V. If C_i is isolated, step 3 reports it:
//     no other disk can contain its points next to V. Otherwise follow C_i along the
//     boundary of V: the boundary arc ends where C_i enters another disk j, i.e. at a
//     corner p of C_i and C_j (if C_j only touches C_i, p is the tangent point; if
//     disk i lies inside disk j, C_i touches V only at such a point). p is in the
//     closure of V, so p lies in the open interior of no other disk, and step 2
//     reports it unless a third circle passes exactly through p (the degenerate case
//     below).
// (b) If U == T, every corner p of C_i and C_j lies in a third closed disk: points
//     just outside both disks near p exist (two circles through p never leave p
//     without an outside wedge or cusp), they are covered by the finitely many other
//     closed disks, so one of them contains p. An isolated circle is covered only by
//     a disk that contains all of it (a disk covering points arbitrarily close to the
//     circle without meeting it contains it): step 3 looks for one at one point.
//
// So "N > 0, every isolated circle in another disk, every corner within a third disk"
// is equivalent to "covered", except when a void corner lies exactly on a third
// circle (within tol): a measure-zero coincidence that would have to happen at every
// corner of a void. Step 2b probes beside every corner for exactly that case; the
// random probes (step 4) are an independent backstop for it and for bugs here.
//
// Tolerance: a point is covered when a center i is within r_i*(1+tol), so voids whose
// corners are all within about r*tol of a third disk are accepted. Disks whose centers
// and radii agree within r*tol count as one disk (coincident circles have no corners,
// and a duplicate must not "cover" the corners of its twin).
//
// One radius r is the case r_i = r: the same code, with the same arithmetic.
//
// Neighbours are found either by looking at every center and every periodic image
// that can be in range (obviously correct) or by a bin grid (fast), sized by the
// largest radius. Both produce the same images with bit-identical coordinates;
// oracle_test.cpp checks they agree.

#include "oracle/oracle.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

namespace oracle {
namespace {

constexpr std::size_t kKeep = 100;           // entries kept in the report lists
constexpr std::size_t kAllPairsMaxN = 256;  // Method::automatic uses all pairs up to here

// Periodic image (a, b) of center j, at (x, y) = center_j + (a*width, b*height).
struct Image {
  std::size_t j;
  long long a, b;
  double x, y;
};

long long floor_div(long long u, long long n) {
  if (u >= 0 && u < n) return 0;  // the common case, without a (slow) division
  return u >= 0 ? u / n : -((-u + n - 1) / n);
}

double wrap(double v, double period) {
  v -= period * std::floor(v / period);
  if (v < 0) v += period;          // rounding can leave v just outside [0, period)
  return v < period ? v : 0.0;
}

// Finds every periodic image of every center within distance R of a point that may lie
// anywhere in the plane. Centers must be wrapped into the box.
class Images {
 public:
  Images(const Box& box, const Points& c, double cell_side, bool use_grid)
      : w_(box.width), h_(box.height), grid_(use_grid) {
    for (const auto& p : c) {
      x_.push_back(p[0]);
      y_.push_back(p[1]);
    }
    if (!grid_) return;
    // Cells at least cell_side wide, but not (many) more cells than centers.
    const double side = std::max(cell_side, std::sqrt(w_ * h_ / (2.0 * c.size())));
    nx_ = static_cast<long long>(std::clamp(std::floor(w_ / side), 1.0, 1e6));
    ny_ = static_cast<long long>(std::clamp(std::floor(h_ / side), 1.0, 1e6));
    cw_ = w_ / nx_;
    ch_ = h_ / ny_;
    // Counting sort of the centers by cell.
    std::vector<std::size_t> cell(c.size());
    start_.assign(nx_ * ny_ + 1, 0);
    for (std::size_t k = 0; k < c.size(); ++k) {
      const long long cx = std::min(nx_ - 1, static_cast<long long>(x_[k] / cw_));
      const long long cy = std::min(ny_ - 1, static_cast<long long>(y_[k] / ch_));
      cell[k] = cy * nx_ + cx;
      ++start_[cell[k] + 1];
    }
    for (std::size_t q = 1; q < start_.size(); ++q) start_[q] += start_[q - 1];
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    id_.resize(c.size());
    for (std::size_t k = 0; k < c.size(); ++k) id_[fill[cell[k]]++] = k;
    for (std::size_t k : id_) {  // coordinates in cell order, for cache locality
      cx_.push_back(x_[k]);
      cy_.push_back(y_[k]);
    }
  }

  // All center indices, in grid cell order when there is a grid: visiting centers in
  // that order keeps the memory accesses of neighbouring queries close together.
  std::vector<std::size_t> order() const {
    if (grid_) return id_;
    std::vector<std::size_t> all(x_.size());
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
    return all;
  }

  // Calls f(image) for each image within R of (px, py); stops and returns true as soon
  // as f returns true.
  template <class F>
  bool visit(double px, double py, double R, F&& f) const {
    return grid_ ? visit_grid(px, py, R, f) : visit_all(px, py, R, f);
  }

 private:
  // The single place where an image is made and tested, for both methods.
  // (xj, yj) is center j, read from x_/y_ or from the grid's cell-ordered copy.
  template <class F>
  bool consider(double px, double py, double R, std::size_t j, double xj, double yj,
                long long a, long long b, F& f) const {
    const Image im{j, a, b, xj + a * w_, yj + b * h_};
    const double dx = im.x - px, dy = im.y - py;
    return dx * dx + dy * dy <= R * R && f(im);
  }

  // With 0 <= x_j < w, x_j + a*w is within R of px only if (px-R)/w - 1 < a <= (px+R)/w;
  // one extra offset on each side guards against rounding.
  template <class F>
  bool visit_all(double px, double py, double R, F& f) const {
    const auto a0 = static_cast<long long>(std::floor((px - R) / w_)) - 1;
    const auto a1 = static_cast<long long>(std::floor((px + R) / w_)) + 1;
    const auto b0 = static_cast<long long>(std::floor((py - R) / h_)) - 1;
    const auto b1 = static_cast<long long>(std::floor((py + R) / h_)) + 1;
    for (std::size_t j = 0; j < x_.size(); ++j)
      for (long long a = a0; a <= a1; ++a) {
        if (std::fabs(x_[j] + a * w_ - px) > R * (1 + 1e-9)) continue;  // cheap, conservative
        for (long long b = b0; b <= b1; ++b)
          if (consider(px, py, R, j, x_[j], y_[j], a, b, f)) return true;
      }
    return false;
  }

  // Unwrapped column u covers x in [u*cw, (u+1)*cw): it is column u mod nx shifted by
  // floor(u/nx) periods. Columns cu-K..cu+K with K*cw > R cover [px-R, px+R], and
  // distinct u give distinct (column, shift), so every image is seen exactly once,
  // however few columns the grid has. Same for rows.
  template <class F>
  bool visit_grid(double px, double py, double R, F& f) const {
    const auto K = 1 + static_cast<long long>(std::floor(R / cw_ + 1e-6));
    const auto L = 1 + static_cast<long long>(std::floor(R / ch_ + 1e-6));
    const auto cu = static_cast<long long>(std::floor(px / cw_));
    const auto cv = static_cast<long long>(std::floor(py / ch_));
    for (long long u = cu - K; u <= cu + K; ++u) {
      const long long a = floor_div(u, nx_);
      for (long long v = cv - L; v <= cv + L; ++v) {
        const long long b = floor_div(v, ny_);
        const long long cell = (v - b * ny_) * nx_ + (u - a * nx_);
        for (std::size_t k = start_[cell]; k < start_[cell + 1]; ++k)
          if (consider(px, py, R, id_[k], cx_[k], cy_[k], a, b, f)) return true;
      }
    }
    return false;
  }

  double w_, h_;
  bool grid_;
  std::vector<double> x_, y_;
  long long nx_ = 1, ny_ = 1;
  double cw_ = 0, ch_ = 0;
  std::vector<std::size_t> start_;  // centers of cell q: id_[start_[q] .. start_[q+1])
  std::vector<std::size_t> id_;
  std::vector<double> cx_, cy_;  // x_[id_[k]], y_[id_[k]]
};

void add_pair(std::vector<Conflict>& list, std::size_t& count, std::size_t i, std::size_t j,
              double d) {
  if (list.size() < kKeep) list.push_back({i, j, d});
  ++count;
}

// why() builds the message; it is only called for kept entries (formatting is slow).
template <class Why>
void add_uncovered(Report& rep, const Box& box, double x, double y, Why why) {
  if (rep.uncovered.size() < kKeep)
    rep.uncovered.push_back({wrap(x, box.width), wrap(y, box.height), why()});
  ++rep.uncovered_count;
}

// How far (in units of the smaller radius) step 2b probes beside each corner.
constexpr double kCornerProbe = 0.01;

// A disk that built a candidate point: it does not count as covering that point.
struct Disk {
  double x, y, r;
};

Report run(const Box& box, const Points& centers, const std::vector<double>& radii, double tol,
           bool conflicts, bool maximality, std::size_t probes, std::uint64_t seed,
           Method method) {
  const double W = box.width, H = box.height;
  if (!(std::isfinite(W) && std::isfinite(H) && W > 0 && H > 0))
    throw std::invalid_argument("oracle: box sides must be finite and positive");
  if (radii.size() != centers.size())
    throw std::invalid_argument("oracle: radii must have one radius per center");
  if (!(tol >= 0 && tol < 1)) throw std::invalid_argument("oracle: tol must be in [0, 1)");
  Points c;
  for (const auto& p : centers) {
    if (!(std::isfinite(p[0]) && std::isfinite(p[1])))
      throw std::invalid_argument("oracle: centers must be finite");
    c.push_back({wrap(p[0], W), wrap(p[1], H)});
  }
  const std::size_t n = c.size();
  double r_max = 0, r_min = std::numeric_limits<double>::infinity();
  std::vector<double> reach(n);  // a point is covered if center k is within reach[k]
  for (std::size_t k = 0; k < n; ++k) {
    if (!(std::isfinite(radii[k]) && radii[k] > 0))
      throw std::invalid_argument("oracle: radii must be finite and > 0");
    r_max = std::max(r_max, radii[k]);
    r_min = std::min(r_min, radii[k]);
    reach[k] = radii[k] * (1 + tol);
  }

  Report rep;
  rep.conflicts_checked = conflicts;
  rep.maximality_checked = maximality;
  rep.n = n;
  rep.r = r_max;
  rep.r_min = n ? r_min : 0;
  rep.tol = tol;
  if (n == 0) {
    if (maximality) add_uncovered(rep, box, 0, 0, [] { return "there are no disks"; });
    return rep;
  }

  const bool grid =
      method == Method::grid || (method == Method::automatic && n > kAllPairsMaxN);
  const double reach_max = r_max * (1 + tol);
  // Coverage queries have radius reach_max: slightly larger cells keep them to 3x3 cells.
  const Images images(box, c, 1.01 * reach_max, grid);

  auto dist2 = [](double x0, double y0, double x1, double y1) {
    return (x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0);
  };
  auto dist = [&](double x0, double y0, double x1, double y1) {
    return std::sqrt(dist2(x0, y0, x1, y1));
  };
  auto covers = [&](const Image& k, double px, double py) {
    return dist2(k.x, k.y, px, py) <= reach[k.j] * reach[k.j];
  };
  auto covered = [&](double px, double py) {
    return images.visit(px, py, reach_max, [&](const Image& k) { return covers(k, px, py); });
  };
  // Is image k (a copy of) generator g: center and radius within g.r*tol?
  auto is_same = [&](const Image& k, const Disk& g) {
    const double same = g.r * tol;
    return dist2(k.x, k.y, g.x, g.y) <= same * same && std::fabs(radii[k.j] - g.r) <= same;
  };
  // Is (px, py) within reach of a disk other than the given one or two (generator) disks?
  auto covered_by_other = [&](double px, double py, const Disk& g0, const Disk& g1) {
    return images.visit(px, py, reach_max, [&](const Image& k) {
      return covers(k, px, py) && !is_same(k, g0) && !is_same(k, g1);
    });
  };

  // Steps 2 (corners) and conflicts: every pair of disks, and every disk with its own
  // images, at every periodic offset that brings them within r_i + r_j.
  std::vector<char> meets(n, 0);  // does circle i meet another circle?
  for (std::size_t i : images.order()) {
    const double xi = c[i][0], yi = c[i][1], ri = radii[i];
    images.visit(xi, yi, ri + r_max, [&](const Image& im) {
      if (im.j == i && im.a == 0 && im.b == 0) return false;  // disk i itself
      const double rj = radii[im.j];
      const double d = dist(xi, yi, im.x, im.y);
      if (d > ri + rj) return false;
      const double lo = std::min(ri, rj), hi = std::max(ri, rj);
      // Coincident circles have no corners; otherwise circles at most ri + rj apart
      // meet unless one lies inside the other.
      const bool meet = !(d <= lo * tol && hi - lo <= lo * tol) && d >= hi - lo;
      if (meet) meets[i] = 1;
      // Count each pair once: j > i, or j == i with a "positive" offset (not its mirror).
      const bool once = im.j > i || (im.j == i && (im.a > 0 || (im.a == 0 && im.b > 0)));
      if (!once) return false;
      rep.min_distance = std::min(rep.min_distance, d);
      if (conflicts && d < lo * (1 - tol))
        add_pair(rep.conflicts, rep.conflict_count, i, im.j, d);
      else if (conflicts && d < hi * (1 - tol))  // allowed: only the larger covers
        add_pair(rep.covered_centers, rep.covered_center_count, i, im.j, d);
      if (!maximality || !meet) return false;
      // Intersection points c_i + a*u -+ h*u_perp (u the unit vector to the other
      // center). h^2 in factored form: accurate near tangency, and exactly 0 for
      // circles exactly tangent (from outside or inside), which meet at one point.
      const double ux = (im.x - xi) / d, uy = (im.y - yi) / d;
      const double a = (ri * ri - rj * rj + d * d) / (2 * d);
      const double h2 = (ri + rj - d) * (d + ri - rj) * (d - ri + rj) * (d + ri + rj);
      const double h = std::sqrt(std::max(0.0, h2)) / (2 * d);
      const Disk gi{xi, yi, ri}, gj{im.x, im.y, rj};
      for (const double side : {-1.0, 1.0}) {
        const double px = xi + a * ux - side * h * uy, py = yi + a * uy + side * h * ux;
        if (!covered_by_other(px, py, gi, gj)) {
          add_uncovered(rep, box, px, py, [&] {
            std::ostringstream why;
            why << "corner of disks " << i << " and " << im.j << " (image offset " << im.a
                << "," << im.b << ") is not covered by a third disk";
            return why.str();
          });
          if (h == 0) break;
          continue;
        }
        // Step 2b: beside a covered corner, a probe a little way into the region
        // outside both circles, along the sum of the two outward normals (both
        // tangent directions when circles touch from outside, where the normals
        // cancel). Sound like any probe, and it sees the void that a corner lying
        // exactly on a third circle hides (the degenerate case above), e.g. the cusp
        // beside two tangent circles.
        const double wx = (px - xi) / ri + (px - im.x) / rj, wy = (py - yi) / ri + (py - im.y) / rj;
        const double wl = std::hypot(wx, wy);
        for (const double sign : {1.0, -1.0}) {
          const double dx = wl > 1e-9 ? wx / wl : sign * uy, dy = wl > 1e-9 ? wy / wl : -sign * ux;
          const double qx = px + kCornerProbe * lo * dx, qy = py + kCornerProbe * lo * dy;
          if (!covered(qx, qy))
            add_uncovered(rep, box, qx, qy, [&] {
              std::ostringstream why;
              why << "probe beside the corner of disks " << i << " and " << im.j
                  << " is covered by no disk";
              return why.str();
            });
          if (wl > 1e-9) break;
        }
        if (h == 0) break;
      }
      return false;
    });
  }
  if (!maximality) return rep;

  // Step 3: a circle that meets no other circle borders a void, unless it lies inside
  // another disk (which then covers all of it, so one point is enough to look at).
  for (std::size_t i = 0; i < n; ++i) {
    if (meets[i]) continue;
    const double xi = c[i][0], yi = c[i][1], ri = radii[i];
    if (!covered_by_other(xi + ri, yi, {xi, yi, ri}, {xi, yi, ri}))
      add_uncovered(rep, box, xi + ri, yi, [&] {
        return "circle of disk " + std::to_string(i) + " meets no other circle";
      });
  }

  // Step 4: random probes, an independent backstop.
  std::mt19937_64 rng(seed);
  auto unit = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };  // [0,1)
  for (std::size_t p = 0; p < probes; ++p) {
    const double px = W * unit(), py = H * unit();
    double nearest = std::numeric_limits<double>::infinity();
    bool hit = false;
    images.visit(px, py, 2 * r_max, [&](const Image& k) {
      const double dk = dist(px, py, k.x, k.y);
      nearest = std::min(nearest, dk);
      hit = hit || dk <= reach[k.j];
      return false;
    });
    rep.max_probe_gap = std::max(rep.max_probe_gap, nearest);
    if (!hit)
      add_uncovered(rep, box, px, py, [&] {
        std::ostringstream why;
        why << "probe: nearest center at distance " << nearest;
        return why.str();
      });
  }
  return rep;
}

// One radius: validated here (also when there are no centers), echoed as given.
Report run_uniform(const Box& box, double r, const Points& centers, double tol, bool conflicts,
                   bool maximality, std::size_t probes, std::uint64_t seed, Method method) {
  if (!(std::isfinite(r) && r > 0)) throw std::invalid_argument("oracle: r must be > 0");
  Report rep = run(box, centers, std::vector<double>(centers.size(), r), tol, conflicts,
                   maximality, probes, seed, method);
  rep.r = rep.r_min = r;
  return rep;
}

}  // namespace

std::string Report::summary() const {
  std::ostringstream s;
  s.precision(10);
  s << "oracle: N=" << n;
  if (r_min == r)
    s << ", r=" << r;
  else
    s << ", radii in [" << r_min << ", " << r << "]";
  s << ", tol=" << tol << ". ";
  if (conflicts_checked) {
    s << "Conflicts: " << conflict_count;
    for (std::size_t k = 0; k < conflicts.size() && k < 5; ++k)
      s << (k ? "; " : " (") << "disks " << conflicts[k].i << " and " << conflicts[k].j
        << " at distance " << conflicts[k].distance;
    s << (conflicts.empty() ? "" : conflict_count > 5 ? "; ...)" : ")") << ". ";
    if (covered_center_count > 0)
      s << "Centers covered by a larger disk (allowed): " << covered_center_count << ". ";
  } else {
    s << "Conflicts: not checked. ";
  }
  s << "Min center distance: " << min_distance << ". ";
  if (maximality_checked) {
    s << "Maximal: " << (uncovered_count == 0 ? "yes" : "no") << ", " << uncovered_count
      << " uncovered witnesses";
    for (std::size_t k = 0; k < uncovered.size() && k < 5; ++k)
      s << (k ? "; " : " (") << "(" << uncovered[k].x << ", " << uncovered[k].y
        << "): " << uncovered[k].why;
    s << (uncovered.empty() ? "" : uncovered_count > 5 ? "; ...)" : ")")
      << ". Max probe gap: " << max_probe_gap << ".";
  } else {
    s << "Maximality: not checked.";
  }
  return s.str();
}

Report check_conflicts(const Box& box, double r, const Points& centers, double tol,
                       Method method) {
  return run_uniform(box, r, centers, tol, true, false, 0, 0, method);
}

Report check_maximal(const Box& box, double r, const Points& centers, double tol,
                     std::size_t probes, std::uint64_t seed, Method method) {
  return run_uniform(box, r, centers, tol, false, true, probes, seed, method);
}

Report check_all(const Box& box, double r, const Points& centers, double tol,
                 std::size_t probes, std::uint64_t seed, Method method) {
  return run_uniform(box, r, centers, tol, true, true, probes, seed, method);
}

Report check_conflicts(const Box& box, const std::vector<double>& radii, const Points& centers,
                       double tol, Method method) {
  return run(box, centers, radii, tol, true, false, 0, 0, method);
}

Report check_maximal(const Box& box, const std::vector<double>& radii, const Points& centers,
                     double tol, std::size_t probes, std::uint64_t seed, Method method) {
  return run(box, centers, radii, tol, false, true, probes, seed, method);
}

Report check_all(const Box& box, const std::vector<double>& radii, const Points& centers,
                 double tol, std::size_t probes, std::uint64_t seed, Method method) {
  return run(box, centers, radii, tol, true, true, probes, seed, method);
}

void summary_list(std::ostringstream& s, const char* title, bool checked, std::size_t count, std::size_t kept,
                  const std::function<void(std::size_t)>& item) {
  s << title << ": ";
  if (!checked) {
    s << "not checked. ";
    return;
  }
  s << count;
  for (std::size_t k = 0; k < kept && k < 5; ++k) {
    s << (k ? "; " : " (");
    item(k);
  }
  s << (kept == 0 ? "" : count > 5 ? "; ...)" : ")") << ". ";
}

}  // namespace oracle
