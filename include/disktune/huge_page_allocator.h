// SPDX-License-Identifier: GPL-3.0-or-later
// An allocator for the large arrays that are read at random (grids of 10^6 cells and
// more): it asks Linux for transparent huge pages, so random reads stop paying a TLB
// miss on top of the cache miss, and filling the array faults in one page where it
// faulted in 512 (a fault costs these machines about 11 µs). Small arrays and other
// systems get plain memory.
#pragma once

#include <cstddef>

namespace disktune::detail {

/// `bytes` of memory, on huge pages where they are large and the system has them
/// (src/packing/huge_pages.cpp); std::bad_alloc where there is none.
void* allocate_large(std::size_t bytes);
/// Gives back what allocate_large(bytes) gave.
void release_large(void* p, std::size_t bytes);

template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}

  T* allocate(std::size_t n) { return static_cast<T*>(allocate_large(n * sizeof(T))); }
  void deallocate(T* p, std::size_t n) { release_large(p, n * sizeof(T)); }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const {
    return true;
  }
  template <class U>
  bool operator!=(const HugePageAllocator<U>&) const {
    return false;
  }
};

}  // namespace disktune::detail
