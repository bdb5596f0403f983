// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Parameters of marked points (Karciauskas-Peters, Sec. 3.2, eqs. 4 and 5): the parameter u
// at which a curve passes through a point the designer marked on it. Derivations in
// doc/parametric_curves.md. All in double.

#ifndef FAIR_MARKED_POINT_PARAMETERS_H
#define FAIR_MARKED_POINT_PARAMETERS_H

#include <fair/Errors.h>
#include <fair/Parametric_curve_2.h>
#include <fair/internal/common/constants.h>
#include <fair/internal/parametric/nearest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {

/// Eq. 4 without its case split: on the standard rational quadratic arc of opening angle alpha
/// from (1,0) to (cos alpha, sin alpha) (end weights 1, middle weight w = cos(alpha/2), control
/// point (1, tan(alpha/2))), the point at angle alpha_i has parameter
///   u = sin(alpha_i/2) / (sin(alpha_i/2) + sin((alpha - alpha_i)/2)).
/// Valid for every 0 < alpha < 2 pi, also alpha >= pi where w <= 0 (for the degree-elevated
/// cubic weights (1+2w)/3 < 0 only beyond 240 degrees, which concerns the conversion, not u).
/// Both sines are > 0 for 0 < alpha_i < alpha: no cancellation, relative error a few ulps.
/// Throws Precondition_error unless 0 < alpha < 2 pi and 0 <= alpha_i <= alpha.
inline double circle_arc_parameter(double alpha_i, double alpha) {
  internal::require(std::isfinite(alpha) && alpha > 0 && alpha < internal::common::two_pi, "circle_arc_parameter: opening angle alpha = ",
                    alpha, " is not in (0, 2 pi)");
  internal::require(std::isfinite(alpha_i) && alpha_i >= 0 && alpha_i <= alpha, "circle_arc_parameter: alpha_i = ",
                    alpha_i, " is not in [0, alpha = ", alpha, "]");
  const double a = std::sin(0.5 * alpha_i), b = std::sin(0.5 * (alpha - alpha_i));
  return a / (a + b);
}

/// The parameter of a point with barycentric coordinates (tau0, tau1, tau2) on the control
/// triangle of a conic in standard rational quadratic form (any weight w): u = sqrt(tau2) /
/// (sqrt(tau0) + sqrt(tau2)), because f(u) has tau0 = (1-u)^2/W, tau2 = u^2/W. tau1 only
/// identifies the point; it is not needed. Throws Precondition_error if tau0 or tau2 is negative
/// beyond rounding (-1e-12) or both vanish (the point P1, on no arc), or a value is not finite.
inline double conic_parameter(double tau0, double tau1, double tau2) {
  internal::require(std::isfinite(tau0) && std::isfinite(tau1) && std::isfinite(tau2),
                    "conic_parameter: barycentric coordinates (", tau0, ", ", tau1, ", ", tau2, ") are not finite");
  internal::require(tau0 >= -1e-12 && tau2 >= -1e-12 && tau0 + tau2 > 0, "conic_parameter: barycentric coordinates (",
                    tau0, ", ", tau1, ", ", tau2, ") are not those of a point of the arc (need tau0, tau2 >= 0, not both 0)");
  const double a = std::sqrt(std::max(tau0, 0.0)), b = std::sqrt(std::max(tau2, 0.0));
  return b / (a + b);
}

/// The parameter of the point q on the conic arc: its barycentric coordinates on the control
/// triangle (signed areas), then the closed form above. Throws Invalid_input_error when the
/// control triangle is degenerate, or when q is farther than `tolerance` times the diameter of
/// the control triangle from the point f(u) found (naming q and the distance).
inline double conic_parameter(const Parametric_conic_arc_2& arc, double qx, double qy, double tolerance = 1e-9) {
  const double x0 = arc.control_x(0), y0 = arc.control_y(0), x1 = arc.control_x(1), y1 = arc.control_y(1);
  const double x2 = arc.control_x(2), y2 = arc.control_y(2);
  auto area = [](double ax, double ay, double bx, double by, double cx, double cy) {
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  };
  const double total = area(x0, y0, x1, y1, x2, y2);
  const double diameter = std::max({std::hypot(x1 - x0, y1 - y0), std::hypot(x2 - x1, y2 - y1), std::hypot(x2 - x0, y2 - y0)});
  if (!(std::fabs(total) > 1e-14 * diameter * diameter))
    throw Invalid_input_error(internal::message("conic_parameter: the control triangle (", x0, ", ", y0, "), (", x1, ", ",
                                                y1, "), (", x2, ", ", y2, ") is degenerate"));
  const double t0 = area(qx, qy, x1, y1, x2, y2) / total, t2 = area(x0, y0, x1, y1, qx, qy) / total;
  const double u = conic_parameter(std::max(t0, 0.0), 1 - t0 - t2, std::max(t2, 0.0));
  const Curve_jet_2 j = arc.jet(u);
  const double d = std::hypot(j.x - qx, j.y - qy);
  if (!(d <= tolerance * diameter))
    throw Invalid_input_error(internal::message("conic_parameter: the point (", qx, ", ", qy, ") is at distance ", d,
                                                " from the conic arc (tolerance ", tolerance * diameter, ")"));
  return u;
}

