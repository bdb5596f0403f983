// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The double-precision solver behind fair::Kappa_curve_2: rational kappa-curves of
// Yan, Schiller, Schaefer, "Circle reproduction with interpolatory curves at local maximal
// curvature points" (equation numbers refer to that paper; weights w = 1 give the polynomial
// kappa-curves of Yan et al. 2017).
//
// Unknowns, per interpolated point i (one "block" of four): the middle control point
// P_i = P_{i,1} (stored as the offset d_i = P_i - Q_i), the join parameter lambda_i of eq. 9
// (P_{i,0} = P_{i-1,2} = (1-lambda_i) P_{i-1} + lambda_i P_i) and the parameter t_i with
// c_i(t_i) = Q_i. The weight w_i is not an unknown: it is 1, a user value, or the clamped
// minimum-eccentricity weight of eq. 16 written as a function of (P, lambda) -- substituted,
// so that E_w of eq. 13 is identically zero.
//
// Equations, per block (a square system, 4n x 4n):
//   r_0, r_1  (c_i(t_i) - Q_i)  = eq. 8/18 divided by its positive denominator
//             (1-t)^2 + 2(1-t)t w + t^2, i.e. the interpolation error as a distance;
//   r_2       eq. 7 divided by A_i + C_i (Q_i is a critical point of curvature);
//   r_3       (k1 - k2) / (k1 + k2), the relative mismatch of |kappa| at the join i between
//             pieces i-1 and i, with k1 = |kappa_{i-1}(1)|, k2 = |kappa_i(0)| from eq. 5
//             (both multiplied by |P_i - P_{i-1}|^3, eq. 10). For an open curve block 0 has no
//             join and r_3 = lambda_0 - 1/2 pins an unused variable.
// The paper's energy (eq. 17/19) is a sum of squares of these same conditions (differently
// normalised); its minimum value zero is reached exactly at a root of this system, so the
// solver minimises 1/2 |r|^2 by Levenberg-Marquardt (Nielsen's damping update, Marquardt's
// diagonal scaling) and stops when max |r| <= tolerance.
//
// Cost per iteration is O(n): every residual depends on the unknowns of blocks i-2..i+1
// only, so J^T J is a band matrix (half bandwidth 15 for open curves; closed curves use the
// zig-zag block order of kappa_banded.h, half bandwidth 31) factored by banded Cholesky.
// The Jacobian is exact (forward-mode automatic differentiation, kappa_dual.h).
// Bounds 0 < lambda_i, t_i < 1 are kept by projection onto [1e-9, 1 - 1e-9].
//
// Initial guess (Section 5.1 / Algorithm 1): lambda = t = 1/2, w = 1, eq. 18 solved for P
// (a (cyclic) tridiagonal, strictly diagonally dominant system), then alternating passes:
// w from eq. 16, t from the unique root of eq. 7 in (0,1) (Appendix A), lambda from eq. 10,
// P from eq. 18.
//
// Accuracy: residuals are evaluated in coordinates local to each Q_i, so that the |kappa|
// mismatch of dense points (control polygon areas ~ h^3) keeps a relative accuracy of about
// 1e-16 / (h kappa). Degenerate cases: a join whose two neighbouring control polygons are both
// straight (|kappa| = 0 on both sides) gives r_3 = 0 with a zero gradient; the damping of
// Levenberg-Marquardt keeps lambda there. Non-convergence within the iteration cap is
// reported (Solve_result::converged == false); the caller decides whether to throw.

#ifndef FAIR_INTERNAL_KAPPA_SOLVER_H
#define FAIR_INTERNAL_KAPPA_SOLVER_H

#include <fair/internal/kappa_banded.h>
#include <fair/internal/kappa_dual.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

enum class Weight_mode { unit, fixed, automatic };

