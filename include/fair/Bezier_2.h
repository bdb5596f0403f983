// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Bezier_2<Kernel>: a planar polynomial Bezier piece of any degree n >= 0,
//   c(t) = sum_{i=0}^{n} B_i^n(t) P_i,   B_i^n(t) = C(n,i) t^i (1-t)^(n-i),   t in [0,1].
// Models the CurvePiece_2 concept of doc/contributing.md.
//
// Accuracy: point(), derivative(), second_derivative(), nth_derivative(), split() and
// hodograph() only add, subtract and multiply in Kernel::FT (de Casteljau's algorithm), so they
// are exact in an exact kernel (EPECK, Simple_cartesian<Gmpq>) and backward stable in double.
// curvature() is computed in double from double control points (internal/common/curvature.h).

#ifndef FAIR_BEZIER_2_H
#define FAIR_BEZIER_2_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Errors.h>
#include <fair/internal/common/curvature.h>

#include <CGAL/number_utils.h>
#include <CGAL/Origin.h>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {

template <class K>
class Bezier_2 {
public:
  typedef K Kernel;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;

  /// A degree-0 piece at the origin (needed by containers); prefer the other constructors.
  Bezier_2() : cp_(1, Point_2(CGAL::ORIGIN)) {}

  /// The piece with control points P_0..P_n (n = size - 1). Throws Precondition_error when empty.
  explicit Bezier_2(std::vector<Point_2> control_points) : cp_(std::move(control_points)) {
    internal::require(!cp_.empty(), "Bezier_2: needs at least one control point");
  }

  /// The cubic piece P0 P1 P2 P3.
  Bezier_2(const Point_2& p0, const Point_2& p1, const Point_2& p2, const Point_2& p3)
    : cp_{p0, p1, p2, p3} {}

  /// The polynomial degree n (number of control points minus one).
  std::size_t degree() const { return cp_.size() - 1; }

  /// The control points P_0..P_n.
  const std::vector<Point_2>& control_points() const { return cp_; }
  const Point_2& control_point(std::size_t i) const {
    internal::require(i < cp_.size(), "Bezier_2::control_point: index ", i, " > degree ", degree());
    return cp_[i];
  }
  const Point_2& source() const { return cp_.front(); }
  const Point_2& target() const { return cp_.back(); }

  /// c(t), exact in an exact kernel (de Casteljau). Any t is accepted (extrapolation outside [0,1]).
  Point_2 point(const FT& t) const {
    std::vector<FT> x, y;
    coordinates(x, y);
    return Point_2(de_casteljau(x, t), de_casteljau(y, t));
  }

  /// c'(t) = n sum_i B_i^{n-1}(t) (P_{i+1} - P_i).
  Vector_2 derivative(const FT& t) const { return nth_derivative(t, 1); }

  /// c''(t).
  Vector_2 second_derivative(const FT& t) const { return nth_derivative(t, 2); }

  /// The k-th derivative c^(k)(t) = n!/(n-k)! sum_i B_i^{n-k}(t) Delta^k P_i (zero when k > n).
  Vector_2 nth_derivative(const FT& t, std::size_t k) const {
    const std::size_t n = degree();
    if (k > n) return Vector_2(FT(0), FT(0));
    std::vector<FT> x, y;
    coordinates(x, y);
    FT factor(1);
    for (std::size_t j = 0; j < k; ++j) {
      forward_difference(x);
      forward_difference(y);
      factor *= FT(static_cast<int>(n - j));
    }
    return Vector_2(factor * de_casteljau(x, t), factor * de_casteljau(y, t));
  }

  /// Signed curvature kappa(t) = (c' x c'') / |c'|^3, computed in double from double control
  /// points, scale-safe (no overflow or underflow unless kappa itself is not representable).
  /// Throws Precondition_error at a singular point (c'(t) = 0 in double), where it is undefined,
  /// and when |kappa(t)| exceeds the double range (a tiny piece: it would be inf).
  double curvature(double t) const {
    double d1x, d1y, d2x, d2y;
    derivatives_double(t, d1x, d1y, d2x, d2y);
    const double speed = std::hypot(d1x, d1y);
    internal::require(speed > 0 && std::isfinite(speed), "Bezier_2::curvature: singular point at t = ", t,
                      " (c'(t) = (", d1x, ", ", d1y, "))");
    const double k = internal::common::signed_curvature(d1x, d1y, d2x, d2y);
    internal::require(std::isfinite(k), "Bezier_2::curvature: |kappa(", t, ")| is beyond the double range (c'(t) = (",
                      d1x, ", ", d1y, "), c''(t) = (", d2x, ", ", d2y, "))");
    return k;
  }

  /// c'(t) and c''(t) in double (fast path for sampling and quadrature).
  void derivatives_double(double t, double& d1x, double& d1y, double& d2x, double& d2y) const {
    const std::size_t n = degree();
    d1x = d1y = d2x = d2y = 0;
    if (n == 0) return;
    std::vector<double> x(cp_.size()), y(cp_.size());
    for (std::size_t i = 0; i < cp_.size(); ++i) {
      x[i] = CGAL::to_double(cp_[i].x());
      y[i] = CGAL::to_double(cp_[i].y());
    }
    forward_difference(x);
    forward_difference(y);
    const double dn = static_cast<double>(n);
    if (n >= 2) {
      std::vector<double> x2 = x, y2 = y;
      forward_difference(x2);
      forward_difference(y2);
      const double f2 = dn * (dn - 1);
      d2x = f2 * de_casteljau(x2, t);
      d2y = f2 * de_casteljau(y2, t);
    }
    d1x = dn * de_casteljau(x, t);
    d1y = dn * de_casteljau(y, t);
  }

