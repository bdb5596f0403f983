// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Circle arcs and conics as homogeneous rational cubics (Karciauskas-Peters Sec. 6, "arcs
// with negative weights after degree elevation are split").
//
// A conic in homogeneous quadratic form (P0, 1), H = (w P1, w), (P2, 1) elevates to
//   (P0, 1), ((P0 + 2 w P1)/3, (1 + 2w)/3), ((2 w P1 + P2)/3, (1 + 2w)/3), (P2, 1).
// Only H = w P1 enters, so the form works for w <= 0 too (P1 at infinity for w = 0, behind the
// chord for w < 0), and the cubic weights are positive iff w > -1/2.
// Circle arc of centre C, radius r from angle a0 to a1 (opening alpha = a1 - a0, mid angle
// m = (a0 + a1)/2): w = cos(alpha/2), P1 = C + r (cos m, sin m)/w, so
//   H = (w C + r (cos m, sin m), w):  finite for every alpha, positive cubic weights iff alpha < 240 deg.
// Rational data: with q = tan(theta/4) rational, cos(theta/2) = (1-q^2)/(1+q^2),
// sin(theta/2) = 2q/(1+q^2) are rational, hence so are cos theta, sin theta, w = cos(alpha/2) and
// (cos m, sin m) (angle addition): the arc is exact, and x^2 + y^2 = r^2 holds exactly on it.

#ifndef FAIR_INTERNAL_EXACT_CONVERSION_CIRCLE_H
#define FAIR_INTERNAL_EXACT_CONVERSION_CIRCLE_H

#include <fair/Errors.h>
#include <fair/internal/common/constants.h>
#include <fair/Rational_bezier_2.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace exact_conversion {

using common::pi;

/// The elevated cubic of the homogeneous quadratic (P0,1), (hx, hy, hw), (P2,1).
/// \throws Precondition_error unless 1 + 2 hw > 0 (the cubic weights must be positive).
template <class K>
Rational_bezier_2<K> conic_cubic(const typename K::Point_2& p0, const typename K::FT& hx, const typename K::FT& hy,
                                 const typename K::FT& hw, const typename K::Point_2& p2, const char* fn) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  const FT w = (FT(1) + FT(2) * hw) / FT(3);
  require(w > FT(0), fn, ": the conic weight ", CGAL::to_double(hw),
          " is <= -1/2, so its cubic weight (1 + 2w)/3 = ", CGAL::to_double(w),
          " is not positive (a circle arc of 240 degrees or more): split the arc first (circle_arc_split)");
  const Point_2 b1((p0.x() + FT(2) * hx) / FT(3) / w, (p0.y() + FT(2) * hy) / FT(3) / w);
  const Point_2 b2((p2.x() + FT(2) * hx) / FT(3) / w, (p2.y() + FT(2) * hy) / FT(3) / w);
  return Rational_bezier_2<K>(std::vector<Point_2>{p0, b1, b2, p2}, std::vector<FT>{FT(1), w, w, FT(1)});
}

inline void check_finite_angle(double a, const char* what, const char* fn) {
  require(std::isfinite(a), fn, ": ", what, " = ", a, " is not finite");
}

/// Sub-arcs of at most 180 degrees (see Exact_spline_conversion.h).
inline std::vector<std::pair<double, double>> split_arc(double a0, double a1) {
  const char* fn = "circle_arc_split";
  check_finite_angle(a0, "start_angle", fn);
  check_finite_angle(a1, "end_angle", fn);
  const double alpha = a1 - a0;
  require(alpha > 0 && alpha <= 2 * pi, fn, ": the opening end_angle - start_angle = ", alpha,
          " (start ", a0, ", end ", a1, ") must be in (0, 2 pi]");
  const int k = alpha > pi ? int(std::ceil(alpha / pi)) : 1; // alpha <= 2 pi: k <= 2 (3 by rounding)
  std::vector<std::pair<double, double>> out;
  for (int i = 0; i < k; ++i)
    out.push_back(std::make_pair(a0 + alpha * i / k, i + 1 == k ? a1 : a0 + alpha * (i + 1) / k));
  return out;
}

} // namespace exact_conversion
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_EXACT_CONVERSION_CIRCLE_H
