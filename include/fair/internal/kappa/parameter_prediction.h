// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// A start for the t_i of fair::Kappa_curve_2's solver on densely sampled smooth data, from the
// density estimate of doc/kappa_existence.md, Sec. 7. A parabola's curvature at a distance u
// from its vertex is kappa (1 - (3/2) kappa^2 u^2) to first order, so |kappa| continuity at the
// join between the vertices at Q_j and Q_{j+1} (interval h_j) puts the join at
// (1/2 + delta_j) h_j from Q_j with
//
//   kappa_j - kappa_{j+1} = 3 kappa^3 h_j^2 delta_j,
//
// and piece i, from the join of interval i-1 to that of interval i, has its vertex Q_i at
//
//   t_i = (1/2 - delta_{i-1}) h_{i-1} / ((1/2 - delta_{i-1}) h_{i-1} + (1/2 + delta_i) h_i)
//       ~ h_{i-1} / (h_{i-1} + h_i) + kappa_s / (3 kappa^3 h)
//
// (w = 1; first order in kappa h and in the variation of delta): on a circle with uneven
// spacing the vertex lies between the midpoints of its intervals; with uniform spacing
// t_i - 1/2 = kappa_s / (3 kappa^3 h).
//
// The paper's start t_i = 1/2 ignores this. On uniform samples of an ellipse the interior
// root's t_i spread linearly with n (measured slopes match the formula to 1-5 %, the table
// of Sec. 7), so from a few hundred points on the passes from t = 1/2 end far from the root.
// kappa_i is estimated from the data as the Menger curvature of Q_{i-1}, Q_i, Q_{i+1}.
// Accuracy: first order in kappa h, and the discrete estimates are O(h)-accurate, so this is a
// start, not a solution. Degenerate cases: a coincident neighbour (an interval of length 0, a
// curvature that is not finite) gives t_i = 1/2 next to it, a straight stretch (kappa = 0 on
// both sides of a join) delta = 0; the result is clamped to
// [predicted_parameter_margin, 1 - predicted_parameter_margin].

#ifndef FAIR_INTERNAL_KAPPA_PARAMETER_PREDICTION_H
#define FAIR_INTERNAL_KAPPA_PARAMETER_PREDICTION_H

#include <fair/internal/kappa/system.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// Predicted t_i are kept this far from 0 and 1: on the bound eq. 7 of the piece degenerates
/// (the point is an end point), and eq. 18 would put the piece's end exactly on Q_i.
constexpr double predicted_parameter_margin = 0.02;
/// The estimate is first order in kappa h, i.e. in the turning angle between consecutive
/// chords; above this turning (radians, about 22 degrees) at some point the data are not a dense
/// sample and no prediction is made. (The ellipses where it helps turn by 0.02-0.22.)
constexpr double predicted_max_turning = 0.4;

/// The neighbours of block i's point: the points of blocks i-1, i+1, or an open curve's fixed
/// end points.
inline void neighbour_points(const Problem& pb, std::size_t i, double& px, double& py, double& nx, double& ny) {
  const std::size_t n = pb.n;
  if (pb.has_start(i)) { const std::size_t j = i == 0 ? n - 1 : i - 1; px = pb.qx[j]; py = pb.qy[j]; }
  else { px = pb.sx; py = pb.sy; }
  if (pb.has_end(i)) { const std::size_t j = i + 1 == n ? 0 : i + 1; nx = pb.qx[j]; ny = pb.qy[j]; }
  else { nx = pb.ex; ny = pb.ey; }
}

/// The t_i of the density estimate (file comment), one per block. Returns max |t_i - 1/2|
/// after clamping; 0, with every t_i = 1/2, for fewer than 3 blocks (kappa_s needs both
/// neighbours' curvatures) or when the chords turn by more than predicted_max_turning at some
/// point.
inline double predicted_parameters(const Problem& pb, std::vector<double>& t) {
  const std::size_t n = pb.n;
  t.assign(n, 0.5);
  if (n < 3) return 0;
  // |kappa| (Menger) at each block's point and the interval to the next point.
  std::vector<double> kappa(n), after(n), before(n);
  for (std::size_t i = 0; i < n; ++i) {
    double px, py, nx, ny;
    neighbour_points(pb, i, px, py, nx, ny);
    const double x = pb.qx[i], y = pb.qy[i];
    const double a = std::hypot(x - px, y - py), b = std::hypot(nx - x, ny - y), c = std::hypot(nx - px, ny - py);
    const double cross = (x - px) * (ny - py) - (y - py) * (nx - px);
    const double turning = std::atan2(std::abs(cross), (x - px) * (nx - x) + (y - py) * (ny - y));
    if (!(turning <= predicted_max_turning)) return 0;
    kappa[i] = std::abs(2 * cross / (a * b * c));
    before[i] = a;
    after[i] = b;
  }
  double spread = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // kappa_s needs the curvature on both sides: an open curve's end blocks keep 1/2.
    if (!pb.closed && (i == 0 || i + 1 == n)) continue;
    const double hb = before[i], ha = after[i];
    if (!(hb > 0 && ha > 0 && std::isfinite(kappa[i]))) continue;
    const std::size_t prev = i == 0 ? n - 1 : i - 1, next = i + 1 == n ? 0 : i + 1;
    // The linearisation of t_i above: the position of Q_i between the midpoints of its two
    // intervals, plus kappa_s / (3 kappa^3 h) with kappa_s the central difference of |kappa|
    // and h the mean interval (on uniform ellipse samples within 1e-4 to 2.5e-3 of the root;
    // the quotient form with one-sided differences was 6-16 times worse).
    const double k = kappa[i], h = 0.5 * (hb + ha);
    const double kappa_s = (kappa[next] - kappa[prev]) / (hb + ha);
    const double ti = hb / (hb + ha) + kappa_s / (3 * k * k * k * h);
    if (!std::isfinite(ti)) continue;
    t[i] = std::min(std::max(ti, predicted_parameter_margin), 1 - predicted_parameter_margin);
    spread = std::max(spread, std::abs(t[i] - 0.5));
  }
  return spread;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_PARAMETER_PREDICTION_H
