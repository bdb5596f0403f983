// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The pivoted fallback of Newton's method (newton.h): the same Jacobian in a general band
// matrix factored with partial pivoting (linear_algebra/banded_lu.h), for the rare singular
// pivot block of the block LU (linear_algebra/block_band_lu.h), which does not pivot across
// blocks.

#ifndef FAIR_INTERNAL_KAPPA_PIVOTED_FALLBACK_H
#define FAIR_INTERNAL_KAPPA_PIVOTED_FALLBACK_H

#include <fair/internal/kappa/banded.h>
#include <fair/internal/kappa/block_range.h>
#include <fair/internal/kappa/system.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// The Jacobian of newton() (blocks of `range`, na of them; fill(ii, row) as for
/// Block_band_lu::factor_rows) into a general band matrix with partial pivoting, in the block
/// order of normal_bandwidth (zig-zag for a whole closed curve, natural otherwise): the fallback
/// when the block LU, which does not pivot across blocks, meets a singular pivot block of a
/// non-singular matrix (dense data near inflections). Half bandwidths 4 * 2 + 3 = 11 (lower)
/// and 4 * 1 + 3 = 7 (upper) in natural order, <= 4 * 5 + 3 = 23 in zig-zag order: O(n), about
/// 3x the work of the block LU. Returns false on an exactly singular matrix.
template <class Fill>
bool factor_pivoted(const Problem& pb, const Block_range& range, std::size_t na, Fill&& fill, Banded_lu& plu) {
  const std::size_t n = pb.n, N = 4 * na;
  const bool zigzag = range.all && pb.closed;
  auto pos = [&](std::size_t j) { return zigzag ? cyclic_position(j, n) : j; };
  auto column_block = [&](std::size_t ii, int k) -> long {
    long b = static_cast<long>(ii) - 2 + k;
    if (zigzag) return ((b % static_cast<long>(n)) + static_cast<long>(n)) % static_cast<long>(n);
    return b;
  };
  std::size_t kl = 0, ku = 0;
  for (std::size_t ii = 0; ii < na; ++ii)
    for (int k = 0; k < 4; ++k) {
      const long b = column_block(ii, k);
      if (b < 0 || b >= static_cast<long>(na)) continue;
      const std::size_t pr = pos(ii), pc = pos(static_cast<std::size_t>(b));
      if (pc < pr) kl = std::max(kl, 4 * (pr - pc) + 3);
      else ku = std::max(ku, 4 * (pc - pr) + 3);
    }
  kl = std::min(kl, N - 1);
  ku = std::min(ku, N - 1);
  plu.reset(N, kl, ku);
  Block4 row[4];
  for (std::size_t ii = 0; ii < na; ++ii) {
    fill(ii, row);
    for (int k = 0; k < 4; ++k) {
      const long b = column_block(ii, k);
      if (b < 0 || b >= static_cast<long>(na)) continue;
      const std::size_t r0 = 4 * pos(ii), c0 = 4 * pos(static_cast<std::size_t>(b));
      for (int e = 0; e < 4; ++e)
        for (int c = 0; c < 4; ++c)
          if (row[k][4 * e + c] != 0.0) plu.add(r0 + e, c0 + c, row[k][4 * e + c]);
    }
  }
  return plu.factor();
}

/// v = J^{-1} v by the factorisation of factor_pivoted, whose unknowns are in zig-zag order for
/// a whole closed curve (`permuted`: workspace).
inline void solve_pivoted(const Problem& pb, const Block_range& range, std::size_t na, const Banded_lu& plu,
                          std::vector<double>& v, std::vector<double>& permuted) {
  const bool zigzag = range.all && pb.closed;
  if (!zigzag) { plu.solve(v.data()); return; }
  const std::size_t n = pb.n;
  permuted.resize(4 * na);
  for (std::size_t ii = 0; ii < na; ++ii)
    for (int c = 0; c < 4; ++c) permuted[4 * cyclic_position(ii, n) + c] = v[4 * ii + c];
  plu.solve(permuted.data());
  for (std::size_t ii = 0; ii < na; ++ii)
    for (int c = 0; c < 4; ++c) v[4 * ii + c] = permuted[4 * cyclic_position(ii, n) + c];
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_PIVOTED_FALLBACK_H
