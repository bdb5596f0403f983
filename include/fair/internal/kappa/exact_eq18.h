// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The exact, fraction-free solution of eq. 18 for the certification (certify.h). With the
// solver's lambda_i, t_i, w_i held fixed (doubles, i.e. exact dyadic rationals), eq. 18 is a
// linear (cyclic) tridiagonal system for the middle control points P_i = P_{i,1}, strictly
// diagonally dominant (the diagonal exceeds the off-diagonal sum by 2 (1-t_i) t_i w_i > 0),
// hence uniquely solvable. Every row is scaled to integers and the solution is
// P_i = N_i / Delta with Delta = det > 0 and integers N_i, obtained with exact divisions only.

#ifndef FAIR_INTERNAL_KAPPA_EXACT_EQ18_H
#define FAIR_INTERNAL_KAPPA_EXACT_EQ18_H

#include <fair/Errors.h>
#include <fair/internal/kappa/exact_integer.h>

#include <CGAL/Gmpq.h>

#include <gmp.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// Exact solution of eq. 18 as P_i = (Nx_i, Ny_i) / Delta with integers Nx, Ny and Delta > 0
/// (the rows of eq. 18, each multiplied by the lcm of its denominators). Closed
/// curves (cyclic system, n >= 3): bordering -- the tridiagonal block T of rows/unknowns
/// 0..n-2 is solved for the two right-hand sides and for the border column,
/// T Y = d, T Z = -(a_0 e_0 + c_{n-2} e_{n-2}), theta = det T; then with the Schur complement
/// V = b_{n-1} theta + a_{n-1} Z_{n-2} + c_{n-1} Z_0 = det(M) (= Delta) and
/// U = d_{n-1} theta - a_{n-1} Y_{n-2} - c_{n-1} Y_0:  N_{n-1} = U, N_i = (Y_i V + U Z_i) / theta
/// (exact division). The result is verified row by row by the certification (Q_i == c_i(t_i)).
inline void exact_eq18_integer(bool closed, const std::vector<CGAL::Gmpq>& qx, const std::vector<CGAL::Gmpq>& qy,
                               const CGAL::Gmpq& sx, const CGAL::Gmpq& sy, const CGAL::Gmpq& ex,
                               const CGAL::Gmpq& ey, const std::vector<CGAL::Gmpq>& lambda,
                               const std::vector<CGAL::Gmpq>& t, const std::vector<CGAL::Gmpq>& w,
                               std::vector<Certify_int>& Nx, std::vector<Certify_int>& Ny, Certify_int& Delta) {
  typedef CGAL::Gmpq Q;
  const std::size_t n = qx.size();
  std::vector<Certify_int> a(n), b(n), c(n);
  std::vector<std::vector<Certify_int>> d(3, std::vector<Certify_int>(n));  // x, y, border column
  for (std::size_t i = 0; i < n; ++i) {
    const Q u = Q(1) - t[i], c0 = u * u, c2 = t[i] * t[i], c1 = Q(2) * u * t[i] * w[i];
    const Q D = c0 + c1 + c2;
    Q A(0), B = c1, C(0), dx = D * qx[i], dy = D * qy[i];
    if (closed || i > 0) {
      A = c0 * (Q(1) - lambda[i]);
      B += c0 * lambda[i];
    } else {
      dx -= c0 * sx;
      dy -= c0 * sy;
    }
    if (closed || i + 1 < n) {
      const Q& l = lambda[(i + 1) % n];
      C = c2 * l;
      B += c2 * (Q(1) - l);
    } else {
      dx -= c2 * ex;
      dy -= c2 * ey;
    }
    const Q* row[5] = {&A, &B, &C, &dx, &dy};
    Certify_int* const out[5] = {&a[i], &b[i], &c[i], &d[0][i], &d[1][i]};
    scale_to_integers(row, 5, out);
  }
  std::vector<std::vector<Certify_int>> N;
  if (!closed) {
    d.pop_back();
    integer_tridiagonal_solve(a, b, c, d, N, Delta);
  } else {
    const std::size_t m = n - 1;  // n >= 3
    std::vector<Certify_int> ta(a.begin(), a.begin() + m), tb(b.begin(), b.begin() + m), tc(c.begin(), c.begin() + m);
    std::vector<std::vector<Certify_int>> td(3, std::vector<Certify_int>(m));
    for (std::size_t r = 0; r < 2; ++r)
      for (std::size_t i = 0; i < m; ++i) mpz_set(td[r][i].v, d[r][i].v);
    mpz_neg(td[2][0].v, a[0].v);
    mpz_sub(td[2][m - 1].v, td[2][m - 1].v, c[m - 1].v);
    std::vector<std::vector<Certify_int>> Y;
    Certify_int theta, V, tmp;
    integer_tridiagonal_solve(ta, tb, tc, td, Y, theta);
    const std::vector<Certify_int>& Z = Y[2];
    mpz_mul(V.v, b[m].v, theta.v);
    mpz_addmul(V.v, a[m].v, Z[m - 1].v);
    mpz_addmul(V.v, c[m].v, Z[0].v);
    FAIR_ASSERT_MSG(mpz_sgn(V.v) != 0, "exact eq.-18 solve: singular cyclic system");
    mpz_set(Delta.v, V.v);
    N.assign(2, std::vector<Certify_int>(n));
    for (std::size_t r = 0; r < 2; ++r) {
      Certify_int& U = N[r][m];
      mpz_mul(U.v, d[r][m].v, theta.v);
      mpz_submul(U.v, a[m].v, Y[r][m - 1].v);
      mpz_submul(U.v, c[m].v, Y[r][0].v);
      for (std::size_t i = 0; i < m; ++i) {
        mpz_mul(tmp.v, Y[r][i].v, V.v);
        mpz_addmul(tmp.v, U.v, Z[i].v);
        mpz_divexact(N[r][i].v, tmp.v, theta.v);
      }
    }
  }
  if (mpz_sgn(Delta.v) < 0) {
    mpz_neg(Delta.v, Delta.v);
    for (auto& v : N)
      for (Certify_int& z : v) mpz_neg(z.v, z.v);
  }
  Nx = std::move(N[0]);
  Ny = std::move(N[1]);
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_EXACT_EQ18_H
