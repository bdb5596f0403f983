// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Scale-robust double arithmetic for Rational_quadratic_bezier_2 (the curvature, end
// curvatures of eq. 5, eccentricity and eq.-15 weight of a conic piece).
//
// Method. Everything double-valued the piece reports depends on the control points through the
// edge vectors e1 = P1-P0, e2 = P2-P1, a = P2-P0 only. These are formed once in double (rounded
// as usual; if a difference overflows, from the halved coordinates), then multiplied by the
// power of two 2^-k that brings their largest component into [1,2): exact (no rounding), so
// the scaled vectors carry the same relative accuracy as the unscaled ones, and every product
// formed from them (D, |V|^3, ...) stays far from overflow and underflow. Results are then
// rescaled by an exact power of two, tracked as a (mantissa, exponent) pair so that no
// intermediate overflows or underflows while the true result is representable. When the true
// result is not representable in double (|result| > DBL_MAX, or so small that it rounds to
// zero), Precondition_error is thrown with the approximate base-2 exponent; never NaN.
//
// The signed double area D = det(e1, e2) is recomputed from the exact rational values of the
// inputs whenever the double determinant cancels (|D| < 2^-40 max|e|^2): the decision that D is
// nonzero is exact (the piece's orientation is decided exactly), and this keeps its relative
// accuracy near 1e-16 even for nearly collinear control points.

#ifndef FAIR_INTERNAL_CONIC_SCALED_H
#define FAIR_INTERNAL_CONIC_SCALED_H

#include <fair/Errors.h>
#include <fair/internal/common/exact_conversion.h>

#include <CGAL/Gmpq.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <gmp.h>

namespace fair {
namespace internal {
namespace conic {

/// A double value m 2^e with m = 0 or 0.5 <= |m| < 1 (never overflows or underflows).
struct Scaled_double {
  double m = 0;
  long e = 0;
  static Scaled_double of(double x) {
    Scaled_double r;
    int ex = 0;
    r.m = std::frexp(x, &ex);
    r.e = ex;
    return r;
  }
  Scaled_double& operator*=(const Scaled_double& o) {
    int ex = 0;
    m = std::frexp(m * o.m, &ex);
    e += o.e + ex;
    return *this;
  }
  Scaled_double& operator/=(const Scaled_double& o) {
    int ex = 0;
    m = std::frexp(m / o.m, &ex);
    e += ex - o.e;
    return *this;
  }
  /// The value as a double: throws Precondition_error (message prefixed by `what`) when it is
  /// not representable (overflow, or a nonzero value below the smallest subnormal).
  double to_double(const char* what) const {
    if (m == 0) return 0.0;
    require(std::isfinite(m), what, " is not representable in double (", m, ")");
    require(e <= 1024, what, " is not representable in double: |value| ~ 2^", e, " > DBL_MAX");
    require(e >= -1073, what, " is not representable in double: |value| ~ 2^", e, " underflows to zero");
    return std::ldexp(m, static_cast<int>(e));
  }
};

/// The exact value of a rational as a Scaled_double (rounded to ~53 bits).
inline Scaled_double scaled_from_gmpq(const CGAL::Gmpq& q) {
  Scaled_double r;
  if (CGAL::is_zero(q)) return r;
  long en = 0, ed = 0;
  const double n = mpz_get_d_2exp(&en, mpq_numref(q.mpq()));
  const double d = mpz_get_d_2exp(&ed, mpq_denref(q.mpq()));
  r = Scaled_double::of(n / d);
  r.e += en - ed;
  return r;
}

/// The edge vectors of a control triangle scaled by an exact power of two:
/// e[0] = (P1-P0) 2^-k, e[1] = (P2-P1) 2^-k, e[2] = (P2-P0) 2^-k (each rounded once, as the plain
/// double differences), largest component in [1,2). `degenerate` is true iff all are zero.
struct Scaled_edges {
  double ex[3] = {0, 0, 0}, ey[3] = {0, 0, 0};
  int k = 0;
  bool degenerate = true;

