// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The initial guess of fair::Kappa_curve_2's solver: Section 5.1 / Algorithm 1 of Yan,
// Schiller, Schaefer -- lambda = t = 1/2, w = 1, eq. 18 solved for P (a (cyclic) tridiagonal
// system), then alternating passes: w from eq. 16, t from the unique root of eq. 7 in (0,1)
// (Appendix A), lambda from eq. 10, P from eq. 18. Each pass is O(n) and converges linearly;
// the Newton-type solve of solver.h finishes the job.
//
// Cost: a pass reads each block's neighbours directly (no Window objects), finds the eq. 7 root
// by safeguarded Newton from the previous t (1-3 evaluations per block), and solves eq. 18 by
// the tridiagonal (Thomas) algorithm, bordered for closed curves, in a reusable workspace
// (no allocation per pass once the workspace has grown to n).

#ifndef FAIR_INTERNAL_KAPPA_REFINEMENT_H
#define FAIR_INTERNAL_KAPPA_REFINEMENT_H

#include <fair/internal/kappa/banded.h>
#include <fair/internal/kappa/system.h>

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

/// The unique root in (0,1) of eq. 7 (Appendix A: the Bernstein coefficients -wA, -(A+B)/4, 0,
/// (B+C)/4, wC have exactly one sign change when A, C > 0 and w > 0, so the root is simple).
/// Safeguarded Newton on the bracket [0,1] (f(0) = -wA < 0 < f(1) = wC), started from
/// `fallback` (the previous t of the refinement, clamped to [0.01, 0.99]; 1/2 if it is NaN):
/// a Newton step leaving the current bracket is replaced by bisection.
/// Stopping rule: with M2 = 12 max_k |second difference of the Bernstein coefficients| >=
/// max |f''| on [0,1] and the Newton step s = f(t)/f'(t), if 2 M2 s^2 <= tol |f'(t)| (tol = 4 eps)
/// then M2 |s| < |f'(t)| / 2 when |s| > tol, so f changes sign between t and t - 2s: the root t*
/// is within 2|s| of t, and by Taylor's theorem |t - s - t*| <= M2 (2s)^2 / (2|f'(t)|) <= tol.
/// The iteration therefore returns t - s as soon as |s| <= tol or 2 M2 s^2 <= tol |f'(t)|
/// (quadratic convergence: typically 1-3 evaluations from the previous pass's t), t when
/// f(t) == 0, or the bracket midpoint when the bracket has shrunk to tol.
/// Accuracy: |result - t*| <= 4 eps plus the rounding error of the evaluated f divided by f'
/// (the root's condition). Cap: 100 evaluations (bisection alone needs 52); the last iterate is
/// returned then.
/// Degenerate case (A == 0 or C == 0: an end point coincides with Q; w <= 0; NaN): returns
/// `fallback`.
/// Safeguarded Newton steps of eq7_root: quadratic convergence from the clamped start needs < 10;
/// the cap only bounds the work on a pathological quartic (then the bracket's midpoint is used).
constexpr int eq7_root_max_steps = 100;
/// The Newton start is the previous t clamped into [eq7_root_start_margin, 1 - margin]: away from
/// the ends, where the quartic's derivative can vanish with the weight terms.
constexpr double eq7_root_start_margin = 0.01;

inline double eq7_root(double A, double B, double C, double w, double fallback) {
  if (!(A > 0.0) || !(C > 0.0) || !(w > 0.0)) return fallback;
  const double tol = 4 * std::numeric_limits<double>::epsilon();
  const double wA = w * A, wC = w * C, AB = A + B, BC = B + C;
  const double M2 = 12 * std::max({std::abs(0.5 * AB - wA), 0.25 * std::abs(C - A), std::abs(wC - 0.5 * BC)});
  double lo = 0.0, hi = 1.0;
  constexpr double margin = eq7_root_start_margin;
  double t = (fallback >= margin) ? std::min(fallback, 1.0 - margin) : (fallback < margin ? margin : 0.5);
  for (int it = 0; it < eq7_root_max_steps; ++it) {
    // f and f' with shared powers (the terms of eq7_value).
    const double u = 1.0 - t, u2 = u * u, t2 = t * t, u3 = u2 * u, t3 = t2 * t;
    const double f = -wA * (u3 * u) - AB * (u3 * t) + BC * (u * t3) + wC * (t3 * t);
    if (f == 0.0) return t;
    if (f < 0.0) lo = t; else hi = t;
    const double df = 4 * wA * u3 - AB * (u3 - 3 * u2 * t) + BC * (3 * u * t2 - t3) + 4 * wC * t3;
    const double step = f / df, next = t - step;
    // Converged (tested before the bracket: a converged t may itself be a bracket end, with
    // t - step rounding onto it).
    if (std::abs(step) <= tol || 2 * M2 * (step * step) <= tol * std::abs(df)) {
      if (next >= lo && next <= hi) return next;
      if (std::abs(step) <= tol) return t;
    }
    if (hi - lo <= tol) return 0.5 * (lo + hi);
    t = (next > lo && next < hi) ? next : 0.5 * (lo + hi);  // also catches df == 0 / NaN steps
  }
  return t;
}

