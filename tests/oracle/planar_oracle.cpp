// SPDX-License-Identifier: GPL-3.0-or-later
//
// Why the 2D maximality check is exact (up to tol).
//
// Let D be the closed domain and U the union of the N closed disks. Candidates are
// (1) intersection points of two circles that lie in D, (2) intersection points of a
// circle with a boundary segment, (3) polygon vertices, (4) the leftmost point of each
// circle that meets no other circle, if it lies in D. A candidate is a witness when no
// disk other than the ones it was built from covers it.
//
// (a) If some p in D is uncovered, let V be its component of D \ U and W the closure
//     of V (W lies in D and in no open disk). Take a component of the boundary of V.
//     If it contains a polygon vertex, that is candidate (3). If it runs along a
//     segment and along a circle, where it passes from one to the other is a point of
//     both: candidate (2). If it lies on the boundary only, it is a whole loop, which
//     has vertices. If it lies on circles only, it passes from circle i to circle j at
//     candidate (1), or it is a whole circle; a whole circle that meets another one
//     only touches it (a crossing would put part of it inside the other disk), and that
//     touching point is candidate (1); otherwise the circle meets no other circle and
//     its leftmost point is candidate (4). In every case the candidate lies in W, so
//     it is in no open disk, and a disk other than its own covers it only if that
//     disk's circle passes exactly through it (within tol): the degenerate case.
// (b) If D is covered, each candidate is covered by another disk: points of D close
//     to it and outside its own disks exist (for (1) away from the boundary, (2) and
//     (3) always: a segment point has half a neighbourhood in D, and a disk through it
//     cannot cover that half alone; an isolated circle is covered only by a disk that
//     contains all of it, and otherwise ringed by uncovered points), and the finitely
//     many closed disks covering them include one that contains the candidate. A
//     circle–circle point on the boundary or within r*tol outside it could in
//     principle have its uncovered side outside D; the boundary disks cover such
//     points in practice (they are within r of the nearest boundary point, which is
//     within r*tol).
// Circle–circle points here include tangent points, from outside or inside; disk i
// has radius r_i throughout, and one radius r is the case r_i = r (same code, same
// arithmetic). As in oracle.cpp, a probe just beside each covered candidate (1), into
// the region outside both disks, catches the degenerate case of a void whose corners
// all lie exactly on third circles (e.g. the cusp between two tangent circles). The
// random probes are an independent backstop for the degenerate cases and for bugs
// here. As in oracle.cpp, disks whose centers and radii agree within r*tol count as
// one disk.
//
// 1D maximality is checked directly: on each segment, the parameter interval each
// boundary disk covers (its reach r*(1+tol) met with the segment), merged and compared
// with [0, 1].

#include "oracle/planar_oracle.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <stdexcept>

namespace oracle {
namespace {

constexpr std::size_t kKeep = 100;  // entries kept in each report list

struct Segment {
  double ax, ay, bx, by;
  std::size_t loop, index;
};

std::vector<Segment> segments_of(const Domain& d) {
  std::vector<Segment> out;
  for (std::size_t l = 0; l < d.loops.size(); ++l) {
    const auto& loop = d.loops[l];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const auto& a = loop[k];
      const auto& b = loop[(k + 1) % loop.size()];
      out.push_back({a[0], a[1], b[0], b[1], l, k});
    }
  }
  return out;
}

double segment_distance(const Segment& s, double x, double y) {
  const double dx = s.bx - s.ax, dy = s.by - s.ay;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((x - s.ax) * dx + (y - s.ay) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(s.ax + t * dx - x, s.ay + t * dy - y);
}

bool even_odd(const std::vector<Segment>& segs, double x, double y) {
  bool inside = false;
  for (const auto& s : segs) {
    if ((s.ay > y) == (s.by > y)) continue;  // does not straddle the horizontal line
    const double cx = s.ax + (y - s.ay) * (s.bx - s.ax) / (s.by - s.ay);
    if (cx > x) inside = !inside;
  }
  return inside;
}

double boundary_distance(const std::vector<Segment>& segs, double x, double y) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : segs) best = std::min(best, segment_distance(s, x, y));
  return best;
}