  Scaled_edges() = default;
  Scaled_edges(const double* x, const double* y) {
    const int from[3] = {0, 1, 0}, to[3] = {1, 2, 2};
    int h = 0;
    for (int pass = 0; pass < 2; ++pass) {
      const double f = pass == 0 ? 1.0 : 0.5; // halving: only when a difference overflows
      bool finite = true;
      for (int i = 0; i < 3; ++i) {
        ex[i] = f * x[to[i]] - f * x[from[i]];
        ey[i] = f * y[to[i]] - f * y[from[i]];
        finite = finite && std::isfinite(ex[i]) && std::isfinite(ey[i]);
      }
      if (finite) break;
      h = 1;
    }
    double m = 0;
    for (int i = 0; i < 3; ++i) m = std::max({m, std::abs(ex[i]), std::abs(ey[i])});
    degenerate = m == 0;
    if (degenerate) return;
    const int s = std::ilogb(m);
    for (int i = 0; i < 3; ++i) {
      ex[i] = std::ldexp(ex[i], -s);
      ey[i] = std::ldexp(ey[i], -s);
    }
    k = s + h;
  }
  double squared_length(int i) const { return ex[i] * ex[i] + ey[i] * ey[i]; }
};

/// Below this |det(e1, e2)| of the scaled edges (largest component in [1,2)) the double
/// determinant may have lost a quarter of its 53 bits or more to cancellation: D is then
/// recomputed from the exact inputs.
constexpr double area_cancellation_threshold = 0x1p-40;

/// D = det(P1-P0, P2-P1) as an unscaled Scaled_double: from the scaled edges `e` of p0, p1, p2,
/// or from the exact rational values of the points when the double determinant cancels.
template <class Point_2>
Scaled_double twice_signed_area(const Scaled_edges& e, const Point_2& p0, const Point_2& p1, const Point_2& p2) {
  const double ds = e.ex[0] * e.ey[1] - e.ey[0] * e.ex[1];
  if (std::abs(ds) >= area_cancellation_threshold) {
    Scaled_double area = Scaled_double::of(ds);
    area.e += 2L * e.k;
    return area;
  }
  using common::to_gmpq;
  const CGAL::Gmpq x0 = to_gmpq(p0.x()), y0 = to_gmpq(p0.y()), x1 = to_gmpq(p1.x()), y1 = to_gmpq(p1.y());
  const CGAL::Gmpq x2 = to_gmpq(p2.x()), y2 = to_gmpq(p2.y());
  return scaled_from_gmpq((x1 - x0) * (y2 - y1) - (y1 - y0) * (x2 - x1));
}

/// eq. 5, signed, on the scaled edge i (0: P1-P0, 1: P2-P1): D / (2 w^2 |e_i|^3), rescaled
/// exactly; `area` is D unscaled. \throws Precondition_error (prefixed by `what`) if the value is
/// not representable in double.
inline double end_curvature(const Scaled_double& area, const Scaled_edges& e, double w, int i, const char* what) {
  const double l = std::hypot(e.ex[i], e.ey[i]); // in [1, 2 sqrt 2) or exactly scaled
  Scaled_double r = area, wq = Scaled_double::of(w), lq = Scaled_double::of(l);
  r /= wq;
  r /= wq;
  r /= lq;
  r /= lq;
  r /= lq;
  r.e -= 1L + 3L * e.k;
  return r.to_double(what);
}

/// eq. 15 squared, |P2-P0|^2 / (2 (|P0-P1|^2 + |P2-P1|^2)), for double points, from the scaled
/// edges (no overflow or underflow at any scale). \throws Precondition_error if P0 == P1 == P2.
inline double minimum_eccentricity_weight_squared(double x0, double y0, double x1, double y1, double x2, double y2) {
  const double x[3] = {x0, x1, x2}, y[3] = {y0, y1, y2};
  const Scaled_edges e(x, y);
  const double den = 2.0 * (e.squared_length(0) + e.squared_length(1));
  require(!e.degenerate && den > 0 && std::isfinite(den),
          "minimum_eccentricity_weight_squared (eq. 15): P0 == P1 == P2 = (", x[1], ", ", y[1], ")");
  return e.squared_length(2) / den;
}

} // namespace conic
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_CONIC_SCALED_H
