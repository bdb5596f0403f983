// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The start strategy of the kappa-curve solver: the cold solve (the density start, the paper's
// initial guess and alternating passes, Newton's method, the Levenberg-Marquardt fallback, the
// steering), the warm start after an edit (a local solve around the moved point, then Newton's
// method from the previous solution) and the warm/cold policy of Kappa_curve_2
// (solve_with_warm_start).

#ifndef FAIR_INTERNAL_KAPPA_START_STRATEGY_H
#define FAIR_INTERNAL_KAPPA_START_STRATEGY_H

#include <fair/Kappa_curve_report.h>
#include <fair/internal/kappa/active_set.h>
#include <fair/internal/kappa/block_range.h>
#include <fair/internal/kappa/fallback.h>
#include <fair/internal/kappa/levenberg_marquardt.h>
#include <fair/internal/kappa/newton.h>
#include <fair/internal/kappa/outcome.h>
#include <fair/internal/kappa/parameter_prediction.h>
#include <fair/internal/kappa/refinement.h>
#include <fair/internal/kappa/solve_settings.h>
#include <fair/internal/kappa/steering.h>
#include <fair/internal/kappa/system.h>
#include <fair/internal/kappa/weight_continuation.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// Cold start: alternating passes before the first Newton run (they bring the residual to
/// ~0.05 on typical data, inside Newton's basin).
constexpr std::size_t fast_passes = 2;
/// The alternating passes stop once max |r| is below this (Newton's basin).
constexpr double refinement_stop = 1e-3;

/// Local warm start: radii R (blocks on each side of the moved one) first, growth, last.
constexpr std::size_t local_radius_first = 8;
constexpr std::size_t local_radius_growth = 4;
constexpr std::size_t local_radius_last = 32;
/// Closed curves: a local range leaves at least this many blocks outside, so that its system
/// stays open-structured (no wrap-around coupling).
constexpr std::size_t closed_range_gap = 3;

/// The density start of cold_start_newton runs when the predicted t_i move this far from 1/2.
constexpr double predicted_spread_min = 0.1;
/// Alternating passes between the density start and its Newton run: one brings lambda and P in
/// line with the predicted t (eq. 10, eq. 18); more passes pull t back towards the passes' own
/// fixed point near 1/2.
constexpr std::size_t density_start_passes = 1;

/// The early decision (doc/kappa_curves.md, "Dense data"): on data where the density estimate
/// lists beyond_limit_decision_points or more points beyond the density limit
/// (points_beyond_density_limit, with the weights of the first passes) the first Newton run gets at most this many Jacobians, and when it ends at no
/// root nothing more is tried: the outcome is UNSOLVED with reason BEYOND_DENSITY_LIMIT. There an
/// interior root does not exist to first order (doc/kappa_existence.md, Sec. 7), and the roots on
/// joins that may exist are exponentially ill-conditioned chains that the fallbacks (the paper's
/// 60 passes, Levenberg-Marquardt with restart) did not reach on any measured data set while
/// spending 40x the time of a random star of the same size (issue 24). That run does not use the
/// pivoted fallback (Solve_settings::pivoted_fallback): a singular pivot block ends it.
constexpr std::size_t beyond_limit_newton_iterations = 8;
/// The early decision applies when the density estimate lists at least this many points beyond
/// the limit. Isolated points beyond it can sit on joins of a root that the fallbacks reach: on
/// the real data of the tests every curve solved with listed points has at most 7 of them (glyph
/// midpoint samplings, two hand-drawn strokes; 10 curves that the bounded attempt alone leaves
/// UNSOLVED), while the dense samples where the fallbacks never succeeded list 20 or more (the
/// benchmark's noisy inflected curves 20-111, the smooth ones 731-99912, the dense glyph
/// samplings 23-277; doc/kappa_curves.md, "Dense data").
constexpr std::size_t beyond_limit_decision_points = 12;