// Centers in square bins of side >= the requested side. visit() looks at every bin
// that the query's bounding square touches, so it sees every center within R.
class Bins {
 public:
  Bins(const Points& c, double side) : c_(c) {
    if (c.empty()) return;
    double x1 = c[0][0], y1 = c[0][1];
    x0_ = x1;
    y0_ = y1;
    for (const auto& p : c) {
      x0_ = std::min(x0_, p[0]);
      y0_ = std::min(y0_, p[1]);
      x1 = std::max(x1, p[0]);
      y1 = std::max(y1, p[1]);
    }
    const double w = x1 - x0_, h = y1 - y0_;
    const double n = static_cast<double>(c.size());
    // Not many more bins than centers: at most about 3N + 1.
    side_ = std::max({side, std::sqrt(w * h / n), std::max(w, h) / (n + 1)});
    nx_ = static_cast<long long>(std::floor(w / side_)) + 1;
    ny_ = static_cast<long long>(std::floor(h / side_)) + 1;
    bins_.resize(static_cast<std::size_t>(nx_ * ny_));
    for (std::size_t k = 0; k < c.size(); ++k)
      bins_[static_cast<std::size_t>(row(c[k][1]) * nx_ + col(c[k][0]))].push_back(k);
  }

  // Calls f(k, distance) for each center k within R of (px, py); stops and returns
  // true as soon as f returns true.
  template <class F>
  bool visit(double px, double py, double R, F&& f) const {
    if (c_.empty()) return false;
    const long long i0 = col(px - R), i1 = col(px + R);
    const long long j0 = row(py - R), j1 = row(py + R);
    for (long long j = j0; j <= j1; ++j)
      for (long long i = i0; i <= i1; ++i)
        for (std::size_t k : bins_[static_cast<std::size_t>(j * nx_ + i)]) {
          const double d = std::hypot(c_[k][0] - px, c_[k][1] - py);
          if (d <= R && f(k, d)) return true;
        }
    return false;
  }

 private:
  // Bin column of x, clamped to the grid (floor is monotone, so a center within R of
  // px has its column between col(px - R) and col(px + R)).
  long long col(double x) const {
    const double u = std::floor((x - x0_) / side_);
    return static_cast<long long>(std::clamp(u, 0.0, static_cast<double>(nx_ - 1)));
  }
  long long row(double y) const {
    const double v = std::floor((y - y0_) / side_);
    return static_cast<long long>(std::clamp(v, 0.0, static_cast<double>(ny_ - 1)));
  }

  const Points& c_;
  double x0_ = 0, y0_ = 0, side_ = 1;
  long long nx_ = 1, ny_ = 1;
  std::vector<std::vector<std::size_t>> bins_;
};

template <class T>
void keep(std::vector<T>& list, std::size_t& count, const T& entry) {
  if (list.size() < kKeep) list.push_back(entry);
  ++count;
}

// why() builds the message; it is only called for kept entries.
template <class Why>
void add_uncovered(PlanarReport& rep, double x, double y, Why why) {
  if (rep.uncovered.size() < kKeep) rep.uncovered.push_back({x, y, why()});
  ++rep.uncovered_count;
}

void validate(const Domain& domain, const Points& centers, const std::vector<double>& radii,
              const PlanarOptions& opt) {
  if (radii.size() != centers.size())
    throw std::invalid_argument("planar oracle: radii must have one radius per center");
  for (double r : radii)
    if (!(std::isfinite(r) && r > 0))
      throw std::invalid_argument("planar oracle: radii must be finite and > 0");
  if (!(opt.tol >= 0 && opt.tol < 1))
    throw std::invalid_argument("planar oracle: tol must be in [0, 1)");
  if (domain.loops.empty()) throw std::invalid_argument("planar oracle: the domain has no loop");
  for (const auto& loop : domain.loops) {
    if (loop.size() < 3) throw std::invalid_argument("planar oracle: a loop has < 3 vertices");
    for (const auto& v : loop)
      if (!(std::isfinite(v[0]) && std::isfinite(v[1])))
        throw std::invalid_argument("planar oracle: vertices must be finite");
  }
  for (const auto& p : centers)
    if (!(std::isfinite(p[0]) && std::isfinite(p[1])))
      throw std::invalid_argument("planar oracle: centers must be finite");
  if (!opt.boundary_flags.empty() && opt.boundary_flags.size() != centers.size())
    throw std::invalid_argument("planar oracle: boundary_flags must have one flag per center");
}

