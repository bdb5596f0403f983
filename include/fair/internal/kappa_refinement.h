// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The initial guess of fair::Kappa_curve_2's solver: Section 5.1 / Algorithm 1 of Yan,
// Schiller, Schaefer -- lambda = t = 1/2, w = 1, eq. 18 solved for P (a (cyclic) tridiagonal,
// strictly diagonally dominant system), then alternating passes: w from eq. 16, t from the
// unique root of eq. 7 in (0,1) (Appendix A), lambda from eq. 10, P from eq. 18. Each pass is
// O(n) and converges linearly; the Newton-type solve of kappa_solver.h finishes the job.

#ifndef FAIR_INTERNAL_KAPPA_REFINEMENT_H
#define FAIR_INTERNAL_KAPPA_REFINEMENT_H

#include <fair/internal/kappa_banded.h>
#include <fair/internal/kappa_system.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

// ----------------------------------------------------------------------------- eq. 7

/// Value of the polynomial of eq. 7 at t.
inline double eq7_value(double A, double B, double C, double w, double t) {
  const double u = 1.0 - t;
  return -w * A * u * u * u * u - (A + B) * u * u * u * t + (B + C) * u * t * t * t + w * C * t * t * t * t;
}

/// The unique root in (0,1) of eq. 7 (Appendix A: the Bernstein coefficients have exactly one
/// sign change when A, C > 0 and w > 0). Safeguarded Newton-bisection on the bracket [0,1]
/// (f(0) = -wA < 0 < f(1) = wC); accuracy: the bracket shrinks to a few ulps or f(t) == 0.
/// Degenerate case (A == 0 or C == 0: an end point coincides with Q): returns `fallback`.
inline double eq7_root(double A, double B, double C, double w, double fallback) {
  if (!(A > 0.0) || !(C > 0.0) || !(w > 0.0)) return fallback;
  double lo = 0.0, hi = 1.0;
  double t = std::min(std::max(fallback, 0.01), 0.99);
  for (int it = 0; it < 200; ++it) {
    const double u = 1.0 - t;
    const double f = eq7_value(A, B, C, w, t);
    if (f == 0.0) return t;
    if (f < 0.0) lo = t; else hi = t;
    // f'(t)
    const double df = 4 * w * A * u * u * u - (A + B) * (u * u * u - 3 * u * u * t) +
                      (B + C) * (3 * u * t * t - t * t * t) + 4 * w * C * t * t * t;
    double next = (df != 0.0) ? t - f / df : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo <= 4 * std::numeric_limits<double>::epsilon()) return 0.5 * (lo + hi);
    const double step = std::abs(next - t);
    t = next;
    if (step <= 4 * std::numeric_limits<double>::epsilon()) return t;  // Newton converged
  }
  return t;
}

// ----------------------------------------------------------------------------- eq. 18

/// Solves eq. 18 for the P_i (as offsets d_i) with lambda, t, w held fixed: a (cyclic)
/// tridiagonal, strictly diagonally dominant system (the diagonal exceeds the off-diagonal
/// sum by 2(1-t_i)t_i w_i > 0), solved by banded LU in the zig-zag order for closed curves.
inline bool solve_eq18(const Problem& pb, State& st) {
  const std::size_t n = pb.n;
  auto pos = [&](std::size_t j) { return pb.closed ? cyclic_position(j, n) : j; };
  const std::size_t band = (pb.closed && n > 1) ? 2 : 1;
  Banded_lu lu(n, std::min(band, n - 1), std::min(band, n - 1));
  std::vector<double> bx(n), by(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = st.t[i], u = 1 - t, w = st.w[i];
    const double c0 = u * u, c2 = t * t;
    double diag = 2 * u * t * w;
    double rx = 0, ry = 0;
    if (pb.has_start(i)) {
      const std::size_t im = (i + n - 1) % n;
      const double l = st.lambda[i];
      diag += c0 * l;
      lu.add(pos(i), pos(im), c0 * (1 - l));
      rx -= c0 * (1 - l) * (pb.qx[im] - pb.qx[i]);
      ry -= c0 * (1 - l) * (pb.qy[im] - pb.qy[i]);
    } else {
      rx -= c0 * (pb.sx - pb.qx[i]);
      ry -= c0 * (pb.sy - pb.qy[i]);
    }
    if (pb.has_end(i)) {
      const std::size_t ip = (i + 1) % n;
      const double l = st.lambda[ip];
      diag += c2 * (1 - l);
      lu.add(pos(i), pos(ip), c2 * l);
      rx -= c2 * l * (pb.qx[ip] - pb.qx[i]);
      ry -= c2 * l * (pb.qy[ip] - pb.qy[i]);
    } else {
      rx -= c2 * (pb.ex - pb.qx[i]);
      ry -= c2 * (pb.ey - pb.qy[i]);
    }
    lu.add(pos(i), pos(i), diag);
    bx[pos(i)] = rx;
    by[pos(i)] = ry;
  }
  if (!lu.factor()) return false;
  lu.solve(bx.data());
  lu.solve(by.data());
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(bx[pos(i)]) || !std::isfinite(by[pos(i)])) return false;
    st.dx[i] = bx[pos(i)];
    st.dy[i] = by[pos(i)];
  }
  return true;
}

