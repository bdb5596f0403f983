// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Rational_bezier_2<Kernel>: a planar rational Bezier piece of any degree n >= 0,
//
//   c(t) = X(t) / W(t),   X(t) = sum_i B_i^n(t) w_i P_i,   W(t) = sum_i B_i^n(t) w_i,   t in [0,1],
//
// with control points P_i and weights w_i > 0. Unit (or all equal) weights give the polynomial
// Bezier piece. Models the CurvePiece_2 concept of doc/contributing.md.
//
// Method: the piece stores its control points and weights only; the homogeneous coordinates
// X, Y, W (fair::Bernstein_polynomial<FT> on request) are evaluated by de Casteljau on demand;
//   c   = X / W,
//   c'  = (X' W - X W') / W^2,
//   c'' = (X'' - 2 W' c' - W'' c) / W        (differentiate X = W c twice).
// Accuracy: point, derivative, second_derivative, squared_curvature and split only add,
// subtract, multiply and divide in FT, so they are exact in an exact kernel (EPECK,
// Simple_cartesian<Gmpq>); in double the de Casteljau evaluations are backward stable and the
// quotients add a few ulps. W(t) > 0 on [0,1] because every weight is positive, so no division
// by zero can occur for t in [0,1]. curvature() is computed in double from double copies of
// the control points, scale-safe (internal/common/curvature.h); it throws where the tangent
// vanishes (a cusp) instead of returning NaN.

#ifndef FAIR_RATIONAL_BEZIER_2_H
#define FAIR_RATIONAL_BEZIER_2_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Errors.h>
#include <fair/internal/common/curvature.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {

template <class K>
class Rational_quadratic_bezier_2;

template <class K>
class Rational_bezier_2 {
public:
  typedef K Kernel;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Bernstein_polynomial<FT> Polynomial;

  /// The piece with control points P_0..P_n and weights w_0..w_n.
  /// \throws Precondition_error if there is no control point, the sizes differ, a coordinate
  /// or weight is not finite, or a weight is <= 0.
  Rational_bezier_2(std::vector<Point_2> control_points, std::vector<FT> weights)
    : cp_(std::move(control_points)), w_(std::move(weights)) {
    init();
  }

  /// The polynomial Bezier piece (all weights 1).
  explicit Rational_bezier_2(std::vector<Point_2> control_points)
    : cp_(std::move(control_points)), w_(cp_.size(), FT(1)) {
    init();
  }

  /// The same conic arc as a general rational Bezier piece (weights 1, w, 1).
  explicit Rational_bezier_2(const Rational_quadratic_bezier_2<K>& q)
    : cp_(q.control_points()), w_(q.weights()) {
    init();
  }

  std::size_t degree() const { return cp_.size() - 1; }
  const std::vector<Point_2>& control_points() const { return cp_; }
  const std::vector<FT>& weights() const { return w_; }
  const Point_2& control_point(std::size_t i) const {
    internal::require(i < cp_.size(), "Rational_bezier_2::control_point: index ", i, " > degree ", degree());
    return cp_[i];
  }
  const FT& weight(std::size_t i) const {
    internal::require(i < w_.size(), "Rational_bezier_2::weight: index ", i, " > degree ", degree());
    return w_[i];
  }
  const Point_2& source() const { return cp_.front(); }
  const Point_2& target() const { return cp_.back(); }

  /// True iff all weights are equal, i.e. the piece is a polynomial Bezier curve (exact test
  /// in an exact kernel).
  bool is_polynomial() const {
    for (const FT& x : w_)
      if (x != w_.front()) return false;
    return true;
  }

  /// Homogeneous coordinates X, Y and W as Bernstein polynomials of degree n (built on call:
  /// the piece stores only its control points and weights).
  Polynomial homogeneous_x() const { return Polynomial(homogeneous(0)); }
  Polynomial homogeneous_y() const { return Polynomial(homogeneous(1)); }
  Polynomial homogeneous_w() const { return Polynomial(w_); }

  /// c(t) (exact in an exact kernel); t in [0,1].
  Point_2 point(const FT& t) const {
    check_parameter(t, "point");
    FT v[3][3];
    homogeneous_jet(t, 0, v);
    return Point_2(v[0][0] / v[0][2], v[0][1] / v[0][2]);
  }

  /// c'(t) (exact in an exact kernel); t in [0,1].
  Vector_2 derivative(const FT& t) const {
    check_parameter(t, "derivative");
    FT v[3][3];
    homogeneous_jet(t, 1, v);
    FT cx, cy, dx, dy;
    first_order(v, cx, cy, dx, dy);
    return Vector_2(dx, dy);
  }

