// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The double-precision solver behind fair::Kappa_curve_2: rational kappa-curves of
// Yan, Schiller, Schaefer, "Circle reproduction with interpolatory curves at local maximal
// curvature points" (equation numbers refer to that paper; weights w = 1 give the polynomial
// kappa-curves of Yan et al. 2017).
//
// The system (unknowns P_i, lambda_i, t_i per block; residuals of eqs. 7, 10, 18: a square
// 4n x 4n system) is in system.h, the initial guess and alternating passes of Section 5.1
// in refinement.h. The paper's energy (eq. 17/19) is a sum of squares of the same
// conditions (differently normalised); its minimum value zero is reached exactly at a root of
// the system, so the solver looks for a root and stops when max |r| <= tolerance.
//
// Two methods, both O(n) per iteration because every residual depends on the unknowns of
// blocks i-2..i+1 only:
//  - Newton's method (newton()): J delta = -r solved directly by the block LU of
//    block_lu.h (Woodbury correction for the wrap-around of closed curves), the
//    Jacobian from jacobian.h, an Armijo backtracking line search, and chord steps
//    (reusing the factorisation) in the quadratic regime. Converges in 2-4 Jacobians from two
//    refinement passes on typical data; it gives up on a singular pivot block or a failed
//    line search.
//  - Levenberg-Marquardt (levenberg_marquardt(), the fallback): minimises 1/2 |r|^2 with
//    Nielsen's damping update and Marquardt's diagonal scaling; J^T J is a band matrix (half
//    bandwidth 15 for open curves; closed curves use the zig-zag block order of
//    banded.h, half bandwidth 31) factored by banded Cholesky, the Jacobian by
//    automatic differentiation (dual.h). Slower per iteration, but robust far from a root.
// Bounds 0 < lambda_i, t_i < 1 are kept by projection onto [parameter_margin, 1 - parameter_margin];
// Newton's method treats the t_i bounds as box constraints of an active-set method (a t_i on
// its face is fixed with its eq. 7 dropped, released by the sign of its multiplier: see
// newton() and doc/kappa_curves.md, "Points on joins"), so a root on joins (ON_JOINS) is solved
// to the tolerance like an interior one; Levenberg-Marquardt keeps the same active set (fixing
// only) and each of its runs is followed by a Newton polish (newton_polish). A singular pivot block of the block LU falls back to a
// pivoted band LU of the same Jacobian (factor_pivoted).
// The warm/cold start policy of Kappa_curve_2 is solve_with_warm_start(). Non-convergence
// within the iteration caps is reported (Kappa_curve_report::status UNSOLVED); the caller
// decides whether to throw.

#ifndef FAIR_INTERNAL_KAPPA_SOLVER_H
#define FAIR_INTERNAL_KAPPA_SOLVER_H

#include <fair/Kappa_curve_options.h>
#include <fair/internal/kappa/banded.h>
#include <fair/internal/kappa/block_lu.h>
#include <fair/internal/kappa/dual.h>
#include <fair/internal/kappa/jacobian.h>
#include <fair/internal/kappa/parameter_prediction.h>
#include <fair/internal/kappa/refinement.h>
#include <fair/internal/kappa/system.h>
#include <fair/internal/common/curvature.h>
#include <fair/internal/conic/curvature_extrema.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

// ----------------------------------------------------------------------------- caps and tolerances

