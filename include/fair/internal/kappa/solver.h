// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The double-precision solver behind fair::Kappa_curve_2: rational kappa-curves of
// Yan, Schiller, Schaefer, "Circle reproduction with interpolatory curves at local maximal
// curvature points" (equation numbers refer to that paper; weights w = 1 give the polynomial
// kappa-curves of Yan et al. 2017).
//
// The system (unknowns P_i, lambda_i, t_i per block; residuals of eqs. 7, 10, 18: a square
// 4n x 4n system) is in kappa_system.h, the initial guess and alternating passes of Section 5.1
// in kappa_refinement.h. The paper's energy (eq. 17/19) is a sum of squares of the same
// conditions (differently normalised); its minimum value zero is reached exactly at a root of
// the system, so the solver looks for a root and stops when max |r| <= tolerance.
//
// Two methods, both O(n) per iteration because every residual depends on the unknowns of
// blocks i-2..i+1 only:
//  - Newton's method (newton()): J delta = -r solved directly by the block LU of
//    kappa_block_lu.h (Woodbury correction for the wrap-around of closed curves), the
//    Jacobian from kappa_jacobian.h, an Armijo backtracking line search, and chord steps
//    (reusing the factorisation) in the quadratic regime. Converges in 2-4 Jacobians from two
//    refinement passes on typical data; it gives up on a singular pivot block or a failed
//    line search.
//  - Levenberg-Marquardt (levenberg_marquardt(), the fallback): minimises 1/2 |r|^2 with
//    Nielsen's damping update and Marquardt's diagonal scaling; J^T J is a band matrix (half
//    bandwidth 15 for open curves; closed curves use the zig-zag block order of
//    kappa_banded.h, half bandwidth 31) factored by banded Cholesky, the Jacobian by
//    automatic differentiation (kappa_dual.h). Slower per iteration, but robust far from a root.
// Bounds 0 < lambda_i, t_i < 1 are kept by projection onto [1e-9, 1 - 1e-9].
// Non-convergence within the iteration caps is reported (Solve_result::converged == false);
// the caller decides whether to throw.

#ifndef FAIR_INTERNAL_KAPPA_SOLVER_H
#define FAIR_INTERNAL_KAPPA_SOLVER_H

#include <fair/internal/kappa/banded.h>
#include <fair/internal/kappa/block_lu.h>
#include <fair/internal/kappa/dual.h>
#include <fair/internal/kappa/jacobian.h>
#include <fair/internal/kappa/refinement.h>
#include <fair/internal/kappa/system.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

struct Solve_settings {
  std::size_t refinement_passes = 60;  // alternating passes of Section 5.1 (paper: 60)
  std::size_t max_iterations = 200;    // Jacobians of the whole solve (Newton and Levenberg-Marquardt)
  double tolerance = 1e-12;            // on max |r|
  bool warm = false;                   // skip the initial guess, start from the given state
  /// Warm start after a change of Q_moved only (block index; n or more: unknown): try local
  /// solves first, see solve().
  std::size_t moved = static_cast<std::size_t>(-1);
};

/// The blocks a (local) Levenberg-Marquardt solve works on: all, or the cyclic (closed) /
/// clipped (open) range first, first+1, ..., first+count-1. In a range solve only the unknowns
/// of these blocks vary and only their residuals are minimised; the others stay fixed.
struct Block_range {
  bool all = true;
  std::size_t first = 0, count = 0;
}; 

// ----------------------------------------------------------------------------- LM

/// Half bandwidth of J^T J in the chosen block order.
inline std::size_t normal_bandwidth(const Problem& pb) {
  const std::size_t n = pb.n;
  auto pos = [&](std::size_t j) { return pb.closed ? cyclic_position(j, n) : j; };
  std::size_t h = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // rows of block i touch blocks i-2..i+1; J^T J couples blocks at distance <= 3.
    for (long d = -3; d <= 3; ++d) {
      long b = static_cast<long>(i) + d;
      if (pb.closed) b = ((b % static_cast<long>(n)) + static_cast<long>(n)) % static_cast<long>(n);
      else if (b < 0 || b >= static_cast<long>(n)) continue;
      const std::size_t pa = pos(i), pbk = pos(static_cast<std::size_t>(b));
      const std::size_t dist = pa > pbk ? pa - pbk : pbk - pa;
      h = std::max(h, 4 * dist + 3);
    }
  }
  return std::min(h, 4 * n - 1);
}

