// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Direct solver for the Jacobian of the kappa-curve system (kappa/system.h): a square matrix
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
//    with Z computed once per factorisation: U has at most 12 non-zero columns (supported on
//    the block rows 0, 1 and n-1; 8 for the kappa Jacobian, whose t columns never wrap), and
//    the columns of Z ("spikes") decay geometrically away from those rows, so they are computed
//    and stored only until they have died out (below 1e-40 of their largest entry): O(1) extra
//    work per factorisation on typical data, O(n) at worst, without the doubled bandwidth of a
//    cyclic reordering.
//    Cyclic systems of fewer than 6 block rows are factored densely with partial pivoting.
//
// Accuracy and degenerate cases: each diagonal 4x4 pivot block is inverted by Gaussian
// elimination with partial pivoting. Without pivoting across blocks the factorisation is not
// backward stable in general; it is used inside a Newton iteration whose step is validated by
// a line search, and factor() returns false on a numerically singular pivot block (pivot below
// 1e-13 of the block's largest entry, or non-finite values), a singular Woodbury capacitance
// matrix or a Woodbury correction that would cancel more than 8 digits (max |Z| > 1e8 max |U|),
// so that the caller can fall back to a pivoted (Levenberg-Marquardt) solve. An accepted
// factorisation can still be inaccurate (no pivoting across blocks): the Newton step it gives is
// accepted only if the line search confirms a decrease of the residual.

#ifndef FAIR_INTERNAL_LINEAR_ALGEBRA_BLOCK_BAND_LU_H
#define FAIR_INTERNAL_LINEAR_ALGEBRA_BLOCK_BAND_LU_H

#include <fair/internal/common/large_buffer.h>
#include <fair/internal/linear_algebra/banded_lu.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace linear_algebra {

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
    std::fill(a_.data(), a_.data() + 4 * n_, Block4{});
  }
  /// As reset(), but the blocks keep stale values: the caller sets every block (all four slots
  /// of every row, zero where the structure has no block). Saves one pass over the storage.
  void resize(std::size_t n, bool cyclic) {
    a_.reserve(4 * n);  // first (may throw): uninitialised, no zero-fill of storage about to be set
    n_ = n;
    cyclic_ = cyclic;
    dense_ = cyclic && n < small_cyclic;
    wrap_columns_.clear();
  }
  std::size_t blocks() const { return n_; }

  /// Block of row i at slot k (column block i-2+k, cyclically or -- open -- when it exists).
  Block4& block(std::size_t i, int k) { return a_[4 * i + static_cast<std::size_t>(k)]; }
  const Block4& block(std::size_t i, int k) const { return a_[4 * i + static_cast<std::size_t>(k)]; }

  /// Factorises in place. Returns false on a numerically singular pivot block or capacitance.
  bool factor() {
    if (dense_) return factor_dense();
    for (std::size_t i = 0; i < n_; ++i)
      if (!eliminate_row(i)) return false;
    if (cyclic_) return factor_wrap();
    return true;
  }

  /// Assembly, factorisation and forward substitution in one sweep (for large n the storage
  /// does not fit in cache; this touches it once instead of three times): fill(i, row) sets
  /// the four blocks row[0..3] of block row i (all of them, zero where the structure has no
  /// block), which is then eliminated at once; b (4n values) is forward-substituted along.
  /// Then finish_solve(b) completes b = A^{-1} b. Same operations as factor() and solve().
  template <class Fill>
  bool factor_rows(Fill&& fill, double* b) {
    for (std::size_t i = 0; i < n_; ++i) {
      fill(i, &a_[4 * i]);
      if (dense_) continue;
      if (!eliminate_row(i)) return false;
      forward_row(i, b);
    }
    if (dense_) return factor_dense();
    if (cyclic_) return factor_wrap();
    return true;
  }

  /// The rest of solve() after factor_rows() has forward-substituted b.
  void finish_solve(double* b) const {
    if (dense_) { dense_lu_.solve(b); return; }
    backward(b);
    woodbury_correction(b);
  }

  /// Solves A x = b in place (after a successful factor()); b has 4n entries.
  void solve(double* b) const {
    if (dense_) { dense_lu_.solve(b); return; }
    solve_open(b);
    woodbury_correction(b);
  }

