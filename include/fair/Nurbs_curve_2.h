// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Nurbs_curve_2<Kernel>: the library's one exchange form — a planar NURBS curve of any
// degree p >= 1,
//
//   c(u) = sum_k N_{k,p}(u) w_k P_k / sum_k N_{k,p}(u) w_k,   u in [u_p, u_n],
//
// with n control points P_k, weights w_k > 0 and the full knot vector u_0 <= ... <= u_{n+p}
// (multiplicities written out). Every curve family of the library returns its curve in this form
// with nurbs(); DXF, OpenCASCADE and CGAL arrangements read it (doc/nurbs.md).
//
// Open and closed:
//  - open: clamped (u_0 = ... = u_p, u_n = ... = u_{n+p}) as the library writes it; any other
//    non-decreasing vector is accepted and evaluated on the domain [u_p, u_n];
//  - closed (is_closed()): the periodic, unclamped form that every standard B-spline evaluator
//    reads: the last p control points (and weights) repeat the first p, and the knot intervals
//    repeat with period N = n - p (u_{k+N} - u_k = u_n - u_p), so the curve is as smooth at
//    u_p = u_n as its knot multiplicities say elsewhere. N >= p. The seam has one weight: a
//    closed loop of rational pieces is one NURBS only when the pieces, each scaled by a constant
//    to agree at every join, come back to the same weight, i.e. when the product of their
//    end-weight ratios w_p / w_0 is 1 (internal/nurbs/assembly.h refuses the others: a p-th root
//    and a new parameter would be needed; doc/nurbs.md §7).
//
// Exactness: construction, pieces(), point, derivatives, knot insertion and the conversions use
// +, -, *, / of FT only, so in an exact kernel (EPECK, Simple_cartesian<Gmpq>) pieces() *are*
// the curve, exactly, and evaluation at a rational u is exact. curvature() is in double
// (internal/common/curvature.h, scale-safe), from the piece's own parameter (no 1/h^k).
// In double every operation is a chain of convex combinations (backward stable, ~p ulps of the
// control polygon's extent), and the homogeneous form (w x, w y, w) is formed with the weights
// scaled by one power of two 2^-e that brings the largest into [1/2, 1]: w x never exceeds |x|,
// so finite control points near DBL_MAX give finite points (review finding 5); the scaling is
// exact, so every point and stored weight is what the unscaled arithmetic gives wherever that
// was finite. A rational piece of pieces() carries the scaled weights (the same piece: only
// ratios of weights matter). An exact FT is not scaled.
//
// Complexity (n control points, degree p, at most n - p pieces):
//  - construction O(n + p) (validation and the list of non-empty spans); is_rational(),
//    breakpoints() O(n);
//  - pieces(): O(n p^3) on the first call -- p + 1 blossom values of O(p^2) per span (blossom.h)
//    -- then O(1): built once and kept (thread-safe, internal/common/lazy_cache.h);
//  - point(u): O(log n + p^2) (the span by binary search, de Casteljau on its piece) once the
//    pieces are built; the first call of point, derivatives or curvature builds them all
//    (O(n p^3) once);
//  - derivatives(u, k): O(log n + p^2 min(k, p) + k^2); curvature(u) O(log n + p^2);
//  - with_knot_inserted(x): O(n + p) (one pass over the points and knots, then the new curve's
//    construction; its pieces are built when first asked for).
//
// Conversion with the C2 cubic spline: Cubic_spline_2::nurbs() and Cubic_spline_2::from_nurbs()
// (fair/Cubic_spline_2.h, which includes this header).
//
// Errors: Precondition_error for a degree < 1, a wrong number of knots or weights, a knot
// vector that decreases, has an empty domain, a multiplicity above p + 1 (above p inside the
// domain), a closed curve whose repeated control points, weights or knot intervals do not
// repeat, a non-finite coordinate, knot or weight, a weight <= 0, or a parameter outside the
// domain. Each message names the index and the value.

#ifndef FAIR_NURBS_CURVE_2_H
#define FAIR_NURBS_CURVE_2_H