// ----------------------------------------------------------------------------- workspace

/// Scratch storage of the passes (reused from pass to pass: no allocation once grown to n).
struct Refinement_workspace {
  std::vector<double> t, w, lambda;  // the new t, w, lambda of a pass
  std::vector<double> sup, inv;      // eq. 18 (Thomas): super-diagonal, reciprocal pivots
  std::vector<double> rx, ry, spike; // right-hand sides / solution; bordering column (closed)
  std::vector<double> bx, by;        // banded fallback
  Banded_lu lu;                      // banded fallback

  void resize_eq18(std::size_t n) {
    for (std::vector<double>* v : {&sup, &inv, &rx, &ry, &spike}) v->resize(n);
  }
  void resize(std::size_t n) {
    resize_eq18(n);
    for (std::vector<double>* v : {&t, &w, &lambda}) v->resize(n);
  }
};

// ----------------------------------------------------------------------------- eq. 18

namespace detail {

/// Row i of eq. 18 in the unknowns d = P - Q: sub d_{i-1} + diag d_i + sup d_{i+1} = r
/// (sub = 0 without a previous block, sup = 0 without a next one; the fixed end points of an
/// open curve go to the right-hand side).
inline void eq18_row(const Problem& pb, const Kappa_solver_state& st, std::size_t i, double& sub, double& diag, double& sup,
                     double& rx, double& ry) {
  const std::size_t n = pb.n;
  const double t = st.t[i], u = 1 - t, w = st.w[i];
  const double c0 = u * u, c2 = t * t;
  diag = 2 * u * t * w;
  rx = 0;
  ry = 0;
  sub = 0;
  sup = 0;
  if (pb.has_start(i)) {
    const std::size_t im = i == 0 ? n - 1 : i - 1;
    const double l = st.lambda[i];
    diag += c0 * l;
    sub = c0 * (1 - l);
    rx -= sub * (pb.qx[im] - pb.qx[i]);
    ry -= sub * (pb.qy[im] - pb.qy[i]);
  } else {
    rx -= c0 * (pb.sx - pb.qx[i]);
    ry -= c0 * (pb.sy - pb.qy[i]);
  }
  if (pb.has_end(i)) {
    const std::size_t ip = i + 1 == n ? 0 : i + 1;
    const double l = st.lambda[ip];
    diag += c2 * (1 - l);
    sup = c2 * l;
    rx -= sup * (pb.qx[ip] - pb.qx[i]);
    ry -= sup * (pb.qy[ip] - pb.qy[i]);
  } else {
    rx -= c2 * (pb.ex - pb.qx[i]);
    ry -= c2 * (pb.ey - pb.qy[i]);
  }
}

/// Eq. 18 by banded LU with partial pivoting (zig-zag order for closed curves): the general
/// method, used when the matrix is not strictly diagonally dominant or the curve is tiny.
inline bool solve_eq18_banded(const Problem& pb, Kappa_solver_state& st, Refinement_workspace& ws) {
  const std::size_t n = pb.n;
  auto pos = [&](std::size_t j) { return pb.closed ? cyclic_position(j, n) : j; };
  const std::size_t band = (pb.closed && n > 1) ? 2 : 1;
  ws.lu.reset(n, std::min(band, n - 1), std::min(band, n - 1));
  ws.bx.assign(n, 0.0);
  ws.by.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    double sub, diag, sup, rx, ry;
    eq18_row(pb, st, i, sub, diag, sup, rx, ry);
    if (pb.has_start(i)) ws.lu.add(pos(i), pos((i + n - 1) % n), sub);
    if (pb.has_end(i)) ws.lu.add(pos(i), pos((i + 1) % n), sup);
    ws.lu.add(pos(i), pos(i), diag);
    ws.bx[pos(i)] = rx;
    ws.by[pos(i)] = ry;
  }
  if (!ws.lu.factor()) return false;
  ws.lu.solve(ws.bx.data());
  ws.lu.solve(ws.by.data());
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(ws.bx[i]) || !std::isfinite(ws.by[i])) return false;
  for (std::size_t i = 0; i < n; ++i) {
    st.dx[i] = ws.bx[pos(i)];
    st.dy[i] = ws.by[pos(i)];
  }
  return true;
}

} // namespace detail

