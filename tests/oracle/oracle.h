// SPDX-License-Identifier: GPL-3.0-or-later
//
// Independent test oracle for disk packings in a periodic box (a torus).
// Written separately from the library: brute force in spirit, standard library only.
//
// Model: box [0,width) x [0,height) with periodic wrap; N disks, of one radius r or
// each with its own radius r_i (the overloads taking `radii`; with equal radii both
// give identical reports).
//  - conflict: two disks (or a disk and its own periodic image) whose centers are
//    closer than min(r_i, r_j)*(1-tol): the smaller disk covers the other center;
//  - covered center (information, not a failure): a pair that is no conflict but
//    closer than max(r_i, r_j)*(1-tol): the larger disk covers the smaller one's
//    center, which the prior-disk rule of varying-radius sampling allows;
//  - covered point: within r_i*(1+tol) of some center i (any periodic image);
//  - maximal: every point of the torus is covered (checked exactly via circle
//    intersection points, plus random probes; see oracle.cpp).
// Centers outside the box are wrapped into it. Inputs must be finite, radii > 0 (one
// per center), width, height > 0 and 0 <= tol < 1, otherwise std::invalid_argument is
// thrown.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace oracle {

struct Box {
  double width = 1, height = 1;
};

// Disks i <= j closer than min(r_i, r_j)*(1-tol) (a conflict) or, for a covered
// center, than max(r_i, r_j)*(1-tol). i == j: a disk and its own periodic image. One
// entry per pair and periodic image (several images can conflict in a tiny box).
struct Conflict {
  std::size_t i, j;
  double distance;
};

// Witness of non-maximality, wrapped into the box: an uncovered random probe, a
// corner of a void (two circles' intersection point not in any third disk), an
// uncovered probe beside a corner, or a point of a circle that meets no other circle
// and lies in no other disk.
struct Uncovered {
  double x, y;
  std::string why;
};

struct Report {
  // Which checks were run; an unchecked property reads as false.
  bool conflicts_checked = false;
  bool maximality_checked = false;
  // Inputs, echoed for summary().
  std::size_t n = 0;
  double r = 0, tol = 0;  // r: the largest radius
  double r_min = 0;       // the smallest radius (== r for one radius)

  // The first 100 found (in no particular order), and how many there are in all.
  std::vector<Conflict> conflicts;
  std::size_t conflict_count = 0;
  // Pairs where only the larger disk covers the other center (never with one radius).
  std::vector<Conflict> covered_centers;
  std::size_t covered_center_count = 0;
  std::vector<Uncovered> uncovered;
  std::size_t uncovered_count = 0;

  // Smallest center distance over all pairs and images (including a disk and its
  // own images); only pairs at most r_i + r_j apart are seen, so infinity means "no
  // two disks meet".
  double min_distance = std::numeric_limits<double>::infinity();
  // Largest distance from a random probe to its nearest center; infinity if some
  // probe has no center within 2r (r the largest radius).
  double max_probe_gap = 0;

  bool conflict_free() const { return conflicts_checked && conflict_count == 0; }
  bool maximal() const { return maximality_checked && uncovered_count == 0; }
  std::string summary() const;  // one paragraph, for test failure messages
};

using Points = std::vector<std::array<double, 2>>;

// How neighbours are found. all_pairs: every center and every relevant periodic
// image (obviously correct, O(N) per query). grid: a uniform bin grid (fast).
// automatic: all_pairs for N <= 256, grid above. Verdicts, counts and distances are
// identical; which entries are kept when there are more than 100 can differ.
enum class Method { automatic, all_pairs, grid };

Report check_conflicts(const Box& box, double r, const Points& centers, double tol = 1e-6,
                       Method method = Method::automatic);

Report check_maximal(const Box& box, double r, const Points& centers, double tol = 1e-6,
                     std::size_t probes = 100000, std::uint64_t seed = 1,
                     Method method = Method::automatic);

// Both checks, sharing one pass over the pairs.
Report check_all(const Box& box, double r, const Points& centers, double tol = 1e-6,
                 std::size_t probes = 100000, std::uint64_t seed = 1,
                 Method method = Method::automatic);

// The same with one radius per center (radii.size() == centers.size()). Bins are
// sized by the largest radius, so radii spanning orders of magnitude are slow.
Report check_conflicts(const Box& box, const std::vector<double>& radii, const Points& centers,
                       double tol = 1e-6, Method method = Method::automatic);

Report check_maximal(const Box& box, const std::vector<double>& radii, const Points& centers,
                     double tol = 1e-6, std::size_t probes = 100000, std::uint64_t seed = 1,
                     Method method = Method::automatic);

Report check_all(const Box& box, const std::vector<double>& radii, const Points& centers,
                 double tol = 1e-6, std::size_t probes = 100000, std::uint64_t seed = 1,
                 Method method = Method::automatic);

// For the reports' summary(): appends "title: count (item 0; ...; item 4; ...). ", or
// "title: not checked. ", item(k) writing the k-th kept witness to s.
void summary_list(std::ostringstream& s, const char* title, bool checked, std::size_t count, std::size_t kept,
                  const std::function<void(std::size_t)>& item);

}  // namespace oracle
