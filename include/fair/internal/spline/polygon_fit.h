// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The internals of fair::fit_cubic_spline (include/fair/Polygon_spline_fit.h): the polygon in
// double, the periodic C2 cubic interpolant solved directly for its B-spline control points, and
// the Cubic_spline_2 built from control points computed on the scaled polygon (all the fits).
//
// Periodic interpolation on the breakpoints t_0 < ... < t_n (chord length, t_n closing the
// polygon): the spline's value at t_i is the first Bezier point of piece i,
//   b_0^i = (h_i b_2^{i-1} + h_{i-1} b_1^i) / (h_{i-1} + h_i)                  (bspline_form.h, eq. 2)
// with b_2^{i-1} = (h_i c_{i-1} + (h_{i-2} + h_{i-1}) c_i) / S_{i-1} and
// b_1^i = ((h_i + h_{i+1}) c_i + h_{i-1} c_{i+1}) / S_i, S_j = h_{j-1} + h_j + h_{j+1}. So
// b_0^i = p_i is the cyclic tridiagonal row
//   alpha_i c_{i-1} + beta_i c_i + gamma_i c_{i+1} = p_i,
//   alpha_i = h_i^2 / ((h_{i-1} + h_i) S_{i-1}),   gamma_i = h_{i-1}^2 / ((h_{i-1} + h_i) S_i),
//   beta_i = (h_i (h_{i-2} + h_{i-1}) / S_{i-1} + h_{i-1} (h_i + h_{i+1}) / S_i) / (h_{i-1} + h_i),
// the B-spline collocation matrix at the knots (alpha + beta + gamma = 1, all positive).
// beta_i - alpha_i - gamma_i = (h_i (h_{i-2} + h_{i-1} - h_i) / S_{i-1} + h_{i-1} (h_i + h_{i+1} -
// h_{i-1}) / S_i) / (h_{i-1} + h_i) is positive unless one interval is longer than its two
// neighbours on one side together; then (rare for a polygon of an optimal curve) the caller uses
// the Hermite form, which is always diagonally dominant. Otherwise elimination without pivoting
// is backward stable (Higham, Thm. 9.9), so linear_algebra::solve_cyclic_tridiagonal. The curve is the
// periodic C2 interpolant of Cubic_interpolating_spline_2 (the same unique spline), without its
// Hermite pieces, the eq.-3 conversion back to control points and the C2 check of that
// conversion: the issue-23 profile put 60 % of fit_cubic_spline's time in those and the distance.

#ifndef FAIR_INTERNAL_SPLINE_POLYGON_FIT_H
#define FAIR_INTERNAL_SPLINE_POLYGON_FIT_H

#include <fair/Cubic_spline_2.h>
#include <fair/internal/common/input_checks.h>
#include <fair/internal/linear_algebra/tridiagonal.h>
#include <fair/internal/optimal/vec2.h>
#include <fair/internal/spline/bspline_form.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace spline {

typedef optimal::Vec2 Vec2;

/// The polygon in double after the common input checks (too few vertices, non-finite or
/// coincident consecutive vertices: Invalid_input_error).
template <class K>
std::vector<Vec2> polygon_to_double(const std::vector<typename K::Point_2>& polygon, bool closed, const char* fn) {
  common::check_interpolation_input(polygon, closed ? 3 : 2, closed, fn);
  std::vector<Vec2> p;
  p.reserve(polygon.size());
  for (const typename K::Point_2& q : polygon) p.push_back(Vec2{{CGAL::to_double(q.x()), CGAL::to_double(q.y())}});
  return p;
}

template <class K>
typename K::Point_2 to_point(const Vec2& v) {
  return typename K::Point_2(typename K::FT(v[0]), typename K::FT(v[1]));
}

/// The control points c_0..c_{n-1} of the periodic C2 cubic through p_0..p_{n-1} at the
/// breakpoints t_0..t_n (n >= 3; the system of the header comment) in `out`; false (and `out`
/// untouched) when a row is not strictly diagonally dominant or the solution overflows.
inline bool periodic_interpolation_control(const std::vector<Vec2>& p, const std::vector<double>& t,
                                           std::vector<Vec2>& out) {
  const std::size_t n = p.size();
  std::vector<double> a(n), b(n), c(n), dx(n), dy(n);
  auto h = [&](std::size_t i, long k) { return knot_interval(t, true, static_cast<long>(i) + k); };
  for (std::size_t i = 0; i < n; ++i) {
    const double hm2 = h(i, -2), hm = h(i, -1), hi = h(i, 0), hp = h(i, 1);
    const double sl = hm2 + hm + hi, sr = hm + hi + hp, s = hm + hi;
    a[i] = hi / s * (hi / sl);
    c[i] = hm / s * (hm / sr);
    b[i] = hi / s * ((hm2 + hm) / sl) + hm / s * ((hi + hp) / sr);
    if (!(b[i] > a[i] + c[i])) return false;
    dx[i] = p[i][0];
    dy[i] = p[i][1];
  }
  const std::vector<double> x = linear_algebra::solve_cyclic_tridiagonal(a, b, c, dx);
  const std::vector<double> y = linear_algebra::solve_cyclic_tridiagonal(a, b, c, dy);
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) return false; // overflow: the Hermite form reports it
  out.resize(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = Vec2{{x[i], y[i]}};
  return true;
}