/// Solves eq. 18 for the P_i (as offsets d_i = P_i - Q_i) with lambda, t, w held fixed: a
/// tridiagonal system (open curves) or a cyclic one (closed curves: corner entries couple
/// blocks 0 and n-1). Row i: (1-t)^2 (1-l_i) d_{i-1} + [2(1-t)t w + (1-t)^2 l_i + t^2 (1-l_{i+1})] d_i
/// + t^2 l_{i+1} d_{i+1} = right-hand side from the Q's.
/// Method: when every row is strictly diagonally dominant (the usual case: t, lambda near 1/2,
/// w not tiny), Gaussian elimination without pivoting -- the Thomas algorithm; a closed curve
/// is bordered: rows 0..n-2 are solved for x_0..x_{n-2} as y - x_{n-1} z (two tridiagonal
/// solves sharing one factorisation), then row n-1 gives x_{n-1}. O(n), no allocation.
/// Otherwise (rows that are not dominant, e.g. t near 0 with lambda_i < 1/2, or closed curves
/// with n < 3) banded LU with partial pivoting (banded.h).
/// Accuracy: both are backward stable (for a row diagonally dominant matrix elimination without
/// pivoting has growth factor <= 2, Higham, Accuracy and Stability, Thm. 9.9; the bordering
/// forms the same Schur complement of row n-1, whose pivot stays dominant).
/// Degenerate case: a singular matrix or a non-finite solution returns false and leaves `st`
/// unchanged.
/// Not linear_algebra::solve_tridiagonal (the library's generic Thomas solve): this is the same
/// elimination, kept fused with the row assembly (each row is eliminated as it is built, and the
/// dominance test of the row decides the fallback before anything is solved), with two
/// right-hand sides and reciprocal pivots in a reused workspace, and bordered rather than
/// Sherman-Morrison when closed. Routing it through the generic solver would change its rounding,
/// and with it the kappa solver's pinned outcomes on real data, for no measured gain.
inline bool solve_eq18(const Problem& pb, Kappa_solver_state& st, Refinement_workspace& ws) {
  const std::size_t n = pb.n;
  if (n == 0) return true;
  if (pb.closed && n < 3) return detail::solve_eq18_banded(pb, st, ws);
  ws.resize_eq18(n);
  double* sup = ws.sup.data();
  double* inv = ws.inv.data();
  double* rx = ws.rx.data();
  double* ry = ws.ry.data();
  double* z = ws.spike.data();
  // Open: rows 0..n-1 in x_0..x_{n-1}. Closed: rows 0..m-1 (m = n-1) in x_0..x_{m-1}, with the
  // column of x_{n-1} (sub_0 in row 0, sup_{m-1} in row m-1) as a third right-hand side z.
  // Each row is assembled and at once eliminated: row i -= (sub_i / pivot_{i-1}) row i-1.
  const bool closed = pb.closed;
  const std::size_t m = closed ? n - 1 : n;
  double last[5] = {0, 0, 0, 0, 0};  // closed: row n-1 (sub, diag, sup, rx, ry)
  for (std::size_t i = 0; i < n; ++i) {
    double sub, diag, s, bx, by;
    detail::eq18_row(pb, st, i, sub, diag, s, bx, by);
    if (!(diag > std::abs(sub) + std::abs(s))) return detail::solve_eq18_banded(pb, st, ws);
    if (i == m) {
      last[0] = sub; last[1] = diag; last[2] = s; last[3] = bx; last[4] = by;
      break;
    }
    double zi = 0;
    if (closed) zi = (i == 0 ? sub : 0.0) + (i + 1 == m ? s : 0.0);
    if (i > 0) {
      const double l = sub * inv[i - 1];
      diag -= l * sup[i - 1];
      bx -= l * rx[i - 1];
      by -= l * ry[i - 1];
      if (closed) zi -= l * z[i - 1];
    }
    inv[i] = 1.0 / diag;
    sup[i] = s;
    rx[i] = bx;
    ry[i] = by;
    if (closed) z[i] = zi;
  }
  // Back substitution.
  rx[m - 1] *= inv[m - 1];
  ry[m - 1] *= inv[m - 1];
  if (closed) z[m - 1] *= inv[m - 1];
  for (std::size_t i = m - 1; i-- > 0;) {
    rx[i] = (rx[i] - sup[i] * rx[i + 1]) * inv[i];
    ry[i] = (ry[i] - sup[i] * ry[i + 1]) * inv[i];
    if (closed) z[i] = (z[i] - sup[i] * z[i + 1]) * inv[i];
  }
  if (closed) {
    // Row n-1: sub x_{n-2} + diag x_{n-1} + sup x_0 = r with x_j = y_j - x_{n-1} z_j.
    const double s = 1.0 / (last[1] - last[0] * z[m - 1] - last[2] * z[0]);
    const double sx = (last[3] - last[0] * rx[m - 1] - last[2] * rx[0]) * s;
    const double sy = (last[4] - last[0] * ry[m - 1] - last[2] * ry[0]) * s;
    for (std::size_t i = 0; i < m; ++i) {
      rx[i] -= sx * z[i];
      ry[i] -= sy * z[i];
    }
    rx[m] = sx;
    ry[m] = sy;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(rx[i]) || !std::isfinite(ry[i])) return false;
  std::copy(rx, rx + n, st.dx.begin());
  std::copy(ry, ry + n, st.dy.begin());
  return true;
}