/// Margin of the projection onto 0 < lambda_i, t_i < 1: keeps 1/lambda^2, 1/(1-lambda)^2 of
/// eq. 10 finite while leaving room for roots very near a bound.
constexpr double parameter_margin = 1e-9;
/// A t_i or lambda_i within this of 0 or 1 is "on the bound": no well-separated interior root
/// there (doc/kappa_existence.md), never reported as converged.
constexpr double bound_margin = 1e-4;
/// Once max |r| <= tolerance, polishing aims at this fraction of the tolerance (rounding
/// permitting), so that derived quantities (e.g. circle reproduction) are accurate to it.
constexpr double polish_fraction = 1e-3;
/// Levenberg-Marquardt: iterations spent polishing (each costs a Jacobian; two suffice).
constexpr std::size_t lm_polish_iterations = 2;
/// Levenberg-Marquardt stalls after this many consecutive accepted steps each gaining less
/// than lm_stall_gain of the cost: no useful decrease left at this precision.
constexpr std::size_t lm_stall_steps = 30;
constexpr double lm_stall_gain = 1e-3;
/// Levenberg-Marquardt also stalls when lm_progress_window iterations together gain less than
/// lm_progress_gain of the cost (a crawl whose steps gain just over lm_stall_gain, far from a
/// root: fuzz findings of session 11 spent their 200 Jacobians so).
constexpr std::size_t lm_progress_window = 25;
constexpr double lm_progress_gain = 0.05;
/// Levenberg-Marquardt: initial damping, near Gauss-Newton (the refined start is close).
constexpr double lm_initial_damping = 1e-8;
/// Levenberg-Marquardt: floor of Marquardt's diagonal scaling relative to its largest entry
/// (a zero column would make the damped matrix singular).
constexpr double lm_diagonal_floor = 1e-12;
/// Levenberg-Marquardt: damping increases tried per iteration, while polishing and otherwise.
constexpr int lm_polish_attempts = 4;
constexpr int lm_attempts = 40;
/// Levenberg-Marquardt: bounds of the damping (below: pure Gauss-Newton in double; above:
/// steps too small to change the state).
constexpr double lm_min_damping = 1e-20;
constexpr double lm_max_damping = 1e30;
/// Levenberg-Marquardt on a contiguous range (count <= n - 3 for closed curves) in natural
/// order: blocks at distance <= 3 couple, half bandwidth 4 * 3 + 3.
constexpr std::size_t range_bandwidth = 15;
/// Newton: Armijo's sufficient-decrease constant (the usual 1e-4).
constexpr double armijo_constant = 1e-4;
/// Newton: smallest step of the backtracking line search (six halvings).
constexpr double newton_min_step = 1.0 / 64;
/// Newton: a step that reduces max |r| by this factor is in the quadratic regime (chord
/// steps next).
constexpr double newton_contraction = 1e-2;
/// Chord steps are kept while each reduces max |r| by this factor or more.
constexpr double chord_contraction = 0.1;
/// Cold start: alternating passes before the first Newton run (they bring the residual to
/// ~0.05 on typical data, inside Newton's basin).
constexpr std::size_t fast_passes = 2;
/// The alternating passes stop once max |r| is below this (Newton's basin).
constexpr double refinement_stop = 1e-3;
/// Restart after a stalled Levenberg-Marquardt: this many times refinement_passes more passes,
/// stopping at restart_stop.
constexpr std::size_t restart_pass_factor = 4;
constexpr double restart_stop = 1e-7;
/// Local warm start: radii R (blocks on each side of the moved one) first, growth, last.
constexpr std::size_t local_radius_first = 8;
constexpr std::size_t local_radius_growth = 4;
constexpr std::size_t local_radius_last = 32;
/// Closed curves: a local range leaves at least this many blocks outside, so that its system
/// stays open-structured (no wrap-around coupling).
constexpr std::size_t closed_range_gap = 3;

struct Solve_settings {
  // The defaults are the user's (Kappa_curve_options), so that they are stated once.
  std::size_t refinement_passes = Kappa_curve_options().refinement_passes;  // passes of Section 5.1
  std::size_t max_iterations = Kappa_curve_options().max_iterations;  // Jacobians of the whole solve (Newton and LM)
  double tolerance = Kappa_curve_options().tolerance;                 // on max |r|
  bool warm = false;                   // skip the initial guess, start from the given state
  /// Warm start after a change of Q_moved only (block index; n or more: unknown): try local
  /// solves first, see solve().
  std::size_t moved = Problem::no_block;
};

/// The caps and tolerance of a solve with these options (no warm start).
inline Solve_settings solve_settings(const Kappa_curve_options& opt) {
  Solve_settings settings;
  settings.refinement_passes = opt.refinement_passes;
  settings.max_iterations = opt.max_iterations;
  settings.tolerance = opt.tolerance;
  return settings;
}

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

inline void project_bounds(Kappa_solver_state& st) {
  const double lo = parameter_margin, hi = 1 - parameter_margin;
  for (std::size_t i = 0; i < st.t.size(); ++i) {
    st.lambda[i] = std::min(std::max(st.lambda[i], lo), hi);
    st.t[i] = std::min(std::max(st.t[i], lo), hi);
  }
}

// ----------------------------------------------------------------------------- active set

/// The active set of the box-constrained problem (doc/kappa_curves.md, "Points on joins"): t_i
/// is FIXED on its face when it sits on the projection bound parameter_margin or
/// 1 - parameter_margin. The set is a function of the state alone, so it survives warm starts
/// without extra bookkeeping. On the face Q_i is (to O(parameter_margin)) the end point of its
/// piece, eq. 7 of the piece holds by itself (its residual is O(u^2), u the distance of t_i to
/// the bound: doc/kappa_existence.md, Sec. 1) and its row degenerates (a zero gradient at the
/// face root): the Newton system drops that equation together with the unknown t_i.
inline bool t_on_face(double t) { return t <= parameter_margin || t >= 1 - parameter_margin; }

/// Drops the equations of the active set from the residuals F of the blocks of `range` (r_2 of
/// a block whose t_i is on its face: set to 0); returns the max |r| of the equations that remain.
inline double drop_face_equations(const Problem& pb, const Kappa_solver_state& st, const Block_range& range,
                                  std::vector<double>& F) {
  const std::size_t na = range.all ? pb.n : range.count;
  double mx = 0;
  for (std::size_t ii = 0; ii < na; ++ii) {
    const std::size_t i = range.all ? ii : (range.first + ii) % pb.n;
    if (t_on_face(st.t[i])) F[4 * ii + 2] = 0.0;
    for (int c = 0; c < 4; ++c) {
      const double a = std::abs(F[4 * ii + c]);
      mx = (a > mx || std::isnan(a)) ? a : mx;
    }
  }
  return mx;
}

