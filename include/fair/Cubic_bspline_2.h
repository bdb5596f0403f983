// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Cubic_bspline_2<Kernel>: the C2 uniform cubic B-spline that takes the data points as
// its control points, converted to cubic fair::Bezier_2 pieces. It is the red "C^2 cubic
// approximating spline" of Fig. 2f and Fig. 18c of Karciauskas & Peters ("the C^2 cubic
// approximating spline interprets the data points as B-spline control points").
//
// Construction. The uniform cubic B-spline segment over control points d_0..d_3 has the Bezier
// points (d_0 + 4 d_1 + d_2)/6, (2 d_1 + d_2)/3, (d_1 + 2 d_2)/3, (d_1 + 4 d_2 + d_3)/6
// (Farin, Curves and Surfaces for CAGD, B-spline to Bezier conversion).
//
// Open curves, end handling (Cubic_bspline_ends):
//  - interpolate_end_points (default): the polygon is extended by the phantom points
//    p_{-1} = 2 p_0 - p_1 and p_{n+1} = 2 p_n - p_{n-1} (linear extrapolation). The curve then
//    starts at p_0 tangent to p_1 - p_0 with zero second derivative (a "natural" end) and ends at
//    p_n likewise; n pieces for n+1 points (>= 2 points).
//  - trimmed: only the segments whose four control points are data; n - 2 pieces (>= 4 points),
//    the curve starts at (p_0 + 4 p_1 + p_2)/6.
// Closed curves: all indices mod the point count, one piece per point (>= 3 points).
//
// Properties. C2 everywhere (the Bezier points satisfy the C2 conditions at every join); does not
// interpolate: at the knot of p_i the curve passes through (p_{i-1} + 4 p_i + p_{i+1})/6
// = p_i + (p_{i+1} - 2 p_i + p_{i-1})/6. Reproduction: linear data (p_i = a + i b) are reproduced
// exactly; quadratic data q(i) give q(u) + q''/6 (shifted by a constant), cubics are not
// reproduced. Convex-hull and variation-diminishing. O(n).
// Exactness: only +, -, * and division by 3 and 6: exact in EPECK and Simple_cartesian<Gmpq>.

#ifndef FAIR_CUBIC_BSPLINE_2_H
#define FAIR_CUBIC_BSPLINE_2_H

#include <fair/Bezier_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/Errors.h>
#include <fair/internal/classic/bspline.h>
#include <fair/internal/classic/common.h>
#include <fair/internal/common/input_checks.h>

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace fair {

/// End handling of an open Cubic_bspline_2.
enum class Cubic_bspline_ends { INTERPOLATE_END_POINTS, TRIMMED };

/// The options of a Cubic_bspline_2 (doc/concepts.md).
struct Cubic_bspline_options {
  /// Closed: the periodic B-spline of the control polygon (>= 3 points).
  bool closed = false;
  /// Open curves: through the end points (phantom points 2 p_0 - p_1, ...) or trimmed.
  Cubic_bspline_ends ends = Cubic_bspline_ends::INTERPOLATE_END_POINTS;
};

template <class K>
class Cubic_bspline_2 {
public:
  typedef K Kernel;
  typedef Cubic_bspline_options Options;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Bezier_2<K> Piece;

  /// The B-spline with control points `points`. Throws Invalid_input_error for too few points
  /// (2 open with end points, 4 trimmed, 3 closed), non-finite coordinates or coincident
  /// consecutive points (rejected for every classic method, so that comparisons use the same
  /// admissible data; a doubled control point would also make the curve singular).
  explicit Cubic_bspline_2(std::vector<Point_2> points, const Cubic_bspline_options& options = {})
    : points_(std::move(points)), options_(options) {
    const char* method = "Cubic_bspline_2";
    const bool closed = options_.closed;
    const Cubic_bspline_ends ends = options_.ends;
    const std::size_t minimum = closed ? 3 : (ends == Cubic_bspline_ends::TRIMMED ? 4 : 2);
    internal::common::check_interpolation_input(points_, minimum, closed, method);
    if (closed || ends == Cubic_bspline_ends::TRIMMED) {
      control_ = points_;
    } else {
      const std::size_t n = points_.size();
      const FT two(2), minus_one(-1), zero(0);
      control_.reserve(n + 2);
      control_.push_back(internal::common::combine<K>(two, points_[0], minus_one, points_[1], zero, points_[0],
                                                      zero, points_[0]));
      control_.insert(control_.end(), points_.begin(), points_.end());
      control_.push_back(internal::common::combine<K>(two, points_[n - 1], minus_one, points_[n - 2], zero,
                                                      points_[0], zero, points_[0]));
    }
    spline_ = internal::classic::classic_uniform_spline<K>(control_, closed, method);
    pieces_ = spline_->polynomial_pieces();
  }

  /// The cubic Bezier pieces (piece i spans the knot interval [i, i+1] of the uniform knots,
  /// starting at the knot of p_i; for `trimmed`, at the knot of p_{i+1}).
  const std::vector<Piece>& pieces() const { return pieces_; }
  /// spline().nurbs(): the C2 cubic in the exchange form (fair/Nurbs_curve_2.h): single interior
  /// knots, clamped when open, periodic when closed; its pieces are pieces() (doc/nurbs.md).
  Nurbs_curve_2<K> nurbs() const { return (*spline_).nurbs(); }
  /// The result as the library's spline (uniform integer breakpoints; clamped form when open,
  /// periodic when closed), whose pieces are pieces().
  const Cubic_spline_2<K>& spline() const { return *spline_; }
  std::size_t number_of_pieces() const { return pieces_.size(); }
  const std::vector<Point_2>& points() const { return points_; }
  /// The control polygon actually used (the data, plus the two phantom points for
  /// interpolate_end_points).
  const std::vector<Point_2>& control_polygon() const { return control_; }
  bool is_closed() const { return options_.closed; }
  const Cubic_bspline_options& options() const { return options_; }

private:
  std::vector<Point_2> points_;
  Cubic_bspline_options options_;
  std::vector<Point_2> control_;
  std::optional<Cubic_spline_2<K>> spline_; // set in the constructor's body, after the data checks
  std::vector<Piece> pieces_;
};

} // namespace fair

#endif // FAIR_CUBIC_BSPLINE_2_H
