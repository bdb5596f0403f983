// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Rational_bezier_2<Kernel>: a planar rational Bezier piece of any degree n >= 0,
//
//   c(t) = X(t) / W(t),   X(t) = sum_i B_i^n(t) w_i P_i,   W(t) = sum_i B_i^n(t) w_i,   t in [0,1],
//
// with control points P_i and weights w_i > 0. Unit (or all equal) weights give the polynomial
// Bezier piece. Models the CurvePiece_2 concept of doc/contributing.md.
//
// Method: the homogeneous coordinates X, Y, W are kept as fair::Bernstein_polynomial<FT>;
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

  /// Homogeneous coordinates X, Y and W as Bernstein polynomials of degree n.
  const Polynomial& homogeneous_x() const { return X_; }
  const Polynomial& homogeneous_y() const { return Y_; }
  const Polynomial& homogeneous_w() const { return W_; }

  /// c(t) (exact in an exact kernel); t in [0,1].
  Point_2 point(const FT& t) const {
    check_parameter(t, "point");
    const FT W = W_.evaluate(t);
    return Point_2(X_.evaluate(t) / W, Y_.evaluate(t) / W);
  }

  /// c'(t) (exact in an exact kernel); t in [0,1].
  Vector_2 derivative(const FT& t) const {
    check_parameter(t, "derivative");
    FT cx, cy, dx, dy;
    first_order(t, cx, cy, dx, dy);
    return Vector_2(dx, dy);
  }

  /// c''(t) (exact in an exact kernel); t in [0,1].
  Vector_2 second_derivative(const FT& t) const {
    check_parameter(t, "second_derivative");
    FT cx, cy, dx, dy;
    first_order(t, cx, cy, dx, dy);
    const FT W = W_.evaluate(t), W1 = W1_.evaluate(t), W2 = W2_.evaluate(t);
    const FT ex = (X2_.evaluate(t) - FT(2) * W1 * dx - W2 * cx) / W;
    const FT ey = (Y2_.evaluate(t) - FT(2) * W1 * dy - W2 * cy) / W;
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
    const std::pair<Polynomial, Polynomial> x = X_.split(s), y = Y_.split(s), w = W_.split(s);
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

  void first_order(const FT& t, FT& cx, FT& cy, FT& dx, FT& dy) const {
    const FT W = W_.evaluate(t), W1 = W1_.evaluate(t);
    cx = X_.evaluate(t) / W;
    cy = Y_.evaluate(t) / W;
    dx = (X1_.evaluate(t) - W1 * cx) / W;
    dy = (Y1_.evaluate(t) - W1 * cy) / W;
  }

  void double_derivatives(double t, double& cx, double& cy, double& dx, double& dy, double& ex,
                          double& ey) const {
    const double W = Wd_.evaluate(t), W1 = Wd1_.evaluate(t), W2 = Wd2_.evaluate(t);
    cx = Xd_.evaluate(t) / W;
    cy = Yd_.evaluate(t) / W;
    dx = (Xd1_.evaluate(t) - W1 * cx) / W;
    dy = (Yd1_.evaluate(t) - W1 * cy) / W;
    ex = (Xd2_.evaluate(t) - 2.0 * W1 * dx - W2 * cx) / W;
    ey = (Yd2_.evaluate(t) - 2.0 * W1 * dy - W2 * cy) / W;
  }

  void init() {
    internal::require(!cp_.empty(), "Rational_bezier_2: needs at least one control point");
    internal::require(cp_.size() == w_.size(), "Rational_bezier_2: ", cp_.size(), " control points but ", w_.size(),
                      " weights");
    std::vector<FT> x, y;
    std::vector<double> xd, yd, wd;
    for (std::size_t i = 0; i < cp_.size(); ++i) {
      const double px = CGAL::to_double(cp_[i].x()), py = CGAL::to_double(cp_[i].y());
      const double wi = CGAL::to_double(w_[i]);
      internal::require(std::isfinite(px) && std::isfinite(py), "Rational_bezier_2: control point ", i, " = (", px,
                        ", ", py, ") is not finite");
      internal::require(std::isfinite(wi) && w_[i] > FT(0), "Rational_bezier_2: weight ", i, " = ", wi,
                        " must be finite and > 0");
      x.push_back(w_[i] * cp_[i].x());
      y.push_back(w_[i] * cp_[i].y());
      xd.push_back(wi * px);
      yd.push_back(wi * py);
      wd.push_back(wi);
    }
    X_ = Polynomial(x);
    Y_ = Polynomial(y);
    W_ = Polynomial(w_);
    X1_ = X_.derivative(); Y1_ = Y_.derivative(); W1_ = W_.derivative();
    X2_ = X1_.derivative(); Y2_ = Y1_.derivative(); W2_ = W1_.derivative();
    Xd_ = Bernstein_polynomial<double>(xd);
    Yd_ = Bernstein_polynomial<double>(yd);
    Wd_ = Bernstein_polynomial<double>(wd);
    Xd1_ = Xd_.derivative(); Yd1_ = Yd_.derivative(); Wd1_ = Wd_.derivative();
    Xd2_ = Xd1_.derivative(); Yd2_ = Yd1_.derivative(); Wd2_ = Wd1_.derivative();
  }

  std::vector<Point_2> cp_;
  std::vector<FT> w_;
  Polynomial X_, Y_, W_, X1_, Y1_, W1_, X2_, Y2_, W2_;
  Bernstein_polynomial<double> Xd_, Yd_, Wd_, Xd1_, Yd1_, Wd1_, Xd2_, Yd2_, Wd2_;
};

} // namespace fair

#endif // FAIR_RATIONAL_BEZIER_2_H
