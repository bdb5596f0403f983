// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The Levenberg-Marquardt fallback of the kappa-curve solver: a Levenberg-Marquardt run
// (levenberg_marquardt.h) followed by a Newton polish (newton_polish: Newton's method reaches
// quadratically the root that Levenberg-Marquardt creeps into), with one restart from more
// alternating passes (refinement.h) when it stalls away from a root.

#ifndef FAIR_INTERNAL_KAPPA_FALLBACK_H
#define FAIR_INTERNAL_KAPPA_FALLBACK_H

#include <fair/internal/kappa/active_set.h>
#include <fair/internal/kappa/levenberg_marquardt.h>
#include <fair/internal/kappa/newton.h>
#include <fair/internal/kappa/outcome.h>
#include <fair/internal/kappa/refinement.h>
#include <fair/internal/kappa/solve_settings.h>
#include <fair/internal/kappa/system.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>

namespace fair {
namespace internal {
namespace kappa {

/// Restart after a stalled Levenberg-Marquardt: this many times refinement_passes more passes,
/// stopping at restart_stop.
constexpr std::size_t restart_pass_factor = 4;
constexpr double restart_stop = 1e-7;

/// newton_polish's second try puts every t_i this close to a bound onto its face.
constexpr double polish_face_margin = 1e-2;

/// Newton's method with the active set from the state a Levenberg-Marquardt run stopped at:
/// Levenberg-Marquardt creeps into a root (linearly, where its Jacobian is nearly singular or a
/// t_i approaches its face) that Newton's method, from close by, reaches quadratically. At most
/// polish_reserve Jacobians; st is kept (and fmax returned) only when the polish ends at a root
/// or lowers max |r|.
inline double newton_polish(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                            Kappa_curve_report& res, double fmax) {
  if (is_root(pb, st, fmax, settings) || remaining_iterations(settings, res) == 0) return fmax;
  Kappa_solver_state trial = st;
  const double f = newton(pb, trial, settings, res, std::min(remaining_iterations(settings, res), polish_reserve / 2));
  if (is_root(pb, trial, f, settings)) {
    st = std::move(trial);
    return f;
  }
  // A crawl into a root on joins: every t_i within polish_face_margin of a bound onto its face
  // (the release rule of newton() frees those whose multiplier says the interior is better).
  Kappa_solver_state snapped = st;
  bool any = false;
  for (double& t : snapped.t) {
    if (t_on_face(t)) continue;
    if (t < polish_face_margin) { t = parameter_margin; any = true; }
    else if (t > 1 - polish_face_margin) { t = 1 - parameter_margin; any = true; }
  }
  double f2 = std::numeric_limits<double>::infinity();
  if (any && remaining_iterations(settings, res) > 0)
    f2 = newton(pb, snapped, settings, res, std::min(remaining_iterations(settings, res), polish_reserve / 2));
  if (is_root(pb, snapped, f2, settings)) {
    st = std::move(snapped);
    return f2;
  }
  if (f < fmax) {
    st = std::move(trial);
    return f;
  }
  return fmax;
}

/// The fallback: Levenberg-Marquardt from st, then newton_polish; if that stalls away from a
/// root, one restart (up to restart_pass_factor x `refinement_passes` more passes from the best
/// state, then Levenberg-Marquardt and newton_polish again), keeping the better. Returns the max
/// |r| reached.
inline double levenberg_marquardt_with_restart(const Problem& pb, Kappa_solver_state& st,
                                               const Solve_settings& settings, Kappa_curve_report& res) {
  const auto lm_cap = [&]() {
    const std::size_t left = remaining_iterations(settings, res);
    return left > 2 * polish_reserve ? left - 2 * polish_reserve : left / 2;
  };
  double fmax = newton_polish(pb, st, settings, res, levenberg_marquardt(pb, st, settings, res, lm_cap()));
  if (!is_root(pb, st, fmax, settings) && remaining_iterations(settings, res) > 0 && settings.refinement_passes > 0) {
    Kappa_solver_state best = st;
    refine(pb, st, restart_pass_factor * settings.refinement_passes, restart_stop, res);
    const double f2 = newton_polish(pb, st, settings, res, levenberg_marquardt(pb, st, settings, res, lm_cap()));
    if (!(f2 < fmax) && !is_root(pb, st, f2, settings)) st = best; else fmax = f2;
  }
  return fmax;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_FALLBACK_H
