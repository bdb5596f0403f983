// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Uninitialised storage for the large work arrays of the O(n) solvers (the kappa-curve block
// LU: 512 bytes per point). Why not std::vector: above glibc's mmap threshold (at most 32 MB)
// every allocation is a fresh mapping, and each 4 KiB page costs a page fault on first touch --
// on a 10^5-point kappa-curve a quarter of the solve (doc/benchmarks.md). On Linux, buffers of
// 2 MiB or more are therefore aligned to 2 MiB and marked MADV_HUGEPAGE, so that the kernel
// maps them with transparent huge pages (512 times fewer faults) when its policy allows; where
// it does not, or elsewhere, they are ordinary allocations. The contents are never read before
// they are written, so no zero-fill is paid for.

#ifndef FAIR_INTERNAL_COMMON_LARGE_BUFFER_H
#define FAIR_INTERNAL_COMMON_LARGE_BUFFER_H

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <type_traits>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace fair {
namespace internal {

/// A growable array of trivially copyable T whose elements are uninitialised after reserve()
/// (see the file comment). Not copyable; moves transfer the storage.
template <class T>
class Large_buffer {
  static_assert(std::is_trivially_copyable<T>::value && std::is_trivially_destructible<T>::value,
                "Large_buffer holds trivially copyable values only");
  static_assert(alignof(T) <= alignof(std::max_align_t), "Large_buffer: malloc's alignment must suffice");

public:
  /// On Linux, buffers of this size or more are aligned to it and offered to transparent huge
  /// pages.
  static constexpr std::size_t huge_page = std::size_t(2) << 20;

  Large_buffer() = default;
  Large_buffer(const Large_buffer&) = delete;
  Large_buffer& operator=(const Large_buffer&) = delete;
  Large_buffer(Large_buffer&& o) noexcept : data_(o.data_), capacity_(o.capacity_) {
    o.data_ = nullptr;
    o.capacity_ = 0;
  }
  Large_buffer& operator=(Large_buffer&& o) noexcept {
    if (this != &o) {
      std::free(data_);
      data_ = o.data_;
      capacity_ = o.capacity_;
      o.data_ = nullptr;
      o.capacity_ = 0;
    }
    return *this;
  }
  ~Large_buffer() { std::free(data_); }

  /// Room for at least `count` elements; the old contents are dropped when it grows.
  /// Throws std::bad_alloc.
  void reserve(std::size_t count) {
    if (count <= capacity_) return;
    std::free(data_);
    data_ = nullptr;
    capacity_ = 0;
    if (count > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_alloc();
    std::size_t bytes = count * sizeof(T);
    void* p = nullptr;
#if defined(__linux__)
    if (bytes >= huge_page) {
      if (bytes > SIZE_MAX - (huge_page - 1)) throw std::bad_alloc();
      bytes = (bytes + huge_page - 1) / huge_page * huge_page;  // aligned_alloc: a multiple of the alignment
      p = std::aligned_alloc(huge_page, bytes);
#if defined(MADV_HUGEPAGE)
      if (p != nullptr) madvise(p, bytes, MADV_HUGEPAGE);  // advice only: failure changes nothing
#endif
    } else
#endif
    {
      p = std::malloc(bytes > 0 ? bytes : 1);
    }
    if (p == nullptr) throw std::bad_alloc();
    data_ = static_cast<T*>(p);
    capacity_ = bytes / sizeof(T);
  }

  std::size_t capacity() const { return capacity_; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }

private:
  T* data_ = nullptr;
  std::size_t capacity_ = 0;
};

} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_COMMON_LARGE_BUFFER_H
