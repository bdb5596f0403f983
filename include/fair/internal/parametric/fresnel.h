// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The Fresnel integrals C(x) = int_0^x cos(pi t^2 / 2) dt, S(x) = int_0^x sin(pi t^2 / 2) dt,
// and the phase integral of the clothoid (Clothoid_2), written for this library.
//
// Fresnel, two regimes (both in double, |error| <= about 1e-15 for |x| <= 100; doc/parametric_curves.md):
// - |x| <= fresnel_series_limit: the power series of C + iS = int_0^x exp(i pi t^2/2) dt,
//     C + iS = sum_k (i z)^k / k! * x / (2k + 1),   z = pi x^2 / 2,
//   whose largest term is below e^z ~ 34 at the limit, so at most ~1.5 digits are lost.
// - |x| > fresnel_series_limit: C + iS = (1 + i)/2 (1 - erfc(w)), w = sqrt(pi)/2 (1 - i) x
//   (substitute t = 2 w s / (sqrt(pi)(1 - i)) in the erf integral), with
//     erfc(w) = exp(-w^2)/sqrt(pi) * 1/(w + (1/2)/(w + 1/(w + (3/2)/(w + 2/(w + ...)))))
//   (the Laplace continued fraction, convergent for Re w > 0), evaluated by the modified Lentz
//   method; exp(-w^2) = exp(i pi x^2/2). Its phase pi x^2 / 2 is rounded like any product, so
//   beyond |x| ~ 100 the absolute error grows like 1e-17 x (C and S stay within 1/(pi x) of 1/2).
// C and S are odd.

#ifndef FAIR_INTERNAL_PARAMETRIC_FRESNEL_H
#define FAIR_INTERNAL_PARAMETRIC_FRESNEL_H

#include <fair/Errors.h>
#include <fair/internal/common/constants.h>
#include <fair/internal/metrics/quadrature.h>

#include <cmath>
#include <complex>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace parametric {

/// Where the series hands over to the continued fraction: there the series' largest term is
/// e^(pi 1.5^2 / 2) ~ 34 (1.5 digits lost) and the fraction needs about 120 steps (16 at x = 5).
constexpr double fresnel_series_limit = 1.5;
/// Caps of the two loops; the series needs 31 terms and the fraction 121 steps at the handover
/// (fewer further out), so reaching a cap is a bug.
constexpr std::size_t fresnel_series_cap = 200;
constexpr std::size_t fresnel_fraction_cap = 2000;

inline void fresnel(double x, double& c, double& s) {
  require(std::isfinite(x), "fresnel_integrals: x = ", x, " is not finite");
  using common::pi;
  const double ax = std::fabs(x);
  if (ax == 0) {
    c = s = 0;
  } else if (ax <= fresnel_series_limit) {
    const double z = 0.5 * pi * ax * ax;
    double power = ax; // z^k / k! * x
    c = 0;
    s = 0;
    std::size_t k = 0;
    for (;; ++k) {
      FAIR_ASSERT_MSG(k < fresnel_series_cap, "x = ", x);
      const double term = power / double(2 * k + 1);
      switch (k % 4) { // i^k
        case 0: c += term; break;
        case 1: s += term; break;
        case 2: c -= term; break;
        default: s -= term; break;
      }
      if (term < 1e-17 * (std::fabs(c) + std::fabs(s)) && k > 2) break;
      power *= z / double(k + 1);
    }
  } else {
    typedef std::complex<double> cd;
    const cd w = std::sqrt(pi) / 2 * cd(1, -1) * ax;
    // modified Lentz for K = a1/(w + a2/(w + a3/(w + ...))), a1 = 1, a_{j+1} = j/2
    const double tiny = 1e-300;
    cd f = tiny, C = f, D = 0;
    for (std::size_t j = 1;; ++j) {
      FAIR_ASSERT_MSG(j < fresnel_fraction_cap, "x = ", x);
      const double a = (j == 1) ? 1.0 : 0.5 * double(j - 1);
      D = w + a * D;
      if (std::abs(D) < tiny) D = tiny;
      C = w + a / C;
      if (std::abs(C) < tiny) C = tiny;
      D = 1.0 / D;
      const cd delta = C * D;
      f *= delta;
      if (std::abs(delta - 1.0) < 1e-16) break;
    }
    const double phase = 0.5 * pi * ax * ax;
    const cd erfc = cd(std::cos(phase), std::sin(phase)) * f / std::sqrt(pi);
    const cd r = cd(0.5, 0.5) * (1.0 - erfc);
    c = r.real();
    s = r.imag();
  }
  if (x < 0) {
    c = -c;
    s = -s;
  }
}

/// Largest phase change of cos/sin(theta) across one quadrature panel of the clothoid: with it
/// the 15-point Kronrod rule (exact to degree 22) is accurate to rounding (its error is below
/// 1^30 / 30!-ish times the panel length).
constexpr double clothoid_panel_phase = 1.0;
/// Cap on the panels of one clothoid (its total turning in radians, about): larger domains are
/// rejected as a precondition, not integrated for minutes.
constexpr std::size_t clothoid_panel_cap = 1000000;

/// int_a^b (cos theta(s), sin theta(s)) ds for theta(s) = theta0 + k0 s + c s^2 / 2 on n equal
/// panels (15-point Kronrod each).
inline void phase_integral(double theta0, double k0, double c, double a, double b, std::size_t n, double& ix,
                           double& iy) {
  ix = iy = 0;
  auto theta = [&](double s) { return theta0 + s * (k0 + 0.5 * c * s); };
  auto fx = [&](double s) { return std::cos(theta(s)); };
  auto fy = [&](double s) { return std::sin(theta(s)); };
  for (std::size_t k = 0; k < n; ++k) {
    const double lo = a + (b - a) * double(k) / double(n), hi = (k + 1 == n) ? b : a + (b - a) * double(k + 1) / double(n);
    ix += metrics::gauss_kronrod_15(fx, lo, hi, "Clothoid_2").kronrod;
    iy += metrics::gauss_kronrod_15(fy, lo, hi, "Clothoid_2").kronrod;
  }
}

/// Panels needed on [a,b] so that each turns by at most clothoid_panel_phase (|theta'| is
/// linear, so its maximum is at an end). Throws Precondition_error above clothoid_panel_cap.
inline std::size_t phase_panels(double k0, double c, double a, double b) {
  const double turn = std::fabs(b - a) * std::max(std::fabs(k0 + c * a), std::fabs(k0 + c * b));
  require(turn / clothoid_panel_phase < double(clothoid_panel_cap), "Clothoid_2: the curve turns by ", turn,
          " rad between s = ", a, " and s = ", b, ", more than the cap of ", double(clothoid_panel_cap), " rad");
  return std::size_t(std::ceil(turn / clothoid_panel_phase)) + 1;
}

} // namespace parametric
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_PARAMETRIC_FRESNEL_H