// The parameter interval [t0, t1] of segment s within distance R of (x, y); false if
// none. Computed from the foot of the perpendicular, so it is accurate when the
// circle only grazes the segment's line.
bool segment_interval(const Segment& s, double x, double y, double R, double& t0, double& t1) {
  const double dx = s.bx - s.ax, dy = s.by - s.ay;
  const double len2 = dx * dx + dy * dy;
  const double tf = ((x - s.ax) * dx + (y - s.ay) * dy) / len2;  // foot parameter
  const double h = std::hypot(s.ax + tf * dx - x, s.ay + tf * dy - y);
  if (h > R) return false;
  const double half = std::sqrt(std::max(0.0, R * R - h * h)) / std::sqrt(len2);
  t0 = tf - half;
  t1 = tf + half;
  return true;
}

// How far (in units of the smaller radius) a probe goes beside each circle–circle corner.
constexpr double kCornerProbe = 0.01;

}  // namespace

double domain_area(const Domain& domain) {
  double total = 0;
  for (std::size_t l = 0; l < domain.loops.size(); ++l) {
    const auto& loop = domain.loops[l];
    double twice = 0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const auto& a = loop[k];
      const auto& b = loop[(k + 1) % loop.size()];
      twice += a[0] * b[1] - a[1] * b[0];
    }
    total += (l == 0 ? 1 : -1) * std::fabs(twice) / 2;
  }
  return total;
}

bool even_odd_inside(const Domain& domain, double x, double y) {
  return even_odd(segments_of(domain), x, y);
}

double distance_to_boundary(const Domain& domain, double x, double y) {
  return boundary_distance(segments_of(domain), x, y);
}

