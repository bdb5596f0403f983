// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The discrete Hausdorff distance of hausdorff_distance() (Fairness_metrics.h): a curve sampled
// into a polyline to a chord tolerance, and the exact point-to-polyline distance through a uniform
// grid of the polyline's segments.

#ifndef FAIR_INTERNAL_METRICS_HAUSDORFF_H
#define FAIR_INTERNAL_METRICS_HAUSDORFF_H

#include <fair/internal/metrics/pieces.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace metrics {

/// Depth cap of the bisection of a parameter interval: 2^-40 of a quarter piece is far below any
/// tolerance a caller can ask for, and it bounds the work on a piece singular at a point.
constexpr int max_polyline_depth = 40;
/// Largest midpoint sagitta of a polyline segment, as a fraction of the chord tolerance: keeps the
/// polyline within about tolerance/4 of the curve, so that the distance is within `tolerance`.
constexpr double polyline_sagitta_fraction = 0.25;
/// Every piece is first split into this many parameter intervals, so that a closed loop piece (or a
/// piece whose midpoint lies on its chord) is not mistaken for a short chord.
constexpr int polyline_initial_splits = 4;

// Sampling of a piece into a polyline with chord <= h (recursive bisection, depth-capped).
template <class Piece>
void sample_polyline_piece(const Piece_jet<Piece>& jet, double t0, double t1, double x0, double y0, double x1, double y1,
                           double h, int depth, std::vector<std::pair<double, double>>& out) {
  const double tm = 0.5 * (t0 + t1);
  const Jet m = jet(tm);
  const double chord = std::hypot(x1 - x0, y1 - y0);
  const double sag = std::hypot(m.x - 0.5 * (x0 + x1), m.y - 0.5 * (y0 + y1));
  if (depth >= max_polyline_depth || (chord <= h && sag <= polyline_sagitta_fraction * h)) {
    out.emplace_back(x1, y1);
    return;
  }
  sample_polyline_piece(jet, t0, tm, x0, y0, m.x, m.y, h, depth + 1, out);
  sample_polyline_piece(jet, tm, t1, m.x, m.y, x1, y1, h, depth + 1, out);
}

template <class Piece>
std::vector<std::pair<double, double>> sample_polyline(const std::vector<Piece>& curve, double h) {
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i < curve.size(); ++i) {
    Piece_jet<Piece> jet(curve[i]);
    const Jet a = jet(0.0), b = jet(1.0);
    if (i == 0) out.emplace_back(a.x, a.y);
    else if (out.back().first != a.x || out.back().second != a.y) out.emplace_back(a.x, a.y);
    double tx = 0, px = a.x, py = a.y;
    for (int q = 1; q <= polyline_initial_splits; ++q) {
      const double tq = double(q) / polyline_initial_splits;
      const Jet e = q == polyline_initial_splits ? b : jet(tq);
      sample_polyline_piece(jet, tx, tq, px, py, e.x, e.y, h, 0, out);
      tx = tq; px = e.x; py = e.y;
    }
  }
  return out;
}

inline double point_segment_distance(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
  double u = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0.0;
  u = std::min(1.0, std::max(0.0, u));
  return std::hypot(px - (ax + u * dx), py - (ay + u * dy));
}

/// max over the points of `a` of the distance to the polyline `b`, with a uniform grid.
inline double directed_polyline_distance(const std::vector<std::pair<double, double>>& a,
                                         const std::vector<std::pair<double, double>>& b) {
  if (b.size() == 1) {
    double best = 0;
    for (const auto& p : a) best = std::max(best, std::hypot(p.first - b[0].first, p.second - b[0].second));
    return best;
  }
  double xmin = b[0].first, xmax = xmin, ymin = b[0].second, ymax = ymin;
  for (const auto& p : b) {
    xmin = std::min(xmin, p.first); xmax = std::max(xmax, p.first);
    ymin = std::min(ymin, p.second); ymax = std::max(ymax, p.second);
  }
  const std::size_t segs = b.size() - 1;
  const double extent = std::max(xmax - xmin, ymax - ymin);
  const double side = std::max(1.0, std::ceil(std::sqrt(double(segs))));
  const double cell = extent > 0 ? extent / side : 1.0;
  const long nx = std::max(1L, long(std::floor((xmax - xmin) / cell)) + 1), ny = std::max(1L, long(std::floor((ymax - ymin) / cell)) + 1);
  std::vector<std::vector<std::size_t>> grid(std::size_t(nx * ny));
  auto cx = [&](double x) { return std::min(nx - 1, std::max(0L, long(std::floor((x - xmin) / cell)))); };
  auto cy = [&](double y) { return std::min(ny - 1, std::max(0L, long(std::floor((y - ymin) / cell)))); };
  for (std::size_t s = 0; s < segs; ++s) {
    const long i0 = cx(std::min(b[s].first, b[s + 1].first)), i1 = cx(std::max(b[s].first, b[s + 1].first));
    const long j0 = cy(std::min(b[s].second, b[s + 1].second)), j1 = cy(std::max(b[s].second, b[s + 1].second));
    for (long i = i0; i <= i1; ++i)
      for (long j = j0; j <= j1; ++j) grid[std::size_t(j * nx + i)].push_back(s);
  }
  // The nonempty cells; for each query they are visited in increasing order of their distance to
  // the query point, stopping as soon as that lower bound exceeds the best distance found: exact
  // (the true minimum over all segments) and O(C log C) per query for C nonempty cells.
  std::vector<long> cells;
  for (long c = 0; c < nx * ny; ++c)
    if (!grid[std::size_t(c)].empty()) cells.push_back(c);
  std::vector<std::pair<double, long>> order(cells.size());
  double result = 0;
  for (const auto& p : a) {
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const long i = cells[k] % nx, j = cells[k] / nx;
      const double x0 = xmin + double(i) * cell, y0 = ymin + double(j) * cell;
      const double dx = std::max({0.0, x0 - p.first, p.first - (x0 + cell)});
      const double dy = std::max({0.0, y0 - p.second, p.second - (y0 + cell)});
      order[k] = std::make_pair(std::hypot(dx, dy), cells[k]);
    }
    std::sort(order.begin(), order.end());
    double best = std::numeric_limits<double>::infinity();
    for (const auto& o : order) {
      // Segments are registered in every cell their bounding box meets (the last cells are clamped
      // to include the box edges), so the cell's lower bound holds for the segment parts inside it.
      if (o.first > best) break;
      for (std::size_t s : grid[std::size_t(o.second)])
        best = std::min(best, point_segment_distance(p.first, p.second, b[s].first, b[s].second, b[s + 1].first,
                                                     b[s + 1].second));
    }
    result = std::max(result, best);
  }
  return result;
}


} // namespace metrics
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_METRICS_HAUSDORFF_H