/// The Bezier points of the pieces of the spline with control points c (closed: m = c.size()
/// pieces; open: m + 3 control points), in double (eq. 2).
inline std::vector<std::array<Vec2, 4>> bezier_pieces(const std::vector<double>& t, const std::vector<Vec2>& c,
                                                      bool closed) {
  typedef Affine_point<double> P;
  const long m = static_cast<long>(t.size()) - 1;
  std::vector<std::array<Vec2, 4>> out(static_cast<std::size_t>(m));
  for (long i = 0; i < m; ++i) {
    double h[5];
    intervals_around(t, closed, i, h);
    P q[4];
    for (int k = 0; k < 4; ++k) {
      const Vec2& v = c[control_index(i - 1 + k, m, closed)];
      q[k] = P{v[0], v[1]};
    }
    const std::array<P, 4> b = bezier_points_of(q, h);
    for (int k = 0; k < 4; ++k) out[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = Vec2{{b[k].x, b[k].y}};
  }
  return out;
}


/// A power of two near the extent of p (the largest coordinate difference from p[0]), so that the
/// fits compute on p / scale, of extent ~1: chord lengths, their squares and the fifth powers of
/// the quintic's system neither overflow nor underflow (issue 29 #6, #7, #20: at 1e80 the
/// quintic's system was "not positive definite", at 1e-160 the cubic failed its own C2 check, at
/// 1e155 a control point became NaN). Division by a power of two is exact (no subnormal results:
/// the scale is at most the extent), so the breakpoints and control points are those of p times
/// 1/scale exactly, scaled back exactly. 1 when p has no extent or scaling would overflow.
inline double fit_scale(const std::vector<optimal::Vec2>& p) {
  double e = 0, a = 0;
  for (const optimal::Vec2& q : p)
    for (int k = 0; k < 2; ++k) {
      e = std::max(e, std::abs(q[k] - p[0][k]));
      a = std::max(a, std::abs(q[k]));
    }
  if (!(e > 0) || !std::isfinite(e)) return 1;
  // At least the smallest normal double, so that 1 / scale is finite (review R20: data of a
  // subnormal extent, e < 2^-1022, gave 1 / scale = inf and NaN points); such data then fit at an
  // extent of e * 2^1022 < 1, still exactly scaled.
  const double scale = std::max(std::ldexp(1.0, std::ilogb(e)), std::numeric_limits<double>::min());
  return a / scale < 1e300 ? scale : 1;
}
inline std::vector<optimal::Vec2> scaled(std::vector<optimal::Vec2> p, double factor) {
  for (optimal::Vec2& q : p) q = {{q[0] * factor, q[1] * factor}};
  return p;
}

/// The Cubic_spline_2 of the breakpoints t and control points `control` computed on the polygon
/// divided by `scale` (fit_scale), mapped back.
template <class K>
Cubic_spline_2<K> spline_from_control(const std::vector<double>& t, const std::vector<Vec2>& control, bool closed,
                                      double scale, const char* fn) {
  typedef typename K::FT FT;
  // The breakpoints are chord lengths (t * scale) unless the spline's own B-spline-to-Bezier
  // conversion (eq. 2 of Cubic_spline_2: control points times sums of knot intervals) would
  // overflow: then they stay chord lengths / scale, the same curve reparametrised by a power of
  // two (polygons beyond ~1e150, issue 29 #20).
  double control_bound = 0;
  for (const Vec2& v : control) control_bound = std::max({control_bound, std::abs(v[0]), std::abs(v[1])});
  const double knot_bound = std::max(std::abs(t.front()), std::abs(t.back()));
  const double knot_scale =
      16 * (knot_bound * scale) * (control_bound * scale) <= std::numeric_limits<double>::max() / 64 ? scale : 1;
  std::vector<FT> breakpoints;
  breakpoints.reserve(t.size());
  for (double x : t) breakpoints.push_back(FT(x * knot_scale));
  std::vector<typename K::Point_2> points;
  points.reserve(control.size());
  for (const Vec2& v : control) points.push_back(to_point<K>(Vec2{{v[0] * scale, v[1] * scale}}));
  Cubic_spline_2<K> spline(std::move(breakpoints), std::move(points), closed);
  spline.check_finite_pieces(fn);
  return spline;
}

} // namespace spline
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_SPLINE_POLYGON_FIT_H
