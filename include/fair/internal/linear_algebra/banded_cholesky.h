// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Cholesky factorisation A = L L^T of a symmetric positive definite band matrix with half
// bandwidth h, O(N h^2 / 2) flops, backward stable. Used by the kappa-curve solver
// (Levenberg-Marquardt's J^T J), the optimal-curve solver (symmetric_band.h) and the quintic fit of
// fair::fit_quintic_spline. A non-positive (or non-finite) pivot makes factor() return false: the
// matrix is not positive definite in floating point, and the callers regularise
// (Levenberg-Marquardt increases its damping, the optimal-curve solver shifts the diagonal).

#ifndef FAIR_INTERNAL_LINEAR_ALGEBRA_BANDED_CHOLESKY_H
#define FAIR_INTERNAL_LINEAR_ALGEBRA_BANDED_CHOLESKY_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace linear_algebra {

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
        // A pointer-bounded loop: the same operations in the same order as an index loop, but
        // libFuzzer's comparison tracing (-fsanitize=fuzzer) does not call back on pointer
        // comparisons -- on an integer bound it did so per element, about half of the kappa
        // solver's time in the fuzz build (doc/fuzzing.md, "Session 17").
        const double* cj = c;
        for (double* const end = Ri + (i - k); Ri != end; ++Ri, ++cj) *Ri -= lik * *cj;
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

} // namespace linear_algebra
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_LINEAR_ALGEBRA_BANDED_CHOLESKY_H
