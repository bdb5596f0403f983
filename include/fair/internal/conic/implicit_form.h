// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The conic carrying a standard-form rational quadratic piece: the implicit equation (eq. 14 of
// Yan, Schiller, Schaefer, "Circle reproduction with interpolatory curves at local maximal
// curvature points") and the eccentricity, behind Rational_quadratic_bezier_2::
// implicit_coefficients() and eccentricity().
//
// Implicit equation. The resultant of eq. 1, written in barycentric coordinates of the control
// triangle, where the curve is tau1^2 = 4 w^2 tau0 tau2: F = L1^2 - 4 w^2 L0 L2 with the affine
// functions L0(X) = det(P1-X, P2-X), L1(X) = det(P2-X, P0-X), L2(X) = det(P0-X, P1-X)
// (L_i = D tau_i). Normalisation: F(P1) = L1(P1)^2 = D^2 > 0 (L0(P1) = L2(P1) = 0).
//
// Eccentricity. eps = sqrt(2R / (eta (a + c) + R)), R = sqrt((a-c)^2 + b^2), eta = -sign(det M)
// of the 3x3 conic matrix (the paper's formula assumes eta = 1). The circle test
// (a-c)^2 + b^2 == 0 and eta are decided exactly on the exact input values (for large w the
// conic is nearly the line pair P0P1, P1P2, det M nearly 0, and its sign in double would be
// rounding noise). The double part runs on a copy translated to P0 and scaled by an exact power
// of two (eccentricity is similarity invariant), with the quadratic part divided by 4 w^2 when
// that exceeds 1, so no overflow or underflow at any scale or weight.

#ifndef FAIR_INTERNAL_CONIC_IMPLICIT_FORM_H
#define FAIR_INTERNAL_CONIC_IMPLICIT_FORM_H

#include <fair/Errors.h>
#include <fair/internal/conic/scaled.h>

#include <CGAL/Gmpq.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>

namespace fair {
namespace internal {
namespace conic {

/// Coefficients {a, b, c, d, e, f} of F = a x^2 + b xy + c y^2 + d x + e y + f (eq. 14) of the
/// conic through the control points (x[i], y[i]) with weight w, in any number type (exact for
/// an exact one).
template <class NT>
std::array<NT, 6> implicit_coefficients(const NT (&x)[3], const NT (&y)[3], const NT& w) {
  NT al[3], be[3], ga[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    al[i] = y[j] - y[k];
    be[i] = x[k] - x[j];
    ga[i] = x[j] * y[k] - y[j] * x[k];
  }
  const NT m = NT(4) * w * w;
  return {{al[1] * al[1] - m * al[0] * al[2],
           NT(2) * al[1] * be[1] - m * (al[0] * be[2] + be[0] * al[2]),
           be[1] * be[1] - m * be[0] * be[2],
           NT(2) * al[1] * ga[1] - m * (al[0] * ga[2] + ga[0] * al[2]),
           NT(2) * be[1] * ga[1] - m * (be[0] * ga[2] + ga[0] * be[2]),
           ga[1] * ga[1] - m * ga[0] * ga[2]}};
}

/// The eccentricity of a non-parabolic conic (w != 1), see the file comment. `exact` are the
/// exact eq.-14 coefficients, `e` the scaled edges of the control triangle, `w` the weight.
inline double eccentricity(const std::array<CGAL::Gmpq, 6>& exact, const Scaled_edges& e, double w) {
  typedef CGAL::Gmpq Q;
  const Q& a = exact[0];
  const Q& b = exact[1];
  const Q& c = exact[2];
  const Q& d = exact[3];
  const Q& ee = exact[4];
  const Q& f = exact[5];
  if (CGAL::is_zero(a - c) && CGAL::is_zero(b)) return 0.0;
  // 4 det [[a, b/2, d/2], [b/2, c, e/2], [d/2, e/2, f]]
  const Q det4 = Q(4) * a * c * f + b * ee * d - a * ee * ee - c * d * d - f * b * b;
  const double eta = CGAL::sign(det4) == CGAL::POSITIVE ? -1.0 : 1.0;

  const double X[3] = {0.0, e.ex[0], e.ex[2]}, Y[3] = {0.0, e.ey[0], e.ey[2]};
  double al[3], be[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    al[i] = Y[j] - Y[k]; be[i] = X[k] - X[j];
  }
  // The quadratic part of eq. 14 is u + m v with m = 4 w^2; for m > 1 it is divided by m
  // (the eccentricity is invariant under positive scaling), so that weights up to the largest
  // double do not overflow.
  const double m4 = 4.0 * w * w;
  const double s = m4 > 1.0 ? 1.0 / (4.0 * w) / w : 1.0, m = m4 > 1.0 ? 1.0 : m4;
  const double ad = s * al[1] * al[1] - m * al[0] * al[2];
  const double bd = s * 2.0 * al[1] * be[1] - m * (al[0] * be[2] + be[0] * al[2]);
  const double cd = s * be[1] * be[1] - m * be[0] * be[2];
  const double R = std::hypot(ad - cd, bd);
  const double den = eta * (ad + cd) + R;
  FAIR_ASSERT_MSG(den > 0 && R >= 0, "Rational_quadratic_bezier_2::eccentricity: R = ", R, ", eta (a+c) + R = ", den);
  return std::sqrt(2.0 * R / den);
}

} // namespace conic
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_CONIC_IMPLICIT_FORM_H
