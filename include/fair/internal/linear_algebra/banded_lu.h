// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Gaussian elimination with partial pivoting on a general band matrix (kl sub-diagonals, ku
// super-diagonals; fill-in of kl extra super-diagonals is stored), O(N kl (kl+ku)) flops, the
// algorithm of LAPACK's dgbtrf/dgbtrs. Used by the kappa-curve solver (the pivoted fallback of
// Newton's method, the alternating passes, the small and capacitance systems of block_band_lu.h).
//
// Accuracy: partial pivoting is backward stable in practice (growth factor bounded by 2^(kl+ku)
// in theory, tiny in practice). An exactly zero (or non-finite) pivot column makes factor() return
// false.

#ifndef FAIR_INTERNAL_LINEAR_ALGEBRA_BANDED_LU_H
#define FAIR_INTERNAL_LINEAR_ALGEBRA_BANDED_LU_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace linear_algebra {

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

} // namespace linear_algebra
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_LINEAR_ALGEBRA_BANDED_LU_H
