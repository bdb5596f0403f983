// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The exact checks of fair::io::certify_curve_file (fair/io/certify_curve.h, whose file comment
// states each property and its defect): the curve file read exactly into
// CGAL::Simple_cartesian<Gmpq> (Certify_curve), and one function per property that returns its
// tally (holds, largest defect, where it first fails).

#ifndef FAIR_IO_INTERNAL_CERTIFY_PROPERTIES_H
#define FAIR_IO_INTERNAL_CERTIFY_PROPERTIES_H

#include <fair/Cubic_spline_2.h>
#include <fair/Errors.h>
#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/Spline_convexity.h>
#include <fair/io/parsing.h>
#include <fair/io/read_curve.h>
#include <fair/io/read_nurbs.h>
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
namespace internal {

typedef CGAL::Simple_cartesian<CGAL::Gmpq> Certify_kernel;

/// |a / scale| in double (0 / 0 is 0, a / 0 is infinite).
inline double certify_relative(const CGAL::Gmpq& a, const CGAL::Gmpq& scale) {
  return scale == 0 ? (a == 0 ? 0.0 : HUGE_VAL) : std::fabs(CGAL::to_double(a / scale));
}

/// The outcome of one property: whether it holds, the largest defect, where it first fails.
struct Certify_tally {
  bool holds = true;
  double defect = 0;
  std::string detail;

  /// Records a defect at `where` (keeps the largest and names the first failure).
  void note(double d, double tolerance, const std::string& where) {
    if (d == 0) return;
    defect = std::max(defect, d);
    if (d > tolerance && holds) {
      holds = false;
      detail = where;
    }
  }
};

/// A curve file read exactly: its text and pieces, the squared diagonal of its control points'
/// bounding box, and for a kappa-curve each piece's "t" (-1 where the file has none).
struct Certify_curve {
  typedef CGAL::Gmpq FT;
  std::string file, text;
  Curve_file<Certify_kernel> curve;
  FT extent2 = 0;
  std::vector<FT> t;
};

/// Reads `file` exactly. \throws Parse_error for a malformed file.
inline Certify_curve certify_read(const std::string& file) {
  typedef CGAL::Gmpq FT;
  Certify_curve c;
  c.file = file;
  c.text = read_text_file(file);
  c.curve = parse_curve_json<Certify_kernel>(c.text, file);
  const auto& pieces = c.curve.pieces;
  FT lo_x = pieces[0].source().x(), hi_x = lo_x, lo_y = pieces[0].source().y(), hi_y = lo_y;
  for (const auto& b : pieces)
    for (const auto& p : b.control_points()) {
      lo_x = std::min(lo_x, p.x());
      hi_x = std::max(hi_x, p.x());
      lo_y = std::min(lo_y, p.y());
      hi_y = std::max(hi_y, p.y());
    }
  c.extent2 = (hi_x - lo_x) * (hi_x - lo_x) + (hi_y - lo_y) * (hi_y - lo_y);
  c.t.assign(pieces.size(), FT(-1));
  if (c.curve.method == "kappa") {
    const Json_value root = parse_json(c.text, file);
    const Json_value* ps = root.find("pieces");
    for (std::size_t j = 0; ps && j < ps->items.size() && j < pieces.size(); ++j)
      if (const Json_value* tj = ps->items[j].find("t"))
        c.t[j] = to_ft<FT>(parse_number(tj->text, file, tj->line, "t"));
  }
  return c;
}

/// C0, G1 or |kappa| (`name`) at every join, and at a closed curve's seam.
inline Certify_tally certify_joins(const Certify_curve& c, const std::string& name, double tolerance) {
  typedef CGAL::Gmpq FT;
  const auto& pieces = c.curve.pieces;
  const std::size_t m = pieces.size();
  const std::size_t joins = c.curve.closed ? m : m - 1;
  Certify_tally p;
  for (std::size_t j = 0; j < joins; ++j) {
    const Rational_bezier_2<Certify_kernel>& a = pieces[j];
    const Rational_bezier_2<Certify_kernel>& b = pieces[(j + 1) % m];
    const std::string where = "join " + std::to_string(j) + " (pieces " + std::to_string(j) + ", " +
                              std::to_string((j + 1) % m) + ")";
    if (name == "C0") {
      const FT d2 = CGAL::squared_distance(a.target(), b.source());
      p.note(d2 == 0 ? 0.0 : std::sqrt(certify_relative(d2, c.extent2)), tolerance, where);
    } else if (name == "G1") {
      const auto ta = a.control_point(a.degree()) - a.control_point(a.degree() - 1);
      const auto tb = b.control_point(1) - b.control_point(0);
      const FT cross = ta.x() * tb.y() - ta.y() * tb.x(), dot = ta * tb;
      if (ta == CGAL::NULL_VECTOR || tb == CGAL::NULL_VECTOR || dot <= 0) {
        p.note(HUGE_VAL, tolerance, where + ": tangents " + (dot <= 0 ? "opposite or orthogonal" : "zero"));
      } else {
        // |sin angle| = |cross| / (|ta| |tb|), its square exactly
        p.note(std::sqrt(certify_relative(cross * cross, ta.squared_length() * tb.squared_length())), tolerance, where);
      }
    } else if (name == "|kappa|") {
      const FT ka = a.squared_curvature(FT(1)), kb = b.squared_curvature(FT(0));
      p.note(certify_relative(ka - kb, std::max(ka, kb)), tolerance, where);
    }
  }
  return p;
}

/// Every point of `points_file` is a piece end or, for a kappa-curve, c_j(t_j).
inline Certify_tally certify_interpolation(const Certify_curve& c, const std::string& points_file, double tolerance) {
  typedef CGAL::Gmpq FT;
  typedef Certify_kernel::Point_2 P;
  Certify_tally p;
  if (points_file.empty()) {
    p.detail = "not checked: no --points";
    return p;
  }
  const auto& pieces = c.curve.pieces;
  const Point_file<Certify_kernel> data = read_point_file<Certify_kernel>(points_file);
  std::vector<P> on_curve;
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    on_curve.push_back(pieces[j].source());
    on_curve.push_back(pieces[j].target());
    if (c.t[j] >= 0 && c.t[j] <= 1) on_curve.push_back(pieces[j].point(c.t[j]));
  }
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    FT best = -1;
    for (const P& q : on_curve) {
      const FT d2 = CGAL::squared_distance(q, data.points[i]);
      if (best < 0 || d2 < best) best = d2;
    }
    p.note(best == 0 ? 0.0 : std::sqrt(certify_relative(best, c.extent2)), tolerance, "point " + std::to_string(i));
  }
  p.detail = (p.holds ? "" : p.detail + "; ") + std::to_string(data.points.size()) + " points";
  return p;
}