/// The (normalised) data of one solve. Block i interpolates (qx[i], qy[i]).
struct Problem {
  bool closed = false;
  std::size_t n = 0;
  std::vector<double> qx, qy;
  double sx = 0, sy = 0, ex = 0, ey = 0;  // open curves: the fixed end points Q_0, Q_{m-1}
  Weight_mode mode = Weight_mode::unit;
  std::vector<double> weight;   // mode fixed: w_i
  std::vector<double> tension;  // mode automatic: mu_i of eq. 16
  double clamp = 0.5;           // mode automatic: lower clamp of eq. 16

  bool has_start(std::size_t j) const { return closed || j >= 1; }
  bool has_end(std::size_t j) const { return closed || j + 1 < n; }
};

/// Unknowns: d_i = P_i - Q_i, lambda_i, t_i; w_i as last computed.
struct State {
  std::vector<double> dx, dy, lambda, t, w;
  void resize(std::size_t n) {
    dx.assign(n, 0.0); dy.assign(n, 0.0); lambda.assign(n, 0.5); t.assign(n, 0.5); w.assign(n, 1.0);
  }
};

struct Solve_settings {
  std::size_t refinement_passes = 60;  // alternating passes of Section 5.1 (paper: 60)
  std::size_t max_iterations = 200;    // Levenberg-Marquardt iterations
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

struct Solve_result {
  std::size_t refinement_passes = 0;
  std::size_t iterations = 0;
  bool converged = false;
  double residual = 0;               // max |r| over all equations
  double interpolation_residual = 0; // max |c_i(t_i) - Q_i| (normalised coordinates)
  double curvature_residual = 0;     // max |eq. 7| / (A_i + C_i)
  double g2_residual = 0;            // max relative |kappa| mismatch at joins
  double weight_residual = 0;        // max |w_i - w~_i| (automatic weights)
  double energy_interpolation = 0, energy_curvature = 0, energy_g2 = 0, energy_weight = 0;
  std::size_t bounds_active = 0;     // t_i or lambda_i within 1e-4 of 0 or 1
};

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

// ----------------------------------------------------------------------------- residuals

template <class S>
struct Window {
  S X[4][2];  // P of blocks i-2..i+1 relative to Q_i
  S lam[4];
  S t[4];
  std::size_t block[4];
  bool valid[4];
};

template <class S>
struct Piece_values {
  S E0[2], E2[2];  // end points relative to Q_i
  S w = S(1.0);
};

/// Seeds slot 4k+c of the window with the unknown c of block i-2+k when `Dual`.
template <class S> inline S make_var(double v, int) { return S(v); }
template <> inline Dual<16> make_var<Dual<16>>(double v, int slot) { return Dual<16>::variable(v, slot); }

template <class S>
void build_window(const Problem& pb, const State& st, std::size_t i, Window<S>& win) {
  const long n = static_cast<long>(pb.n);
  for (int k = 0; k < 4; ++k) {
    long b = static_cast<long>(i) - 2 + k;
    if (pb.closed) b = ((b % n) + n) % n;
    win.valid[k] = pb.closed || (b >= 0 && b < n);
    if (!win.valid[k]) { win.block[k] = 0; continue; }
    const std::size_t bb = static_cast<std::size_t>(b);
    win.block[k] = bb;
    win.X[k][0] = make_var<S>(st.dx[bb], 4 * k + 0) + (pb.qx[bb] - pb.qx[i]);
    win.X[k][1] = make_var<S>(st.dy[bb], 4 * k + 1) + (pb.qy[bb] - pb.qy[i]);
    win.lam[k] = make_var<S>(st.lambda[bb], 4 * k + 2);
    win.t[k] = make_var<S>(st.t[bb], 4 * k + 3);
  }
}

/// The clamped minimum-eccentricity weight of eqs. 15-16 for control points E0, P, E2.
template <class S>
S automatic_weight(const S* E0, const S* P, const S* E2, double mu, double clamp) {
  const S ax = E2[0] - E0[0], ay = E2[1] - E0[1];
  const S bx = E0[0] - P[0], by = E0[1] - P[1];
  const S cx = E2[0] - P[0], cy = E2[1] - P[1];
  const S den = 2.0 * (bx * bx + by * by + cx * cx + cy * cy);
  if (!(value(den) > 0.0)) return S(clamp > 0 ? std::max(clamp, 1.0) : 1.0);
  const S what = sqrt((ax * ax + ay * ay) / den);  // eq. 15
  return max_with(mu * what, clamp);                  // eq. 16
}

/// End points and weight of piece j = i - 2 + k (k = 1 or 2) in the window of block i.
template <class S>
void piece_values(const Problem& pb, const State& st, std::size_t i, const Window<S>& win, int k,
                  Piece_values<S>& pv) {
  const std::size_t j = win.block[k];
  if (pb.has_start(j)) {
    for (int c = 0; c < 2; ++c) pv.E0[c] = (1.0 - win.lam[k]) * win.X[k - 1][c] + win.lam[k] * win.X[k][c];
  } else {
    pv.E0[0] = S(pb.sx - pb.qx[i]); pv.E0[1] = S(pb.sy - pb.qy[i]);
  }
  if (pb.has_end(j)) {
    for (int c = 0; c < 2; ++c) pv.E2[c] = (1.0 - win.lam[k + 1]) * win.X[k][c] + win.lam[k + 1] * win.X[k + 1][c];
  } else {
    pv.E2[0] = S(pb.ex - pb.qx[i]); pv.E2[1] = S(pb.ey - pb.qy[i]);
  }
  switch (pb.mode) {
    case Weight_mode::unit: pv.w = S(1.0); break;
    case Weight_mode::fixed: pv.w = S(pb.weight[j]); break;
    case Weight_mode::automatic:
      pv.w = automatic_weight(pv.E0, win.X[k], pv.E2, pb.tension[j], pb.clamp);
      break;
  }
  (void)st;
}

/// The four residuals of block i (see the file comment). If `w_out` is given it receives w_i.
template <class S>
void block_residuals(const Problem& pb, const State& st, std::size_t i, const Window<S>& win, S r[4],
                     double* w_out = nullptr) {
  Piece_values<S> pc;
  piece_values(pb, st, i, win, 2, pc);
  if (w_out) *w_out = value(pc.w);
  const S& t = win.t[2];
  const S u = 1.0 - t;
  const S b0 = u * u, b1 = 2.0 * u * t * pc.w, b2 = t * t;
  const S den = b0 + b1 + b2;
  // eq. 8 (with eq. 9 substituted: eq. 18), Q_i is the local origin.
  r[0] = (b0 * pc.E0[0] + b1 * win.X[2][0] + b2 * pc.E2[0]) / den;
  r[1] = (b0 * pc.E0[1] + b1 * win.X[2][1] + b2 * pc.E2[1]) / den;
  // eq. 7
  const S A = pc.E0[0] * pc.E0[0] + pc.E0[1] * pc.E0[1];
  const S B = pc.E0[0] * pc.E2[0] + pc.E0[1] * pc.E2[1];
  const S C = pc.E2[0] * pc.E2[0] + pc.E2[1] * pc.E2[1];
  const S f = -pc.w * A * (u * u * u * u) - (A + B) * (u * u * u * t) + (B + C) * (u * t * t * t) +
              pc.w * C * (t * t * t * t);
  const S AC = A + C;
  r[2] = value(AC) > 0.0 ? f / AC : S(0.0);
  // |kappa| continuity at the join between pieces i-1 and i (eqs. 5, 10).
  if (pb.has_start(i)) {
    Piece_values<S> pp;
    piece_values(pb, st, i, win, 1, pp);
    const std::size_t jm = win.block[1];
    S fac1(1.0), Apx, Apy;
    if (pb.has_start(jm)) { fac1 = 1.0 - win.lam[1]; Apx = win.X[0][0]; Apy = win.X[0][1]; }
    else { Apx = S(pb.sx - pb.qx[i]); Apy = S(pb.sy - pb.qy[i]); }
    S fac2(1.0), Anx, Any;
    if (pb.has_end(i)) { fac2 = win.lam[3]; Anx = win.X[3][0]; Any = win.X[3][1]; }
    else { Anx = S(pb.ex - pb.qx[i]); Any = S(pb.ey - pb.qy[i]); }
    const S* X1 = win.X[1];
    const S* X2 = win.X[2];
    const S cr1 = (Apx - X1[0]) * (X2[1] - X1[1]) - (Apy - X1[1]) * (X2[0] - X1[0]);
    const S cr2 = (X1[0] - X2[0]) * (Any - X2[1]) - (X1[1] - X2[1]) * (Anx - X2[0]);
    const S& lam = win.lam[2];
    const S k1 = fac1 * abs(cr1) / (pp.w * pp.w * lam * lam);
    const S k2 = fac2 * abs(cr2) / (pc.w * pc.w * (1.0 - lam) * (1.0 - lam));
    const S sum = k1 + k2;
    r[3] = value(sum) > 0.0 ? (k1 - k2) / sum : S(0.0);
  } else {
    r[3] = win.lam[2] - 0.5;
  }
}

/// All residuals in double; returns max |r| and fills the per-kind maxima/energies.
inline double evaluate(const Problem& pb, const State& st, std::vector<double>& F, Solve_result* res = nullptr,
                       std::vector<double>* weights = nullptr) {
  F.resize(4 * pb.n);
  double mx = 0;
  if (res) {
    res->interpolation_residual = res->curvature_residual = res->g2_residual = 0;
    res->energy_interpolation = res->energy_curvature = res->energy_g2 = 0;
  }
  Window<double> win;
  for (std::size_t i = 0; i < pb.n; ++i) {
    build_window(pb, st, i, win);
    double r[4], w = 1;
    block_residuals(pb, st, i, win, r, &w);
    if (weights) (*weights)[i] = w;
    for (int c = 0; c < 4; ++c) {
      F[4 * i + c] = r[c];
      const double a = std::abs(r[c]);
      mx = (a > mx || std::isnan(a)) ? a : mx;
    }
    if (res) {
      const double ip = std::hypot(r[0], r[1]);
      res->interpolation_residual = std::max(res->interpolation_residual, ip);
      res->curvature_residual = std::max(res->curvature_residual, std::abs(r[2]));
      res->energy_interpolation += r[0] * r[0] + r[1] * r[1];
      res->energy_curvature += r[2] * r[2];
      if (pb.has_start(i)) {
        res->g2_residual = std::max(res->g2_residual, std::abs(r[3]));
        res->energy_g2 += r[3] * r[3];
      }
    }
  }
  return mx;
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

/// Solves the kappa-curve system; `st` holds the initial state when settings.warm.
/// Levenberg-Marquardt from `st`; returns the final max |r|. Counts iterations in res.
inline double levenberg_marquardt(const Problem& pb, State& st, const Solve_settings& settings, Solve_result& res,
                                  std::size_t max_iterations, const Block_range& range = {}) {
  const std::size_t n = pb.n;
  project_bounds(st);
  const std::size_t na = range.all ? n : range.count, N = 4 * na;
  // Block of the ii-th active unknown block and its position in the band order.
  auto block = [&](std::size_t ii) { return range.all ? ii : (range.first + ii) % n; };
  auto pos = [&](std::size_t ii) { return range.all ? (pb.closed ? cyclic_position(ii, n) : ii) : ii; };
  // A contiguous range (count <= n - 3 for closed curves) in natural order couples blocks at
  // distance <= 3 only: half bandwidth 15.
  const std::size_t h = range.all ? normal_bandwidth(pb) : std::min<std::size_t>(15, N - 1);
  auto evaluate_active = [&](const State& s, std::vector<double>& Fa) {
    if (range.all) return evaluate(pb, s, Fa);
    Fa.resize(N);
    Window<double> win;
    double mx = 0;
    for (std::size_t ii = 0; ii < na; ++ii) {
      build_window(pb, s, block(ii), win);
      double r[4];
      block_residuals(pb, s, block(ii), win, r);
      for (int c = 0; c < 4; ++c) {
        Fa[4 * ii + c] = r[c];
        const double a = std::abs(r[c]);
        mx = (a > mx || std::isnan(a)) ? a : mx;
      }
    }
    return mx;
  };

  std::vector<double> F, Ftrial, g(N), D(N), delta(N), Abase;
  double fmax = evaluate_active(st, F);
  auto cost_of = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return 0.5 * s;
  };
  double cost = cost_of(F);
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
      trial = st;
      for (std::size_t ii = 0; ii < na; ++ii) {
        const std::size_t i = block(ii), p = 4 * pos(ii);
        trial.dx[i] += delta[p];
        trial.dy[i] += delta[p + 1];
        trial.lambda[i] += delta[p + 2];
        trial.t[i] += delta[p + 3];
      }
      project_bounds(trial);
      const double fm = evaluate_active(trial, Ftrial);
      const double ct = cost_of(Ftrial);
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

/// Solves the kappa-curve system; `st` holds the initial state when settings.warm.
/// Strategy: initial guess and up to `refinement_passes` alternating passes (stopping early
/// once max |r| <= 1e-3), Levenberg-Marquardt; if that stalls away from a root, one restart:
/// up to 4 x `refinement_passes` more passes from the best state, then Levenberg-Marquardt again.
inline Solve_result solve(const Problem& pb, State& st, const Solve_settings& settings) {
  Solve_result res;
  const std::size_t n = pb.n;
  if (!settings.warm || st.t.size() != n) {
    initial_guess(pb, st);
    refine(pb, st, settings.refinement_passes, 1e-3, res);
  }
  double fmax = std::numeric_limits<double>::infinity();
  bool local_done = false;
  if (settings.warm && st.t.size() == n && settings.moved < n) {
    // Local warm start: the change of one Q_i perturbs the solution by amounts that decay
    // geometrically along the curve, so first solve only for the blocks within distance R of
    // the moved one (the others held fixed; a square 4(2R+1) system, O(R) per iteration) and
    // accept the result iff the residual of the WHOLE system is within the tolerance; R = 8,
    // 32, then the global solve. The accepted state is a root of the full system to the same
    // tolerance as a global solve.
    std::vector<double> F;
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
      Solve_result sub;
      levenberg_marquardt(pb, trial, settings, sub, settings.max_iterations, range);
      res.iterations += sub.iterations;
      const double fm = evaluate(pb, trial, F);
      if (fm <= settings.tolerance) { st = trial; fmax = fm; local_done = true; }
    }
  }
  if (!local_done) fmax = levenberg_marquardt(pb, st, settings, res, settings.max_iterations);
  if (!(fmax <= settings.tolerance) && res.iterations < settings.max_iterations && settings.refinement_passes > 0) {
    State best = st;
    refine(pb, st, 4 * settings.refinement_passes, 1e-7, res);
    const double f2 = levenberg_marquardt(pb, st, settings, res, settings.max_iterations - res.iterations);
    if (!(f2 < fmax)) st = best; else fmax = f2;
  }
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
    frozen.mode = Weight_mode::fixed;
    frozen.weight = st.w;
    res.residual = evaluate(frozen, st, F, &res);
    if (pb.mode == Weight_mode::automatic) {
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
  // A "root" with some t_i or lambda_i on its bound is degenerate (Q_i at a join: its piece
  // has no interior curvature extremum there); it is never reported as converged.
  for (std::size_t i = 0; i < n; ++i) {
    const double b = 1e-4;
    if (st.t[i] < b || st.t[i] > 1 - b) ++res.bounds_active;
    if (pb.has_start(i) && (st.lambda[i] < b || st.lambda[i] > 1 - b)) ++res.bounds_active;
  }
  res.converged = res.residual <= settings.tolerance && res.bounds_active == 0;
  return res;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_SOLVER_H
