// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Cubic_spline_2<Kernel>: the one spline representation of the library — a planar
// non-uniform cubic C2 B-spline with single breakpoints t_0 < t_1 < ... < t_m, open (clamped) or
// closed (periodic), polynomial or rational (homogeneous control points (w d, w), w > 0).
// It is the form CAD consumes (a NURBS curve of degree 3) and the form the methods of
// Karciauskas & Peters [KP13] produce; its pieces are the library's Bezier pieces, so sampling,
// metrics and SVG output work on it unchanged.
//
// Control points (the paper's c_i is the control point of breakpoint t_i, eqs. 2, 3):
//  - open, clamped (knot vector t_0 x4, t_1, ..., t_{m-1}, t_m x4): m + 3 control points
//    d_0 .. d_{m+2}; d_0 is the start of the curve (b_0^0), d_1 = b_1^0, d_{i+1} = c_i for
//    0 <= i <= m, d_{m+1} = b_2^{m-1}, d_{m+2} the end of the curve (eq. 10, corrected).
//  - closed, periodic with period t_m - t_0: m control points, d_i = c_i, whose basis
//    function is supported on [t_{i-2}, t_{i+2}] (indices and breakpoints periodic).
// Piece i spans [t_i, t_{i+1}] and is parametrised over [0, 1] by u = (t - t_i) / h_i, h_i =
// t_{i+1} - t_i; consecutive pieces join with the G2 scalars beta_i = h_i / h_{i-1} of eq. 1.
// The derivation of eqs. 1-3 and 10 in this form is in doc/cubic_splines.md.
//
// Representation: the breakpoints, the control points and, for a rational spline only, the
// weights; nothing derived is stored. The Bezier points of piece i (eq. 2) are computed on demand
// from c_{i-1} .. c_{i+2} and h_{i-2} .. h_{i+2} (internal/spline/bspline_form.h), in affine
// coordinates for a polynomial spline and homogeneous ones for a rational spline.
//
// Exactness: construction, pieces, evaluation, knot insertion and from_bezier_pieces use
// +, -, *, / only: exact in an exact kernel (EPECK, Simple_cartesian<Gmpq>), in double each
// result is a few affine combinations (backward stable, relative error ~1e-15 of the control
// polygon's extent). curvature() is computed in double. Complexity: O(1) per piece, O(m) for
// all pieces, O(log m) per evaluation (a branch-free binary search for the piece), O(m) per knot
// insertion (the copy; 3 new control points).

#ifndef FAIR_CUBIC_SPLINE_2_H
#define FAIR_CUBIC_SPLINE_2_H

#include <fair/Bezier_2.h>
#include <fair/Errors.h>
#include <fair/Nurbs_curve_2.h>
#include <fair/Rational_bezier_2.h>
#include <fair/internal/spline/bspline_form.h>
#include <fair/internal/spline/checks.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace fair {

template <class K>
class Cubic_spline_2 {
public:
  typedef K Kernel;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Rational_bezier_2<K> Piece;     ///< pieces(): always (weights 1 when polynomial)
  typedef Bezier_2<K> Polynomial_piece;   ///< polynomial_pieces(): only when !is_rational()
  static constexpr std::size_t degree = 3;

  /// The polynomial spline on `breakpoints` (t_0 < ... < t_m, m >= 1 open, m >= 3 closed) with
  /// `control_points` (m + 3 open, m closed; layout above).
  /// \throws Precondition_error for too few breakpoints, a non-finite or non-increasing
  /// breakpoint, a wrong number of control points, or a non-finite coordinate (the message
  /// names the index and the values); also for breakpoints or coordinates so large (beyond
  /// ~1e307) that the sums of a few of them in eq. 2 would overflow double.
  Cubic_spline_2(std::vector<FT> breakpoints, std::vector<Point_2> control_points, bool closed = false)
    : t_(std::move(breakpoints)), d_(std::move(control_points)), closed_(closed) {
    validate();
  }