/// As above with a temporary workspace.
inline bool solve_eq18(const Problem& pb, Kappa_solver_state& st) {
  Refinement_workspace ws;
  return solve_eq18(pb, st, ws);
}

// ----------------------------------------------------------------------------- refinement

/// Clamp of the passes' t_i to [pass_t_margin, 1 - pass_t_margin]: a t of exactly 0 or 1 would
/// put Q_i on a join, where eq. 7 has no interior root to follow.
constexpr double pass_t_margin = 1e-6;
/// Clamp of the passes' lambda_i to [pass_lambda_margin, 1 - pass_lambda_margin]: eq. 10 divides
/// by lambda^2 and (1-lambda)^2, and a join at a control point would make a piece degenerate.
constexpr double pass_lambda_margin = 1e-3;

/// One alternating pass of Section 5.1 (Algorithm 1, lines 7-11): w from eq. 16 (automatic
/// weights; unit/fixed weights stay), t from eq. 7 (clamped by pass_t_margin; a degenerate
/// piece keeps its t), lambda from eq. 10 (clamped by pass_lambda_margin; kept when both sides
/// have zero curvature), P from eq. 18 (kept if that solve fails). Coordinates are local to
/// each Q_i, as in system.h: X_j = d_j + (Q_j - Q_i).
inline void refinement_pass(const Problem& pb, Kappa_solver_state& st, Refinement_workspace& ws) {
  const std::size_t n = pb.n;
  if (n == 0) return;
  ws.resize(n);
  const double* dx = st.dx.data();
  const double* dy = st.dy.data();
  const double* qx = pb.qx.data();
  const double* qy = pb.qy.data();
  const double* lam = st.lambda.data();
  double* newt = ws.t.data();
  double* neww = ws.w.data();
  double* newl = ws.lambda.data();
  // Per join i: sqrt of the two (unweighted) curvature numerators of eq. 10; the weights are
  // divided out once the new w of both neighbouring pieces is known.
  double a0 = 0, b0 = 0;
  auto set_lambda = [&](std::size_t i, double a, double b) {
    a /= neww[i == 0 ? n - 1 : i - 1];
    b /= neww[i];
    if (a + b > 0 && std::isfinite(a + b))
      newl[i] = std::min(std::max(a / (a + b), pass_lambda_margin), 1 - pass_lambda_margin);
    else newl[i] = lam[i];
  };
  for (std::size_t i = 0; i < n; ++i) {
    const bool start = pb.has_start(i), end = pb.has_end(i);
    const std::size_t im = i == 0 ? n - 1 : i - 1, ip = i + 1 == n ? 0 : i + 1;
    // X1 = P_{i-1}, X2 = P_i, X3 = P_{i+1} relative to Q_i.
    double X1[2] = {0, 0}, X3[2] = {0, 0};
    const double X2[2] = {dx[i], dy[i]};
    if (start) { X1[0] = dx[im] + (qx[im] - qx[i]); X1[1] = dy[im] + (qy[im] - qy[i]); }
    if (end) { X3[0] = dx[ip] + (qx[ip] - qx[i]); X3[1] = dy[ip] + (qy[ip] - qy[i]); }
    // Piece i: end points (eq. 9), weight (eq. 16), t (eq. 7).
    double E0[2], E2[2];
    if (start) {
      for (int c = 0; c < 2; ++c) E0[c] = (1.0 - lam[i]) * X1[c] + lam[i] * X2[c];
    } else {
      E0[0] = pb.sx - qx[i]; E0[1] = pb.sy - qy[i];
    }
    if (end) {
      for (int c = 0; c < 2; ++c) E2[c] = (1.0 - lam[ip]) * X2[c] + lam[ip] * X3[c];
    } else {
      E2[0] = pb.ex - qx[i]; E2[1] = pb.ey - qy[i];
    }
    double w = 1.0;
    if (pb.mode == Kappa_weights::FIXED) w = pb.weight[i];
    else if (pb.mode == Kappa_weights::AUTOMATIC) w = automatic_weight<double>(E0, X2, E2, pb.tension[i], pb.clamp);
    neww[i] = w;
    const double A = E0[0] * E0[0] + E0[1] * E0[1];
    const double B = E0[0] * E2[0] + E0[1] * E2[1];
    const double C = E2[0] * E2[0] + E2[1] * E2[1];
    newt[i] = std::min(std::max(eq7_root(A, B, C, w, st.t[i]), pass_t_margin), 1 - pass_t_margin);
    // Join i (between pieces i-1 and i), eq. 10: |kappa_{i-1}(1)| = |kappa_i(0)| <=>
    // fac1 |cr1| / (w_{i-1}^2 l^2) = fac2 |cr2| / (w_i^2 (1-l)^2), solved for l.
    if (!start) { newl[i] = lam[i]; continue; }
    double Ap[2], An[2], fac1 = 1, fac2 = 1;
    if (pb.has_start(im)) {
      const std::size_t imm = im == 0 ? n - 1 : im - 1;
      fac1 = 1 - lam[im];
      Ap[0] = dx[imm] + (qx[imm] - qx[i]);
      Ap[1] = dy[imm] + (qy[imm] - qy[i]);
    } else {
      Ap[0] = pb.sx - qx[i]; Ap[1] = pb.sy - qy[i];
    }
    if (end) { fac2 = lam[ip]; An[0] = X3[0]; An[1] = X3[1]; }
    else { An[0] = pb.ex - qx[i]; An[1] = pb.ey - qy[i]; }
    const double cr1 = (Ap[0] - X1[0]) * (X2[1] - X1[1]) - (Ap[1] - X1[1]) * (X2[0] - X1[0]);
    const double cr2 = (X1[0] - X2[0]) * (An[1] - X2[1]) - (X1[1] - X2[1]) * (An[0] - X2[0]);
    const double a = std::sqrt(fac1 * std::abs(cr1)), b = std::sqrt(fac2 * std::abs(cr2));
    if (i == 0) { a0 = a; b0 = b; }  // closed curve: needs the new w_{n-1}
    else set_lambda(i, a, b);
  }
  if (pb.closed) set_lambda(0, a0, b0);
  std::copy(newt, newt + n, st.t.begin());
  std::copy(neww, neww + n, st.w.begin());
  std::copy(newl, newl + n, st.lambda.begin());
  solve_eq18(pb, st, ws);  // on failure st keeps its P (with the new lambda, t, w)
}