/// Cold start, the Newton paths. On dense smooth data with w = 1 first the density start
/// (parameter_prediction.h: predicted t_i, one pass, at most density_start_iterations Jacobians
/// of Newton's method, kept only at an interior root). Then the initial guess, fast_passes
/// alternating passes, Newton's method with the active set (the fast path: from a residual of
/// ~0.05 it converges quadratically in two or three Jacobians on typical data). If that does
/// not end at an interior root: the paper's way, up to `refinement_passes` passes from the
/// initial guess, then Newton's method again (on random data in the unit square it then
/// converges as often as Levenberg-Marquardt, and it finds an interior root for some sets whose
/// fast path ended on joins). An interior root is preferred; else the first root on joins
/// found.
/// Early decision: where the first passes leave points beyond the density limit, only the fast
/// path runs (its Newton run capped at beyond_limit_newton_iterations), and `decided` is set when
/// it ends at no root: then st is its last state and the caller tries nothing more.
/// Returns true (fmax set) at a root; otherwise st is the state after the passes.
inline bool cold_start_newton(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                              Kappa_curve_report& res, double& fmax, bool* decided = nullptr) {
  if (decided != nullptr) *decided = false;
  // The density start (parameter_prediction.h): on densely sampled smooth data the interior
  // root's t_i lie far from 1/2, where the paper's start begins (uniform samples of the ellipse
  // (cos a, 0.99 sin a): n = 160-260 UNSOLVED from it, INTERIOR in 1-3 Jacobians from this one;
  // doc/kappa_curves.md, "Dense smooth data"). Only with w = 1 (the estimate is that of
  // parabolas), when a prediction is made (the chords turn little at every point, every t_i
  // inside the density limit) and it moves some t_i by predicted_spread_min or more; kept only
  // at an interior root (a root on joins from this start can be worse than what the paths
  // below find).
  std::vector<double> predicted;
  if (pb.mode == Kappa_weights::UNIT && predicted_parameters(pb, predicted) >= predicted_spread_min) {
    st.resize(pb.n);  // the initial guess (w = 1), with the predicted t instead of 1/2
    st.t.swap(predicted);
    solve_eq18(pb, st);
    refine(pb, st, std::min(density_start_passes, settings.refinement_passes), refinement_stop, res);
    fmax = newton(pb, st, settings, res, std::min(remaining_iterations(settings, res), density_start_iterations));
    if (is_root(pb, st, fmax, settings) && bounds_active(pb, st) == 0) return true;
  }
  initial_guess(pb, st);
  const std::size_t first_passes = std::min<std::size_t>(fast_passes, settings.refinement_passes);
  refine(pb, st, first_passes, refinement_stop, res);
  // O(n): the density estimate from the data, with the weights the passes computed.
  const bool beyond_limit = points_beyond_density_limit(pb, st).size() >= beyond_limit_decision_points;
  const std::size_t first_cap = beyond_limit ? beyond_limit_newton_iterations : newton_iterations;
  Solve_settings first = settings;
  first.pivoted_fallback = !beyond_limit;
  fmax = newton(pb, st, first, res, std::min(remaining_iterations(settings, res), first_cap));
  if (is_root(pb, st, fmax, settings) && bounds_active(pb, st) == 0) return true;
  const bool on_joins = is_root(pb, st, fmax, settings);
  if (beyond_limit) {
    if (decided != nullptr) *decided = !on_joins;
    return on_joins;
  }
  Kappa_solver_state joins_root;
  const double joins_fmax = fmax;
  if (on_joins) joins_root = st;
  // The start is recomputed (deterministic) rather than kept: no copy of the state on the
  // fast path.
  initial_guess(pb, st);
  Kappa_curve_report passes;
  refine(pb, st, settings.refinement_passes, refinement_stop, passes);
  res.refinement_passes = passes.refinement_passes;
  if (res.iterations < settings.max_iterations && passes.refinement_passes > first_passes) {
    Kappa_solver_state after_passes = st;
    fmax = newton(pb, st, settings, res, std::min(settings.max_iterations - res.iterations, newton_iterations));
    if (is_root(pb, st, fmax, settings) && (!on_joins || bounds_active(pb, st) == 0)) return true;
    st = after_passes;
  }
  if (!on_joins) return false;
  st = std::move(joins_root);
  fmax = joins_fmax;
  return true;
}

