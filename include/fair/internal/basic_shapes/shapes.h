// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The basic shapes of fair/Basic_shape_design.h as open clamped splines, by the conversions of
// the library: a shape given by a rational Bezier curve of degree <= 3 by exact_spline (Sec. 6,
// eqs. 9-10, exact; fair/Exact_spline_conversion.h), a circle arc split by circle_arc_split
// into sub-arcs of at most 180 degrees, each circle_arc_cubic with its marks through eq. 4
// (circle_arc_parameter, fair/Marked_point_parameters.h), a parametric curve by
// parametric_curve_spline (Sec. 5, fair/Parametric_curve_spline.h).

#ifndef FAIR_INTERNAL_BASIC_SHAPES_SHAPES_H
#define FAIR_INTERNAL_BASIC_SHAPES_SHAPES_H

#include <fair/Basic_shape_design.h>
#include <fair/Errors.h>
#include <fair/Exact_spline_conversion.h>
#include <fair/internal/common/constants.h>
#include <fair/Marked_point_parameters.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace basic_shapes {

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
  // The line of degree 1, elevated by exact_spline: linearly parametrised (linear precision).
  return Basic_shape_2(exact_spline(Rational_bezier_2<K>({from, to}), marks), "segment");
}

template <class K>
Basic_shape_2<K> Basic_shape_2<K>::conic(const Rational_quadratic_bezier_2<K>& arc, const std::vector<FT>& marks) {
  return Basic_shape_2(exact_spline(arc, marks), "conic");
}

template <class K>
Basic_shape_2<K> Basic_shape_2<K>::cubic(const Rational_bezier_2<K>& curve, const std::vector<FT>& marks) {
  return Basic_shape_2(exact_spline(curve, marks), "cubic");
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
  if (!std::isfinite(start_angle) || !std::isfinite(end_angle) || !(opening > 0) || opening > internal::common::two_pi)
    throw Invalid_input_error(internal::message(fn, ": degenerate arc from ", start_angle, " to ", end_angle,
                                                " rad: the opening ", opening,
                                                " must be in (0, 2 pi] (counter-clockwise)"));
  check_marks(mark_angles, start_angle, end_angle, fn);
  std::vector<Spline> parts;
  std::size_t next = 0;
  for (const std::pair<double, double>& sub : circle_arc_split(start_angle, end_angle)) {
    const double a = sub.first, b = sub.second;
    std::vector<FT> marks;
    for (; next < mark_angles.size() && mark_angles[next] < b; ++next) {
      if (!(mark_angles[next] > a)) continue;  // on the split angle: the join of two sub-arcs already
      const double u = circle_arc_parameter(mark_angles[next] - a, b - a);
      if (u > 0 && u < 1 && (marks.empty() || FT(u) > marks.back())) marks.push_back(FT(u));
    }
    parts.push_back(exact_spline(circle_arc_cubic<K>(center, radius, a, b), marks));
  }
  return Basic_shape_2(std::move(parts), "arc");
}

} // namespace fair

#endif // FAIR_INTERNAL_BASIC_SHAPES_SHAPES_H