/// Each conic piece (1, w, 1) has one certified interior |curvature| maximum whose isolating
/// interval holds t_j, or none and t_j on its join (0 or 1).
inline Certify_tally certify_kappa_maxima(const Certify_curve& c, double tolerance) {
  const auto& pieces = c.curve.pieces;
  Certify_tally p;
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    const Rational_bezier_2<Certify_kernel>& b = pieces[j];
    const CGAL::Gmpq& t = c.t[j];
    const std::string where = "piece " + std::to_string(j);
    if (b.degree() != 2 || b.weight(0) != 1 || b.weight(2) != 1 || t < 0) {
      p.note(HUGE_VAL, tolerance, where + ": not a conic piece (1, w, 1) with \"t\"");
      continue;
    }
    const Rational_quadratic_bezier_2<Certify_kernel> conic(b.control_point(0), b.control_point(1), b.control_point(2),
                                                            b.weight(1));
    std::size_t maxima = 0;
    double distance = HUGE_VAL;
    for (const Curvature_extremum& e : conic.curvature_extrema())
      if (e.kind == Curvature_extremum_kind::MAXIMUM) {
        ++maxima;
        distance = t >= e.t_lower && t <= e.t_upper
                       ? 0.0
                       : std::min(std::fabs(CGAL::to_double(t - e.t_lower)), std::fabs(CGAL::to_double(t - e.t_upper)));
      }
    if (maxima == 1) p.note(distance, tolerance, where + ": t off the maximum");
    else if (maxima == 0 && (t == 0 || t == 1)) continue;  // on its join
    else p.note(HUGE_VAL, tolerance, where + ": " + std::to_string(maxima) + " interior maxima");
  }
  return p;
}

/// Proposition 1 on the file's "bspline" as a cubic spline with single knots: a convex control
/// polygon implies a locally convex curve. Not applicable (holds, said in the detail) otherwise.
inline Certify_tally certify_proposition_1(const Certify_curve& c) {
  Certify_tally p;
  const Json_value root = parse_json(c.text, c.file);
  const Json_value* bs = root.find("bspline");
  try {
    if (!bs) throw Precondition_error("no \"bspline\" member");
    const Cubic_spline_2<Certify_kernel> s = Cubic_spline_2<Certify_kernel>::from_nurbs(read_nurbs<Certify_kernel>(*bs, c.file));
    const Spline_convexity_report<Certify_kernel> r = spline_convexity(s);
    p.holds = r.proposition_holds();
    p.detail = std::string("control polygon ") + (r.polygon_convex ? "convex" : "not convex") + ", curve " +
               (r.curve_locally_convex ? "locally convex" : "not locally convex");
  } catch (const Precondition_error& e) {
    p.detail = std::string("not applicable: ") + e.what();
  }
  return p;
}

} // namespace internal
} // namespace io
} // namespace fair

#endif // FAIR_IO_INTERNAL_CERTIFY_PROPERTIES_H
