// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Cubic_interpolating_spline_2<Kernel>: the classic C2 cubic interpolating spline
// through points p_0..p_n. Its result is a fair::Cubic_spline_2 (spline(): the knots u_i as
// breakpoints, open or periodic), whose cubic fair::Bezier_2 pieces (one per interval) are
// pieces().
// It is the baseline of Fig. 2c and Fig. 18d of Karciauskas & Peters, "Curvature-sensitive
// splines" (the "classic C^2 cubic spline interpolant" that oscillates where the curvature
// of the data changes abruptly).
//
// Formulation (first-derivative, "tangent" form; de Boor, A Practical Guide to Splines, ch. IV).
// Knots u_i with intervals h_i = u_{i+1} - u_i (Knot_spacing). On [u_i, u_{i+1}] the spline is
// the cubic Hermite interpolant of p_i, p_{i+1} with derivatives m_i, m_{i+1} (d/du). C2 at an
// interior knot i (equate the one-sided second derivatives and multiply by h_{i-1} h_i / 2):
//   h_i m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_{i-1} m_{i+1}
//       = 3 ( h_i (p_i - p_{i-1}) / h_{i-1} + h_{i-1} (p_{i+1} - p_i) / h_i ).        (C2)
// End conditions:
//   natural   c''(u_0) = c''(u_n) = 0:   2 m_0 + m_1 = 3 (p_1 - p_0) / h_0,
//                                        m_{n-1} + 2 m_n = 3 (p_n - p_{n-1}) / h_{n-1};
//   clamped   m_0 and m_n given (d/du in the chosen spacing: for uniform knots the derivative
//             with respect to the point index, for chordal knots with respect to chord length);
//   periodic  (options.closed) the points are a closed polygon, n+1 intervals with h_n from p_n
//             back to p_0, and (C2) holds at every knot, indices mod n+1;
//   not-a-knot  c''' continuous at u_1 and u_{n-1} (the first two and the last two pieces are
//             one cubic each; de Boor ch. IV): eliminating m_2 from (C2) at u_1 and the jump
//             condition gives, with d_i = (p_{i+1} - p_i) / h_i,
//               h_1 m_0 + (h_0 + h_1) m_1 = (h_1 (3 h_0 + 2 h_1) d_0 + h_0^2 d_1) / (h_0 + h_1),
//             mirrored at the end. It reproduces cubics (the natural spline does not), so a
//             spline through samples of a smooth curve converges as O(h^4) up to the ends.
//             Three points give the parabola (both conditions coincide; its slope at u_1 is
//             (h_1 d_0 + h_0 d_1) / (h_0 + h_1), m_0 = 2 d_0 - m_1, m_2 = 2 d_1 - m_1), two the segment.
// The system is strictly diagonally dominant (not-a-knot: its two end rows are not, which
// elimination without pivoting tolerates: the first pivot is h_1 > 0, and the second row's
// pivot stays positive, de Boor ch. IV); it is solved per coordinate by the Thomas
// algorithm (open) or by Sherman-Morrison on the cyclic system (periodic): O(n) time and memory.
//
// Exactness: with Knot_spacing::UNIFORM every number is rational in the data, so in an exact
// kernel (EPECK, Simple_cartesian<Gmpq>) the pieces interpolate exactly, and C1, C2 and the end
// conditions hold exactly. Centripetal/chordal knots are computed in double and converted
// exactly to FT (see Knot_spacing); the solve is then exact for those knots.
// Accuracy in double: the solve is backward stable (diagonal dominance, no pivoting needed);
// relative errors of a few ulps times the condition number, which is at most 6 for uniform
// knots (Gershgorin: the symmetric matrix has its eigenvalues in [1, 6]) and grows like
// max(h)/min(h) for strongly non-uniform chordal knots.

#ifndef FAIR_CUBIC_INTERPOLATING_SPLINE_2_H
#define FAIR_CUBIC_INTERPOLATING_SPLINE_2_H

#include <fair/Bezier_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/Errors.h>
#include <fair/Knot_spacing.h>
#include <fair/internal/classic/common.h>
#include <fair/internal/linear_algebra/tridiagonal.h>
#include <fair/internal/common/input_checks.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {

