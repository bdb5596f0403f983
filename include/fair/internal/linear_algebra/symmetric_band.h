// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Symmetric band matrices, optionally cyclic (closed curves), and their O(n w^2) Cholesky solve
// (doc/optimal_curves.md, "Banded solve"): the storage rule Band_layout, shared by the scalar
// matrix Banded_symmetric (the reduced Newton system of the optimal-curve solver) and the 2x2-block
// Hessian of optimal/hessian.h; solve_banded_positive_definite reorders a cyclic band by the
// folding order of cyclic_order.h and factors it with banded_cholesky.h.
//
// Storage. Row i keeps the entries (blocks) (i, i + d) for d = 0..w (i + d taken mod n when
// cyclic); the entry (i, j) with j "before" i is the transpose of the stored (j, i). A cyclic
// matrix with n <= 2w + 1 has every pair within cyclic distance w, and the two directions round
// the cycle would both be within w: it is stored dense (n <= 2w + 1 is tiny), which keeps at(i, j)
// and at(j, i) one entry. Memory O(n w) in both cases (no n^2 storage).

#ifndef FAIR_INTERNAL_LINEAR_ALGEBRA_SYMMETRIC_BAND_H
#define FAIR_INTERNAL_LINEAR_ALGEBRA_SYMMETRIC_BAND_H

#include <fair/Errors.h>
#include <fair/internal/linear_algebra/banded_cholesky.h>
#include <fair/internal/linear_algebra/cyclic_order.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace linear_algebra {

/// Where the entry (i, j) of a symmetric band matrix lives: slot (row, offset) and whether it is the
/// transpose of the stored one. Shared by the block and the scalar matrix.
struct Band_layout {
  std::size_t n = 0, w = 0;
  bool cyclic = false, dense = false;

  void reset(std::size_t vertices, std::size_t half_bandwidth, bool is_cyclic) {
    n = vertices;
    w = half_bandwidth;
    cyclic = is_cyclic;
    dense = cyclic && n <= 2 * w + 1;
  }
  std::size_t slots() const { return dense ? n * n : n * (w + 1); }
  /// Cyclic (or plain) distance of i and j.
  std::size_t distance(std::size_t i, std::size_t j) const {
    const std::size_t d = i > j ? i - j : j - i;
    return cyclic ? std::min(d, n - d) : d;
  }
  bool in_band(std::size_t i, std::size_t j) const { return i < n && j < n && distance(i, j) <= w; }
  /// The slot of (i, j); `transposed` tells whether the slot holds (j, i).
  std::size_t slot(std::size_t i, std::size_t j, bool& transposed) const {
    FAIR_ASSERT_MSG(in_band(i, j), "entry (", i, ", ", j, ") outside the band ", w, " of a matrix of size ", n,
                    cyclic ? " (cyclic)" : "");
    if (dense) {
      transposed = i > j;
      return transposed ? j * n + i : i * n + j;
    }
    std::size_t d;
    if (cyclic) {
      d = j >= i ? j - i : j + n - i;  // (j - i) mod n without a division
      transposed = d > w;
      if (transposed) return j * (w + 1) + (n - d);
      return i * (w + 1) + d;
    }
    transposed = j < i;
    if (transposed) return j * (w + 1) + (i - j);
    return i * (w + 1) + (j - i);
  }
};

/// Scalar symmetric banded (cyclic if `cyclic`) matrix: the reduced Newton system of the
/// optimal-curve solver (optimal/reduced_system.h).
class Banded_symmetric {
public:
  void reset(std::size_t n, std::size_t half_bandwidth, bool cyclic) {
    layout_.reset(n, half_bandwidth, cyclic);
    data_.assign(layout_.slots(), 0.0);
  }
  std::size_t size() const { return layout_.n; }
  std::size_t half_bandwidth() const { return layout_.w; }
  bool cyclic() const { return layout_.cyclic; }
  bool in_band(std::size_t i, std::size_t j) const { return layout_.in_band(i, j); }
  /// Entry (i, j) = entry (j, i) for cyclic distance |i - j| <= w; Internal_error outside the band.
  double& at(std::size_t i, std::size_t j) {
    bool t;
    return data_[layout_.slot(i, j, t)];
  }
  double at(std::size_t i, std::size_t j) const {
    bool t;
    return data_[layout_.slot(i, j, t)];
  }
  void add_to_diagonal(double shift) {
    for (std::size_t i = 0; i < layout_.n; ++i) at(i, i) += shift;
  }

private:
  Band_layout layout_;
  std::vector<double> data_;
};

/// Solves A x = b for symmetric positive definite A by banded Cholesky A = L L^T: O(n w^2) time, O(n w)
/// memory. A cyclic A is first reordered by the folding order (half-bandwidth <= 2w, still O(n w^2); a
/// cyclic A with n <= 2w + 1 is dense and tiny). Returns false, leaving `rhs_in_solution_out` unchanged,
/// if a pivot is <= 0 or not finite (A not positive definite to working precision), so that the caller
/// can shift the diagonal and retry; never throws for that.
inline bool solve_banded_positive_definite(const Banded_symmetric& a, std::vector<double>& rhs_in_solution_out) {
  const std::size_t n = a.size();
  require(rhs_in_solution_out.size() == n, "solve_banded_positive_definite: right-hand side of size ",
          rhs_in_solution_out.size(), " for a matrix of size ", n);
  if (n == 0) return true;
  // Workspace kept per thread across calls: a Newton iteration solves systems of the same size
  // repeatedly, and fresh multi-megabyte buffers cost a page fault per 4 KiB each time (more than the
  // factorisation itself at n = 1e5). It holds O(n w) doubles of the largest system solved so far.
  thread_local std::vector<std::size_t> order, position;  // position -> original index, and back
  thread_local std::vector<double> x;
  std::size_t wb;  // half-bandwidth of the reordered plain band
  const std::size_t w = a.half_bandwidth();
  if (!a.cyclic()) {
    order.resize(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    wb = std::min(w, n - 1);
  } else if (n <= 2 * w + 1) {
    order.resize(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    wb = n - 1;
  } else {
    folding_order(n, order);
    wb = std::min(2 * w, n - 1);
  }
  position.resize(n);
  for (std::size_t p = 0; p < n; ++p) position[order[p]] = p;
  // The reordered matrix, entry (p, q) with q in [p - wb, p], factored by the library's one banded
  // Cholesky (banded_cholesky.h).
  thread_local Banded_cholesky chol;
  chol.reset(n, wb);
  const std::size_t reach = a.cyclic() ? std::min(w, n - 1) : w;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t d = 0; d <= reach; ++d) {
      if (!a.cyclic() && i + d >= n) break;
      const std::size_t j = (i + d) % n;
      if (!a.in_band(i, j)) continue;
      std::size_t p = position[i], q = position[j];
      if (p < q) std::swap(p, q);
      FAIR_ASSERT_MSG(p - q <= wb, "reordered entry (", p, ", ", q, ") outside the band ", wb);
      chol.set_lower(p, q, a.at(i, j));  // set, not add: a small cyclic matrix meets a pair twice
    }
  if (!chol.factor()) return false;
  x.resize(n);
  for (std::size_t p = 0; p < n; ++p) x[p] = rhs_in_solution_out[order[p]];
  chol.solve(x.data());
  for (std::size_t p = 0; p < n; ++p)
    if (!std::isfinite(x[p])) return false;
  for (std::size_t p = 0; p < n; ++p) rhs_in_solution_out[order[p]] = x[p];
  return true;
}

} // namespace linear_algebra
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_LINEAR_ALGEBRA_SYMMETRIC_BAND_H
