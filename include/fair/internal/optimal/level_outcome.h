// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The outcome of a level of the optimal-curve solver (Optimal_curve_status CONVERGED, DIVERGING,
// CAPPED): the tests that end a level on its iteration cap (a runaway extent is DIVERGING) or on
// the geometry of an accepted step (an extent beyond the divergence cap, a collapsing edge).

#ifndef FAIR_INTERNAL_OPTIMAL_LEVEL_OUTCOME_H
#define FAIR_INTERNAL_OPTIMAL_LEVEL_OUTCOME_H

#include <fair/Optimal_curve_report.h>
#include <fair/internal/optimal/constraints.h>
#include <fair/internal/optimal/vec2.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

typedef fair::Optimal_curve_status Status;

/// A polygon whose bounding-box extent exceeds this multiple of the input's is diverging.
constexpr double divergence_extent_factor = 1e3;
/// An edge (with a free end) shorter than this fraction of the extent is degenerate: the level stops CAPPED.
constexpr double degenerate_edge_fraction = 1e-12;
/// A level ending on its iteration cap with its extent grown by this factor since its start, and
/// by still_growing since half its iterations, is DIVERGING (else CAPPED).
constexpr double runaway_growth = 4;
constexpr double still_growing = 1.5;

struct Level_outcome {
  std::size_t iterations = 0;
  double energy = 0, gradient_norm = 0;
  Status status = Status::CAPPED;
};

inline double polygon_extent(const std::vector<Vec2>& c) {
  double x0 = c[0][0], x1 = x0, y0 = c[0][1], y1 = y0;
  for (const Vec2& p : c) {
    x0 = std::min(x0, p[0]); x1 = std::max(x1, p[0]);
    y0 = std::min(y0, p[1]); y1 = std::max(y1, p[1]);
  }
  return std::max(x1 - x0, y1 - y0);
}

/// The shortest edge with at least one free end (edges between two fixed vertices do not move).
inline double free_min_edge(const std::vector<Vec2>& c, bool closed, const Vertex_roles& roles) {
  const std::size_t n = c.size(), e = closed ? n : n - 1;
  double m = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < e; ++j)
    if (roles.role[j] == Vertex_role::FREE || roles.role[(j + 1) % n] == Vertex_role::FREE)
      m = std::min(m, vec::norm(vec::sub(c[(j + 1) % n], c[j])));
  return m;
}

/// The status of a level that ends on its iteration cap at c: one that ends with its extent grown
/// many times since its start (runaway_growth), and still growing over the second half of its
/// iterations (still_growing), is running away (DIVERGING); one that grew and then settled (a
/// nearly collinear start bulging out to its minimiser) is only CAPPED.
inline Status capped_status(const std::vector<Vec2>& c, double start_extent, double half_way_extent) {
  const double extent = polygon_extent(c);
  const bool runaway = extent > runaway_growth * start_extent && extent > still_growing * half_way_extent;
  return runaway ? Status::DIVERGING : Status::CAPPED;
}

/// Whether the accepted step to `trial` ends the level, and how (`status`). DIVERGING only when the
/// curve runs away (its extent beyond max_extent: no finite minimiser); an edge with a free end that
/// degenerates is a solver failure on a problem that may well have a minimiser (with beta > 0 the
/// length is bounded by F/beta): CAPPED.
inline bool geometry_stop(const std::vector<Vec2>& trial, bool closed, const Vertex_roles& roles, double max_extent,
                          Status& status) {
  const double extent = polygon_extent(trial);
  const bool runaway = extent > max_extent,
             collapsed = free_min_edge(trial, closed, roles) < degenerate_edge_fraction * extent;
  if (!(runaway || collapsed)) return false;
  status = runaway ? Status::DIVERGING : Status::CAPPED;
  return true;
}

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_LEVEL_OUTCOME_H