/// End conditions of an open C2 cubic interpolating spline. A closed spline has no ends: it is
/// periodic (C2 at every knot, Cubic_interpolating_spline_options::closed).
enum class Spline_end_condition { NATURAL, CLAMPED, NOT_A_KNOT };

/// The options of a Cubic_interpolating_spline_2 (doc/concepts.md). The one rule for closed
/// curves: `closed` makes the spline periodic, and `end_condition` applies to open curves only
/// (a closed spline ignores it).
struct Cubic_interpolating_spline_options {
  /// Closed: the periodic spline, one piece per point, the last closing back to the first (>= 3).
  bool closed = false;
  /// Open curves: NATURAL or NOT_A_KNOT (CLAMPED needs the two end derivatives: the expert
  /// constructor). Ignored when closed.
  Spline_end_condition end_condition = Spline_end_condition::NATURAL;
  /// The knots u_i (Knot_spacing.h).
  Knot_spacing knot_spacing = Knot_spacing::UNIFORM;
};

template <class K>
class Cubic_interpolating_spline_2 {
public:
  typedef K Kernel;
  typedef Cubic_interpolating_spline_options Options;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Bezier_2<K> Piece;

  /// The periodic spline (options.closed, needs >= 3 points; the curve closes from the last point
  /// back to the first, which must differ), or the open natural or not-a-knot spline
  /// (options.end_condition, needs >= 2 points).
  /// Throws Invalid_input_error for too few points, non-finite coordinates or coincident
  /// consecutive points, and Precondition_error for an open curve with end_condition CLAMPED
  /// (use the expert constructor).
  explicit Cubic_interpolating_spline_2(std::vector<Point_2> points, const Cubic_interpolating_spline_options& options = {})
    : points_(std::move(points)), options_(not_clamped(options)),
      pieces_(build(Vector_2(FT(0), FT(0)), Vector_2(FT(0), FT(0)))), spline_(make_spline()) {}

  /// Expert: the open clamped spline (>= 2 points) with c'(u_0) = start_derivative and c'(u_n) =
  /// end_derivative, derivatives with respect to the knot parameter u of options.knot_spacing;
  /// options().end_condition is CLAMPED. Throws Invalid_input_error as above and for a non-finite
  /// derivative, Precondition_error for options.closed (a closed spline has no ends).
  Cubic_interpolating_spline_2(std::vector<Point_2> points, const Vector_2& start_derivative,
                               const Vector_2& end_derivative, const Cubic_interpolating_spline_options& options = {})
    : points_(std::move(points)), options_(clamped(options)),
      pieces_(build(checked(start_derivative, "start_derivative"), checked(end_derivative, "end_derivative"))),
      spline_(make_spline()) {}

  /// The spline: breakpoints knots(), clamped (natural, clamped) or periodic; its B-spline
  /// control points follow from the Hermite pieces by eq. 3 of Karciauskas & Peters. Its pieces
  /// are pieces(): exactly in an exact kernel, to rounding (~1e-15 relative) in double.
  const Cubic_spline_2<K>& spline() const { return spline_; }
  /// The cubic Bezier (Hermite) pieces; piece i runs from point i to point i+1 (mod the point
  /// count when periodic), with local parameter t = (u - u_i) / h_i. Their end points are the
  /// data points themselves, so the curve interpolates exactly in every kernel.
  const std::vector<Piece>& pieces() const { return pieces_; }
  /// spline().nurbs(): the C2 cubic in the exchange form (fair/Nurbs_curve_2.h): single interior
  /// knots, clamped when open, periodic when closed; its pieces are pieces() (doc/nurbs.md).
  Nurbs_curve_2<K> nurbs() const { return spline_.nurbs(); }
  std::size_t number_of_pieces() const { return pieces_.size(); }
  /// The interpolated points.
  const std::vector<Point_2>& points() const { return points_; }
  /// The knots u_0 = 0 < u_1 < ... (one more than the number of pieces).
  const std::vector<FT>& knots() const { return knots_; }
  /// The derivatives m_i = c'(u_i) with respect to u (one per point).
  const std::vector<Vector_2>& derivatives() const { return derivatives_; }
  bool is_closed() const { return options_.closed; }
  const Cubic_interpolating_spline_options& options() const { return options_; }

private:
  static const Cubic_interpolating_spline_options& not_clamped(const Cubic_interpolating_spline_options& o) {
    internal::require(o.closed || o.end_condition != Spline_end_condition::CLAMPED,
                      "Cubic_interpolating_spline_2: a clamped spline needs its two end derivatives; "
                      "use the constructor taking start_derivative and end_derivative");
    return o;
  }
  static Cubic_interpolating_spline_options clamped(Cubic_interpolating_spline_options o) {
    internal::require(!o.closed, "Cubic_interpolating_spline_2: a closed (periodic) spline has no end derivatives");
    o.end_condition = Spline_end_condition::CLAMPED;
    return o;
  }

