// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The local formulas of the csr-spline (Karciauskas & Peters, "Curvature-sensitive splines",
// Sec. 4, eq. 6 with the corrections of issue 10; derivations in doc/csr_splines.md):
//  - the eq.-6 stencils p_i, p_i^L, p_i^R written with the knot intervals h_j = t_{j+1} - t_j
//    instead of beta_j = h_j / h_{j-1} (the same numbers; one division fewer per coefficient);
//  - the end stencils b_1^0 and b_2^{m-1} of the clamped ends (the one-sided quadratics);
//  - the discrete curvature kappa_i of the quadratic interpolant f_i;
//  - the curvature-sensitive ratio of eq. 6 (mu_i, nu_i) with both epsilon rules of the paper.
// Every stencil c = sum_k w_k q_{i+k} is affine (sum w_k = 1); callers apply it in the difference
// form c = q_i + sum_{k != 0} w_k (q_{i+k} - q_i), exact in an exact kernel and translation
// invariant in floating point.

#ifndef FAIR_INTERNAL_CSR_STENCILS_H
#define FAIR_INTERNAL_CSR_STENCILS_H

#include <fair/internal/common/curvature.h>

#include <cmath>
#include <limits>

namespace fair {
namespace internal {
namespace csr {

/// What the stencils need at a breakpoint t_i with intervals hm = h_{i-1}, h0 = h_i: the weights
/// wm, wp of q_{i-1}, q_{i+1} in p_i (below), beta_i = h_i / h_{i-1} and 1 / beta_i. Three
/// divisions; each set serves c_{i-1}, c_i and c_{i+1} (construction.h keeps a rolling window).
template <class FT>
struct Breakpoint_weights {
  FT wm, wp, beta, inv_beta;
};

template <class FT>
Breakpoint_weights<FT> breakpoint_weights(const FT& hm, const FT& h0) {
  const FT s = FT(1) / (FT(3) * (hm + h0)), rm = FT(1) / hm, r0 = FT(1) / h0;
  return Breakpoint_weights<FT>{-(h0 * h0) * s * rm, -(hm * hm) * s * r0, h0 * rm, hm * r0};
}

/// p_i = F(t_{i-1}, t_i, t_{i+1}) for the quadratic f_i through q_{i-1}, q_i, q_{i+1} at
/// t_{i-1}, t_i, t_{i+1} (F the cubic blossom), hm = h_{i-1}, h0 = h_i. Eq. 6 as printed:
///   w_{-1} = -beta_i^2 / (3 (beta_i + 1)) = -h_i^2 / (3 h_{i-1} (h_{i-1} + h_i)),
///   w_{+1} = -1 / (3 beta_i (beta_i + 1)) = -h_{i-1}^2 / (3 h_i (h_{i-1} + h_i)).
template <class FT>
void centre_stencil(const FT& hm, const FT& h0, FT& wm, FT& wp) {
  const Breakpoint_weights<FT> w = breakpoint_weights(hm, h0);
  wm = w.wm;
  wp = w.wp;
}

/// p_i^L = F(t_{i-1}, t_i, t_{i+1}) for f_{i-1} (through q_{i-2}, q_{i-1}, q_i at t_{i-2},
/// t_{i-1}, t_i); hmm = h_{i-2}, hm = h_{i-1}, h0 = h_i. Corrected eq. 6:
///   a_{-2} = -beta_{i-1}^2 / (3 (beta_{i-1} + 1))  (as printed; = w_{-1} of p_{i-1}),
///   a_{-1} = (1 + beta_{i-1} - beta_i) / 3          (printed: beta_{i-1} / 3).
template <class FT>
void left_stencil(const FT& hmm, const FT& hm, const FT& h0, FT& am2, FT& am1) {
  const Breakpoint_weights<FT> l = breakpoint_weights(hmm, hm), c = breakpoint_weights(hm, h0);
  am2 = l.wm;
  am1 = (FT(1) + l.beta - c.beta) / FT(3);
}

/// p_i^R = F(t_{i-1}, t_i, t_{i+1}) for f_{i+1} (through q_i, q_{i+1}, q_{i+2} at t_i, t_{i+1},
/// t_{i+2}); hm = h_{i-1}, h0 = h_i, hp = h_{i+1}. Corrected eq. 6:
///   a_1 = (1 + 1/beta_{i+1} - 1/beta_i) / 3       (printed: 1 / (3 beta_{i+1})),
///   a_2 = -1 / (3 beta_{i+1} (beta_{i+1} + 1))      (printed: with the sign +; = w_{+1} of p_{i+1}).
template <class FT>
void right_stencil(const FT& hm, const FT& h0, const FT& hp, FT& a1, FT& a2) {
  const Breakpoint_weights<FT> c = breakpoint_weights(hm, h0), r = breakpoint_weights(h0, hp);
  a1 = (FT(1) + r.inv_beta - c.inv_beta) / FT(3);
  a2 = r.wp;
}

/// The clamped start: b_1^0 = F(t_0, t_0, t_1) for f_1 (through q_0, q_1, q_2 at t_0, t_1, t_2),
/// h0 = h_0, h1 = h_1, beta = beta_1: the weights of q_1 and q_2 (that of q_0 is 1 - w1 - w2):
///   w1 = (beta + 1) / (3 beta),  w2 = -1 / (3 beta (beta + 1)).
/// By symmetry (reverse the parameter) the end b_2^{m-1} = F(t_{m-1}, t_m, t_m) of f_{m-1} is the
/// same formula with h0 = h_{m-1}, h1 = h_{m-2} and the weights of q_{m-1}, q_{m-2}.
template <class FT>
void end_stencil(const FT& h0, const FT& h1, FT& w1, FT& w2) {
  w1 = (h0 + h1) / (FT(3) * h1);
  w2 = -(h0 * h0) / (FT(3) * h1 * (h0 + h1));
}

/// A curvature standing in for infinity: the quadratic f_i has f'(t_i) = 0 (the data reverse
/// their direction at q_i) or the double computation overflowed. Large but with room for the sum
/// of two of them, so the ratios below stay in [0, 1].
constexpr double infinite_curvature = std::numeric_limits<double>::max() / 4;

/// Where the curvature of a quadratic through three samples is taken.
enum class Quadratic_node { FIRST, MIDDLE, LAST };

/// |curvature| of the quadratic through q0, q1, q2 at parameters x0 < x1 < x2 (intervals h0, h1,
/// chords (dx0, dy0) = q1 - q0 and (dx1, dy1) = q2 - q1) at the node `at`, in double. With the
/// divided differences D1 = (q1 - q0)/h0, D2 = (q2 - q1)/h1, D = (D2 - D1)/(h0 + h1):
///   f'' = 2 D,  f'(x) = D1 + D (2x - x0 - x1), i.e. f'(x0) = D1 - h0 D, f'(x1) = D1 + h0 D,
///   f'(x2) = D1 + (h0 + 2 h1) D.
/// Curvature is a geometric quantity: it does not depend on the speed of the parametrisation.
inline double quadratic_curvature(double dx0, double dy0, double h0, double dx1, double dy1, double h1,
                                  Quadratic_node at) {
  const double d1x = dx0 / h0, d1y = dy0 / h0;
  const double dx = (dx1 / h1 - d1x) / (h0 + h1), dy = (dy1 / h1 - d1y) / (h0 + h1);
  const double s = at == Quadratic_node::FIRST ? -h0 : (at == Quadratic_node::MIDDLE ? h0 : h0 + 2 * h1);
  const double fx = d1x + s * dx, fy = d1y + s * dy;
  if (fx == 0 && fy == 0) return infinite_curvature;
  // Fast path: with |f'|^2 and |f''| well inside the double range the naive formula neither
  // overflows nor underflows; otherwise the scaled evaluation of signed_curvature.
  const double u2 = fx * fx + fy * fy, v = std::fabs(dx) + std::fabs(dy);
  double k;
  if (u2 > 1e-150 && u2 < 1e150 && v < 1e150 && v > 1e-150)
    k = std::fabs(2 * (fx * dy - fy * dx)) / (u2 * std::sqrt(u2));
  else
    k = std::fabs(common::signed_curvature(fx, fy, 2 * dx, 2 * dy));
  return std::isfinite(k) && k < infinite_curvature ? k : infinite_curvature;
}

/// The curvature-sensitive ratio of eq. 6, a / (a + b) for curvatures a, b >= 0:
///  - case split (the paper's first form): a / (a + b) if a + b > epsilon, else 1/2;
///  - add epsilon (the paper's alternative): (a + epsilon) / (a + b + 2 epsilon).
/// Always in [0, 1]; 1/2 whenever the denominator is not positive (epsilon = 0 and a = b = 0).
inline double curvature_ratio(double a, double b, double epsilon, bool add_epsilon) {
  if (add_epsilon) {
    const double d = a + b + 2 * epsilon;
    return d > 0 ? (a + epsilon) / d : 0.5;
  }
  const double d = a + b;
  return d > epsilon && d > 0 ? a / d : 0.5;
}

} // namespace csr
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_CSR_STENCILS_H
