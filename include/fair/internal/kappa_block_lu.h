// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Direct solver for the Jacobian of the kappa-curve system (kappa_system.h): a square matrix
// of 4x4 blocks in which block row i only has the column blocks i-2, i-1, i, i+1 ("slots"
// 0..3), clipped at the ends for open curves and cyclic for closed curves.
//
//  - Open structure: block LU without block pivoting. Row i has no entry right of column
//    block i+1, so the factors keep the pattern (no fill-in): L has the slots 0 and 1, U the
//    slots 2 and 3. Cost O(n): per block row one 4x4 inversion and four 4x4 products (about
//    300 multiply-adds); a solve costs about 64 multiply-adds per block row.
//  - Cyclic structure: A = B + U V^T, where B is A without its four wrap-around blocks
//    (row 0: columns n-2, n-1; row 1: column n-1; row n-1: column 0) and V^T x picks the
//    unknowns of the column blocks n-2, n-1, 0. Sherman-Morrison-Woodbury:
//      A^{-1} b = y - Z (I + V^T Z)^{-1} V^T y,   y = B^{-1} b,   Z = B^{-1} U,
//    with Z computed once per factorisation (one solve per non-zero column of U, at most 12).
//    This keeps the cost O(n) without the doubled bandwidth of a cyclic reordering.
//    Cyclic systems of fewer than 6 block rows are factored densely with partial pivoting.
//
// Accuracy and degenerate cases: each diagonal 4x4 pivot block is inverted by Gaussian
// elimination with partial pivoting. Without pivoting across blocks the factorisation is not
// backward stable in general; it is used inside a Newton iteration whose step is validated by
// a line search, and factor() returns false on a numerically singular pivot block (pivot below
// 1e-13 of the block's largest entry, or non-finite values) or a singular Woodbury capacitance
// matrix, so that the caller can fall back to a pivoted (Levenberg-Marquardt) solve.

#ifndef FAIR_INTERNAL_KAPPA_BLOCK_LU_H
#define FAIR_INTERNAL_KAPPA_BLOCK_LU_H

#include <fair/internal/kappa_banded.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// A 4x4 block, row-major.
typedef std::array<double, 16> Block4;

/// Inverts a 4x4 block by Gauss-Jordan elimination with partial pivoting. Returns false if a
/// pivot is below `relative_floor` times the largest entry of the block (or not finite).
inline bool invert_block(const Block4& a, Block4& inv, double relative_floor = 1e-13) {
  double m[4][8];
  double scale = 0;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      m[r][c] = a[4 * r + c];
      m[r][4 + c] = (r == c) ? 1.0 : 0.0;
      scale = std::max(scale, std::abs(a[4 * r + c]));
    }
  if (!(scale > 0) || !std::isfinite(scale)) return false;
  for (int k = 0; k < 4; ++k) {
    int p = k;
    for (int r = k + 1; r < 4; ++r)
      if (std::abs(m[r][k]) > std::abs(m[p][k])) p = r;
    if (!(std::abs(m[p][k]) > relative_floor * scale)) return false;
    if (p != k)
      for (int c = 0; c < 8; ++c) std::swap(m[k][c], m[p][c]);
    const double ip = 1.0 / m[k][k];
    for (int c = 0; c < 8; ++c) m[k][c] *= ip;
    for (int r = 0; r < 4; ++r) {
      if (r == k || m[r][k] == 0.0) continue;
      const double f = m[r][k];
      for (int c = 0; c < 8; ++c) m[r][c] -= f * m[k][c];
    }
  }
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) inv[4 * r + c] = m[r][4 + c];
  return true;
}

/// c = a * b (4x4 blocks).
inline void multiply_blocks(const Block4& a, const Block4& b, Block4& c) {
  for (int r = 0; r < 4; ++r)
    for (int col = 0; col < 4; ++col)
      c[4 * r + col] = a[4 * r] * b[col] + a[4 * r + 1] * b[4 + col] + a[4 * r + 2] * b[8 + col] +
                       a[4 * r + 3] * b[12 + col];
}

/// c -= a * b (4x4 blocks).
inline void subtract_product(const Block4& a, const Block4& b, Block4& c) {
  for (int r = 0; r < 4; ++r)
    for (int col = 0; col < 4; ++col)
      c[4 * r + col] -= a[4 * r] * b[col] + a[4 * r + 1] * b[4 + col] + a[4 * r + 2] * b[8 + col] +
                        a[4 * r + 3] * b[12 + col];
}

/// y -= a * x (4x4 block times 4-vector).
inline void subtract_product(const Block4& a, const double* x, double* y) {
  for (int r = 0; r < 4; ++r)
    y[r] -= a[4 * r] * x[0] + a[4 * r + 1] * x[1] + a[4 * r + 2] * x[2] + a[4 * r + 3] * x[3];
}

