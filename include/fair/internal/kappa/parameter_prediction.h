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
// start, not a solution. Degenerate cases: a coincident neighbour (an interval of length 0)
// leaves t_i = 1/2 at its block and the blocks next to it; a t_i outside the margins (beyond
// the density limit, or kappa near 0) means no prediction at all.

#ifndef FAIR_INTERNAL_KAPPA_PARAMETER_PREDICTION_H
#define FAIR_INTERNAL_KAPPA_PARAMETER_PREDICTION_H

#include <fair/internal/kappa/system.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// A predicted t_i closer than this to 0 or 1 means no prediction: the data are beyond the
/// density limit there, and the interior root the density start looks for does not exist.
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

/// The relative change of |kappa| from a point to either neighbour, |kappa_j - kappa| / kappa, up to
/// which the density estimate is taken at its word (it is first order in that change). Beyond it --
/// next to an inflection (where |kappa| has a kink that a central difference hides), on a straight
/// run where kappa is rounding noise, where a straight run meets an arc -- it says nothing.
constexpr double density_estimate_max_relative_step = 0.25;

/// The density estimate of t_i (file comment) at every block, NaN where none is attempted: a
/// coincident neighbour, an open curve's end block (kappa_s needs the curvature on both sides),
/// chords turning by more than predicted_max_turning at the block or a neighbour (the estimate is
/// first order in the turning), or fewer than 3 blocks; +inf where it is attempted but undefined
/// (kappa = 0 on both sides: 0/0). If `first_order` is given, it flags the blocks whose estimate
/// is within its domain: a turning above rounding noise at the block and both neighbours, and a
/// relative change of |kappa| to either neighbour of at most density_estimate_max_relative_step.
/// Returns false when the chords turn by more than
/// predicted_max_turning at some point: the data are not a dense sample as a whole.
/// Scale-free: curvatures enter only as kappa h = 2 sin(turning) h / chord, from unit chord
/// directions, so spacings of 1e-300 give the same t_i as spacings of 1.
inline bool density_estimates(const Problem& pb, std::vector<double>& t, std::vector<char>* first_order = nullptr) {
  const std::size_t n = pb.n;
  t.assign(n, std::numeric_limits<double>::quiet_NaN());
  if (first_order != nullptr) first_order->assign(n, 0);
  if (n < 3) return true;
  // Per block: the intervals to its neighbours, the chord between them, the sine of the
  // turning between the two unit chord directions; usable = no coincident neighbour and a
  // turning of at most predicted_max_turning.
  std::vector<double> before(n), after(n), chord(n), sine(n);
  std::vector<char> usable(n, 0), noise(n, 0);
  bool dense = true;
  for (std::size_t i = 0; i < n; ++i) {
    double px, py, nx, ny;
    neighbour_points(pb, i, px, py, nx, ny);
    const double x = pb.qx[i], y = pb.qy[i];
    const double a = std::hypot(x - px, y - py), b = std::hypot(nx - x, ny - y), c = std::hypot(nx - px, ny - py);
    if (!(a > 0 && b > 0 && c > 0 && std::isfinite(a + b + c))) continue;
    const double ux = (x - px) / a, uy = (y - py) / a, vx = (nx - x) / b, vy = (ny - y) / b;
    const double cross = ux * vy - uy * vx, dot = ux * vx + uy * vy;
    if (!(std::atan2(std::abs(cross), dot) <= predicted_max_turning)) {
      dense = false;
      continue;
    }
    before[i] = a;
    after[i] = b;
    chord[i] = c;
    sine[i] = std::abs(cross);
    usable[i] = 1;
    // The unit chord directions carry rounding errors of about eps |coordinates| / interval: a
    // turning below a few dozen of those is noise, not curvature (a straight run).
    const double size = std::max({std::abs(x), std::abs(y), std::abs(px), std::abs(py), std::abs(nx), std::abs(ny)});
    noise[i] = sine[i] <= 64 * std::numeric_limits<double>::epsilon() * size / std::min(a, b);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!pb.closed && (i == 0 || i + 1 == n)) continue;
    const std::size_t prev = i == 0 ? n - 1 : i - 1, next = i + 1 == n ? 0 : i + 1;
    if (!usable[i] || !usable[prev] || !usable[next]) continue;
    // The linearisation of t_i above: the position of Q_i between the midpoints of its two
    // intervals, plus kappa_s / (3 kappa^3 h) with kappa_s the central difference of |kappa|
    // and h the mean interval (on uniform ellipse samples within 1e-4 to 2.5e-3 of the root;
    // the quotient form with one-sided differences was 6-16 times worse). In units of h:
    // kappa_s / (3 kappa^3 h) = (K_next - K_prev) / (6 K^3) with K = kappa h.
    const double h = 0.5 * (before[i] + after[i]);
    auto kappa_h = [&](std::size_t j) { return 2 * sine[j] * (h / chord[j]); };
    const double k = kappa_h(i), k_prev = kappa_h(prev), k_next = kappa_h(next);
    const double ti = before[i] / (before[i] + after[i]) + (k_next - k_prev) / (6 * k * k * k);
    t[i] = std::isnan(ti) ? std::numeric_limits<double>::infinity() : ti;
    if (first_order != nullptr)
      (*first_order)[i] = !noise[prev] && !noise[i] && !noise[next] &&
                          std::abs(k_next - k) <= density_estimate_max_relative_step * k &&
                          std::abs(k - k_prev) <= density_estimate_max_relative_step * k;
  }
  return dense;
}