private:
  /// Left-looking elimination of block row i (rows above already eliminated): L_{i,i-2},
  /// L_{i,i-1} and D_i^{-1} replace the slots 0, 1, 2; slot 3 is U_{i,i+1} unchanged.
  bool eliminate_row(std::size_t i) {
    Block4 l;
    if (i >= 2) {
      multiply_blocks(block(i, 0), block(i - 2, 2), l);
      block(i, 0) = l;                                   // L_{i,i-2}
      subtract_product(l, block(i - 2, 3), block(i, 1));
    }
    if (i >= 1) {
      multiply_blocks(block(i, 1), block(i - 1, 2), l);
      block(i, 1) = l;                                   // L_{i,i-1}
      subtract_product(l, block(i - 1, 3), block(i, 2));
    }
    Block4 inv;
    if (!invert_block(block(i, 2), inv)) return false;
    block(i, 2) = inv;                                   // D_i^{-1}
    return true;
  }

  /// Forward substitution of block row i: y_i = b_i - L_{i,i-1} y_{i-1} - L_{i,i-2} y_{i-2}.
  void forward_row(std::size_t i, double* b) const {
    if (i >= 1) subtract_product(block(i, 1), b + 4 * (i - 1), b + 4 * i);
    if (i >= 2) subtract_product(block(i, 0), b + 4 * (i - 2), b + 4 * i);
  }

  /// Backward substitution: U x = y with U_{kk} = D_k (its inverse stored), U_{k,k+1} in slot 3.
  void backward(double* b) const {
    double tmp[4];
    for (std::size_t k = n_; k-- > 0;) {
      double* x = b + 4 * k;
      if (k + 1 < n_) subtract_product(block(k, 3), b + 4 * (k + 1), x);
      const Block4& inv = block(k, 2);
      for (int r = 0; r < 4; ++r) tmp[r] = inv[4 * r] * x[0] + inv[4 * r + 1] * x[1] + inv[4 * r + 2] * x[2] + inv[4 * r + 3] * x[3];
      for (int r = 0; r < 4; ++r) x[r] = tmp[r];
    }
  }

  /// b -= Z (I + V^T Z)^{-1} V^T b: turns B^{-1} b into A^{-1} b (cyclic systems).
  void woodbury_correction(double* b) const {
    if (!cyclic_ || wrap_columns_.empty()) return;
    const std::size_t m = wrap_columns_.size();
    std::vector<double> s(m);
    for (std::size_t c = 0; c < m; ++c) s[c] = b[wrap_columns_[c]];
    capacitance_.solve(s.data());
    for (const Spike* z : {&top_, &bottom_}) {
      const std::size_t mc = z->columns.size();
      for (std::size_t r = 0; r < 4 * z->blocks; ++r) {
        const double* zr = &z->values[r * mc];
        double v = 0;
        for (std::size_t c = 0; c < mc; ++c) v += zr[c] * s[z->columns[c]];
        b[4 * z->first_block + r] -= v;
      }
    }
  }

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
    for (std::size_t i = 1; i < n_; ++i) forward_row(i, b);
    backward(b);
  }

  /// Columns of Z = B^{-1} U on the block rows first_block .. first_block + blocks - 1 (zero
  /// elsewhere), row-major; columns[c] is the index of column c among the columns of U.
  struct Spike {
    std::size_t first_block = 0, blocks = 0;
    std::vector<std::size_t> columns;
    std::vector<double> values;
    double at(std::size_t row, std::size_t c) const {  // Z(row, columns[c])
      const std::size_t f = 4 * first_block;
      return row >= f && row < f + 4 * blocks ? values[(row - f) * columns.size() + c] : 0.0;
    }
  };

  // Truncation of the spikes: a block row whose entries (and, forward, the previous one's)
  // are below this fraction of the largest entry so far ends the spike. B^{-1} of the kappa
  // system decays geometrically away from the diagonal (the solution's dependence on a point
  // is local), so the spikes are short -- O(1) instead of O(n) work and memory per
  // factorisation -- and the neglected entries are far below the rounding of the rest. A
  // system without decay simply gets full-length spikes.
  static constexpr double spike_floor = 1e-40;
  // Largest accepted max |Z| / max |U| (see factor_wrap).
  static constexpr double max_woodbury_growth = 1e8;

  /// y -= a x for panels of 4 x m values (row-major).
  static void subtract_panel(const Block4& a, const double* x, double* y, std::size_t m) {
    for (int r = 0; r < 4; ++r) {
      double* yr = y + static_cast<std::size_t>(r) * m;
      const double a0 = a[4 * r], a1 = a[4 * r + 1], a2 = a[4 * r + 2], a3 = a[4 * r + 3];
      for (std::size_t c = 0; c < m; ++c) yr[c] -= a0 * x[c] + a1 * x[m + c] + a2 * x[2 * m + c] + a3 * x[3 * m + c];
    }
  }
  /// x = a x for a panel of 4 x m values.
  static void multiply_panel(const Block4& a, double* x, std::size_t m, std::vector<double>& tmp) {
    tmp.assign(4 * m, 0.0);
    for (int r = 0; r < 4; ++r) {
      const double a0 = a[4 * r], a1 = a[4 * r + 1], a2 = a[4 * r + 2], a3 = a[4 * r + 3];
      for (std::size_t c = 0; c < m; ++c)
        tmp[static_cast<std::size_t>(r) * m + c] = a0 * x[c] + a1 * x[m + c] + a2 * x[2 * m + c] + a3 * x[3 * m + c];
    }
    std::copy(tmp.begin(), tmp.end(), x);
  }
  static double panel_max(const double* x, std::size_t count) {
    double mx = 0;
    for (std::size_t k = 0; k < count; ++k) mx = std::max(mx, std::abs(x[k]));
    return mx;
  }

  /// The top spike: columns of U supported on block rows 0 and 1 (in `values`, 8 x m rows on
  /// entry). Forward substitution downwards until the spike has died out, then backward
  /// substitution over that range only (below it the solution is zero).
  void solve_top_spike(Spike& z) const {
    const std::size_t m = z.columns.size(), panel = 4 * m;
    double biggest = panel_max(z.values.data(), z.values.size());
    std::size_t rows = std::min<std::size_t>(2, n_);
    z.values.resize(panel * rows);
    if (rows == 2) subtract_panel(block(1, 1), &z.values[0], &z.values[panel], m);
    while (rows < n_) {
      const double* prev = &z.values[panel * (rows - 2)];
      if (panel_max(prev, 2 * panel) <= spike_floor * biggest) break;  // died out
      z.values.resize(panel * (rows + 1), 0.0);
      double* y = &z.values[panel * rows];
      subtract_panel(block(rows, 1), y - panel, y, m);
      subtract_panel(block(rows, 0), y - 2 * panel, y, m);
      biggest = std::max(biggest, panel_max(y, panel));
      ++rows;
    }
    std::vector<double> tmp;
    for (std::size_t k = rows; k-- > 0;) {
      double* x = &z.values[panel * k];
      if (k + 1 < rows) subtract_panel(block(k, 3), x + panel, x, m);
      multiply_panel(block(k, 2), x, m, tmp);
    }
    z.first_block = 0;
    z.blocks = rows;
  }

  /// The bottom spike: columns of U supported on block row n-1 (in `values`, 4 x m rows on
  /// entry). Forward substitution leaves them unchanged; backward substitution upwards until
  /// the spike has died out.
  void solve_bottom_spike(Spike& z) const {
    const std::size_t m = z.columns.size(), panel = 4 * m;
    std::vector<double> tmp, built;  // built: block rows n-1, n-2, ... (reversed)
    built = z.values;
    multiply_panel(block(n_ - 1, 2), built.data(), m, tmp);
    double biggest = panel_max(built.data(), panel);
    std::size_t rows = 1;
    while (rows < n_) {
      const double* prev = &built[panel * (rows - 1)];
      if (panel_max(prev, panel) <= spike_floor * biggest) break;
      built.resize(panel * (rows + 1), 0.0);
      double* x = &built[panel * rows];
      const std::size_t k = n_ - 1 - rows;
      subtract_panel(block(k, 3), &built[panel * (rows - 1)], x, m);
      multiply_panel(block(k, 2), x, m, tmp);
      biggest = std::max(biggest, panel_max(x, panel));
      ++rows;
    }
    z.values.assign(panel * rows, 0.0);
    for (std::size_t j = 0; j < rows; ++j)  // back to natural row order
      std::copy(&built[panel * j], &built[panel * j] + panel, &z.values[panel * (rows - 1 - j)]);
    z.first_block = n_ - rows;
    z.blocks = rows;
  }

  /// Woodbury data for the cyclic wrap-around blocks (see the file comment).
  bool factor_wrap() {
    // Column blocks picked by V^T: n-2 and n-1 (wrap blocks in rows 0 and 1: top spike) and 0
    // (wrap block in row n-1: bottom spike).
    wrap_columns_.clear();
    top_ = Spike();
    bottom_ = Spike();
    auto wrap_value = [&](int cb, std::size_t row, int r, int q) -> double {
      if (cb == 0) return row == 0 ? block(0, 0)[4 * r + q] : 0.0;
      if (cb == 1) return row == 0 ? block(0, 1)[4 * r + q] : row == 1 ? block(1, 0)[4 * r + q] : 0.0;
      return row == n_ - 1 ? block(n_ - 1, 3)[4 * r + q] : 0.0;
    };
    const std::size_t cols[3] = {n_ - 2, n_ - 1, 0};
    std::vector<std::pair<int, int>> top_picks, bottom_picks;
    for (int cb = 0; cb < 3; ++cb)
      for (int q = 0; q < 4; ++q) {
        bool nonzero = false;
        for (std::size_t row : {std::size_t(0), std::size_t(1), n_ - 1})
          for (int r = 0; r < 4; ++r) nonzero = nonzero || wrap_value(cb, row, r, q) != 0.0;
        if (!nonzero) continue;  // e.g. t_j never enters a wrap-around residual
        Spike& z = cb < 2 ? top_ : bottom_;
        z.columns.push_back(wrap_columns_.size());
        (cb < 2 ? top_picks : bottom_picks).emplace_back(cb, q);
        wrap_columns_.push_back(4 * cols[cb] + static_cast<std::size_t>(q));
      }
    const std::size_t m = wrap_columns_.size();
    if (m == 0) return true;
    if (!top_.columns.empty()) {
      const std::size_t mt = top_.columns.size();
      top_.values.assign(8 * mt, 0.0);
      for (std::size_t c = 0; c < mt; ++c)
        for (std::size_t row = 0; row < 2; ++row)
          for (int r = 0; r < 4; ++r)
            top_.values[(4 * row + static_cast<std::size_t>(r)) * mt + c] = wrap_value(top_picks[c].first, row, r, top_picks[c].second);
      solve_top_spike(top_);
    }
    if (!bottom_.columns.empty()) {
      const std::size_t mb = bottom_.columns.size();
      bottom_.values.assign(4 * mb, 0.0);
      for (std::size_t c = 0; c < mb; ++c)
        for (int r = 0; r < 4; ++r)
          bottom_.values[static_cast<std::size_t>(r) * mb + c] = wrap_value(bottom_picks[c].first, n_ - 1, r, bottom_picks[c].second);
      solve_bottom_spike(bottom_);
    }
    // Growth check: A^{-1} = B^{-1} - Z (I + V^T Z)^{-1} V^T B^{-1} cancels large terms when B (the
    // cut matrix) is ill-conditioned even though A is not, and the correction then loses about
    // log10(max |Z| / max |U|) digits: refuse beyond 1e8 (the caller falls back to a pivoted
    // method). This also bounds what the truncated spike tails (< 1e-40 of the spike before the
    // backward substitution) can become.
    double biggest_u = 0, biggest_z = 0;
    for (int cb = 0; cb < 3; ++cb)
      for (std::size_t row : {std::size_t(0), std::size_t(1), n_ - 1})
        for (int r = 0; r < 4; ++r)
          for (int q = 0; q < 4; ++q) biggest_u = std::max(biggest_u, std::abs(wrap_value(cb, row, r, q)));
    for (const Spike* z : {&top_, &bottom_})
      for (double v : z->values) {
        if (!std::isfinite(v)) return false;
        biggest_z = std::max(biggest_z, std::abs(v));
      }
    if (!(biggest_z <= max_woodbury_growth * biggest_u)) return false;
    capacitance_.reset(m, m - 1, m - 1);
    for (const Spike* z : {&top_, &bottom_})
      for (std::size_t c = 0; c < z->columns.size(); ++c)
        for (std::size_t r = 0; r < m; ++r)
          capacitance_.add(r, z->columns[c], (r == z->columns[c] ? 1.0 : 0.0) + z->at(wrap_columns_[r], c));
    return capacitance_.factor();
  }

  std::size_t n_ = 0;
  bool cyclic_ = false, dense_ = false;
  Large_buffer<Block4> a_;  // 4 blocks per row (512 bytes): huge pages for large n
  Spike top_, bottom_;                     // Z = B^{-1} U
  std::vector<std::size_t> wrap_columns_;  // unknown index picked by each column of V
  Banded_lu capacitance_;                  // I + V^T Z (dense: bandwidths m-1)
  Banded_lu dense_lu_;                     // small cyclic systems
};

} // namespace linear_algebra
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_LINEAR_ALGEBRA_BLOCK_BAND_LU_H
