// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Marks on the shapes of a design (fair/Basic_shape_design.h, doc/basic_shapes.md): a design file
// (fair/io/read_design.h) may mark a segment, a conic or a rational cubic by a point on it instead
// of a parameter; these functions give the point's parameter, and refuse a point off its shape:
//   segment: u = (q - a).(b - a) / |b - a|^2 (exact in an exact kernel), distance from the line
//            |(q - a) x (b - a)| / |b - a|;
//   conic:   the closed form u = sqrt(tau_2) / (sqrt(tau_0) + sqrt(tau_2)) of issue 10
//            (fair::conic_parameter, fair/Marked_point_parameters.h);
//   cubic:   eq. 5 of Karciauskas-Peters, the nearest point (fair::nearest_parameter).
// The marked points themselves are the shapes' points at these parameters (Design_file::marked_points).

#ifndef FAIR_DESIGN_MARKS_H
#define FAIR_DESIGN_MARKS_H

#include <fair/Errors.h>
#include <fair/Marked_point_parameters.h>
#include <fair/Parametric_curve_2.h>
#include <fair/Rational_bezier_2.h>
#include <fair/Rational_quadratic_bezier_2.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <string>

namespace fair {

/// The parameter of q on the segment [a, b]; throws Invalid_input_error if q is farther than
/// tolerance * |b - a| from the line through a and b.
template <class K>
typename K::FT segment_mark_parameter(const typename K::Point_2& a, const typename K::Point_2& b,
                                 const typename K::Point_2& q, double tolerance) {
  typedef typename K::FT FT;
  const typename K::Vector_2 d = b - a, e = q - a;
  const FT dd = d * d;
  const double cross = CGAL::to_double(d.x() * e.y() - d.y() * e.x());
  const double len = std::sqrt(CGAL::to_double(dd));
  const double off = std::fabs(cross) / len;
  if (!(off <= tolerance * len))
    throw Invalid_input_error(internal::message("the marked point (", CGAL::to_double(q.x()), ", ", CGAL::to_double(q.y()),
                                      ") is off its segment: distance ", off, " > ", tolerance * len));
  return (e * d) / dd;
}

/// The parameter of q on the conic arc c: the closed form of issue 10 (fair::conic_parameter,
/// in double); throws Invalid_input_error if q is off the arc.
template <class K>
typename K::FT conic_mark_parameter(const Rational_quadratic_bezier_2<K>& c, const typename K::Point_2& q, double tolerance) {
  auto x = [&](std::size_t i) { return CGAL::to_double(c.control_point(i).x()); };
  auto y = [&](std::size_t i) { return CGAL::to_double(c.control_point(i).y()); };
  const Parametric_conic_arc_2 arc(x(0), y(0), x(1), y(1), x(2), y(2), CGAL::to_double(c.weight()));
  return typename K::FT(fair::conic_parameter(arc, CGAL::to_double(q.x()), CGAL::to_double(q.y()), tolerance));
}

/// A rational Bezier curve as a ParametricCurve_2 (fair/Parametric_curve_2.h) over [0, 1], its
/// jets evaluated in FT and rounded to double, for nearest_parameter (eq. 5).
template <class K>
class Rational_bezier_parametric_2 {
public:
  explicit Rational_bezier_parametric_2(const Rational_bezier_2<K>& c) : c_(c) {}
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
typename K::FT cubic_mark_parameter(const Rational_bezier_2<K>& c, const typename K::Point_2& q, double tolerance) {
  Nearest_parameter_options o;
  o.tolerance = tolerance;
  return typename K::FT(
      nearest_parameter(Rational_bezier_parametric_2<K>(c), CGAL::to_double(q.x()), CGAL::to_double(q.y()), 0.0, 1.0, o));
}

} // namespace fair

#endif // FAIR_DESIGN_MARKS_H
