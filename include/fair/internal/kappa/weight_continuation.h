// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Continuation from w = 1 to automatic weights (issue 24, "Automatic weights end at curvature
// maxima"; doc/kappa_curves.md, "Automatic weights"). With the weights of eq. 16 a solve can end
// at a root that puts a point at a curvature minimum of its piece, or crawl towards such a root
// without reaching the tolerance, while the polynomial kappa-curve (w = 1) of the same data is a
// clean root. From that w = 1 root the weights are moved along w(s) = 1 + s (w_eq16 - 1),
// s = 0 .. 1 (Problem::weight_blend), by Newton's method at each step from the root of the
// step before, so that the solve stays in the basin of the root where every point is at a
// maximum (or on a join) as long as that root exists along the path.

#ifndef FAIR_INTERNAL_KAPPA_WEIGHT_CONTINUATION_H
#define FAIR_INTERNAL_KAPPA_WEIGHT_CONTINUATION_H

#include <fair/internal/kappa/newton.h>
#include <fair/internal/kappa/outcome.h>
#include <fair/internal/kappa/solve_settings.h>
#include <fair/internal/kappa/steering.h>
#include <fair/internal/kappa/system.h>

#include <algorithm>
#include <cstddef>
#include <utility>

namespace fair {
namespace internal {
namespace kappa {

/// The first step of s, and the smallest before the continuation gives up.
constexpr double continuation_first_step = 0.25;
constexpr double continuation_min_step = 1.0 / 64;
/// Jacobians of Newton's method per step: from the root of the step before it converges in 2-4.
constexpr std::size_t continuation_step_iterations = 8;

/// Whether st is a root of pb (max |r| = fmax) where every point is at the maximum of |kappa|
/// of its piece or on a join: a kappa-curve (what classify() reports INTERIOR or ON_JOINS).
inline bool is_clean_root(const Problem& pb, const Kappa_solver_state& st, double fmax,
                          const Solve_settings& settings) {
  if (!is_root(pb, st, fmax, settings)) return false;
  for (std::size_t i = 0; i < pb.n; ++i)
    if (not_at_piece_maximum(pb, st, i)) return false;
  return true;
}

/// Continuation along w(s) = 1 + s (w_eq16 - 1): from st, a clean root of pb (mode AUTOMATIC)
/// at weight_blend `from`, towards weight_blend `to` (either direction). Steps of s start at
/// continuation_first_step, grow by 1.5 after a step whose Newton run ends at a clean root and
/// halve otherwise, down to continuation_min_step; each step from a secant predictor through the
/// last two roots (t_i on a face kept there), and if that fails from the last root itself, within
/// continuation_step_iterations Jacobians and the cap of res. Returns the weight_blend reached:
/// st is the clean root there and fmax its max |r| (st and fmax unchanged when no step succeeded,
/// the return value is then `from`). Where it stops short of `to`, the branch of kappa-curves that
/// starts at `from` ends (measured on the real data: t_i of one point runs away as s approaches
/// the end, and the roots beyond are the ones with that point at a curvature minimum;
/// doc/kappa_curves.md, "Automatic weights").
inline double continue_weights(const Problem& pb, Kappa_solver_state& st, double from, double to,
                               const Solve_settings& settings, Kappa_curve_report& res, double& fmax) {
  Problem path = pb;
  const double dir = to > from ? 1.0 : -1.0;
  double s = from, h = continuation_first_step, s_prev = from;
  Kappa_solver_state& at = st;
  Kappa_solver_state prev;
  bool have_prev = false;
  while (dir * (to - s) > 0) {
    if (h < continuation_min_step || remaining_iterations(settings, res) == 0) break;
    const double next = dir > 0 ? std::min(to, s + h) : std::max(to, s - h);
    path.weight_blend = next;
    Kappa_solver_state trial = at;
    if (have_prev) {  // secant predictor along the path of roots (a t_i on a face stays there)
      const double a = (next - s) / (s - s_prev);
      for (std::size_t i = 0; i < pb.n; ++i) {
        trial.dx[i] += a * (at.dx[i] - prev.dx[i]);
        trial.dy[i] += a * (at.dy[i] - prev.dy[i]);
        trial.lambda[i] += a * (at.lambda[i] - prev.lambda[i]);
        if (!t_on_face(at.t[i])) trial.t[i] += a * (at.t[i] - prev.t[i]);
      }
      project_bounds(trial);
    }
    double f = newton(path, trial, settings, res, std::min(remaining_iterations(settings, res), continuation_step_iterations));
    if (have_prev && !is_clean_root(path, trial, f, settings) && remaining_iterations(settings, res) > 0) {
      trial = at;  // the predictor overshot: from the last root itself
      f = newton(path, trial, settings, res, std::min(remaining_iterations(settings, res), continuation_step_iterations));
    }
    if (is_clean_root(path, trial, f, settings)) {
      prev = std::move(at);
      at = std::move(trial);
      s_prev = s;
      s = next;
      fmax = f;
      have_prev = true;
      h *= 1.5;
    } else {
      h *= 0.5;
    }
  }
  return s;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_WEIGHT_CONTINUATION_H