/// Options of nearest_parameter.
struct Nearest_parameter_options {
  /// Uniform samples of [u_lo, u_hi] that bracket the local minima of |f(u) - q|: a minimum
  /// narrower than the sample spacing can be missed (the nearest of those found is returned).
  std::size_t samples = 64;
  /// q must be within tolerance * (diameter of the samples' bounding box) of the curve ...
  double tolerance = 1e-9;
  /// ... unless the least-squares parameter of a point off the curve is wanted (eq. 5 allows it).
  bool allow_off_curve = false;
  /// Cap on the safeguarded Newton steps per bracket (bisection alone needs < 1100).
  std::size_t max_iterations = 2000;
};

/// Eq. 5: the parameter u in [u_lo, u_hi] (inside f's domain) of the point of the
/// ParametricCurve_2 f nearest to q = (qx, qy): the roots of d/du |f(u) - q|^2 bracketed by
/// samples, refined by safeguarded Newton (accurate to a few ulps of u where q is on f and
/// |f'| > 0), the nearest of them and of the ends. O(samples + iterations) jets.
/// Throws Precondition_error for a bad interval or samples < 2, Invalid_input_error when q is
/// farther than the tolerance from f (unless allow_off_curve; the message names q and the
/// distance), Non_convergence_error if a bracket is not resolved within max_iterations.
template <class Curve>
double nearest_parameter(const Curve& f, double qx, double qy, double u_lo, double u_hi,
                         const Nearest_parameter_options& options = Nearest_parameter_options()) {
  using namespace internal::parametric;
  internal::require(std::isfinite(qx) && std::isfinite(qy), "nearest_parameter: the point (", qx, ", ", qy,
                    ") is not finite");
  internal::require(std::isfinite(u_lo) && std::isfinite(u_hi) && u_lo < u_hi && u_lo >= f.parameter_begin() &&
                        u_hi <= f.parameter_end(),
                    "nearest_parameter: [", u_lo, ", ", u_hi, "] is not a subinterval of the domain [", f.parameter_begin(),
                    ", ", f.parameter_end(), "]");
  internal::require(options.samples >= 2, "nearest_parameter: needs samples >= 2, got ", options.samples);
  const std::size_t n = options.samples;
  std::vector<double> u(n + 1), g(n + 1);
  double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
  Nearest_candidate best{u_lo, HUGE_VAL};
  for (std::size_t k = 0; k <= n; ++k) {
    u[k] = (k == n) ? u_hi : u_lo + (u_hi - u_lo) * double(k) / double(n);
    const Curve_jet_2 j = f.jet(u[k]);
    internal::require(std::isfinite(j.x) && std::isfinite(j.y) && std::isfinite(j.dx) && std::isfinite(j.dy),
                      "nearest_parameter: the curve's jet is not finite at u = ", u[k]);
    g[k] = half_gradient(j, qx, qy);
    xmin = std::min(xmin, j.x), xmax = std::max(xmax, j.x), ymin = std::min(ymin, j.y), ymax = std::max(ymax, j.y);
    const double d = squared_distance(j, qx, qy);
    if (d < best.distance) best = Nearest_candidate{u[k], d};
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (!(g[k] < 0 && g[k + 1] > 0)) continue; // a local minimum of |f - q|^2 in (u_k, u_k+1)
    const double r = refine_minimum(f, qx, qy, u[k], u[k + 1], options.max_iterations);
    const double d = squared_distance(f.jet(r), qx, qy);
    if (d < best.distance) best = Nearest_candidate{r, d};
  }
  const double distance = std::sqrt(best.distance), diameter = std::hypot(xmax - xmin, ymax - ymin);
  if (!options.allow_off_curve && !(distance <= options.tolerance * diameter))
    throw Invalid_input_error(internal::message("nearest_parameter: the point (", qx, ", ", qy, ") is at distance ",
                                                distance, " from the curve on [", u_lo, ", ", u_hi, "] (tolerance ",
                                                options.tolerance * diameter, ")"));
  return best.u;
}

} // namespace fair

#endif // FAIR_MARKED_POINT_PARAMETERS_H