/// As above with a temporary workspace.
inline void refinement_pass(const Problem& pb, Kappa_solver_state& st) {
  Refinement_workspace ws;
  refinement_pass(pb, st, ws);
}

/// Initial guess of Algorithm 1 (lines 2-5): lambda = t = 1/2, w = 1 (or the fixed weights).
inline void initial_guess(const Problem& pb, Kappa_solver_state& st, Refinement_workspace& ws) {
  st.resize(pb.n);
  if (pb.mode == Kappa_weights::FIXED) st.w = pb.weight;
  solve_eq18(pb, st, ws);
}

inline void initial_guess(const Problem& pb, Kappa_solver_state& st) {
  Refinement_workspace ws;
  initial_guess(pb, st, ws);
}

/// Alternating passes (Sec. 5.1) until `max_passes` or max |r| <= stop; returns max |r|.
inline double refine(const Problem& pb, Kappa_solver_state& st, std::size_t max_passes, double stop, Kappa_curve_report& res) {
  std::vector<double> F;
  Refinement_workspace ws;
  double fmax = evaluate(pb, st, F);
  for (std::size_t p = 0; p < max_passes && !(fmax <= stop); ++p) {
    refinement_pass(pb, st, ws);
    ++res.refinement_passes;
    fmax = evaluate(pb, st, F);
  }
  return fmax;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_REFINEMENT_H
