// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Cardinal spline curves and the parameter / auxiliary points that minimise their curvature
// variation, after J. Li, "Curvature variation minimizing Cardinal spline curves"
// ([Li] in doc/references.md; eq. numbers refer to it).
// The user manual is doc/cardinal_splines.md. The class Cardinal_spline_2 is how users meet it
// (options: Cardinal_spline_options.h, report: Cardinal_spline_report.h); the free functions
// optimal_cardinal_parameters and cardinal_auxiliary_points are its engine.
//
// Conventions. The segment on the four consecutive points (q0, q1, q2, q3) is (eqs. 1-2)
//     r(t) = b0(t) q0 + b1(t) q1 + b2(t) q2 + b3(t) q3,   t in [0,1],
//     b0 = -a t^3 + 2a t^2 - a t,        b1 = (2-a) t^3 + (a-3) t^2 + 1,
//     b2 = (a-2) t^3 + (3-2a) t^2 + a t, b3 = a t^3 - a t^2,
// with a = alpha = (1 - T)/2 (T the tension). It runs from q1 to q2 with end tangents
// alpha (q2 - q0) and alpha (q3 - q1) (eqs. 3-4): alpha = 1/2 is the (uniform) Catmull-Rom spline.
// It is the cubic Bezier piece q1, q1 + alpha (q2 - q0)/3, q2 - alpha (q3 - q1)/3, q2.
//
// Open curve on p_0..p_n: segments i = 0..n-1 run from p_i to p_{i+1} on (p_{i-1}, p_i, p_{i+1},
// p_{i+2}) with the auxiliary points p_{-1} and p_{n+1} (the paper numbers them r_{-1}..r_{n-2}).
// Closed curve on p_0..p_{N-1}: N segments, indices taken mod N; no auxiliary points.
//
// Exactness: construction, evaluation, Bezier conversion, the optimum of eqs. 18-20 and the
// energy of eq. 10 use +, -, *, / of Kernel::FT only, so they are exact in an exact kernel
// (EPECK, Simple_cartesian<Gmpq>) and ordinary rounded arithmetic in double.

#ifndef FAIR_CARDINAL_SPLINE_2_H
#define FAIR_CARDINAL_SPLINE_2_H

#include <fair/Bezier_2.h>
#include <fair/Cardinal_spline_options.h>
#include <fair/Cardinal_spline_report.h>
#include <fair/Errors.h>
#include <fair/internal/cardinal/optimum.h>
#include <fair/internal/classic/common.h>
#include <fair/internal/common/input_checks.h>
#include <fair/internal/nurbs/assembly.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <type_traits>
#include <vector>

