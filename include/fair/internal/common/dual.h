// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The library's one forward-mode dual number: a value, its gradient and (if S, second order) its
// symmetric Hessian with respect to N local variables. A local function written once, templated
// on its scalar, is evaluated with double (value), Dual<N> (exact gradient: the kappa-curve
// Jacobian, kappa/system.h and kappa/jacobian.h; the gradient of the optimal-curve functional) or
// Dual<N, true> (exact gradient and Hessian: the Newton system of the optimal-curve functional,
// optimal/functional.h). Only the operations those functions use are provided. Every operation
// propagates the exact first and second derivatives, no truncation error:
//   (a b)' = a' b + a b',   (a / b)' = (a' - (a / b) b') / b,
//   (a b)'' = a'' b + a b'' + a' b'^T + b' a'^T,   f(a)'' = f'(a) a'' + f''(a) a' a'^T.
// First order divides by the quotient rule above (one division per quotient); second order
// multiplies by the reciprocal 1/b, whose Hessian is a chain rule (f(b) = 1/b). The two orders
// therefore round a quotient's gradient differently in the last bit; each is the formula its
// callers were validated with.
//
// abs(), max_with() use the derivative of the active branch (an element of the Clarke
// generalised gradient at the kink); abs_pow() is |a|^alpha with the conventions stated there.

#ifndef FAIR_INTERNAL_COMMON_DUAL_H
#define FAIR_INTERNAL_COMMON_DUAL_H

#include <cmath>

namespace fair {
namespace internal {
namespace common {

/// Tag of the constructor that leaves the derivatives uninitialised, for results whose every entry is
/// written next (zeroing ~100 doubles per operation showed in profiles).
struct No_init {};

template <int N, bool S = false>
struct Dual {
  static constexpr bool second = S;
  double v;
  double g[N];
  double h[S ? N * N : 1];  // row-major, symmetric (exactly: every update is symmetric in i, j)