/// The blocks within distance R of block `moved` (cyclic for closed curves, clipped for open
/// ones); false when they would cover the curve, or leave fewer than closed_range_gap blocks of
/// a closed one: then only the global solve is left.
inline bool local_range(const Problem& pb, std::size_t moved, std::size_t R, Block_range& range) {
  const std::size_t n = pb.n;
  range.all = false;
  if (pb.closed) {
    if (2 * R + 1 + closed_range_gap > n) return false;
    range.first = (moved + n - R) % n;
    range.count = 2 * R + 1;
  } else {
    range.first = moved > R ? moved - R : 0;
    range.count = std::min(n, moved + R + 1) - range.first;
    if (range.count >= n) return false;
  }
  return true;
}

/// Local warm start after a change of the block settings.moved only: the change of one Q_i
/// perturbs the solution by amounts that decay geometrically along the curve, so first solve
/// only for the blocks within distance R of the moved one (the others held fixed; a square
/// 4(2R+1) system, O(R) per iteration) and accept the result iff the residual of the WHOLE
/// system is within the tolerance; R = local_radius_first, ... local_radius_last, then the
/// global solve. The accepted state is a root of the full system to the same tolerance as a
/// global solve. A local result that falls short but lowers the global residual is kept as the
/// start of the next stage. Each stage: Newton (at most newton_iterations Jacobians), else a
/// short Levenberg-Marquardt run (at most local_lm_iterations), both within the cap of the
/// whole solve. Returns true (fmax set) at an interior root; otherwise st is the best state, and
/// `original` (if given, empty) receives st as it was when a stage changed it.
inline bool local_warm_start(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                             Kappa_curve_report& res, double& fmax, Kappa_solver_state* original = nullptr) {
  if (settings.moved >= pb.n) return false;
  std::vector<double> F;
  double best = evaluate(pb, st, F);
  for (std::size_t R = local_radius_first; R <= local_radius_last; R *= local_radius_growth) {
    Block_range range;
    if (!local_range(pb, settings.moved, R, range)) break;
    Kappa_solver_state trial = st;
    // An edit can take a point off its join: a t_i of the range on its face whose multiplier is
    // negative already at the start is released before Newton's method (whose own release acts
    // only at a root of the reduced system, which the edited data may not have with t_i fixed).
    std::vector<char> released(range.count, 0);
    release_faces(pb, trial, range, released);
    const std::size_t newton_cap = std::min(remaining_iterations(settings, res), warm_newton_iterations);
    if (!(newton(pb, trial, settings, res, newton_cap, range) <= settings.tolerance)) {
      trial = st;
      const std::size_t lm_cap = std::min(remaining_iterations(settings, res), local_lm_iterations);
      // Without the active set: after an edit that takes a point off its join the previous t_i
      // sits on its face, and only the unconstrained run can move it off (there is no release).
      levenberg_marquardt(pb, trial, settings, res, lm_cap, range, false);
    }
    const double fm = evaluate(pb, trial, F);
    if (is_root(pb, trial, fm, settings)) {
      st = trial;
      fmax = fm;
      return true;
    }
    if (fm < best) {
      if (original != nullptr && original->t.empty()) *original = st;  // st before its first change
      st = trial;
      best = fm;
    }
  }
  return false;
}

/// Global warm start: Newton's method from the previous solution. Returns true (fmax set) at
/// an interior root; otherwise st is left unchanged.
inline bool global_warm_newton(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                               Kappa_curve_report& res, double& fmax) {
  Kappa_solver_state start = st;
  fmax = newton(pb, st, settings, res, std::min(remaining_iterations(settings, res), warm_newton_iterations));
  if (is_root(pb, st, fmax, settings)) return true;
  st = start;
  return false;
}