/// The t_i of the density estimate, one per block, as a start for the solver. Returns
/// max |t_i - 1/2|; 0, with every t_i = 1/2, when no prediction is made: the data are not a dense
/// sample as a whole (density_estimates), or some estimated t_i lies outside
/// [predicted_parameter_margin, 1 - predicted_parameter_margin] (beyond the density limit of
/// Sec. 7: no interior root to start near; near-straight stretches, where kappa is tiny, also end
/// here). Blocks without an estimate keep 1/2.
inline double predicted_parameters(const Problem& pb, std::vector<double>& t) {
  std::vector<double> estimate;
  const bool dense = density_estimates(pb, estimate);
  t.assign(pb.n, 0.5);
  if (!dense) return 0;
  double spread = 0;
  for (std::size_t i = 0; i < pb.n; ++i) {
    const double ti = estimate[i];
    if (std::isnan(ti)) continue;
    if (!(ti >= predicted_parameter_margin && ti <= 1 - predicted_parameter_margin)) {
      t.assign(pb.n, 0.5);
      return 0;
    }
    t[i] = ti;
    spread = std::max(spread, std::abs(ti - 0.5));
  }
  return spread;
}

/// The input points (increasing indices) where the data are denser than interior kappa-curves
/// allow (doc/kappa_existence.md, Sec. 7): the density estimate, within its domain (first_order of
/// density_estimates: away from inflections and straight runs), puts the curvature maximum of the
/// point's piece outside the piece (t_i outside [0, 1]). The estimate is that of parabolic pieces.
/// It is conservative where the piece and both neighbours have weights <= 1 (ellipse arcs, whose
/// |kappa| falls off from a vertex more slowly, Sec. 7, "Pieces of weight w != 1"); other points
/// are not listed. O(n).
inline std::vector<std::size_t> points_beyond_density_limit(const Problem& pb, const Kappa_solver_state& st) {
  std::vector<double> estimate;
  std::vector<char> first_order;
  density_estimates(pb, estimate, &first_order);
  const std::size_t n = pb.n;
  auto weight_at_most_1 = [&](std::size_t j) { return j >= st.w.size() || st.w[j] <= 1; };
  std::vector<std::size_t> points;
  for (std::size_t i = 0; i < n; ++i) {
    if (!first_order[i] || (estimate[i] >= 0 && estimate[i] <= 1)) continue;
    // first_order[i] implies both neighbours exist (closed: cyclic).
    const std::size_t prev = i == 0 ? n - 1 : i - 1, next = i + 1 == n ? 0 : i + 1;
    if (!weight_at_most_1(prev) || !weight_at_most_1(i) || !weight_at_most_1(next)) continue;
    points.push_back(pb.point_index(i));
  }
  return points;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_PARAMETER_PREDICTION_H