  /// The rational spline with weights w_i > 0 (homogeneous control points (w_i d_i, w_i)).
  /// All weights equal make it polynomial: is_rational() is then false and weights() are 1.
  /// \throws Precondition_error as above, or for a weight that is not finite and > 0.
  Cubic_spline_2(std::vector<FT> breakpoints, std::vector<Point_2> control_points, std::vector<FT> weights,
                 bool closed = false)
    : t_(std::move(breakpoints)), d_(std::move(control_points)), w_(std::move(weights)), closed_(closed) {
    internal::require(w_.size() == d_.size(), "fair::Cubic_spline_2: ", w_.size(), " weights for ", d_.size(),
                      " control points");
    validate();
  }

  /// The spline whose pieces are `cubic_pieces` (piece i over [t_i, t_{i+1}]), by eq. 3.
  /// \throws Invalid_input_error if the pieces are not C2 for these breakpoints: the spline
  /// rebuilt from the control points must reproduce every Bezier point, exactly in an exact
  /// kernel, in double within 1e-9 of the extent of the pieces' control points.
  static Cubic_spline_2 from_bezier_pieces(std::vector<FT> breakpoints, const std::vector<Polynomial_piece>& cubic_pieces,
                                           bool closed = false) {
    std::vector<std::array<Homogeneous, 4>> b;
    b.reserve(cubic_pieces.size());
    for (const Polynomial_piece& p : cubic_pieces) {
      internal::require(p.degree() == 3, "fair::Cubic_spline_2::from_bezier_pieces: piece ", b.size(), " has degree ",
                        p.degree(), ", expected 3");
      b.push_back(homogeneous_of(p.control_points(), std::vector<FT>(4, FT(1))));
    }
    return from_homogeneous_bezier(std::move(breakpoints), b, closed, false, "from_bezier_pieces");
  }

  /// As from_bezier_pieces, for rational cubic pieces (eq. 3 in homogeneous coordinates). The
  /// homogeneous end points must agree: the end weight of piece i equals the start weight of
  /// piece i+1 (scale a piece's weights to make them so).
  static Cubic_spline_2 from_rational_bezier_pieces(std::vector<FT> breakpoints,
                                                    const std::vector<Piece>& cubic_pieces, bool closed = false) {
    std::vector<std::array<Homogeneous, 4>> b;
    b.reserve(cubic_pieces.size());
    for (const Piece& p : cubic_pieces) {
      internal::require(p.degree() == 3, "fair::Cubic_spline_2::from_rational_bezier_pieces: piece ", b.size(),
                        " has degree ", p.degree(), ", expected 3");
      b.push_back(homogeneous_of(p.control_points(), p.weights()));
    }
    return from_homogeneous_bezier(std::move(breakpoints), b, closed, true, "from_rational_bezier_pieces");
  }

  const std::vector<FT>& breakpoints() const { return t_; }
  const std::vector<Point_2>& control_points() const { return d_; }
  /// The weights, built on call (all 1 for a polynomial spline, which stores none).
  std::vector<FT> weights() const { return rational() ? w_ : std::vector<FT>(d_.size(), FT(1)); }
  /// Weight i (1 for a polynomial spline). \throws Precondition_error for i >= number_of_control_points().
  FT weight(std::size_t i) const {
    internal::require(i < d_.size(), "fair::Cubic_spline_2::weight: index ", i, " >= ", d_.size());
    return rational() ? w_[i] : FT(1);
  }
  bool is_rational() const { return rational(); }
  bool is_closed() const { return closed_; }
  std::size_t number_of_pieces() const { return t_.size() - 1; }
  std::size_t number_of_control_points() const { return d_.size(); }
  /// The parameter interval [t_0, t_m].
  std::pair<FT, FT> domain() const { return {t_.front(), t_.back()}; }

  /// eq. 1: beta_i = h_i / h_{i-1} (1 <= i < m open; any 0 <= i < m closed, h_{-1} = h_{m-1}).
  FT beta(std::size_t i) const {
    internal::require(i < number_of_pieces() && (closed_ || i >= 1), "fair::Cubic_spline_2::beta: index ", i,
                      " outside ", closed_ ? "[0, " : "[1, ", number_of_pieces(), ")");
    return internal::spline::knot_interval(t_, closed_, static_cast<long>(i)) /
           internal::spline::knot_interval(t_, closed_, static_cast<long>(i) - 1);
  }

