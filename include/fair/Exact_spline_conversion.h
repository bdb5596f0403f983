// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact conversion of rational curves of degree <= 3 to the library's C2 cubic spline
// (Karciauskas-Peters Sec. 6, eqs. 9 and 10 as corrected in issue 10; doc/exact_conversion.md),
// and circle arcs as rational cubics with the splitting rule for large openings.
//
// exact_spline(f, u) marks 0 < u_1 < ... < u_{m-1} < 1 on f and returns the open clamped
// Cubic_spline_2 on the breakpoints 0, u_1, ..., u_{m-1}, 1 with the m+3 homogeneous control
// points d_0 = b_0, d_1 = f^h[0,0,u_1], d_{i+1} = c_i = f^h[u_{i-1}, u_i, u_{i+1}] (eq. 9, the
// blossom of the homogeneous cubic f^h), d_{m+1} = f^h[u_{m-1},1,1], d_{m+2} = b_3 (eq. 10).
// This is knot insertion of the u_i into the one Bezier piece, so the spline equals f on ALL of
// [0,1]: spline.point(t) == f.point(t) for every t, exactly in an exact kernel (EPECK,
// Simple_cartesian<Gmpq>); in double a few ulps per operation. Only +, -, *, / of FT: no square
// root. O(m).

#ifndef FAIR_EXACT_SPLINE_CONVERSION_H
#define FAIR_EXACT_SPLINE_CONVERSION_H

#include <fair/Bezier_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/Errors.h>
#include <fair/Rational_bezier_2.h>
#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/internal/exact_conversion/blossom.h>
#include <fair/internal/exact_conversion/circle.h>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {

/// The C2 cubic spline that reproduces `curve` (a rational or polynomial Bezier piece of degree
/// 0..3, degree-elevated to 3 in homogeneous coordinates) exactly on [0,1], with one breakpoint
/// at each interior parameter (see the file comment). Rational iff the curve's weights are not
/// all equal; the control weights are then blossoms of positive weights, hence positive.
/// \throws Precondition_error if the degree exceeds 3; Invalid_input_error unless the interior
/// parameters are finite, in (0,1) and strictly increasing (none at all gives the Bezier piece).
template <class K>
Cubic_spline_2<K> exact_spline(const Rational_bezier_2<K>& curve, const std::vector<typename K::FT>& interior_parameters) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  namespace ec = internal::exact_conversion;
  const char* fn = "exact_spline";
  ec::check_weights(curve, fn);
  const std::array<ec::Homogeneous<FT>, 4> b = ec::homogeneous_cubic(curve, fn);
  ec::check_marks(interior_parameters, fn);
  const std::vector<ec::Homogeneous<FT>> d = ec::de_boor_points(b, interior_parameters);
  std::vector<Point_2> points;
  std::vector<FT> weights;
  points.reserve(d.size());
  weights.reserve(d.size());
  for (const ec::Homogeneous<FT>& h : d) {
    FAIR_ASSERT_MSG(h.w > FT(0), "exact_spline: a blossom of positive weights is positive, got ", CGAL::to_double(h.w));
    points.push_back(Point_2(h.x / h.w, h.y / h.w));
    weights.push_back(h.w);
  }
  std::vector<FT> t = ec::unit_breakpoints(interior_parameters);
  if (curve.is_polynomial()) return Cubic_spline_2<K>(std::move(t), std::move(points), false);
  return Cubic_spline_2<K>(std::move(t), std::move(points), std::move(weights), false);
}

/// The polynomial piece (degree <= 3): a polynomial spline, same guarantees.
template <class K>
Cubic_spline_2<K> exact_spline(const Bezier_2<K>& curve, const std::vector<typename K::FT>& interior_parameters) {
  return exact_spline(Rational_bezier_2<K>(curve.control_points()), interior_parameters);
}

/// A conic arc in standard form (weights 1, w, 1), degree-elevated to (1, (1+2w)/3, (1+2w)/3, 1).
template <class K>
Cubic_spline_2<K> exact_spline(const Rational_quadratic_bezier_2<K>& conic, const std::vector<typename K::FT>& interior_parameters) {
  return exact_spline(Rational_bezier_2<K>(conic), interior_parameters);
}

/// The degree-elevated cubic of the homogeneous conic (P0, 1), (hx, hy, hw), (P2, 1) -- the
/// standard form with hw = w, (hx, hy) = w P1, but valid for w <= 0 as well (arcs of 180 degrees
/// or more, where the quadratic's P1 is at infinity or behind the chord). Exact in FT.
/// \throws Precondition_error unless hw > -1/2 (otherwise a cubic weight is <= 0).
template <class K>
Rational_bezier_2<K> homogeneous_conic_cubic(const typename K::Point_2& p0, const typename K::FT& hx,
                                             const typename K::FT& hy, const typename K::FT& hw,
                                             const typename K::Point_2& p2) {
  return internal::exact_conversion::conic_cubic<K>(p0, hx, hy, hw, p2, "homogeneous_conic_cubic");
}

/// Largest circle arc opening a rational cubic with positive weights can represent (exclusive).
constexpr double max_circle_arc_cubic_opening = 4 * internal::exact_conversion::pi / 3;

