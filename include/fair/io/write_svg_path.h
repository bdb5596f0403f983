// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::io::svg_path: a curve (fair::Nurbs_curve_2) as the `d` attribute of an SVG <path>, for
// programs that read SVG paths (doc/io.md, "SVG path"):
//
//  - a polynomial piece of degree 1, 2 or 3 is one L, Q or C command with its own control
//    points: exact (the nearest doubles, %.17g, of the piece's control points);
//  - a rational piece, or a polynomial one of degree > 3, is approximated by cubic C commands
//    with a certified bound on the distance between the piece and the cubics.
//
// The bound. On a sub-interval of a piece, in its local parameter s in [0, 1], the piece is
// c(s) = A(s) / W(s) with A = (wx, wy) and W the homogeneous Bernstein polynomials of degree q
// (W > 0). The cubic C(s) is the Hermite interpolant of c: C(0) = c(0), C(1) = c(1),
// C'(0) = c'(0) = q (A_1 - W_1 c(0)) / W_0, C'(1) = c'(1) = q (W_{q-1} c(1) - A_{q-1}) / W_q,
// i.e. the Bezier points c(0), c(0) + c'(0)/3, c(1) - c'(1)/3, c(1). Then
//
//   c(s) - C(s) = (A(s) - W(s) C(s)) / W(s) = E(s) / W(s),
//
// E a vector polynomial of degree q + 3 whose Bernstein coefficients E_k follow from degree
// elevation of A and the Bernstein product W C. A Bernstein polynomial is a convex combination
// of its coefficients, so |E(s)| <= max_k |E_k| and W(s) >= min_k W_k > 0:
//
//   |c(s) - C(s)| <= max_k |E_k| / min_k W_k          for every s in [0, 1]       (B)
//
// — a bound on the parametric distance, hence on the Hausdorff distance. Rounding of the double
// computation of (B) is covered by adding 32 (q + 4) eps (max |A_k| + max W_k max |C_k|) / min W_k.
// A sub-interval whose bound is above the tolerance is halved (de Casteljau at 1/2 on the
// homogeneous coefficients) and both halves treated again; the Hermite error is O(h^4), so each
// halving divides the bound by about 16.
//
// Numbers are doubles (an exact kernel's values rounded to the nearest double): the SVG path has
// no other numbers. A closed curve ends with "Z" (its last point is its first).
//
// The approximation itself is in fair/io/internal/svg_path_approximation.h.
//
// Errors: Precondition_error for a tolerance that is not finite or below 1e-13 of the curve's
// extent (rounding could not certify it), or a value that is not finite as a double;
// Non_convergence_error if 40 halvings do not reach the tolerance (not met on any test curve).

#ifndef FAIR_IO_WRITE_SVG_PATH_H
#define FAIR_IO_WRITE_SVG_PATH_H