namespace fair {

/// The optimum of eqs. 18-20 (open curve) or of its closed analogue (see doc/cardinal_splines.md):
/// the parameter alpha*, the auxiliary points (open curves only; for a closed curve they are
/// left equal to the first and last data point and are not used) and the energy of eq. 10 there.
template <class K>
struct Cardinal_parameters {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  FT alpha;
  Point_2 aux_start;
  Point_2 aux_end;
  FT energy;
  bool closed = false;
};

/// The auxiliary points that minimise the energy of eq. 10 for a fixed alpha != 0 (eqs. 16-17,
/// solved as eqs. 19-20): p_{-1} = (1 - 2/alpha)(p_1 - p_0) + p_2 and
/// p_{n+1} = p_{n-2} - (1 - 2/alpha)(p_n - p_{n-1}). With them the two end segments have
/// r''' = 0 (they are parabolic arcs) and contribute nothing to eq. 10.
/// \throws Invalid_input_error for fewer than 3 points or bad points; Precondition_error if alpha == 0.
template <class Point_2>
std::pair<Point_2, Point_2> cardinal_auxiliary_points(const std::vector<Point_2>& p,
                                                      const typename CGAL::Kernel_traits<Point_2>::Kernel::FT& alpha) {
  internal::common::check_interpolation_input(p, 3, false, "cardinal_auxiliary_points");
  internal::require(!CGAL::is_zero(alpha), "cardinal_auxiliary_points: alpha = 0 has no optimal auxiliary points (eqs. 16-17 divide by alpha)");
  const std::pair<Point_2, Point_2> aux = internal::cardinal::auxiliary_points_unchecked(p, alpha);
  // A tiny alpha (1 - 2/alpha huge) or huge coordinates overflow double.
  internal::common::check_finite_points(std::vector<Point_2>{aux.first, aux.second},
                                        "cardinal_auxiliary_points (auxiliary points overflow)");
  return aux;
}

/// The minimiser of the approximate curvature variation energy of eq. 10.
///
/// Open curve (p_0..p_n, n >= 3): alpha* of eq. 18 (the sums run over the n-2 interior segments),
/// then p_{-1}*, p_{n+1}* of eqs. 19-20. Closed curve (N >= 3 points): alpha* = -2 M / D with the
/// sums of eq. 18 taken over all N segments (indices mod N) -- derivation in doc/cardinal_splines.md.
///
/// Degenerate data, reported by Invalid_input_error (never a division by zero):
///  - D = sum |d_i|^2 = 0 (the denominator of eq. 18; e.g. p_{i+2} + p_{i+3} = p_i + p_{i+1} for all
///    i, as for points alternating between two positions): eq. 10 does not depend on alpha, so there
///    is no unique optimum;
///  - alpha* <= 0: the infimum of eq. 10 over alpha > 0 is not attained (alpha* = 0) or the minimiser
///    reverses every tangent (alpha* < 0, cusps at the data points); happens only for data that fold
///    back on themselves. Cardinal_spline_2 falls back to Catmull-Rom (alpha = 1/2) there, with the
///    status NO_OPTIMUM.
/// Also throws Invalid_input_error for too few points, non-finite or duplicate consecutive points.
template <class Point_2>
Cardinal_parameters<typename CGAL::Kernel_traits<Point_2>::Kernel>
optimal_cardinal_parameters(const std::vector<Point_2>& p, bool closed = false) {
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel K;
  typedef typename K::FT FT;
  const char* method = closed ? "optimal_cardinal_parameters (closed)" : "optimal_cardinal_parameters (open)";
  const internal::cardinal::Cardinal_sums<FT> s =
      internal::cardinal::checked_cardinal_interior_sums<FT>(p, closed ? 3 : 4, closed, method); // one pass
  const internal::cardinal::Alpha_optimum<FT> o = internal::cardinal::optimal_alpha(s);
  if (o.outcome == internal::cardinal::Alpha_optimum<FT>::ZERO_DENOMINATOR)
    throw Invalid_input_error(internal::message(
        method, ": the denominator of eq. 18, sum |d_i|^2 with d_i = -p_i - p_{i+1} + p_{i+2} + p_{i+3}, is 0 "
        "(the data alternate so that every d_i vanishes): the energy of eq. 10 does not depend on alpha and "
        "has no unique minimiser"));
  const FT alpha = o.alpha;
  if (o.outcome == internal::cardinal::Alpha_optimum<FT>::NOT_POSITIVE)
    throw Invalid_input_error(internal::message(
        method, ": the optimal parameter of eq. 18 is alpha* = ", CGAL::to_double(alpha),
        " <= 0 (sum d_i.m_i / sum |d_i|^2 = ", CGAL::to_double(o.M) / CGAL::to_double(o.D),
        "): the data fold back on themselves and no Cardinal spline with alpha > 0 minimises eq. 10; "
        "use a fixed alpha such as 1/2 (Catmull-Rom)"));
  Cardinal_parameters<K> out{alpha, p.front(), p.back(), internal::cardinal::checked_energy(s.energy(alpha), method),
                             closed};
  if (!closed) {
    const std::pair<Point_2, Point_2> aux = internal::cardinal::auxiliary_points_unchecked(p, alpha);
    internal::common::check_finite_points(std::vector<Point_2>{aux.first, aux.second},
                                          "optimal_cardinal_parameters (auxiliary points overflow)");
    out.aux_start = aux.first;
    out.aux_end = aux.second;
    // With the optimal auxiliary points the two end segments contribute 0 (see the doc page):
    // eq. 10 at the optimum is the interior energy only.
  }
  return out;
}

/// \brief A Cardinal spline curve (eqs. 1-2), open with two auxiliary points or closed: a model
/// of the curve-family contract (doc/concepts.md).
///
/// Its pieces are exactly cubic Bezier_2<K> pieces (pieces()); report() says which alpha it uses
/// and why (status()), its auxiliary points and the energy of eq. 10. Exact in an exact kernel.
/// Complexity: O(n) construction (eq. 18 and the pieces), O(1) evaluation.
template <class K>
class Cardinal_spline_2 {
public:
  typedef K Kernel;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Bezier_2<K> Piece;
  typedef Cardinal_spline_options Options;
  typedef Cardinal_spline_report<K> Report;