inline void project_bounds(State& st) {
  const double lo = 1e-9, hi = 1 - 1e-9;
  for (std::size_t i = 0; i < st.t.size(); ++i) {
    st.lambda[i] = std::min(std::max(st.lambda[i], lo), hi);
    st.t[i] = std::min(std::max(st.t[i], lo), hi);
  }
}

/// Assembles J^T J (into `chol`, reset to half bandwidth h) and g = J^T F, in block order
/// `cyclic_position` for closed curves.
inline void assemble_normal_equations(const Problem& pb, const State& st, Banded_cholesky& chol,
                                      std::vector<double>& g, std::size_t h, const Block_range& range = {}) {
  const std::size_t n = pb.n;
  const std::size_t na = range.all ? n : range.count, N = 4 * na;
  const std::size_t none = static_cast<std::size_t>(-1);
  // Position of block j among the unknowns (none: held fixed).
  auto pos = [&](std::size_t j) -> std::size_t {
    if (range.all) return pb.closed ? cyclic_position(j, n) : j;
    const std::size_t k = pb.closed ? (j + n - range.first) % n : j - range.first;  // wraps when j < first
    return k < range.count ? k : none;
  };
  chol.reset(N, h);
  g.assign(N, 0.0);
  Window<Dual<16>> win;
  std::size_t colpos[16];
  int slots[16];
  for (std::size_t ii = 0; ii < na; ++ii) {
    const std::size_t i = range.all ? ii : (range.first + ii) % n;
    build_window(pb, st, i, win);
    Dual<16> r[4];
    block_residuals(pb, st, i, win, r);
    int m = 0;
    for (int k = 0; k < 4; ++k) {
      if (!win.valid[k]) continue;
      const std::size_t p = pos(win.block[k]);
      if (p == none) continue;
      for (int c = 0; c < 4; ++c) { slots[m] = 4 * k + c; colpos[m] = 4 * p + c; ++m; }
    }
    // Local 16 x 16 block of J^T J and local gradient, then one scatter into the band.
    double M[16][16] = {};
    double gl[16] = {};
    for (int e = 0; e < 4; ++e) {
      const double* de = r[e].d.data();
      const double fe = r[e].v;
      for (int a = 0; a < 16; ++a) {
        gl[a] += de[a] * fe;
        const double va = de[a];
        if (va == 0.0) continue;
        for (int b = 0; b <= a; ++b) M[a][b] += va * de[b];
      }
    }
    for (int a = 0; a < m; ++a) {
      const int sa = slots[a];
      g[colpos[a]] += gl[sa];
      for (int b = 0; b < m; ++b) {
        if (colpos[a] < colpos[b]) continue;
        const int sb = slots[b];
        const double v = sa >= sb ? M[sa][sb] : M[sb][sa];
        if (v != 0.0) chol.add_lower(colpos[a], colpos[b], v);
      }
    }
  }
}

/// 1/2 |v|^2.
inline double half_squared_norm(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return 0.5 * s;
}

/// Block of the ii-th unknown block of a range.
inline std::size_t range_block(const Problem& pb, const Block_range& range, std::size_t ii) {
  return range.all ? ii : (range.first + ii) % pb.n;
}

/// trial = st + alpha * delta on the blocks of `range`, the unknowns of the ii-th block at
/// delta[4 pos(ii) ...], projected onto the bounds.
template <class Position>
void stepped_state(const Problem& pb, const Block_range& range, const State& st, const std::vector<double>& delta,
                   double alpha, Position pos, State& trial) {
  trial = st;
  const std::size_t na = range.all ? pb.n : range.count;
  for (std::size_t ii = 0; ii < na; ++ii) {
    const std::size_t i = range_block(pb, range, ii), p = 4 * pos(ii);
    trial.dx[i] += alpha * delta[p];
    trial.dy[i] += alpha * delta[p + 1];
    trial.lambda[i] += alpha * delta[p + 2];
    trial.t[i] += alpha * delta[p + 3];
  }
  project_bounds(trial);
}

