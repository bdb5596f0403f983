// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// What a designer must know about an optimal curve besides its status (issue 25 §2): how far it
// swings out of its data (extent_ratio) and whether it crosses itself where the input polygon
// does not (self_intersections against input_self_intersections).
//
// extent_ratio = max_v |v - g| / max_i |p_i - g|, g the centroid of the input points p_i, v the
// vertices of the optimal polygon: 1 for a curve that stays within the circle around g through
// the farthest point, 4 for a balloon four times the data's size. Rotation- and scale-invariant
// (the solve commutes with similarities; a bounding-box ratio would depend on the orientation).
//
// Self-intersections: the pairs of non-adjacent edges of a polygon that share a point, decided
// exactly on the double coordinates (orientation signs from the exact determinant, after a
// floating-point filter of Shewchuk's orient2d: |l - r| > 3.33e-16 (|l| + |r|) decides the sign,
// l and r the two products, else CGAL::Gmpq), so the count is certified
// for the polygon the solver returns. Candidate pairs by a sweep over the edges sorted by their
// smallest x (an edge meets only those whose x-range overlaps its own): O(n log n + k) for k
// overlapping pairs.

#ifndef FAIR_INTERNAL_OPTIMAL_SHAPE_CHECK_H
#define FAIR_INTERNAL_OPTIMAL_SHAPE_CHECK_H

#include <fair/internal/optimal/vec2.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

/// The sign of (b - a) x (c - a), exact for double coordinates (file comment).
inline int exact_orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double l = (b[0] - a[0]) * (c[1] - a[1]), r = (b[1] - a[1]) * (c[0] - a[0]);
  const double det = l - r, bound = 3.3306690738754716e-16 * (std::abs(l) + std::abs(r));
  // Shewchuk's orient2d filter (its ccwerrboundA = (3 + 16 eps) eps, eps = 2^-53, covers the
  // rounding of the differences and of the products): beyond it the sign is that of det.
  if (std::isfinite(det) && std::isfinite(bound) && std::abs(det) > bound) return det > 0 ? 1 : -1;
  const CGAL::Gmpq ax(a[0]), ay(a[1]);
  const CGAL::Gmpq e = (CGAL::Gmpq(b[0]) - ax) * (CGAL::Gmpq(c[1]) - ay) - (CGAL::Gmpq(b[1]) - ay) * (CGAL::Gmpq(c[0]) - ax);
  return CGAL::sign(e);
}

/// Whether the segments [a, b] and [c, d] share a point (exact on doubles).
inline bool segments_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int o1 = exact_orientation(a, b, c), o2 = exact_orientation(a, b, d);
  const int o3 = exact_orientation(c, d, a), o4 = exact_orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  // Touching or collinear configurations: a point on the other segment (bounding-box test is
  // exact for collinear points).
  auto on = [](const Vec2& p, const Vec2& q, const Vec2& x) {
    return std::min(p[0], q[0]) <= x[0] && x[0] <= std::max(p[0], q[0]) && std::min(p[1], q[1]) <= x[1] &&
           x[1] <= std::max(p[1], q[1]);
  };
  return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) || (o4 == 0 && on(c, d, b));
}

/// The number of pairs of non-adjacent edges of the polygon c (closed: with the closing edge)
/// that share a point (file comment).
inline std::size_t count_self_intersections(const std::vector<Vec2>& c, bool closed) {
  const std::size_t n = c.size(), edges = closed ? n : (n == 0 ? 0 : n - 1);
  if (edges < 3 && !(closed && edges == 3)) return 0;
  std::vector<std::size_t> order(edges);
  for (std::size_t j = 0; j < edges; ++j) order[j] = j;
  auto lo = [&](std::size_t j) { return std::min(c[j][0], c[(j + 1) % n][0]); };
  auto hi = [&](std::size_t j) { return std::max(c[j][0], c[(j + 1) % n][0]); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lo(a) < lo(b); });
  std::size_t count = 0;
  for (std::size_t u = 0; u < edges; ++u) {
    const std::size_t i = order[u];
    const double xi = hi(i);
    const double ylo = std::min(c[i][1], c[(i + 1) % n][1]), yhi = std::max(c[i][1], c[(i + 1) % n][1]);
    for (std::size_t v = u + 1; v < edges && lo(order[v]) <= xi; ++v) {
      const std::size_t j = order[v];
      const std::size_t d = i > j ? i - j : j - i;
      if (d == 1 || (closed && d == edges - 1)) continue;  // adjacent edges share their vertex
      if (std::max(c[j][1], c[(j + 1) % n][1]) < ylo || std::min(c[j][1], c[(j + 1) % n][1]) > yhi) continue;
      if (segments_meet(c[i], c[(i + 1) % n], c[j], c[(j + 1) % n])) ++count;
    }
  }
  return count;
}

/// max_v |v - g| / max_i |p_i - g| (file comment); 1 when the points have no extent.
inline double extent_ratio(const std::vector<Vec2>& curve, const std::vector<Vec2>& points) {
  double gx = 0, gy = 0;
  for (const Vec2& p : points) { gx += p[0]; gy += p[1]; }
  gx /= static_cast<double>(points.size());
  gy /= static_cast<double>(points.size());
  double rp = 0, rc = 0;
  for (const Vec2& p : points) rp = std::max(rp, std::hypot(p[0] - gx, p[1] - gy));
  for (const Vec2& v : curve) rc = std::max(rc, std::hypot(v[0] - gx, v[1] - gy));
  return rp > 0 && std::isfinite(rc / rp) ? std::max(1.0, rc / rp) : 1.0;
}

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_SHAPE_CHECK_H