PlanarReport check_planar(const Domain& domain, const Points& c, const std::vector<double>& radii,
                          const PlanarOptions& opt) {
  validate(domain, c, radii, opt);
  const double tol = opt.tol;
  const std::size_t n = c.size();
  const auto segs = segments_of(domain);
  double r_max = 0, r_min = std::numeric_limits<double>::infinity();
  std::vector<double> reach(n);  // a point is covered if center k is within reach[k]
  for (std::size_t k = 0; k < n; ++k) {
    r_max = std::max(r_max, radii[k]);
    r_min = std::min(r_min, radii[k]);
    reach[k] = radii[k] * (1 + tol);
  }
  const double reach_max = r_max * (1 + tol);
  // slack: how far outside the boundary still counts as in (r*tol of the disks concerned).
  auto in_domain = [&](double x, double y, double slack) {
    return even_odd(segs, x, y) || boundary_distance(segs, x, y) <= slack;
  };

  PlanarReport rep;
  rep.containment_checked = opt.containment;
  rep.boundary_checked = opt.boundary;
  rep.conflicts_checked = opt.conflicts;
  rep.maximality_checked = opt.maximality;
  rep.n = n;
  rep.r = r_max;
  rep.r_min = n ? r_min : 0;
  rep.tol = tol;

  const Bins bins(c, reach_max);
  auto covered = [&](double px, double py) {
    return bins.visit(px, py, reach_max, [&](std::size_t k, double d) { return d <= reach[k]; });
  };

  // Which disks are boundary disks.
  std::vector<char> on_boundary(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const bool flagged = opt.boundary_flags.empty()
                             ? boundary_distance(segs, c[i][0], c[i][1]) <= radii[i] * tol
                             : opt.boundary_flags[i] != 0;
    on_boundary[i] = flagged;
    rep.boundary_count += flagged;
  }

  // (a) Containment.
  if (opt.containment)
    for (std::size_t i = 0; i < n; ++i)
      if (!in_domain(c[i][0], c[i][1], radii[i] * tol))
        keep(rep.outside, rep.outside_count,
             {i, c[i][0], c[i][1], boundary_distance(segs, c[i][0], c[i][1])});

  // (b) Boundary disks on the boundary; a center on every corner.
  if (opt.boundary) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!on_boundary[i]) continue;
      const double dist = boundary_distance(segs, c[i][0], c[i][1]);
      if (!(dist <= radii[i] * tol))
        keep(rep.off_boundary, rep.off_boundary_count, {i, c[i][0], c[i][1], dist});
    }
    for (std::size_t l = 0; l < domain.loops.size(); ++l)
      for (std::size_t k = 0; k < domain.loops[l].size(); ++k) {
        const auto& v = domain.loops[l][k];
        if (bins.visit(v[0], v[1], r_max * tol,
                       [&](std::size_t i, double d) { return d <= radii[i] * tol; }))
          continue;
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto& p : c) nearest = std::min(nearest, std::hypot(p[0] - v[0], p[1] - v[1]));
        keep(rep.bare_corners, rep.bare_corner_count, {l, k, v[0], v[1], nearest});
      }
  }

  if (!opt.conflicts && !opt.maximality) return rep;
  if (opt.maximality && n == 0) {
    add_uncovered(rep, domain.loops[0][0][0], domain.loops[0][0][1], [] { return "there are no disks"; });
    return rep;
  }

  // Is disk k not (a copy of) disk g: center or radius off by more than r_g*tol?
  auto far = [&](std::size_t k, std::size_t g) {
    const double same = radii[g] * tol;
    return std::hypot(c[k][0] - c[g][0], c[k][1] - c[g][1]) > same ||
           std::fabs(radii[k] - radii[g]) > same;
  };
  // Is (px, py) within reach of a disk other than (the disks at) g0 and g1?
  auto covered_by_other = [&](double px, double py, std::size_t g0, std::size_t g1) {
    return bins.visit(px, py, reach_max, [&](std::size_t k, double d) {
      return d <= reach[k] && far(k, g0) && far(k, g1);
    });
  };

  // (c) Conflicts, and candidates (1): every pair at most r_i + r_j apart.
  std::vector<char> meets(n, 0);  // does circle i meet another circle?
  for (std::size_t i = 0; i < n; ++i) {
    const double xi = c[i][0], yi = c[i][1], ri = radii[i];
    bins.visit(xi, yi, ri + r_max, [&](std::size_t j, double d) {
      const double rj = radii[j];
      if (j == i || d > ri + rj) return false;
      const double lo = std::min(ri, rj), hi = std::max(ri, rj);
      // Coincident circles have no corners; others meet unless one is inside the other.
      const bool meet = !(d <= lo * tol && hi - lo <= lo * tol) && d >= hi - lo;
      if (meet) meets[i] = 1;
      if (j < i) return false;  // each pair once
      rep.min_distance = std::min(rep.min_distance, d);
      if (opt.conflicts && d < lo * (1 - tol))
        keep(rep.conflicts, rep.conflict_count, {i, j, d});
      else if (opt.conflicts && d < hi * (1 - tol))  // allowed: only the larger covers
        keep(rep.covered_centers, rep.covered_center_count, {i, j, d});
      if (!opt.maximality || !meet) return false;
      // c_i + a*u -+ h*u_perp, with h^2 in factored form (exactly 0 when tangent).
      const double ux = (c[j][0] - xi) / d, uy = (c[j][1] - yi) / d;
      const double a = (ri * ri - rj * rj + d * d) / (2 * d);
      const double h2 = (ri + rj - d) * (d + ri - rj) * (d - ri + rj) * (d + ri + rj);
      const double h = std::sqrt(std::max(0.0, h2)) / (2 * d);
      for (const double side : {-1.0, 1.0}) {
        const double px = xi + a * ux - side * h * uy, py = yi + a * uy + side * h * ux;
        if (!covered_by_other(px, py, i, j)) {
          if (in_domain(px, py, lo * tol))
            add_uncovered(rep, px, py, [&] {
              return "corner of disks " + std::to_string(i) + " and " + std::to_string(j) +
                     " is not covered by a third disk";
            });
        } else {
          // Beside a covered corner, into the region outside both disks (along the sum
          // of the outward normals, or both tangent directions when they cancel).
          const double wx = (px - xi) / ri + (px - c[j][0]) / rj;
          const double wy = (py - yi) / ri + (py - c[j][1]) / rj;
          const double wl = std::hypot(wx, wy);
          for (const double sign : {1.0, -1.0}) {
            const bool cancel = !(wl > 1e-9);
            const double dx = cancel ? sign * uy : wx / wl, dy = cancel ? -sign * ux : wy / wl;
            const double qx = px + kCornerProbe * lo * dx, qy = py + kCornerProbe * lo * dy;
            if (even_odd(segs, qx, qy) && !covered(qx, qy))
              add_uncovered(rep, qx, qy, [&] {
                return "probe beside the corner of disks " + std::to_string(i) + " and " +
                       std::to_string(j) + " is covered by no disk";
              });
            if (!cancel) break;
          }
        }
        if (h == 0) break;
      }
      return false;
    });
  }
  if (!opt.maximality) return rep;

  // Candidates (2): each circle with each segment.
  for (std::size_t i = 0; i < n; ++i) {
    const double ri = radii[i];
    for (std::size_t s = 0; s < segs.size(); ++s) {
      const Segment& g = segs[s];
      if (std::min(g.ax, g.bx) > c[i][0] + ri || std::max(g.ax, g.bx) < c[i][0] - ri ||
          std::min(g.ay, g.by) > c[i][1] + ri || std::max(g.ay, g.by) < c[i][1] - ri)
        continue;
      double t0, t1;
      if (!segment_interval(g, c[i][0], c[i][1], ri, t0, t1)) continue;
      for (double t : {t0, t1}) {
        if (t < 0 || t > 1) continue;
        const double px = g.ax + t * (g.bx - g.ax), py = g.ay + t * (g.by - g.ay);
        if (!covered_by_other(px, py, i, i))
          add_uncovered(rep, px, py, [&] {
            return "circle of disk " + std::to_string(i) + " meets segment " +
                   std::to_string(g.index) + " of loop " + std::to_string(g.loop) +
                   " at a point no other disk covers";
          });
        if (t1 == t0) break;
      }
    }
  }

  // Candidates (3): polygon vertices.
  for (std::size_t l = 0; l < domain.loops.size(); ++l)
    for (std::size_t k = 0; k < domain.loops[l].size(); ++k) {
      const auto& v = domain.loops[l][k];
      if (!covered(v[0], v[1]))
        add_uncovered(rep, v[0], v[1], [&] {
          return "vertex " + std::to_string(k) + " of loop " + std::to_string(l) + " is not covered";
        });
    }

  // Candidates (4): a circle that meets no other circle (and lies in no other disk).
  for (std::size_t i = 0; i < n; ++i) {
    if (meets[i]) continue;
    const double px = c[i][0] - radii[i], py = c[i][1];
    if (in_domain(px, py, radii[i] * tol) && !covered_by_other(px, py, i, i))
      add_uncovered(rep, px, py, [&] {
        return "circle of disk " + std::to_string(i) + " meets no other circle";
      });
  }

  // Random probes, uniform over the domain by rejection from its bounding box.
  double bx0 = domain.loops[0][0][0], by0 = domain.loops[0][0][1], bx1 = bx0, by1 = by0;
  for (const auto& loop : domain.loops)
    for (const auto& v : loop) {
      bx0 = std::min(bx0, v[0]);
      by0 = std::min(by0, v[1]);
      bx1 = std::max(bx1, v[0]);
      by1 = std::max(by1, v[1]);
    }
  std::mt19937_64 rng(opt.seed);
  auto unit = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };  // [0,1)
  const std::size_t max_tries = 1000 * opt.probes + 1000;  // a domain of almost no area
  for (std::size_t tries = 0; rep.probes < opt.probes && tries < max_tries; ++tries) {
    const double px = bx0 + (bx1 - bx0) * unit(), py = by0 + (by1 - by0) * unit();
    if (!even_odd(segs, px, py)) continue;
    ++rep.probes;
    double nearest = std::numeric_limits<double>::infinity();
    bool hit = false;
    bins.visit(px, py, 2 * r_max, [&](std::size_t k, double d) {
      nearest = std::min(nearest, d);
      hit = hit || d <= reach[k];
      return false;
    });
    rep.max_probe_gap = std::max(rep.max_probe_gap, nearest);
    if (!hit)
      add_uncovered(rep, px, py, [&] {
        std::ostringstream why;
        why << "probe: nearest center at distance " << nearest;
        return why.str();
      });
  }

  // 1D maximality: on each segment, the union of the intervals boundary disks cover.
  for (const Segment& g : segs) {
    std::vector<std::array<double, 2>> cover;
    for (std::size_t i = 0; i < n; ++i) {
      double t0, t1;
      if (on_boundary[i] && segment_interval(g, c[i][0], c[i][1], reach[i], t0, t1) && t1 >= 0 &&
          t0 <= 1)
        cover.push_back({t0, t1});
    }
    std::sort(cover.begin(), cover.end());
    double done = 0;  // [0, done] is covered (t = 0 alone counts: a gap has length)
    auto gap = [&](double t0, double t1) {
      const double tm = (t0 + t1) / 2;
      keep(rep.boundary_gaps, rep.boundary_gap_count,
           {g.loop, g.index, t0, t1, g.ax + tm * (g.bx - g.ax), g.ay + tm * (g.by - g.ay)});
    };
    for (const auto& iv : cover) {
      if (iv[0] > done) gap(done, iv[0]);
      done = std::max(done, iv[1]);
      if (done >= 1) break;
    }
    if (done < 1) gap(done, 1);
  }
  return rep;
}