  /// Piece i (0 <= i < m) over [t_i, t_{i+1}], as a rational cubic Bezier piece (eq. 2).
  Piece piece(std::size_t i) const {
    check_piece_index(i, "piece");
    return to_piece(static_cast<long>(i));
  }

  /// All m pieces, computed on call (O(m)).
  std::vector<Piece> pieces() const {
    std::vector<Piece> out;
    out.reserve(number_of_pieces());
    for (std::size_t i = 0; i < number_of_pieces(); ++i) out.push_back(to_piece(static_cast<long>(i)));
    return out;
  }

  /// Piece i as a polynomial cubic Bezier piece. \throws Precondition_error if is_rational().
  Polynomial_piece polynomial_piece(std::size_t i) const {
    check_piece_index(i, "polynomial_piece");
    require_polynomial("polynomial_piece");
    return to_polynomial_piece(affine_bezier_points(static_cast<long>(i)));
  }

  /// All pieces as polynomial cubic Bezier pieces. \throws Precondition_error if is_rational().
  std::vector<Polynomial_piece> polynomial_pieces() const {
    require_polynomial("polynomial_pieces");
    std::vector<Polynomial_piece> out;
    out.reserve(number_of_pieces());
    for (std::size_t i = 0; i < number_of_pieces(); ++i)
      out.push_back(to_polynomial_piece(affine_bezier_points(static_cast<long>(i))));
    return out;
  }

  /// The point at the global parameter t in [t_0, t_m]. \throws Precondition_error outside.
  /// O(log m): the binary search for the piece, its four Bezier points (eq. 2) and de Casteljau.
  Point_2 point(const FT& t) const {
    const std::size_t i = locate(t, "point");
    const FT u = (t - t_[i]) / (t_[i + 1] - t_[i]);
    if (!rational()) {
      const Affine p = internal::spline::cubic_point(affine_bezier_points(static_cast<long>(i)), u);
      return Point_2(p.x, p.y);
    }
    const Homogeneous p = internal::spline::cubic_point(homogeneous_bezier_points(static_cast<long>(i)), u);
    return Point_2(p.x / p.w, p.y / p.w);
  }

  /// d/dt at t (one-sided from the right at a breakpoint; C2 makes the sides agree).
  Vector_2 derivative(const FT& t) const {
    if (!rational()) {
      const Affine_jet j = affine_jet(t, "derivative");
      return Vector_2(j[1].x, j[1].y);
    }
    const Jet j = jet(t, "derivative");
    const FT& W = j[0].w;
    const FT cx = j[0].x / W, cy = j[0].y / W;
    return Vector_2((j[1].x - cx * j[1].w) / W, (j[1].y - cy * j[1].w) / W);
  }

  /// d^2/dt^2 at t: c'' = (X'' - 2 W' c' - W'' c) / W.
  Vector_2 second_derivative(const FT& t) const {
    if (!rational()) {
      const Affine_jet j = affine_jet(t, "second_derivative");
      return Vector_2(j[2].x, j[2].y);
    }
    const Jet j = jet(t, "second_derivative");
    const FT& W = j[0].w;
    const FT cx = j[0].x / W, cy = j[0].y / W;
    const FT dx = (j[1].x - cx * j[1].w) / W, dy = (j[1].y - cy * j[1].w) / W;
    const FT two(2);
    return Vector_2((j[2].x - two * j[1].w * dx - j[2].w * cx) / W, (j[2].y - two * j[1].w * dy - j[2].w * cy) / W);
  }

  /// The signed curvature at t, in double. \throws Precondition_error where the tangent vanishes.
  double curvature(double t) const {
    const std::size_t i = locate(FT(t), "curvature");
    const double t0 = CGAL::to_double(t_[i]), h = CGAL::to_double(t_[i + 1]) - t0;
    return piece(i).curvature(std::min(1.0, std::max(0.0, (t - t0) / h)));
  }

