// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The outcome of a kappa-curve solve (Kappa_curve_status INTERIOR, ON_JOINS, UNSOLVED): the
// points on joins, the points at a curvature minimum of their piece, the worst points, and the
// report of a finished solve (finish: a solve that missed the tolerance still returns a valid
// interpolating G1 curve); is_root, the test of a root of the box-constrained problem.

#ifndef FAIR_INTERNAL_KAPPA_OUTCOME_H
#define FAIR_INTERNAL_KAPPA_OUTCOME_H

#include <fair/Kappa_curve_options.h>
#include <fair/Kappa_curve_report.h>
#include <fair/internal/common/curvature.h>
#include <fair/internal/kappa/active_set.h>
#include <fair/internal/kappa/parameter_prediction.h>
#include <fair/internal/kappa/refinement.h>
#include <fair/internal/kappa/solve_settings.h>
#include <fair/internal/kappa/system.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// Number of t_i, lambda_i within bound_margin of 0 or 1. A "root" with such a value is
/// degenerate (Q_i at a join: its piece has no interior curvature extremum there); it is never
/// reported as converged. `points` receives the input points (Problem::point_index) of these blocks.
inline std::size_t bounds_active(const Problem& pb, const Kappa_solver_state& st,
                                 std::vector<std::size_t>* points = nullptr) {
  std::size_t count = 0;
  const double b = bound_margin;
  if (points) points->clear();
  for (std::size_t i = 0; i < pb.n; ++i) {
    const bool t_out = st.t[i] < b || st.t[i] > 1 - b;
    const bool lambda_out = pb.has_start(i) && (st.lambda[i] < b || st.lambda[i] > 1 - b);
    count += (t_out ? 1 : 0) + (lambda_out ? 1 : 0);
    if (points && (t_out || lambda_out)) points->push_back(pb.point_index(i));
  }
  return count;
}

/// Whether the input point of block i (t_i inside the bound margin) is at a curvature MINIMUM
/// of its piece: the numerator E of kappa' (eq. 4) decreases at t_i, by more than
/// minimum_derivative_floor relative to the size of its terms (below it the piece is a
/// circular arc to that accuracy and no minimum is reported).
inline bool point_at_minimum(const Problem& pb, const Kappa_solver_state& st, std::size_t i) {
  const double t = st.t[i];
  if (!(t > bound_margin && t < 1 - bound_margin)) return false;
  const Eq4_of_piece e = eq4_of_piece(pb, st, i);
  return e.derivative(t) < -minimum_derivative_floor * e.size;
}

/// |kappa| of the rational quadratic with control points P0, P1, P2 and weights (1, w, 1) at t:
/// C = P / W with P = u^2 P0 + 2ut w P1 + t^2 P2, W = u^2 + 2ut w + t^2 (u = 1 - t), and
/// C' = (P'W - PW') / W^2, C'' = (P''W - PW'') / W^2 - 2 W' (P'W - PW') / W^3.
inline double rational_quadratic_abs_curvature(const double* P0, const double* P1, const double* P2, double w,
                                               double t) {
  const double u = 1 - t;
  const double W = u * u + 2 * u * t * w + t * t, dW = 2 * (-u + (u - t) * w + t), ddW = 4 * (1 - w);
  double d1[2], d2[2];
  for (int c = 0; c < 2; ++c) {
    const double P = u * u * P0[c] + 2 * u * t * w * P1[c] + t * t * P2[c];
    const double dP = 2 * (-u * P0[c] + (u - t) * w * P1[c] + t * P2[c]), ddP = 2 * (P0[c] - 2 * w * P1[c] + P2[c]);
    const double a = dP * W - P * dW;
    d1[c] = a / (W * W);
    d2[c] = (ddP * W - P * ddW) / (W * W) - 2 * dW * a / (W * W * W);
  }
  return std::fabs(common::signed_curvature(d1[0], d1[1], d2[0], d2[1]));
}

/// Samples per piece of the check below: enough to see that a maximum of |kappa| lies away from
/// the join (a rational quadratic's |kappa| has at most two interior extrema).
constexpr int join_maximum_samples = 64;

