// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact certification of a kappa-curve (see fair::certify in Kappa_curve_2.h).
//
// Method. The solver's lambda_i, t_i, w_i are doubles, i.e. exact dyadic rationals. With them
// held fixed, eq. 18 is a linear (cyclic) tridiagonal system for the middle control points
// P_i = P_{i,1}, strictly diagonally dominant (the diagonal exceeds the off-diagonal sum by
// 2 (1-t_i) t_i w_i > 0), hence uniquely solvable. It is solved EXACTLY and fraction-free
// (exact_eq18_integer): every row is scaled to integers, and the integer solution is
// P_i = N_i / Delta with Delta = det > 0 and integers N_i, obtained with exact divisions only
// (no gcd: canonicalising rationals of ~200 n bits is what made a Gmpq solve slow). The join
// points E_i = (1-lambda_i) P_{i-1} + lambda_i P_i (eq. 9) are formed exactly.
// The checks then run on the SCALED curve rho * c with rho = Delta / 2^s in [1,2) (s = bit length
// of Delta minus 1): its control points rho P_i = N_i / 2^s and rho E_i, and the scaled points
// rho Q_i, are dyadic rationals, on which Gmpq arithmetic needs no expensive gcd (GMP strips
// powers of two). Every certified property is invariant under this positive scaling: Q_i ==
// c_i(t_i), orientation and strict order (G1), the parameters of the curvature extrema
// (eq. 4 scales by a positive factor), the relative |kappa| mismatch (eq. 5, both curvatures
// scale by 1/rho); a nonzero interpolation distance is reported as measured on the scaled curve,
// an upper bound for the unscaled one (rho >= 1; at most 2x loose).
// Exactly: Q_i == c_i(t_i), E_i shared (C0), orientation(P_{i-1}, E_i, P_i) == COLLINEAR with E_i
// strictly between (G1). The eq.-4 numerator: interval filter (eq4_filtered_extremum) on
// enclosures of the exact scaled coordinates -- exact signs of the 5 Bernstein coefficients
// (Descartes: 0 or exactly 1 simple root in (0,1)) and a certified sign change at t_i -/+ delta --
// with the exact isolation (Rational_quadratic_bezier_2::curvature_extrema) as the fallback
// whenever an interval sign is undecided. The relative |kappa| mismatch at each join,
// (|k1| - |k2|) / (|k1| + |k2|), is enclosed by outward-rounded interval arithmetic (eq. 5).
// The certificate's exact_pieces are the unscaled pieces in original coordinates (canonical
// Gmpq N_i / Delta): building them costs a few gcds of ~200 n-bit integers per piece, which
// dominates for long curves.

#ifndef FAIR_INTERNAL_KAPPA_CERTIFY_H
#define FAIR_INTERNAL_KAPPA_CERTIFY_H

#include <fair/Errors.h>
#include <fair/internal/common/exact_conversion.h>
#include <fair/Rational_quadratic_bezier_2.h>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
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
/// matrices); throws std::logic_error otherwise. O(n) multiplications of O(n)-word integers.
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
    if (mpz_sgn(th[i].v) == 0)
      throw std::logic_error("fair: exact eq.-18 solve: singular leading minor (the system is not diagonally dominant)");
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
  Certify_int L, f;
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
    Certify_int* out[5] = {&a[i], &b[i], &c[i], &d[0][i], &d[1][i]};
    mpz_set_ui(L.v, 1);
    for (const Q* q : row) mpz_lcm(L.v, L.v, mpq_denref(q->mpq()));
    for (int k = 0; k < 5; ++k) {
      mpz_divexact(f.v, L.v, mpq_denref(row[k]->mpq()));
      mpz_mul(out[k]->v, mpq_numref(row[k]->mpq()), f.v);
    }
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
    if (mpz_sgn(V.v) == 0) throw std::logic_error("fair: exact eq.-18 solve: singular cyclic system");
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

/// Sign of the Bernstein quartic sum_k b_k C(4,k) (1-t)^(4-k) t^k at the double t, from
/// enclosures b of its coefficients (call with upward rounding, CGAL::Protect_FPU_rounding):
/// +1 / -1 when certain, 0 when the enclosure contains 0.
inline int quartic_sign_interval(const CGAL::Interval_nt<false>* b, double t) {
  typedef CGAL::Interval_nt<false> I;
  const I T(t), S = I(1) - T, S2 = S * S, T2 = T * T;
  const I v = b[0] * S2 * S2 + I(4) * b[1] * S2 * S * T + I(6) * b[2] * S2 * T2 + I(4) * b[3] * S * T2 * T +
              b[4] * T2 * T2;
  return v.inf() > 0 ? 1 : (v.sup() < 0 ? -1 : 0);
}

