// An allocator for the large per-vertex arrays of the topology searches: on Linux, blocks of 2 MiB
// or more are 2 MiB-aligned and marked for transparent huge pages (madvise MADV_HUGEPAGE), which
// the kernel then backs with 2 MiB pages when it can. A search that jumps around arrays of tens of
// megabytes then takes 512 times fewer page faults on first touch and far fewer TLB misses.
// Elsewhere, or for smaller blocks, it is std::allocator.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace tessera::internal {

template <typename T> struct Huge_page_allocator {
  using value_type = T;

  Huge_page_allocator() = default;
  template <typename U> Huge_page_allocator(const Huge_page_allocator<U>&) {}

  T* allocate(std::size_t n) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (n > max_size())
      throw std::bad_array_new_length();
    if (huge(n)) {
      const std::size_t bytes = rounded(n);
      void* p = std::aligned_alloc(huge_page, bytes);
      if (p == nullptr)
        throw std::bad_alloc();
      madvise(p, bytes, MADV_HUGEPAGE); // a hint: failure leaves ordinary pages
      return static_cast<T*>(p);
    }
#endif
    return std::allocator<T>().allocate(n);
  }

  void deallocate(T* p, std::size_t n) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (huge(n)) {
      std::free(p);
      return;
    }
#endif
    std::allocator<T>().deallocate(p, n);
  }

  static constexpr std::size_t max_size() {
    return std::size_t(-1) / 2 / sizeof(T);
  }

  friend bool operator==(const Huge_page_allocator&, const Huge_page_allocator&) {
    return true;
  }
  friend bool operator!=(const Huge_page_allocator&, const Huge_page_allocator&) {
    return false;
  }

private:
  static constexpr std::size_t huge_page = std::size_t(1) << 21;
  // Whether a block of n elements goes to huge pages (the same answer in allocate and deallocate).
  static bool huge(std::size_t n) {
    return n * sizeof(T) >= huge_page && alignof(T) <= huge_page;
  }
  static std::size_t rounded(std::size_t n) {
    return (n * sizeof(T) + huge_page - 1) & ~(huge_page - 1);
  }
};

} // namespace tessera::internal
