// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The curvature extrema of a standard-form rational quadratic (eq. 4 of Yan, Schiller,
// Schaefer, "Circle reproduction with interpolatory curves at local maximal curvature points"),
// behind Rational_quadratic_bezier_2::curvature_extrema().
//
// The numerator E of kappa'(t) is a quartic in Bernstein form (eq4_coefficients). Two stages:
//  - fast path (eq4_unique_extremum): the coefficients are enclosed by interval arithmetic on
//    enclosures of the exact inputs; when their signs are certain and show 0 variations (no
//    root in [0,1]) or 1 variation (exactly one simple root in (0,1), Descartes' rule in the
//    Bernstein basis), the root is bracketed by certified_unique_root_quartic
//    (internal/conic/quartic_root.h): certified for the exact inputs, E(t_lower) and E(t_upper)
//    of opposite exact signs, bracket a few ulps wide, exact fallback inside;
//  - otherwise (isolated_curvature_extrema): certified isolation (fair::Bernstein_root_isolation)
//    of E built exactly from the exact values of the inputs; then, for a root of multiplicity m,
//    the exact sign sigma of E just right of the root: E(upper) for an open interval (there is
//    no other root in (root, upper)), or the m-th derivative of E at an exact (point) root.
//    Odd m: E changes sign, -,+ means MAXIMUM of |kappa| and +,- MINIMUM; even m: STATIONARY.
// Both stages return the same extrema; the fast path avoids the exact isolation on almost
// every piece.
// Both fill fair::Curvature_extremum, declared in Rational_quadratic_bezier_2.h, which includes
// this file: the result type is a template parameter (`Extremum`, with members t_lower, t_upper,
// t, multiplicity and kind of the enum type Curvature_extremum_kind) so that the public header
// stays its one owner without an include cycle.

#ifndef FAIR_INTERNAL_CONIC_CURVATURE_EXTREMA_H
#define FAIR_INTERNAL_CONIC_CURVATURE_EXTREMA_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Bernstein_root_isolation.h>
#include <fair/Errors.h>
#include <fair/internal/conic/quartic_root.h>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace conic {

/// Roots that are dyadic rationals with at most this many bits after the binary point (e.g. 1/2
/// for a symmetric piece) are tested exactly and reported as point roots t_lower == t_upper.
constexpr int short_dyadic_root_bits = 32;

/// Bisections of an isolating interval while looking for the sign of E next to its root. One
/// always suffices (an end that is itself a root is bisected away, or the root becomes a point);
/// the cap only turns a bug into an Internal_error instead of a loop.
constexpr int max_sign_search_bisections = 4000;

/// The signs of n interval coefficients and their number of sign variations, or -1 when a
/// coefficient enclosure contains 0 (the filter cannot decide; the caller goes exact). Shared by
/// the eq.-4 filters of the conic piece and of the kappa certificate.
inline int certain_sign_variations(const CGAL::Interval_nt<false>* c, int n, int* sign) {
  int variations = 0;
  for (int i = 0; i < n; ++i) {
    if (c[i].inf() > 0) sign[i] = 1;
    else if (c[i].sup() < 0) sign[i] = -1;
    else return -1;
    if (i > 0 && sign[i] != sign[i - 1]) ++variations;
  }
  return variations;
}

/// The Bernstein coefficients of the numerator of kappa'(t), eq. 4 of the paper, in any number
/// type. The paper's polynomial E satisfies  W' |V|^2 - W V.V' = -4 E  (checked symbolically),
/// and d|kappa|/dt has the sign of W' |V|^2 - W V.V', hence the sign of -E.
template <class NT>
std::vector<NT> eq4_coefficients(const NT& x0, const NT& y0, const NT& x1, const NT& y1, const NT& x2,
                                 const NT& y2, const NT& w) {
  const NT ax = x0 - x1, ay = y0 - y1;   // P0 - P1
  const NT bx = x0 - x2, by = y0 - y2;   // P0 - P2
  const NT cx = x1 - x2, cy = y1 - y2;   // P1 - P2
  const NT n01 = ax * ax + ay * ay, n02 = bx * bx + by * by, n12 = cx * cx + cy * cy;
  const NT w2 = w * w, w3 = w2 * w;
  const NT quarter = NT(1) / NT(4), half = NT(1) / NT(2);
  // (P2 - P0).(P0 - 2 P1 + P2) = -(P0-P2).((P0-P1) - (P1-P2))
  const NT mid = -(bx * (ax - cx) + by * (ay - cy));
  return {NT(-2) * w3 * n01 + w * (ax * bx + ay * by),
          -(w2 * n01) + quarter * n02,
          half * w * mid,
          -(quarter * n02) + w2 * n12,
          -(w * (bx * cx + by * cy)) + NT(2) * w3 * n12};
}

