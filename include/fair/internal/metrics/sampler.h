// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The sampler of Curve_sampling.h: arc length by adaptive Gauss-Legendre bisection of |c'(t)|,
// normals and curvatures with one-sided limits at singular parameters.

#ifndef FAIR_INTERNAL_METRICS_SAMPLER_H
#define FAIR_INTERNAL_METRICS_SAMPLER_H

#include <fair/Errors.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace fair {
namespace internal {
namespace metrics {

/// c'(t) of a piece in double.
template <class Piece>
void speed_vector(const Piece& piece, double t, double& dx, double& dy) {
  typedef typename Piece::FT FT;
  const auto d = piece.derivative(FT(t));
  dx = CGAL::to_double(d.x());
  dy = CGAL::to_double(d.y());
}

template <class Piece>
double speed(const Piece& piece, double t) {
  double dx, dy;
  speed_vector(piece, t, dx, dy);
  return std::hypot(dx, dy);
}

/// 7-point Gauss-Legendre rule on [a, b] for |c'|.
template <class Piece>
double gauss_legendre_7(const Piece& piece, double a, double b) {
  // Nodes and weights of the 7-point rule on [-1, 1].
  static const double x[4] = {0.0, 0.4058451513773971669066064, 0.7415311855993944398638648,
                              0.9491079123427585245261897};
  static const double w[4] = {0.4179591836734693877551020, 0.3818300505051189449503698,
                              0.2797053914892766679014678, 0.1294849661688696932706114};
  const double m = 0.5 * (a + b), h = 0.5 * (b - a);
  double s = w[0] * speed(piece, m);
  for (int k = 1; k < 4; ++k) s += w[k] * (speed(piece, m - h * x[k]) + speed(piece, m + h * x[k]));
  return s * h;
}

template <class Piece>
double adaptive_length(const Piece& piece, double a, double b, double whole, double tol, int depth) {
  const double m = 0.5 * (a + b);
  const double left = gauss_legendre_7(piece, a, m), right = gauss_legendre_7(piece, m, b);
  const double refined = left + right;
  if (std::abs(refined - whole) <= tol || depth >= 40) return refined;
  return adaptive_length(piece, a, m, left, 0.5 * tol, depth + 1) +
         adaptive_length(piece, m, b, right, 0.5 * tol, depth + 1);
}

/// A length scale of the piece: the length of its control polygon (positive unless the piece
/// is a single point).
template <class Piece>
double control_polygon_length(const Piece& piece) {
  const auto cps = piece.control_points();
  double len = 0, px = 0, py = 0;
  bool first = true;
  for (const auto& p : cps) {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    if (!first) len += std::hypot(x - px, y - py);
    px = x;
    py = y;
    first = false;
  }
  return len;
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
  static const double nudges[4] = {0.0, 1e-9, 1e-7, 1e-5};
  for (double nudge : nudges) {
    const double s = t < 0.5 ? t + nudge : t - nudge;
    double dx, dy;
    speed_vector(piece, s, dx, dy);
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