  static const Vector_2& checked(const Vector_2& v, const char* name) {
    const double x = CGAL::to_double(v.x()), y = CGAL::to_double(v.y());
    if (!std::isfinite(x) || !std::isfinite(y))
      throw Invalid_input_error(internal::message("Cubic_interpolating_spline_2: ", name, " = (", x, ", ", y,
                                                  ") is not finite"));
    return v;
  }

  Cubic_spline_2<K> make_spline() const { return Cubic_spline_2<K>::from_bezier_pieces(knots_, pieces_, is_closed()); }

  // Sets knots_ and derivatives_ (declared before pieces_) and returns the Hermite pieces.
  std::vector<Piece> build(const Vector_2& start_derivative, const Vector_2& end_derivative) {
    const char* method = "Cubic_interpolating_spline_2";
    const bool closed = is_closed();
    internal::common::check_interpolation_input(points_, closed ? 3 : 2, closed, method);
    const std::vector<Point_2>& p = points_;
    const std::size_t n = p.size();
    const std::vector<FT> h = internal::classic::classic_knot_intervals<K>(p, closed, options_.knot_spacing, method);
    const Spline_end_condition end = options_.end_condition;  // open curves only
    knots_ = internal::classic::classic_cumulative_knots(h);

    // Rows of the (cyclic) tridiagonal system, one per point; a = sub, b = diagonal, c = super.
    std::vector<FT> a(n, FT(0)), b(n, FT(0)), c(n, FT(0)), dx(n, FT(0)), dy(n, FT(0));
    const FT two(2), three(3);
    auto interior_row = [&](std::size_t i, std::size_t im, std::size_t ip, const FT& hm, const FT& hp) {
      // (C2) at knot i with left interval hm = h_{i-1} and right interval hp = h_i.
      a[i] = hp;
      b[i] = two * (hm + hp);
      c[i] = hm;
      const FT l = hp / hm, r = hm / hp;
      dx[i] = three * (l * (p[i].x() - p[im].x()) + r * (p[ip].x() - p[i].x()));
      dy[i] = three * (l * (p[i].y() - p[im].y()) + r * (p[ip].y() - p[i].y()));
    };
    if (closed) {
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t im = (i + n - 1) % n, ip = (i + 1) % n;
        interior_row(i, im, ip, h[im], h[i]);
      }
    } else {
      for (std::size_t i = 1; i + 1 < n; ++i) interior_row(i, i - 1, i + 1, h[i - 1], h[i]);
      if (end == Spline_end_condition::NATURAL) {
        b[0] = two;
        c[0] = FT(1);
        dx[0] = three * (p[1].x() - p[0].x()) / h[0];
        dy[0] = three * (p[1].y() - p[0].y()) / h[0];
        a[n - 1] = FT(1);
        b[n - 1] = two;
        dx[n - 1] = three * (p[n - 1].x() - p[n - 2].x()) / h[n - 2];
        dy[n - 1] = three * (p[n - 1].y() - p[n - 2].y()) / h[n - 2];
      } else if (end == Spline_end_condition::NOT_A_KNOT) {
        not_a_knot_rows(h, b, c, a, dx, dy);
      } else {  // clamped: identity rows
        b[0] = FT(1);
        dx[0] = start_derivative.x();
        dy[0] = start_derivative.y();
        b[n - 1] = FT(1);
        dx[n - 1] = end_derivative.x();
        dy[n - 1] = end_derivative.y();
      }
    }
    std::vector<FT> mx, my;
    if (!closed && end == Spline_end_condition::NOT_A_KNOT && n <= 3) {
      // the segment (n = 2) or the parabola (n = 3): see the header
      const FT dx0 = (p[1].x() - p[0].x()) / h[0], dy0 = (p[1].y() - p[0].y()) / h[0];
      mx.assign(n, dx0);
      my.assign(n, dy0);
      if (n == 3) {
        const FT dx1 = (p[2].x() - p[1].x()) / h[1], dy1 = (p[2].y() - p[1].y()) / h[1];
        mx[1] = (h[1] * dx0 + h[0] * dx1) / (h[0] + h[1]);
        my[1] = (h[1] * dy0 + h[0] * dy1) / (h[0] + h[1]);
        mx[0] = two * dx0 - mx[1];
        my[0] = two * dy0 - my[1];
        mx[2] = two * dx1 - mx[1];
        my[2] = two * dy1 - my[1];
      }
    } else if (closed) {
      mx = internal::linear_algebra::solve_cyclic_tridiagonal(a, b, c, dx);
      my = internal::linear_algebra::solve_cyclic_tridiagonal(a, b, c, dy);
    } else {
      mx = internal::linear_algebra::solve_tridiagonal(a, b, c, dx);
      my = internal::linear_algebra::solve_tridiagonal(a, b, c, dy);
    }
    derivatives_.clear();
    derivatives_.reserve(n);
    for (std::size_t i = 0; i < n; ++i) derivatives_.push_back(Vector_2(mx[i], my[i]));
    return internal::classic::classic_hermite_pieces<K>(p, derivatives_, h, method);
  }

  // The two not-a-knot rows (see the header; n >= 4 points, else solved in closed form):
  // diagonal b, the off-diagonal entry c of row 0 and a of row n-1, right-hand sides dx, dy.
  void not_a_knot_rows(const std::vector<FT>& h, std::vector<FT>& b, std::vector<FT>& c, std::vector<FT>& a,
                       std::vector<FT>& dx, std::vector<FT>& dy) const {
    const std::vector<Point_2>& p = points_;
    const std::size_t n = p.size(), e = n - 1;  // e intervals
    if (n <= 3) return;
    const FT two(2), three(3);
    b[0] = h[1];
    c[0] = h[0] + h[1];
    a[n - 1] = h[e - 2] + h[e - 1];
    b[n - 1] = h[e - 2];
    // (h_1 (3 h_0 + 2 h_1) d_0 + h_0^2 d_1) / (h_0 + h_1), d_i as differences over h_i
    const FT w0 = h[1] * (three * h[0] + two * h[1]) / h[0], w1 = h[0] * h[0] / h[1];
    dx[0] = (w0 * (p[1].x() - p[0].x()) + w1 * (p[2].x() - p[1].x())) / (h[0] + h[1]);
    dy[0] = (w0 * (p[1].y() - p[0].y()) + w1 * (p[2].y() - p[1].y())) / (h[0] + h[1]);
    const FT v0 = h[e - 2] * (three * h[e - 1] + two * h[e - 2]) / h[e - 1], v1 = h[e - 1] * h[e - 1] / h[e - 2];
    dx[n - 1] = (v0 * (p[e].x() - p[e - 1].x()) + v1 * (p[e - 1].x() - p[e - 2].x())) / (h[e - 2] + h[e - 1]);
    dy[n - 1] = (v0 * (p[e].y() - p[e - 1].y()) + v1 * (p[e - 1].y() - p[e - 2].y())) / (h[e - 2] + h[e - 1]);
  }

  std::vector<Point_2> points_;
  Cubic_interpolating_spline_options options_;
  std::vector<FT> knots_;
  std::vector<Vector_2> derivatives_;
  std::vector<Piece> pieces_;
  Cubic_spline_2<K> spline_;
};

} // namespace fair

#endif // FAIR_CUBIC_INTERPOLATING_SPLINE_2_H
