// SPDX-License-Identifier: GPL-3.0-or-later
// Outputs written whole or not at all: a temporary beside the target, renamed into
// place, alone or with the other outputs of a transaction.
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>

#include "disktune/errors.h"
#include "disktune/io.h"

namespace disktune {
namespace {

namespace fs = std::filesystem;

// The temporaries not yet renamed, where a signal handler can reach them: fixed slots
// of plain characters, a slot counting as taken only once its path is complete.
constexpr int kSlots = 64;
constexpr std::size_t kPathMax = 4096;
char g_temporary[kSlots][kPathMax];
std::atomic<bool> g_taken[kSlots];

int remember(const std::string& temporary) {
  if (temporary.size() >= kPathMax) return -1;  // still written; a signal may leave it
  for (int k = 0; k < kSlots; ++k) {
    if (g_taken[k].load()) continue;
    std::memcpy(g_temporary[k], temporary.c_str(), temporary.size() + 1);
    bool expected = false;
    if (g_taken[k].compare_exchange_strong(expected, true)) return k;
  }
  return -1;
}

void forget(int slot) {
  if (slot >= 0) g_taken[slot].store(false);
}

thread_local OutputTransaction* t_open = nullptr;

// Where the bytes must go: the file a symbolic link points to (so the link stays).
std::string target_of(const std::string& path) {
  std::error_code ec;
  if (!fs::is_symlink(fs::symlink_status(path, ec))) return path;
  const fs::path resolved = fs::weakly_canonical(path, ec);
  return ec ? path : resolved.string();
}

// Renames a finished temporary over its target, keeping an existing target's mode.
void put_in_place(const std::string& temporary, const std::string& target) {
  std::error_code ec;
  const fs::file_status old = fs::status(target, ec);
  if (!ec && fs::is_regular_file(old)) fs::permissions(temporary, old.permissions(), ec);
  if (std::rename(temporary.c_str(), target.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(temporary.c_str());
    throw IoError("cannot write '" + target + "': " + why);
  }
}

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  // A device or a pipe (/dev/null, /dev/stdout, a FIFO) is written straight into:
  // renaming a temporary over it would replace the device with a plain file.
  std::error_code ec;
  const auto kind = fs::status(path, ec);
  if (!ec && fs::exists(kind) && !fs::is_regular_file(kind) && !fs::is_directory(kind)) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw IoError("cannot write '" + path + "': " + std::strerror(errno));
    write(out);
    out.flush();
    if (!out) throw IoError("writing '" + path + "' failed");
    return;
  }
  // Refused before anything is written: renamed over at the end, a folder would fail
  // only after the outputs before it in a transaction were in place.
  if (!ec && fs::is_directory(kind))
    throw IoError("cannot write '" + path + "': it is a folder; give a file name");
  const std::string target = target_of(path);
  // A per-call suffix keeps concurrent writers to the same path apart.
  const std::string tmp = target + ".tmp" + std::to_string(std::random_device{}() & 0xffffff);
  const int slot = remember(tmp);
  try {
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) {
        throw IoError("cannot write '" + path + "': " + std::strerror(errno) +
                      " (check that the folder exists and is writable)");
      }
      write(out);
      out.flush();
      if (!out) throw IoError("writing '" + path + "' failed (disk full?)");
    }
    if (t_open) {
      t_open->staged_.push_back({tmp, target, slot});  // renamed at commit, slot kept till then
      return;
    }
    put_in_place(tmp, target);
  } catch (...) {
    std::remove(tmp.c_str());
    forget(slot);
    throw;
  }
  forget(slot);
}

OutputTransaction::OutputTransaction() {
  if (t_open) throw std::logic_error("output transactions do not nest");
  t_open = this;
}

OutputTransaction::~OutputTransaction() {
  if (t_open == this) t_open = nullptr;
  for (const Staged& s : staged_) {
    std::remove(s.temporary.c_str());
    forget(s.slot);
  }
}

bool OutputTransaction::open_here() { return t_open != nullptr; }

void OutputTransaction::commit() {
  if (t_open == this) t_open = nullptr;
  while (!staged_.empty()) {
    const Staged s = staged_.front();
    staged_.erase(staged_.begin());
    try {
      put_in_place(s.temporary, s.target);
    } catch (...) {
      forget(s.slot);
      throw;  // the destructor removes the rest
    }
    forget(s.slot);
  }
}

void remove_temporary_outputs() noexcept {
  for (int k = 0; k < kSlots; ++k) {
    if (g_taken[k].load()) ::unlink(g_temporary[k]);
  }
}

}  // namespace disktune
