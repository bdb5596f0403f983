// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The sampler of Curve_sampling.h: arc length by the adaptive Gauss-Kronrod quadrature of
// |c'(t)| (internal/metrics/quadrature.h) on every sampling interval, normals and curvatures with
// one-sided limits at singular parameters.

#ifndef FAIR_INTERNAL_METRICS_SAMPLER_H
#define FAIR_INTERNAL_METRICS_SAMPLER_H

#include <fair/Errors.h>
#include <fair/Quadrature.h>
#include <fair/internal/metrics/pieces.h>
#include <fair/internal/metrics/quadrature.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace fair {
namespace internal {
namespace metrics {

/// int_a^b |c'(t)| dt on one piece by adaptive_integral.
template <class Piece>
double arc_length_between(const Piece_jet<Piece>& jet, double a, double b, const Quadrature_options& options,
                          const char* what) {
  return adaptive_integral([&](double t) { return jet(t, 1).speed(); }, a, b, options, what).value;
}

/// Signed curvature from c' and c'' in double, scaled so that neither |c'|^3 nor the cross
/// product overflows or underflows: with m = max(|x'|, |y'|), u = c'/m, v = c''/m,
/// kappa = (u x v) / (m |u|^3). NaN when c' = 0 or a value is not finite.
template <class Piece>
double scaled_curvature(const Piece& piece, double t) {
  typedef typename Piece::FT FT;
  const auto d1 = piece.derivative(FT(t));
  const auto d2 = piece.second_derivative(FT(t));
  const double x1 = CGAL::to_double(d1.x()), y1 = CGAL::to_double(d1.y());
  const double x2 = CGAL::to_double(d2.x()), y2 = CGAL::to_double(d2.y());
  const double m = std::max(std::abs(x1), std::abs(y1));
  if (!(m > 0) || !std::isfinite(m)) return std::numeric_limits<double>::quiet_NaN();
  const double ux = x1 / m, uy = y1 / m, vx = x2 / m, vy = y2 / m;
  const double u = std::hypot(ux, uy);
  return (ux * vy - uy * vx) / (u * u * u) / m;
}

/// Unit normal and curvature at t, with the one-sided limit at a singular parameter. The
/// piece's own curvature() is used; where it fails (it may overflow for coordinates near the
/// ends of the double range), scaled_curvature() from the piece's derivatives.
template <class Piece>
void normal_and_curvature(const Piece& piece, std::size_t index, double t, double& nx, double& ny,
                          double& kappa) {
  typedef typename Piece::FT FT;
  static const double nudges[4] = {0.0, 1e-9, 1e-7, 1e-5};
  for (double nudge : nudges) {
    const double s = t < 0.5 ? t + nudge : t - nudge;
    const auto d = piece.derivative(FT(s));
    const double dx = CGAL::to_double(d.x()), dy = CGAL::to_double(d.y());
    const double v = std::hypot(dx, dy);
    if (!(v > 0) || !std::isfinite(v)) continue;
    double k = std::numeric_limits<double>::quiet_NaN();
    try {
      k = piece.curvature(s);
    } catch (const Precondition_error&) {
    }
    if (!std::isfinite(k)) k = scaled_curvature(piece, s);
    if (!std::isfinite(k)) continue;
    nx = -dy / v;
    ny = dx / v;
    kappa = k;
    return;
  }
  throw Precondition_error(message("sample_curve: piece ", index, " is singular at t = ", t,
                                   " (c'(t) = 0 or undefined curvature, also nearby)"));
}

} // namespace metrics
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_METRICS_SAMPLER_H