/// The residuals of the blocks of `range` (all: evaluate()) into F; returns max |r|.
inline double evaluate_range(const Problem& pb, const State& s, const Block_range& range, std::vector<double>& F) {
  if (range.all) return evaluate(pb, s, F);
  F.resize(4 * range.count);
  Window<double> win;
  double mx = 0;
  for (std::size_t ii = 0; ii < range.count; ++ii) {
    const std::size_t i = range_block(pb, range, ii);
    build_window(pb, s, i, win);
    double r[4];
    block_residuals(pb, s, i, win, r);
    for (int c = 0; c < 4; ++c) {
      F[4 * ii + c] = r[c];
      const double a = std::abs(r[c]);
      mx = (a > mx || std::isnan(a)) ? a : mx;
    }
  }
  return mx;
}

/// Levenberg-Marquardt from `st` on the blocks of `range` (all by default); returns the final
/// max |r|. Counts iterations in res.
inline double levenberg_marquardt(const Problem& pb, State& st, const Solve_settings& settings, Solve_result& res,
                                  std::size_t max_iterations, const Block_range& range = {}) {
  const std::size_t n = pb.n;
  project_bounds(st);
  const std::size_t na = range.all ? n : range.count, N = 4 * na;
  // Position of the ii-th active unknown block (range_block) in the band order.
  auto pos = [&](std::size_t ii) { return range.all ? (pb.closed ? cyclic_position(ii, n) : ii) : ii; };
  // A contiguous range (count <= n - 3 for closed curves) in natural order couples blocks at
  // distance <= 3 only: half bandwidth 15.
  const std::size_t h = range.all ? normal_bandwidth(pb) : std::min<std::size_t>(15, N - 1);
  std::vector<double> F, Ftrial, g(N), D(N), delta(N), Abase;
  double fmax = evaluate_range(pb, st, range, F);
  double cost = half_squared_norm(F);
  double mu = -1, nu = 2;
  Banded_cholesky chol;
  State trial;

  // Polishing: once max |r| <= tolerance, at most two more iterations aim at 1e-3 tolerance
  // (rounding permitting), so that derived quantities (e.g. circle reproduction) are accurate
  // to the tolerance itself. Stall: 30 consecutive accepted steps each gaining < 0.1 %.
  std::size_t polish = 0, stalled = 0;
  std::size_t iterations = 0;
  while (iterations < max_iterations && std::isfinite(cost)) {
    if (fmax <= settings.tolerance) {
      if (polish >= 2 || fmax <= 1e-3 * settings.tolerance) break;
      ++polish;
    }
    ++iterations;
    ++res.iterations;
    assemble_normal_equations(pb, st, chol, g, h, range);
    double maxdiag = 0;
    for (std::size_t k = 0; k < N; ++k) maxdiag = std::max(maxdiag, chol.diagonal(k));
    if (!(maxdiag > 0) || !std::isfinite(maxdiag)) break;
    for (std::size_t k = 0; k < N; ++k) D[k] = std::max(chol.diagonal(k), 1e-12 * maxdiag);
    if (mu < 0) mu = 1e-8;
    Abase = chol.storage();
    bool accepted = false;
    for (int attempt = 0; attempt < (polish ? 4 : 40) && !accepted; ++attempt) {
      chol.storage() = Abase;
      for (std::size_t k = 0; k < N; ++k) chol.add_diagonal(k, mu * D[k]);
      if (!chol.factor()) { mu *= nu; nu *= 2; continue; }
      for (std::size_t k = 0; k < N; ++k) delta[k] = -g[k];
      chol.solve(delta.data());
      stepped_state(pb, range, st, delta, 1.0, pos, trial);
      const double fm = evaluate_range(pb, trial, range, Ftrial);
      const double ct = half_squared_norm(Ftrial);
      double pred = 0;
      for (std::size_t k = 0; k < N; ++k) pred += delta[k] * (mu * D[k] * delta[k] - g[k]);
      pred *= 0.5;
      if (std::isfinite(ct) && ct < cost) {
        const double rho = pred > 0 ? (cost - ct) / pred : 1.0;
        stalled = (ct > 0.999 * cost) ? stalled + 1 : 0;
        st = trial;
        F.swap(Ftrial);
        cost = ct;
        fmax = fm;
        // Nielsen's update, but faster towards Gauss-Newton on very good steps: from the
        // refined initial guess the full Newton step is almost always right.
        const double q = 2 * rho - 1;
        mu *= (rho > 0.75) ? 0.01 : std::max(1.0 / 3.0, 1 - q * q * q);
        mu = std::max(mu, 1e-20);
        nu = 2;
        accepted = true;
      } else {
        mu *= nu;
        nu *= 2;
        if (mu > 1e30) break;
      }
    }
    if (!accepted || stalled >= 30) break;  // stagnation: no (useful) decrease at this precision
  }
  return fmax;
}

