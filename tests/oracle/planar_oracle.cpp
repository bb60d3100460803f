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
//     cannot cover that half alone; an isolated circle is ringed by uncovered points,
//     since equal disks cannot contain one another), and the finitely many closed
//     disks covering them include one that contains the candidate. A circle–circle
//     point on the boundary or within r*tol outside it could in principle have its
//     uncovered side outside D; the boundary disks cover such points in practice
//     (they are within r of the nearest boundary point, which is within r*tol).
// The random probes are an independent backstop for the degenerate cases and for bugs
// here. As in oracle.cpp, centers within r*tol of each other count as one disk.
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

void validate(const Domain& domain, const Points& centers, double r, const PlanarOptions& opt) {
  if (!(std::isfinite(r) && r > 0)) throw std::invalid_argument("planar oracle: r must be > 0");
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

PlanarReport check_planar(const Domain& domain, const Points& c, double r,
                          const PlanarOptions& opt) {
  validate(domain, c, r, opt);
  const double tol = opt.tol;
  const std::size_t n = c.size();
  const auto segs = segments_of(domain);
  const double reach = r * (1 + tol);  // a point is covered if a center is this close
  const double same = r * tol;         // centers this close are one disk; "on" a line
  auto in_domain = [&](double x, double y) {
    return even_odd(segs, x, y) || boundary_distance(segs, x, y) <= same;
  };

  PlanarReport rep;
  rep.containment_checked = opt.containment;
  rep.boundary_checked = opt.boundary;
  rep.conflicts_checked = opt.conflicts;
  rep.maximality_checked = opt.maximality;
  rep.n = n;
  rep.r = r;
  rep.tol = tol;

  const Bins bins(c, reach);

  // Which disks are boundary disks.
  std::vector<char> on_boundary(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const bool flagged = opt.boundary_flags.empty()
                             ? boundary_distance(segs, c[i][0], c[i][1]) <= same
                             : opt.boundary_flags[i] != 0;
    on_boundary[i] = flagged;
    rep.boundary_count += flagged;
  }

  // (a) Containment.
  if (opt.containment)
    for (std::size_t i = 0; i < n; ++i)
      if (!in_domain(c[i][0], c[i][1]))
        keep(rep.outside, rep.outside_count,
             {i, c[i][0], c[i][1], boundary_distance(segs, c[i][0], c[i][1])});

  // (b) Boundary disks on the boundary; a center on every corner.
  if (opt.boundary) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!on_boundary[i]) continue;
      const double dist = boundary_distance(segs, c[i][0], c[i][1]);
      if (!(dist <= same)) keep(rep.off_boundary, rep.off_boundary_count, {i, c[i][0], c[i][1], dist});
    }
    for (std::size_t l = 0; l < domain.loops.size(); ++l)
      for (std::size_t k = 0; k < domain.loops[l].size(); ++k) {
        const auto& v = domain.loops[l][k];
        if (bins.visit(v[0], v[1], same, [](std::size_t, double) { return true; })) continue;
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

  auto far = [&](std::size_t k, std::size_t g) {
    return std::hypot(c[k][0] - c[g][0], c[k][1] - c[g][1]) > same;
  };
  // Is (px, py) within reach of a disk other than (the disks at) g0 and g1?
  auto covered_by_other = [&](double px, double py, std::size_t g0, std::size_t g1) {
    return bins.visit(px, py, reach, [&](std::size_t k, double) { return far(k, g0) && far(k, g1); });
  };

  // (c) Conflicts, and candidates (1): every pair within 2r.
  std::vector<char> meets(n, 0);  // does circle i meet another circle?
  for (std::size_t i = 0; i < n; ++i) {
    const double xi = c[i][0], yi = c[i][1];
    bins.visit(xi, yi, 2 * r, [&](std::size_t j, double d) {
      if (j == i) return false;
      if (d > same) meets[i] = 1;
      if (j < i) return false;  // each pair once
      rep.min_distance = std::min(rep.min_distance, d);
      if (opt.conflicts && d < r * (1 - tol)) keep(rep.conflicts, rep.conflict_count, {i, j, d});
      if (!opt.maximality || d <= same) return false;
      // From c_i towards c_j, turned by +-acos(d/2r); tangent circles meet once.
      const double base = std::atan2(c[j][1] - yi, c[j][0] - xi);
      const double half = std::acos(std::min(1.0, d / (2 * r)));
      for (double ang : {base - half, base + half}) {
        const double px = xi + r * std::cos(ang), py = yi + r * std::sin(ang);
        if (!covered_by_other(px, py, i, j) && in_domain(px, py))
          add_uncovered(rep, px, py, [&] {
            return "corner of disks " + std::to_string(i) + " and " + std::to_string(j) +
                   " is not covered by a third disk";
          });
        if (half == 0) break;
      }
      return false;
    });
  }
  if (!opt.maximality) return rep;

  // Candidates (2): each circle with each segment.
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t s = 0; s < segs.size(); ++s) {
      const Segment& g = segs[s];
      if (std::min(g.ax, g.bx) > c[i][0] + r || std::max(g.ax, g.bx) < c[i][0] - r ||
          std::min(g.ay, g.by) > c[i][1] + r || std::max(g.ay, g.by) < c[i][1] - r)
        continue;
      double t0, t1;
      if (!segment_interval(g, c[i][0], c[i][1], r, t0, t1)) continue;
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

  // Candidates (3): polygon vertices.
  for (std::size_t l = 0; l < domain.loops.size(); ++l)
    for (std::size_t k = 0; k < domain.loops[l].size(); ++k) {
      const auto& v = domain.loops[l][k];
      if (!bins.visit(v[0], v[1], reach, [](std::size_t, double) { return true; }))
        add_uncovered(rep, v[0], v[1], [&] {
          return "vertex " + std::to_string(k) + " of loop " + std::to_string(l) + " is not covered";
        });
    }

  // Candidates (4): a circle that meets no other circle.
  for (std::size_t i = 0; i < n; ++i) {
    if (meets[i]) continue;
    const double px = c[i][0] - r, py = c[i][1];
    if (in_domain(px, py) && !covered_by_other(px, py, i, i))
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
    bins.visit(px, py, 2 * r, [&](std::size_t, double d) {
      nearest = std::min(nearest, d);
      return false;
    });
    rep.max_probe_gap = std::max(rep.max_probe_gap, nearest);
    if (!(nearest <= reach))
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
      if (on_boundary[i] && segment_interval(g, c[i][0], c[i][1], reach, t0, t1) && t1 >= 0 &&
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

bool PlanarReport::ok() const {
  const bool any = containment_checked || boundary_checked || conflicts_checked || maximality_checked;
  return any && (!containment_checked || inside()) && (!boundary_checked || on_boundary()) &&
         (!conflicts_checked || conflict_free()) &&
         (!maximality_checked || (maximal() && boundary_maximal()));
}

std::string PlanarReport::summary() const {
  std::ostringstream s;
  s.precision(10);
  s << "planar oracle: N=" << n << " (" << boundary_count << " on the boundary), r=" << r
    << ", tol=" << tol << ". ";
  auto list = [&](const char* title, bool checked, std::size_t count, std::size_t kept,
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
