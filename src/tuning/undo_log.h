// SPDX-License-Identifier: GPL-3.0-or-later
// Edits of a packing made through an UndoLog can be taken back, newest first. Tuning
// operations use it to try a move and keep it only when it serves the target (never
// past the exact count, never lowering the count in an injection phase).
#pragma once

#include <vector>

#include "disktune/packing.h"

namespace disktune::detail {

class UndoLog {
 public:
  explicit UndoLog(Packing& packing) : packing_(packing) {}

  DiskId insert(Vec2 c, double r, std::uint8_t flags = 0) {
    const DiskId id = packing_.insert(c, r, flags);
    edits_.push_back({Kind::insert, id, {}, r, flags});
    return id;
  }
  void move(DiskId id, Vec2 c) {
    edits_.push_back({Kind::move, id, packing_.center(id), packing_.radius(id), packing_.flags(id)});
    packing_.move(id, c);
  }
  void set_flags(DiskId id, std::uint8_t flags) {
    edits_.push_back({Kind::flags, id, {}, 0, packing_.flags(id)});
    packing_.set_flags(id, flags);
  }
  void remove(DiskId id) {
    edits_.push_back({Kind::remove, id, packing_.center(id), packing_.radius(id), packing_.flags(id)});
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
        case Kind::remove: renamed.push_back({e->id, packing_.insert(e->center, e->radius, e->flags)}); break;
      }
    }
    edits_.resize(mark);
  }
  /// Keeps the edits: the log forgets them.
  void commit() { edits_.clear(); }

 private:
  enum class Kind { insert, move, flags, remove };
  struct Edit {
    Kind kind;
    DiskId id;
    Vec2 center;
    double radius;
    std::uint8_t flags;
  };
  long inserted_minus_removed() const {
    long n = 0;
    for (const Edit& e : edits_) n += e.kind == Kind::insert ? 1 : e.kind == Kind::remove ? -1 : 0;
    return n;
  }

  Packing& packing_;
  std::vector<Edit> edits_;
};

}  // namespace disktune::detail
