// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::io::certify_curve_file: exact certification of a curve JSON written by fair-curves
// (doc/fair_curves_program.md, "certify"; issue 26 §3). The numbers of the file are read exactly
// (a decimal is the double it denotes, "p/q" the rational) into CGAL::Simple_cartesian<Gmpq>, and
// every property is decided in exact rational arithmetic on those numbers, or by a certified
// root isolation (the curvature extrema of a conic piece):
//
//   C0            every join (and a closed curve's seam): the end of piece j is the start of j+1;
//   G1            the end tangent of piece j and the start tangent of piece j+1 are parallel and
//                 point the same way (cross product 0, dot product > 0; tangents b_q - b_{q-1}
//                 and b_1 - b_0, which the positive weights do not turn);
//   |kappa|       the squared curvature at the end of piece j equals that at the start of j+1;
//   interpolation each point of --points is a point of the curve: a piece end, or, for a
//                 kappa-curve, c_j(t_j) of the piece's "point" and "t";
//   kappa maxima  kappa-curves: the |curvature| of each conic piece has one maximum in (0, 1),
//                 certified (Rational_quadratic_bezier_2::curvature_extrema), and t_j lies in its
//                 isolating interval; or t_j is 0 or 1 (a point on its join) and the piece has
//                 no interior maximum;
//   Proposition 1 cubic splines with single knots (their "bspline", Cubic_spline_2::from_nurbs):
//                 a convex control polygon implies a locally convex curve (spline_convexity).
//
// Which properties a file claims follows from its "method" (claimed_properties()). A file of
// doubles made by a floating-point solve generally meets G1 and |kappa| only to rounding: each
// property reports its defect, a relative number (|sin| of the tangent angle; |k1^2 - k2^2| /
// max(k1^2, k2^2); distance / extent; |t_j - t*|), and holds when the defect is 0, or at most
// `tolerance` (default 0: exactly).
//
// The checks themselves are in fair/io/internal/certify_properties.h.
//
// Errors: Parse_error (read_curve.h, read_nurbs.h, read_points.h) for a malformed file.

#ifndef FAIR_IO_CERTIFY_CURVE_H
#define FAIR_IO_CERTIFY_CURVE_H

#include <fair/io/internal/certify_properties.h>

#include <string>
#include <vector>

namespace fair {
namespace io {

/// One certified property: its name, whether it holds, the largest defect (0: exactly) and a
/// detail naming where it fails.
struct Certified_property {
  std::string name;
  bool holds = true;
  double defect = 0;
  std::string detail;
};

/// The properties a curve file's method claims (C0 always).
inline std::vector<std::string> claimed_properties(const std::string& method) {
  if (method == "kappa") return {"C0", "G1", "|kappa|", "interpolation", "kappa maxima"};
  if (method == "cardinal" || method == "catmull-rom") return {"C0", "G1", "interpolation"};
  if (method == "cubic") return {"C0", "G1", "|kappa|", "interpolation", "Proposition 1"};
  if (method == "csr" || method == "bspline" || method == "quasi" || method == "shapes")
    return {"C0", "G1", "|kappa|", "Proposition 1"};
  if (method == "optimal") return {"C0", "G1", "interpolation"};
  return {"C0"};
}

/// The certificate of the curve file `file` (and of `points_file`, when not empty, for
/// interpolation): one property per claimed property of its method, in the order of
/// claimed_properties(). \throws Parse_error for a malformed file.
inline std::vector<Certified_property> certify_curve_file(const std::string& file, const std::string& points_file = "",
                                                          double tolerance = 0) {
  const internal::Certify_curve curve = internal::certify_read(file);
  std::vector<Certified_property> out;
  for (const std::string& name : claimed_properties(curve.curve.method)) {
    internal::Certify_tally tally;
    if (name == "interpolation") tally = internal::certify_interpolation(curve, points_file, tolerance);
    else if (name == "kappa maxima") tally = internal::certify_kappa_maxima(curve, tolerance);
    else if (name == "Proposition 1") tally = internal::certify_proposition_1(curve);
    else tally = internal::certify_joins(curve, name, tolerance);  // C0, G1, |kappa|
    Certified_property p;
    p.name = name;
    p.holds = tally.holds;
    p.defect = tally.defect;
    p.detail = tally.detail;
    out.push_back(p);
  }
  return out;
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_CERTIFY_CURVE_H