  /// The Cardinal spline through `points` (closed: N >= 3 points, do not repeat the first; open:
  /// n + 1 points). Without options.alpha: Li's alpha* of eq. 18 (open: n + 1 >= 4 points) and,
  /// open, the optimal auxiliary points of eqs. 19-20 (status OPTIMAL); when eq. 18 has no positive
  /// optimum the Catmull-Rom spline, alpha = 1/2, with the auxiliary points optimal for it
  /// (status NO_OPTIMUM). With options.alpha: that alpha and, open (n + 1 >= 3 points), the
  /// auxiliary points optimal for it (eqs. 16-17; status GIVEN_ALPHA).
  /// \throws Invalid_input_error for too few, non-finite or coincident consecutive points, or when
  /// a piece, its third derivative or eq. 10 overflows the number type; Precondition_error unless
  /// options.alpha is finite and > 0; Solve_error carrying the report for NO_OPTIMUM when
  /// options.throw_on_failure is set.
  explicit Cardinal_spline_2(std::vector<Point_2> points, const Cardinal_spline_options& options = {})
    : points_(std::move(points)), options_(options) {
    if (options_.alpha) {
      // Checked in double first: FT(NaN) or FT(inf) is undefined in an exact FT (Gmpq: SIGFPE).
      internal::require(std::isfinite(*options_.alpha) && *options_.alpha > 0, "Cardinal_spline_2: options.alpha = ",
                        *options_.alpha, " must be finite and > 0");
      given_alpha(FT(*options_.alpha));
      return;
    }
    const bool closed = options_.closed;
    const char* method = closed ? "Cardinal_spline_2 (closed)" : "Cardinal_spline_2 (open)";
    const internal::cardinal::Alpha_optimum<FT> o = internal::cardinal::optimal_alpha(
        internal::cardinal::checked_cardinal_interior_sums<FT>(points_, closed ? 3 : 4, closed, method)); // one pass
    const bool found = o.outcome == internal::cardinal::Alpha_optimum<FT>::FOUND;
    report_.status = found ? Cardinal_spline_status::OPTIMAL : Cardinal_spline_status::NO_OPTIMUM;
    report_.alpha = found ? o.alpha : FT(1) / FT(2);
    set_auxiliary_points();
    build();
    if (!found && options_.throw_on_failure)
      throw Solve_error(
          internal::message(method, ": eq. 18 has no positive optimum (",
                            o.outcome == internal::cardinal::Alpha_optimum<FT>::ZERO_DENOMINATOR
                                ? std::string("its denominator sum |d_i|^2 is 0")
                                : internal::message("alpha* = ", CGAL::to_double(o.alpha), " <= 0"),
                            "); without throw_on_failure the curve is Catmull-Rom (alpha = 1/2), ", report_),
          report_);
  }

  /// Expert: an alpha in FT (any rational in an exact kernel), for the data and the closedness of
  /// `options` (options.alpha must be empty), with, open, the auxiliary points optimal for it.
  /// Status GIVEN_ALPHA. \throws as the first constructor.
  /// (A template, so that `Cardinal_spline_2<K>(points, {})` -- generic code's default options --
  /// cannot pick this constructor with alpha = FT{} = 0: a braced list deduces no Alpha.)
  template <class Alpha, class = std::enable_if_t<std::is_convertible<const Alpha&, FT>::value &&
                                                  !std::is_same<Alpha, Cardinal_spline_options>::value>>
  Cardinal_spline_2(std::vector<Point_2> points, const Alpha& alpha, const Cardinal_spline_options& options = {})
    : points_(std::move(points)), options_(options) {
    internal::require(!options_.alpha, "Cardinal_spline_2: alpha given twice (argument and options.alpha)");
    given_alpha(FT(alpha));
  }

