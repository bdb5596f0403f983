// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The sums behind the curvature-variation-minimising Cardinal spline of
// J. Li, "Curvature variation minimizing Cardinal spline curves" (equation numbers below refer
// to /work/shared/papers/li-curvature-variation-cardinal-splines.md).
//
// For the segment built on the four points (q0, q1, q2, q3) the paper defines (eq. 8)
//     d = -q0 - q1 + q2 + q3,   m = q1 - q2,
// and the third derivative of the segment is the constant r''' = 6 alpha d + 12 m, so that
//     E_i = int_0^1 |r_i'''|^2 dt = 36 alpha^2 |d|^2 + 144 alpha d.m + 144 |m|^2      (eq. 9).
// Everything here is a sum of products of coordinates: exact in an exact number type.

#ifndef FAIR_INTERNAL_CARDINAL_OPTIMUM_H
#define FAIR_INTERNAL_CARDINAL_OPTIMUM_H

#include <fair/Errors.h>

#include <CGAL/number_utils.h>

#include <cstddef>
#include <vector>

namespace fair {
namespace internal {

/// The three sums of eq. 10: D = sum |d_i|^2, M = sum d_i.m_i, S = sum |m_i|^2.
template <class FT>
struct Cardinal_sums {
  FT D = FT(0), M = FT(0), S = FT(0);

  template <class Point_2>
  void add(const Point_2& q0, const Point_2& q1, const Point_2& q2, const Point_2& q3) {
    // Work on coordinates, not on kernel constructions: with EPECK this keeps one lazy DAG per
    // sum instead of one per intermediate vector, and with double it is a handful of flops.
    const FT dx = q2.x() + q3.x() - q0.x() - q1.x(), dy = q2.y() + q3.y() - q0.y() - q1.y();
    const FT mx = q1.x() - q2.x(), my = q1.y() - q2.y();
    D += dx * dx + dy * dy;
    M += dx * mx + dy * my;
    S += mx * mx + my * my;
  }

  /// The energy of eq. 10 for the parameter alpha.
  FT energy(const FT& alpha) const { return FT(36) * alpha * alpha * D + FT(144) * alpha * M + FT(144) * S; }
};

/// The sums over the interior segments i = 0..n-3 of an open curve (the ones that do not touch an
/// auxiliary point; eq. 15 / eq. 18), or over all N segments of a closed curve (indices mod N).
template <class FT, class Point_2>
Cardinal_sums<FT> cardinal_interior_sums(const std::vector<Point_2>& p, bool closed) {
  Cardinal_sums<FT> s;
  const std::size_t N = p.size();
  if (closed) {
    for (std::size_t i = 0; i < N; ++i) s.add(p[(i + N - 1) % N], p[i], p[(i + 1) % N], p[(i + 2) % N]);
  } else {
    for (std::size_t i = 0; i + 3 < N; ++i) s.add(p[i], p[i + 1], p[i + 2], p[i + 3]);
  }
  return s;
}

} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_CARDINAL_OPTIMUM_H
