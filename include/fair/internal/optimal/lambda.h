// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The lambda trade-off of Gumhold's Sec. 3.2 (eqs. 10-12; doc/optimal_curves.md, "Lambda"):
//   beta = q(eta) (1 - lambda), beta0 = lambda,  q(eta) = 4 * 10^(3.5 eta + 0.08),
// the x4 being the true-curvature convention (kappa -> 2 kappa multiplies |kappa L0|^2 by 4, so the
// paper's q must be multiplied by 4 to keep its balance against the length term). eta_i is the
// ratio of the lengths of segment i on the lambda = 0 curve (the chord) and on the lambda = 1
// reference curve (eq. 11). lambda_i and eta_i are given per segment; the values at the points are
// the averages of the two adjacent segments (open ends: the end segment's value), and each
// segment is blended from its start value to its own value on its first half and to its end
// value on its second half with phi_4 (C4, the polynomial of degree 9 of Sec. 3.2), in the
// arc-length fraction of the segment on the current polygon.

#ifndef FAIR_INTERNAL_OPTIMAL_LAMBDA_H
#define FAIR_INTERNAL_OPTIMAL_LAMBDA_H

#include <fair/internal/optimal/constraints.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

/// phi_4(x) = 70x^9 - 315x^8 + 540x^7 - 420x^6 + 126x^5 (Sec. 3.2), Horner form.
inline double phi4(double x) {
  return x * x * x * x * x * (126 + x * (-420 + x * (540 + x * (-315 + x * 70))));
}

/// q(eta) of eq. 12 times 4 (true curvature).
inline double lambda_scale(double eta) { return 4 * std::pow(10.0, 3.5 * eta + 0.08); }

/// The C4 blend of per-segment values v_i at arc-length fraction x in [0,1] of segment i.
inline double blended(const std::vector<double>& v, bool closed, std::size_t i, double x) {
  const std::size_t m = v.size();
  const double start = closed ? 0.5 * (v[(i + m - 1) % m] + v[i]) : (i == 0 ? v[0] : 0.5 * (v[i - 1] + v[i]));
  const double end = closed ? 0.5 * (v[i] + v[(i + 1) % m]) : (i + 1 == m ? v[i] : 0.5 * (v[i] + v[i + 1]));
  if (x < 0.5) return start + (v[i] - start) * phi4(2 * x);
  return v[i] + (end - v[i]) * phi4(2 * x - 1);
}

/// Per-edge beta and per-vertex beta0 of eq. 10 on the polygon c whose input points are at
/// `interpolation` (increasing; closed: segment i runs from point i to point i+1 mod m).
/// fixed_q > 0: q of eq. 10 held at that value (eta unused) instead of q(eta).
inline void lambda_weights(const std::vector<Vec2>& c, bool closed, const std::vector<std::size_t>& interpolation,
                           const std::vector<double>& lambda, const std::vector<double>& eta,
                           std::vector<double>& edge_beta, std::vector<double>& vertex_beta0, double fixed_q = 0) {
  const std::size_t n = c.size(), m = interpolation.size(), segments = closed ? m : m - 1;
  edge_beta.assign(closed ? n : n - 1, 0);
  vertex_beta0.assign(n, 0);
  for (std::size_t i = 0; i < segments; ++i) {
    const std::size_t a = interpolation[i], b = i + 1 < m ? interpolation[i + 1] : n;  // closed: wraps to vertex 0
    double total = 0;
    for (std::size_t v = a; v < b; ++v) total += vec::norm(vec::sub(c[(v + 1) % n], c[v]));
    double arc = 0;
    for (std::size_t v = a; v < b; ++v) {
      const double l = vec::norm(vec::sub(c[(v + 1) % n], c[v]));
      vertex_beta0[v] = blended(lambda, closed, i, arc / total);
      const double x = (arc + 0.5 * l) / total;
      const double q = fixed_q > 0 ? fixed_q : lambda_scale(blended(eta, closed, i, x));
      edge_beta[v] = q * (1 - blended(lambda, closed, i, x));
      arc += l;
    }
    if (!closed && i + 1 == segments) vertex_beta0[n - 1] = blended(lambda, closed, i, 1.0);
  }
}

} // namespace optimal
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_OPTIMAL_LAMBDA_H