  /// c''(t) (exact in an exact kernel); t in [0,1].
  Vector_2 second_derivative(const FT& t) const {
    check_parameter(t, "second_derivative");
    FT v[3][3];
    homogeneous_jet(t, 2, v);
    FT cx, cy, dx, dy;
    first_order(v, cx, cy, dx, dy);
    const FT &W = v[0][2], &W1 = v[1][2], &W2 = v[2][2];
    const FT ex = (v[2][0] - FT(2) * W1 * dx - W2 * cx) / W;
    const FT ey = (v[2][1] - FT(2) * W1 * dy - W2 * cy) / W;
    return Vector_2(ex, ey);
  }

  /// kappa(t)^2 = det(c', c'')^2 / |c'|^6, exact in an exact kernel.
  /// \throws Precondition_error where c'(t) = 0.
  FT squared_curvature(const FT& t) const {
    const Vector_2 d1 = derivative(t), d2 = second_derivative(t);
    const FT n2 = d1 * d1;
    internal::require(!CGAL::is_zero(n2), "Rational_bezier_2::squared_curvature: the tangent vanishes at t = ",
                      CGAL::to_double(t));
    const FT det = d1.x() * d2.y() - d1.y() * d2.x();
    return det * det / (n2 * n2 * n2);
  }

  /// Signed curvature det(c', c'') / |c'|^3 in double (from double control points), scale-safe:
  /// no overflow or underflow unless kappa itself is not representable (internal/common/curvature.h).
  /// \throws Precondition_error if t is not in [0,1], the tangent vanishes at t, or |kappa(t)|
  /// exceeds the double range (a tiny piece: it would be inf).
  double curvature(double t) const {
    internal::require(t >= 0 && t <= 1, "Rational_bezier_2::curvature: t = ", t, " is not in [0,1]");
    double cx, cy, dx, dy, ex, ey;
    double_derivatives(t, cx, cy, dx, dy, ex, ey);
    const double n = std::hypot(dx, dy);
    internal::require(n > 0 && std::isfinite(n), "Rational_bezier_2::curvature: the tangent vanishes at t = ", t,
                      " (|c'| = ", n, ")");
    const double k = internal::common::signed_curvature(dx, dy, ex, ey);
    internal::require(std::isfinite(k), "Rational_bezier_2::curvature: |kappa(", t,
                      ")| is beyond the double range (|c'| = ", n, ")");
    return k;
  }

  /// Homogeneous de Casteljau subdivision at s in (0,1): the pieces on [0,s] and [s,1], each
  /// reparametrised to [0,1]. Exact in an exact kernel; the weights stay positive.
  std::pair<Rational_bezier_2, Rational_bezier_2> split(const FT& s) const {
    internal::require(s > FT(0) && s < FT(1), "Rational_bezier_2::split: s = ", CGAL::to_double(s),
                      " is not in (0,1)");
    const std::pair<Polynomial, Polynomial> x = homogeneous_x().split(s), y = homogeneous_y().split(s),
                                            w = homogeneous_w().split(s);
    return std::make_pair(from_homogeneous(x.first, y.first, w.first),
                          from_homogeneous(x.second, y.second, w.second));
  }

  /// The same curve traversed backwards: c_rev(t) = c(1-t).
  Rational_bezier_2 reversed() const {
    return Rational_bezier_2(std::vector<Point_2>(cp_.rbegin(), cp_.rend()),
                             std::vector<FT>(w_.rbegin(), w_.rend()));
  }

private:
  static Rational_bezier_2 from_homogeneous(const Polynomial& x, const Polynomial& y, const Polynomial& w) {
    std::vector<Point_2> p;
    std::vector<FT> ws;
    for (std::size_t i = 0; i <= x.degree(); ++i) {
      p.push_back(Point_2(x[i] / w[i], y[i] / w[i]));
      ws.push_back(w[i]);
    }
    return Rational_bezier_2(std::move(p), std::move(ws));
  }

  void check_parameter(const FT& t, const char* fn) const {
    internal::require(t >= FT(0) && t <= FT(1), "Rational_bezier_2::", fn, ": t = ", CGAL::to_double(t),
                      " is not in [0,1]");
  }

  // The homogeneous coordinates (w_i x_i or w_i y_i) of coordinate k (0: x, 1: y).
  std::vector<FT> homogeneous(int k) const {
    std::vector<FT> h(cp_.size());
    for (std::size_t i = 0; i < cp_.size(); ++i) h[i] = w_[i] * (k == 0 ? cp_[i].x() : cp_[i].y());
    return h;
  }

