// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The basic shapes of fair/Basic_shape_design.h as open clamped splines. A shape given by a
// rational Bezier curve of degree <= 3 is degree-elevated to 3 (homogeneous Bernstein
// elevation, exact) and converted exactly: the one-piece clamped spline over [0,1] with a knot
// inserted at every marked parameter, which is the conversion of Sec. 6 (eqs. 9-10 amount to
// knot insertion into the one cubic, see doc/exact_conversion.md).

#ifndef FAIR_INTERNAL_BASIC_SHAPES_SHAPES_H
#define FAIR_INTERNAL_BASIC_SHAPES_SHAPES_H

#include <fair/Basic_shape_design.h>
#include <fair/Bernstein_polynomial.h>
#include <fair/Errors.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace basic_shapes {

/// Largest opening of one circle sub-arc: a quarter circle, so that the middle weight
/// cos(alpha/2) >= 1/sqrt(2) and the elevated weights (1 + 2 cos(alpha/2))/3 stay well above 0.
constexpr double max_sub_arc_opening = 1.5707963267948966;
/// Cap on the number of sub-arcs (an opening <= 2 pi needs at most 4).
constexpr std::size_t max_sub_arcs = 8;

/// Throws Invalid_input_error unless lo < marks[0] < ... < marks.back() < hi.
template <class T>
void check_marks(const std::vector<T>& marks, const T& lo, const T& hi, const char* fn) {
  for (std::size_t i = 0; i < marks.size(); ++i) {
    if (!(marks[i] > lo && marks[i] < hi))
      throw Invalid_input_error(message(fn, ": mark ", i, " = ", CGAL::to_double(marks[i]), " is not inside (",
                                        CGAL::to_double(lo), ", ", CGAL::to_double(hi), ")"));
    if (i > 0 && !(marks[i - 1] < marks[i]))
      throw Invalid_input_error(message(fn, ": marks must be strictly increasing, mark ", i - 1, " = ",
                                        CGAL::to_double(marks[i - 1]), " and mark ", i, " = ",
                                        CGAL::to_double(marks[i])));
  }
}

/// The same rational curve as a piece of degree 3 (homogeneous degree elevation, exact).
template <class K>
Rational_bezier_2<K> elevated_to_cubic(const Rational_bezier_2<K>& c, const char* fn) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  if (c.degree() > 3) throw Invalid_input_error(message(fn, ": degree ", c.degree(), " > 3"));
  if (c.degree() == 3) return c;
  const std::size_t times = 3 - c.degree();
  const Bernstein_polynomial<FT> x = c.homogeneous_x().elevated(times), y = c.homogeneous_y().elevated(times),
                                 w = c.homogeneous_w().elevated(times);
  std::vector<Point_2> p;
  std::vector<FT> ws;
  for (std::size_t i = 0; i <= 3; ++i) {
    p.push_back(Point_2(x[i] / w[i], y[i] / w[i]));
    ws.push_back(w[i]);
  }
  return Rational_bezier_2<K>(std::move(p), std::move(ws));
}

/// The open clamped spline of the cubic `c` over [0,1] with knots at the marks (already checked).
template <class K>
Cubic_spline_2<K> exact_cubic_spline(const Rational_bezier_2<K>& c, const std::vector<typename K::FT>& marks) {
  typedef typename K::FT FT;
  const std::vector<FT> unit = {FT(0), FT(1)};
  Cubic_spline_2<K> s = c.is_polynomial()
                            ? Cubic_spline_2<K>::from_bezier_pieces(unit, {Bezier_2<K>(c.control_points())})
                            : Cubic_spline_2<K>::from_rational_bezier_pieces(unit, {c});
  for (const FT& u : marks) s = s.with_knot_inserted(u);
  return s;
}

/// The standard rational quadratic circle arc of centre c, radius r from angle a to angle a + alpha
/// (0 < alpha < pi): P0, P2 on the circle, P1 at r / cos(alpha/2) on the bisector, w = cos(alpha/2).
template <class K>
Rational_quadratic_bezier_2<K> circle_sub_arc(const typename K::Point_2& c, const typename K::FT& r, double a,
                                              double alpha) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  const double mid = a + alpha / 2, w = std::cos(alpha / 2);
  const FT r1 = r / FT(w);
  const Point_2 p0(c.x() + r * FT(std::cos(a)), c.y() + r * FT(std::sin(a)));
  const Point_2 p1(c.x() + r1 * FT(std::cos(mid)), c.y() + r1 * FT(std::sin(mid)));
  const Point_2 p2(c.x() + r * FT(std::cos(a + alpha)), c.y() + r * FT(std::sin(a + alpha)));
  return Rational_quadratic_bezier_2<K>(p0, p1, p2, FT(w));
}

/// The parameter of the point at angle delta from the start of a standard rational quadratic arc
/// of opening alpha: eq. 4 in the form without a case split,
/// u = sin(delta/2) / (sin(delta/2) + sin((alpha - delta)/2)).
inline double arc_parameter(double delta, double alpha) {
  const double a = std::sin(delta / 2), b = std::sin((alpha - delta) / 2);
  return a / (a + b);
}

} // namespace basic_shapes
} // namespace internal

