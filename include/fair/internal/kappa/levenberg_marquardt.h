// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Levenberg-Marquardt on the kappa-curve system (the robust fallback of solver.h): minimises
// 1/2 |r|^2 with Nielsen's damping update and Marquardt's diagonal scaling. J^T J is a band
// matrix (half bandwidth 15 for open curves; closed curves use the zig-zag block order of
// linear_algebra/cyclic_order.h, half bandwidth 31) assembled from the block Jacobians of
// jacobian.h and factored by banded Cholesky (linear_algebra/banded_cholesky.h). Keeps the
// active set of active_set.h (fixing only).

#ifndef FAIR_INTERNAL_KAPPA_LEVENBERG_MARQUARDT_H
#define FAIR_INTERNAL_KAPPA_LEVENBERG_MARQUARDT_H

#include <fair/internal/kappa/active_set.h>
#include <fair/internal/kappa/banded.h>
#include <fair/internal/kappa/block_range.h>
#include <fair/internal/kappa/jacobian.h>
#include <fair/internal/kappa/solve_settings.h>
#include <fair/internal/kappa/system.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

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

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_LEVENBERG_MARQUARDT_H
