// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The Jacobian of the kappa-curve system (system.h), block row by block row: the four
// residuals of block i and their derivatives with respect to the 16 unknowns of the blocks
// i-2, i-1, i, i+1 (window slot k = block i-2+k, unknown c = x, y, lambda, t at column 4k+c).
//
// Accuracy: exact to rounding. The values come from the templates that evaluate the residuals
// (system.h); the derivatives of the piece residuals and of r_3 are written out by hand, those
// of the automatic weight of eq. 16 by forward-mode automatic differentiation (common/dual.h). All are
// checked against a differentiation over all 16 unknowns in test_kappa_solver.cpp.
// Degenerate cases: abs() and the clamp of eq. 16 contribute the derivative of the active
// branch; residuals defined as 0 at a degenerate configuration (system.h) have a zero
// gradient there.

#ifndef FAIR_INTERNAL_KAPPA_JACOBIAN_H
#define FAIR_INTERNAL_KAPPA_JACOBIAN_H

#include <fair/internal/kappa/system.h>

#include <cmath>
#include <cstddef>

namespace fair {
namespace internal {
namespace kappa {

/// Scratch space of block_jacobian.
struct Jacobian_workspace {
  Window<double> values;
};

/// Adds to the Jacobian row J the gradient g = d(.)/d(E0, P, E2) of a quantity of the piece of
/// window block k (P = X[k]), through eq. 9: E0 = (1 - lambda_k) X[k-1] + lambda_k X[k] (when
/// the piece has a start join) and E2 = (1 - lambda_{k+1}) X[k] + lambda_{k+1} X[k+1] (when it
/// has an end join); fixed end points of open curves are constants.
inline void add_piece_gradient(const Window<double>& win, int k, bool start, bool end, const double* g, double* J) {
  const double lam = win.lam[k];
  for (int c = 0; c < 2; ++c) {
    J[4 * k + c] += g[2 + c];
    if (start) {
      J[4 * (k - 1) + c] += (1.0 - lam) * g[c];
      J[4 * k + c] += lam * g[c];
      J[4 * k + 2] += (win.X[k][c] - win.X[k - 1][c]) * g[c];
    }
    if (end) {
      const double lam_next = win.lam[k + 1];
      J[4 * k + c] += (1.0 - lam_next) * g[4 + c];
      J[4 * (k + 1) + c] += lam_next * g[4 + c];
      J[4 * (k + 1) + 2] += (win.X[k + 1][c] - win.X[k][c]) * g[4 + c];
    }
  }
}

/// Weight of the piece of window block k and its gradient with respect to (E0, P, E2)
/// (zero unless the weights are automatic).
inline double piece_weight_gradient(const Problem& pb, const Kappa_solver_state& st, std::size_t i, const Window<double>& win,
                                    int k, double g[6]) {
  for (int c = 0; c < 6; ++c) g[c] = 0.0;
  if (pb.mode != Kappa_weights::AUTOMATIC) return window_piece_weight(pb, st, i, win, k);
  Piece_values<double> pv;
  piece_values(pb, st, i, win, k, pv);
  typedef Dual<6> D6;
  D6 E0[2], X[2], E2[2];
  for (int c = 0; c < 2; ++c) {
    E0[c] = D6::variable(c, pv.E0[c]);
    X[c] = D6::variable(2 + c, win.X[k][c]);
    E2[c] = D6::variable(4 + c, pv.E2[c]);
  }
  const D6 w = piece_weight(pb, win.block[k], E0, X, E2);
  for (int c = 0; c < 6; ++c) g[c] = w.g[c];
  return w.v;
}

/// r_0..r_2 of a piece (piece_residuals, system.h, which gives the values) and their
/// derivatives by hand: g[e][0..5] with respect to (E0, P, E2), g[e][6] to t, gw[e] to w.
/// With u = 1 - t, b = (u^2, 2utw, t^2), D = b0 + b1 + b2 and N = b0 E0 + b1 P + b2 E2:
///   r_c = N_c / D:  dr_c/dE0_c = b0/D, dr_c/dP_c = b1/D, dr_c/dE2_c = b2/D,
///                   dr_c/dt = (N_c' - r_c D') / D,  dr_c/dw = 2ut (P_c - r_c) / D;
///   r_2 = f / (A + C) with f of eq. 7 in A = E0.E0, B = E0.E2, C = E2.E2 (P does not enter):
///     df/dA = -w u^4 - u^3 t, df/dB = u t^3 - u^3 t, df/dC = u t^3 + w t^4,
///     df/dt = 4wA u^3 - (A+B)(u^3 - 3u^2 t) + (B+C)(3u t^2 - t^3) + 4wC t^3, df/dw = C t^4 - A u^4,
///   and d(A + C) = 2 E0.dE0 + 2 E2.dE2.
/// (Forward-mode differentiation of the same expressions cost 25 % of a random-star solve.)
inline void piece_residual_gradients(const double* E0, const double* X, const double* E2, double t, double w,
                                     double r[3], double g[3][7], double gw[3]) {
  piece_residuals(E0, X, E2, t, w, r);
  for (int e = 0; e < 3; ++e) {
    for (int c = 0; c < 7; ++c) g[e][c] = 0.0;
    gw[e] = 0.0;
  }
  const double u = 1.0 - t;
  const double b0 = u * u, b1 = 2.0 * u * t * w, b2 = t * t, den = b0 + b1 + b2;
  const double db0 = -2.0 * u, db1 = 2.0 * w * (u - t), db2 = 2.0 * t, dden = db0 + db1 + db2;
  for (int c = 0; c < 2; ++c) {
    g[c][c] = b0 / den;
    g[c][2 + c] = b1 / den;
    g[c][4 + c] = b2 / den;
    g[c][6] = (db0 * E0[c] + db1 * X[c] + db2 * E2[c] - r[c] * dden) / den;
    gw[c] = 2.0 * u * t * (X[c] - r[c]) / den;
  }
  const double A = E0[0] * E0[0] + E0[1] * E0[1];
  const double B = E0[0] * E2[0] + E0[1] * E2[1];
  const double C = E2[0] * E2[0] + E2[1] * E2[1];
  const double AC = A + C;
  if (!(AC > 0.0)) return;  // r_2 is defined as 0 there, with a zero gradient
  const double u2 = u * u, u3 = u2 * u, u4 = u3 * u, t2 = t * t, t3 = t2 * t, t4 = t3 * t;
  const double fA = -w * u4 - u3 * t, fB = u * t3 - u3 * t, fC = u * t3 + w * t4;
  for (int c = 0; c < 2; ++c) {
    g[2][c] = (2.0 * (fA - r[2]) * E0[c] + fB * E2[c]) / AC;
    g[2][4 + c] = (fB * E0[c] + 2.0 * (fC - r[2]) * E2[c]) / AC;
  }
  g[2][6] = (4.0 * w * A * u3 - (A + B) * (u3 - 3.0 * u2 * t) + (B + C) * (3.0 * u * t2 - t3) + 4.0 * w * C * t3) / AC;
  gw[2] = (C * t4 - A * u4) / AC;
}

/// Residuals r[e] of block i and J[e][4k+c] = d r[e] / d (unknown c of block i-2+k); columns
/// of blocks that do not exist (open curves) are zero.
///  - r_0..r_2 depend on the unknowns only through the piece's control points E0, P_i, E2 and
///    t_i (and the weight, a function of those): automatic differentiation in these 7
///    directions, then the chain rule through eq. 9 (add_piece_gradient);
///  - r_3 = (k1 - k2) / (k1 + k2) (system.h, join_residual) is differentiated by hand:
///    dr_3 = 2 (k2 dk1 - k1 dk2) / (k1 + k2)^2 with k1 = fac1 |cr1| / (w_{i-1}^2 lambda_i^2),
///    k2 = fac2 |cr2| / (w_i^2 (1 - lambda_i)^2), cr1, cr2 the cross products of eq. 10.
inline void block_jacobian(const Problem& pb, const Kappa_solver_state& st, std::size_t i, Jacobian_workspace& ws, double r[4],
                           double J[4][16]) {
  for (int e = 0; e < 4; ++e)
    for (int c = 0; c < 16; ++c) J[e][c] = 0.0;
  Window<double>& win = ws.values;
  build_window(pb, st, i, win);
  Piece_values<double> pv;
  piece_values(pb, st, i, win, 2, pv);
  const bool start = pb.has_start(i), end = pb.has_end(i);
  // r_0..r_2 over (E0, P_i, E2, t_i), the weight's dependence on (E0, P_i, E2) by the chain rule.
  double gwc[6];
  const double wc = piece_weight_gradient(pb, st, i, win, 2, gwc);
  double g[3][7], dr_dw[3];
  piece_residual_gradients(pv.E0, win.X[2], pv.E2, win.t[2], wc, r, g, dr_dw);
  for (int e = 0; e < 3; ++e) {
    for (int c = 0; c < 6; ++c) g[e][c] += dr_dw[e] * gwc[c];
    add_piece_gradient(win, 2, start, end, g[e], J[e]);
    J[e][11] = g[e][6];
  }
  if (!start) {
    r[3] = win.lam[2] - 0.5;
    J[3][10] = 1.0;
    return;
  }
  // r_3: value as join_residual computes it, gradient by hand.
  r[3] = join_residual(pb, st, i, win, wc);
  const std::size_t jm = win.block[1];
  const bool prev_start = pb.has_start(jm);
  double gwp[6];
  const double wp = piece_weight_gradient(pb, st, i, win, 1, gwp);
  const double* X1 = win.X[1];
  const double* X2 = win.X[2];
  double Ap[2], An[2], fac1 = 1.0, fac2 = 1.0;
  if (prev_start) { fac1 = 1.0 - win.lam[1]; Ap[0] = win.X[0][0]; Ap[1] = win.X[0][1]; }
  else { Ap[0] = pb.sx - pb.qx[i]; Ap[1] = pb.sy - pb.qy[i]; }
  if (end) { fac2 = win.lam[3]; An[0] = win.X[3][0]; An[1] = win.X[3][1]; }
  else { An[0] = pb.ex - pb.qx[i]; An[1] = pb.ey - pb.qy[i]; }
  const double u1[2] = {Ap[0] - X1[0], Ap[1] - X1[1]}, v1[2] = {X2[0] - X1[0], X2[1] - X1[1]};
  const double u2[2] = {X1[0] - X2[0], X1[1] - X2[1]}, v2[2] = {An[0] - X2[0], An[1] - X2[1]};
  const double cr1 = u1[0] * v1[1] - u1[1] * v1[0];
  const double cr2 = u2[0] * v2[1] - u2[1] * v2[0];
  const double lam = win.lam[2];
  const double s1 = 1.0 / (wp * wp * lam * lam), s2 = 1.0 / (wc * wc * (1.0 - lam) * (1.0 - lam));
  const double k1 = fac1 * std::abs(cr1) * s1, k2 = fac2 * std::abs(cr2) * s2;
  const double sum = k1 + k2;
  if (!(sum > 0.0)) return;  // r_3 is defined as 0 there, with a zero gradient
  double dk1[16] = {}, dk2[16] = {};
  // d|cr1|: cr1 = u1 x v1 with u1 = Ap - X1, v1 = X2 - X1 (abs: derivative of the active branch).
  const double c1 = fac1 * (cr1 < 0 ? -1.0 : 1.0) * s1;
  const double gAp[2] = {v1[1], -v1[0]}, gX2[2] = {-u1[1], u1[0]};
  for (int c = 0; c < 2; ++c) {
    if (prev_start) dk1[c] += c1 * gAp[c];
    dk1[4 + c] -= c1 * (gAp[c] + gX2[c]);
    dk1[8 + c] += c1 * gX2[c];
  }
  if (prev_start) dk1[6] -= std::abs(cr1) * s1;          // fac1 = 1 - lambda_{i-1}
  dk1[10] -= 2.0 * k1 / lam;                              // lambda_i^-2
  double gw[16] = {};
  add_piece_gradient(win, 1, prev_start, true, gwp, gw);  // w_{i-1}^-2
  for (int c = 0; c < 16; ++c) dk1[c] -= 2.0 * k1 / wp * gw[c];
  // d|cr2|: cr2 = u2 x v2 with u2 = X1 - X2, v2 = An - X2.
  const double c2 = fac2 * (cr2 < 0 ? -1.0 : 1.0) * s2;
  const double gX1[2] = {v2[1], -v2[0]}, gAn[2] = {-u2[1], u2[0]};
  for (int c = 0; c < 2; ++c) {
    dk2[4 + c] += c2 * gX1[c];
    dk2[8 + c] -= c2 * (gX1[c] + gAn[c]);
    if (end) dk2[12 + c] += c2 * gAn[c];
  }
  if (end) dk2[14] += std::abs(cr2) * s2;                 // fac2 = lambda_{i+1}
  dk2[10] += 2.0 * k2 / (1.0 - lam);                      // (1 - lambda_i)^-2
  if (pb.mode == Kappa_weights::AUTOMATIC) {
    for (int c = 0; c < 16; ++c) gw[c] = 0.0;
    add_piece_gradient(win, 2, start, end, gwc, gw);  // w_i^-2
    for (int c = 0; c < 16; ++c) dk2[c] -= 2.0 * k2 / wc * gw[c];
  }
  const double f = 2.0 / (sum * sum);
  for (int c = 0; c < 16; ++c) J[3][c] = f * (k2 * dk1[c] - k1 * dk2[c]);
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_JACOBIAN_H