// ----------------------------------------------------------------------------- refinement

/// One alternating pass of Section 5.1 (Algorithm 1, lines 7-11).
inline void refinement_pass(const Problem& pb, State& st) {
  const std::size_t n = pb.n;
  Window<double> win;
  // w from eq. 16 (automatic weights), then t from eq. 7, piece by piece.
  std::vector<double> newt(n), neww(n);
  for (std::size_t i = 0; i < n; ++i) {
    build_window(pb, st, i, win);
    Piece_values<double> pc;
    piece_values(pb, st, i, win, 2, pc);
    neww[i] = pc.w;
    const double A = pc.E0[0] * pc.E0[0] + pc.E0[1] * pc.E0[1];
    const double B = pc.E0[0] * pc.E2[0] + pc.E0[1] * pc.E2[1];
    const double C = pc.E2[0] * pc.E2[0] + pc.E2[1] * pc.E2[1];
    newt[i] = std::min(std::max(eq7_root(A, B, C, pc.w, st.t[i]), 1e-6), 1 - 1e-6);
  }
  st.w = neww;
  st.t = newt;
  // lambda from eq. 10: |kappa_{i-1}(1)| = |kappa_i(0)|  <=>  c1 / l^2 = c2 / (1-l)^2.
  std::vector<double> newl = st.lambda;
  for (std::size_t i = 0; i < n; ++i) {
    if (!pb.has_start(i)) continue;
    build_window(pb, st, i, win);
    const std::size_t jm = win.block[1];
    double fac1 = 1, Apx, Apy, fac2 = 1, Anx, Any;
    if (pb.has_start(jm)) { fac1 = 1 - win.lam[1]; Apx = win.X[0][0]; Apy = win.X[0][1]; }
    else { Apx = pb.sx - pb.qx[i]; Apy = pb.sy - pb.qy[i]; }
    if (pb.has_end(i)) { fac2 = win.lam[3]; Anx = win.X[3][0]; Any = win.X[3][1]; }
    else { Anx = pb.ex - pb.qx[i]; Any = pb.ey - pb.qy[i]; }
    const double* X1 = win.X[1];
    const double* X2 = win.X[2];
    const double cr1 = (Apx - X1[0]) * (X2[1] - X1[1]) - (Apy - X1[1]) * (X2[0] - X1[0]);
    const double cr2 = (X1[0] - X2[0]) * (Any - X2[1]) - (X1[1] - X2[1]) * (Anx - X2[0]);
    const double wm = st.w[jm], wi = st.w[i];
    const double a = std::sqrt(fac1 * std::abs(cr1)) / wm, b = std::sqrt(fac2 * std::abs(cr2)) / wi;
    if (a + b > 0 && std::isfinite(a + b)) newl[i] = std::min(std::max(a / (a + b), 1e-3), 1 - 1e-3);
  }
  st.lambda = newl;
  State backup = st;
  if (!solve_eq18(pb, st)) st = backup;
}

/// Initial guess of Algorithm 1 (lines 2-5): lambda = t = 1/2, w = 1 (or the fixed weights).
inline void initial_guess(const Problem& pb, State& st) {
  st.resize(pb.n);
  if (pb.mode == Weight_mode::fixed) st.w = pb.weight;
  solve_eq18(pb, st);
}

/// Alternating passes (Sec. 5.1) until `max_passes` or max |r| <= stop; returns max |r|.
inline double refine(const Problem& pb, State& st, std::size_t max_passes, double stop, Solve_result& res) {
  std::vector<double> F;
  double fmax = evaluate(pb, st, F);
  for (std::size_t p = 0; p < max_passes && !(fmax <= stop); ++p) {
    refinement_pass(pb, st);
    ++res.refinement_passes;
    fmax = evaluate(pb, st, F);
  }
  return fmax;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_REFINEMENT_H
