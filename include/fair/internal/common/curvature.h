// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The one signed curvature of the library in double, from the first and second derivatives:
//   kappa = (c' x c'') / |c'|^3.
// Evaluated naively, |c'|^3 overflows for |c'| beyond about 1e102 and underflows below 1e-102
// (the piece scaled by 1e150 would get curvature 0 or NaN), and the cross product fails at
// 1e154. Here c' = 2^e1 u and c'' = 2^e2 v with the largest component of u and of v in [1, 2):
//   kappa = 2^(e2 - 2 e1) (u x v) / |u|^3,
// where |u|^2 is in [1, 8) and |u x v| < 8, so nothing overflows or underflows before the final
// exact scaling by 2^(e2 - 2 e1), which over/underflows only when kappa itself is outside the
// double range. Scaling by powers of two is exact in binary floating point, so the result is
// scale-covariant bit for bit: for the piece scaled by 2^j (c' and c'' scaled by 2^j exactly) it
// is 2^-j times the unscaled curvature (unless that is subnormal).

#ifndef FAIR_INTERNAL_COMMON_CURVATURE_H
#define FAIR_INTERNAL_COMMON_CURVATURE_H

#include <algorithm>
#include <cmath>
#include <limits>

namespace fair {
namespace internal {
namespace common {

/// Signed curvature (c' x c'') / |c'|^3 of c' = (x1, y1), c'' = (x2, y2), relative error a few
/// ulps at every scale (see the file comment). At a singular point (c' = 0, where the curvature
/// is undefined) it returns 0, like for c'' = 0; callers that must reject singular points test
/// c' themselves. A non-finite input gives NaN.
inline double signed_curvature(double x1, double y1, double x2, double y2) {
  const double m1 = std::max(std::fabs(x1), std::fabs(y1)), m2 = std::max(std::fabs(x2), std::fabs(y2));
  if (!std::isfinite(m1) || !std::isfinite(m2)) return std::numeric_limits<double>::quiet_NaN();
  if (m1 == 0 || m2 == 0) return 0.0;
  const int e1 = std::ilogb(m1), e2 = std::ilogb(m2); // exact exponents, also of subnormals
  const double ux = std::scalbn(x1, -e1), uy = std::scalbn(y1, -e1);
  const double vx = std::scalbn(x2, -e2), vy = std::scalbn(y2, -e2);
  const double u2 = ux * ux + uy * uy;
  return std::scalbn((ux * vy - uy * vx) / (u2 * std::sqrt(u2)), e2 - 2 * e1);
}

} // namespace common
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_COMMON_CURVATURE_H
