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
// Errors: Parse_error (read_curve.h, read_nurbs.h, read_points.h) for a malformed file.

#ifndef FAIR_IO_CERTIFY_CURVE_H
#define FAIR_IO_CERTIFY_CURVE_H

#include <fair/Cubic_spline_2.h>
#include <fair/Errors.h>
#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/Spline_convexity.h>
#include <fair/io/parsing.h>
#include <fair/io/read_curve.h>
#include <fair/io/read_points.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
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

namespace internal {

typedef CGAL::Simple_cartesian<CGAL::Gmpq> Certify_kernel;

inline double certify_relative(const CGAL::Gmpq& a, const CGAL::Gmpq& scale) {
  return scale == 0 ? (a == 0 ? 0.0 : HUGE_VAL) : std::fabs(CGAL::to_double(a / scale));
}

/// Records a defect at `where` (keeps the largest and names the first failure).
inline void certify_note(Certified_property& p, double defect, double tolerance, const std::string& where) {
  if (defect == 0) return;
  p.defect = std::max(p.defect, defect);
  if (defect > tolerance && p.holds) {
    p.holds = false;
    p.detail = where;
  }
}

} // namespace internal

/// The certificate of the curve file `file` (and of `points_file`, when not empty, for
/// interpolation): one property per claimed property of its method, in the order of
/// claimed_properties(). \throws Parse_error for a malformed file.
inline std::vector<Certified_property> certify_curve_file(const std::string& file, const std::string& points_file = "",
                                                          double tolerance = 0) {
  typedef internal::Certify_kernel Q;
  typedef CGAL::Gmpq FT;
  typedef Q::Point_2 P;
  const std::string text = read_text_file(file);
  const Curve_file<Q> curve = parse_curve_json<Q>(text, file);
  const std::vector<Rational_bezier_2<Q>>& pieces = curve.pieces;
  const std::size_t m = pieces.size();
  const std::size_t joins = curve.closed ? m : m - 1;
  // the extent: the control points' bounding box diagonal, squared, exactly
  FT lo_x = pieces[0].source().x(), hi_x = lo_x, lo_y = pieces[0].source().y(), hi_y = lo_y;
  for (const auto& b : pieces)
    for (const P& p : b.control_points()) {
      lo_x = std::min(lo_x, p.x());
      hi_x = std::max(hi_x, p.x());
      lo_y = std::min(lo_y, p.y());
      hi_y = std::max(hi_y, p.y());
    }
  const FT extent2 = (hi_x - lo_x) * (hi_x - lo_x) + (hi_y - lo_y) * (hi_y - lo_y);

  // the kappa-curve's "point" and "t" per piece (read exactly like every number of the file)
  std::vector<FT> t(m, FT(-1));
  if (curve.method == "kappa") {
    const Json_value root = parse_json(text, file);
    const Json_value* ps = root.find("pieces");
    for (std::size_t j = 0; ps && j < ps->items.size() && j < m; ++j)
      if (const Json_value* tj = ps->items[j].find("t"))
        t[j] = to_ft<FT>(parse_number(tj->text, file, tj->line, "t"));
  }

  std::vector<Certified_property> out;
  for (const std::string& name : claimed_properties(curve.method)) {
    Certified_property p;
    p.name = name;
    for (std::size_t j = 0; j < joins && name != "interpolation" && name != "kappa maxima" && name != "Proposition 1";
         ++j) {
      const Rational_bezier_2<Q>& a = pieces[j];
      const Rational_bezier_2<Q>& b = pieces[(j + 1) % m];
      const std::string where = "join " + std::to_string(j) + " (pieces " + std::to_string(j) + ", " +
                                std::to_string((j + 1) % m) + ")";
      if (name == "C0") {
        const FT d2 = CGAL::squared_distance(a.target(), b.source());
        internal::certify_note(p, d2 == 0 ? 0.0 : std::sqrt(internal::certify_relative(d2, extent2)), tolerance, where);
      } else if (name == "G1") {
        const auto ta = a.control_point(a.degree()) - a.control_point(a.degree() - 1);
        const auto tb = b.control_point(1) - b.control_point(0);
        const FT cross = ta.x() * tb.y() - ta.y() * tb.x(), dot = ta * tb;
        if (ta == CGAL::NULL_VECTOR || tb == CGAL::NULL_VECTOR || dot <= 0) {
          internal::certify_note(p, HUGE_VAL, tolerance, where + ": tangents " + (dot <= 0 ? "opposite or orthogonal" : "zero"));
        } else {
          // |sin angle| = |cross| / (|ta| |tb|), its square exactly
          internal::certify_note(p, std::sqrt(internal::certify_relative(cross * cross, ta.squared_length() * tb.squared_length())),
                                 tolerance, where);
        }
      } else if (name == "|kappa|") {
        const FT ka = a.squared_curvature(FT(1)), kb = b.squared_curvature(FT(0));
        internal::certify_note(p, internal::certify_relative(ka - kb, std::max(ka, kb)), tolerance, where);
      }
    }
    if (name == "interpolation") {
      if (points_file.empty()) {
        p.detail = "not checked: no --points";
      } else {
        const Point_file<Q> data = read_point_file<Q>(points_file);
        std::vector<P> on_curve;
        for (std::size_t j = 0; j < m; ++j) {
          on_curve.push_back(pieces[j].source());
          on_curve.push_back(pieces[j].target());
          if (t[j] >= 0 && t[j] <= 1) on_curve.push_back(pieces[j].point(t[j]));
        }
        for (std::size_t i = 0; i < data.points.size(); ++i) {
          FT best = -1;
          for (const P& c : on_curve) {
            const FT d2 = CGAL::squared_distance(c, data.points[i]);
            if (best < 0 || d2 < best) best = d2;
          }
          internal::certify_note(p, best == 0 ? 0.0 : std::sqrt(internal::certify_relative(best, extent2)), tolerance,
                                 "point " + std::to_string(i));
        }
        p.detail = (p.holds ? "" : p.detail + "; ") + std::to_string(data.points.size()) + " points";
      }
    }
    if (name == "kappa maxima") {
      for (std::size_t j = 0; j < m; ++j) {
        const Rational_bezier_2<Q>& b = pieces[j];
        const std::string where = "piece " + std::to_string(j);
        if (b.degree() != 2 || b.weight(0) != 1 || b.weight(2) != 1 || t[j] < 0) {
          internal::certify_note(p, HUGE_VAL, tolerance, where + ": not a conic piece (1, w, 1) with \"t\"");
          continue;
        }
        const Rational_quadratic_bezier_2<Q> conic(b.control_point(0), b.control_point(1), b.control_point(2), b.weight(1));
        std::size_t maxima = 0;
        double distance = HUGE_VAL;
        for (const Curvature_extremum& e : conic.curvature_extrema())
          if (e.kind == Curvature_extremum_kind::MAXIMUM) {
            ++maxima;
            distance = t[j] >= e.t_lower && t[j] <= e.t_upper
                           ? 0.0
                           : std::min(std::fabs(CGAL::to_double(t[j] - e.t_lower)), std::fabs(CGAL::to_double(t[j] - e.t_upper)));
          }
        if (maxima == 1) internal::certify_note(p, distance, tolerance, where + ": t off the maximum");
        else if (maxima == 0 && (t[j] == 0 || t[j] == 1)) continue;  // on its join
        else internal::certify_note(p, HUGE_VAL, tolerance, where + ": " + std::to_string(maxima) + " interior maxima");
      }
    }
    if (name == "Proposition 1") {
      const Json_value root = parse_json(text, file);
      const Json_value* bs = root.find("bspline");
      try {
        if (!bs) throw Precondition_error("no \"bspline\" member");
        const Cubic_spline_2<Q> s = Cubic_spline_2<Q>::from_nurbs(read_nurbs<Q>(*bs, file));
        const Spline_convexity_report<Q> r = spline_convexity(s);
        p.holds = r.proposition_holds();
        p.detail = std::string("control polygon ") + (r.polygon_convex ? "convex" : "not convex") + ", curve " +
                   (r.curve_locally_convex ? "locally convex" : "not locally convex");
      } catch (const Precondition_error& e) {
        p.detail = std::string("not applicable: ") + e.what();
      }
    }
    out.push_back(p);
  }
  return out;
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_CERTIFY_CURVE_H
