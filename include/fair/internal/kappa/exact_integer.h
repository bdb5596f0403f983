// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact integer arithmetic of the kappa-curve certification (certify.h): a minimal RAII GMP
// integer, the fraction-free solution of integer tridiagonal systems, and the conversions of
// the integer results (N / Delta, N / 2^s) to rationals. Every raw mpz_* call of the
// certification is in this file and in exact_eq18.h: canonicalising rationals of ~200 n bits is
// what made a Gmpq solve slow, so these work on integers with exact divisions and batch gcds.

#ifndef FAIR_INTERNAL_KAPPA_EXACT_INTEGER_H
#define FAIR_INTERNAL_KAPPA_EXACT_INTEGER_H

#include <fair/Errors.h>

#include <CGAL/Gmpq.h>

#include <gmp.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// Minimal RAII GMP integer (raw mpz_t, no reference counting, in-place operations).
struct Certify_int {
  mpz_t v;
  Certify_int() { mpz_init(v); }
  Certify_int(const Certify_int& o) { mpz_init_set(v, o.v); }
  Certify_int(Certify_int&& o) noexcept { mpz_init(v); mpz_swap(v, o.v); }
  Certify_int& operator=(const Certify_int& o) { mpz_set(v, o.v); return *this; }
  Certify_int& operator=(Certify_int&& o) noexcept { mpz_swap(v, o.v); return *this; }
  ~Certify_int() { mpz_clear(v); }
};

/// Fraction-free exact solution of the integer tridiagonal system
///   a_i x_{i-1} + b_i x_i + c_i x_{i+1} = d_{r,i}   (a_0 and c_{n-1} ignored)
/// for every right-hand side r: x_{r,i} = N[r][i] / det with integers N and det = det(M).
/// Forward sweep with the continuants theta_i = b_i theta_{i-1} - a_i c_{i-1} theta_{i-2}
/// (leading principal minors) and psi_i = d_i theta_{i-1} - a_i psi_{i-1}; back substitution
/// N_i = (psi_i det - c_i theta_{i-1} N_{i+1}) / theta_i, an exact division (Cramer: det x_i is
/// an integer). Requires all leading minors nonzero (true for strictly diagonally dominant
/// matrices: a broken invariant otherwise, Internal_error). O(n) multiplications of O(n)-word integers.
inline void integer_tridiagonal_solve(const std::vector<Certify_int>& a, const std::vector<Certify_int>& b,
                                      const std::vector<Certify_int>& c,
                                      const std::vector<std::vector<Certify_int>>& d,
                                      std::vector<std::vector<Certify_int>>& N, Certify_int& det) {
  const std::size_t n = b.size();
  std::vector<Certify_int> th(n);
  Certify_int tmp, tmp2;
  for (std::size_t i = 0; i < n; ++i) {
    mpz_set(th[i].v, b[i].v);
    if (i >= 1) mpz_mul(th[i].v, th[i].v, th[i - 1].v);
    if (i >= 1) {
      mpz_mul(tmp.v, a[i].v, c[i - 1].v);
      if (i >= 2) mpz_mul(tmp.v, tmp.v, th[i - 2].v);
      mpz_sub(th[i].v, th[i].v, tmp.v);
    }
    FAIR_ASSERT_MSG(mpz_sgn(th[i].v) != 0, "exact eq.-18 solve: singular leading minor ", i,
                    " (the system is not diagonally dominant)");
  }
  mpz_set(det.v, th[n - 1].v);
  N.assign(d.size(), std::vector<Certify_int>(n));
  std::vector<Certify_int> psi(n);
  for (std::size_t r = 0; r < d.size(); ++r) {
    mpz_set(psi[0].v, d[r][0].v);
    for (std::size_t i = 1; i < n; ++i) {
      mpz_mul(psi[i].v, d[r][i].v, th[i - 1].v);
      mpz_submul(psi[i].v, a[i].v, psi[i - 1].v);
    }
    mpz_set(N[r][n - 1].v, psi[n - 1].v);
    for (std::size_t i = n - 1; i-- > 0;) {
      mpz_mul(tmp.v, psi[i].v, det.v);
      mpz_mul(tmp2.v, c[i].v, N[r][i + 1].v);
      if (i >= 1) mpz_mul(tmp2.v, tmp2.v, th[i - 1].v);
      mpz_sub(tmp.v, tmp.v, tmp2.v);
      mpz_divexact(N[r][i].v, tmp.v, th[i].v);
    }
  }
}

