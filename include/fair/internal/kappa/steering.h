// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Sec. 3.2 steering of the kappa-curve solver: from a root that puts input points at curvature
// minima of their pieces (a root of the equations that is not a kappa-curve), move those t_i to
// where their pieces' |kappa| is largest and solve again (steer_off_minima).

#ifndef FAIR_INTERNAL_KAPPA_STEERING_H
#define FAIR_INTERNAL_KAPPA_STEERING_H

#include <fair/internal/kappa/active_set.h>
#include <fair/internal/kappa/fallback.h>
#include <fair/internal/kappa/newton.h>
#include <fair/internal/kappa/outcome.h>
#include <fair/internal/kappa/solve_settings.h>
#include <fair/internal/kappa/system.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// Rounds of steer_off_minima.
constexpr std::size_t steering_rounds = 3;

/// Where |kappa| of the piece of block i is largest: its interior maximum
/// (piece_maximum_parameter), else -- |kappa| monotone along the piece -- the end where it is
/// larger (on that face).
inline double piece_maximum_or_end(const Problem& pb, const Kappa_solver_state& st, std::size_t i) {
  const Eq4_of_piece e = eq4_of_piece(pb, st, i);
  const double lo = parameter_margin, hi = 1 - parameter_margin;
  if (e.value(lo) < 0 && e.value(hi) > 0) return piece_maximum_parameter(e);
  return e.value(0.5) < 0 ? hi : lo;  // E < 0: |kappa| increasing
}

/// Sec. 3.2 steering: with weights w_i < 1 a root can put an input point at a curvature MINIMUM
/// of its piece, and a point on a join can be where its piece's |kappa| is smallest
/// (not_at_piece_maximum) -- a root of the equations that is not a kappa-curve. From such a root
/// every such t_i is moved to where its piece's |kappa| is largest (piece_maximum_or_end; all
/// decided on the same state) and Newton's method runs again (a fresh active set, at most
/// newton_iterations Jacobians), then newton_polish if that ends away from a root, all within
/// the cap of the whole solve. The result is kept iff it is a root with fewer such points; at
/// most steering_rounds rounds. Returns max |r| of st. Measured (doc/kappa_curves.md,
/// "Outcomes"): it solves a few real-data curves more; a Levenberg-Marquardt run after a failed
/// Newton run solved two more but doubled the Jacobians of hard random sets, and was dropped.
inline double steer_off_minima(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                               Kappa_curve_report& res, double fmax) {
  for (std::size_t round = 0; round < steering_rounds; ++round) {
    if (!(fmax <= settings.tolerance) || remaining_iterations(settings, res) == 0) break;
    std::vector<std::size_t> minima;
    for (std::size_t i = 0; i < pb.n; ++i)
      if (not_at_piece_maximum(pb, st, i)) minima.push_back(i);
    if (minima.empty()) break;
    Kappa_solver_state trial = st;
    for (const std::size_t i : minima) trial.t[i] = piece_maximum_or_end(pb, st, i);
    double f = newton(pb, trial, settings, res, std::min(remaining_iterations(settings, res), newton_iterations));
    f = newton_polish(pb, trial, settings, res, f);
    if (!is_root(pb, trial, f, settings)) break;
    std::size_t left = 0;
    for (std::size_t i = 0; i < pb.n; ++i) left += not_at_piece_maximum(pb, trial, i) ? 1 : 0;
    if (left >= minima.size()) break;
    st = std::move(trial);
    fmax = f;
  }
  return fmax;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_STEERING_H
