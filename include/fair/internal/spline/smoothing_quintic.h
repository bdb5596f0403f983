// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The engine of fair::fit_smoothing_quintic_runs (include/fair/Polygon_spline_fit.h): the C4
// quintic smoothing spline of one run of polygon vertices v_0..v_N (closed: periodic) on the
// chord-length knots t_k, which interpolates the "hard" vertices and minimises
//   J(c) = int |c'''(t)|^2 dt + sum_{k free} w_k |c(t_k) - v_k|^2,   w_k = hbar^5 / (sigma a_k^2)
// (the cubic's rule of smoothing_fit.h with the quintic's energy: int |c'''|^2 scales as h^-5).
// Derivation (doc/optimal_curves.md, "The quintic smoothing spline"):
//
// Form. Piece i is the quintic Hermite interpolant of (p, m, s) = value, first and second
// derivative at t_i and t_{i+1} (internal/optimal/spline_fit.h), so every such curve is C2 and
// int |c'''|^2 = sum_i z_i^T K_i z_i, z_i = (p_i, p_{i+1}, H_i m_i, H_i^2 s_i, H_{i+1} m_{i+1},
// H_{i+1}^2 s_{i+1}), K_i = S M S / h_i^5 (M = quintic_jerk_matrix, S = diag(1, 1, h/H_i, h^2/H_i^2,
// h/H_{i+1}, h^2/H_{i+1}^2), H the mean interval at a knot: a scaling of the unknowns only, which
// gives all of them the unit of a length and the entries of K_i one order, h^-5). J is a quadratic in the unknowns
// u = (p_k, H_k m_k, H_k^2 s_k) per knot (p_k fixed at v_k on the hard knots); its minimiser solves
//   (sum_i P_i^T K_i P_i + W) u = W v,    W = diag(w_k on the p_k of the free knots),
// with the hard p_k eliminated (identity rows, their columns moved to the right-hand side). With 3
// unknowns per knot ordered knot by knot a piece couples indices 3i .. 3i + 5: half-bandwidth 5,
// cyclic when closed: banded Cholesky, O(n) (linear_algebra/symmetric_band.h).
//
// What the minimiser is. Integrating by parts on each piece (c^(6) = 0),
//   dJ/2 = sum_pieces [c''' dc'' - c'''' dc' + c^(5) dc]_{t_i+}^{t_{i+1}-} + sum_k w_k (c(t_k) - v_k) dc(t_k):
// dc' and dc'' are free at every knot, so c''' and c'''' are continuous there (C4); dc(t_k) is free
// at a free knot, so the jump of c^(5) there is w_k (c(t_k) - v_k) (Reinsch's condition one order
// up: the spline is C5 where it meets a free vertex); open ends are natural, c''' = c'''' = 0
// (dc', dc'' free there). So the fit is the quintic smoothing spline, and w = 0 everywhere (every
// vertex hard) the natural (periodic) C4 quintic interpolant. Positive definite: a u in the kernel
// has c''' = 0, a quadratic (one polynomial: C4 pieces of degree 2), vanishing at every hard knot
// and at every free knot with w_k > 0 — at >= 3 knots for an open run of >= 3 vertices (its two
// ends are hard) or a closed run: zero.

#ifndef FAIR_INTERNAL_SPLINE_SMOOTHING_QUINTIC_H
#define FAIR_INTERNAL_SPLINE_SMOOTHING_QUINTIC_H

#include <fair/internal/linear_algebra/symmetric_band.h>
#include <fair/internal/optimal/spline_fit.h>
#include <fair/internal/optimal/vec2.h>

#include <array>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace spline {

/// The quintic smoothing spline of v on the knots t (open: t.size() == v.size() >= 3; closed:
/// v.size() + 1, v.size() >= 3) for the inverse weights d_k = 1 / w_k (0: v_k interpolated): its
/// Bezier pieces (degree 5, one per interval) and values y_k = c(t_k). False when the system is not
/// positive definite to working precision (mathematically it is: file comment).
inline bool smoothing_quintic_solve(const std::vector<optimal::Vec2>& v, const std::vector<double>& t, bool closed,
                                    const std::vector<double>& d, std::vector<std::array<optimal::Vec2, 6>>& pieces,
                                    std::vector<optimal::Vec2>& y) {
  const std::size_t n = v.size(), edges = t.size() - 1, size = 3 * n;
  std::vector<double> h(edges), H(n);
  for (std::size_t i = 0; i < edges; ++i) h[i] = t[i + 1] - t[i];
  for (std::size_t k = 0; k < n; ++k) {
    const double left = (closed || k > 0) ? h[(k + edges - 1) % edges] : h[0];
    const double right = (closed || k < edges) ? h[k % edges] : h[edges - 1];
    H[k] = 0.5 * (left + right);
  }
  auto hard = [&](std::size_t k) { return !(d[k] > 0); };
  linear_algebra::Banded_symmetric a;
  a.reset(size, 5, closed);
  std::array<std::vector<double>, 2> rhs{{std::vector<double>(size, 0.0), std::vector<double>(size, 0.0)}};
  const std::array<std::array<double, 6>, 6> M = optimal::quintic_jerk_matrix();
  for (std::size_t i = 0; i < edges; ++i) {
    const std::size_t j = (i + 1) % n;
    const double hi = h[i], scale = 1 / (hi * hi * hi * hi * hi);
    const double S[6] = {1, 1, hi / H[i], hi * hi / (H[i] * H[i]), hi / H[j], hi * hi / (H[j] * H[j])};
    const std::size_t u[6] = {3 * i, 3 * j, 3 * i + 1, 3 * i + 2, 3 * j + 1, 3 * j + 2};
    // a local index is fixed when it is the value of a hard knot
    const bool fixed[6] = {hard(i), hard(j), false, false, false, false};
    const optimal::Vec2* value[6] = {&v[i], &v[j], nullptr, nullptr, nullptr, nullptr};
    for (int r = 0; r < 6; ++r) {
      if (fixed[r]) continue;
      for (int c = 0; c < 6; ++c) {
        const double k = S[r] * M[r][c] * S[c] * scale;
        if (fixed[c]) {
          for (int x = 0; x < 2; ++x) rhs[x][u[r]] -= k * (*value[c])[x];
        } else if (c >= r) {
          a.at(u[r], u[c]) += k;  // each unordered pair once: at(i, j) and at(j, i) are one entry
        }
      }
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (hard(k)) {
      a.at(3 * k, 3 * k) = 1;
      for (int x = 0; x < 2; ++x) rhs[x][3 * k] = v[k][x];
    } else {
      a.at(3 * k, 3 * k) += 1 / d[k];
      for (int x = 0; x < 2; ++x) rhs[x][3 * k] += v[k][x] / d[k];
    }
  }
  for (int x = 0; x < 2; ++x)
    if (!linear_algebra::solve_banded_positive_definite(a, rhs[x])) return false;
  std::vector<optimal::Vec2> m(n), s(n);
  y.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    for (int x = 0; x < 2; ++x) {
      y[k][x] = hard(k) ? v[k][x] : rhs[x][3 * k];  // exact on the hard knots
      m[k][x] = rhs[x][3 * k + 1] / H[k];
      s[k][x] = rhs[x][3 * k + 2] / (H[k] * H[k]);
    }
  pieces = optimal::quintic_bezier_pieces(y, t, m, s);
  return true;
}

} // namespace spline
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_SPLINE_SMOOTHING_QUINTIC_H
