// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdlib>
#include <new>

#include "disktune/huge_page_allocator.h"
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace disktune::detail {
namespace {

constexpr std::size_t kHuge = std::size_t{2} << 20;  // a transparent huge page
bool large(std::size_t bytes) { return bytes >= 2 * kHuge; }

}  // namespace

void* allocate_large(std::size_t bytes) {
  if (!large(bytes)) return ::operator new(bytes);
  void* p = nullptr;
  const std::size_t rounded = (bytes + kHuge - 1) / kHuge * kHuge;
  if (posix_memalign(&p, kHuge, rounded) != 0) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  madvise(p, rounded, MADV_HUGEPAGE);  // a hint: failure only costs speed
#endif
  return p;
}

void release_large(void* p, std::size_t bytes) {
  if (!large(bytes)) {
    ::operator delete(p);
  } else {
    std::free(p);
  }
}

}  // namespace disktune::detail
