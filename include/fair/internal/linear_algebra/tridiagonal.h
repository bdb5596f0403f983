// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The library's one tridiagonal solver, plain and cyclic (issue 23 §3: one linear-algebra part),
// O(n), used by the classic C2 cubic interpolating spline (Cubic_interpolating_spline_2), the
// periodic polygon fit (fit_cubic_spline) and the exact kappa certificate's oracle tests:
//  - solve_tridiagonal: the Thomas algorithm (Gaussian elimination without pivoting on a
//    tridiagonal matrix);
//  - solve_cyclic_tridiagonal: a tridiagonal matrix plus the two corner entries of a periodic
//    problem, reduced to two tridiagonal solves by the Sherman-Morrison formula
//    (A = B + u v^T  =>  x = y - (v.y / (1 + v.z)) z  with  B y = d, B z = u).
//
// Not folded here, because they are other algorithms: the fraction-free integer solve of the
// kappa certificate (kappa/exact_integer.h: continuants and exact divisions, no field
// arithmetic) and the banded solvers with pivoting or Cholesky (the quintic fit's rank-4
// Woodbury correction sits on a banded Cholesky of half-bandwidth 3, not on a tridiagonal).
// The kappa refinement's eq.-18 solve (kappa/refinement.h) is this Thomas elimination, fused
// with the row assembly, a per-row dominance test that falls back to banded LU, and a bordered
// (not Sherman-Morrison) closing row, in a reused workspace: see the note there.
//
// Both are generic in the number type NT: they only add, subtract, multiply and divide, so they
// are exact with an exact field type (Gmpq, Lazy_exact_nt<Gmpq>).
//
// Accuracy and domain: elimination without pivoting is backward stable for strictly diagonally
// dominant matrices, which is the case for every system the spline builds
// (|b_i| >= |a_i| + |c_i| + min(h) > |a_i| + |c_i|). A zero pivot (impossible for those
// systems, possible for arbitrary user matrices) throws fair::Precondition_error rather than
// dividing by zero.
//
// Lazy exact numbers (EPECK): every unknown depends on all the previous ones, so without care
// the lazy expression DAG is n levels deep and its exact evaluation recurses n levels deep (a
// stack overflow beyond a few thousand rows). For long systems the solvers therefore force the
// exact value every `prune_stride` rows, which cuts the DAG (CGAL prunes a lazy node
// once its exact value is known). The exact values themselves have bit lengths growing linearly
// with n (the Thomas recurrence is a continued fraction), so an exact solve costs O(n^2) bit
// operations: about 1 s for n = 2000 uniform knots on a 2020s laptop core.

#ifndef FAIR_INTERNAL_LINEAR_ALGEBRA_TRIDIAGONAL_H
#define FAIR_INTERNAL_LINEAR_ALGEBRA_TRIDIAGONAL_H

#include <fair/Errors.h>

#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/number_utils.h>

#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace linear_algebra {

/// Rows between two forced exact evaluations in the solvers (for lazy number types only).
constexpr std::size_t prune_stride = 128;
/// Systems shorter than this are never pruned (their lazy DAG is shallow enough).
constexpr std::size_t prune_minimum = 512;

/// Forces and caches the exact value of a lazy number (pruning its DAG); no-op for other types.
template <class NT>
void prune_lazy(const NT&) {}
template <class ET>
void prune_lazy(const CGAL::Lazy_exact_nt<ET>& x) {
  CGAL::exact(x);
}

/// Solves the n x n tridiagonal system
///   a[i] x[i-1] + b[i] x[i] + c[i] x[i+1] = d[i],   i = 0..n-1,
/// (a[0] and c[n-1] are ignored) by the Thomas algorithm, in 8n arithmetic operations.
/// Throws Precondition_error on mismatched sizes or a zero pivot.
template <class NT>
std::vector<NT> solve_tridiagonal(const std::vector<NT>& a, const std::vector<NT>& b,
                                  const std::vector<NT>& c, const std::vector<NT>& d) {
  const std::size_t n = b.size();
  require(n > 0 && a.size() == n && c.size() == n && d.size() == n,
          "solve_tridiagonal: sizes a=", a.size(), " b=", n, " c=", c.size(), " d=", d.size(),
          " must be equal and non-zero");
  std::vector<NT> cp(n), dp(n);
  // Forward sweep: eliminate the sub-diagonal.
  NT pivot = b[0];
  require(pivot != NT(0), "solve_tridiagonal: zero pivot at row 0");
  cp[0] = c[0] / pivot;
  dp[0] = d[0] / pivot;
  for (std::size_t i = 1; i < n; ++i) {
    pivot = b[i] - a[i] * cp[i - 1];
    require(pivot != NT(0), "solve_tridiagonal: zero pivot at row ", i,
            " (the matrix is not diagonally dominant)");
    cp[i] = (i + 1 < n) ? c[i] / pivot : NT(0);
    dp[i] = (d[i] - a[i] * dp[i - 1]) / pivot;
    if (n >= prune_minimum && i % prune_stride == 0) {
      prune_lazy(cp[i]);
      prune_lazy(dp[i]);
    }
  }
  // Back substitution.
  std::vector<NT> x(n);
  x[n - 1] = dp[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) {
    x[i] = dp[i] - cp[i] * x[i + 1];
    if (n >= prune_minimum && i % prune_stride == 0) prune_lazy(x[i]);
  }
  return x;
}

/// Solves the n x n cyclic tridiagonal system (n >= 3)
///   a[i] x[i-1 mod n] + b[i] x[i] + c[i] x[i+1 mod n] = d[i],   i = 0..n-1,
/// so a[0] is the top-right corner and c[n-1] the bottom-left corner. Sherman-Morrison with
/// gamma = -b[0]: B = A - u v^T, u = (gamma, 0, .., 0, c[n-1]), v = (1, 0, .., 0, a[0]/gamma),
/// which keeps B diagonally dominant when A is. Two Thomas solves: O(n).
template <class NT>
std::vector<NT> solve_cyclic_tridiagonal(const std::vector<NT>& a, const std::vector<NT>& b,
                                         const std::vector<NT>& c, const std::vector<NT>& d) {
  const std::size_t n = b.size();
  require(n >= 3 && a.size() == n && c.size() == n && d.size() == n,
          "solve_cyclic_tridiagonal: needs n >= 3 equal sizes, got a=", a.size(), " b=", n,
          " c=", c.size(), " d=", d.size());
  require(b[0] != NT(0), "solve_cyclic_tridiagonal: b[0] = 0");
  const NT gamma = -b[0];
  std::vector<NT> bb = b;
  bb[0] = b[0] - gamma;
  bb[n - 1] = b[n - 1] - a[0] * c[n - 1] / gamma;
  std::vector<NT> u(n, NT(0));
  u[0] = gamma;
  u[n - 1] = c[n - 1];
  const std::vector<NT> y = solve_tridiagonal(a, bb, c, d);
  const std::vector<NT> z = solve_tridiagonal(a, bb, c, u);
  // v = (1, 0, ..., 0, a[0]/gamma)
  const NT vy = y[0] + a[0] * y[n - 1] / gamma;
  const NT vz = z[0] + a[0] * z[n - 1] / gamma;
  const NT denominator = NT(1) + vz;
  require(denominator != NT(0), "solve_cyclic_tridiagonal: singular cyclic system (1 + v.z = 0)");
  const NT factor = vy / denominator;
  std::vector<NT> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = y[i] - factor * z[i];
  return x;
}

} // namespace linear_algebra
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_LINEAR_ALGEBRA_TRIDIAGONAL_H