/// Newton's method on the square system: each step solves J delta = -r directly (block LU,
/// kappa_block_lu.h, O(n)), then a backtracking (Armijo) line search on 1/2 |r|^2 along delta
/// with the bounds projected. In the quadratic regime, "chord" steps reuse the last
/// factorisation (cost: one evaluation and one solve); once max |r| <= tolerance, at most one
/// more chord step pushes the residual towards the rounding floor, so that derived quantities
/// are accurate to the tolerance itself. `max_iterations` caps the Jacobian factorisations of
/// this call (res.iterations counts them, cumulatively); Jacobians and chord steps together are
/// capped by 2 x max_iterations.
/// Returns max |r| reached (st: the last accepted state). Stops early -- leaving the rest to
/// Levenberg-Marquardt -- on a singular pivot block or a failed line search.
inline double newton(const Problem& pb, State& st, const Solve_settings& settings, Solve_result& res,
                     std::size_t max_iterations, const Block_range& range = {}) {
  const std::size_t n = pb.n, na = range.all ? n : range.count, N = 4 * na;
  project_bounds(st);
  std::vector<double> F, Ftrial, delta(N);
  double fmax = evaluate_range(pb, st, range, F), cost = half_squared_norm(F);
  Block_band_lu lu;
  Jacobian_workspace jws;
  State trial;
  bool factored = false;
  auto try_step = [&](double alpha) {
    stepped_state(pb, range, st, delta, alpha, [](std::size_t ii) { return ii; }, trial);
    const double fm = evaluate_range(pb, trial, range, Ftrial);
    const double ct = half_squared_norm(Ftrial);
    // Armijo condition: the directional derivative of 1/2|r|^2 along the Newton step is -|r|^2.
    if (!(std::isfinite(ct) && ct <= (1 - 2e-4 * alpha) * cost)) return false;
    st.dx.swap(trial.dx); st.dy.swap(trial.dy); st.lambda.swap(trial.lambda); st.t.swap(trial.t);
    F.swap(Ftrial);
    cost = ct;
    fmax = fm;
    return true;
  };
  auto chord_step = [&]() {  // the Newton step with the last factorised Jacobian
    for (std::size_t k = 0; k < N; ++k) delta[k] = -F[k];
    lu.solve(delta.data());
    return try_step(1.0);
  };
  bool contracting = false;  // the last step reduced max |r| by 1e2 or more
  std::size_t jacobians = 0;
  for (std::size_t it = 0; it < 2 * max_iterations && jacobians < max_iterations && std::isfinite(cost); ++it) {
    if (fmax <= settings.tolerance) {
      if (factored && fmax > 1e-3 * settings.tolerance) chord_step();
      break;
    }
    // In the quadratic regime the Jacobian of the previous iterate is accurate enough: a chord
    // step (one solve and one evaluation, ~15 % of an iteration) gains about as much as a new
    // Newton step. Kept while it reduces max |r| tenfold or more.
    if (factored && contracting) {
      const double before = fmax;
      contracting = chord_step() && fmax <= 0.1 * before;
      continue;
    }
    // A range (count <= n - 3 for closed curves) is an open-structured system: the window
    // block k of its block ii is its block ii - 2 + k, or a constant outside the range.
    lu.resize(na, range.all && pb.closed);
    for (std::size_t k = 0; k < N; ++k) delta[k] = -F[k];
    auto fill = [&](std::size_t ii, Block4* row) {
      double r[4], J[4][16];
      block_jacobian(pb, st, range_block(pb, range, ii), jws, r, J);
      for (int k = 0; k < 4; ++k) {
        Block4& b = row[k];
        if (!jws.values.valid[k] || (!range.all && (ii + k < 2 || ii + k - 2 >= na))) {
          b.fill(0.0);
          continue;
        }
        for (int e = 0; e < 4; ++e)
          for (int c = 0; c < 4; ++c) b[4 * e + c] = J[e][4 * k + c];
      }
    };
    ++res.iterations;
    ++jacobians;
    factored = lu.factor_rows(fill, delta.data());
    if (!factored) break;
    lu.finish_solve(delta.data());
    const double before = fmax;
    bool accepted = false;
    for (double alpha = 1.0; alpha >= 1.0 / 64 && !accepted; alpha *= 0.5) accepted = try_step(alpha);
    if (!accepted) break;
    contracting = fmax <= 1e-2 * before;
  }
  return fmax;
}

