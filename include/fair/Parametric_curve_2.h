// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The concept ParametricCurve_2 -- a planar curve known by its value, first and second
// derivative in its own parameter u (Karciauskas-Peters, Sec. 5: the input of the quintic
// approximation) -- and its models: Archimedean spiral, circle involute, clothoid, circle arc,
// conic arc (rational quadratic Bezier). Everything here is double; the spline built from such a
// curve (Parametric_curve_spline.h) converts the jets to the kernel's FT.
//
// Concept ParametricCurve_2 (doc/parametric_curves.md):
//   double parameter_begin() const;      // u_begin < u_end, both finite
//   double parameter_end() const;
//   Curve_jet_2 jet(double u) const;     // f(u), f'(u), f''(u) for u in [u_begin, u_end]
// A model throws Precondition_error for u outside its domain or not finite, never returns NaN.

#ifndef FAIR_PARAMETRIC_CURVE_2_H
#define FAIR_PARAMETRIC_CURVE_2_H

#include <fair/Errors.h>
#include <fair/internal/parametric/checks.h>
#include <fair/internal/parametric/fresnel.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {

/// Value (x, y), first derivative (dx, dy) and second derivative (ddx, ddy) of a parametric
/// curve with respect to its own parameter, in double.
struct Curve_jet_2 {
  double x, y, dx, dy, ddx, ddy;
};

/// The Fresnel integrals C(x) = int_0^x cos(pi t^2/2) dt and S(x) = int_0^x sin(pi t^2/2) dt.
struct Fresnel_integrals {
  double c, s;
};

/// C(x), S(x): power series for |x| <= 1.5, Laplace continued fraction of erfc beyond; absolute
/// error about 1e-15 for |x| <= 100 (growing like 1e-17 |x| further out, from rounding the phase
/// pi x^2/2). Throws Precondition_error for a non-finite x.
inline Fresnel_integrals fresnel_integrals(double x) {
  Fresnel_integrals r;
  internal::parametric::fresnel(x, r.c, r.s);
  return r;
}

/// The Archimedean spiral f(theta) = center + r(theta) (cos theta, sin theta), r = a + b theta,
/// theta in [theta0, theta1]. Closed forms, a few ulps relative to max(|r|, |b|).
/// |f'|^2 = r^2 + b^2 > 0 unless a = b = 0 (rejected): r = 0 (the spiral through its center,
/// theta = -a/b) is a regular point with speed |b| and curvature 2/|b|, accepted.
class Archimedean_spiral_2 {
public:
  Archimedean_spiral_2(double a, double b, double theta0, double theta1, double center_x = 0, double center_y = 0)
    : a_(a), b_(b), t0_(theta0), t1_(theta1), cx_(center_x), cy_(center_y) {
    using namespace internal::parametric;
    check_finite("Archimedean_spiral_2", "a", a);
    check_finite("Archimedean_spiral_2", "b", b);
    check_finite("Archimedean_spiral_2", "center x", center_x);
    check_finite("Archimedean_spiral_2", "center y", center_y);
    check_domain("Archimedean_spiral_2", theta0, theta1);
    internal::require(a != 0 || b != 0, "Archimedean_spiral_2: a = b = 0 is the point ", center_x, ", ", center_y);
  }
  double parameter_begin() const { return t0_; }
  double parameter_end() const { return t1_; }
  Curve_jet_2 jet(double t) const {
    internal::parametric::check_parameter("Archimedean_spiral_2", t, t0_, t1_);
    const double c = std::cos(t), s = std::sin(t), r = a_ + b_ * t;
    return Curve_jet_2{cx_ + r * c, cy_ + r * s, b_ * c - r * s, b_ * s + r * c, -2 * b_ * s - r * c, 2 * b_ * c - r * s};
  }
  double a() const { return a_; }
  double b() const { return b_; }

private:
  double a_, b_, t0_, t1_, cx_, cy_;
};

