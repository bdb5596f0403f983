// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// A value computed on first use and kept: how a family hands out `const std::vector<Piece>&
// pieces()` (doc/concepts.md) without building every piece in its constructor when the pieces
// are only a view of a representation it already stores (Csr_spline_2: 10^6 Bezier pieces are
// 10^6 heap blocks, more than the whole construction of the spline; doc/benchmarks.md).
//
// Thread-safe as the standard library's const members are: concurrent get() calls compute the
// value once (double-checked, an acquire/release flag and a mutex); copies and moves take the
// value if it is there, else start empty.

#ifndef FAIR_INTERNAL_COMMON_LAZY_CACHE_H
#define FAIR_INTERNAL_COMMON_LAZY_CACHE_H

#include <atomic>
#include <mutex>
#include <utility>

namespace fair {
namespace internal {
namespace common {

template <class T>
class Lazy_cache {
public:
  Lazy_cache() = default;
  Lazy_cache(const Lazy_cache& other) { take(other, false); }
  Lazy_cache(Lazy_cache&& other) noexcept { take(other, true); }
  Lazy_cache& operator=(const Lazy_cache& other) {
    if (this != &other) {
      Lazy_cache copy(other);
      *this = std::move(copy);
    }
    return *this;
  }
  Lazy_cache& operator=(Lazy_cache&& other) noexcept {
    if (this != &other) {
      std::scoped_lock lock(mutex_, other.mutex_);
      value_ = std::move(other.value_);
      ready_.store(other.ready_.load(std::memory_order_relaxed), std::memory_order_release);
    }
    return *this;
  }

  /// The value, computed by make() on the first call.
  template <class Make>
  const T& get(Make make) const {
    if (!ready_.load(std::memory_order_acquire)) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!ready_.load(std::memory_order_relaxed)) {
        value_ = make();
        ready_.store(true, std::memory_order_release);
      }
    }
    return value_;
  }

private:
  void take(const Lazy_cache& other, bool move) {
    std::lock_guard<std::mutex> lock(other.mutex_);
    if (!other.ready_.load(std::memory_order_relaxed)) return;
    value_ = move ? std::move(other.value_) : other.value_;
    ready_.store(true, std::memory_order_release);
  }

  mutable std::mutex mutex_;
  mutable std::atomic<bool> ready_{false};
  mutable T value_;
};

}  // namespace common
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_COMMON_LAZY_CACHE_H
