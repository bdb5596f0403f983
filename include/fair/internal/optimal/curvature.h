// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The discrete curvature kappa_j at a polygon vertex b = c_j with neighbours a = c_{j-1}, c = c_{j+1}
// (Gumhold, Sec. 2.2.2), in the TRUE-curvature convention of issue 11 (doc/optimal_curves.md,
// "Discrete curvature (and the paper's factor 2)"): on a regular n-gon of circumradius r every
// discretisation tends to 1/r, where the paper's eq. 6 and eq. 9 give 1/(2r).
//   Delta_0 = b - a, Delta_1 = c - b, l_0 = |Delta_0|, l_1 = |Delta_1|, s = (l_0 + l_1)/2,
//   X = Delta_0 . Delta_1, Y = det(Delta_0, Delta_1) (the paper's Delta_0^T Delta_1^*), phi = atan2(Y, X),
//   REGULARISED   kappa = phi / (s cos(phi/2.1))          (eq. 9 times 2; finite for |phi| <= pi)
//   TURNING_ANGLE kappa = phi / s                         (kappa^phi of eq. 6 times 2)
//   CIRCUMCIRCLE  kappa = 2 sin(phi) / |c - a|
//                       = 2 Y / (l_0 l_1 |c - a|)         (kappa° of eq. 6 times 2: 1/circumradius)
// kappa > 0 for a left turn (counter-clockwise). Written once, templated on the scalar (double or
// common::Dual, common/dual.h), as a function of the two edge vectors.

#ifndef FAIR_INTERNAL_OPTIMAL_CURVATURE_H
#define FAIR_INTERNAL_OPTIMAL_CURVATURE_H

#include <fair/Optimal_curve_options.h>
#include <fair/internal/common/dual.h>

#include <cmath>

namespace fair {
namespace internal {
namespace optimal {

using common::abs_pow;
using common::Dual;

/// The 2 + delta of eq. 9 with the paper's delta = 0.1: |f(phi)| = |phi / cos(phi/2.1)| <= 42.04 on
/// [-pi, pi] (the paper's 21.1 is f/2 at s = 1).
constexpr double regularisation_divisor = 2.1;

/// kappa_j from the edge vectors u = Delta_{j-1} = c_j - c_{j-1} and v = Delta_j = c_{j+1} - c_j (it
/// depends on the vertices only through them); the caller guarantees u != 0 != v.
template <class T>
T local_curvature(Curvature_discretisation d, const T& ux, const T& uy, const T& vx, const T& vy) {
  using std::atan2;
  using std::cos;
  using std::sqrt;
  const T l0 = sqrt(ux * ux + uy * uy), l1 = sqrt(vx * vx + vy * vy);
  const T y = ux * vy - uy * vx;
  if (d == Curvature_discretisation::CIRCUMCIRCLE) {
    const T wx = ux + vx, wy = uy + vy;
    return 2.0 * y / (l0 * l1 * sqrt(wx * wx + wy * wy));
  }
  const T x = ux * vx + uy * vy;
  const T phi = atan2(y, x);
  const T s = 0.5 * (l0 + l1);
  if (d == Curvature_discretisation::TURNING_ANGLE) return phi / s;
  return phi / (s * cos(phi / regularisation_divisor));
}

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_CURVATURE_H
