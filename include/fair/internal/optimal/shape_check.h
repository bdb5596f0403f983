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
// Self-intersections: internal/common/polygon_crossings.h (exact orientation signs on the double
// coordinates, a sweep over the edges).

#ifndef FAIR_INTERNAL_OPTIMAL_SHAPE_CHECK_H
#define FAIR_INTERNAL_OPTIMAL_SHAPE_CHECK_H

#include <fair/internal/common/polygon_crossings.h>
#include <fair/internal/optimal/vec2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

/// The number of crossings of the polygon c (closed: with the closing edge), certified
/// (`common::polygon_crossings`: pairs of edges that share a point, consecutive ones where they
/// fold back).
inline std::size_t count_self_intersections(const std::vector<Vec2>& c, bool closed) {
  return common::polygon_crossings(c, closed);
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
