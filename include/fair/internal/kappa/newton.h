// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Newton's method on the square kappa-curve system with the active set of active_set.h: the
// direct O(n) block LU solve (linear_algebra/block_band_lu.h, Woodbury correction for closed
// curves), an Armijo line search, chord steps in the quadratic regime, the pivoted fallback
// (pivoted_fallback.h) on a singular pivot block.

#ifndef FAIR_INTERNAL_KAPPA_NEWTON_H
#define FAIR_INTERNAL_KAPPA_NEWTON_H

#include <fair/internal/kappa/active_set.h>
#include <fair/internal/kappa/banded.h>
#include <fair/internal/kappa/block_range.h>
#include <fair/internal/kappa/jacobian.h>
#include <fair/internal/kappa/pivoted_fallback.h>
#include <fair/internal/kappa/solve_settings.h>
#include <fair/internal/kappa/system.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// Newton: Armijo's sufficient-decrease constant (the usual 1e-4).
constexpr double armijo_constant = 1e-4;
/// Newton: smallest step of the backtracking line search (six halvings).
constexpr double newton_min_step = 1.0 / 64;
/// Newton: a step that reduces max |r| by this factor is in the quadratic regime (chord
/// steps next).
constexpr double newton_contraction = 1e-2;
/// Chord steps are kept while each reduces max |r| by this factor or more.
constexpr double chord_contraction = 0.1;

/// Newton's method on the square system: each step solves J delta = -r directly (block LU,
/// linear_algebra/block_band_lu.h, O(n)), then a backtracking (Armijo) line search on 1/2 |r|^2 along delta
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
  auto solve_permuted = [&](std::vector<double>& v) { solve_pivoted(pb, range, na, plu, v, permuted); };
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
      if (!settings.pivoted_fallback) break;
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

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_NEWTON_H