  /// The same curve with the breakpoint s inserted (Boehm), t_j < s < t_{j+1}.
  /// \throws Precondition_error if s is not strictly inside an interval.
  Cubic_spline_2 with_knot_inserted(const FT& s) const {
    internal::require(t_.front() < s && s < t_.back(), "fair::Cubic_spline_2::with_knot_inserted: ",
                      CGAL::to_double(s), " is not inside (", CGAL::to_double(t_.front()), ", ",
                      CGAL::to_double(t_.back()), ")");
    const std::size_t j = static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), s) - t_.begin()) - 1;
    internal::require(!(t_[j] == s), "fair::Cubic_spline_2::with_knot_inserted: ", CGAL::to_double(s),
                      " is already breakpoint ", j, " (single knots only)");
    const std::vector<Homogeneous> h = homogeneous_control();
    std::vector<Homogeneous> c = internal::spline::insert_knot(t_, h, closed_, static_cast<long>(j), s);
    std::vector<FT> t = t_;
    t.insert(t.begin() + static_cast<std::ptrdiff_t>(j) + 1, s);
    return from_homogeneous_control(std::move(t), c, closed_, rational());
  }

  /// The same spline with control point i moved to p (the designer's edit): C2 by construction.
  Cubic_spline_2 with_control_point(std::size_t i, const Point_2& p) const {
    internal::require(i < d_.size(), "fair::Cubic_spline_2::with_control_point: index ", i, " >= ", d_.size());
    Cubic_spline_2 out = *this;
    out.d_[i] = p;
    out.validate();
    return out;
  }

  /// Throws Invalid_input_error naming `method` unless, in double, every Bezier point of every
  /// piece and the Bezier coefficients of its first and second derivatives, 3 (b_{k+1} - b_k) and
  /// 6 (b_{k+2} - 2 b_{k+1} + b_k), are finite: finite control points can still give pieces whose
  /// combinations overflow (coordinates or breakpoints near DBL_MAX), and a family that hands out
  /// pieces refuses them rather than return inf or NaN. Polynomial splines only (a no-op for a
  /// rational one, whose pieces Rational_bezier_2 checks). O(m), no allocation.
  void check_finite_pieces(const char* method) const {
    if (rational()) return;
    // Sufficient and O(1): eq. 2 multiplies control points by sums of at most three intervals
    // (each <= 2 T, T the largest |breakpoint|, a closed spline's period included) and divides
    // by such sums; the Bezier points are convex combinations (<= C, the largest |coordinate|),
    // their differences at most 6 C, 24 C. With 8 T C and 32 C below DBL_MAX nothing overflows,
    // so the loop below could not throw.
    const double T = std::max(std::abs(CGAL::to_double(t_.front())), std::abs(CGAL::to_double(t_.back())));
    const double big = std::numeric_limits<double>::max() / 64;
    if (bound_ <= big && 16 * T * bound_ <= big) return;
    const FT three(3), six(6);
    for (std::size_t j = 0; j < number_of_pieces(); ++j) {
      const std::array<Affine, 4> c = affine_bezier_points(static_cast<long>(j));
      for (std::size_t k = 0; k < 4; ++k) {
        const double x = CGAL::to_double(c[k].x), y = CGAL::to_double(c[k].y);
        if (!std::isfinite(x) || !std::isfinite(y))
          throw Invalid_input_error(internal::message(method, ": constructed point ", k, " = (", x, ", ", y,
                                                      ") is not finite; the input coordinates are too large for "
                                                      "this number type"));
      }
      for (std::size_t k = 0; k < 3; ++k) {
        const double dx = CGAL::to_double(three * (c[k + 1].x - c[k].x)), dy = CGAL::to_double(three * (c[k + 1].y - c[k].y));
        double ex = 0, ey = 0;
        if (k < 2) {
          ex = CGAL::to_double(six * (c[k + 2].x - FT(2) * c[k + 1].x + c[k].x));
          ey = CGAL::to_double(six * (c[k + 2].y - FT(2) * c[k + 1].y + c[k].y));
        }
        if (!std::isfinite(dx) || !std::isfinite(dy) || !std::isfinite(ex) || !std::isfinite(ey))
          throw Invalid_input_error(internal::message(
              method, ": piece ", j, ": the derivatives are not finite (first difference (", dx, ", ", dy,
              "), second difference (", ex, ", ", ey, ") of control point ", k,
              "); the input coordinates are too large for this number type"));
      }
    }
  }

  /// The full knot vector of the NURBS form, size knot_vector_control_points().size() + 4.
  /// Open: t_0 x4, t_1, ..., t_{m-1}, t_m x4 with control_points(). Closed (unclamped periodic
  /// form): t_{-3}, ..., t_{m+3} (extended by the period) with the control points
  /// c_{-1}, c_0, ..., c_{m+1}; a standard B-spline evaluator on [t_0, t_m] gives the curve.
  std::vector<FT> knot_vector() const {
    const long m = static_cast<long>(number_of_pieces());
    std::vector<FT> u;
    u.reserve(static_cast<std::size_t>(m + 7));
    for (long k = -3; k <= m + 3; ++k) u.push_back(internal::spline::extended_knot(t_, closed_, k)); // clamped or periodic
    return u;
  }

  /// The control points matching knot_vector(): open, control_points(); closed, c_{-1} .. c_{m+1}.
  std::vector<Point_2> knot_vector_control_points() const { return wrapped(d_); }
  /// The weights matching knot_vector_control_points().
  std::vector<FT> knot_vector_weights() const { return wrapped(weights()); }

  /// The spline in the exchange form (fair/Nurbs_curve_2.h): degree 3, knot_vector(),
  /// knot_vector_control_points() and, when rational, knot_vector_weights(); clamped when open,
  /// the periodic form when closed. The same curve, exactly in an exact kernel.
  Nurbs_curve_2<K> nurbs() const {
    return Nurbs_curve_2<K>(3, knot_vector(), knot_vector_control_points(),
                            rational() ? knot_vector_weights() : std::vector<FT>{}, closed_);
  }

  /// The C2 cubic spline a NURBS curve is, when it is one: degree 3, every knot inside the
  /// domain simple; an open curve clamped (end knots of multiplicity 4), a closed one periodic.
  /// Inverse of nurbs(). \throws Precondition_error naming the knot or property that does not fit.
  static Cubic_spline_2 from_nurbs(const Nurbs_curve_2<K>& c) {
    const char* who = "fair::Cubic_spline_2::from_nurbs";
    const std::vector<FT>& u = c.knots();
    const std::vector<Point_2>& P = c.control_points();
    const std::size_t n = P.size();
    const bool closed = c.is_closed();
    internal::require(c.degree() == 3, who, ": degree ", c.degree(), " is not 3");
    if (!closed) {
      for (std::size_t k = 0; k <= 3; ++k)
        internal::require(u[k] == u[0] && u[n + k] == u[n], who, ": the knot vector is not clamped (knot ", k,
                          " or ", n + k, " differs from the end knots)");
    }
    std::vector<FT> t;
    for (std::size_t k = 3; k <= n; ++k) {
      if (k > 3)
        internal::require(u[k - 1] < u[k], who, ": knot ", k, " = ", CGAL::to_double(u[k]),
                          " is multiple inside the domain (a C2 cubic spline has single breakpoints)");
      t.push_back(u[k]);
    }
    const long skip_front = closed ? 1 : 0, skip_back = closed ? 2 : 0; // the periodic wrap c_{-1}, c_m, c_{m+1}
    std::vector<Point_2> d(P.begin() + skip_front, P.end() - skip_back);
    if (!c.is_rational()) return Cubic_spline_2(std::move(t), std::move(d), closed);
    std::vector<FT> w(c.weights().begin() + skip_front, c.weights().end() - skip_back);
    return Cubic_spline_2(std::move(t), std::move(d), std::move(w), closed);
  }