/// Number of t_i, lambda_i within 1e-4 of 0 or 1. A "root" with such a value is degenerate
/// (Q_i at a join: its piece has no interior curvature extremum there); it is never reported
/// as converged.
inline std::size_t bounds_active(const Problem& pb, const State& st, std::vector<std::size_t>* blocks = nullptr) {
  std::size_t count = 0;
  const double b = 1e-4;
  if (blocks) blocks->clear();
  for (std::size_t i = 0; i < pb.n; ++i) {
    const bool t_out = st.t[i] < b || st.t[i] > 1 - b;
    const bool lambda_out = pb.has_start(i) && (st.lambda[i] < b || st.lambda[i] > 1 - b);
    count += (t_out ? 1 : 0) + (lambda_out ? 1 : 0);
    if (blocks && (t_out || lambda_out)) blocks->push_back(i);
  }
  return count;
}

/// Iteration cap of the Newton phase before the Levenberg-Marquardt fallback takes over.
constexpr std::size_t newton_iterations = 30;
/// Iteration cap of the Levenberg-Marquardt run of a local warm-start stage.
constexpr std::size_t local_lm_iterations = 20;

/// The report of a solve that reached max |r| = fmax at st (and st.w set to the weights).
inline Solve_result finish(const Problem& pb, State& st, const Solve_settings& settings, Solve_result res, double fmax) {
  const std::size_t n = pb.n;
  std::vector<double> F;
  res.converged = fmax <= settings.tolerance;
  std::vector<double> w(n, 1.0);
  if (res.converged) {
    res.residual = evaluate(pb, st, F, &res, &w);
    st.w = w;
  } else {
    // Restore interpolation and G1 (eq. 18 with the current lambda, t, w held fixed) so that
    // the returned curve is always a valid interpolating G1 curve; the report then says how
    // far curvature continuity, eq. 7 and (automatic weights) eq. 16 are from holding.
    evaluate(pb, st, F, nullptr, &w);
    State backup = st;
    st.w = w;
    if (!solve_eq18(pb, st)) st = backup;
    Problem frozen = pb;
    frozen.mode = Weight_mode::FIXED;
    frozen.weight = st.w;
    res.residual = evaluate(frozen, st, F, &res);
    if (pb.mode == Weight_mode::AUTOMATIC) {
      std::vector<double> wt(n, 1.0);
      evaluate(pb, st, F, nullptr, &wt);
      for (std::size_t i = 0; i < n; ++i) {
        const double e = st.w[i] - wt[i];
        res.weight_residual = std::max(res.weight_residual, std::abs(e));
        res.energy_weight += e * e;
      }
      res.residual = std::max(res.residual, res.weight_residual);
    }
  }
  res.bounds_active = bounds_active(pb, st, &res.boundary_blocks);
  res.converged = res.residual <= settings.tolerance && res.bounds_active == 0;
  return res;
}