  /// The coordinate functions x(t), y(t) as fair::Bernstein_polynomial (coefficients = the
  /// control point coordinates), for root finding and exact polynomial algebra.
  Bernstein_polynomial<FT> x_polynomial() const {
    std::vector<FT> x, y;
    coordinates(x, y);
    return Bernstein_polynomial<FT>(std::move(x));
  }
  Bernstein_polynomial<FT> y_polynomial() const {
    std::vector<FT> x, y;
    coordinates(x, y);
    return Bernstein_polynomial<FT>(std::move(y));
  }

  /// The hodograph c'(t) as a Bezier piece of degree n-1 whose control "points" are
  /// O + n (P_{i+1} - P_i). The hodograph of a degree-0 piece is the degree-0 piece at O.
  Bezier_2 hodograph() const {
    const std::size_t n = degree();
    if (n == 0) return Bezier_2();
    std::vector<Point_2> h;
    h.reserve(n);
    const FT fn(static_cast<int>(n));
    for (std::size_t i = 0; i < n; ++i)
      h.push_back(Point_2(fn * (cp_[i + 1].x() - cp_[i].x()), fn * (cp_[i + 1].y() - cp_[i].y())));
    return Bezier_2(std::move(h));
  }

  /// The two pieces c|[0,t] and c|[t,1], reparametrised to [0,1] (de Casteljau subdivision).
  /// Throws Precondition_error unless 0 < t < 1.
  std::pair<Bezier_2, Bezier_2> split(const FT& t) const {
    internal::require(FT(0) < t && t < FT(1), "Bezier_2::split: t = ", CGAL::to_double(t),
                      " is not in (0,1)");
    std::vector<FT> x, y;
    coordinates(x, y);
    const std::size_t m = x.size();
    std::vector<Point_2> left, right(m, Point_2(CGAL::ORIGIN));
    left.reserve(m);
    left.push_back(Point_2(x[0], y[0]));
    right[m - 1] = Point_2(x[m - 1], y[m - 1]);
    const FT s = FT(1) - t;
    for (std::size_t r = 1; r < m; ++r) {
      for (std::size_t i = 0; i + r < m; ++i) {
        x[i] = s * x[i] + t * x[i + 1];
        y[i] = s * y[i] + t * y[i + 1];
      }
      left.push_back(Point_2(x[0], y[0]));
      right[m - 1 - r] = Point_2(x[m - 1 - r], y[m - 1 - r]);
    }
    return std::make_pair(Bezier_2(std::move(left)), Bezier_2(std::move(right)));
  }

  /// The piece restricted to [t0,t1] (0 <= t0 < t1 <= 1), reparametrised to [0,1].
  Bezier_2 subcurve(const FT& t0, const FT& t1) const {
    internal::require(FT(0) <= t0 && t0 < t1 && t1 <= FT(1), "Bezier_2::subcurve: [",
                      CGAL::to_double(t0), ", ", CGAL::to_double(t1), "] is not a subinterval of [0,1]");
    Bezier_2 c = *this;
    if (t1 < FT(1)) c = c.split(t1).first;
    if (t0 > FT(0)) c = c.split(t0 / t1).second;
    return c;
  }

  /// The same curve traversed backwards: c(1-t).
  Bezier_2 reversed() const { return Bezier_2(std::vector<Point_2>(cp_.rbegin(), cp_.rend())); }

  /// The same curve as a piece of degree n+1 (degree elevation).
  Bezier_2 elevated() const {
    const std::size_t n = degree();
    std::vector<Point_2> q;
    q.reserve(n + 2);
    q.push_back(cp_.front());
    const FT n1(static_cast<int>(n + 1));
    for (std::size_t i = 1; i <= n; ++i) {
      const FT a = FT(static_cast<int>(i)) / n1, b = FT(1) - a;
      q.push_back(Point_2(a * cp_[i - 1].x() + b * cp_[i].x(), a * cp_[i - 1].y() + b * cp_[i].y()));
    }
    q.push_back(cp_.back());
    return Bezier_2(std::move(q));
  }

  friend bool operator==(const Bezier_2& a, const Bezier_2& b) { return a.cp_ == b.cp_; }
  friend bool operator!=(const Bezier_2& a, const Bezier_2& b) { return !(a == b); }

private:
  void coordinates(std::vector<FT>& x, std::vector<FT>& y) const {
    x.resize(cp_.size());
    y.resize(cp_.size());
    for (std::size_t i = 0; i < cp_.size(); ++i) {
      x[i] = cp_[i].x();
      y[i] = cp_[i].y();
    }
  }
  template <class T>
  static void forward_difference(std::vector<T>& v) {
    for (std::size_t i = 0; i + 1 < v.size(); ++i) v[i] = v[i + 1] - v[i];
    v.pop_back();
  }
  // de Casteljau evaluation of the scalar Bernstein coefficients b (destroyed).
  template <class T, class U>
  static T de_casteljau(std::vector<T>& b, const U& t) {
    if (b.empty()) return T(0);
    const T tt(t);
    const T s = T(1) - tt;
    for (std::size_t r = b.size() - 1; r > 0; --r)
      for (std::size_t i = 0; i < r; ++i) b[i] = s * b[i] + tt * b[i + 1];
    return b[0];
  }

  std::vector<Point_2> cp_;
};

} // namespace fair

#endif // FAIR_BEZIER_2_H