private:
  typedef internal::spline::Homogeneous_point<FT> Homogeneous;
  typedef internal::spline::Affine_point<FT> Affine;
  typedef std::array<Homogeneous, 3> Jet;
  typedef std::array<Affine, 3> Affine_jet;

  // The representation (issue 23 §4): breakpoints, control points and, for a rational spline
  // only, weights. Nothing derived is stored: the Bezier points of a piece (eq. 2) cost a few
  // dozen operations from 4 control points and 5 intervals, less than reading a stored copy.
  bool rational() const { return !w_.empty(); }

  void validate() {
    bound_ = internal::spline::check_spline_data<K>(t_, d_, rational() ? &w_ : nullptr, closed_);
    if (rational() && std::all_of(w_.begin(), w_.end(), [&](const FT& w) { return w == w_.front(); }))
      w_.clear(); // equal weights: the same curve, polynomial form
  }

  // c_{i-1} .. c_{i+2} and h_{i-2} .. h_{i+2}, then eq. 2.
  std::array<Affine, 4> affine_bezier_points(long i) const {
    FT h[5];
    internal::spline::intervals_around(t_, closed_, i, h);
    const long m = static_cast<long>(number_of_pieces());
    Affine c[4];
    for (int k = 0; k < 4; ++k) {
      const Point_2& p = d_[internal::spline::control_index(i - 1 + k, m, closed_)];
      c[k] = Affine{p.x(), p.y()};
    }
    return internal::spline::bezier_points_of(c, h);
  }

  std::array<Homogeneous, 4> homogeneous_bezier_points(long i) const {
    FT h[5];
    internal::spline::intervals_around(t_, closed_, i, h);
    const long m = static_cast<long>(number_of_pieces());
    Homogeneous c[4];
    for (int k = 0; k < 4; ++k) c[k] = homogeneous_control(internal::spline::control_index(i - 1 + k, m, closed_));
    return internal::spline::bezier_points_of(c, h);
  }

  Homogeneous homogeneous_control(std::size_t k) const {
    if (!rational()) return Homogeneous{d_[k].x(), d_[k].y(), FT(1)};
    return Homogeneous{w_[k] * d_[k].x(), w_[k] * d_[k].y(), w_[k]};
  }

  std::vector<Homogeneous> homogeneous_control() const {
    std::vector<Homogeneous> h;
    h.reserve(d_.size());
    for (std::size_t i = 0; i < d_.size(); ++i) h.push_back(homogeneous_control(i));
    return h;
  }

  static std::array<Homogeneous, 4> homogeneous_of(const std::vector<Point_2>& p, const std::vector<FT>& w) {
    std::array<Homogeneous, 4> b;
    for (std::size_t k = 0; k < 4; ++k) b[k] = Homogeneous{w[k] * p[k].x(), w[k] * p[k].y(), w[k]};
    return b;
  }

  // rational = false: the w of every point is 1 in exact arithmetic (affine combinations of
  // weights 1), so it is set to 1 rather than divided by (in double it is 1 +- a few ulps).
  static Cubic_spline_2 from_homogeneous_control(std::vector<FT> t, const std::vector<Homogeneous>& c, bool closed,
                                                 bool rational = true) {
    if (!rational) {
      std::vector<Point_2> d;
      d.reserve(c.size());
      for (const Homogeneous& h : c) d.push_back(Point_2(h.x, h.y));
      return Cubic_spline_2(std::move(t), std::move(d), closed);
    }
    std::vector<Point_2> d;
    std::vector<FT> w;
    d.reserve(c.size());
    w.reserve(c.size());
    for (const Homogeneous& h : c) {
      internal::require(h.w > FT(0), "fair::Cubic_spline_2: a homogeneous control point has weight ",
                        CGAL::to_double(h.w), " <= 0");
      d.push_back(Point_2(h.x / h.w, h.y / h.w));
      w.push_back(h.w);
    }
    return Cubic_spline_2(std::move(t), std::move(d), std::move(w), closed);
  }

  static Cubic_spline_2 from_homogeneous_bezier(std::vector<FT> t, const std::vector<std::array<Homogeneous, 4>>& b,
                                                bool closed, bool rational, const char* fn) {
    internal::spline::check_breakpoints(t, closed, fn);
    internal::require(b.size() + 1 == t.size(), "fair::Cubic_spline_2::", fn, ": ", b.size(), " pieces for ", t.size(),
                      " breakpoints (expected ", t.size() - 1, ")");
    const std::vector<Homogeneous> c = internal::spline::control_from_bezier(t, b, closed);
    for (std::size_t i = 0; i < c.size(); ++i)
      if (!(c[i].w > FT(0)))
        throw Invalid_input_error(internal::message("fair::Cubic_spline_2::", fn, ": control point ", i, " has weight ",
                                                    CGAL::to_double(c[i].w), " <= 0"));
    Cubic_spline_2 s = from_homogeneous_control(std::move(t), c, closed, rational);
    internal::spline::check_reproduces<K>([&](long i) { return s.homogeneous_bezier_points(i); }, b, fn);
    return s;
  }

  template <class T>
  std::vector<T> wrapped(const std::vector<T>& v) const {
    if (!closed_) return v;
    const std::size_t m = v.size();
    std::vector<T> out;
    out.reserve(m + 3);
    out.push_back(v[m - 1]);
    out.insert(out.end(), v.begin(), v.end());
    out.push_back(v[0]);
    out.push_back(v[1 % m]);
    return out;
  }

  Piece to_piece(long i) const {
    std::vector<Point_2> p;
    p.reserve(4);
    if (!rational()) {
      for (const Affine& a : affine_bezier_points(i)) p.push_back(Point_2(a.x, a.y));
      return Piece(std::move(p));
    }
    std::vector<FT> w;
    w.reserve(4);
    for (const Homogeneous& h : homogeneous_bezier_points(i)) {
      p.push_back(Point_2(h.x / h.w, h.y / h.w));
      w.push_back(h.w);
    }
    return Piece(std::move(p), std::move(w));
  }

  Polynomial_piece to_polynomial_piece(const std::array<Affine, 4>& b) const {
    return Polynomial_piece(Point_2(b[0].x, b[0].y), Point_2(b[1].x, b[1].y), Point_2(b[2].x, b[2].y),
                            Point_2(b[3].x, b[3].y));
  }

  void check_piece_index(std::size_t i, const char* fn) const {
    internal::require(i < number_of_pieces(), "fair::Cubic_spline_2::", fn, ": index ", i, " >= ", number_of_pieces());
  }

  void require_polynomial(const char* fn) const {
    internal::require(!rational(), "fair::Cubic_spline_2::", fn, ": the spline is rational; use pieces()");
  }

  std::size_t locate(const FT& t, const char* fn) const {
    if (!(t_.front() <= t && t <= t_.back()))
      internal::require(false, "fair::Cubic_spline_2::", fn, ": parameter ", CGAL::to_double(t), " outside [",
                        CGAL::to_double(t_.front()), ", ", CGAL::to_double(t_.back()), "]");
    // The last i < m with t_i <= t, by a binary search without data-dependent branches (the
    // halving is a conditional move): with random t, std::upper_bound's mispredicted branches
    // cost more than the piece's arithmetic (issue 23 §4 profile).
    const FT* base = t_.data();
    std::size_t n = number_of_pieces();
    while (n > 1) {
      const std::size_t half = n / 2;
      base = (base[half] <= t) ? base + half : base;
      n -= half;
    }
    return static_cast<std::size_t>(base - t_.data());
  }

  // Value and first two derivatives d/dt in homogeneous coordinates.
  Jet jet(const FT& t, const char* fn) const {
    const std::size_t i = locate(t, fn);
    const FT h = t_[i + 1] - t_[i];
    Jet j = internal::spline::cubic_jet(homogeneous_bezier_points(static_cast<long>(i)), (t - t_[i]) / h);
    const FT h2 = h * h;
    j[1] = Homogeneous{j[1].x / h, j[1].y / h, j[1].w / h};
    j[2] = Homogeneous{j[2].x / h2, j[2].y / h2, j[2].w / h2};
    return j;
  }

  // The same for a polynomial spline (weight 1: the derivatives are those of the affine points).
  Affine_jet affine_jet(const FT& t, const char* fn) const {
    const std::size_t i = locate(t, fn);
    const FT h = t_[i + 1] - t_[i];
    Affine_jet j = internal::spline::cubic_jet(affine_bezier_points(static_cast<long>(i)), (t - t_[i]) / h);
    const FT h2 = h * h;
    j[1] = Affine{j[1].x / h, j[1].y / h};
    j[2] = Affine{j[2].x / h2, j[2].y / h2};
    return j;
  }

  std::vector<FT> t_;
  std::vector<Point_2> d_;
  std::vector<FT> w_; // empty for a polynomial spline
  bool closed_ = false;
  double bound_ = 0;  // the largest |coordinate| of a control point (check_spline_data)
};

} // namespace fair

#endif // FAIR_CUBIC_SPLINE_2_H