  /// Expert: an open curve through p_0..p_n (n >= 1) with parameter alpha > 0 and the given
  /// auxiliary points p_{-1} = aux_start, p_{n+1} = aux_end (options.closed must be false and
  /// options.alpha empty). Status GIVEN_ALPHA.
  /// \throws Invalid_input_error for bad data points or non-finite auxiliary points,
  ///         Precondition_error unless alpha > 0, for options.closed or options.alpha.
  Cardinal_spline_2(std::vector<Point_2> points, const FT& alpha, const Point_2& aux_start, const Point_2& aux_end,
                    const Cardinal_spline_options& options = {})
    : points_(std::move(points)), options_(options) {
    internal::require(!options_.closed, "Cardinal_spline_2: a closed curve has no auxiliary points");
    internal::require(!options_.alpha, "Cardinal_spline_2: alpha given twice (argument and options.alpha)");
    internal::common::check_interpolation_input(points_, 2, false, "Cardinal_spline_2");
    internal::common::check_finite_points(std::vector<Point_2>{aux_start, aux_end}, "Cardinal_spline_2 (auxiliary points)");
    report_.status = Cardinal_spline_status::GIVEN_ALPHA;
    report_.alpha = alpha;
    check_alpha();
    report_.aux_start = aux_start;
    report_.aux_end = aux_end;
    build();
  }

  /// The interpolated data points p_0..p_n, as given (without auxiliary points).
  const std::vector<Point_2>& points() const { return points_; }
  /// All segments as cubic Bezier pieces, joined end to start (C^1 at the joins): n for an open
  /// curve on n+1 points, N for a closed one on N points.
  const std::vector<Piece>& pieces() const { return pieces_; }
  std::size_t number_of_pieces() const { return pieces_.size(); }
  /// The curve in the exchange form (fair/Nurbs_curve_2.h; doc/nurbs.md, "Cardinal_spline_2"):
  /// degree 3 on the uniform knots 0, 1, ..., n (the parameter of eqs. 1-2: segment i at u = i + t),
  /// interior knots of multiplicity 2 (the segments are C1 there, not C2). Closed: the periodic
  /// form. Exactly the pieces in an exact kernel. O(n).
  Nurbs_curve_2<K> nurbs() const {
    std::vector<FT> t;
    for (std::size_t i = 0; i <= pieces_.size(); ++i) t.push_back(FT(static_cast<int>(i)));
    return internal::nurbs::hermite_cubic_nurbs<K>(pieces_, t, options_.closed, "Cardinal_spline_2::nurbs");
  }
  bool is_closed() const { return options_.closed; }
  const Cardinal_spline_options& options() const { return options_; }
  /// The alpha used and why, the auxiliary points, the energy of eq. 10.
  const Report& report() const { return report_; }
  /// report().status: OPTIMAL, GIVEN_ALPHA or NO_OPTIMUM.
  Cardinal_spline_status status() const { return report_.status; }

  /// The alpha used (report().alpha).
  const FT& alpha() const { return report_.alpha; }
  /// The tension T = 1 - 2 alpha (alpha = (1-T)/2, eq. 2).
  FT tension() const { return FT(1) - FT(2) * report_.alpha; }
  /// p_{-1} and p_{n+1}; \throws Precondition_error for a closed curve.
  const Point_2& aux_start() const {
    internal::require(!is_closed(), "Cardinal_spline_2::aux_start: a closed curve has no auxiliary points");
    return report_.aux_start;
  }
  const Point_2& aux_end() const {
    internal::require(!is_closed(), "Cardinal_spline_2::aux_end: a closed curve has no auxiliary points");
    return report_.aux_end;
  }
  /// The approximate curvature variation energy of eq. 10 (report().energy): the sum over all
  /// segments of int_0^1 |r_i'''(t)|^2 dt (eq. 9), exact in an exact kernel. The true energy of
  /// eq. 5: fair::curvature_variation_energy(pieces(), ...) (Fairness_metrics.h).
  const FT& approximate_energy() const { return report_.energy; }

  /// The four points (q0, q1, q2, q3) that define segment i (eq. 1).
  void segment_points(std::size_t i, const Point_2*& q0, const Point_2*& q1, const Point_2*& q2, const Point_2*& q3) const {
    check_segment(i);
    segment_points_unchecked(i, q0, q1, q2, q3);
  }

