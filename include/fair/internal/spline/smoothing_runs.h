// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The runs of the smoothing fits (fair::fit_smoothing_spline_runs, fair::fit_smoothing_quintic_runs:
// one C2 / C4 run between consecutive corners, G0 at them) and the spline-resolution test of the
// optimal curve's hierarchy (issue 25 §3; doc/optimal_curves.md, "The smoothing spline", "Distance
// within the resolution").
//
// Why the hierarchy asks the spline: the smoothing fit approaches the free vertices within a
// tolerance (optimal_spline_distance_fraction of the resolution extent/rho) and meets the input
// points exactly; its distance to the polygon can be no smaller than that of the interpolant of
// every vertex where that interpolant is the only admissible fit (sigma = 0). The sagitta test of
// subdivide (eps(l, phi) = (l/2) tan(|phi|/4) <= eps_max) bounds the distance of the circle arc
// tangent to one vertex bisector from the chord; the C2 cubic through the polygon bulges more where
// the curvature grows along the edge (up to 1.21 eps_max measured on the 117 Quick, Draw! strokes).
// So on the final level, the edges whose piece of the C2 interpolant lies farther from the edge
// than the fit's tolerance are split as well (new vertices by the four-point rule, then the level
// is solved again): afterwards sigma = 0 is admissible on every run and the delivered spline is
// within the tolerance by construction.

#ifndef FAIR_INTERNAL_SPLINE_SMOOTHING_RUNS_H
#define FAIR_INTERNAL_SPLINE_SMOOTHING_RUNS_H

#include <fair/internal/optimal/spline_fit.h>
#include <fair/internal/optimal/vec2.h>
#include <fair/internal/spline/smoothing_fit.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {

/// The distance from Optimal_curve_2::spline() (and its quintic, fit_smoothing_quintic_runs) to the
/// optimal polygon that the smoothing fit allows, as a fraction of the polygon's resolution
/// (rotation-invariant extent / rho): doc/optimal_curves.md, "The smoothing spline".
constexpr double optimal_spline_distance_fraction = 0.9;

namespace internal {
namespace spline {

/// Where the runs of a polygon of n vertices start and end: run r covers the vertices ends[r] ..
/// ends[r + 1] (indices mod n; the last run of a closed polygon with corners wraps around);
/// `periodic`: one closed run without corners (ends = {0, n - 1}, the closing edge included).
struct Run_layout {
  std::vector<std::size_t> ends;
  bool periodic = false;
};

/// The corners as the fits use them: sorted, unique, without the two ends of an open polygon.
inline std::vector<std::size_t> normalised_corners(std::vector<std::size_t> corners, std::size_t n, bool closed) {
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  if (!closed)
    corners.erase(std::remove_if(corners.begin(), corners.end(), [n](std::size_t c) { return c == 0 || c + 1 == n; }),
                  corners.end());
  return corners;
}

/// The runs between the (normalised) corners.
inline Run_layout run_layout(std::size_t n, bool closed, const std::vector<std::size_t>& corners) {
  Run_layout out;
  out.periodic = closed && corners.empty();
  if (out.periodic) {
    out.ends = {0, n - 1};
    return out;
  }
  if (!closed) out.ends.push_back(0);
  out.ends.insert(out.ends.end(), corners.begin(), corners.end());
  if (closed) out.ends.push_back(corners.front() + n);  // wraps around
  else out.ends.push_back(n - 1);
  return out;
}

/// The edges (edge j from c[j] to c[j + 1 mod n]) on which the C2 interpolant of every vertex,
/// run by run between the corners (natural ends, periodic without corners: the sigma = 0 fit of
/// fit_smoothing_spline_runs), lies farther than `tolerance` from the edge: 1 there, else 0.
/// Every edge is tested with the Bezier-hull bound first (most are skipped). O(n).
inline std::vector<unsigned char> interpolant_beyond_edges(const std::vector<optimal::Vec2>& c, bool closed,
                                                           const std::vector<std::size_t>& corners, double tolerance) {
  const std::size_t n = c.size(), edges = closed ? n : n - 1;
  std::vector<unsigned char> out(edges, 0);
  if (n < 3) return out;  // the segment
  const Run_layout layout = run_layout(n, closed, normalised_corners(corners, n, closed));
  for (std::size_t r = 0; r + 1 < layout.ends.size(); ++r) {
    std::vector<optimal::Vec2> v;
    for (std::size_t i = layout.ends[r]; i <= layout.ends[r + 1]; ++i) v.push_back(c[i % n]);
    std::vector<double> t(1, 0.0);
    const std::size_t run_edges = layout.periodic ? v.size() : v.size() - 1;
    for (std::size_t i = 0; i < run_edges; ++i) {
      const double h = optimal::vec::norm(optimal::vec::sub(v[(i + 1) % v.size()], v[i]));
      if (!(h > 0) || !std::isfinite(h)) return std::vector<unsigned char>(edges, 0);  // the fit reports it
      t.push_back(t.back() + h);
    }
    Reinsch_spline s;
    if (!smoothing_spline_solve(v, t, layout.periodic, std::vector<double>(v.size(), 0.0), s)) continue;
    const std::vector<std::array<optimal::Vec2, 4>> pieces = reinsch_bezier_pieces(s, t);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const optimal::Vec2 &e0 = v[i], &e1 = v[(i + 1) % v.size()];
      double bound = 0;
      for (const optimal::Vec2& b : pieces[i]) bound = std::max(bound, optimal::distance_to_segment(b, e0, e1));
      if (bound > tolerance && piece_edge_distance(pieces[i], e0, e1) > tolerance) out[(layout.ends[r] + i) % n] = 1;
    }
  }
  return out;
}

} // namespace spline
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_SPLINE_SMOOTHING_RUNS_H
