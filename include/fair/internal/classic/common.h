// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Pieces shared by the classic interpolants (Cubic_interpolating_spline_2, Catmull_rom_2,
// Cubic_quasi_interpolant_2, Cubic_bspline_2, Four_point_subdivision_2): the knot intervals
// of a fair::Knot_spacing, the cubic Hermite -> Bezier conversion and the uniform cubic
// B-spline segment -> Bezier conversion.

#ifndef FAIR_INTERNAL_CLASSIC_COMMON_H
#define FAIR_INTERNAL_CLASSIC_COMMON_H

#include <fair/Bezier_2.h>
#include <fair/Errors.h>
#include <fair/Knot_spacing.h>
#include <fair/internal/common/combination.h>
#include <fair/internal/common/input_checks.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace classic {

/// The knot intervals h_i between consecutive points (n - 1 of them, or n for a closed curve
/// where h_{n-1} runs from p_{n-1} back to p_0). Throws Invalid_input_error when a non-uniform
/// interval is zero or not finite in double (coincident points, or a distance that under- or
/// overflows double even with std::hypot).
template <class K>
std::vector<typename K::FT> classic_knot_intervals(const std::vector<typename K::Point_2>& p,
                                                   bool closed, Knot_spacing spacing,
                                                   const char* method) {
  typedef typename K::FT FT;
  const std::size_t n = p.size();
  const std::size_t m = closed ? n : n - 1;
  std::vector<FT> h;
  h.reserve(m);
  double total = 0;  // the last knot: finite intervals can still sum beyond double
  for (std::size_t i = 0; i < m; ++i) {
    if (spacing == Knot_spacing::UNIFORM) {
      h.push_back(FT(1));
      continue;
    }
    const std::size_t j = (i + 1) % n;
    // Differences in FT first (exact in an exact kernel), then to double.
    const double dx = CGAL::to_double(p[j].x() - p[i].x());
    const double dy = CGAL::to_double(p[j].y() - p[i].y());
    const double d = std::hypot(dx, dy);
    const double hi = (spacing == Knot_spacing::CHORDAL) ? d : std::sqrt(d);
    if (!(hi > 0) || !std::isfinite(hi))
      throw Invalid_input_error(message(method, ": ", to_string(spacing), " knot interval between points ", i,
                                        " and ", j, " is ", hi, " (distance ", d,
                                        " in double); points must be distinct and their distance "
                                        "representable"));
    total += hi;
    if (!std::isfinite(total))
      throw Invalid_input_error(message(method, ": the ", to_string(spacing), " knots overflow double at point ", j,
                                        " (the intervals sum beyond ", std::numeric_limits<double>::max(),
                                        "); the input coordinates are too large for this number type"));
    h.push_back(FT(hi));
  }
  return h;
}

/// The cumulative knots u_0 = 0, u_{i+1} = u_i + h_i.
template <class FT>
std::vector<FT> classic_cumulative_knots(const std::vector<FT>& h) {
  std::vector<FT> u(1, FT(0));
  u.reserve(h.size() + 1);
  for (const FT& hi : h) {
    u.push_back(u.back() + hi);
    // In a floating FT a tiny interval after huge ones is lost in the sum (centripetal knots of
    // far-apart points and one close pair: issue 29 #20): said here, at the point, instead of
    // "breakpoints not increasing" from the spline.
    if (!(u.back() > u[u.size() - 2]))
      throw Invalid_input_error(message("knot spacing: the knot of point ", u.size() - 1, " does not exceed the one of point ",
                                        u.size() - 2, " in this number type (interval ", CGAL::to_double(hi),
                                        " after a knot sum of ", CGAL::to_double(u[u.size() - 2]),
                                        "): the points are too unevenly spaced; use uniform knots or rescale"));
  }
  return u;
}

/// The cubic Bezier piece of the Hermite interpolant on [u_i, u_i + h]:
/// c(u_i) = p, c'(u_i) = m0, c(u_i + h) = q, c'(u_i + h) = m1 (derivatives d/du).
/// In the local parameter t = (u - u_i)/h the end derivatives are h m0 and h m1, so
/// P1 = p + h m0 / 3 and P2 = q - h m1 / 3.
template <class K>
Bezier_2<K> classic_hermite_piece(const typename K::Point_2& p, const typename K::FT& mx0,
                                  const typename K::FT& my0, const typename K::Point_2& q,
                                  const typename K::FT& mx1, const typename K::FT& my1,
                                  const typename K::FT& h) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  const FT s = h / FT(3);
  return Bezier_2<K>(p, Point_2(p.x() + s * mx0, p.y() + s * my0),
                     Point_2(q.x() - s * mx1, q.y() - s * my1), q);
}