class Block_band_lu {
public:
  /// n block rows; cyclic: closed-curve structure, else clipped.
  void reset(std::size_t n, bool cyclic) {
    resize(n, cyclic);
    std::fill(a_.begin(), a_.end(), Block4{});
  }
  /// As reset(), but the blocks keep stale values: the caller sets every block (all four slots
  /// of every row, zero where the structure has no block). Saves one pass over the storage.
  void resize(std::size_t n, bool cyclic) {
    n_ = n;
    cyclic_ = cyclic;
    dense_ = cyclic && n < small_cyclic;
    a_.resize(4 * n_);
    z_.clear();
    wrap_columns_.clear();
  }
  std::size_t blocks() const { return n_; }

  /// Block of row i at slot k (column block i-2+k, cyclically or -- open -- when it exists).
  Block4& block(std::size_t i, int k) { return a_[4 * i + static_cast<std::size_t>(k)]; }
  const Block4& block(std::size_t i, int k) const { return a_[4 * i + static_cast<std::size_t>(k)]; }

  /// Factorises in place. Returns false on a numerically singular pivot block or capacitance.
  bool factor() {
    if (dense_) return factor_dense();
    Block4 inv, l;
    for (std::size_t k = 0; k < n_; ++k) {
      if (!invert_block(block(k, 2), inv)) return false;
      block(k, 2) = inv;  // D_k^{-1}
      for (std::size_t i = k + 1; i <= k + 2 && i < n_; ++i) {
        const int s = static_cast<int>(k + 2 - i);  // slot of column k in row i
        multiply_blocks(block(i, s), inv, l);
        block(i, s) = l;                                            // L_{ik}
        if (k + 1 < n_) subtract_product(l, block(k, 3), block(i, s + 1));  // U_{k,k+1}
      }
    }
    if (cyclic_) return factor_wrap();
    return true;
  }

  /// Solves A x = b in place (after a successful factor()); b has 4n entries.
  void solve(double* b) const {
    if (dense_) { dense_lu_.solve(b); return; }
    solve_open(b);
    if (!cyclic_ || wrap_columns_.empty()) return;
    const std::size_t m = wrap_columns_.size();
    std::vector<double> s(m);
    for (std::size_t c = 0; c < m; ++c) s[c] = b[wrap_columns_[c]];
    capacitance_.solve(s.data());
    const double* z = z_.data();
    for (std::size_t r = 0; r < 4 * n_; ++r, z += m) {
      double v = 0;
      for (std::size_t c = 0; c < m; ++c) v += z[c] * s[c];
      b[r] -= v;
    }
  }

private:
  // Below this many blocks a cyclic matrix has slots naming the same column block (n <= 3) or
  // is too small for the Woodbury splitting to pay: it is factored densely (partial pivoting).
  static constexpr std::size_t small_cyclic = 6;

  bool factor_dense() {
    const std::size_t N = 4 * n_;
    dense_lu_.reset(N, N - 1, N - 1);
    for (std::size_t i = 0; i < n_; ++i)
      for (int k = 0; k < 4; ++k) {
        const std::size_t c = (i + n_ * 2 + static_cast<std::size_t>(k) - 2) % n_;
        for (int r = 0; r < 4; ++r)
          for (int q = 0; q < 4; ++q) dense_lu_.add(4 * i + r, 4 * c + q, block(i, k)[4 * r + q]);
      }
    return dense_lu_.factor();
  }

  /// y = B^{-1} b for the open part B (the wrap-around blocks ignored).
  void solve_open(double* b) const {
    // Forward: L y = b (unit block diagonal).
    for (std::size_t i = 1; i < n_; ++i) {
      subtract_product(block(i, 1), b + 4 * (i - 1), b + 4 * i);
      if (i >= 2) subtract_product(block(i, 0), b + 4 * (i - 2), b + 4 * i);
    }
    // Backward: U x = y with U_{kk} = D_k (its inverse stored), U_{k,k+1} in slot 3.
    double tmp[4];
    for (std::size_t k = n_; k-- > 0;) {
      double* x = b + 4 * k;
      if (k + 1 < n_) subtract_product(block(k, 3), b + 4 * (k + 1), x);
      const Block4& inv = block(k, 2);
      for (int r = 0; r < 4; ++r) tmp[r] = inv[4 * r] * x[0] + inv[4 * r + 1] * x[1] + inv[4 * r + 2] * x[2] + inv[4 * r + 3] * x[3];
      for (int r = 0; r < 4; ++r) x[r] = tmp[r];
    }
  }

  /// Y = B^{-1} Y for m right-hand sides at once, Y row-major (4n x m): one sweep over the
  /// factors instead of m (the factors dominate the memory traffic for large n). The usual
  /// m = 8 (kappa_solver.h: x, y of P_{n-2}; x, y, lambda of P_{n-1} and P_0) has its own
  /// fixed-size instance, which the compiler vectorises.
  void solve_open(double* Y, std::size_t m) const {
    if (m == 8) solve_open_panels<8>(Y, 8);
    else solve_open_panels<0>(Y, m);
  }

