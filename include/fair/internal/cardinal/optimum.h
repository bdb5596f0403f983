// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The sums behind the curvature-variation-minimising Cardinal spline of
// J. Li, "Curvature variation minimizing Cardinal spline curves" (equation numbers below refer
// to it: [Li] in doc/references.md).
//
// For the segment built on the four points (q0, q1, q2, q3) the paper defines (eq. 8)
//     d = -q0 - q1 + q2 + q3,   m = q1 - q2,
// and the third derivative of the segment is the constant r''' = 6 alpha d + 12 m, so that
//     E_i = int_0^1 |r_i'''|^2 dt = 36 alpha^2 |d|^2 + 144 alpha d.m + 144 |m|^2      (eq. 9).
// Everything here is a sum of products of coordinates: exact in an exact number type.

#ifndef FAIR_INTERNAL_CARDINAL_OPTIMUM_H
#define FAIR_INTERNAL_CARDINAL_OPTIMUM_H

#include <fair/Errors.h>

#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace cardinal {

/// The number type the sums of eq. 10 are accumulated in. For EPECK's lazy numbers the sums are
/// accumulated directly in the exact type: a lazy sum of n terms would build a DAG of depth n
/// (slow, and its exact evaluation recurses n deep); the result is wrapped back as one lazy number.
template <class FT>
struct Cardinal_accumulator {
  typedef FT Type;
  static const FT& convert(const FT& x) { return x; }
  static const FT& wrap(const FT& x) { return x; }
};
template <class ET>
struct Cardinal_accumulator<CGAL::Lazy_exact_nt<ET>> {
  typedef ET Type;
  static const ET& convert(const CGAL::Lazy_exact_nt<ET>& x) { return CGAL::exact(x); }
  static CGAL::Lazy_exact_nt<ET> wrap(const ET& x) { return CGAL::Lazy_exact_nt<ET>(x); }
};

/// The three sums of eq. 10: D = sum |d_i|^2, M = sum d_i.m_i, S = sum |m_i|^2.
/// In double the sums carry the usual O(n eps) relative rounding error of recursive summation.
template <class FT>
class Cardinal_sums {
public:
  typedef Cardinal_accumulator<FT> Acc;
  typedef typename Acc::Type AT;

  template <class Point_2>
  void add(const Point_2& q0, const Point_2& q1, const Point_2& q2, const Point_2& q3) {
    // Coordinates, not kernel constructions: a handful of flops in double, no lazy nodes in EPECK.
    // (Copies: for EPECK, x() returns a temporary whose exact value must not be referenced.)
    const AT x0 = Acc::convert(q0.x()), y0 = Acc::convert(q0.y());
    const AT x1 = Acc::convert(q1.x()), y1 = Acc::convert(q1.y());
    const AT x2 = Acc::convert(q2.x()), y2 = Acc::convert(q2.y());
    const AT x3 = Acc::convert(q3.x()), y3 = Acc::convert(q3.y());
    add_values(x0, y0, x1, y1, x2, y2, x3, y3);
  }

  void add_values(const AT& x0, const AT& y0, const AT& x1, const AT& y1, const AT& x2, const AT& y2, const AT& x3,
                  const AT& y3) {
    const AT dx = x2 + x3 - x0 - x1, dy = y2 + y3 - y0 - y1; // d = -q0 - q1 + q2 + q3 (eq. 8)
    const AT mx = x1 - x2, my = y1 - y2;                       // m = q1 - q2
    D_ += dx * dx + dy * dy;
    M_ += dx * mx + dy * my;
    S_ += mx * mx + my * my;
  }

  FT D() const { return Acc::wrap(D_); }
  FT M() const { return Acc::wrap(M_); }
  FT S() const { return Acc::wrap(S_); }

  /// The energy of eq. 10 for the parameter alpha (of the original, unscaled points).
  FT energy(const FT& alpha) const {
    const FT e = FT(36) * alpha * alpha * D() + FT(144) * alpha * M() + FT(144) * S();
    if constexpr (std::is_floating_point<FT>::value) return std::ldexp(e, 2 * exponent_); // exact, no NaN
    else return e;
  }

  /// The points were multiplied by 2^-exponent before add() (floating point only): D, M, S are
  /// 2^(-2 exponent) times those of the original points (alpha* = -2M/D is unchanged) and
  /// energy() undoes the scaling.
  void set_scale_exponent(int exponent) { exponent_ = exponent; }

private:
  AT D_ = AT(0), M_ = AT(0), S_ = AT(0);
  int exponent_ = 0;
};

/// `e`, an energy of eq. 10, unless it is not finite in a floating-point FT: the sums of squares
/// of finite but huge coordinates (beyond ~1e150) overflow double, and then Invalid_input_error
/// says so instead of returning inf or NaN. Exact number types are returned as they are.
template <class FT>
FT checked_energy(const FT& e, const char* method) {
  if constexpr (std::is_floating_point<FT>::value) {
    if (!std::isfinite(e))
      throw Invalid_input_error(message(method, ": the energy of eq. 10 is ", e,
                                        " in double: the coordinates are too large for this number type"));
  }
  return e;
}

