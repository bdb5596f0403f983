// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Banded linear algebra shared by the solvers (the kappa-curve solver fair::Kappa_curve_2, the
// quintic fit of fair::fit_quintic_spline):
//  - Banded_lu: Gaussian elimination with partial pivoting on a general band matrix
//    (kl sub-diagonals, ku super-diagonals; fill-in of kl extra super-diagonals is stored),
//    O(N kl (kl+ku)) flops, the algorithm of LAPACK's dgbtrf/dgbtrs;
//  - Banded_cholesky: Cholesky factorisation of a symmetric positive definite band matrix
//    with half bandwidth h, O(N h^2 / 2) flops.
//  - cyclic_position: the "zig-zag" ordering 0, n-1, 1, n-2, 2, ... that turns a cyclic band
//    (closed curves: the matrix is banded plus wrap-around corners) into an ordinary band of
//    twice the width, so one banded solver serves open and closed curves alike.
//
// Accuracy: partial pivoting is backward stable in practice (growth factor bounded by 2^(kl+ku)
// in theory, tiny in practice); Cholesky is backward stable. Degenerate case: an exactly zero
// pivot (singular matrix) or a non-positive Cholesky pivot makes factor() return false; the
// callers then regularise (Levenberg-Marquardt increases its damping).

#ifndef FAIR_INTERNAL_COMMON_BANDED_H
#define FAIR_INTERNAL_COMMON_BANDED_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace common {

/// Position of block j (0 <= j < n) in the zig-zag order 0, n-1, 1, n-2, 2, ...
/// Blocks at cyclic distance d end up at most 2d positions apart... precisely |pos(a)-pos(b)|
/// <= 2d + 1 when a and b are d apart cyclically.
inline std::size_t cyclic_position(std::size_t j, std::size_t n) {
  return (2 * j <= n - 1) ? 2 * j : 2 * (n - j) - 1;
}

/// General band matrix with partial-pivoting LU. Entry (i,j) is stored when
/// i - kl <= j <= i + kl + ku (the extra kl super-diagonals hold the fill-in of pivoting).
class Banded_lu {
public:
  Banded_lu() = default;
  Banded_lu(std::size_t n, std::size_t kl, std::size_t ku) { reset(n, kl, ku); }

  void reset(std::size_t n, std::size_t kl, std::size_t ku) {
    n_ = n; kl_ = kl; ku_ = ku; w_ = 2 * kl + ku + 1;
    a_.assign(n_ * w_, 0.0);
    piv_.assign(n_, 0);
  }
  std::size_t size() const { return n_; }

  /// Adds v to entry (i,j); (i,j) must lie in the band i-kl <= j <= i+ku.
  void add(std::size_t i, std::size_t j, double v) { a_[i * w_ + (j + kl_ - i)] += v; }

  /// In-place LU with partial pivoting. Returns false on an exactly zero pivot column.
  bool factor() {
    for (std::size_t k = 0; k < n_; ++k) {
      const std::size_t last = std::min(n_ - 1, k + kl_);
      std::size_t p = k;
      double best = std::abs(at(k, k));
      for (std::size_t r = k + 1; r <= last; ++r)
        if (std::abs(at(r, k)) > best) { best = std::abs(at(r, k)); p = r; }
      piv_[k] = p;
      if (!(best > 0.0) || !std::isfinite(best)) return false;
      const std::size_t jend = std::min(n_ - 1, k + kl_ + ku_);
      if (p != k)
        for (std::size_t j = k; j <= jend; ++j) std::swap(at(k, j), at(p, j));
      const double inv = 1.0 / at(k, k);
      for (std::size_t r = k + 1; r <= last; ++r) {
        const double l = at(r, k) * inv;
        at(r, k) = l;
        if (l == 0.0) continue;
        for (std::size_t j = k + 1; j <= jend; ++j) at(r, j) -= l * at(k, j);
      }
    }
    return true;
  }