/// The involute of the circle of radius R about `center`,
/// f(t) = center + R (cos t + t sin t, sin t - t cos t), t in [t0, t1]; f'(t) = R t (cos t, sin t).
/// t = 0 is its cusp (f' = 0, curvature 1/(R|t|) unbounded): the domain must not contain it,
/// 0 < t0 < t1 or t0 < t1 < 0 (Precondition_error otherwise). Closed forms, a few ulps of R(1+|t|).
class Circle_involute_2 {
public:
  Circle_involute_2(double radius, double t0, double t1, double center_x = 0, double center_y = 0)
    : r_(radius), t0_(t0), t1_(t1), cx_(center_x), cy_(center_y) {
    using namespace internal::parametric;
    check_finite("Circle_involute_2", "center x", center_x);
    check_finite("Circle_involute_2", "center y", center_y);
    internal::require(std::isfinite(radius) && radius > 0, "Circle_involute_2: radius = ", radius, " is not > 0");
    check_domain("Circle_involute_2", t0, t1);
    internal::require(t0 > 0 || t1 < 0, "Circle_involute_2: [", t0, ", ", t1,
                      "] contains the cusp t = 0 (f'(0) = 0, unbounded curvature)");
  }
  double parameter_begin() const { return t0_; }
  double parameter_end() const { return t1_; }
  Curve_jet_2 jet(double t) const {
    internal::parametric::check_parameter("Circle_involute_2", t, t0_, t1_);
    const double c = std::cos(t), s = std::sin(t);
    return Curve_jet_2{cx_ + r_ * (c + t * s), cy_ + r_ * (s - t * c), r_ * t * c, r_ * t * s, r_ * (c - t * s), r_ * (s + t * c)};
  }

private:
  double r_, t0_, t1_, cx_, cy_;
};

/// The clothoid (Euler spiral) with curvature kappa(s) = (kappa0 + c s) / scale, s in [s0, s1]:
///   f(s) = origin + scale int_0^s (cos theta, sin theta),  theta(s) = theta0 + kappa0 s + c s^2/2,
/// so f(0) = origin with direction theta0 (0 need not lie in [s0, s1]); kappa0 = 0, c = pi,
/// scale 1 gives (C(s), S(s)) of fresnel_integrals. |f'| = scale: regular everywhere; c = 0 is a
/// circle (or a line). Position by 15-point Kronrod panels each turning <= 1 rad, tabulated at
/// construction (O(turning) once, O(1) per jet); absolute error about 1e-15 scale (1 + |s|).
/// Derivatives in closed form. Throws Precondition_error when the domain turns more than 1e6 rad.
class Clothoid_2 {
public:
  Clothoid_2(double kappa0, double c, double s0, double s1, double scale = 1, double origin_x = 0, double origin_y = 0,
             double theta0 = 0)
    : k0_(kappa0), c_(c), s0_(s0), s1_(s1), scale_(scale), ox_(origin_x), oy_(origin_y), th0_(theta0) {
    using namespace internal::parametric;
    check_finite("Clothoid_2", "kappa0", kappa0);
    check_finite("Clothoid_2", "c", c);
    check_finite("Clothoid_2", "origin x", origin_x);
    check_finite("Clothoid_2", "origin y", origin_y);
    check_finite("Clothoid_2", "theta0", theta0);
    internal::require(std::isfinite(scale) && scale > 0, "Clothoid_2: scale = ", scale, " is not > 0");
    check_domain("Clothoid_2", s0, s1);
    phase_integral(th0_, k0_, c_, 0.0, s0_, phase_panels(k0_, c_, 0.0, s0_), bx_, by_);
    n_ = phase_panels(k0_, c_, s0_, s1_);
    h_ = (s1_ - s0_) / double(n_);
    cx_.assign(n_ + 1, bx_);
    cy_.assign(n_ + 1, by_);
    for (std::size_t k = 0; k < n_; ++k) {
      double ix, iy;
      phase_integral(th0_, k0_, c_, knot(k), knot(k + 1), 1, ix, iy);
      cx_[k + 1] = cx_[k] + ix;
      cy_[k + 1] = cy_[k] + iy;
    }
  }
  double parameter_begin() const { return s0_; }
  double parameter_end() const { return s1_; }
  Curve_jet_2 jet(double s) const {
    internal::parametric::check_parameter("Clothoid_2", s, s0_, s1_);
    std::size_t k = std::size_t(std::floor((s - s0_) / h_));
    if (k >= n_) k = n_ - 1;
    double ix = 0, iy = 0;
    if (s != knot(k)) internal::parametric::phase_integral(th0_, k0_, c_, knot(k), s, 1, ix, iy);
    const double th = th0_ + s * (k0_ + 0.5 * c_ * s), dth = k0_ + c_ * s;
    const double co = std::cos(th), si = std::sin(th);
    return Curve_jet_2{ox_ + scale_ * (cx_[k] + ix), oy_ + scale_ * (cy_[k] + iy), scale_ * co, scale_ * si,
                       -scale_ * dth * si, scale_ * dth * co};
  }
  /// The signed curvature (kappa0 + c s) / scale in closed form.
  double curvature(double s) const { return (k0_ + c_ * s) / scale_; }

private:
  double knot(std::size_t k) const { return (k == n_) ? s1_ : s0_ + h_ * double(k); }
  double k0_, c_, s0_, s1_, scale_, ox_, oy_, th0_;
  double bx_ = 0, by_ = 0, h_ = 0;
  std::size_t n_ = 0;
  std::vector<double> cx_, cy_;
};