/// The sums over the interior segments i = 0..n-3 of an open curve (the ones that do not touch an
/// auxiliary point; eq. 15 / eq. 18), or over all N segments of a closed curve (indices mod N).
template <class FT, class Point_2>
Cardinal_sums<FT> cardinal_interior_sums(const std::vector<Point_2>& p, bool closed) {
  typedef typename Cardinal_sums<FT>::Acc Acc;
  typedef typename Cardinal_sums<FT>::AT AT;
  Cardinal_sums<FT> s;
  const std::size_t N = p.size();
  if constexpr (std::is_floating_point<FT>::value) {
    // Floating point: alpha* is invariant under translation and scaling, so the sums are taken on
    // the points translated to p_0 and scaled by a power of two (exact) that brings their extent
    // to [1/2, 1): huge coordinates cannot overflow |d|^2 nor tiny ones underflow it.
    const double x0 = double(p[0].x()), y0 = double(p[0].y());
    double extent = 0;
    for (const Point_2& q : p) {
      const double ax = std::fabs(double(q.x()) - x0), ay = std::fabs(double(q.y()) - y0);
      if (ax > extent) extent = ax;
      if (ay > extent) extent = ay;
    }
    if (extent > 0 && std::isfinite(extent)) {
      int e = 0;
      std::frexp(extent, &e);
      // 2^-e as two exact factors: 2^1074 (subnormal extents) is not a double.
      const int e1 = e / 2, e2 = e - e1;
      const double f1 = std::ldexp(1.0, -e1), f2 = std::ldexp(1.0, -e2);
      auto X = [&](std::size_t k) { return ((double(p[k].x()) - x0) * f1) * f2; };
      auto Y = [&](std::size_t k) { return ((double(p[k].y()) - y0) * f1) * f2; };
      if (closed) {
        for (std::size_t i = 0; i < N; ++i) {
          const std::size_t a = (i + N - 1) % N, b = (i + 1) % N, c = (i + 2) % N;
          s.add_values(X(a), Y(a), X(i), Y(i), X(b), Y(b), X(c), Y(c));
        }
      } else {
        // Sliding window: every point is scaled once.
        double wx[4], wy[4];
        for (std::size_t k = 0; k < 3 && k < N; ++k) { wx[k] = X(k); wy[k] = Y(k); }
        for (std::size_t i = 0; i + 3 < N; ++i) {
          wx[3] = X(i + 3);
          wy[3] = Y(i + 3);
          s.add_values(wx[0], wy[0], wx[1], wy[1], wx[2], wy[2], wx[3], wy[3]);
          wx[0] = wx[1]; wx[1] = wx[2]; wx[2] = wx[3];
          wy[0] = wy[1]; wy[1] = wy[2]; wy[2] = wy[3];
        }
      }
      s.set_scale_exponent(e);
      return s;
    }
  }
  if (std::is_same<AT, FT>::value) {
    if (closed) {
      for (std::size_t i = 0; i < N; ++i) s.add(p[(i + N - 1) % N], p[i], p[(i + 1) % N], p[(i + 2) % N]);
    } else {
      for (std::size_t i = 0; i + 3 < N; ++i) s.add(p[i], p[i + 1], p[i + 2], p[i + 3]);
    }
    return s;
  }
  // Lazy exact numbers: convert every coordinate once.
  std::vector<AT> x, y;
  x.reserve(N);
  y.reserve(N);
  for (const Point_2& q : p) {
    x.push_back(Acc::convert(q.x()));
    y.push_back(Acc::convert(q.y()));
  }
  if (closed) {
    for (std::size_t i = 0; i < N; ++i) {
      const std::size_t a = (i + N - 1) % N, b = (i + 1) % N, c = (i + 2) % N;
      s.add_values(x[a], y[a], x[i], y[i], x[b], y[b], x[c], y[c]);
    }
  } else {
    for (std::size_t i = 0; i + 3 < N; ++i)
      s.add_values(x[i], y[i], x[i + 1], y[i + 1], x[i + 2], y[i + 2], x[i + 3], y[i + 3]);
  }
  return s;
}

/// alpha* of eq. 18 from the sums, or why there is none: D = sum |d_i|^2 = 0 (eq. 10 does not
/// depend on alpha) or alpha* = -2 M / D <= 0 (no minimiser with alpha > 0). Never divides by 0.
template <class FT>
struct Alpha_optimum {
  enum Outcome { FOUND, ZERO_DENOMINATOR, NOT_POSITIVE } outcome = ZERO_DENOMINATOR;
  FT alpha = FT(0);  ///< alpha* (FOUND and NOT_POSITIVE), 0 for ZERO_DENOMINATOR
  FT D = FT(0), M = FT(0);
};
template <class FT>
Alpha_optimum<FT> optimal_alpha(const Cardinal_sums<FT>& s) {
  Alpha_optimum<FT> o;
  o.D = s.D();
  o.M = s.M();
  if (CGAL::is_zero(o.D)) return o;
  o.alpha = -FT(2) * o.M / o.D;  // eq. 18 (closed: the same formula over all N segments)
  o.outcome = CGAL::is_positive(o.alpha) ? Alpha_optimum<FT>::FOUND : Alpha_optimum<FT>::NOT_POSITIVE;
  return o;
}

/// The optimal auxiliary points of eqs. 19-20 for alpha != 0, without input checks (the public
/// fair::cardinal_auxiliary_points checks and calls this).
template <class Point_2, class FT>
std::pair<Point_2, Point_2> auxiliary_points_unchecked(const std::vector<Point_2>& p, const FT& alpha) {
  const std::size_t n = p.size() - 1;
  const FT c = FT(1) - FT(2) / alpha;                                              // eq. 19
  const Point_2 start(c * (p[1].x() - p[0].x()) + p[2].x(), c * (p[1].y() - p[0].y()) + p[2].y());
  const Point_2 end(p[n - 2].x() - c * (p[n].x() - p[n - 1].x()),                 // eq. 20
                    p[n - 2].y() - c * (p[n].y() - p[n - 1].y()));
  return std::make_pair(start, end);
}

} // namespace cardinal
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_CARDINAL_OPTIMUM_H