  /// Solves A x = b in place (after factor()).
  void solve(double* b) const {
    for (std::size_t k = 0; k < n_; ++k) {
      if (piv_[k] != k) std::swap(b[k], b[piv_[k]]);
      const std::size_t last = std::min(n_ - 1, k + kl_);
      for (std::size_t r = k + 1; r <= last; ++r) b[r] -= at(r, k) * b[k];
    }
    for (std::size_t k = n_; k-- > 0;) {
      const std::size_t jend = std::min(n_ - 1, k + kl_ + ku_);
      double s = b[k];
      for (std::size_t j = k + 1; j <= jend; ++j) s -= at(k, j) * b[j];
      b[k] = s / at(k, k);
    }
  }

private:
  double& at(std::size_t i, std::size_t j) { return a_[i * w_ + (j + kl_ - i)]; }
  double at(std::size_t i, std::size_t j) const { return a_[i * w_ + (j + kl_ - i)]; }

  std::size_t n_ = 0, kl_ = 0, ku_ = 0, w_ = 1;
  std::vector<double> a_;
  std::vector<std::size_t> piv_;
};

/// Symmetric positive definite band matrix (half bandwidth h), lower triangle stored row-wise.
class Banded_cholesky {
public:
  void reset(std::size_t n, std::size_t h) {
    n_ = n; h_ = std::min(h, n == 0 ? 0 : n - 1); w_ = h_ + 1;
    a_.assign(n_ * w_, 0.0);
  }
  std::size_t size() const { return n_; }
  std::size_t half_bandwidth() const { return h_; }

  /// Adds v to entry (i,j) with j <= i <= j + h.
  void add_lower(std::size_t i, std::size_t j, double v) { a_[i * w_ + (j + h_ - i)] += v; }
  /// Sets entry (i,j) with j <= i <= j + h.
  void set_lower(std::size_t i, std::size_t j, double v) { a_[i * w_ + (j + h_ - i)] = v; }
  double diagonal(std::size_t i) const { return a_[i * w_ + h_]; }
  void add_diagonal(std::size_t i, double v) { a_[i * w_ + h_] += v; }
  std::vector<double>& storage() { return a_; }

  /// In-place Cholesky A = L L^T. Returns false if a pivot is not positive (not SPD in floating
  /// point); the content is then unusable.
  /// Right-looking (outer-product) order: column k is scaled, then the trailing h x h triangle
  /// gets the rank-1 update A(i,j) -= L(i,k) L(j,k), whose inner loop runs along a stored row
  /// with independent operations (vectorised, throughput bound), unlike the row-by-row order
  /// whose dot products and divisions form one serial dependency chain. Same flops (N h^2 / 2),
  /// same rounding error bound.
  bool factor() {
    col_.resize(h_ + 1);
    for (std::size_t k = 0; k < n_; ++k) {
      double* Rk = row(k);
      const double d = Rk[k];
      if (!(d > 0.0) || !std::isfinite(d)) return false;
      const double l = std::sqrt(d), inv = 1.0 / l;
      Rk[k] = l;
      const std::size_t iend = std::min(n_ - 1, k + h_);
      double* c = col_.data();  // c[i - k - 1] = L(i,k), k < i <= iend
      for (std::size_t i = k + 1; i <= iend; ++i) {
        double& a = row(i)[k];
        a *= inv;
        c[i - k - 1] = a;
      }
      for (std::size_t i = k + 1; i <= iend; ++i) {
        double* Ri = row(i) + (k + 1);
        const double lik = c[i - k - 1];
        const std::size_t len = i - k;
        for (std::size_t j = 0; j < len; ++j) Ri[j] -= lik * c[j];
      }
    }
    return true;
  }

  /// Solves A x = b in place (after factor()).
  void solve(double* b) const {
    for (std::size_t i = 0; i < n_; ++i) {
      const std::size_t j0 = i > h_ ? i - h_ : 0;
      const double* Li = &a_[i * w_ + (h_ - i)];
      double s = b[i];
      for (std::size_t k = j0; k < i; ++k) s -= Li[k] * b[k];
      b[i] = s / Li[i];
    }
    for (std::size_t i = n_; i-- > 0;) {
      const double* Li = &a_[i * w_ + (h_ - i)];
      b[i] /= Li[i];
      const double bi = b[i];
      const std::size_t j0 = i > h_ ? i - h_ : 0;
      for (std::size_t k = j0; k < i; ++k) b[k] -= Li[k] * bi;
    }
  }

private:
  double* row(std::size_t i) { return a_.data() + i * w_ + h_ - i; }  // row(i)[j] = A(i,j)

  std::size_t n_ = 0, h_ = 0, w_ = 1;
  std::vector<double> a_, col_;
};

} // namespace common
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_COMMON_BANDED_H
