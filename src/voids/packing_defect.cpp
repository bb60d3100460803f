// SPDX-License-Identifier: GPL-3.0-or-later
// The exact check of a packing, once for every space: conflicts first, then maximality,
// the first defect named in one sentence with every digit of its place.
#include <string>

#include "../domain/point_text.h"
#include "disktune/errors.h"
#include "disktune/surface_voids.h"
#include "disktune/voids.h"
#include "packing_checks.h"

namespace disktune {
namespace {

bool one_radius(const Packing& packing) { return !packing.sizing(); }
bool one_radius(const SurfacePacking& packing) { return packing.sizing().is_constant(); }

template <class P>
std::string defect_of(const P& packing) {
  if (packing.empty()) return "holds no disks";
  // The common answer, none, from the fastest search; a defect is then named by the
  // searches below, conflicts first.
  if (detail::conflict_free_and_maximal(packing)) return "";
  if (const auto pair = detail::first_conflict(packing)) {
    return "the disks centered at " + detail::point_text(packing.center((*pair)[0])) + " and " +
           detail::point_text(packing.center((*pair)[1])) + " cover each other's centers (a conflict): they are closer than " +
           (one_radius(packing) ? "r" : "the smaller of their radii");
  }
  if (const auto hole = detail::first_hole(packing)) return "not maximal: " + *hole + " is covered by no disk";
  return "";
}

template <class P>
void validate(const P& packing, const std::string& what) {
  const std::string defect = defect_of(packing);
  if (defect.empty()) return;
  // A hole is what a packing made by other means most often has: say how to get one.
  if (defect.rfind("not maximal", 0) == 0)
    throw InvalidInput(what + ": " + defect + "; start from a maximal sample", InvalidInput::Remedy::sample);
  throw InvalidInput(what + ": " + defect);
}

}  // namespace

std::string packing_defect(const Packing& packing) { return defect_of(packing); }
std::string packing_defect(const SurfacePacking& packing) { return defect_of(packing); }
void validate_packing(const Packing& packing, const std::string& what) { validate(packing, what); }
void validate_packing(const SurfacePacking& packing, const std::string& what) { validate(packing, what); }
bool is_conflict_free(const Packing& packing) { return !detail::first_conflict(packing); }
bool is_conflict_free(const SurfacePacking& packing) { return !detail::first_conflict(packing); }

}  // namespace disktune
