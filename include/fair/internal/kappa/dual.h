// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// A forward-mode automatic-differentiation number with a fixed number N of partial
// derivatives, used by the kappa-curve solver to obtain the exact (to rounding) Jacobian of
// its residuals: every residual of the solver depends on at most 16 unknowns, so its
// gradient is carried along with its value at a cost of about N+1 flops per operation.
//
// Accuracy: derivatives are as accurate as the value (no finite differences). abs() and
// max() use the derivative of the active branch (a valid element of the Clarke generalised
// gradient at the kink).

#ifndef FAIR_INTERNAL_KAPPA_DUAL_H
#define FAIR_INTERNAL_KAPPA_DUAL_H

#include <array>
#include <cmath>

namespace fair {
namespace internal {
namespace kappa {

template <int N>
struct Dual {
  double v = 0.0;
  std::array<double, N> d{};

  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT: constants convert implicitly
  static Dual variable(double value, int slot) {
    Dual r(value);
    r.d[slot] = 1.0;
    return r;
  }

  Dual& operator+=(const Dual& o) { v += o.v; for (int i = 0; i < N; ++i) d[i] += o.d[i]; return *this; }
  Dual& operator-=(const Dual& o) { v -= o.v; for (int i = 0; i < N; ++i) d[i] -= o.d[i]; return *this; }
  Dual& operator*=(const Dual& o) {
    for (int i = 0; i < N; ++i) d[i] = d[i] * o.v + v * o.d[i];
    v *= o.v;
    return *this;
  }
  Dual& operator/=(const Dual& o) {
    const double inv = 1.0 / o.v, q = v * inv;
    for (int i = 0; i < N; ++i) d[i] = (d[i] - q * o.d[i]) * inv;
    v = q;
    return *this;
  }
  friend Dual operator+(Dual a, const Dual& b) { return a += b; }
  friend Dual operator-(Dual a, const Dual& b) { return a -= b; }
  friend Dual operator*(Dual a, const Dual& b) { return a *= b; }
  friend Dual operator/(Dual a, const Dual& b) { return a /= b; }
  friend Dual operator+(Dual a, double b) { a.v += b; return a; }
  friend Dual operator+(double b, Dual a) { a.v += b; return a; }
  friend Dual operator-(Dual a, double b) { a.v -= b; return a; }
  friend Dual operator-(double b, const Dual& a) { Dual r = -a; r.v += b; return r; }
  friend Dual operator*(Dual a, double b) { a.v *= b; for (int i = 0; i < N; ++i) a.d[i] *= b; return a; }
  friend Dual operator*(double b, Dual a) { return a * b; }
  friend Dual operator/(Dual a, double b) { return a * (1.0 / b); }
  friend Dual operator/(double b, const Dual& a) { return Dual(b) / a; }
  Dual operator-() const { Dual r; r.v = -v; for (int i = 0; i < N; ++i) r.d[i] = -d[i]; return r; }
};

template <int N> inline Dual<N> sqrt(const Dual<N>& a) {
  Dual<N> r;
  r.v = std::sqrt(a.v);
  const double f = r.v > 0.0 ? 0.5 / r.v : 0.0;
  for (int i = 0; i < N; ++i) r.d[i] = f * a.d[i];
  return r;
}
template <int N> inline Dual<N> abs(const Dual<N>& a) { return a.v < 0.0 ? -a : a; }
template <int N> inline double value(const Dual<N>& a) { return a.v; }
inline double value(double a) { return a; }
using std::abs;
using std::sqrt;

/// max(a, c) for a constant c (the clamp of eq. 16).
template <int N> inline Dual<N> max_with(const Dual<N>& a, double c) { return a.v > c ? a : Dual<N>(c); }
inline double max_with(double a, double c) { return a > c ? a : c; }

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_DUAL_H
