// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Interval filters of the kappa-curve certification (certify.h): outward-rounded interval
// arithmetic on enclosures of the exact coordinates decides the curvature extrema of a piece
// (eq. 4) and encloses the relative |kappa| mismatch at a join (eq. 5) without exact rationals,
// whose lengths grow along the curve. An undecided filter hands over to the exact predicates.

#ifndef FAIR_INTERNAL_KAPPA_INTERVAL_FILTERS_H
#define FAIR_INTERNAL_KAPPA_INTERVAL_FILTERS_H

#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/internal/conic/curvature_extrema.h>

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// Smallest half width of the bracket (t - delta, t + delta) that eq4_filtered_extremum tries:
/// a few hundred ulps of t in (0,1), above the rounding of the solver's t_i.
constexpr double filter_bracket_first = 0x1p-44;
/// Largest half width tried; beyond it the exact isolation is cheaper than more brackets.
constexpr double filter_bracket_last = 0x1p-20;
/// Growth of the half width from one bracket to the next.
constexpr double filter_bracket_growth = 8;

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
  int sign[5];
  const int variations = conic::certain_sign_variations(c.data(), 5, sign);
  if (variations <= 0) return variations;
  if (variations != 1) return -1;
  kind = sign[0] < 0 ? Curvature_extremum_kind::MAXIMUM : Curvature_extremum_kind::MINIMUM;
  for (double delta = filter_bracket_first; delta <= filter_bracket_last; delta *= filter_bracket_growth) {
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

#endif // FAIR_INTERNAL_KAPPA_INTERVAL_FILTERS_H
