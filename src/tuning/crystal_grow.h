// SPDX-License-Identifier: GPL-3.0-or-later
// The growth loop of crystal growth (paper, 2.3 and 3.2), shared by the plane and the
// surface: the lattice geometry (sites, seeding, settling a disk on a site) comes from
// a Lattice type, the bookkeeping that keeps the count moving one way lives here.
#pragma once

#include <cstddef>
#include <functional>

#include "disktune/errors.h"

namespace disktune::detail {

/// The lattice has one spacing: the paper has no crystal growth for varying radii.
inline void require_one_radius(bool one_radius) {
  if (!one_radius) {
    throw InvalidInput("crystal growth needs one radius (a hexagonal lattice has one spacing); "
                       "with a sizing function use void or repeller injection, sifting or "
                       "attractor ejection");
  }
}

/// Lattice provides: packing() (its size()), seed(log, room), has_sites(),
/// take_site(), taken(site), settle(log, site, room) and, for ejection, tidy(log,
/// site, within) (the attractor step around a new site). Log is its undo log type.
/// Returns the change in the count (its absolute value), never past max_change.
template <class Log, class Lattice>
std::size_t grow_crystal(Lattice& lattice, bool inject, std::size_t max_change,
                         const std::function<void()>& after_step) {
  auto& p = lattice.packing();
  const std::size_t start = p.size();
  auto within = [&](std::size_t n) {  // never past the target
    return inject ? n <= start + max_change : n + max_change >= start;
  };
  Log batch(p);
  if (max_change == 0 || !lattice.seed(batch, max_change) || !within(p.size())) {
    batch.revert();
    return 0;
  }
  // A step can move the count the wrong way (deleting disks near a dense site may
  // leave less room than they took; refilling voids near a sparse site adds disks).
  // Steps are kept in a batch that is committed whenever the count is back at or past
  // where the last commit left it, so committed states never go the wrong way; a
  // batch still behind at the end is taken back.
  std::size_t committed = start;
  auto ahead = [&] { return inject ? p.size() >= committed : p.size() <= committed; };
  if (ahead()) batch.commit(), committed = p.size();
  while (lattice.has_sites() && p.size() != (inject ? start + max_change : start - max_change)) {
    const auto site = lattice.take_site();
    if (lattice.taken(site)) continue;
    const std::size_t step = batch.mark();
    const std::size_t room = inject ? start + max_change - std::min(p.size(), start + max_change) : max_change;
    if (!lattice.settle(batch, site, room)) {
      batch.revert_to(step);
      continue;
    }
    if (!inject) lattice.tidy(batch, site, within);
    if (!within(p.size())) {
      batch.revert_to(step);
      continue;
    }
    if (ahead()) {
      batch.commit();
      committed = p.size();
      if (after_step) after_step();
    }
  }
  batch.revert();
  return inject ? p.size() - start : start - p.size();
}

}  // namespace disktune::detail