#include <fair/Errors.h>
#include <fair/Nurbs_curve_2.h>
#include <fair/io/internal/svg_path_approximation.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace fair {
namespace io {

/// One command of the path: `degree` 1 (L), 2 (Q) or 3 (C) with control points[0..degree]
/// (points[0] is the current point), standing for the parameters [t0, t1] of piece `piece`
/// of Nurbs_curve_2::pieces(); `error_bound` 0 when the command is the piece itself, else the
/// certified bound (B) on |piece(t0 + s (t1 - t0)) - command(s)|, s in [0, 1].
struct Svg_path_segment {
  std::size_t piece = 0;
  double t0 = 0, t1 = 1;
  int degree = 3;
  std::array<std::array<double, 2>, 4> points{};
  double error_bound = 0;
};

/// The path: its `d` text, its commands, and the largest bound of any command (0: exact).
struct Svg_path {
  std::string d;
  std::vector<Svg_path_segment> segments;
  double error_bound = 0;
  bool is_exact() const { return error_bound == 0; }
};

/// The extent of a curve: the diagonal of its control points' bounding box (which contains the
/// curve), in double.
template <class K>
double svg_path_extent(const Nurbs_curve_2<K>& c) {
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for (const auto& p : c.control_points()) {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    lo[0] = std::min(lo[0], x);
    hi[0] = std::max(hi[0], x);
    lo[1] = std::min(lo[1], y);
    hi[1] = std::max(hi[1], y);
  }
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
}

/// The curve as an SVG path (file comment); `tolerance` bounds the distance of every
/// approximated piece from its cubics, in the curve's units.
/// \throws Precondition_error, Non_convergence_error as in the file comment.
template <class K>
Svg_path svg_path(const Nurbs_curve_2<K>& c, double tolerance) {
  const double extent = svg_path_extent(c);
  if (!std::isfinite(extent))
    throw Precondition_error("fair::io::svg_path: a control point is not finite as a double");
  if (!std::isfinite(tolerance) || !(tolerance >= 1e-13 * extent) || !(tolerance > 0))
    throw Precondition_error("fair::io::svg_path: tolerance " + internal::svg_number(tolerance) +
                             " is not finite or below 1e-13 of the curve's extent " + internal::svg_number(extent));
  Svg_path path;
  const auto& pieces = c.pieces();
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    const auto& b = pieces[j];
    const std::size_t q = b.degree();
    if (b.is_polynomial() && q <= 3) {
      Svg_path_segment s;
      s.piece = j;
      s.degree = static_cast<int>(q);
      for (std::size_t i = 0; i <= q; ++i)
        s.points[i] = {internal::svg_finite(b.control_point(i).x(), j, "coordinate"),
                       internal::svg_finite(b.control_point(i).y(), j, "coordinate")};
      path.segments.push_back(s);
      continue;
    }
    std::vector<internal::Svg_homogeneous> H(q + 1);
    for (std::size_t i = 0; i <= q; ++i) {
      const double w = internal::svg_finite(b.weight(i), j, "weight");
      H[i] = {w * internal::svg_finite(b.control_point(i).x(), j, "coordinate"),
              w * internal::svg_finite(b.control_point(i).y(), j, "coordinate"), w};
    }
    std::vector<internal::Svg_cubic> cubics;
    internal::svg_approximate(H, j, 0, 1, tolerance, 0, cubics);
    const std::size_t first = path.segments.size();
    for (const internal::Svg_cubic& cubic : cubics) {
      Svg_path_segment s;
      s.piece = j;
      s.t0 = cubic.s0;
      s.t1 = cubic.s1;
      s.degree = 3;
      s.points = cubic.points;
      s.error_bound = cubic.error_bound;
      path.segments.push_back(s);
    }
    // The piece's ends are its first and last control points, as doubles: (w x) / w may differ
    // from x by an ulp, and consecutive pieces must meet exactly (the ulp is inside the rounding
    // term of the bound).
    path.segments[first].points[0] = {internal::svg_finite(b.control_point(0).x(), j, "coordinate"),
                                      internal::svg_finite(b.control_point(0).y(), j, "coordinate")};
    path.segments.back().points[3] = {internal::svg_finite(b.control_point(q).x(), j, "coordinate"),
                                      internal::svg_finite(b.control_point(q).y(), j, "coordinate")};
  }
  std::string& d = path.d;
  for (std::size_t k = 0; k < path.segments.size(); ++k) {
    const Svg_path_segment& s = path.segments[k];
    path.error_bound = std::max(path.error_bound, s.error_bound);
    if (k == 0) d += "M " + internal::svg_number(s.points[0][0]) + " " + internal::svg_number(s.points[0][1]);
    d += s.degree == 1 ? " L" : (s.degree == 2 ? " Q" : " C");
    for (int i = 1; i <= s.degree; ++i)
      d += " " + internal::svg_number(s.points[static_cast<std::size_t>(i)][0]) + " " +
           internal::svg_number(s.points[static_cast<std::size_t>(i)][1]);
  }
  if (c.is_closed() && !d.empty()) d += " Z";
  return path;
}

/// The default tolerance of the program: 1e-6 of the curve's extent (a millionth of the
/// drawing, far below what a renderer shows; about 4 to 8 cubics per conic piece of a kappa-curve).
template <class K>
Svg_path svg_path(const Nurbs_curve_2<K>& c) {
  return svg_path(c, 1e-6 * svg_path_extent(c));
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_WRITE_SVG_PATH_H
