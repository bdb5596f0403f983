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
//    u_p = u_n as its knot multiplicities say elsewhere. N >= p.
//
// Exactness: construction, pieces(), point, derivatives, knot insertion and the conversions use
// +, -, *, / of FT only, so in an exact kernel (EPECK, Simple_cartesian<Gmpq>) pieces() *are*
// the curve, exactly, and evaluation at a rational u is exact. curvature() is in double
// (internal/common/curvature.h, scale-safe). In double every operation is a chain of convex
// combinations (backward stable, ~p ulps of the control polygon's extent).
//
// Complexity: construction O(n + p) (validation); pieces() O(n p^3) once, cached (thread-safe);
// point/derivatives O(log n + p^2 + order p) once the pieces are built; insert_knot O(n + p).
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
  /// piece's start. Built on the first call and kept.
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
  std::vector<Vector_2> derivatives(const FT& u, std::size_t order) const {
    const Located l = locate(u, "derivatives");
    const Piece& b = *l.piece;
    const std::size_t q = b.degree();
    // homogeneous coefficients, then their derivatives evaluated at t (scaled by 1 / h^k)
    std::vector<std::vector<FT>> A(3, std::vector<FT>(q + 1));
    for (std::size_t j = 0; j <= q; ++j) {
      A[0][j] = b.weight(j) * b.control_point(j).x();
      A[1][j] = b.weight(j) * b.control_point(j).y();
      A[2][j] = b.weight(j);
    }
    std::vector<std::array<FT, 3>> D; // D[k] = (X^(k), Y^(k), W^(k)) at u
    FT scale(1);
    for (std::size_t k = 0; k <= order; ++k) {
      std::array<FT, 3> v;
      for (int c = 0; c < 3; ++c) v[static_cast<std::size_t>(c)] = k <= q ? de_casteljau(A[static_cast<std::size_t>(c)], l.t) * scale : FT(0);
      D.push_back(v);
      if (k < q) {
        for (auto& a : A) {
          for (std::size_t j = 0; j + 1 < a.size(); ++j) a[j] = a[j + 1] - a[j];
          a.pop_back();
        }
        scale = scale * FT(static_cast<int>(q - k)) / l.h;
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
    return C;
  }

  /// Signed curvature at u in double (c' x c'' / |c'|^3, scale-safe).
  /// \throws Precondition_error where the tangent vanishes or |kappa| overflows double.
  double curvature(const FT& u) const {
    const std::vector<Vector_2> d = derivatives(u, 2);
    const double x1 = CGAL::to_double(d[1].x()), y1 = CGAL::to_double(d[1].y());
    internal::require(x1 != 0 || y1 != 0, "fair::Nurbs_curve_2::curvature: the tangent vanishes at u = ",
                      CGAL::to_double(u));
    const double k = internal::common::signed_curvature(x1, y1, CGAL::to_double(d[2].x()), CGAL::to_double(d[2].y()));
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
    std::vector<Homogeneous> H = homogeneous();
    if (closed_) {
      // reduce to the first period's span: u_p <= x < u_{p+N}
      const FT x0 = x == u_[P_.size()] ? u_[p_] : x;
      internal::nurbs::insert_knot_periodic(p_, u, H, internal::nurbs::find_span(p_, P_.size(), u_, x0), x0);
    } else {
      internal::nurbs::insert_knot_open(p_, u, H, internal::nurbs::find_span(p_, P_.size(), u_, x), x);
    }
    return from_homogeneous(p_, std::move(u), H, closed_);
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

  std::vector<Homogeneous> homogeneous() const {
    std::vector<Homogeneous> H;
    H.reserve(P_.size());
    for (std::size_t k = 0; k < P_.size(); ++k) H.push_back(Homogeneous{w_[k] * P_[k].x(), w_[k] * P_[k].y(), w_[k]});
    return H;
  }

  static Nurbs_curve_2 from_homogeneous(std::size_t p, std::vector<FT> u, const std::vector<Homogeneous>& H,
                                        bool closed) {
    std::vector<Point_2> P;
    std::vector<FT> w;
    for (const Homogeneous& h : H) {
      P.push_back(Point_2(h.x / h.w, h.y / h.w));
      w.push_back(h.w);
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
