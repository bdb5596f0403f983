// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The square system behind fair::Kappa_curve_2 (rational kappa-curves of Yan, Schiller, Schaefer;
// equation numbers refer to that paper): the unknowns of one solve, and the four residuals of
// each block, evaluated in double (solver.h, refinement.h) or with derivatives
// (jacobian.h).
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
// Accuracy: residuals are evaluated in coordinates local to each Q_i, so that the |kappa|
// mismatch of dense points (control polygon areas ~ h^3 for spacing h) keeps a relative accuracy
// of roughly 1e-16 / (h kappa) (an estimate; measured rounding floor of max |r| on the closed
// benchmark stars of bench_kappa.cpp: 3.6e-15 at n = 10^3, 4.1e-14 at 10^4, 4.5e-13 at 10^5, i.e.
// proportional to 1/h). Degenerate cases: a join whose two neighbouring control polygons are both
// straight (|kappa| = 0 on both sides) gives r_3 = 0 with a zero gradient; the solvers keep
// lambda there (Newton's block LU reports the singular pivot; Levenberg-Marquardt's damping).

#ifndef FAIR_INTERNAL_KAPPA_SYSTEM_H
#define FAIR_INTERNAL_KAPPA_SYSTEM_H

#include <fair/Kappa_curve_options.h>
#include <fair/Kappa_curve_report.h>
#include <fair/internal/common/dual.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

// The residuals are templates on their scalar: double, or common::Dual for derivatives. The
// declarations let one unqualified call serve both (the Dual overloads are found by argument-
// dependent lookup).
using common::Dual;
using common::max_with;
using common::value;
using std::abs;
using std::sqrt;

/// The (normalised) data of one solve. Block i interpolates (qx[i], qy[i]).
struct Problem {
  bool closed = false;
  std::size_t n = 0;
  std::vector<double> qx, qy;
  double sx = 0, sy = 0, ex = 0, ey = 0;  // open curves: the fixed end points Q_0, Q_{m-1}
  Kappa_weights mode = Kappa_weights::UNIT;  // the public enum: the solver reads the option as given
  std::vector<double> weight;   // mode fixed: w_i
  std::vector<double> tension;  // mode automatic: mu_i of eq. 16
  double clamp = 0.5;           // mode automatic: lower clamp of eq. 16
  /// Mode automatic: the weight used is 1 + s (w_eq16 - 1) with s = weight_blend, the path of
  /// the continuation from w = 1 (weight_continuation.h); 1 (eq. 16 itself) except there.
  double weight_blend = 1.0;

  bool has_start(std::size_t j) const { return closed || j >= 1; }
  bool has_end(std::size_t j) const { return closed || j + 1 < n; }
  /// Index among the curve's input points of the point block j interpolates (an open curve's
  /// end points are input points 0 and n + 1).
  std::size_t point_index(std::size_t j) const { return closed ? j : j + 1; }
  /// The block of input point p (an open curve's end points belong to its end blocks), or
  /// no_block when p is not an input point.
  std::size_t block_of_point(std::size_t p) const {
    if (p >= (closed ? n : n + 2)) return no_block;
    return closed ? p : std::min(std::max<std::size_t>(p, 1) - 1, n - 1);
  }
  /// "No block": a warm start after an unknown change.
  static constexpr std::size_t no_block = static_cast<std::size_t>(-1);
};

// The unknowns of a solve are the public fair::Kappa_solver_state (d_i = P_i - Q_i, lambda_i,
// t_i; w_i as last computed) and its report the public fair::Kappa_curve_report, both filled
// here directly (residuals normalised as in the file comment).

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

/// Seed<S>::variable(v, slot): v as a constant (double) or as derivative direction `slot` of
/// a Dual number (the window unknown c of block k is slot 4k+c).
template <class S> struct Seed {
  static S variable(double v, int) { return S(v); }
};
template <int N, bool S> struct Seed<Dual<N, S>> {
  static Dual<N, S> variable(double v, int slot) { return Dual<N, S>::variable(slot, v); }
};