// ------------------------------------------------------------------ Basic_shape_2

template <class K>
Basic_shape_2<K>::Basic_shape_2(Spline part, std::string kind) : kind_(std::move(kind)) {
  internal::require(!part.is_closed(), "Basic_shape_2: a shape is an open spline, got a closed one");
  parts_.push_back(std::move(part));
}

template <class K>
Basic_shape_2<K>::Basic_shape_2(std::vector<Spline> parts, std::string kind)
  : parts_(std::move(parts)), kind_(std::move(kind)) {
  internal::require(!parts_.empty(), "Basic_shape_2: a shape needs at least one part");
  for (std::size_t i = 0; i < parts_.size(); ++i)
    internal::require(!parts_[i].is_closed(), "Basic_shape_2: part ", i, " is closed, a part is an open spline");
}

template <class K>
Basic_shape_2<K> Basic_shape_2<K>::segment(const Point_2& from, const Point_2& to, const std::vector<FT>& marks) {
  const char* fn = "fair::Basic_shape_2::segment";
  if (from == to)
    throw Invalid_input_error(internal::message(fn, ": zero-length segment at (", CGAL::to_double(from.x()), ", ",
                                                CGAL::to_double(from.y()), ")"));
  internal::basic_shapes::check_marks(marks, FT(0), FT(1), fn);
  const typename K::Vector_2 d = (to - from) / FT(3);
  const Rational_bezier_2<K> line({from, from + d, to - d, to});
  return Basic_shape_2(internal::basic_shapes::exact_cubic_spline(line, marks), "segment");
}

template <class K>
Basic_shape_2<K> Basic_shape_2<K>::conic(const Rational_quadratic_bezier_2<K>& arc, const std::vector<FT>& marks) {
  const char* fn = "fair::Basic_shape_2::conic";
  internal::basic_shapes::check_marks(marks, FT(0), FT(1), fn);
  const Rational_bezier_2<K> c = internal::basic_shapes::elevated_to_cubic(Rational_bezier_2<K>(arc), fn);
  return Basic_shape_2(internal::basic_shapes::exact_cubic_spline(c, marks), "conic");
}

template <class K>
Basic_shape_2<K> Basic_shape_2<K>::cubic(const Rational_bezier_2<K>& curve, const std::vector<FT>& marks) {
  const char* fn = "fair::Basic_shape_2::cubic";
  internal::basic_shapes::check_marks(marks, FT(0), FT(1), fn);
  const Rational_bezier_2<K> c = internal::basic_shapes::elevated_to_cubic(curve, fn);
  return Basic_shape_2(internal::basic_shapes::exact_cubic_spline(c, marks), "cubic");
}

template <class K>
Basic_shape_2<K> Basic_shape_2<K>::circle_arc(const Point_2& center, const FT& radius, double start_angle,
                                              double end_angle, const std::vector<double>& mark_angles) {
  using namespace internal::basic_shapes;
  const char* fn = "fair::Basic_shape_2::circle_arc";
  const double r = CGAL::to_double(radius);
  if (!(radius > FT(0)) || !std::isfinite(r))
    throw Invalid_input_error(internal::message(fn, ": the radius ", r, " must be finite and > 0"));
  const double opening = end_angle - start_angle;
  if (!std::isfinite(start_angle) || !std::isfinite(end_angle) || !(opening > 0) || opening > 2 * M_PI)
    throw Invalid_input_error(internal::message(fn, ": degenerate arc from ", start_angle, " to ", end_angle,
                                                " rad: the opening ", opening,
                                                " must be in (0, 2 pi] (counter-clockwise)"));
  check_marks(mark_angles, start_angle, end_angle, fn);
  const std::size_t n = static_cast<std::size_t>(std::ceil(opening / max_sub_arc_opening - 1e-12));
  const std::size_t count = n == 0 ? 1 : n;
  FAIR_ASSERT_MSG(count <= max_sub_arcs, "circle arc of opening ", opening, " split into ", count, " sub-arcs");
  const double alpha = opening / double(count);
  std::vector<Spline> parts;
  std::size_t next = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double a = k == 0 ? start_angle : start_angle + double(k) * alpha;
    const double b = k + 1 == count ? end_angle : start_angle + double(k + 1) * alpha;
    std::vector<FT> marks;
    for (; next < mark_angles.size() && mark_angles[next] < b; ++next) {
      if (!(mark_angles[next] > a)) continue;  // on the split angle: the join of two sub-arcs already
      const double u = arc_parameter(mark_angles[next] - a, b - a);
      if (u > 0 && u < 1 && (marks.empty() || FT(u) > marks.back())) marks.push_back(FT(u));
    }
    const Rational_bezier_2<K> c = elevated_to_cubic(Rational_bezier_2<K>(circle_sub_arc<K>(center, radius, a, b - a)), fn);
    parts.push_back(exact_cubic_spline(c, marks));
  }
  return Basic_shape_2(std::move(parts), "arc");
}

} // namespace fair

#endif // FAIR_INTERNAL_BASIC_SHAPES_SHAPES_H
