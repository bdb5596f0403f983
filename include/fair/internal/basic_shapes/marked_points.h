// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Parameters of points marked on shapes given by points (the design file may mark a segment or a
// conic by points instead of parameters), with a check that the point is on the curve.
//   segment: u = (q - a).(b - a) / |b - a|^2 (exact), distance from the line |(q-a) x (b-a)| / |b-a|;
//   conic in standard form: with the barycentric coordinates tau_0, tau_1, tau_2 of q on the
//   control triangle, u = sqrt(tau_2) / (sqrt(tau_0) + sqrt(tau_2)) (tau_0 = (1-u)^2 / W,
//   tau_2 = u^2 / W on the curve; issue 10's closed form of eq. 5), then |f(u) - q| is checked.

#ifndef FAIR_INTERNAL_BASIC_SHAPES_MARKED_POINTS_H
#define FAIR_INTERNAL_BASIC_SHAPES_MARKED_POINTS_H

#include <fair/Errors.h>
#include <fair/Rational_quadratic_bezier_2.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <string>

namespace fair {
namespace internal {
namespace basic_shapes {

/// The parameter of q on the segment [a, b]; throws Invalid_input_error if q is farther than
/// tolerance * |b - a| from the line through a and b.
template <class K>
typename K::FT segment_parameter(const typename K::Point_2& a, const typename K::Point_2& b,
                                 const typename K::Point_2& q, double tolerance) {
  typedef typename K::FT FT;
  const typename K::Vector_2 d = b - a, e = q - a;
  const FT dd = d * d;
  const double cross = CGAL::to_double(d.x() * e.y() - d.y() * e.x());
  const double len = std::sqrt(CGAL::to_double(dd));
  const double off = std::fabs(cross) / len;
  if (!(off <= tolerance * len))
    throw Invalid_input_error(message("the marked point (", CGAL::to_double(q.x()), ", ", CGAL::to_double(q.y()),
                                      ") is off its segment: distance ", off, " > ", tolerance * len));
  return (e * d) / dd;
}

/// The parameter of q on the conic arc c; throws Invalid_input_error if f(u) is farther than
/// tolerance * (size of the control triangle) from q.
template <class K>
typename K::FT conic_parameter(const Rational_quadratic_bezier_2<K>& c, const typename K::Point_2& q,
                               double tolerance) {
  typedef typename K::FT FT;
  auto area = [](const typename K::Point_2& a, const typename K::Point_2& b, const typename K::Point_2& p) {
    return CGAL::to_double((b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x()));
  };
  const auto &p0 = c.control_point(0), &p1 = c.control_point(1), &p2 = c.control_point(2);
  const double A = area(p0, p1, p2);
  const double t0 = std::max(0.0, area(q, p1, p2) / A), t2 = std::max(0.0, area(p0, p1, q) / A);
  const double s0 = std::sqrt(t0), s2 = std::sqrt(t2);
  const double u = s0 + s2 > 0 ? s2 / (s0 + s2) : 0.5;
  const auto f = c.point(FT(u));
  const double dx = CGAL::to_double(f.x() - q.x()), dy = CGAL::to_double(f.y() - q.y());
  const double size = std::sqrt(CGAL::to_double(CGAL::squared_distance(p0, p1))) +
                      std::sqrt(CGAL::to_double(CGAL::squared_distance(p1, p2)));
  const double off = std::hypot(dx, dy);
  if (!(off <= tolerance * size))
    throw Invalid_input_error(message("the marked point (", CGAL::to_double(q.x()), ", ", CGAL::to_double(q.y()),
                                      ") is off its conic: the conic point at its closed-form parameter u = ", u, " is ", off,
                                      " away, more than ", tolerance * size));
  return FT(u);
}

} // namespace basic_shapes
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_BASIC_SHAPES_MARKED_POINTS_H