/// Whether the point of block i, with t_i within bound_margin of 0 or 1 (Q_i on a join), fails
/// to be the maximum of |kappa| over its piece: some sample of the piece exceeds |kappa| at t_i
/// by more than a relative 1e-6. The face multiplier only looks at the join's side; a piece whose
/// |kappa| rises towards the join but is larger still at its other end passes that test and not
/// this one. Only demotes an outcome (a sample above the join's value is a witness).
inline bool join_point_not_at_maximum(const Problem& pb, const Kappa_solver_state& st, std::size_t i) {
  const double t = st.t[i];
  if (t > bound_margin && t < 1 - bound_margin) return false;
  Window<double> win;
  build_window(pb, st, i, win);
  Piece_values<double> pv;
  piece_values(pb, st, i, win, 2, pv);
  const double* X = win.X[2];
  const double at_join = rational_quadratic_abs_curvature(pv.E0, X, pv.E2, pv.w, t);
  if (!std::isfinite(at_join)) return false;
  for (int k = 0; k <= join_maximum_samples; ++k) {
    const double v = rational_quadratic_abs_curvature(pv.E0, X, pv.E2, pv.w, double(k) / join_maximum_samples);
    if (std::isfinite(v) && v > at_join * (1 + 1e-6)) return true;
  }
  return false;
}

/// Whether the point of block i is not where its piece's |kappa| is largest, the test of the
/// outcome (classify: points_at_minima): at an interior minimum (point_at_minimum), on its face
/// with |kappa| falling towards the join (face_multiplier_negative), or on a join whose piece
/// has larger |kappa| elsewhere (join_point_not_at_maximum).
inline bool not_at_piece_maximum(const Problem& pb, const Kappa_solver_state& st, std::size_t i) {
  return point_at_minimum(pb, st, i) || (t_on_face(st.t[i]) && face_multiplier_negative(pb, st, i)) ||
         join_point_not_at_maximum(pb, st, i);
}

/// The outcome of a solve whose per-block residuals are F (4 per block, as evaluate()) and, with
/// automatic weights, weight_error (|w_i - eq. 16|, per block; empty otherwise): status, points
/// at minima, worst points and the points beyond the density limit.
inline void classify(const Problem& pb, const Kappa_solver_state& st, const Solve_settings& settings,
                     const std::vector<double>& F, const std::vector<double>& weight_error, Kappa_curve_report& res) {
  res.bounds_active = bounds_active(pb, st, &res.points_on_joins);
  res.points_at_minima.clear();
  // A point on its face whose multiplier is negative (|kappa| of its piece falls towards the
  // join) is at a minimum of |kappa| over its piece too, at the piece's end; a point on a join
  // whose piece has larger |kappa| elsewhere is not at the piece's maximum either.
  for (std::size_t i = 0; i < pb.n; ++i)
    if (not_at_piece_maximum(pb, st, i)) res.points_at_minima.push_back(pb.point_index(i));
  const bool solved = res.residual <= settings.tolerance;
  res.status = !solved || !res.points_at_minima.empty() ? Kappa_curve_status::UNSOLVED
               : res.bounds_active > 0                  ? Kappa_curve_status::ON_JOINS
                                                        : Kappa_curve_status::INTERIOR;
  res.worst_points.clear();
  res.points_beyond_density_limit.clear();
  res.reason = Kappa_curve_unsolved_reason::NONE;
  if (res.status != Kappa_curve_status::UNSOLVED) return;
  res.points_beyond_density_limit = points_beyond_density_limit(pb, st);
  // The reason (Kappa_curve_unsolved_reason): a root of the equations with points at minima is
  // explained by those points; a solve that missed the tolerance on data with points beyond the
  // density limit by those points (the likely cause, and the early decision of start_strategy.h
  // stops there); otherwise the worst points say where it stalled.
  res.reason = solved                                   ? Kappa_curve_unsolved_reason::POINTS_AT_MINIMA
               : !res.points_beyond_density_limit.empty() ? Kappa_curve_unsolved_reason::BEYOND_DENSITY_LIMIT
                                                          : Kappa_curve_unsolved_reason::NO_CONVERGENCE;
  std::vector<Kappa_point_residual> all(pb.n);
  for (std::size_t i = 0; i < pb.n; ++i) {
    double r = weight_error.empty() ? 0.0 : weight_error[i];
    if (std::isnan(r)) r = std::numeric_limits<double>::infinity();  // NaN: the worst, and a valid sort key
    for (int c = 0; c < 4; ++c) {
      const double a = std::abs(F[4 * i + c]);
      r = std::isnan(a) ? std::numeric_limits<double>::infinity() : std::max(r, a);  // NaN: the worst
    }
    all[i] = Kappa_point_residual{pb.point_index(i), r};
  }
  const std::size_t k = std::min(all.size(), Kappa_curve_report::worst_points_listed);
  std::partial_sort(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(k), all.end(),
                    [](const Kappa_point_residual& a, const Kappa_point_residual& b) {
                      return a.residual > b.residual || (a.residual == b.residual && a.point < b.point);
                    });
  res.worst_points.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(k));
}