#include <fair/Errors.h>
#include <fair/Rational_bezier_2.h>
#include <fair/internal/common/curvature.h>
#include <fair/internal/common/lazy_cache.h>
#include <fair/internal/nurbs/blossom.h>
#include <fair/internal/nurbs/knot_vector.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace fair {

template <class K>
class Nurbs_curve_2 {
public:
  typedef K Kernel;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Rational_bezier_2<K> Piece;

  /// The curve of degree `degree` with the full knot vector `knots` (n + p + 1 values),
  /// `control_points` (n) and `weights` (n, all > 0; empty: all 1, a polynomial curve).
  /// `closed`: the periodic form described in the file comment.
  /// \throws Precondition_error as listed in the file comment.
  Nurbs_curve_2(std::size_t degree, std::vector<FT> knots, std::vector<Point_2> control_points,
                std::vector<FT> weights = {}, bool closed = false)
    : p_(degree), u_(std::move(knots)), P_(std::move(control_points)), w_(std::move(weights)), closed_(closed) {
    if (w_.empty()) w_.assign(P_.size(), FT(1));
    validate();
    for (std::size_t i = p_; i < P_.size(); ++i)
      if (u_[i] < u_[i + 1]) spans_.push_back(i);
  }

  std::size_t degree() const { return p_; }
  /// The full knot vector u_0 .. u_{n+p}.
  const std::vector<FT>& knots() const { return u_; }
  /// P_0 .. P_{n-1} (closed: the last p repeat the first p).
  const std::vector<Point_2>& control_points() const { return P_; }
  /// w_0 .. w_{n-1} (all 1 for a polynomial curve).
  const std::vector<FT>& weights() const { return w_; }
  std::size_t number_of_control_points() const { return P_.size(); }
  /// True unless every weight equals the first (equal weights give the polynomial curve).
  bool is_rational() const {
    for (const FT& w : w_)
      if (w != w_.front()) return true;
    return false;
  }
  bool is_closed() const { return closed_; }
  /// [u_p, u_n].
  std::pair<FT, FT> domain() const { return {u_[p_], u_[P_.size()]}; }

  /// The Bezier pieces, one per non-empty knot span of the domain in order (by blossoming,
  /// internal/nurbs/blossom.h; a rational piece where the weights differ). Consecutive pieces
  /// share their joint point bit for bit, and a closed curve's last piece ends on the first
  /// piece's start. Built on the first call and kept. In double a rational piece's weights are the
  /// curve's scaled by one power of two (the largest in [1/2, 1]; file comment).
  const std::vector<Piece>& pieces() const {
    return pieces_.get([this] { return make_pieces(); });
  }
  std::size_t number_of_pieces() const { return spans().size(); }
  /// The knot values that bound the pieces: piece j spans [breakpoints()[j], breakpoints()[j+1]].
  std::vector<FT> breakpoints() const {
    std::vector<FT> b;
    for (std::size_t i : spans()) b.push_back(u_[i]);
    b.push_back(u_[P_.size()]);
    return b;
  }

  /// c(u), u in the domain. Exact in an exact kernel.
  Point_2 point(const FT& u) const {
    const Located l = locate(u, "point");
    return l.piece->point(l.t);
  }
  /// c'(u) (with respect to u).
  Vector_2 derivative(const FT& u) const { return derivatives(u, 1)[1]; }
  /// c''(u).
  Vector_2 second_derivative(const FT& u) const { return derivatives(u, 2)[2]; }

  /// c(u) - ORIGIN, c'(u), ..., c^(order)(u), by differencing the span's homogeneous Bezier
  /// coefficients and the quotient rule C^(k) = (A^(k) - sum_{j=1..k} binom(k,j) w^(j) C^(k-j)) / w.
  /// At a knot the derivatives are those of the piece on the right (at the domain's end, the left).
  /// In double c^(k) is the piece's k-th derivative in its parameter t divided by h^k (h the
  /// span's length), so it is inf where that is beyond the double range; curvature() is not.
  std::vector<Vector_2> derivatives(const FT& u, std::size_t order) const {
    const Located l = locate(u, "derivatives");
    return jet(*l.piece, l.t, order, l.h);
  }

