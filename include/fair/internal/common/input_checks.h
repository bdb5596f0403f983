// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Validation of user point data shared by every method. Each check throws
// fair::Invalid_input_error with a message that names the method, the offending index
// and the offending values.

#ifndef FAIR_INTERNAL_COMMON_INPUT_CHECKS_H
#define FAIR_INTERNAL_COMMON_INPUT_CHECKS_H

#include <fair/Errors.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace common {

/// Throws unless every coordinate converts to a finite double.
template <class Point_2>
void check_finite_points(const std::vector<Point_2>& points, const char* method) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double x = CGAL::to_double(points[i].x()), y = CGAL::to_double(points[i].y());
    if (!std::isfinite(x) || !std::isfinite(y))
      throw Invalid_input_error(message(method, ": point ", i, " = (", x, ", ", y,
                                        ") has a non-finite coordinate"));
  }
}

/// Throws unless there are at least `minimum` points.
template <class Point_2>
void check_point_count(const std::vector<Point_2>& points, std::size_t minimum, const char* method) {
  if (points.size() < minimum)
    throw Invalid_input_error(message(method, ": needs at least ", minimum, " points, got ",
                                      points.size()));
}

/// Throws if two consecutive points coincide (and, for a closed curve, the last and first).
template <class Point_2>
void check_distinct_consecutive(const std::vector<Point_2>& points, bool closed, const char* method) {
  const std::size_t n = points.size();
  const std::size_t pairs = closed ? n : (n == 0 ? 0 : n - 1);
  for (std::size_t i = 0; i < pairs; ++i) {
    const std::size_t j = (i + 1) % n;
    if (points[i] == points[j])
      throw Invalid_input_error(message(method, ": consecutive points ", i, " and ", j,
                                        " coincide at (", CGAL::to_double(points[i].x()), ", ",
                                        CGAL::to_double(points[i].y()), ")"));
  }
}

/// The checks every interpolating method needs: count, finiteness, distinct neighbours.
template <class Point_2>
void check_interpolation_input(const std::vector<Point_2>& points, std::size_t minimum, bool closed,
                               const char* method) {
  check_point_count(points, minimum, method);
  check_finite_points(points, method);
  check_distinct_consecutive(points, closed, method);
}

} // namespace common
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_COMMON_INPUT_CHECKS_H