/// The report of a solve that reached max |r| = fmax at st (and st.w set to the weights).
/// With res.weight_blend < 1 (automatic weights, start_strategy.h: cold_solve, continue_from_unit_weights)
/// st is a root of the blended system: its residuals and outcome are those of that system, and
/// weight_residual / energy_weight say how far the weights are from eq. 16.
inline Kappa_curve_report finish(const Problem& pb_in, Kappa_solver_state& st, const Solve_settings& settings,
                                 Kappa_curve_report res, double fmax) {
  Problem blended;
  const bool blend = pb_in.mode == Kappa_weights::AUTOMATIC && res.weight_blend < 1;
  if (blend) {
    blended = pb_in;
    blended.weight_blend = res.weight_blend;
  } else {
    res.weight_blend = 1;
  }
  const Problem& pb = blend ? blended : pb_in;
  const std::size_t n = pb.n;
  std::vector<double> F, weight_error;
  std::vector<double> w(n, 1.0);
  if (fmax <= settings.tolerance) {
    res.residual = evaluate(pb, st, F, &res, &w);
    st.w = w;
    if (blend) {  // the distance to eq. 16 (not part of the blended system's residual)
      std::vector<double> wt(n, 1.0), G;
      evaluate(pb_in, st, G, nullptr, &wt);
      for (std::size_t i = 0; i < n; ++i) {
        const double e = st.w[i] - wt[i];
        res.weight_residual = std::max(res.weight_residual, std::abs(e));
        res.energy_weight += e * e;
      }
    }
  } else {
    // Restore interpolation and G1 (eq. 18 with the current lambda, t, w held fixed) so that
    // the returned curve is always a valid interpolating G1 curve; the report then says how
    // far curvature continuity, eq. 7 and (automatic weights) eq. 16 are from holding.
    evaluate(pb, st, F, nullptr, &w);
    Kappa_solver_state backup = st;
    st.w = w;
    if (!solve_eq18(pb, st)) st = backup;
    Problem frozen = pb;
    frozen.mode = Kappa_weights::FIXED;
    frozen.weight = st.w;
    res.residual = evaluate(frozen, st, F, &res);
    if (pb.mode == Kappa_weights::AUTOMATIC) {
      std::vector<double> wt(n, 1.0), G;
      evaluate(pb, st, G, nullptr, &wt);
      weight_error.resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        const double e = st.w[i] - wt[i];
        weight_error[i] = std::abs(e);
        res.weight_residual = std::max(res.weight_residual, std::abs(e));
        res.energy_weight += e * e;
      }
      res.residual = std::max(res.residual, res.weight_residual);
    }
  }
  classify(pb, st, settings, F, weight_error, res);
  return res;
}

/// A root of the box-constrained problem: max |r| = fmax of the equations that remain within the
/// tolerance, and every t_i on its face with a non-negative multiplier (face_multiplier_negative:
/// Q_i is where its piece's |kappa| is largest). Its t_i on their faces are the points on joins
/// (Kappa_curve_status::ON_JOINS). O(n), eq. 4 evaluated only on the faces.
inline bool is_root(const Problem& pb, const Kappa_solver_state& st, double fmax, const Solve_settings& settings) {
  if (!(fmax <= settings.tolerance)) return false;
  for (std::size_t i = 0; i < pb.n; ++i)
    if (t_on_face(st.t[i]) && face_multiplier_negative(pb, st, i)) return false;
  return true;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_OUTCOME_H
