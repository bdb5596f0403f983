// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Eq. 5 of Karciauskas-Peters: the parameter u of the point of f nearest to q, a root of
//   g(u) = (f(u) - q) . f'(u) = (1/2) d/du |f(u) - q|^2,   g'(u) = |f'(u)|^2 + (f(u) - q) . f''(u).
// Uniform samples bracket the local minima of |f - q|^2 (g changes sign from - to +); each
// bracket is refined by safeguarded Newton (a Newton step that leaves the bracket, or meets
// g' <= 0, becomes a bisection; the bracket shrinks every step), and the nearest of these minima
// and of the two ends wins.

#ifndef FAIR_INTERNAL_PARAMETRIC_NEAREST_H
#define FAIR_INTERNAL_PARAMETRIC_NEAREST_H

#include <fair/Errors.h>
#include <fair/Parametric_curve_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace parametric {

struct Nearest_candidate {
  double u, distance;
};

inline double squared_distance(const Curve_jet_2& j, double qx, double qy) {
  return (j.x - qx) * (j.x - qx) + (j.y - qy) * (j.y - qy);
}
inline double half_gradient(const Curve_jet_2& j, double qx, double qy) {
  return (j.x - qx) * j.dx + (j.y - qy) * j.dy;
}

/// The root of g in [lo, hi] with g(lo) < 0 < g(hi), by safeguarded Newton; at most `cap`
/// steps (a bisection step halves the bracket, so 1100 steps reach any double resolution).
template <class Curve>
double refine_minimum(const Curve& f, double qx, double qy, double lo, double hi, std::size_t cap) {
  double u = 0.5 * (lo + hi);
  const double width = hi - lo;
  for (std::size_t it = 0; it < cap; ++it) {
    const Curve_jet_2 j = f.jet(u);
    const double g = half_gradient(j, qx, qy);
    if (g == 0) return u;
    if (g < 0) lo = u; else hi = u;
    const double dg = j.dx * j.dx + j.dy * j.dy + (j.x - qx) * j.ddx + (j.y - qy) * j.ddy;
    double next = (dg > 0) ? u - g / dg : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    // converged: the step is at the resolution of u (relative to the initial bracket), or the
    // bracket is at machine resolution
    if (std::fabs(next - u) <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(u), width) ||
        !(lo < 0.5 * (lo + hi) && 0.5 * (lo + hi) < hi))
      return next;
    u = next;
  }
  throw Non_convergence_error(message("nearest_parameter: safeguarded Newton did not converge in ", cap,
                                      " steps near u = ", u, " for the point (", qx, ", ", qy, ")"),
                              cap, hi - lo);
}

} // namespace parametric
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_PARAMETRIC_NEAREST_H