/// The rational cubic of the counter-clockwise circle arc of centre `center` and radius `radius`
/// from `start_angle` to `end_angle` (radians), opening alpha = end - start in (0, 240 deg),
/// built from the homogeneous quadratic so that 180 deg <= alpha < 240 deg works. The cos and
/// sin of the angles are rounded to double, so in an exact kernel the result is the exact
/// rational cubic through those rounded values (use rational_circle_arc_cubic for exact data).
/// \throws Precondition_error if the radius is not finite and > 0, an angle is not finite, or
/// alpha is not in (0, max_circle_arc_cubic_opening).
template <class K>
Rational_bezier_2<K> circle_arc_cubic(const typename K::Point_2& center, const typename K::FT& radius,
                                      double start_angle, double end_angle) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  namespace ec = internal::exact_conversion;
  const char* fn = "circle_arc_cubic";
  const double r = CGAL::to_double(radius);
  internal::require(std::isfinite(r) && radius > FT(0), fn, ": radius ", r, " must be finite and > 0");
  ec::check_finite_angle(start_angle, "start_angle", fn);
  ec::check_finite_angle(end_angle, "end_angle", fn);
  const double alpha = end_angle - start_angle;
  internal::require(alpha > 0 && alpha < max_circle_arc_cubic_opening, fn, ": the opening ", alpha, " rad (",
                    alpha * 180 / ec::pi, " deg; start ", start_angle, ", end ", end_angle,
                    ") must be in (0, 240 deg): the cubic weights (1 + 2 cos(alpha/2))/3 must be positive; "
                    "split larger arcs with circle_arc_split");
  const double m = 0.5 * (start_angle + end_angle);
  const FT w(std::cos(0.5 * alpha));
  const Point_2 p0(center.x() + radius * FT(std::cos(start_angle)), center.y() + radius * FT(std::sin(start_angle)));
  const Point_2 p2(center.x() + radius * FT(std::cos(end_angle)), center.y() + radius * FT(std::sin(end_angle)));
  return ec::conic_cubic<K>(p0, w * center.x() + radius * FT(std::cos(m)), w * center.y() + radius * FT(std::sin(m)), w,
                            p2, fn);
}

/// The same arc from exact data: its end angles theta_0 < theta_1 are given by the rational
/// quarter-angle tangents q_k = tan(theta_k / 4) (q_0 < q_1), so that every control point and
/// weight is rational and x^2 + y^2 = r^2 holds EXACTLY on the arc in an exact kernel. Example:
/// q_0 = 0, q_1 = 1/2 on the unit circle gives the quadratic w = 3/5, P0 = (1,0), P1 = (1,4/3),
/// P2 = (-7/25,24/25) of issue 10.
/// \throws Precondition_error if the radius is not > 0, q_0 >= q_1, or the opening is >= 240 deg.
template <class K>
Rational_bezier_2<K> rational_circle_arc_cubic(const typename K::Point_2& center, const typename K::FT& radius,
                                               const typename K::FT& q0, const typename K::FT& q1) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  const char* fn = "rational_circle_arc_cubic";
  internal::require(radius > FT(0), fn, ": radius ", CGAL::to_double(radius), " must be > 0");
  internal::require(q0 < q1, fn, ": the quarter-angle tangents must increase, got q0 = ", CGAL::to_double(q0),
                    ", q1 = ", CGAL::to_double(q1));
  // half angles: cos(theta/2), sin(theta/2) from q = tan(theta/4)
  const FT n0 = FT(1) + q0 * q0, n1 = FT(1) + q1 * q1;
  const FT c0 = (FT(1) - q0 * q0) / n0, s0 = FT(2) * q0 / n0, c1 = (FT(1) - q1 * q1) / n1, s1 = FT(2) * q1 / n1;
  const FT w = c1 * c0 + s1 * s0;           // cos(alpha/2)
  const FT half_sin = s1 * c0 - c1 * s0;    // sin(alpha/2) > 0 iff alpha < 360 deg
  internal::require(half_sin > FT(0) && FT(1) + FT(2) * w > FT(0), fn, ": the arc from q0 = ", CGAL::to_double(q0),
                    " to q1 = ", CGAL::to_double(q1), " opens ", 4 * (std::atan(CGAL::to_double(q1)) - std::atan(CGAL::to_double(q0))),
                    " rad, not less than 240 deg: split it");
  const FT cm = c0 * c1 - s0 * s1, sm = s0 * c1 + c0 * s1; // (cos, sin) of the mid angle
  const Point_2 p0(center.x() + radius * (c0 * c0 - s0 * s0), center.y() + radius * FT(2) * s0 * c0);
  const Point_2 p2(center.x() + radius * (c1 * c1 - s1 * s1), center.y() + radius * FT(2) * s1 * c1);
  return internal::exact_conversion::conic_cubic<K>(p0, w * center.x() + radius * cm, w * center.y() + radius * sm, w, p2, fn);
}

/// The splitting rule: an arc of opening alpha = end - start > 180 deg is split into
/// k = ceil(alpha / 180 deg) equal sub-arcs (a full circle into 2), otherwise returned whole.
/// Why 180 deg and not 240 deg: the inner Bezier points of the arc's cubic lie at distance
/// 2 r sin(alpha/2) / (1 + 2 cos(alpha/2)) from the end points along the end tangents -- at most
/// 2 r for alpha <= 180 deg, unbounded as alpha -> 240 deg -- and the inner weights
/// (1 + 2 cos(alpha/2))/3 are >= 1/3 for alpha <= 180 deg but tend to 0: sub-arcs of at most
/// 180 deg keep the control polygon a usable design handle and the weights well conditioned.
/// \throws Precondition_error unless the angles are finite and 0 < alpha <= 2 pi.
inline std::vector<std::pair<double, double>> circle_arc_split(double start_angle, double end_angle) {
  return internal::exact_conversion::split_arc(start_angle, end_angle);
}

} // namespace fair

#endif // FAIR_EXACT_SPLINE_CONVERSION_H
