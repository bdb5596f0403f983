// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The "zig-zag" order 0, n-1, 1, n-2, 2, ... of the unknowns of a cyclic band matrix (closed
// curves: banded plus wrap-around corners): it turns the cyclic band of half bandwidth w into an
// ordinary band of half bandwidth <= 2w + 1, so that one banded solver (banded_lu.h,
// banded_cholesky.h) serves open and closed curves alike. Used by the kappa-curve solver (block
// order of J^T J and of its pivoted fallback) and the optimal-curve solver (symmetric_band.h).

#ifndef FAIR_INTERNAL_LINEAR_ALGEBRA_CYCLIC_ORDER_H
#define FAIR_INTERNAL_LINEAR_ALGEBRA_CYCLIC_ORDER_H

#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace linear_algebra {

/// Position of block j (0 <= j < n) in the zig-zag order 0, n-1, 1, n-2, 2, ...
/// Blocks at cyclic distance d end up at most 2d positions apart... precisely |pos(a)-pos(b)|
/// <= 2d + 1 when a and b are d apart cyclically.
inline std::size_t cyclic_position(std::size_t j, std::size_t n) {
  return (2 * j <= n - 1) ? 2 * j : 2 * (n - j) - 1;
}

/// The inverse permutation of cyclic_position ("folding order"): order[p] = the index at
/// position p. It turns a cyclic band of half-bandwidth w into a plain band of half-bandwidth
/// <= 2w (doc/optimal_curves.md, "Banded solve": neighbours i, i+d at positions 2i, 2i+2d; across
/// the wrap and across the fold |4m + 3 - 2d| <= 2d - 1).
inline void folding_order(std::size_t n, std::vector<std::size_t>& order) {
  order.resize(n);
  for (std::size_t j = 0; j < n; ++j) order[cyclic_position(j, n)] = j;
}

} // namespace linear_algebra
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_LINEAR_ALGEBRA_CYCLIC_ORDER_H