  /// r_i(t) (eq. 1), t in [0,1], exact in an exact kernel.
  Point_2 point(std::size_t i, const FT& t) const {
    FT b[4];
    basis(t, b);
    return combine(i, b);
  }
  /// The first derivative r_i'(t).
  Vector_2 derivative(std::size_t i, const FT& t) const {
    const FT a = report_.alpha, t2 = t * t;
    FT b[4] = {-FT(3) * a * t2 + FT(4) * a * t - a, FT(3) * (FT(2) - a) * t2 + FT(2) * (a - FT(3)) * t,
               FT(3) * (a - FT(2)) * t2 + FT(2) * (FT(3) - FT(2) * a) * t + a, FT(3) * a * t2 - FT(2) * a * t};
    return combine(i, b) - CGAL::ORIGIN;
  }
  /// The second derivative r_i''(t).
  Vector_2 second_derivative(std::size_t i, const FT& t) const {
    const FT a = report_.alpha;
    FT b[4] = {-FT(6) * a * t + FT(4) * a, FT(6) * (FT(2) - a) * t + FT(2) * (a - FT(3)),
               FT(6) * (a - FT(2)) * t + FT(2) * (FT(3) - FT(2) * a), FT(6) * a * t - FT(2) * a};
    return combine(i, b) - CGAL::ORIGIN;
  }
  /// The third derivative 6 alpha d_i + 12 m_i, constant on the segment (eqs. 7-8).
  Vector_2 third_derivative(std::size_t i) const {
    check_segment(i);
    return third_derivative_unchecked(i);
  }

  /// The point at the global parameter u in [0, number_of_pieces()]: segment floor(u) (the last
  /// segment for u = number_of_pieces()) at t = u - floor(u).
  /// \throws Precondition_error for u outside that range.
  Point_2 point(const FT& u) const {
    const std::size_t S = number_of_pieces();
    internal::require(!(u < FT(0)) && !(FT(static_cast<double>(S)) < u), "Cardinal_spline_2::point: u = ",
                      CGAL::to_double(u), " is outside [0, ", S, "]");
    double f = std::floor(CGAL::to_double(u));
    std::size_t i = f < 0 ? 0 : static_cast<std::size_t>(f);
    if (i >= S) i = S - 1;
    // to_double may round an exact u across an integer: correct the segment index exactly.
    while (i > 0 && u < FT(static_cast<double>(i))) --i;
    while (i + 1 < S && !(u < FT(static_cast<double>(i + 1)))) ++i;
    return point(i, u - FT(static_cast<double>(i)));
  }

  /// Segment i as the cubic Bezier piece q1, q1 + alpha (q2 - q0)/3, q2 - alpha (q3 - q1)/3, q2
  /// (same parametrisation: piece(t) = r_i(t) identically). \throws Precondition_error if
  /// i >= number_of_pieces().
  const Piece& piece(std::size_t i) const {
    check_segment(i);
    return pieces_[i];
  }

private:
  std::size_t segments() const { return options_.closed ? points_.size() : points_.size() - 1; }