  /// Signed curvature at u in double: c' x c'' / |c'|^3 of the span's piece in its own parameter
  /// t = (u - u_i) / h, which is the curvature in u (it does not depend on the parametrisation),
  /// without the factors 1/h and 1/h^2 of the derivatives in u that overflowed on spans of length
  /// 1e-300 (review finding 4). In double a piece with a |coordinate| above 2^500 is scaled by a
  /// power of two 2^-e first (the largest into [1/2, 1]) and kappa by 2^-e after (kappa(s c) = kappa(c) / s), exactly,
  /// so finite control points near DBL_MAX give kappa too; then internal/common/curvature.h.
  /// \throws Precondition_error where the tangent vanishes or |kappa| overflows double.
  double curvature(const FT& u) const {
    const Located l = locate(u, "curvature");
    int e = 0;
    const std::vector<Vector_2> d = jet(*l.piece, l.t, 2, FT(1), &e);
    const double x1 = CGAL::to_double(d[1].x()), y1 = CGAL::to_double(d[1].y());
    internal::require(x1 != 0 || y1 != 0, "fair::Nurbs_curve_2::curvature: the tangent vanishes at u = ",
                      CGAL::to_double(u));
    const double k = std::scalbn(
        internal::common::signed_curvature(x1, y1, CGAL::to_double(d[2].x()), CGAL::to_double(d[2].y())), -e);
    internal::require(std::isfinite(k), "fair::Nurbs_curve_2::curvature: |kappa(", CGAL::to_double(u),
                      ")| is beyond the double range");
    return k;
  }

  /// The same curve with the knot x inserted once (Boehm's algorithm; the curve is unchanged,
  /// exactly in an exact kernel). x in the domain; its multiplicity must stay <= p inside the
  /// domain (<= p + 1 at an end of an open curve).
  Nurbs_curve_2 with_knot_inserted(const FT& x) const {
    check_parameter(x, "with_knot_inserted");
    const std::size_t m = internal::nurbs::multiplicity(u_, x);
    const bool end = !closed_ && (x == u_[p_] || x == u_[P_.size()]);
    internal::require(m + 1 <= (end ? p_ + 1 : p_), "fair::Nurbs_curve_2::with_knot_inserted: the knot ",
                      CGAL::to_double(x), " has multiplicity ", m, " already (at most ", end ? p_ + 1 : p_, ")");
    std::vector<FT> u = u_;
    int e = 0;
    std::vector<Homogeneous> H = homogeneous(e);
    if (closed_) {
      // reduce to the first period's span: u_p <= x < u_{p+N}
      const FT x0 = x == u_[P_.size()] ? u_[p_] : x;
      internal::nurbs::insert_knot_periodic(p_, u, H, internal::nurbs::find_span(p_, P_.size(), u_, x0), x0);
    } else {
      internal::nurbs::insert_knot_open(p_, u, H, internal::nurbs::find_span(p_, P_.size(), u_, x), x);
    }
    return from_homogeneous(p_, std::move(u), H, closed_, e);
  }

private:
  typedef internal::nurbs::Homogeneous_point<FT> Homogeneous;
  struct Located {
    const Piece* piece;
    FT t, h; // local parameter in [0, 1] and the span length
  };

  static FT de_casteljau(std::vector<FT> b, const FT& t) {
    for (std::size_t r = 1; r < b.size(); ++r)
      for (std::size_t j = 0; j + r < b.size(); ++j) b[j] = (FT(1) - t) * b[j] + t * b[j + 1];
    return b[0];
  }

  static FT scaled(const FT& x, int e) { return internal::nurbs::scaled_by_power_of_two(x, e); }