/// Solves the kappa-curve system; `st` holds the initial state when settings.warm.
/// Strategy (cold start): initial guess, two alternating passes, Newton's method (the fast
/// path). If that does not reach an interior root: back to the state after the two passes, up
/// to `refinement_passes` passes in all (stopping early once max |r| <= 1e-3), then Newton's
/// method again, then (from the same passes) Levenberg-Marquardt; if that stalls away from a
/// root, one restart: up to 4 x `refinement_passes` more passes from the best state, then
/// Levenberg-Marquardt again.
/// Warm start: local solves around the moved point (see below), else Newton's method, else
/// Levenberg-Marquardt, from the previous solution.
inline Solve_result solve(const Problem& pb, State& st, const Solve_settings& settings) {
  Solve_result res;
  const std::size_t n = pb.n;
  const bool cold = !settings.warm || st.t.size() != n;
  if (cold) {
    initial_guess(pb, st);
    // Fast path: two passes bring the residual to ~0.05, from where Newton's method converges
    // quadratically in two or three Jacobians on typical data. If it fails, start again the
    // paper's way (up to refinement_passes passes), then Newton, then Levenberg-Marquardt.
    const std::size_t fast_passes = std::min<std::size_t>(2, settings.refinement_passes);
    refine(pb, st, fast_passes, 1e-3, res);
    const double f = newton(pb, st, settings, res, std::min<std::size_t>(settings.max_iterations, newton_iterations));
    if (f <= settings.tolerance && bounds_active(pb, st) == 0) return finish(pb, st, settings, res, f);
    // The start is recomputed (deterministic) rather than kept: no copy of the state on the
    // fast path.
    initial_guess(pb, st);
    Solve_result passes;
    refine(pb, st, settings.refinement_passes, 1e-3, passes);
    res.refinement_passes = passes.refinement_passes;
    // Newton's method again from there (on random data in the unit square it then converges as
    // often as Levenberg-Marquardt, and the union of both is larger), else Levenberg-Marquardt.
    if (res.iterations < settings.max_iterations && passes.refinement_passes > fast_passes) {
      State after_passes = st;
      const double f2 = newton(pb, st, settings, res, std::min(settings.max_iterations - res.iterations, newton_iterations));
      if (f2 <= settings.tolerance && bounds_active(pb, st) == 0) return finish(pb, st, settings, res, f2);
      st = after_passes;
    }
  }
  // What is left of the iteration cap (Jacobians of the whole solve).
  auto remaining = [&]() { return settings.max_iterations > res.iterations ? settings.max_iterations - res.iterations : 0; };
  double fmax = std::numeric_limits<double>::infinity();
  bool local_done = false;
  if (!cold && settings.moved < n) {
    // Local warm start: the change of one Q_i perturbs the solution by amounts that decay
    // geometrically along the curve, so first solve only for the blocks within distance R of
    // the moved one (the others held fixed; a square 4(2R+1) system, O(R) per iteration) and
    // accept the result iff the residual of the WHOLE system is within the tolerance; R = 8,
    // 32, then the global solve. The accepted state is a root of the full system to the same
    // tolerance as a global solve. A local result that falls short but lowers the global
    // residual is kept as the start of the next stage. Each stage: Newton (at most
    // newton_iterations Jacobians), else a short Levenberg-Marquardt run (at most
    // local_lm_iterations), both within the cap of the whole solve.
    std::vector<double> F;
    double best = evaluate(pb, st, F);
    for (std::size_t R = 8; R <= 32 && !local_done; R *= 4) {
      Block_range range;
      range.all = false;
      if (pb.closed) {
        if (2 * R + 1 + 3 > n) break;
        range.first = (settings.moved + n - R) % n;
        range.count = 2 * R + 1;
      } else {
        range.first = settings.moved > R ? settings.moved - R : 0;
        range.count = std::min(n, settings.moved + R + 1) - range.first;
        if (range.count >= n) break;
      }
      State trial = st;
      if (!(newton(pb, trial, settings, res, std::min(remaining(), newton_iterations), range) <= settings.tolerance)) {
        trial = st;
        levenberg_marquardt(pb, trial, settings, res, std::min(remaining(), local_lm_iterations), range);
      }
      const double fm = evaluate(pb, trial, F);
      if (fm <= settings.tolerance && bounds_active(pb, trial) == 0) { st = trial; fmax = fm; local_done = true; }
      else if (fm < best) { st = trial; best = fm; }
    }
  }
  if (!local_done && !cold) {
    // Global warm start: Newton's method from the previous solution, else Levenberg-Marquardt.
    State start = st;
    const double f = newton(pb, st, settings, res, std::min(remaining(), newton_iterations));
    if (f <= settings.tolerance && bounds_active(pb, st) == 0) return finish(pb, st, settings, res, f);
    st = start;
  }
  if (!local_done) fmax = levenberg_marquardt(pb, st, settings, res, remaining());
  if (!(fmax <= settings.tolerance) && remaining() > 0 && settings.refinement_passes > 0) {
    State best = st;
    refine(pb, st, 4 * settings.refinement_passes, 1e-7, res);
    const double f2 = levenberg_marquardt(pb, st, settings, res, remaining());
    if (!(f2 < fmax)) st = best; else fmax = f2;
  }
  return finish(pb, st, settings, res, fmax);
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_SOLVER_H