PlanarReport check_planar(const Domain& domain, const Points& c, double r,
                          const PlanarOptions& opt) {
  // One radius: validated here (also when there are no centers), echoed as given.
  if (!(std::isfinite(r) && r > 0)) throw std::invalid_argument("planar oracle: r must be > 0");
  PlanarReport rep = check_planar(domain, c, std::vector<double>(c.size(), r), opt);
  rep.r = rep.r_min = r;
  return rep;
}

bool PlanarReport::ok() const {
  const bool any = containment_checked || boundary_checked || conflicts_checked || maximality_checked;
  return any && (!containment_checked || inside()) && (!boundary_checked || on_boundary()) &&
         (!conflicts_checked || conflict_free()) &&
         (!maximality_checked || (maximal() && boundary_maximal()));
}

std::string PlanarReport::summary() const {
  std::ostringstream s;
  s.precision(10);
  s << "planar oracle: N=" << n << " (" << boundary_count << " on the boundary), ";
  if (r_min == r)
    s << "r=" << r;
  else
    s << "radii in [" << r_min << ", " << r << "]";
  s << ", tol=" << tol << ". ";
  auto list = [&](const char* title, bool checked, std::size_t count, std::size_t kept,
                  const std::function<void(std::size_t)>& item) {
    summary_list(s, title, checked, count, kept, item);
  };
  list("Centers outside", containment_checked, outside_count, outside.size(), [&](std::size_t k) {
    s << "disk " << outside[k].i << " at (" << outside[k].x << ", " << outside[k].y
      << "), " << outside[k].distance_to_boundary << " from the boundary";
  });
  list("Boundary disks off the boundary", boundary_checked, off_boundary_count,
       off_boundary.size(), [&](std::size_t k) {
         s << "disk " << off_boundary[k].i << " at (" << off_boundary[k].x << ", "
           << off_boundary[k].y << "), " << off_boundary[k].distance_to_boundary << " away";
       });
  list("Corners without a disk", boundary_checked, bare_corner_count, bare_corners.size(),
       [&](std::size_t k) {
         s << "vertex " << bare_corners[k].vertex << " of loop " << bare_corners[k].loop << " at ("
           << bare_corners[k].x << ", " << bare_corners[k].y << "), nearest center "
           << bare_corners[k].nearest_center;
       });
  list("Conflicts", conflicts_checked, conflict_count, conflicts.size(), [&](std::size_t k) {
    s << "disks " << conflicts[k].i << " and " << conflicts[k].j << " at distance "
      << conflicts[k].distance;
  });
  if (conflicts_checked && covered_center_count > 0)
    s << "Centers covered by a larger disk (allowed): " << covered_center_count << ". ";
  s << "Min center distance: " << min_distance << ". ";
  list("Uncovered (2D)", maximality_checked, uncovered_count, uncovered.size(), [&](std::size_t k) {
    s << "(" << uncovered[k].x << ", " << uncovered[k].y << "): " << uncovered[k].why;
  });
  list("Boundary gaps (1D)", maximality_checked, boundary_gap_count, boundary_gaps.size(),
       [&](std::size_t k) {
         const auto& g = boundary_gaps[k];
         s << "segment " << g.segment << " of loop " << g.loop << ", t in [" << g.t0 << ", "
           << g.t1 << "], around (" << g.x << ", " << g.y << ")";
       });
  if (maximality_checked) s << "Probes: " << probes << ", max probe gap: " << max_probe_gap << ".";
  return s.str();
}

}  // namespace oracle