/// Interval fast path for the extrema of eq. 4. Inputs: enclosures of the exact coordinates of
/// P0, P1, P2 and of w, and `exact()` returning the exact eq.-4 coefficients (called only if an
/// interval sign is undecided near the root). Returns 0 when the enclosed coefficients certify
/// that E has no root in [0,1] (no sign variation); 1 when they certify exactly one simple root
/// in (0,1) (one variation, nonzero ends), which is then stored in `x` with a certified bracket
/// (E(t_lower), E(t_upper) of opposite exact signs, or t_lower == t_upper == the exact root,
/// detected for short dyadic roots, see short_dyadic_root_bits) and its kind (E from - to + is
/// a MAXIMUM of |kappa|); -1 when the intervals cannot decide (the caller then runs
/// isolated_curvature_extrema). The bracket is a few ulps wide (see quartic_root.h).
template <class Exact_coefficients, class Extremum>
int eq4_unique_extremum(const Rq_interval& x0, const Rq_interval& y0, const Rq_interval& x1, const Rq_interval& y1,
                        const Rq_interval& x2, const Rq_interval& y2, const Rq_interval& w,
                        Exact_coefficients exact, Extremum& x) {
  typedef decltype(x.kind) Kind;
  Rq_interval b[5];
  int sign[5];
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const std::vector<Rq_interval> c = eq4_coefficients<Rq_interval>(x0, y0, x1, y1, x2, y2, w);
    std::copy(c.begin(), c.end(), b);
    const int variations = certain_sign_variations(b, 5, sign);
    if (variations <= 0) return variations;
    if (variations != 1) return -1;
    if (sign[0] > 0)
      for (int i = 0; i < 5; ++i) b[i] = -b[i]; // certified_unique_root_quartic wants f(0) < 0
  }
  const int flip = sign[0];
  bool have_exact = false;
  std::array<CGAL::Gmpq, 5> e;
  auto exact_sign = [&](double t) {
    if (!have_exact) {
      const std::vector<CGAL::Gmpq> v = exact();
      for (std::size_t i = 0; i < 5; ++i) e[i] = flip > 0 ? CGAL::Gmpq(-v[i]) : v[i];
      have_exact = true;
    }
    return quartic_sign_exact(e, t);
  };
  const Quartic_root r = certified_unique_root_quartic(b, exact_sign);
  x.multiplicity = 1;
  x.kind = sign[0] < 0 ? Kind::MAXIMUM : Kind::MINIMUM;
  x.t = r.t;
  // The shortest dyadic nearby.
  const double m = std::ldexp(std::nearbyint(std::ldexp(r.t, short_dyadic_root_bits)), -short_dyadic_root_bits);
  if (r.t_lower < m && m < r.t_upper && exact_sign(m) == CGAL::ZERO) {
    x.t = m;
    x.t_lower = x.t_upper = CGAL::Gmpq(m); // a short dyadic exact root (e.g. 1/2 by symmetry)
    return 1;
  }
  x.t_lower = CGAL::Gmpq(r.t_lower);
  x.t_upper = CGAL::Gmpq(r.t_upper);
  return 1;
}

/// The certified critical points in (0,1) of the exact eq.-4 polynomial E (not identically
/// zero), sorted, each with its kind: exact isolation, see the file comment.
template <class Extremum>
std::vector<Extremum> isolated_curvature_extrema(const Bernstein_polynomial<CGAL::Gmpq>& E) {
  typedef decltype(Extremum::kind) Kind;
  std::vector<Extremum> out;
  Bernstein_root_isolation iso(E);
  for (std::size_t i = 0; i < iso.number_of_roots(); ++i) {
    const Isolating_interval I = iso[i];
    if (I.is_point() && (CGAL::is_zero(I.lower) || I.lower == CGAL::Gmpq(1))) continue; // t = 0 or 1
    Extremum x;
    x.multiplicity = I.multiplicity;
    int right = 0;
    for (int attempt = 0; right == 0 && attempt < max_sign_search_bisections; ++attempt) {
      const Isolating_interval& J = iso[i];
      if (J.is_point()) {
        Bernstein_polynomial<CGAL::Gmpq> d = E;
        for (int k = 0; k < J.multiplicity; ++k) d = d.derivative();
        right = CGAL::sign(d.evaluate(J.lower));
      } else {
        // No other root in (root, upper): E(upper) is the sign just right of the root unless
        // upper is itself the next root; likewise for lower. Otherwise bisect once more.
        right = CGAL::sign(E.evaluate(J.upper));
        if (right == 0) {
          const int l = CGAL::sign(E.evaluate(J.lower));
          right = (J.multiplicity % 2 == 1) ? -l : l;
        }
        if (right == 0) iso.refine(i, J.width() / 2);
      }
    }
    FAIR_ASSERT_MSG(right != 0, "Rational_quadratic_bezier_2::curvature_extrema: no sign next to the root in ", iso[i]);
    const int left = (I.multiplicity % 2 == 1) ? -right : right;
    if (I.multiplicity % 2 == 0) x.kind = Kind::STATIONARY;
    else x.kind = (left < 0 && right > 0) ? Kind::MAXIMUM : Kind::MINIMUM;
    x.t = iso.root_approximation(i);
    x.t_lower = iso[i].lower;
    x.t_upper = iso[i].upper;
    out.push_back(x);
  }
  return out;
}

} // namespace conic
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_CONIC_CURVATURE_EXTREMA_H