  // c - ORIGIN and its derivatives up to `order` with respect to u = u_i + h t on the piece b, t
  // in [0, 1] (file comment of derivatives()). In a floating-point FT whose largest |coordinate|
  // of the piece is above 2^500 the coordinates are scaled by 2^-e first, e bringing it into
  // [1/2, 1], and the results
  // back by 2^e (exact): the differences of the coefficients cannot overflow where the results
  // are finite; the weights are at most 1 already (homogeneous()). With `exponent`, the results
  // stay scaled by 2^-e and *exponent = e (curvature() scales kappa instead: |c'|^3 could overflow).
  static std::vector<Vector_2> jet(const Piece& b, const FT& t, std::size_t order, const FT& h,
                                   int* exponent = nullptr) {
    const std::size_t q = b.degree();
    int e = 0;
    if constexpr (std::is_floating_point<FT>::value) {
      double m = 0;
      for (std::size_t j = 0; j <= q; ++j)
        m = std::max({m, std::fabs(b.control_point(j).x()), std::fabs(b.control_point(j).y())});
      // only where a difference could overflow: below, nothing changes, not even a subnormal
      if (m > 0x1p500) e = internal::nurbs::normalising_exponent<FT>(m);
    }
    // homogeneous coefficients, then their derivatives evaluated at t (scaled by 1 / h^k)
    std::vector<std::vector<FT>> A(3, std::vector<FT>(q + 1));
    for (std::size_t j = 0; j <= q; ++j) {
      A[0][j] = b.weight(j) * scaled(b.control_point(j).x(), -e);
      A[1][j] = b.weight(j) * scaled(b.control_point(j).y(), -e);
      A[2][j] = b.weight(j);
    }
    std::vector<std::array<FT, 3>> D; // D[k] = (X^(k), Y^(k), W^(k)) at u
    FT scale(1);
    for (std::size_t k = 0; k <= order; ++k) {
      std::array<FT, 3> v;
      for (std::size_t c = 0; c < 3; ++c) v[c] = k <= q ? de_casteljau(A[c], t) * scale : FT(0);
      D.push_back(v);
      if (k < q) {
        for (auto& a : A) {
          for (std::size_t j = 0; j + 1 < a.size(); ++j) a[j] = a[j + 1] - a[j];
          a.pop_back();
        }
        scale = scale * FT(static_cast<int>(q - k)) / h;
      }
    }
    std::vector<Vector_2> C;
    for (std::size_t k = 0; k <= order; ++k) {
      FT x = D[k][0], y = D[k][1];
      FT binom(1);
      for (std::size_t j = 1; j <= k; ++j) {
        binom = binom * FT(static_cast<int>(k - j + 1)) / FT(static_cast<int>(j));
        x = x - binom * D[j][2] * C[k - j].x();
        y = y - binom * D[j][2] * C[k - j].y();
      }
      C.push_back(Vector_2(x / D[0][2], y / D[0][2]));
    }
    if (exponent) *exponent = e;
    else
      for (Vector_2& c : C) c = Vector_2(scaled(c.x(), e), scaled(c.y(), e));
    return C;
  }

  void validate() const {
    const char* who = "fair::Nurbs_curve_2";
    internal::require(w_.size() == P_.size(), who, ": ", w_.size(), " weights for ", P_.size(), " control points");
    internal::nurbs::check_knot_vector(p_, P_.size(), u_, closed_, who);
    for (std::size_t k = 0; k < P_.size(); ++k) {
      const double x = CGAL::to_double(P_[k].x()), y = CGAL::to_double(P_[k].y()), w = CGAL::to_double(w_[k]);
      internal::require(std::isfinite(x) && std::isfinite(y), who, ": control point ", k, " = (", x, ", ", y,
                        ") is not finite");
      internal::require(std::isfinite(w) && w_[k] > FT(0), who, ": weight ", k, " = ", w, " is not finite and > 0");
    }
    if (!closed_) return;
    const std::size_t N = P_.size() - p_;
    for (std::size_t k = 0; k < p_; ++k)
      internal::require(P_[k + N] == P_[k] && w_[k + N] == w_[k], who, ": closed curve: control point ", k + N,
                        " (and its weight) must repeat control point ", k, " (the last p = ", p_,
                        " control points of the periodic form repeat the first)");
  }

