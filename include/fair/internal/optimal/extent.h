// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The data's centroid and the extent that the resolution rho refers to (doc/optimal_curves.md,
// "Hierarchy" and "Errors"): accurate for points far from the origin against their spread, and
// without overflow near the top of the double range.

#ifndef FAIR_INTERNAL_OPTIMAL_EXTENT_H
#define FAIR_INTERNAL_OPTIMAL_EXTENT_H

#include <fair/internal/optimal/vec2.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

/// The centroid of c given its plain mean `mean` (as a caller computed it), refined where the mean's
/// rounding errors, n ulps of the largest coordinate, may reach the data's spread: for points far
/// from the origin against their extent (fuzz, session 20: 13 points at x = 2.6e45 whose y spans
/// 300; the mean's x was off by 1e29 and that error became the extent, so the hierarchy never
/// subdivided and the spline's tolerance was 1e27). There it is c[0] plus the mean of the
/// differences to c[0], which are exact when within a factor 2 of c[0] (Sterbenz) and otherwise
/// rounded relative to their own size. Where the spread is at least 2^-26 of the magnitude the
/// plain mean is returned unchanged (its error is then below n 2^-26 ulps of the spread), so
/// ordinary data give bit-identical results.
inline Vec2 refined_centroid(const std::vector<Vec2>& c, const Vec2& mean) {
  double magnitude = 0, spread = 0;
  for (const Vec2& p : c) {
    magnitude = std::max(magnitude, std::max(std::abs(p[0]), std::abs(p[1])));
    spread = std::max(spread, std::max(std::abs(p[0] - mean[0]), std::abs(p[1] - mean[1])));
  }
  if (!(spread < 0x1p-26 * magnitude)) return mean;  // also: an infinite magnitude (a NaN mean stays NaN below)
  const double n = static_cast<double>(c.size());
  double x = 0, y = 0;
  for (const Vec2& p : c) {
    x += (p[0] - c[0][0]) / n;
    y += (p[1] - c[0][1]) / n;
  }
  return {{c[0][0] + x, c[0][1] + y}};
}

/// The extent that rho refers to: twice the largest distance of a vertex from the vertices'
/// centroid. The paper's bounding-box extent depends on the orientation (a rotated input would
/// be subdivided differently, and rigid motions would not commute with the solve); this one is
/// invariant and between the bounding box's larger side and 2 sqrt(2) times it.
inline double rotation_invariant_extent(const std::vector<Vec2>& c) {
  const double n = static_cast<double>(c.size());
  double x = 0, y = 0;
  for (const Vec2& p : c) { x += p[0]; y += p[1]; }
  x /= n;
  y /= n;
  if (!std::isfinite(x) || !std::isfinite(y)) {  // the sum overflowed (review R20): the sum of p / n
    x = y = 0;
    for (const Vec2& p : c) { x += p[0] / n; y += p[1] / n; }
  }
  const Vec2 g = refined_centroid(c, {{x, y}});
  double r = 0;
  for (const Vec2& p : c) r = std::max(r, std::hypot(p[0] - g[0], p[1] - g[1]));
  return 2 * r;
}

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_EXTENT_H