/// Relative size (to the terms of eq. 4's coefficients, before their cancellation) below which a
/// derivative of eq. 4's numerator counts as zero: the piece is a circular arc to that relative
/// accuracy (the numerator vanishes identically for a circle) and has no extremum worth the name.
constexpr double minimum_derivative_floor = 1e-8;

/// The numerator E of kappa' (eq. 4, fair::internal::conic::eq4_coefficients; E goes from - to +
/// at a maximum of |kappa|) of the piece of block i in the Bernstein basis of degree 4, and the
/// size of the terms of its coefficients (for relative tests). The weight is the piece's own
/// (1, the user's, or eq. 16 of the current control points).
struct Eq4_of_piece {
  std::vector<double> b;
  double size = 0;
  double value(double t) const {
    const double u = 1 - t;
    return b[0] * u * u * u * u + 4 * b[1] * u * u * u * t + 6 * b[2] * u * u * t * t + 4 * b[3] * u * t * t * t +
           b[4] * t * t * t * t;
  }
  /// E'(t) / 4 (Bernstein basis of degree 3).
  double derivative(double t) const {
    const double u = 1 - t;
    return (b[1] - b[0]) * u * u * u + 3 * (b[2] - b[1]) * u * u * t + 3 * (b[3] - b[2]) * u * t * t +
           (b[4] - b[3]) * t * t * t;
  }
};
inline Eq4_of_piece eq4_of_piece(const Problem& pb, const Kappa_solver_state& st, std::size_t i) {
  Window<double> win;
  build_window(pb, st, i, win);
  Piece_values<double> pv;
  piece_values(pb, st, i, win, 2, pv);
  const double* X = win.X[2];
  const double w = pv.w;
  Eq4_of_piece e;
  e.b = conic::eq4_coefficients<double>(pv.E0[0], pv.E0[1], X[0], X[1], pv.E2[0], pv.E2[1], w);
  const auto sq = [](double x, double y) { return x * x + y * y; };
  e.size = (w * w * w + w + 1) * (sq(pv.E0[0] - X[0], pv.E0[1] - X[1]) + sq(X[0] - pv.E2[0], X[1] - pv.E2[1]) +
                                  sq(pv.E0[0] - pv.E2[0], pv.E0[1] - pv.E2[1]));
  return e;
}

/// The multiplier of the face constraint of block i (t_i on its face): the one-sided derivative
/// of |kappa| of piece i at Q_i (the piece's end at the join), taken towards the join, as the
/// sign-carrying value of eq. 4's numerator: -E(t_i) at t_i = 1, +E(t_i) at t_i = 0 (E < 0 where
/// |kappa| increases). Non-negative (|kappa| rises towards the join, so that the maximum of
/// |kappa| over the piece is at Q_i, on the join) is the first-order condition of the
/// constrained solution; negative beyond the floor means the piece's maximum lies inside it and
/// the interior is better: the variable is released.
inline bool face_multiplier_negative(const Problem& pb, const Kappa_solver_state& st, std::size_t i) {
  const Eq4_of_piece e = eq4_of_piece(pb, st, i);
  const double v = e.value(st.t[i]), m = st.t[i] > 0.5 ? -v : v;
  return m < -minimum_derivative_floor * e.size;
}

