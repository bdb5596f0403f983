// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The settings and caps of the kappa-curve solver (solver.h): the projection margin of the
// bounds 0 < lambda_i, t_i < 1, the tolerance and iteration caps of a solve (Solve_settings, from
// the user's Kappa_curve_options), the Jacobian caps of its phases, and what is left of them.

#ifndef FAIR_INTERNAL_KAPPA_SOLVE_SETTINGS_H
#define FAIR_INTERNAL_KAPPA_SOLVE_SETTINGS_H

#include <fair/Kappa_curve_options.h>
#include <fair/Kappa_curve_report.h>
#include <fair/internal/kappa/system.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// Margin of the projection onto 0 < lambda_i, t_i < 1: keeps 1/lambda^2, 1/(1-lambda)^2 of
/// eq. 10 finite while leaving room for roots very near a bound.
constexpr double parameter_margin = 1e-9;
/// A t_i or lambda_i within this of 0 or 1 is "on the bound": no well-separated interior root
/// there (doc/kappa_existence.md), never reported as converged.
constexpr double bound_margin = 1e-4;
/// Once max |r| <= tolerance, polishing aims at this fraction of the tolerance (rounding
/// permitting), so that derived quantities (e.g. circle reproduction) are accurate to it.
constexpr double polish_fraction = 1e-3;

/// The caps and tolerance of one solve, and its warm start.
struct Solve_settings {
  // The defaults are the user's (Kappa_curve_options), so that they are stated once.
  std::size_t refinement_passes = Kappa_curve_options().refinement_passes;  // passes of Section 5.1
  std::size_t max_iterations = Kappa_curve_options().max_iterations;  // Jacobians of the whole solve (Newton and LM)
  double tolerance = Kappa_curve_options().tolerance;                 // on max |r|
  bool warm = false;                   // skip the initial guess, start from the given state
  /// Warm start after a change of Q_moved only (block index; n or more: unknown): try local
  /// solves first, see solve().
  std::size_t moved = Problem::no_block;
  /// Newton's method factors a Jacobian whose block LU meets a singular pivot block by the
  /// pivoted band LU (pivoted_fallback.h; ~5x a Jacobian on a whole closed curve, whose zig-zag
  /// band is wide). Off in the bounded attempt of the early decision beyond the density limit
  /// (start_strategy.h), where such a Jacobian means the attempt has failed.
  bool pivoted_fallback = true;
};

/// The caps and tolerance of a solve with these options (no warm start).
inline Solve_settings solve_settings(const Kappa_curve_options& opt) {
  Solve_settings settings;
  settings.refinement_passes = opt.refinement_passes;
  settings.max_iterations = opt.max_iterations;
  settings.tolerance = opt.tolerance;
  return settings;
}

/// Projects every lambda_i, t_i onto [parameter_margin, 1 - parameter_margin].
inline void project_bounds(Kappa_solver_state& st) {
  const double lo = parameter_margin, hi = 1 - parameter_margin;
  for (std::size_t i = 0; i < st.t.size(); ++i) {
    st.lambda[i] = std::min(std::max(st.lambda[i], lo), hi);
    st.t[i] = std::min(std::max(st.t[i], lo), hi);
  }
}

/// 1/2 |v|^2.
inline double half_squared_norm(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return 0.5 * s;
}

/// Iteration cap of the Newton phase before the Levenberg-Marquardt fallback takes over.
constexpr std::size_t newton_iterations = 30;
/// Iteration cap of Newton's method in each warm-start stage: from a nearby previous solution it
/// converges in 2-5 Jacobians; more means it is outside the basin (an edit that moves points
/// onto or off joins), where the cold start's Newton paths are cheaper than crawling on.
constexpr std::size_t warm_newton_iterations = 8;
/// Iteration cap of the Levenberg-Marquardt run of a local warm-start stage.
constexpr std::size_t local_lm_iterations = 20;

/// Jacobians of the density start's Newton run. From that start the ellipses of
/// doc/kappa_curves.md converge in 1-10; a longer run that fails costs the fallback its
/// Jacobians.
constexpr std::size_t density_start_iterations = 10;

/// Jacobians kept back from each Levenberg-Marquardt run of the fallback for the Newton polish
/// that follows it (newton_polish).
constexpr std::size_t polish_reserve = 8;

/// Warm start after an edit of one input point (start_strategy.h, solve_with_warm_start): the
/// residuals of block i depend on the blocks i-2..i+1 and their points only, so moving the point
/// of block m changes the residuals of blocks m-1..m+2 -- none further than edit_reach blocks
/// away (cyclically for closed curves).
constexpr std::size_t edit_reach = 2;
/// The previous solution failed hopelessly away from the edit when a scale-free residual of a
/// block further than edit_reach from the moved one is at least this: for the |kappa| mismatch
/// (k1 - k2) / (k1 + k2) of eq. 5 (at most 1, where one side is straight), curvatures differing
/// by a factor 3 or more at a join. Then the re-solve runs Newton's method only (the warm stages,
/// the cold start's Newton paths): no Levenberg-Marquardt, no cold solve after the warm one
/// (doc/kappa_curves.md, "The solver", item 7). Measured on 2560 moves of the real data (old
/// solver): no move of a curve left at a residual >= 0.47 was solved (24 moves, 6 curves), while
/// moves of curves left at 0.35 (automatic weights) and 0.048 (w = 1) and below were.
constexpr double hopeless_residual = 0.5;

/// What is left of the iteration cap (Jacobians of the whole solve).
inline std::size_t remaining_iterations(const Solve_settings& settings, const Kappa_curve_report& res) {
  return settings.max_iterations > res.iterations ? settings.max_iterations - res.iterations : 0;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_SOLVE_SETTINGS_H