  /// GIVEN_ALPHA from the options or the expert constructor.
  void given_alpha(const FT& alpha) {
    const bool closed = options_.closed;
    internal::common::check_interpolation_input(points_, 3, closed,
                                                closed ? "Cardinal_spline_2 (closed)" : "Cardinal_spline_2 (open)");
    report_.status = Cardinal_spline_status::GIVEN_ALPHA;
    report_.alpha = alpha;
    check_alpha();
    set_auxiliary_points();
    build();
  }
  /// Open: the auxiliary points optimal for report_.alpha (eqs. 16-17 as eqs. 19-20); closed: the
  /// first and the last point (not used).
  void set_auxiliary_points() {
    if (options_.closed) {
      report_.aux_start = points_.front();
      report_.aux_end = points_.back();
      return;
    }
    const std::pair<Point_2, Point_2> aux = cardinal_auxiliary_points(points_, report_.alpha);
    report_.aux_start = aux.first;
    report_.aux_end = aux.second;
  }
  /// The pieces and eq. 10, checked for overflow.
  void build() {
    const std::size_t S = segments();
    pieces_.reserve(S);
    const FT c = report_.alpha / FT(3);
    internal::cardinal::Cardinal_sums<FT> sums;
    const Point_2 *q0, *q1, *q2, *q3;
    for (std::size_t i = 0; i < S; ++i) {
      segment_points_unchecked(i, q0, q1, q2, q3);
      pieces_.push_back(Piece(*q1, Point_2(q1->x() + c * (q2->x() - q0->x()), q1->y() + c * (q2->y() - q0->y())),
                              Point_2(q2->x() - c * (q3->x() - q1->x()), q2->y() - c * (q3->y() - q1->y())), *q2));
      sums.add(*q0, *q1, *q2, *q3);
    }
    // Finite data with a huge alpha or coordinates near 1e308 can give pieces (or derivatives)
    // that overflow double: refused (Invalid_input_error) rather than handed out with inf or NaN.
    internal::classic::classic_check_finite_pieces(pieces_, "Cardinal_spline_2");
    for (std::size_t i = 0; i < S; ++i) {
      const Vector_2 d3 = third_derivative_unchecked(i);
      const double x = CGAL::to_double(d3.x()), y = CGAL::to_double(d3.y());
      if (!std::isfinite(x) || !std::isfinite(y))
        throw Invalid_input_error(internal::message("Cardinal_spline_2: the third derivative of segment ", i, " is (", x,
                                                    ", ", y, ") in this number type: the coordinates are too large"));
    }
    report_.energy = internal::cardinal::checked_energy(sums.energy(report_.alpha), "Cardinal_spline_2 (eq. 10)");
  }
  void check_alpha() const {
    internal::require(std::isfinite(CGAL::to_double(report_.alpha)) && CGAL::is_positive(report_.alpha),
                      "Cardinal_spline_2: alpha = ", CGAL::to_double(report_.alpha),
                      " must be finite and > 0 (alpha = (1 - tension)/2; alpha <= 0 collapses or reverses the tangents)");
  }
  void check_segment(std::size_t i) const {
    internal::require(i < number_of_pieces(), "Cardinal_spline_2: piece index ", i, " >= number of pieces ",
                      number_of_pieces());
  }
  /// Open: q0 = p_{i-1} (p_{-1} = aux_start), q3 = p_{i+2} (p_{n+1} = aux_end); closed: mod N.
  void segment_points_unchecked(std::size_t i, const Point_2*& q0, const Point_2*& q1, const Point_2*& q2,
                                const Point_2*& q3) const {
    const std::size_t N = points_.size();
    if (options_.closed) {
      q0 = &points_[(i + N - 1) % N]; q1 = &points_[i]; q2 = &points_[(i + 1) % N]; q3 = &points_[(i + 2) % N];
    } else {
      q0 = i == 0 ? &report_.aux_start : &points_[i - 1];
      q1 = &points_[i];
      q2 = &points_[i + 1];
      q3 = i + 2 < N ? &points_[i + 2] : &report_.aux_end;
    }
  }
  Vector_2 third_derivative_unchecked(std::size_t i) const {
    const FT a = report_.alpha;
    const FT b[4] = {-FT(6) * a, FT(12) - FT(6) * a, FT(6) * a - FT(12), FT(6) * a};
    const Point_2 *q0, *q1, *q2, *q3;
    segment_points_unchecked(i, q0, q1, q2, q3);
    return Vector_2(b[0] * q0->x() + b[1] * q1->x() + b[2] * q2->x() + b[3] * q3->x(),
                    b[0] * q0->y() + b[1] * q1->y() + b[2] * q2->y() + b[3] * q3->y());
  }
  void basis(const FT& t, FT* b) const { // eq. 2
    const FT a = report_.alpha, t2 = t * t, t3 = t2 * t;
    b[0] = -a * t3 + FT(2) * a * t2 - a * t;
    b[1] = (FT(2) - a) * t3 + (a - FT(3)) * t2 + FT(1);
    b[2] = (a - FT(2)) * t3 + (FT(3) - FT(2) * a) * t2 + a * t;
    b[3] = a * t3 - a * t2;
  }
  Point_2 combine(std::size_t i, const FT* b) const {
    const Point_2 *q0, *q1, *q2, *q3;
    segment_points(i, q0, q1, q2, q3);
    return Point_2(b[0] * q0->x() + b[1] * q1->x() + b[2] * q2->x() + b[3] * q3->x(),
                   b[0] * q0->y() + b[1] * q1->y() + b[2] * q2->y() + b[3] * q3->y());
  }

  std::vector<Point_2> points_;
  Cardinal_spline_options options_;
  Report report_;
  std::vector<Piece> pieces_;
};

} // namespace fair

#endif // FAIR_CARDINAL_SPLINE_2_H