/// Assembles J^T J (into `chol`, reset to half bandwidth h) and g = J^T F, in block order
/// `cyclic_position` for closed curves.
inline void assemble_normal_equations(const Problem& pb, const Kappa_solver_state& st, Banded_cholesky& chol,
                                      std::vector<double>& g, std::size_t h, const Block_range& range = {},
                                      bool active_set = true) {
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
  Jacobian_workspace jws;
  const Window<double>& win = jws.values;
  std::size_t colpos[16];
  int slots[16];
  for (std::size_t ii = 0; ii < na; ++ii) {
    const std::size_t i = range.all ? ii : (range.first + ii) % n;
    // The block row of the Jacobian (jacobian.h; forward-mode differentiation over all 16
    // window unknowns here cost 60 % of a Levenberg-Marquardt iteration).
    double r[4], J[4][16];
    block_jacobian(pb, st, i, jws, r, J);
    // The active set (as in newton()): a t_i on its face is fixed with its eq. 7 dropped -- the
    // row r_2 of block i and the column of t_i (slot 11: only block row i depends on it) vanish.
    if (active_set && t_on_face(st.t[i])) {
      r[2] = 0.0;
      for (int c = 0; c < 16; ++c) J[2][c] = 0.0;
      for (int e = 0; e < 4; ++e) J[e][11] = 0.0;
    }
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
      const double* de = J[e];
      const double fe = r[e];
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
void stepped_state(const Problem& pb, const Block_range& range, const Kappa_solver_state& st, const std::vector<double>& delta,
                   double alpha, Position pos, Kappa_solver_state& trial) {
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
inline double evaluate_range(const Problem& pb, const Kappa_solver_state& s, const Block_range& range, std::vector<double>& F) {
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

inline bool snap_to_faces(const Problem& pb, const Block_range& range, Kappa_solver_state& st);

/// Levenberg-Marquardt from `st` on the blocks of `range` (all by default); returns the final
/// max |r| of the equations that remain. Counts iterations in res. Keeps the active set of
/// newton(): the eq. 7 of a t_i on its face and that t_i are dropped (assemble_normal_equations,
/// drop_face_equations), and a t_i that an accepted step leaves within bound_margin of a bound is
/// fixed on its face (snap_to_faces); it never releases (newton_polish does, through newton()).
/// `active_set` false: the plain method on all equations, t_i free within the projection bounds
/// (the local warm-start stages).
inline double levenberg_marquardt(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                                  Kappa_curve_report& res, std::size_t max_iterations, const Block_range& range = {},
                                  bool active_set = true) {
  const std::size_t n = pb.n;
  project_bounds(st);
  const std::size_t na = range.all ? n : range.count, N = 4 * na;
  // Position of the ii-th active unknown block (range_block) in the band order.
  auto pos = [&](std::size_t ii) { return range.all ? (pb.closed ? cyclic_position(ii, n) : ii) : ii; };
  const std::size_t h = range.all ? normal_bandwidth(pb) : std::min<std::size_t>(range_bandwidth, N - 1);
  std::vector<double> F, Ftrial, g(N), D(N), delta(N), Abase;
  // The residuals of the equations that remain (the active set of newton(): a t_i on its face
  // has its eq. 7 dropped, see assemble_normal_equations).
  auto residuals = [&](const Kappa_solver_state& s, std::vector<double>& R) {
    const double mx = evaluate_range(pb, s, range, R);
    return active_set ? drop_face_equations(pb, s, range, R) : mx;
  };
  double fmax = residuals(st, F);
  double cost = half_squared_norm(F);
  double mu = -1, nu = 2;
  Banded_cholesky chol;
  Kappa_solver_state trial;

  // Polishing (lm_polish_iterations, towards polish_fraction x tolerance) and stall detection
  // (lm_stall_steps steps each gaining < lm_stall_gain): see the constants above.
  std::size_t polish = 0, stalled = 0;
  std::size_t iterations = 0;
  std::vector<double> cost_history;  // cost before each iteration: the window of lm_progress_window
  while (iterations < max_iterations && std::isfinite(cost)) {
    if (fmax <= settings.tolerance) {
      if (polish >= lm_polish_iterations || fmax <= polish_fraction * settings.tolerance) break;
      ++polish;
    }
    if (cost_history.size() >= lm_progress_window &&
        cost > (1 - lm_progress_gain) * cost_history[cost_history.size() - lm_progress_window])
      break;
    cost_history.push_back(cost);
    ++iterations;
    ++res.iterations;
    assemble_normal_equations(pb, st, chol, g, h, range, active_set);
    double maxdiag = 0;
    for (std::size_t k = 0; k < N; ++k) maxdiag = std::max(maxdiag, chol.diagonal(k));
    if (!(maxdiag > 0) || !std::isfinite(maxdiag)) break;
    for (std::size_t k = 0; k < N; ++k) D[k] = std::max(chol.diagonal(k), lm_diagonal_floor * maxdiag);
    if (mu < 0) mu = lm_initial_damping;
    Abase = chol.storage();
    bool accepted = false;
    for (int attempt = 0; attempt < (polish ? lm_polish_attempts : lm_attempts) && !accepted; ++attempt) {
      chol.storage() = Abase;
      for (std::size_t k = 0; k < N; ++k) chol.add_diagonal(k, mu * D[k]);
      if (!chol.factor()) { mu *= nu; nu *= 2; continue; }
      for (std::size_t k = 0; k < N; ++k) delta[k] = -g[k];
      chol.solve(delta.data());
      stepped_state(pb, range, st, delta, 1.0, pos, trial);
      const double fm = residuals(trial, Ftrial);
      const double ct = half_squared_norm(Ftrial);
      double pred = 0;
      for (std::size_t k = 0; k < N; ++k) pred += delta[k] * (mu * D[k] * delta[k] - g[k]);
      pred *= 0.5;
      if (std::isfinite(ct) && ct < cost) {
        const double rho = pred > 0 ? (cost - ct) / pred : 1.0;
        stalled = (ct > (1 - lm_stall_gain) * cost) ? stalled + 1 : 0;
        st = trial;
        F.swap(Ftrial);
        cost = ct;
        fmax = fm;
        // The fixing rule of newton(): a t_i that the step leaves within bound_margin of a bound
        // goes onto its face (no linear creep into the singular face root).
        if (active_set && snap_to_faces(pb, range, st)) {
          fmax = residuals(st, F);
          cost = half_squared_norm(F);
        }
        // Nielsen's update, but faster towards Gauss-Newton on very good steps: from the
        // refined initial guess the full Newton step is almost always right.
        const double q = 2 * rho - 1;
        mu *= (rho > 0.75) ? 0.01 : std::max(1.0 / 3.0, 1 - q * q * q);
        mu = std::max(mu, lm_min_damping);
        nu = 2;
        accepted = true;
      } else {
        mu *= nu;
        nu *= 2;
        if (mu > lm_max_damping) break;
      }
    }
    if (!accepted || stalled >= lm_stall_steps) break;  // stagnation: no (useful) decrease at this precision
  }
  return fmax;
}

/// The Jacobian of newton() (blocks of `range`, na of them; fill(ii, row) as for
/// Block_band_lu::factor_rows) into a general band matrix with partial pivoting, in the block
/// order of normal_bandwidth (zig-zag for a whole closed curve, natural otherwise): the fallback
/// when the block LU, which does not pivot across blocks, meets a singular pivot block of a
/// non-singular matrix (dense data near inflections). Half bandwidths 4 * 2 + 3 = 11 (lower)
/// and 4 * 1 + 3 = 7 (upper) in natural order, <= 4 * 5 + 3 = 23 in zig-zag order: O(n), about
/// 3x the work of the block LU. Returns false on an exactly singular matrix.
template <class Fill>
bool factor_pivoted(const Problem& pb, const Block_range& range, std::size_t na, Fill&& fill, Banded_lu& plu) {
  const std::size_t n = pb.n, N = 4 * na;
  const bool zigzag = range.all && pb.closed;
  auto pos = [&](std::size_t j) { return zigzag ? cyclic_position(j, n) : j; };
  auto column_block = [&](std::size_t ii, int k) -> long {
    long b = static_cast<long>(ii) - 2 + k;
    if (zigzag) return ((b % static_cast<long>(n)) + static_cast<long>(n)) % static_cast<long>(n);
    return b;
  };
  std::size_t kl = 0, ku = 0;
  for (std::size_t ii = 0; ii < na; ++ii)
    for (int k = 0; k < 4; ++k) {
      const long b = column_block(ii, k);
      if (b < 0 || b >= static_cast<long>(na)) continue;
      const std::size_t pr = pos(ii), pc = pos(static_cast<std::size_t>(b));
      if (pc < pr) kl = std::max(kl, 4 * (pr - pc) + 3);
      else ku = std::max(ku, 4 * (pc - pr) + 3);
    }
  kl = std::min(kl, N - 1);
  ku = std::min(ku, N - 1);
  plu.reset(N, kl, ku);
  Block4 row[4];
  for (std::size_t ii = 0; ii < na; ++ii) {
    fill(ii, row);
    for (int k = 0; k < 4; ++k) {
      const long b = column_block(ii, k);
      if (b < 0 || b >= static_cast<long>(na)) continue;
      const std::size_t r0 = 4 * pos(ii), c0 = 4 * pos(static_cast<std::size_t>(b));
      for (int e = 0; e < 4; ++e)
        for (int c = 0; c < 4; ++c)
          if (row[k][4 * e + c] != 0.0) plu.add(r0 + e, c0 + c, row[k][4 * e + c]);
    }
  }
  return plu.factor();
}

/// The fixing rule of newton()'s active set, after an accepted step: a free t_i within
/// bound_margin of a bound (where the outcome would call it on a join anyway) is put on that face.
/// This ends the linear "creep" of Newton's method into a root on the face, whose Jacobian is
/// singular there (doc/kappa_existence.md, Sec. 1), in one step. Returns whether any was.
inline bool snap_to_faces(const Problem& pb, const Block_range& range,
                          Kappa_solver_state& st) {
  const std::size_t na = range.all ? pb.n : range.count;
  bool any = false;
  for (std::size_t ii = 0; ii < na; ++ii) {
    const std::size_t i = range_block(pb, range, ii);
    double& t = st.t[i];
    if (t_on_face(t)) continue;
    if (t < bound_margin) { t = parameter_margin; any = true; }
    else if (t > 1 - bound_margin) { t = 1 - parameter_margin; any = true; }
  }
  return any;
}

/// The largest alpha in (0, 1) at which the step alpha delta puts a free t_i of `range` on a
/// bound (the first crossing), or 0 if the full step crosses none.
inline double first_crossing(const Problem& pb, const Block_range& range, const std::vector<double>& delta,
                             const Kappa_solver_state& st) {
  const std::size_t na = range.all ? pb.n : range.count;
  double alpha = 1;
  bool any = false;
  for (std::size_t ii = 0; ii < na; ++ii) {
    const double t = st.t[range_block(pb, range, ii)], d = delta[4 * ii + 3];
    if (t_on_face(t)) continue;
    const double a = d > 0 ? (1 - parameter_margin - t) / d : d < 0 ? (parameter_margin - t) / d : 2.0;
    if (a < alpha) { alpha = a; any = true; }
  }
  return any ? alpha : 0.0;
}

/// A t in (0,1) of the maximum of |kappa| of the piece of block i (the sign change - to + of
/// eq. 4's numerator E, by bisection on the Bernstein quartic), or 1/2 if E has none there.
inline double piece_maximum_parameter(const Eq4_of_piece& e) {
  auto E = [&](double t) { return e.value(t); };
  double lo = parameter_margin, hi = 1 - parameter_margin;
  if (!(E(lo) < 0 && E(hi) > 0)) return 0.5;
  for (int k = 0; k < 60 && hi - lo > 1e-12; ++k) {  // 60 halvings: below 1e-12 from a unit bracket
    const double mid = 0.5 * (lo + hi);
    (E(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}
/// The same for the piece of block i.
inline double piece_maximum_parameter(const Problem& pb, const Kappa_solver_state& st, std::size_t i) {
  return piece_maximum_parameter(eq4_of_piece(pb, st, i));
}

/// Releases of one t_i per Newton run: a t_i released this often and back on its face stays
/// fixed (no cycling; the outcome then lists the point among points_at_minima).
constexpr char max_releases = 2;

/// The release step of newton()'s active set at a root of the reduced system: every block of
/// `range` whose t is on its face with a negative multiplier (face_multiplier_negative) and was
/// not released before is released, t moved to its piece's maximum of |kappa|. Returns whether
/// any was released.
inline bool release_faces(const Problem& pb, Kappa_solver_state& st, const Block_range& range,
                          std::vector<char>& released) {
  const std::size_t na = range.all ? pb.n : range.count;
  bool any = false;
  std::vector<std::size_t> to_release;
  for (std::size_t ii = 0; ii < na; ++ii) {
    const std::size_t i = range.all ? ii : (range.first + ii) % pb.n;
    if (released[ii] >= max_releases || !t_on_face(st.t[i]) || !face_multiplier_negative(pb, st, i)) continue;
    to_release.push_back(ii);
  }
  for (std::size_t ii : to_release) {  // all decided on the same state, then moved
    const std::size_t i = range.all ? ii : (range.first + ii) % pb.n;
    st.t[i] = piece_maximum_parameter(pb, st, i);
    ++released[ii];
    any = true;
  }
  return any;
}

/// Newton's method on the square system: each step solves J delta = -r directly (block LU,
/// block_lu.h, O(n)), then a backtracking (Armijo) line search on 1/2 |r|^2 along delta
/// with the bounds projected. In the quadratic regime, "chord" steps reuse the last
/// factorisation (cost: one evaluation and one solve); once max |r| <= tolerance, at most one
/// more chord step pushes the residual towards the rounding floor, so that derived quantities
/// are accurate to the tolerance itself. `max_iterations` caps the Jacobian factorisations of
/// this call (res.iterations counts them, cumulatively); Jacobians and chord steps together are
/// capped by 2 x max_iterations.
/// Box constraints (active set, doc/kappa_curves.md): a t_i on its face (t_on_face) is fixed
/// there and its eq. 7 dropped -- in the Jacobian its row r_2 becomes the identity row of t_i,
/// whose column (which only block row i has) is cleared, so the block structure is kept -- and
/// the residual and line search are those of the equations that remain (drop_face_equations). A
/// free t_i that a projected step puts on its bound is fixed from the next iteration on. At a
/// root of the reduced system each fixed t_i whose multiplier is negative
/// (face_multiplier_negative: the maximum of |kappa| of its piece is inside the piece) is
/// released -- moved to that maximum -- and the iteration goes on; a variable released
/// max_releases times stays fixed if it comes back, so the set changes at most 2 max_releases + 1
/// times per block (no cycling).
/// Returns max |r| of the equations that remain (st: the last accepted state). Stops early --
/// leaving the rest to Levenberg-Marquardt -- on a singular pivot block or a failed line search.
inline double newton(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                     Kappa_curve_report& res, std::size_t max_iterations, const Block_range& range = {}) {
  const std::size_t n = pb.n, na = range.all ? n : range.count, N = 4 * na;
  project_bounds(st);
  std::vector<double> F, Ftrial, delta(N);
  evaluate_range(pb, st, range, F);
  double fmax = drop_face_equations(pb, st, range, F), cost = half_squared_norm(F);
  std::vector<char> released(na, 0);
  Block_band_lu lu;
  Jacobian_workspace jws;
  Kappa_solver_state trial;
  bool factored = false, pivoted = false;
  Banded_lu plu;  // the pivoted fallback (factor_pivoted)
  std::vector<double> permuted;
  // delta = J^{-1} delta by the pivoted factorisation, whose unknowns are in zig-zag order for
  // a whole closed curve.
  auto solve_permuted = [&](std::vector<double>& v) {
    const bool zigzag = range.all && pb.closed;
    if (!zigzag) { plu.solve(v.data()); return; }
    permuted.resize(N);
    for (std::size_t ii = 0; ii < na; ++ii)
      for (int c = 0; c < 4; ++c) permuted[4 * cyclic_position(ii, n) + c] = v[4 * ii + c];
    plu.solve(permuted.data());
    for (std::size_t ii = 0; ii < na; ++ii)
      for (int c = 0; c < 4; ++c) v[4 * ii + c] = permuted[4 * cyclic_position(ii, n) + c];
  };
  auto try_step = [&](double alpha) {
    stepped_state(pb, range, st, delta, alpha, [](std::size_t ii) { return ii; }, trial);
    evaluate_range(pb, trial, range, Ftrial);
    const double fm = drop_face_equations(pb, trial, range, Ftrial);
    const double ct = half_squared_norm(Ftrial);
    // Armijo condition: the directional derivative of 1/2|r|^2 along the Newton step is -|r|^2.
    if (!(std::isfinite(ct) && ct <= (1 - 2 * armijo_constant * alpha) * cost)) return false;
    st.dx.swap(trial.dx); st.dy.swap(trial.dy); st.lambda.swap(trial.lambda); st.t.swap(trial.t);
    F.swap(Ftrial);
    cost = ct;
    fmax = fm;
    return true;
  };
  auto chord_step = [&]() {  // the Newton step with the last factorised Jacobian
    for (std::size_t k = 0; k < N; ++k) delta[k] = -F[k];
    if (pivoted) solve_permuted(delta);
    else lu.solve(delta.data());
    return try_step(1.0);
  };
  bool contracting = false;  // the last step reduced max |r| by 1e2 or more
  std::size_t jacobians = 0;
  for (std::size_t it = 0; it < 2 * max_iterations && jacobians < max_iterations && std::isfinite(cost); ++it) {
    if (fmax <= settings.tolerance) {
      if (factored && fmax > polish_fraction * settings.tolerance) chord_step();
      if (!release_faces(pb, st, range, released)) break;
      evaluate_range(pb, st, range, F);
      fmax = drop_face_equations(pb, st, range, F);
      cost = half_squared_norm(F);
      factored = contracting = false;
      continue;
    }
    // In the quadratic regime the Jacobian of the previous iterate is accurate enough: a chord
    // step (one solve and one evaluation, ~15 % of an iteration) gains about as much as a new
    // Newton step. Kept while it reduces max |r| tenfold or more.
    if (factored && contracting) {
      const double before = fmax;
      contracting = chord_step() && fmax <= chord_contraction * before;
      continue;
    }
    // A range (count <= n - 3 for closed curves) is an open-structured system: the window
    // block k of its block ii is its block ii - 2 + k, or a constant outside the range.
    lu.resize(na, range.all && pb.closed);
    for (std::size_t k = 0; k < N; ++k) delta[k] = -F[k];
    auto fill = [&](std::size_t ii, Block4* row) {
      double r[4], J[4][16];
      const std::size_t i = range_block(pb, range, ii);
      block_jacobian(pb, st, i, jws, r, J);
      if (t_on_face(st.t[i])) {  // eq. 7 and t_i dropped: identity row of t_i (slot 2, column 3)
        for (int c = 0; c < 16; ++c) J[2][c] = 0.0;
        J[0][11] = J[1][11] = 0.0;
        J[2][11] = 1.0;
      }
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
    pivoted = !factored;
    if (pivoted) {  // a singular pivot block: the pivoted band LU of the same Jacobian
      factored = factor_pivoted(pb, range, na, fill, plu);
      if (!factored) break;
      for (std::size_t k = 0; k < N; ++k) delta[k] = -F[k];
      solve_permuted(delta);
    } else {
      lu.finish_solve(delta.data());
    }
    const double before = fmax;
    bool accepted = false;
    for (double alpha = 1.0; alpha >= newton_min_step && !accepted; alpha *= 0.5) accepted = try_step(alpha);
    if (!accepted) {
      // The projected step does not decrease the residual: the step up to its first crossing
      // of a bound, where that t_i lands on its face (fixed from the next iteration on).
      const double alpha = first_crossing(pb, range, delta, st);
      if (!(alpha > 0) || !try_step(alpha)) break;
    }
    if (snap_to_faces(pb, range, st)) {
      evaluate_range(pb, st, range, F);
      fmax = drop_face_equations(pb, st, range, F);
      cost = half_squared_norm(F);
      factored = contracting = false;
      continue;
    }
    contracting = fmax <= newton_contraction * before;
  }
  return fmax;
}

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
/// at minima, worst points, the points beyond the density limit.
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
  if (res.status != Kappa_curve_status::UNSOLVED) return;
  res.points_beyond_density_limit = points_beyond_density_limit(pb, st);
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

/// Iteration cap of the Newton phase before the Levenberg-Marquardt fallback takes over.
constexpr std::size_t newton_iterations = 30;
/// Iteration cap of Newton's method in each warm-start stage: from a nearby previous solution it
/// converges in 2-5 Jacobians; more means it is outside the basin (an edit that moves points
/// onto or off joins), where the cold start's Newton paths are cheaper than crawling on.
constexpr std::size_t warm_newton_iterations = 8;
/// Iteration cap of the Levenberg-Marquardt run of a local warm-start stage.
constexpr std::size_t local_lm_iterations = 20;

/// The report of a solve that reached max |r| = fmax at st (and st.w set to the weights).
inline Kappa_curve_report finish(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                                 Kappa_curve_report res, double fmax) {
  const std::size_t n = pb.n;
  std::vector<double> F, weight_error;
  std::vector<double> w(n, 1.0);
  if (fmax <= settings.tolerance) {
    res.residual = evaluate(pb, st, F, &res, &w);
    st.w = w;
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

/// What is left of the iteration cap (Jacobians of the whole solve).
inline std::size_t remaining_iterations(const Solve_settings& settings, const Kappa_curve_report& res) {
  return settings.max_iterations > res.iterations ? settings.max_iterations - res.iterations : 0;
}

/// The density start of cold_start_newton runs when the predicted t_i move this far from 1/2.
constexpr double predicted_spread_min = 0.1;
/// Alternating passes between the density start and its Newton run: one brings lambda and P in
/// line with the predicted t (eq. 10, eq. 18); more passes pull t back towards the passes' own
/// fixed point near 1/2.
constexpr std::size_t density_start_passes = 1;
/// Jacobians of the density start's Newton run. From that start the ellipses of
/// doc/kappa_curves.md converge in 1-10; a longer run that fails costs the fallback its
/// Jacobians.
constexpr std::size_t density_start_iterations = 10;

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
/// Returns true (fmax set) at a root; otherwise st is the state after the passes.
inline bool cold_start_newton(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                              Kappa_curve_report& res, double& fmax) {
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
  fmax = newton(pb, st, settings, res, std::min(remaining_iterations(settings, res), newton_iterations));
  if (is_root(pb, st, fmax, settings) && bounds_active(pb, st) == 0) return true;
  const bool on_joins = is_root(pb, st, fmax, settings);
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
/// whole solve. Returns true (fmax set) at an interior root; otherwise st is the best state.
inline bool local_warm_start(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                             Kappa_curve_report& res, double& fmax) {
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

/// Jacobians kept back from each Levenberg-Marquardt run of the fallback for the Newton polish
/// that follows it (newton_polish).
constexpr std::size_t polish_reserve = 8;
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

/// The cold solve: its Newton paths (cold_start_newton), on failure Levenberg-Marquardt with
/// restart from the passes; then steer_off_minima. `newton_paths_failed`: this caller already ran
/// cold_start_newton on these data with its full caps and it failed; it is deterministic, so
/// the run is skipped and only the start and passes are recomputed (st is then the state after
/// the passes, as cold_start_newton leaves it on failure). Returns max |r|.
inline double cold_solve(const Problem& pb, Kappa_solver_state& st, const Solve_settings& settings,
                         Kappa_curve_report& res, bool newton_paths_failed) {
  double fmax = std::numeric_limits<double>::infinity();
  bool root = false;
  if (!newton_paths_failed) {
    root = cold_start_newton(pb, st, settings, res, fmax);
  } else {
    initial_guess(pb, st);
    refine(pb, st, settings.refinement_passes, refinement_stop, res);
  }
  if (!root) fmax = levenberg_marquardt_with_restart(pb, st, settings, res);
  return steer_off_minima(pb, st, settings, res, fmax);
}

/// What solve() did beyond its report, for solve_with_warm_start.
struct Solve_trace {
  /// A warm solve ran cold_start_newton with its full caps (as a cold solve runs it) and it
  /// failed.
  bool cold_newton_paths_failed = false;
};

/// Solves the kappa-curve system; `st` holds the initial state when settings.warm.
/// Cold start: cold_solve. Warm start (st of size n): local_warm_start around the moved block,
/// else global_warm_newton, else cold_start_newton (report().warm_started false then), else
/// levenberg_marquardt_with_restart from the previous solution.
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
  bool root = local_warm_start(pb, st, settings, res, fmax) || global_warm_newton(pb, st, settings, res, fmax);
  if (!root) {
    // The Newton paths of a cold start (a few Jacobians) before Levenberg-Marquardt from the
    // previous solution: an edit that moves points onto or off joins can leave the previous
    // solution outside Newton's basin while the cold start's passes land inside it.
    // With the Jacobians of its three Newton runs left, their caps are those of a cold solve.
    const bool full_caps =
        remaining_iterations(settings, res) >=
        std::min(settings.max_iterations, 2 * newton_iterations + density_start_iterations);
    Kappa_solver_state fresh;
    if (cold_start_newton(pb, fresh, settings, res, fmax)) {
      st = std::move(fresh);
      res.warm_started = false;
      root = true;
    } else if (trace != nullptr) {
      trace->cold_newton_paths_failed = full_caps;
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

#endif // FAIR_INTERNAL_KAPPA_SOLVER_H
