// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Interpolation by rational quadratic pieces at a curvature extremum (Yan, Schiller, Schaefer
// [YSS19], eq. 6 and eq. 7): the certified parameter t at which a standard-form piece with end
// points P0, P2 and weight w has its curvature extremum at a given point Q, and the piece through
// Q at a given t. The building block of the kappa-curves (Kappa_curve_2.h).

#ifndef FAIR_RATIONAL_QUADRATIC_INTERPOLATION_H
#define FAIR_RATIONAL_QUADRATIC_INTERPOLATION_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Errors.h>
#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/internal/common/exact_conversion.h>
#include <fair/internal/conic/interpolation.h>

#include <CGAL/Gmpq.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <vector>

namespace fair {

/// The certified parameter at which Q is a curvature extremum (eq. 7), see
/// curvature_extremum_parameter().
template <class K>
struct Curvature_extremum_parameter {
  /// Bernstein coefficients of eq. 7 (eq. A.1): (-wA, -(A+B)/4, 0, (B+C)/4, wC), in FT (exact
  /// in an exact kernel; rounded in a floating kernel, where the certificate uses the exact
  /// values of the double inputs instead).
  Bernstein_polynomial<typename K::FT> polynomial;
  /// The exact root lies in [t_lower, t_upper] (f(t_lower) < 0 < f(t_upper) exactly, or
  /// t_lower == t_upper == root). Dyadic rationals, usually a few ulps apart.
  CGAL::Gmpq t_lower, t_upper;
  double t = 0.5;             ///< double approximation in [t_lower, t_upper]
  int sign_variations = 1;    ///< the certified sign variation count of eq. A.1 (always 1)
  int exact_evaluations = 0;  ///< exact sign evaluations the interval filter needed
};

/// Solves eq. 7: the parameter t in (0,1) at which the standard-form rational quadratic with end
/// points P0, P2, weight w, passing through Q at t (eq. 6), has a critical point of curvature
/// at Q. Verifies EXACTLY (Appendix A) that the eq.-A.1 coefficients have exactly one sign
/// variation, so the root is unique and simple, then refines it with a certified bracket a few
/// ulps wide, in every kernel (method in internal/conic/interpolation.h).
/// \throws Precondition_error if a coordinate or w is not finite, w <= 0, P0 == Q or P2 == Q.
template <class K>
Curvature_extremum_parameter<K> curvature_extremum_parameter(const typename K::Point_2& p0,
                                                             const typename K::Point_2& q,
                                                             const typename K::Point_2& p2,
                                                             const typename K::FT& w) {
  typedef typename K::FT FT;
  const char* fn = "curvature_extremum_parameter (eq. 7)";
  const std::array<FT, 5> b = internal::conic::eq7_coefficients<FT>(p0.x(), p0.y(), q.x(), q.y(), p2.x(), p2.y(), w);
  internal::conic::Rational_quadratic_extremum_parameter r;
  if constexpr (internal::common::Is_floating_nt<FT>::value) {
    // The double fast path (interval filter, exact fallback) on the exact values of the inputs.
    r = internal::conic::rational_quadratic_extremum_parameter(CGAL::to_double(p0.x()), CGAL::to_double(p0.y()),
                                                               CGAL::to_double(q.x()), CGAL::to_double(q.y()),
                                                               CGAL::to_double(p2.x()), CGAL::to_double(p2.y()),
                                                               CGAL::to_double(w));
  } else {
    internal::conic::check_eq7_input(p0, q, p2, w, fn);
    r = internal::conic::exact_rational_quadratic_extremum_parameter(b, fn);
  }
  Curvature_extremum_parameter<K> out;
  out.polynomial = Bernstein_polynomial<FT>(std::vector<FT>(b.begin(), b.end()));
  out.t = r.t;
  out.t_lower = CGAL::Gmpq(r.t_lower);
  out.t_upper = CGAL::Gmpq(r.t_upper);
  out.sign_variations = r.sign_variations;
  out.exact_evaluations = r.exact_evaluations;
  return out;
}

/// eq. 6: the standard-form piece with end points P0, P2 and weight w that passes through Q at
/// parameter t in (0,1). P1 = Q - ((1-t)^2 (P0-Q) + t^2 (P2-Q)) / (2 (1-t) t w), which is eq. 6
/// rearranged (exact in an exact kernel, so point(t) == Q exactly there).
/// \throws Precondition_error unless 0 < t < 1, or if the resulting piece is degenerate.
template <class K>
Rational_quadratic_bezier_2<K> rational_quadratic_through(const typename K::Point_2& p0,
                                                          const typename K::Point_2& q,
                                                          const typename K::Point_2& p2,
                                                          const typename K::FT& w, const typename K::FT& t) {
  typedef typename K::FT FT;
  internal::require(t > FT(0) && t < FT(1), "rational_quadratic_through (eq. 6): t = ", CGAL::to_double(t),
                    " is not in (0,1)");
  internal::require(std::isfinite(CGAL::to_double(w)) && w > FT(0),
                    "rational_quadratic_through (eq. 6): the weight must be finite and > 0, got w = ",
                    CGAL::to_double(w));
  const FT s = FT(1) - t, d = FT(2) * s * t * w;
  const typename K::Vector_2 v = ((p0 - q) * (s * s) + (p2 - q) * (t * t)) / d;
  return Rational_quadratic_bezier_2<K>(p0, q - v, p2, w);
}

} // namespace fair

#endif // FAIR_RATIONAL_QUADRATIC_INTERPOLATION_H