/// Interval filter for the curvature extrema of one piece near t (eq. 4), from enclosures of
/// the exact control points and weight (any positive scaling of the piece gives the same
/// answer). Returns 0: the exact eq.-4 coefficients have certain signs without a variation, no
/// root in [0,1]; 1: certain signs with exactly one variation (Descartes' rule in the Bernstein
/// basis: exactly one root in (0,1), simple), sign[0] < 0 meaning a MAXIMUM of |kappa| (E goes
/// from - to +), and the root certified inside (lower, upper) = (t - delta, t + delta) by
/// certain opposite signs of E there, for the first delta in 2^-44, 2^-41, ..., 2^-20 that
/// decides; distance = an upper bound on max(t - lower, upper - t). -1: undecided (a
/// coefficient enclosure contains 0, more variations, or no certified sign change within 2^-20
/// of t): the caller runs the exact isolation.
inline int eq4_filtered_extremum(const CGAL::Interval_nt<false>* xy, const CGAL::Interval_nt<false>& w, double t,
                                 Curvature_extremum_kind& kind, double& lower, double& upper, double& distance) {
  typedef CGAL::Interval_nt<false> I;
  CGAL::Protect_FPU_rounding<true> guard;
  const std::vector<I> c = conic::eq4_coefficients<I>(xy[0], xy[1], xy[2], xy[3], xy[4], xy[5], w);
  int sign[5], variations = 0;
  for (int i = 0; i < 5; ++i) {
    const I& v = c[static_cast<std::size_t>(i)];
    if (v.inf() > 0) sign[i] = 1;
    else if (v.sup() < 0) sign[i] = -1;
    else return -1;
    if (i > 0 && sign[i] != sign[i - 1]) ++variations;
  }
  if (variations == 0) return 0;
  if (variations != 1) return -1;
  kind = sign[0] < 0 ? Curvature_extremum_kind::MAXIMUM : Curvature_extremum_kind::MINIMUM;
  for (double delta = 0x1p-44; delta <= 0x1p-20; delta *= 8) {
    const double lo = t - delta, hi = t + delta;  // any doubles: the bracket is (lo, hi) as computed
    if (!(lo > 0 && hi < 1 && lo < t && t < hi)) break;
    const int sl = quartic_sign_interval(c.data(), lo), sh = quartic_sign_interval(c.data(), hi);
    if (sl != 0 && sh != 0 && sl != sh) {
      lower = lo;
      upper = hi;
      distance = std::max(t - lo, hi - t);  // rounded upward (guard): an upper bound
      return 1;
    }
  }
  return -1;
}

/// Certified enclosure of the relative |kappa| mismatch (|k1| - |k2|) / (|k1| + |k2|) at the
/// join E of the exact pieces (A, P, E, wa) and (E, R, B, wb), by interval arithmetic on
/// enclosures of the exact coordinates (eq. 5: |kappa(1)| of the first piece is
/// |Delta(A,P,E)| / (wa^2 |E-P|^3), |kappa(0)| of the second |Delta(E,R,B)| / (wb^2 |R-E|^3);
/// the ratio is invariant under any common positive scaling of the coordinates). Cheaper than
/// exact rationals, whose lengths grow along the curve.
inline void relative_mismatch_interval(const CGAL::Interval_nt<false>* a, const CGAL::Interval_nt<false>* p,
                                       const CGAL::Interval_nt<false>* e, const CGAL::Interval_nt<false>* r,
                                       const CGAL::Interval_nt<false>* b, const CGAL::Interval_nt<false>& Wa,
                                       const CGAL::Interval_nt<false>& Wb, double& lo, double& hi) {
  typedef CGAL::Interval_nt<false> I;
  CGAL::Protect_FPU_rounding<true> guard;
  // Edge vectors, scaled by a power of two to about unit size: the ratio is scale invariant,
  // and unscaled coordinates of 1e+-100 would overflow or underflow l^3 (outward-rounded
  // scaling keeps every interval an enclosure, also where a small component underflows).
  I v[4][2] = {{p[0] - a[0], p[1] - a[1]}, {e[0] - p[0], e[1] - p[1]}, {r[0] - e[0], r[1] - e[1]}, {b[0] - r[0], b[1] - r[1]}};
  double biggest = 0;
  for (const auto& vi : v)
    for (const I& c : vi) biggest = std::max(biggest, std::max(std::abs(c.inf()), std::abs(c.sup())));
  if (biggest > 0 && std::isfinite(biggest)) {
    const double f = std::ldexp(1.0, -std::ilogb(biggest));
    for (auto& vi : v)
      for (I& c : vi) c = c * f;
  }
  const I d1 = CGAL::abs(v[0][0] * v[1][1] - v[0][1] * v[1][0]);
  const I d2 = CGAL::abs(v[2][0] * v[3][1] - v[2][1] * v[3][0]);
  const I l1 = CGAL::sqrt(CGAL::square(v[1][0]) + CGAL::square(v[1][1]));
  const I l2 = CGAL::sqrt(CGAL::square(v[2][0]) + CGAL::square(v[2][1]));
  const I k1 = d1 / (Wa * Wa * l1 * l1 * l1), k2 = d2 / (Wb * Wb * l2 * l2 * l2);
  const I m = (k1 - k2) / (k1 + k2);
  lo = m.inf();
  hi = m.sup();
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_CERTIFY_H