template <class S>
void build_window(const Problem& pb, const Kappa_solver_state& st, std::size_t i, Window<S>& win) {
  const long n = static_cast<long>(pb.n);
  for (int k = 0; k < 4; ++k) {
    long b = static_cast<long>(i) - 2 + k;
    if (pb.closed) {  // b is in [i - 2, i + 1]: no integer division in this hot loop
      while (b < 0) b += n;
      while (b >= n) b -= n;
    }
    win.valid[k] = pb.closed || (b >= 0 && b < n);
    if (!win.valid[k]) { win.block[k] = 0; continue; }
    const std::size_t bb = static_cast<std::size_t>(b);
    win.block[k] = bb;
    win.X[k][0] = Seed<S>::variable(st.dx[bb], 4 * k + 0) + (pb.qx[bb] - pb.qx[i]);
    win.X[k][1] = Seed<S>::variable(st.dy[bb], 4 * k + 1) + (pb.qy[bb] - pb.qy[i]);
    win.lam[k] = Seed<S>::variable(st.lambda[bb], 4 * k + 2);
    win.t[k] = Seed<S>::variable(st.t[bb], 4 * k + 3);
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

/// The weight of piece j with control points E0, P, E2: 1, the user's, or eq. 16.
template <class S>
S piece_weight(const Problem& pb, std::size_t j, const S* E0, const S* P, const S* E2) {
  switch (pb.mode) {
    case Kappa_weights::FIXED: return S(pb.weight[j]);
    case Kappa_weights::AUTOMATIC: {
      if (pb.weight_blend == 1.0) return automatic_weight(E0, P, E2, pb.tension[j], pb.clamp);
      return 1.0 + pb.weight_blend * (automatic_weight(E0, P, E2, pb.tension[j], pb.clamp) - 1.0);
    }
    case Kappa_weights::UNIT: break;
  }
  return S(1.0);
}

/// End points and weight of piece j = i - 2 + k (k = 1 or 2) in the window of block i.
template <class S>
void piece_values(const Problem& pb, const Kappa_solver_state& st, std::size_t i, const Window<S>& win, int k,
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
  pv.w = piece_weight(pb, j, pv.E0, win.X[k], pv.E2);
  (void)st;
}

/// The weight of piece j = i - 2 + k (k = 1 or 2) in the window of block i (its end points are
/// formed only when the weight depends on them).
template <class S>
S window_piece_weight(const Problem& pb, const Kappa_solver_state& st, std::size_t i, const Window<S>& win, int k) {
  if (pb.mode != Kappa_weights::AUTOMATIC) return piece_weight<S>(pb, win.block[k], nullptr, nullptr, nullptr);
  Piece_values<S> pv;
  piece_values(pb, st, i, win, k, pv);
  return pv.w;
}

/// Residuals r_0, r_1 (eq. 18 as a distance) and r_2 (eq. 7 over A + C) of a piece with
/// control points E0, X, E2 relative to the interpolated point, parameter t and weight w.
template <class S>
void piece_residuals(const S* E0, const S* X, const S* E2, const S& t, const S& w, S r[3]) {
  const S u = 1.0 - t;
  const S b0 = u * u, b1 = 2.0 * u * t * w, b2 = t * t;
  const S den = b0 + b1 + b2;
  // eq. 8 (with eq. 9 substituted: eq. 18), Q_i is the local origin.
  r[0] = (b0 * E0[0] + b1 * X[0] + b2 * E2[0]) / den;
  r[1] = (b0 * E0[1] + b1 * X[1] + b2 * E2[1]) / den;
  // eq. 7
  const S A = E0[0] * E0[0] + E0[1] * E0[1];
  const S B = E0[0] * E2[0] + E0[1] * E2[1];
  const S C = E2[0] * E2[0] + E2[1] * E2[1];
  const S f = -w * A * (u * u * u * u) - (A + B) * (u * u * u * t) + (B + C) * (u * t * t * t) + w * C * (t * t * t * t);
  const S AC = A + C;
  r[2] = value(AC) > 0.0 ? f / AC : S(0.0);
}

/// Residual r_3 of block i: |kappa| continuity at the join between pieces i-1 and i (eqs. 5,
/// 10), given the weight wc of piece i; lambda_0 - 1/2 for the first block of an open curve.
template <class S>
S join_residual(const Problem& pb, const Kappa_solver_state& st, std::size_t i, const Window<S>& win, const S& wc) {
  if (!pb.has_start(i)) return win.lam[2] - 0.5;
  const S wp = window_piece_weight(pb, st, i, win, 1);
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
  const S k1 = fac1 * abs(cr1) / (wp * wp * lam * lam);
  const S k2 = fac2 * abs(cr2) / (wc * wc * (1.0 - lam) * (1.0 - lam));
  const S sum = k1 + k2;
  return value(sum) > 0.0 ? (k1 - k2) / sum : S(0.0);
}

/// The four residuals of block i (see the file comment). If `w_out` is given it receives w_i.
template <class S>
void block_residuals(const Problem& pb, const Kappa_solver_state& st, std::size_t i, const Window<S>& win, S r[4],
                     double* w_out = nullptr) {
  Piece_values<S> pc;
  piece_values(pb, st, i, win, 2, pc);
  if (w_out) *w_out = value(pc.w);
  piece_residuals(pc.E0, win.X[2], pc.E2, win.t[2], pc.w, r);
  r[3] = join_residual(pb, st, i, win, pc.w);
}

/// All residuals in double; returns max |r| and fills the per-kind maxima/energies.
inline double evaluate(const Problem& pb, const Kappa_solver_state& st, std::vector<double>& F,
                       Kappa_curve_report* res = nullptr, std::vector<double>* weights = nullptr) {
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

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_SYSTEM_H
