// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Cubic_quasi_interpolant_2<Kernel>: the cubic (-1, 8, -1)/6 quasi-interpolant, the
// baseline of Fig. 2e and Fig. 18e of Karciauskas & Peters ("Curvature-sensitive splines"; their
// Section 4 reduces to it when all beta_j = 1). The uniform cubic B-spline whose control points
// are
//   c_i = (-p_{i-1} + 8 p_i - p_{i+1}) / 6,
// converted to cubic fair::Bezier_2 pieces (one per data interval).
//
// Does it interpolate? No, not in general. At the knot of p_i the curve passes through
//   (c_{i-1} + 4 c_i + c_{i+1})/6 = (-p_{i-2} + 4 p_{i-1} + 30 p_i + 4 p_{i+1} - p_{i+2})/36
//                                 = p_i - Delta^4 p_{i-2} / 36,
// where Delta^4 p_{i-2} = p_{i-2} - 4 p_{i-1} + 6 p_i - 4 p_{i+1} + p_{i+2}. So it interpolates p_i
// exactly when the fourth difference centred at i vanishes (e.g. data from a cubic), and the
// deviation is O(h^4) for smooth data. It reproduces cubic polynomials: data p_i = q(i) with q a
// cubic give the curve q (the (-1,8,-1)/6 rule is the B-spline quasi-interpolant of cubic
// precision). C2, local (piece i depends on p_{i-2}..p_{i+3}), O(n).
//
// Open curves, end handling (documented choice): the data are extended by two phantom points at
// each end taken on the cubic through the four end points (p_{-1} = 4 p_0 - 6 p_1 + 4 p_2 - p_3,
// p_{-2} likewise from p_{-1}..p_2, symmetric at the other end). Hence cubic reproduction holds up
// to the ends, the curve spans all n intervals, and it interpolates p_0, p_1, p_{n-1}, p_n exactly
// (their fourth differences involve only points on that end cubic). Needs >= 4 points.
// Closed curves: indices mod the point count, one piece per point, >= 3 points.
// Exactness: only +, -, * and division by 3 and 6: exact in EPECK and Simple_cartesian<Gmpq>.

#ifndef FAIR_CUBIC_QUASI_INTERPOLANT_2_H
#define FAIR_CUBIC_QUASI_INTERPOLANT_2_H

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

/// The options of a Cubic_quasi_interpolant_2 (doc/concepts.md).
struct Cubic_quasi_interpolant_options {
  /// Closed: the periodic quasi-interpolant (>= 3 points); open: >= 4 points.
  bool closed = false;
};

template <class K>
class Cubic_quasi_interpolant_2 {
public:
  typedef K Kernel;
  typedef Cubic_quasi_interpolant_options Options;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Bezier_2<K> Piece;

  /// Throws Invalid_input_error for too few points (4 open, 3 closed), non-finite coordinates or
  /// coincident consecutive points.
  explicit Cubic_quasi_interpolant_2(std::vector<Point_2> points, const Cubic_quasi_interpolant_options& options = {})
    : points_(std::move(points)), options_(options) {
    const bool closed = options_.closed;
    internal::common::check_interpolation_input(points_, closed ? 3 : 4, closed, "Cubic_quasi_interpolant_2");
    const std::size_t n = points_.size();
    std::vector<Point_2> data;  // the data the (-1,8,-1)/6 rule is applied to
    if (closed) {
      data = points_;
    } else {
      const Point_2 a1 = internal::classic::classic_cubic_extrapolation<K>(points_[0], points_[1], points_[2], points_[3]);
      const Point_2 a2 = internal::classic::classic_cubic_extrapolation<K>(a1, points_[0], points_[1], points_[2]);
      const Point_2 b1 = internal::classic::classic_cubic_extrapolation<K>(points_[n - 1], points_[n - 2], points_[n - 3],
                                                                  points_[n - 4]);
      const Point_2 b2 = internal::classic::classic_cubic_extrapolation<K>(b1, points_[n - 1], points_[n - 2], points_[n - 3]);
      data.reserve(n + 4);
      data.push_back(a2);
      data.push_back(a1);
      data.insert(data.end(), points_.begin(), points_.end());
      data.push_back(b1);
      data.push_back(b2);
    }
    const std::size_t m = data.size();
    const FT w(FT(-1) / FT(6)), c(FT(8) / FT(6)), zero(0);
    if (closed) {
      control_.reserve(m);
      for (std::size_t i = 0; i < m; ++i)
        control_.push_back(internal::common::combine<K>(w, data[(i + m - 1) % m], c, data[i], w, data[(i + 1) % m],
                                                        zero, data[i]));
    } else {
      control_.reserve(m - 2);
      for (std::size_t i = 1; i + 1 < m; ++i)
        control_.push_back(internal::common::combine<K>(w, data[i - 1], c, data[i], w, data[i + 1], zero, data[i]));
    }
    spline_ = internal::classic::classic_uniform_spline<K>(control_, closed, "Cubic_quasi_interpolant_2");
    pieces_ = spline_->polynomial_pieces();
  }

  /// The cubic Bezier pieces; piece i spans the knot interval [i, i+1], from near p_i to near
  /// p_{i+1} (exactly, where the fourth difference vanishes).
  const std::vector<Piece>& pieces() const { return pieces_; }
  /// spline().nurbs(): the C2 cubic in the exchange form (fair/Nurbs_curve_2.h): single interior
  /// knots, clamped when open, periodic when closed; its pieces are pieces() (doc/nurbs.md).
  Nurbs_curve_2<K> nurbs() const { return (*spline_).nurbs(); }
  /// The result as the library's spline (uniform integer breakpoints; clamped form when open,
  /// periodic when closed), whose pieces are pieces().
  const Cubic_spline_2<K>& spline() const { return *spline_; }
  std::size_t number_of_pieces() const { return pieces_.size(); }
  const std::vector<Point_2>& points() const { return points_; }
  /// The B-spline control points c_i (for an open curve c_{-1}..c_{n+1}, from the extended data).
  const std::vector<Point_2>& control_polygon() const { return control_; }
  bool is_closed() const { return options_.closed; }
  const Cubic_quasi_interpolant_options& options() const { return options_; }

private:
  std::vector<Point_2> points_;
  Cubic_quasi_interpolant_options options_;
  std::vector<Point_2> control_;
  std::optional<Cubic_spline_2<K>> spline_; // set in the constructor's body, after the data checks
  std::vector<Piece> pieces_;
};

} // namespace fair

#endif // FAIR_CUBIC_QUASI_INTERPOLANT_2_H
