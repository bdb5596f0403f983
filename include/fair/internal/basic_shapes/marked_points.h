// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Parameters of points marked on shapes given by points (the design file may mark a segment, a
// conic or a cubic by points instead of parameters), with a check that the point is on the curve:
//   segment: u = (q - a).(b - a) / |b - a|^2 (exact), distance from the line |(q-a) x (b-a)| / |b-a|;
//   conic: the closed form u = sqrt(tau_2) / (sqrt(tau_0) + sqrt(tau_2)) of issue 10;
//   cubic: eq. 5, the nearest point (bracketed Newton).

#ifndef FAIR_INTERNAL_BASIC_SHAPES_MARKED_POINTS_H
#define FAIR_INTERNAL_BASIC_SHAPES_MARKED_POINTS_H

#include <fair/Errors.h>
#include <fair/Marked_point_parameters.h>
#include <fair/Parametric_curve_2.h>
#include <fair/Rational_bezier_2.h>
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

/// The parameter of q on the conic arc c: the closed form of issue 10 (conic_parameter of
/// fair/Marked_point_parameters.h, in double); throws Invalid_input_error if q is off the arc.
template <class K>
typename K::FT conic_parameter(const Rational_quadratic_bezier_2<K>& c, const typename K::Point_2& q, double tolerance) {
  auto x = [&](std::size_t i) { return CGAL::to_double(c.control_point(i).x()); };
  auto y = [&](std::size_t i) { return CGAL::to_double(c.control_point(i).y()); };
  const Parametric_conic_arc_2 arc(x(0), y(0), x(1), y(1), x(2), y(2), CGAL::to_double(c.weight()));
  return typename K::FT(fair::conic_parameter(arc, CGAL::to_double(q.x()), CGAL::to_double(q.y()), tolerance));
}

/// A rational Bezier curve as a ParametricCurve_2 (fair/Parametric_curve_2.h) over [0, 1], its
/// jets evaluated in FT and rounded to double, for nearest_parameter (eq. 5).
template <class K>
class Bezier_parametric_curve {
public:
  explicit Bezier_parametric_curve(const Rational_bezier_2<K>& c) : c_(c) {}
  double parameter_begin() const { return 0; }
  double parameter_end() const { return 1; }
  Curve_jet_2 jet(double u) const {
    const typename K::FT t(u);
    const auto p = c_.point(t);
    const auto d = c_.derivative(t), e = c_.second_derivative(t);
    using CGAL::to_double;
    return Curve_jet_2{to_double(p.x()), to_double(p.y()), to_double(d.x()), to_double(d.y()), to_double(e.x()),
                       to_double(e.y())};
  }

private:
  const Rational_bezier_2<K>& c_;
};

/// The parameter of q on the rational cubic c by eq. 5 (nearest_parameter); throws
/// Invalid_input_error if q is farther than tolerance * (size of c) from c.
template <class K>
typename K::FT cubic_parameter(const Rational_bezier_2<K>& c, const typename K::Point_2& q, double tolerance) {
  Nearest_parameter_options o;
  o.tolerance = tolerance;
  return typename K::FT(
      nearest_parameter(Bezier_parametric_curve<K>(c), CGAL::to_double(q.x()), CGAL::to_double(q.y()), 0.0, 1.0, o));
}

} // namespace basic_shapes
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_BASIC_SHAPES_MARKED_POINTS_H