inline double cold_solve(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                         Kappa_curve_report& res, bool newton_paths_failed, bool continuation = true);

/// Automatic weights (doc/kappa_curves.md, "Automatic weights: continuation from w = 1"): the
/// w = 1 kappa-curve of the same data (a cold solve with w = 1, without this continuation),
/// continued along w(s) = 1 + s (w~ - 1) towards eq. 16's weights (weight_continuation.h), all
/// within `budget` Jacobians (counted in res.iterations). Returns the s reached (out: the
/// kappa-curve there, fout its max |r| at that s), or -1 when the w = 1 solve gives no
/// kappa-curve.
inline double continue_from_unit_weights(const Problem& pb, Kappa_solver_state& out, const Solve_settings& settings,
                                         Kappa_curve_report& res, double& fout, std::size_t budget) {
  Problem unit = pb;
  unit.mode = Kappa_weights::UNIT;
  Solve_settings capped = settings;
  capped.max_iterations = budget;
  Kappa_curve_report side;
  double f = cold_solve(unit, out, capped, side, false, false);
  double reached = -1;
  if (is_clean_root(unit, out, f, capped)) reached = continue_weights(pb, out, 0.0, 1.0, capped, side, f);
  res.iterations += side.iterations;
  fout = f;
  return reached;
}

/// The cold solve: its Newton paths (cold_start_newton), on failure Levenberg-Marquardt with
/// restart from the passes; then steer_off_minima. `newton_paths_failed`: this caller already ran
/// cold_start_newton on these data with its full caps and it failed; it is deterministic, so
/// the run is skipped and only the start and passes are recomputed (st is then the state after
/// the passes, as cold_start_newton leaves it on failure).
/// Automatic weights (`continuation`), where all that gives no kappa-curve:
/// continue_from_unit_weights with a cap of its own (settings.max_iterations Jacobians more, so
/// that every solve that finds a kappa-curve without it is unchanged); its result is kept when
/// it is a kappa-curve, at s = 1 or (res.weight_blend = s) below. Returns max |r| (of the
/// blended system when res.weight_blend < 1).
inline double cold_solve(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                         Kappa_curve_report& res, bool newton_paths_failed, bool continuation) {
  double fmax = std::numeric_limits<double>::infinity();
  bool root = false;
  if (!newton_paths_failed) {
    bool decided = false;
    root = cold_start_newton(pb, st, settings, res, fmax, &decided);
    if (decided) return fmax;  // beyond the density limit: UNSOLVED, nothing more tried
  } else {
    initial_guess(pb, st);
    refine(pb, st, settings.refinement_passes, refinement_stop, res);
  }
  if (!root) fmax = levenberg_marquardt_with_restart(pb, st, settings, res);
  fmax = steer_off_minima(pb, st, settings, res, fmax);
  if (!continuation || pb.mode != Kappa_weights::AUTOMATIC || is_clean_root(pb, st, fmax, settings)) return fmax;
  Kappa_solver_state cand;
  double cand_f = 0;
  const double cand_s = continue_from_unit_weights(pb, cand, settings, res, cand_f, settings.max_iterations);
  if (cand_s < 0) return fmax;
  st = std::move(cand);
  if (cand_s < 1) res.weight_blend = cand_s;
  return cand_f;
}