  // c and c' from the homogeneous jet v (rows: X, X', X''; columns: x, y, w).
  static void first_order(const FT (&v)[3][3], FT& cx, FT& cy, FT& dx, FT& dy) {
    const FT &W = v[0][2], &W1 = v[1][2];
    cx = v[0][0] / W;
    cy = v[0][1] / W;
    dx = (v[1][0] - W1 * cx) / W;
    dy = (v[1][1] - W1 * cy) / W;
  }

  // de Casteljau of the m scalar Bernstein coefficients in b (destroyed) at t.
  template <class T>
  static T de_casteljau(T* b, std::size_t m, const T& t) {
    const T s = T(1) - t;
    for (std::size_t r = 1; r < m; ++r)
      for (std::size_t i = 0; i + r < m; ++i) b[i] = s * b[i] + t * b[i + 1];
    return b[0];
  }

  // v[d] = the d-th derivative (d <= order) of (X, Y, W) at t, each the de Casteljau value of
  // the derivative's Bernstein coefficients n (b_{i+1} - b_i) (applied d times): the arithmetic
  // of Bernstein_polynomial::derivative() and evaluate(), so the values are those of the
  // polynomial forms, without storing them (issue 23 §4: a piece is its control points and
  // weights; building nine polynomials per piece made pieces() cost microseconds a piece).
  template <class T, class Coordinate>
  void jet_of(const T& t, int order, T (&v)[3][3], Coordinate coordinate) const {
    const std::size_t m = cp_.size();
    T local[3][8];
    std::vector<T> heap[3];
    T* b[3];
    for (int k = 0; k < 3; ++k) {
      if (m <= 8) b[k] = local[k];
      else {
        heap[k].resize(m);
        b[k] = heap[k].data();
      }
    }
    for (int d = 0; d <= order; ++d) {
      for (int k = 0; k < 3; ++k) {
        for (std::size_t i = 0; i < m; ++i) b[k][i] = coordinate(i, k);
        std::size_t len = m;
        for (int e = 0; e < d; ++e) { // the e-th derivative's coefficients, as derivative() forms them
          if (len == 1) {
            b[k][0] = T(0);
            break;
          }
          const T nn(static_cast<int>(len - 1));
          for (std::size_t i = 0; i + 1 < len; ++i) b[k][i] = nn * (b[k][i + 1] - b[k][i]);
          --len;
        }
        v[d][k] = de_casteljau(b[k], len, t);
      }
    }
  }

  void homogeneous_jet(const FT& t, int order, FT (&v)[3][3]) const {
    jet_of(t, order, v, [&](std::size_t i, int k) -> FT {
      return k == 2 ? w_[i] : w_[i] * (k == 0 ? cp_[i].x() : cp_[i].y());
    });
  }

  void double_derivatives(double t, double& cx, double& cy, double& dx, double& dy, double& ex,
                          double& ey) const {
    double v[3][3];
    jet_of(t, 2, v, [&](std::size_t i, int k) -> double {
      const double wi = CGAL::to_double(w_[i]);
      return k == 2 ? wi : wi * CGAL::to_double(k == 0 ? cp_[i].x() : cp_[i].y());
    });
    const double W = v[0][2], W1 = v[1][2], W2 = v[2][2];
    cx = v[0][0] / W;
    cy = v[0][1] / W;
    dx = (v[1][0] - W1 * cx) / W;
    dy = (v[1][1] - W1 * cy) / W;
    ex = (v[2][0] - 2.0 * W1 * dx - W2 * cx) / W;
    ey = (v[2][1] - 2.0 * W1 * dy - W2 * cy) / W;
  }

  // One validation pass over the control points; nothing else is built.
  void init() {
    internal::require(!cp_.empty(), "Rational_bezier_2: needs at least one control point");
    internal::require(cp_.size() == w_.size(), "Rational_bezier_2: ", cp_.size(), " control points but ", w_.size(),
                      " weights");
    for (std::size_t i = 0; i < cp_.size(); ++i) {
      const double px = CGAL::to_double(cp_[i].x()), py = CGAL::to_double(cp_[i].y());
      const double wi = CGAL::to_double(w_[i]);
      internal::require(std::isfinite(px) && std::isfinite(py), "Rational_bezier_2: control point ", i, " = (", px,
                        ", ", py, ") is not finite");
      internal::require(std::isfinite(wi) && w_[i] > FT(0), "Rational_bezier_2: weight ", i, " = ", wi,
                        " must be finite and > 0");
    }
  }

  std::vector<Point_2> cp_;
  std::vector<FT> w_;
};

} // namespace fair

#endif // FAIR_RATIONAL_BEZIER_2_H