/// The circle arc center + radius (cos u, sin u), u in [start_angle, end_angle] (radians,
/// counter-clockwise, start < end). Closed forms.
class Parametric_circle_arc_2 {
public:
  Parametric_circle_arc_2(double center_x, double center_y, double radius, double start_angle, double end_angle)
    : cx_(center_x), cy_(center_y), r_(radius), a0_(start_angle), a1_(end_angle) {
    using namespace internal::parametric;
    check_finite("Parametric_circle_arc_2", "center x", center_x);
    check_finite("Parametric_circle_arc_2", "center y", center_y);
    internal::require(std::isfinite(radius) && radius > 0, "Parametric_circle_arc_2: radius = ", radius, " is not > 0");
    check_domain("Parametric_circle_arc_2", start_angle, end_angle);
  }
  double parameter_begin() const { return a0_; }
  double parameter_end() const { return a1_; }
  Curve_jet_2 jet(double u) const {
    internal::parametric::check_parameter("Parametric_circle_arc_2", u, a0_, a1_);
    const double c = std::cos(u), s = std::sin(u);
    return Curve_jet_2{cx_ + r_ * c, cy_ + r_ * s, -r_ * s, r_ * c, -r_ * c, -r_ * s};
  }

private:
  double cx_, cy_, r_, a0_, a1_;
};

/// The conic arc f(u) = (P0 B0 + w P1 B1 + P2 B2) / (B0 + w B1 + B2), u in [0,1], B_j the
/// quadratic Bernstein polynomials (standard form: end weights 1). The denominator
/// 1 - 2u(1-u)(1-w) is >= (1+w)/2 on [0,1], so w > -1 is required (w in (-1,0) is the
/// complementary arc, e.g. a circle arc of more than 180 degrees with w = cos(alpha/2)); w = 0 is
/// rejected (P1 would be a point at infinity). Quotient rule in double.
class Parametric_conic_arc_2 {
public:
  Parametric_conic_arc_2(double p0x, double p0y, double p1x, double p1y, double p2x, double p2y, double w)
    : p_{p0x, p0y, p1x, p1y, p2x, p2y}, w_(w) {
    for (double v : p_) internal::parametric::check_finite("Parametric_conic_arc_2", "a control point coordinate", v);
    internal::require(std::isfinite(w) && w > -1 && w != 0, "Parametric_conic_arc_2: weight w = ", w,
                      " is not in (-1, 0) or (0, inf)");
  }
  double parameter_begin() const { return 0; }
  double parameter_end() const { return 1; }
  Curve_jet_2 jet(double u) const {
    internal::parametric::check_parameter("Parametric_conic_arc_2", u, 0, 1);
    const double b0 = (1 - u) * (1 - u), b1 = 2 * u * (1 - u), b2 = u * u;
    const double d0 = -2 * (1 - u), d1 = 2 - 4 * u, d2 = 2 * u; // B_j'
    const double W = b0 + w_ * b1 + b2, W1 = d0 + w_ * d1 + d2, W2 = 2 - 4 * w_ + 2;
    Curve_jet_2 j;
    double* out[3][2] = {{&j.x, &j.y}, {&j.dx, &j.dy}, {&j.ddx, &j.ddy}};
    for (int c = 0; c < 2; ++c) {
      const double n = b0 * p_[c] + w_ * b1 * p_[2 + c] + b2 * p_[4 + c];
      const double n1 = d0 * p_[c] + w_ * d1 * p_[2 + c] + d2 * p_[4 + c];
      const double n2 = 2 * p_[c] - 4 * w_ * p_[2 + c] + 2 * p_[4 + c];
      const double f = n / W, f1 = (n1 - f * W1) / W, f2 = (n2 - 2 * f1 * W1 - f * W2) / W;
      *out[0][c] = f;
      *out[1][c] = f1;
      *out[2][c] = f2;
    }
    return j;
  }
  /// The control point P_i (i = 0, 1, 2) and the weight.
  double control_x(std::size_t i) const { return p_[2 * i]; }
  double control_y(std::size_t i) const { return p_[2 * i + 1]; }
  double weight() const { return w_; }

private:
  double p_[6];
  double w_;
};

} // namespace fair

#endif // FAIR_PARAMETRIC_CURVE_2_H