/// Whether `previous`, the solution before an edit of the input point of block `moved` (offsets
/// in pb's normalisation), failed hopelessly away from the edit: a scale-free residual -- eq. 7
/// or the |kappa| mismatch (r_2, r_3) -- of a block further than edit_reach blocks from `moved`
/// is at least hopeless_residual. The edit does not change those residuals (they depend on the
/// blocks i-2..i+1 and their points only, and not on the scale of the renormalisation), so they
/// are what the previous solve left where the data are unchanged. O(n), one evaluation. False
/// for an unknown edit (moved >= n).
inline bool failed_hopelessly_away_from_edit(const Problem& pb, const Kappa_solver_state& previous,
                                             std::size_t moved) {
  if (moved >= pb.n || previous.t.size() != pb.n) return false;
  std::vector<double> F;
  evaluate(pb, previous, F);
  for (std::size_t i = 0; i < pb.n; ++i) {
    std::size_t d = i > moved ? i - moved : moved - i;
    if (pb.closed) d = std::min(d, pb.n - d);
    if (d <= edit_reach) continue;
    if (!(std::abs(F[4 * i + 2]) < hopeless_residual) || !(std::abs(F[4 * i + 3]) < hopeless_residual))
      return true;  // NaN too
  }
  return false;
}

/// What solve() did beyond its report, for solve_with_warm_start.
struct Solve_trace {
  /// A warm solve ran cold_start_newton with its full caps (as a cold solve runs it) and it
  /// failed.
  bool cold_newton_paths_failed = false;
  /// The early decision (cold_start_newton) ended the solve: beyond the density limit, no root.
  bool decided_beyond_limit = false;
  /// The Newton paths failed and the previous solution had failed hopelessly away from the edit
  /// (failed_hopelessly_away_from_edit): no Levenberg-Marquardt ran.
  bool hopeless_previous = false;
};

/// Solves the kappa-curve system; `st` holds the initial state when settings.warm.
/// Cold start: cold_solve. Warm start (st of size n): local_warm_start around the moved block,
/// else global_warm_newton, else cold_start_newton (report().warm_started false then), else
/// levenberg_marquardt_with_restart from the previous solution -- unless that solution failed
/// hopelessly away from the edit (trace->hopeless_previous; see there).
inline Kappa_curve_report solve(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                                Solve_trace* trace = nullptr) {
  Kappa_curve_report res;
  if (trace != nullptr) *trace = Solve_trace{};
  const bool cold = !settings.warm || st.t.size() != pb.n;
  res.warm_started = !cold;
  if (cold) {
    const double fmax = cold_solve(pb, st, settings, res, false);
    return finish(pb, st, settings, res, fmax);
  }
  double fmax = std::numeric_limits<double>::infinity();
  // The previous solution, for the test below: st, or its copy from before a local stage changed
  // it (made only then: no cost on edits that Newton's method solves).
  Kappa_solver_state original;
  bool root = local_warm_start(pb, st, settings, res, fmax, &original) || global_warm_newton(pb, st, settings, res, fmax);
  if (!root) {
    // The Newton paths of a cold start (a few Jacobians) before Levenberg-Marquardt from the
    // previous solution: an edit that moves points onto or off joins can leave the previous
    // solution outside Newton's basin while the cold start's passes land inside it.
    // With the Jacobians of its three Newton runs left, their caps are those of a cold solve.
    const bool full_caps =
        remaining_iterations(settings, res) >=
        std::min(settings.max_iterations, 2 * newton_iterations + density_start_iterations);
    Kappa_solver_state fresh;
    bool decided = false;
    if (cold_start_newton(pb, fresh, settings, res, fmax, &decided)) {
      st = std::move(fresh);
      res.warm_started = false;
      root = true;
    } else if (trace != nullptr) {
      trace->cold_newton_paths_failed = full_caps;
      trace->decided_beyond_limit = decided;
    }
    if (decided) {  // beyond the density limit: the previous solution's neighbourhood, reported
      std::vector<double> F;
      return finish(pb, st, settings, res, evaluate(pb, st, F));
    }
    // The previous solve ran the whole fallback (passes, Levenberg-Marquardt with restart) on data
    // that are the same where it ended far from any root (doc/kappa_curves.md, "The solver", item
    // 7): no Levenberg-Marquardt, here nor in the cold solve of solve_with_warm_start. Not with
    // automatic weights: their previous kappa-curve can be a root of the blended system
    // (weight_blend < 1), whose residuals with eq. 16's weights this test cannot tell from a
    // failure. Checked only here, where Newton's method has failed: no cost on edits it solves.
    // (global_warm_newton and cold_start_newton leave st as it was when they fail.)
    if (!root && pb.mode != Kappa_weights::AUTOMATIC &&
        failed_hopelessly_away_from_edit(pb, original.t.empty() ? st : original, settings.moved)) {
      if (trace != nullptr) trace->hopeless_previous = true;
      std::vector<double> F;
      return finish(pb, st, settings, res, evaluate(pb, st, F));
    }
  }
  if (!root) fmax = levenberg_marquardt_with_restart(pb, st, settings, res);
  return finish(pb, st, settings, res, steer_off_minima(pb, st, settings, res, fmax));
}