  Dual() : v(0) { zero(); }
  Dual(double value) : v(value) { zero(); }  // NOLINT: a constant (mixes with double in templated code)
  Dual(No_init, double value) : v(value) {
    if constexpr (!S) h[0] = 0;  // the placeholder of first order: defined, so that copies are
  }
  /// The independent variable number i (0-based) with the given value.
  static Dual variable(int i, double value) {
    Dual d(value);
    d.g[i] = 1;
    return d;
  }

private:
  void zero() {
    for (int i = 0; i < N; ++i) g[i] = 0;
    for (double& x : h) x = 0;
  }
};

/// The result of a unary function f at a: f(a), f'(a) a', f'(a) a'' + f''(a) a' a'^T.
template <int N, bool S>
inline Dual<N, S> chain(const Dual<N, S>& a, double f, double df, double ddf) {
  Dual<N, S> r(No_init(), f);
  for (int i = 0; i < N; ++i) r.g[i] = df * a.g[i];
  if constexpr (S)
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) r.h[i * N + j] = df * a.h[i * N + j] + ddf * (a.g[i] * a.g[j]);
  return r;
}

template <int N, bool S> inline Dual<N, S> operator+(const Dual<N, S>& a, const Dual<N, S>& b) {
  Dual<N, S> r(No_init(), a.v + b.v);
  for (int i = 0; i < N; ++i) r.g[i] = a.g[i] + b.g[i];
  if constexpr (S) for (int i = 0; i < N * N; ++i) r.h[i] = a.h[i] + b.h[i];
  return r;
}
template <int N, bool S> inline Dual<N, S> operator-(const Dual<N, S>& a, const Dual<N, S>& b) {
  Dual<N, S> r(No_init(), a.v - b.v);
  for (int i = 0; i < N; ++i) r.g[i] = a.g[i] - b.g[i];
  if constexpr (S) for (int i = 0; i < N * N; ++i) r.h[i] = a.h[i] - b.h[i];
  return r;
}
template <int N, bool S> inline Dual<N, S> operator-(const Dual<N, S>& a) {
  if constexpr (S) {
    return chain(a, -a.v, -1.0, 0.0);
  } else {
    Dual<N, S> r(No_init(), -a.v);
    for (int i = 0; i < N; ++i) r.g[i] = -a.g[i];
    return r;
  }
}
template <int N, bool S> inline Dual<N, S> operator*(const Dual<N, S>& a, const Dual<N, S>& b) {
  Dual<N, S> r(No_init(), a.v * b.v);
  for (int i = 0; i < N; ++i) r.g[i] = a.g[i] * b.v + a.v * b.g[i];
  if constexpr (S)
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        r.h[i * N + j] = a.h[i * N + j] * b.v + a.v * b.h[i * N + j] + a.g[i] * b.g[j] + b.g[i] * a.g[j];
  return r;
}
template <int N, bool S> inline Dual<N, S> operator*(double s, const Dual<N, S>& a) {
  Dual<N, S> r(No_init(), s * a.v);
  for (int i = 0; i < N; ++i) r.g[i] = s * a.g[i];
  if constexpr (S) for (int i = 0; i < N * N; ++i) r.h[i] = s * a.h[i];
  return r;
}
template <int N, bool S> inline Dual<N, S> operator*(const Dual<N, S>& a, double s) { return s * a; }
template <int N, bool S> inline Dual<N, S> operator+(const Dual<N, S>& a, double s) { Dual<N, S> r = a; r.v += s; return r; }
template <int N, bool S> inline Dual<N, S> operator+(double s, const Dual<N, S>& a) { return a + s; }
template <int N, bool S> inline Dual<N, S> operator-(const Dual<N, S>& a, double s) { Dual<N, S> r = a; r.v -= s; return r; }
template <int N, bool S> inline Dual<N, S> operator-(double s, const Dual<N, S>& a) { return (-a) + s; }
/// 1/a: f' = -1/a^2, f'' = 2/a^3.
template <int N, bool S> inline Dual<N, S> reciprocal(const Dual<N, S>& a) {
  const double r = 1 / a.v;
  return chain(a, r, -r * r, 2 * r * r * r);
}
template <int N, bool S> inline Dual<N, S> operator/(const Dual<N, S>& a, const Dual<N, S>& b) {
  if constexpr (S) {
    return a * reciprocal(b);
  } else {  // the quotient rule
    const double inv = 1.0 / b.v, q = a.v * inv;
    Dual<N, S> r(No_init(), q);
    for (int i = 0; i < N; ++i) r.g[i] = (a.g[i] - q * b.g[i]) * inv;
    return r;
  }
}
template <int N, bool S> inline Dual<N, S> operator/(const Dual<N, S>& a, double s) { return (1 / s) * a; }
template <int N, bool S> inline Dual<N, S> operator/(double s, const Dual<N, S>& a) {
  if constexpr (S) {
    return s * reciprocal(a);
  } else {  // the quotient rule with a constant numerator
    const double inv = 1.0 / a.v, q = s * inv;
    Dual<N, S> r(No_init(), q);
    for (int i = 0; i < N; ++i) r.g[i] = (0.0 - q * a.g[i]) * inv;
    return r;
  }
}

/// sqrt(a); at a = 0 the first-order gradient is 0 (the kappa-curve weight of eq. 15 at a
/// degenerate piece), the second-order one infinite.
template <int N, bool S> inline Dual<N, S> sqrt(const Dual<N, S>& a) {
  const double r = std::sqrt(a.v);
  if constexpr (S) {
    return chain(a, r, 0.5 / r, -0.25 / (r * a.v));
  } else {
    const double f = r > 0.0 ? 0.5 / r : 0.0;
    Dual<N, S> d(No_init(), r);
    for (int i = 0; i < N; ++i) d.g[i] = f * a.g[i];
    return d;
  }
}
template <int N, bool S> inline Dual<N, S> sin(const Dual<N, S>& a) {
  const double s = std::sin(a.v), c = std::cos(a.v);
  return chain(a, s, c, -s);
}
template <int N, bool S> inline Dual<N, S> cos(const Dual<N, S>& a) {
  const double s = std::sin(a.v), c = std::cos(a.v);
  return chain(a, c, -s, -c);
}
/// atan2(y, x) for (x, y) != (0, 0): d = (x dy - y dx)/(x^2 + y^2), second order by the product rule
/// of the dual arithmetic (u = x dy - y dx is not a dual, so it is spelled out on the derivatives).
template <int N, bool S> inline Dual<N, S> atan2(const Dual<N, S>& y, const Dual<N, S>& x) {
  // phi(x, y): phi_x = -y/r2, phi_y = x/r2, phi_xx = 2xy/r2^2, phi_yy = -2xy/r2^2, phi_xy = (y^2-x^2)/r2^2.
  const double r2 = x.v * x.v + y.v * y.v, r4 = r2 * r2;
  const double px = -y.v / r2, py = x.v / r2;
  const double pxx = 2 * x.v * y.v / r4, pyy = -pxx, pxy = (y.v * y.v - x.v * x.v) / r4;
  Dual<N, S> r(No_init(), std::atan2(y.v, x.v));
  for (int i = 0; i < N; ++i) r.g[i] = px * x.g[i] + py * y.g[i];
  if constexpr (S)
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        r.h[i * N + j] = px * x.h[i * N + j] + py * y.h[i * N + j] + pxx * (x.g[i] * x.g[j]) +
                         pyy * (y.g[i] * y.g[j]) + pxy * (x.g[i] * y.g[j] + y.g[i] * x.g[j]);
  return r;
}

/// |a|^alpha for alpha >= 1. At a = 0: value 0, derivative 0 (for alpha = 1 the minimal-norm
/// subgradient), second derivative 2 for alpha = 2 and 0 otherwise (for 1 <= alpha < 2 the true second
/// derivative is unbounded near 0; for alpha > 2 it is 0).
inline double abs_pow(double a, double alpha) {
  if (alpha == 2) return a * a;
  return std::pow(std::fabs(a), alpha);
}
template <int N, bool S> inline Dual<N, S> abs_pow(const Dual<N, S>& a, double alpha) {
  if (alpha == 2) return a * a;
  const double m = std::fabs(a.v);
  if (m == 0) return chain(a, 0.0, 0.0, 0.0);
  const double sign = a.v > 0 ? 1.0 : -1.0;
  const double p = std::pow(m, alpha - 2);  // |a|^(alpha-2)
  return chain(a, p * m * m, alpha * p * m * sign, alpha * (alpha - 1) * p);
}

/// |a| with the derivative of the active branch (-a below 0).
template <int N, bool S> inline Dual<N, S> abs(const Dual<N, S>& a) { return a.v < 0.0 ? -a : a; }
/// The value of a scalar, double or dual.
template <int N, bool S> inline double value(const Dual<N, S>& a) { return a.v; }
inline double value(double a) { return a; }
/// max(a, c) for a constant c (the clamp of the kappa-curve weight, eq. 16).
template <int N, bool S> inline Dual<N, S> max_with(const Dual<N, S>& a, double c) { return a.v > c ? a : Dual<N, S>(c); }
inline double max_with(double a, double c) { return a > c ? a : c; }

} // namespace common
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_COMMON_DUAL_H