/// The canonical rationals X_i / (2^e_i Delta) (Delta > 0) with a single big gcd (batch
/// coprimality): with Delta = 2^z D, D odd, and G = gcd(prod_{X_i != 0} X_i mod D, D), every
/// common divisor of X_i and D divides G, so gcd(X_i, D) = gcd(X_i, G) -- 1 without any work when
/// G == 1, the usual case. Powers of two are cancelled by counting trailing zeros. Cost: one
/// modular multiplication per entry and one gcd, instead of one gcd of ~|Delta|-bit integers per
/// entry (which dominated building the certificate's canonical Gmpq pieces).
inline std::vector<CGAL::Gmpq> canonical_fractions(const std::vector<const Certify_int*>& X,
                                                   const std::vector<mp_bitcnt_t>& e, const Certify_int& Delta) {
  Certify_int D, M, G, g, num, den;
  const mp_bitcnt_t z = mpz_scan1(Delta.v, 0);
  mpz_fdiv_q_2exp(D.v, Delta.v, z);
  mpz_set_ui(M.v, 1);
  for (const Certify_int* x : X)
    if (mpz_sgn(x->v) != 0) {
      mpz_mul(M.v, M.v, x->v);
      mpz_mod(M.v, M.v, D.v);
    }
  mpz_gcd(G.v, M.v, D.v);
  const bool coprime = mpz_cmp_ui(G.v, 1) == 0;
  std::vector<CGAL::Gmpq> out(X.size());
  mpq_t q;
  mpq_init(q);
  for (std::size_t i = 0; i < X.size(); ++i) {
    if (mpz_sgn(X[i]->v) == 0) continue;  // out[i] == 0
    if (coprime) {
      mpz_set(num.v, X[i]->v);
      mpz_set(den.v, D.v);
    } else {
      mpz_gcd(g.v, X[i]->v, G.v);
      mpz_divexact(num.v, X[i]->v, g.v);
      mpz_divexact(den.v, D.v, g.v);
    }
    const mp_bitcnt_t twos = e[i] + z, tn = mpz_scan1(num.v, 0), c = std::min(twos, tn);
    mpz_fdiv_q_2exp(num.v, num.v, c);  // exact: c <= trailing zeros of num
    mpz_mul_2exp(den.v, den.v, twos - c);
    mpz_swap(mpq_numref(q), num.v);
    mpz_swap(mpq_denref(q), den.v);
    out[i] = CGAL::Gmpq(q);  // canonical: den > 0, gcd(num, den) == 1
  }
  mpq_clear(q);
  return out;
}

/// Number of bits of |z| minus 1 (floor(log2 |z|) for z != 0): the s with 2^s <= |z| < 2^(s+1).
inline mp_bitcnt_t floor_log2(const Certify_int& z) { return mpz_sizeinbase(z.v, 2) - 1; }

/// The dyadic rational z / 2^s (canonical: GMP strips the common powers of two, no gcd).
inline CGAL::Gmpq dyadic_fraction(const Certify_int& z, mp_bitcnt_t s) {
  mpq_t q;
  mpq_init(q);
  mpz_set(mpq_numref(q), z.v);
  mpq_div_2exp(q, q, s);
  CGAL::Gmpq r(q);
  mpq_clear(q);
  return r;
}

/// For the dyadic lambda = l / 2^k in (0, 1): the integer (2^k - l) a + l b, i.e. 2^k times
/// (1 - lambda) a + lambda b (eq. 9 on integer numerators), and k.
inline mp_bitcnt_t dyadic_combination(const CGAL::Gmpq& lambda, const Certify_int& a, const Certify_int& b,
                                      Certify_int& out) {
  const mpz_srcptr l = mpq_numref(lambda.mpq()), den = mpq_denref(lambda.mpq());  // den = 2^k
  Certify_int ml;
  mpz_sub(ml.v, den, l);
  mpz_mul(out.v, ml.v, a.v);
  mpz_addmul(out.v, l, b.v);
  return mpz_sizeinbase(den, 2) - 1;
}

/// The integers L q_k (k < count) for the rationals q_k, with L the lcm of their denominators:
/// one row of a rational linear system scaled to integers.
inline void scale_to_integers(const CGAL::Gmpq* const* q, std::size_t count, Certify_int* const* out) {
  Certify_int L, f;
  mpz_set_ui(L.v, 1);
  for (std::size_t k = 0; k < count; ++k) mpz_lcm(L.v, L.v, mpq_denref(q[k]->mpq()));
  for (std::size_t k = 0; k < count; ++k) {
    mpz_divexact(f.v, L.v, mpq_denref(q[k]->mpq()));
    mpz_mul(out[k]->v, mpq_numref(q[k]->mpq()), f.v);
  }
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_EXACT_INTEGER_H