/// The Bezier form of the uniform cubic B-spline segment with control points d0..d3:
/// B0 = (d0 + 4 d1 + d2)/6, B1 = (2 d1 + d2)/3, B2 = (d1 + 2 d2)/3, B3 = (d1 + 4 d2 + d3)/6.
template <class K>
Bezier_2<K> classic_bspline_segment(const typename K::Point_2& d0, const typename K::Point_2& d1,
                                    const typename K::Point_2& d2, const typename K::Point_2& d3) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  const FT six(6), three(3), four(4), two(2);
  return Bezier_2<K>(
      Point_2((d0.x() + four * d1.x() + d2.x()) / six, (d0.y() + four * d1.y() + d2.y()) / six),
      Point_2((two * d1.x() + d2.x()) / three, (two * d1.y() + d2.y()) / three),
      Point_2((d1.x() + two * d2.x()) / three, (d1.y() + two * d2.y()) / three),
      Point_2((d1.x() + four * d2.x() + d3.x()) / six, (d1.y() + four * d2.y() + d3.y()) / six));
}

/// The point on the cubic through P0..P3 (at parameters 0,1,2,3) at parameter -1:
/// 4 P0 - 6 P1 + 4 P2 - P3 (the fourth difference of a cubic vanishes). Used as phantom data
/// so that cubic reproduction holds up to the ends of open curves.
template <class K>
typename K::Point_2 classic_cubic_extrapolation(const typename K::Point_2& p0, const typename K::Point_2& p1,
                                                const typename K::Point_2& p2, const typename K::Point_2& p3) {
  typedef typename K::FT FT;
  return common::combine<K>(FT(4), p0, FT(-6), p1, FT(4), p2, FT(-1), p3);
}

/// Throws Invalid_input_error if a constructed control point is not finite in double (finite
/// data whose differences or combinations overflow double, e.g. coordinates near 1e308), so that
/// no method hands out infinite or NaN pieces.
template <class Point_range>
void classic_check_finite_output(const Point_range& points, const char* method) {
  std::size_t i = 0;
  for (const auto& q : points) {
    const double x = CGAL::to_double(q.x()), y = CGAL::to_double(q.y());
    if (!std::isfinite(x) || !std::isfinite(y))
      throw Invalid_input_error(message(method, ": constructed point ", i, " = (", x, ", ", y,
                                        ") is not finite; the input coordinates are too large for "
                                        "this number type"));
    ++i;
  }
}

/// classic_check_finite_output over the control points of every piece, and the same for the
/// control points of its first and second hodographs, d (c_{k+1} - c_k) and
/// d (d - 1) (c_{k+2} - 2 c_{k+1} + c_k) for degree d: finite control points whose differences
/// overflow (coordinates of both signs near 1e308) would give an infinite or NaN derivative.
/// With these finite, every point, first and second derivative (convex combinations) is finite.
template <class Piece>
void classic_check_finite_pieces(const std::vector<Piece>& pieces, const char* method) {
  typedef typename Piece::FT FT;
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    const auto c = pieces[j].control_points();
    classic_check_finite_output(c, method);
    const FT d(static_cast<int>(c.size()) - 1);
    for (std::size_t k = 0; k + 1 < c.size(); ++k) {
      const double dx = CGAL::to_double(d * (c[k + 1].x() - c[k].x())), dy = CGAL::to_double(d * (c[k + 1].y() - c[k].y()));
      double ex = 0, ey = 0;
      if (k + 2 < c.size()) {
        const FT dd = d * (d - FT(1));
        ex = CGAL::to_double(dd * (c[k + 2].x() - FT(2) * c[k + 1].x() + c[k].x()));
        ey = CGAL::to_double(dd * (c[k + 2].y() - FT(2) * c[k + 1].y() + c[k].y()));
      }
      if (!std::isfinite(dx) || !std::isfinite(dy) || !std::isfinite(ex) || !std::isfinite(ey))
        throw Invalid_input_error(message(method, ": piece ", j, ": the derivatives are not finite (first difference (",
                                          dx, ", ", dy, "), second difference (", ex, ", ", ey,
                                          ") of control point ", k, "); the input coordinates are too large for "
                                          "this number type"));
    }
  }
}

/// The Hermite interpolant through p_0..p_{n-1} with derivatives m_i = c'(u_i) (d/du) on the
/// knot intervals h: piece i (classic_hermite_piece) joins p_i to p_{(i+1) mod n}, so h has
/// n - 1 entries for an open curve and n for a closed one. Throws Invalid_input_error (see
/// classic_check_finite_output) when a control point is not finite.
template <class K>
std::vector<Bezier_2<K>> classic_hermite_pieces(const std::vector<typename K::Point_2>& p,
                                                const std::vector<typename K::Vector_2>& m,
                                                const std::vector<typename K::FT>& h, const char* method) {
  const std::size_t n = p.size();
  std::vector<Bezier_2<K>> pieces;
  pieces.reserve(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    const std::size_t j = (i + 1) % n;
    pieces.push_back(classic_hermite_piece<K>(p[i], m[i].x(), m[i].y(), p[j], m[j].x(), m[j].y(), h[i]));
  }
  classic_check_finite_pieces(pieces, method);
  return pieces;
}

} // namespace classic
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_CLASSIC_COMMON_H