  /// solve_open for M right-hand sides (M = 0: m given at run time).
  template <std::size_t M>
  void solve_open_panels(double* Y, std::size_t m_runtime) const {
    const std::size_t m = M ? M : m_runtime;
    auto subtract = [m](const Block4& a, const double* x, double* y) {  // y -= a x (4 x m panels)
      for (int r = 0; r < 4; ++r) {
        double* yr = y + static_cast<std::size_t>(r) * m;
        const double a0 = a[4 * r], a1 = a[4 * r + 1], a2 = a[4 * r + 2], a3 = a[4 * r + 3];
        for (std::size_t c = 0; c < m; ++c) yr[c] -= a0 * x[c] + a1 * x[m + c] + a2 * x[2 * m + c] + a3 * x[3 * m + c];
      }
    };
    const std::size_t panel = 4 * m;
    for (std::size_t i = 1; i < n_; ++i) {
      subtract(block(i, 1), Y + panel * (i - 1), Y + panel * i);
      if (i >= 2) subtract(block(i, 0), Y + panel * (i - 2), Y + panel * i);
    }
    std::vector<double> tmp(panel);
    for (std::size_t k = n_; k-- > 0;) {
      double* x = Y + panel * k;
      if (k + 1 < n_) subtract(block(k, 3), Y + panel * (k + 1), x);
      const Block4& inv = block(k, 2);
      for (int r = 0; r < 4; ++r) {
        double* tr = tmp.data() + static_cast<std::size_t>(r) * m;
        const double a0 = inv[4 * r], a1 = inv[4 * r + 1], a2 = inv[4 * r + 2], a3 = inv[4 * r + 3];
        for (std::size_t c = 0; c < m; ++c) tr[c] = a0 * x[c] + a1 * x[m + c] + a2 * x[2 * m + c] + a3 * x[3 * m + c];
      }
      std::copy(tmp.begin(), tmp.end(), x);
    }
  }

  /// Woodbury data for the cyclic wrap-around blocks (see the file comment).
  bool factor_wrap() {
    const std::size_t N = 4 * n_;
    // Column blocks picked by V^T, and the wrap blocks (row, slot) of each.
    const std::size_t cols[3] = {n_ - 2, n_ - 1, 0};
    wrap_columns_.clear();
    std::vector<std::pair<int, int>> picked;  // (column block index in cols, component)
    auto wrap_block_value = [&](int cb, std::size_t row, int r, int q) -> double {
      if (cb == 0) return row == 0 ? block(0, 0)[4 * r + q] : 0.0;
      if (cb == 1) return row == 0 ? block(0, 1)[4 * r + q] : row == 1 ? block(1, 0)[4 * r + q] : 0.0;
      return row == n_ - 1 ? block(n_ - 1, 3)[4 * r + q] : 0.0;
    };
    const std::size_t rows[3] = {0, 1, n_ - 1};
    for (int cb = 0; cb < 3; ++cb)
      for (int q = 0; q < 4; ++q) {
        bool nonzero = false;
        for (std::size_t row : rows)
          for (int r = 0; r < 4; ++r) nonzero = nonzero || wrap_block_value(cb, row, r, q) != 0.0;
        if (!nonzero) continue;  // e.g. t_j never enters a wrap-around residual
        picked.emplace_back(cb, q);
        wrap_columns_.push_back(4 * cols[cb] + static_cast<std::size_t>(q));
      }
    const std::size_t m = wrap_columns_.size();
    if (m == 0) return true;
    z_.assign(N * m, 0.0);  // U, row-major
    for (std::size_t c = 0; c < m; ++c)
      for (std::size_t row : rows)
        for (int r = 0; r < 4; ++r)
          z_[(4 * row + static_cast<std::size_t>(r)) * m + c] = wrap_block_value(picked[c].first, row, r, picked[c].second);
    solve_open(z_.data(), m);  // Z = B^{-1} U
    for (double v : z_)
      if (!std::isfinite(v)) return false;
    capacitance_.reset(m, m - 1, m - 1);
    for (std::size_t r = 0; r < m; ++r)
      for (std::size_t c = 0; c < m; ++c) capacitance_.add(r, c, (r == c ? 1.0 : 0.0) + z_[wrap_columns_[r] * m + c]);
    return capacitance_.factor();
  }

  std::size_t n_ = 0;
  bool cyclic_ = false, dense_ = false;
  std::vector<Block4> a_;
  std::vector<double> z_;                  // Z = B^{-1} U, row-major (4n x m)
  std::vector<std::size_t> wrap_columns_;  // unknown index picked by each column of V
  Banded_lu capacitance_;                  // I + V^T Z (dense: bandwidths m-1)
  Banded_lu dense_lu_;                     // small cyclic systems
};

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_BLOCK_LU_H
