// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact certification of a kappa-curve (see fair::certify in Kappa_curve_2.h).
//
// Method. The solver's lambda_i, t_i, w_i are doubles, i.e. exact dyadic rationals. With them
// held fixed, eq. 18 is a linear (cyclic) tridiagonal system for the middle control points
// P_i = P_{i,1}, strictly diagonally dominant (the diagonal exceeds the off-diagonal sum by
// 2 (1-t_i) t_i w_i > 0), hence uniquely solvable. It is solved EXACTLY over CGAL::Gmpq, the join
// points E_i = (1-lambda_i) P_{i-1} + lambda_i P_i (eq. 9) are formed exactly, and the pieces
// (E_i, P_i, E_{i+1}, w_i) are built in Simple_cartesian<Gmpq>. This exact curve is the one
// being certified: it differs from the double curve by the rounding of the solve only.
// Then, exactly: Q_i == c_i(t_i), E_i shared (C0), orientation(P_{i-1}, E_i, P_i) == COLLINEAR
// with E_i strictly between (G1); certified isolation of the roots of the eq.-4 numerator in
// (0,1) with their kind (Rational_quadratic_bezier_2::curvature_extrema); and the relative
// |kappa| mismatch at each join, (|k1| - |k2|) / (|k1| + |k2|) = (rho - 1) / (rho + 1) with
// rho^2 = k1^2 / k2^2 computed exactly (eq. 5) and the square root enclosed by interval
// arithmetic with outward rounding.
//
// Cost: the exact solve makes the bit length of the P_i grow linearly along the curve, so the
// whole certification is O(n^2) bit operations: fine for hundreds of pieces, slow for
// thousands in one curve (see doc/kappa_curves.md).

#ifndef FAIR_INTERNAL_KAPPA_CERTIFY_H
#define FAIR_INTERNAL_KAPPA_CERTIFY_H

#include <fair/Errors.h>
#include <fair/internal/classic_tridiagonal.h>
#include <fair/internal/rational_quadratic_exact.h>
#include <fair/Rational_quadratic_bezier_2.h>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// Exact solution of eq. 18 for the P_i (x and y separately), original coordinates.
/// q: interpolated points of the pieces; s/e: fixed end points of an open curve.
inline void exact_eq18(bool closed, const std::vector<CGAL::Gmpq>& qx, const std::vector<CGAL::Gmpq>& qy,
                       const CGAL::Gmpq& sx, const CGAL::Gmpq& sy, const CGAL::Gmpq& ex, const CGAL::Gmpq& ey,
                       const std::vector<CGAL::Gmpq>& lambda, const std::vector<CGAL::Gmpq>& t,
                       const std::vector<CGAL::Gmpq>& w, std::vector<CGAL::Gmpq>& px, std::vector<CGAL::Gmpq>& py) {
  typedef CGAL::Gmpq Q;
  const std::size_t n = qx.size();
  std::vector<Q> a(n, Q(0)), b(n, Q(0)), c(n, Q(0)), dx(n), dy(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Q u = Q(1) - t[i], c0 = u * u, c2 = t[i] * t[i], c1 = Q(2) * u * t[i] * w[i];
    const Q D = c0 + c1 + c2;
    dx[i] = D * qx[i];
    dy[i] = D * qy[i];
    b[i] = c1;
    if (closed || i > 0) {
      a[i] = c0 * (Q(1) - lambda[i]);
      b[i] += c0 * lambda[i];
    } else {
      dx[i] -= c0 * sx;
      dy[i] -= c0 * sy;
    }
    if (closed || i + 1 < n) {
      const Q& l = lambda[(i + 1) % n];
      c[i] = c2 * l;
      b[i] += c2 * (Q(1) - l);
    } else {
      dx[i] -= c2 * ex;
      dy[i] -= c2 * ey;
    }
  }
  if (closed) {
    px = solve_cyclic_tridiagonal(a, b, c, dx);
    py = solve_cyclic_tridiagonal(a, b, c, dy);
  } else {
    px = solve_tridiagonal(a, b, c, dx);
    py = solve_tridiagonal(a, b, c, dy);
  }
}

/// Certified enclosure of the relative |kappa| mismatch (|k1| - |k2|) / (|k1| + |k2|) at the
/// join E of the exact pieces (A, P, E, wa) and (E, R, B, wb), by interval arithmetic on
/// enclosures of the exact coordinates (eq. 5: |kappa(1)| of the first piece is
/// |Delta(A,P,E)| / (wa^2 |E-P|^3), |kappa(0)| of the second |Delta(E,R,B)| / (wb^2 |R-E|^3)).
/// Cheaper than exact rationals, whose lengths grow along the curve.
inline void relative_mismatch_interval(const CGAL::Gmpq* a, const CGAL::Gmpq* p, const CGAL::Gmpq* e,
                                       const CGAL::Gmpq* r, const CGAL::Gmpq* b, const CGAL::Gmpq& wa,
                                       const CGAL::Gmpq& wb, double& lo, double& hi) {
  typedef CGAL::Interval_nt<false> I;
  CGAL::Protect_FPU_rounding<true> guard;
  auto iv = [](const CGAL::Gmpq& q) { const std::pair<double, double> x = CGAL::to_interval(q); return I(x.first, x.second); };
  const I ax = iv(a[0]), ay = iv(a[1]), px = iv(p[0]), py = iv(p[1]), ex = iv(e[0]), ey = iv(e[1]);
  const I rx = iv(r[0]), ry = iv(r[1]), bx = iv(b[0]), by = iv(b[1]), Wa = iv(wa), Wb = iv(wb);
  const I d1 = CGAL::abs((px - ax) * (ey - py) - (py - ay) * (ex - px));
  const I d2 = CGAL::abs((rx - ex) * (by - ry) - (ry - ey) * (bx - rx));
  const I l1 = CGAL::sqrt(CGAL::square(ex - px) + CGAL::square(ey - py));
  const I l2 = CGAL::sqrt(CGAL::square(rx - ex) + CGAL::square(ry - ey));
  const I k1 = d1 / (Wa * Wa * l1 * l1 * l1), k2 = d2 / (Wb * Wb * l2 * l2 * l2);
  const I m = (k1 - k2) / (k1 + k2);
  lo = m.inf();
  hi = m.sup();
}


} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_CERTIFY_H
