// SPDX-License-Identifier: GPL-3.0-or-later
// Edits of a packing made through an UndoLog can be taken back, newest first. Tuning
// operations use it to try a move and keep it only when it serves the target (never
// past the exact count, never lowering the count in an injection phase), and it takes
// them back by itself when an exception cuts an operation short.
#pragma once

#include <exception>
#include <utility>
#include <vector>

#include "disktune/packing.h"
#include "disktune/surface_packing.h"

namespace disktune::detail {

// Where a disk is, and how to put one there, for each kind of packing.
inline Vec2 position_of(const Packing& p, DiskId id) { return p.center(id); }
inline DiskId insert_at(Packing& p, Vec2 c, double r, std::uint8_t flags) { return p.insert(c, r, flags); }
inline SurfacePoint position_of(const SurfacePacking& p, DiskId id) { return p.point(id); }
inline DiskId insert_at(SurfacePacking& p, const SurfacePoint& c, double, std::uint8_t flags) {
  return p.insert(c, flags);  // the radius follows from the sizing
}

template <class P>
class BasicUndoLog {
 public:
  using Point = decltype(position_of(std::declval<const P&>(), DiskId{}));
  explicit BasicUndoLog(P& packing) : packing_(packing), unwinding_(std::uncaught_exceptions()) {}
  BasicUndoLog(const BasicUndoLog&) = delete;
  BasicUndoLog& operator=(const BasicUndoLog&) = delete;
  /// An operation cut short by an exception is taken back: every single operation is a
  /// transaction. (Leaving normally keeps the edits, as commit() does.) Should putting
  /// a disk back fail too (out of memory), nothing more can be done while unwinding.
  ~BasicUndoLog() {
    if (std::uncaught_exceptions() <= unwinding_) return;
    try {
      revert();
    } catch (...) {
    }
  }

  DiskId insert(const Point& c, double r, std::uint8_t flags = 0) {
    const DiskId id = insert_at(packing_, c, r, flags);
    edits_.push_back({Kind::insert, id, {}, r, flags});
    return id;
  }
  void move(DiskId id, const Point& c) {
    edits_.push_back({Kind::move, id, position_of(packing_, id), packing_.radius(id), packing_.flags(id)});
    packing_.move(id, c);
  }
  void set_flags(DiskId id, std::uint8_t flags) {
    edits_.push_back({Kind::flags, id, {}, 0, packing_.flags(id)});
    packing_.set_flags(id, flags);
  }
  void remove(DiskId id) {
    edits_.push_back({Kind::remove, id, position_of(packing_, id), packing_.radius(id), packing_.flags(id)});
    packing_.remove(id);
  }

  /// Net change in the number of disks since the log was last opened or committed.
  long added() const { return inserted_minus_removed(); }
  bool empty() const { return edits_.empty(); }

  /// A point in the log to come back to with revert_to().
  std::size_t mark() const { return edits_.size(); }

  /// Takes every edit back, newest first. A removed disk comes back with the same
  /// center, radius and flags, possibly under another id.
  void revert() { revert_to(0); }

  /// Takes back the edits made since `mark`, newest first.
  void revert_to(std::size_t mark) {
    // A disk brought back may get a new id; older edits of it follow the new one.
    std::vector<std::pair<DiskId, DiskId>> renamed;
    auto current = [&](DiskId id) {
      for (auto it = renamed.rbegin(); it != renamed.rend(); ++it) {
        if (it->first == id) return it->second;
      }
      return id;
    };
    for (auto e = edits_.rbegin(); e != edits_.rend() - mark; ++e) {
      const DiskId id = current(e->id);
      switch (e->kind) {
        case Kind::insert: packing_.remove(id); break;
        case Kind::move: packing_.move(id, e->center); break;
        case Kind::flags: packing_.set_flags(id, e->flags); break;
        case Kind::remove: renamed.push_back({e->id, insert_at(packing_, e->center, e->radius, e->flags)}); break;
      }
    }
    edits_.resize(mark);
  }
  /// Keeps the edits: the log forgets them.
  void commit() { edits_.clear(); }

  /// Calls f(id) for each disk inserted or moved since `mark` that is still there (a
  /// disk placed twice, twice): where the operation put disks.
  template <class F>
  void for_each_placed(std::size_t mark, F&& f) const {
    for (std::size_t i = mark; i < edits_.size(); ++i) {
      const Edit& e = edits_[i];
      if ((e.kind == Kind::insert || e.kind == Kind::move) && packing_.alive(e.id)) f(e.id);
    }
  }

 private:
  enum class Kind { insert, move, flags, remove };
  struct Edit {
    Kind kind;
    DiskId id;
    Point center;
    double radius;
    std::uint8_t flags;
  };
  long inserted_minus_removed() const {
    long n = 0;
    for (const Edit& e : edits_) n += e.kind == Kind::insert ? 1 : e.kind == Kind::remove ? -1 : 0;
    return n;
  }

  P& packing_;
  int unwinding_;  // exceptions in flight when the log was opened
  std::vector<Edit> edits_;
};

using UndoLog = BasicUndoLog<Packing>;
using SurfaceUndoLog = BasicUndoLog<SurfacePacking>;

}  // namespace disktune::detail