  void check_parameter(const FT& x, const char* fn) const {
    internal::require(!(x < u_[p_]) && !(u_[P_.size()] < x), "fair::Nurbs_curve_2::", fn, ": u = ",
                      CGAL::to_double(x), " is outside the domain [", CGAL::to_double(u_[p_]), ", ",
                      CGAL::to_double(u_[P_.size()]), "]");
  }

  // The indices i of the non-empty spans [u_i, u_{i+1}] of the domain.
  const std::vector<std::size_t>& spans() const { return spans_; }

  Located locate(const FT& u, const char* fn) const {
    check_parameter(u, fn);
    const std::size_t i = internal::nurbs::find_span(p_, P_.size(), u_, u);
    const std::size_t j = static_cast<std::size_t>(std::lower_bound(spans_.begin(), spans_.end(), i) - spans_.begin());
    const FT h = u_[i + 1] - u_[i];
    return Located{&pieces()[j], (u - u_[i]) / h, h};
  }

  // (w x, w y, w) with the weights scaled by 2^-e (file comment: w <= 1, so w x cannot
  // overflow; exact); e is 0 in an exact FT.
  std::vector<Homogeneous> homogeneous(int& e) const { return internal::nurbs::homogeneous_points(P_, w_, e); }
  std::vector<Homogeneous> homogeneous() const {
    int e = 0;
    return homogeneous(e);
  }

  // The curve of homogeneous control points H whose weights are scaled by 2^-e (homogeneous()):
  // the stored weights are scaled back (exact).
  static Nurbs_curve_2 from_homogeneous(std::size_t p, std::vector<FT> u, const std::vector<Homogeneous>& H,
                                        bool closed, int e) {
    std::vector<Point_2> P;
    std::vector<FT> w;
    for (const Homogeneous& h : H) {
      P.push_back(Point_2(h.x / h.w, h.y / h.w));
      w.push_back(scaled(h.w, e));
    }
    if (closed) { // the repeated points are the same values, bit for bit
      const std::size_t N = P.size() - p;
      for (std::size_t k = 0; k < p; ++k) {
        P[k + N] = P[k];
        w[k + N] = w[k];
      }
    }
    return Nurbs_curve_2(p, std::move(u), std::move(P), std::move(w), closed);
  }

  std::vector<Piece> make_pieces() const {
    const std::vector<Homogeneous> H = homogeneous();
    const bool rational = is_rational();
    std::vector<Piece> out;
    for (std::size_t i : spans()) {
      std::vector<Homogeneous> b = internal::nurbs::span_bezier(p_, u_, H, i);
      std::vector<Point_2> cp;
      std::vector<FT> w;
      for (std::size_t j = 0; j <= p_; ++j) {
        cp.push_back(Point_2(b[j].x / b[j].w, b[j].y / b[j].w));
        w.push_back(rational ? b[j].w : FT(1));
      }
      if (!out.empty()) { // the joint computed once: consecutive pieces meet bit for bit
        cp.front() = out.back().target();
        if (rational) w.front() = out.back().weights().back();
      }
      out.emplace_back(std::move(cp), std::move(w));
    }
    if (closed_ && out.size() > 0) { // the last piece ends on the first's start
      std::vector<Point_2> cp = out.back().control_points();
      std::vector<FT> w = out.back().weights();
      cp.back() = out.front().source();
      if (rational) w.back() = out.front().weights().front();
      out.back() = Piece(std::move(cp), std::move(w));
    }
    return out;
  }

  std::size_t p_;
  std::vector<FT> u_;
  std::vector<Point_2> P_;
  std::vector<FT> w_;
  bool closed_;
  std::vector<std::size_t> spans_; // the non-empty spans of the domain (derived, O(n))
  internal::common::Lazy_cache<std::vector<Piece>> pieces_;
};

}  // namespace fair

#endif  // FAIR_NURBS_CURVE_2_H