/// The warm/cold start policy of Kappa_curve_2: with a `previous` solution of the same size
/// (offsets already in pb's normalisation), a warm start after a change of input point
/// `moved_point` (any value that is not an input point: unknown change), and if that ends
/// UNSOLVED a cold start as well, keeping the better solve (by outcome, then residual)
/// (report().warm_started says which); without one, a cold start. `st` receives the solution.
/// After an edit of one point of a curve whose solve failed hopelessly away from that point
/// (failed_hopelessly_away_from_edit; w = 1 and fixed weights): Newton's method only (the warm
/// stages, the cold start's Newton paths), no Levenberg-Marquardt and no cold solve
/// (doc/kappa_curves.md, "The solver", item 7).
inline Kappa_curve_report solve_with_warm_start(const Problem& pb, const Kappa_solver_state* previous,
                                                std::size_t moved_point, Solve_settings settings,
                                                Kappa_solver_state& st) {
  settings.warm = false;
  settings.moved = Problem::no_block;
  if (previous == nullptr || previous->t.size() != pb.n) return solve(pb, st, settings);
  st = *previous;
  Solve_settings warm = settings;
  warm.warm = true;
  warm.moved = pb.block_of_point(moved_point);
  Solve_trace trace;
  const Kappa_curve_report warm_report = solve(pb, st, warm, &trace);
  // A warm root on joins is the constrained solution near the previous one: kept (a cold solve
  // costs more than the whole warm one and would jump to another root far from the edit).
  if (warm_report.status != Kappa_curve_status::UNSOLVED) return warm_report;
  // Decided beyond the density limit: the cold solve would repeat the same bounded attempt.
  if (trace.decided_beyond_limit) return warm_report;
  // The previous solve failed hopelessly away from the edit: the cold solve would repeat its
  // fallback where the data are unchanged.
  if (trace.hopeless_previous) return warm_report;
  // The cold solve; when the warm one's fallback already ran the cold Newton paths and they
  // failed, they are not repeated (up to 2 x newton_iterations + density_start_iterations
  // Jacobians for nothing: fuzz finding slow-fixed-weights-25-points). Otherwise (e.g. a warm
  // root with a point at a minimum from the warm Newton stages) the cold solve runs all paths.
  Kappa_solver_state cold;
  Kappa_curve_report cold_report;
  const double cold_fmax = cold_solve(pb, cold, settings, cold_report, trace.cold_newton_paths_failed);
  cold_report = finish(pb, cold, settings, cold_report, cold_fmax);
  // Ranked by outcome (INTERIOR, ON_JOINS, UNSOLVED: the enum's order), then by residual (NaN last).
  const auto rank = [](const Kappa_curve_report& r) { return static_cast<int>(r.status); };
  const bool cold_better = rank(cold_report) < rank(warm_report) ||
                           (rank(cold_report) == rank(warm_report) &&
                            (cold_report.residual < warm_report.residual || (std::isnan(warm_report.residual) && !std::isnan(cold_report.residual))));
  if (!cold_better) return warm_report;
  st = std::move(cold);
  return cold_report;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_START_STRATEGY_H
