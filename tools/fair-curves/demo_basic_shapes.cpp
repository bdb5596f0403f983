// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Demo cases of design with basic shapes (Karciauskas-Peters Sec. 6, doc/basic_shapes.md): the
// designs of Figs. 10, 11, 12 and 14 -- circle arcs, ellipses, a hyperbola, a polynomial cubic and
// a line, with marked points, merged into one C2 cubic spline that keeps every shape on its
// interior -- and a designer's edit of the control polygon.

#include "basic_shapes_figures.h"
#include "registry.h"
#include "tool_common.h"

#include <fair/Basic_shape_design.h>
#include <fair/Fairness_metrics.h>
#include <fair/Parametric_curve_2.h>
#include <fair/Spline_convexity.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using fair_curves::Kernel;
using fair_curves::Point_2;
typedef fair::Basic_shape_2<Kernel> Shape;
typedef fair::Rational_quadratic_bezier_2<Kernel> Conic;
typedef CGAL::Exact_predicates_exact_constructions_kernel EPECK;

using fair_curves::pi;

// n marks evenly spaced strictly inside (a, b).
std::vector<double> even(double a, double b, int n) {
  std::vector<double> m;
  for (int k = 1; k <= n; ++k) m.push_back(a + (b - a) * k / (n + 1));
  return m;
}

// The quarter of the ellipse (centre c, semi-axes a, b) from angle q pi/2 to (q+1) pi/2 (ccw), as a
// conic in standard form (w = 1/sqrt 2).
Conic quarter_ellipse(const Point_2& c, double a, double b, int q) {
  auto at = [&](int k) {
    const double t = k * pi / 2;
    return Point_2(c.x() + a * std::cos(t), c.y() + b * std::sin(t));
  };
  const Point_2 p0 = at(q), p2 = at(q + 1);
  const Point_2 p1(p0.x() + p2.x() - c.x(), p0.y() + p2.y() - c.y());
  return Conic(p0, p1, p2, std::sqrt(0.5));
}

// The marked points of a shape: the curve at the interior breakpoints of its parts.
void marked_points(const Shape& s, std::vector<fair::io::Xy>& out) {
  for (const auto& part : s.parts())
    for (std::size_t i = 1; i + 1 < part.breakpoints().size(); ++i) {
      const Point_2 p = part.point(part.breakpoints()[i]);
      out.push_back(fair::io::Xy{p.x(), p.y()});
    }
}

// Fig. 12's design (three quarters of the unit circle and a conic quarter) in any kernel.
template <class K>
std::vector<fair::Basic_shape_2<K>> fig12_shapes(bool ellipse) {
  typedef typename K::Point_2 P;
  std::vector<fair::Basic_shape_2<K>> s;
  s.push_back(fair::Basic_shape_2<K>::circle_arc(P(0, 0), typename K::FT(1), 0, 1.5 * pi, even(0, 1.5 * pi, 17)));
  const fair::Rational_quadratic_bezier_2<K> q(P(0, -1), P(ellipse ? 0.9 : 0.6, ellipse ? -0.9 : -0.6), P(1, 0),
                                               typename K::FT(ellipse ? 0.5 : 1.6));
  s.push_back(fair::Basic_shape_2<K>::conic(q, {0.2, 0.4, 0.5, 0.6, 0.8}));
  return s;
}

void add_design_case(fair_curves::Gallery& gallery, const std::string& title, const std::string& caption,
                     const std::vector<Shape>& shapes, const fair::Cubic_spline_2<Kernel>& spline,
                     const fair::Basic_shape_design_2<Kernel>& design, const fair::Cubic_spline_2<EPECK>* exact_design = nullptr) {
  std::vector<fair::io::Xy> marks;
  for (const Shape& s : shapes) marked_points(s, marks);
  const fair_curves::Curve_figures f = fair_curves::design_figures(spline, marks, title);
  fair_curves::Gallery_case g;
  g.title = title;
  g.caption = caption;
  g.images = {{"curve", f.curve_svg}, {"curvature", f.curvature_svg}};
  std::string joins;
  for (const fair::Shape_join& j : design.joins)
    if (!j.inside) joins += std::string(joins.empty() ? "" : ", ") + fair::to_string(j.kind);
  const auto pieces = spline.pieces();
  // The library's figures: the curvature range over its profile and the certified extrema, and
  // the certified inflections (fair/Fairness_metrics.h).
  const fair::Fairness_report fairness = fair::fairness_report(pieces);
  std::size_t exact = 0;
  for (const fair::Shape_span& s : design.spans) exact += s.end_exact - s.first_exact;
  g.measurements = {{"pieces / control points", std::to_string(spline.number_of_pieces()) + " / " +
                                                     std::to_string(spline.number_of_control_points())},
                    {"joins between shapes", joins.empty() ? "none" : joins},
                    {"pieces reproducing a shape exactly", std::to_string(exact)},
                    {"curvature range (profile and certified extrema)",
                     "[" + fair_curves::format_number(fairness.min_curvature) + ", " +
                         fair_curves::format_number(fairness.max_curvature) + "]"},
                    {std::string("inflections") + (fairness.certified ? " (certified)" : " (sampled)"),
                     std::to_string(fairness.inflection_count)},
                    {"arc length", fair_curves::format_number(f.sampled.length(), 10)}};
  // Proposition 1, certified for the drawn spline's data (exact copy, basic_shapes_figures.h), or
  // for the design computed in EPECK when given (in double, rounding turns collinear control points
  // and nearly straight Bezier polygons by an ulp either way).
  const auto c = exact_design ? fair::spline_convexity(*exact_design) : fair_curves::certified_convexity(spline);
  g.measurements.emplace_back(std::string("Proposition 1: polygon convex / curve locally convex") +
                                  (exact_design ? " (design in EPECK)" : ""),
                              std::string(c.polygon_convex ? "yes" : "no") + " / " +
                                  (c.curve_locally_convex ? "yes" : "no"));
  gallery.add_case(std::move(g));
}

void add_design(fair_curves::Gallery& gallery, const std::string& title, const std::string& caption,
                const std::vector<Shape>& shapes, bool closed = false, double merge_tolerance = 1e-9) {
  fair::Basic_shape_design_options o;
  o.closed = closed;
  o.merge_tolerance = merge_tolerance;
  const auto d = fair::basic_shape_design(shapes, o);
  add_design_case(gallery, title, caption, shapes, d.spline, d);
}

} // namespace

void add_basic_shape_cases(fair_curves::Gallery& gallery) {
  gallery.add_section(
      "Design with basic shapes",
      "Karciauskas and Peters, Sec. 6: the designer places basic shapes and marks points on them; each becomes an "
      "exact C2 cubic spline (knots at the marks), and the control polygons are merged into one C2 spline "
      "(Fig. 9): end points that agree or nearly agree become one control point, end points apart are joined by "
      "an edge, every new beta is 1. Every shape is reproduced exactly on its pieces away from the joins. Grey: "
      "the merged control polygon; black dots: the marked points. See doc/basic_shapes.md.");
  const Point_2 o(0, 0);
  // Fig. 10: a semi-circle above a semi-ellipse, not touching: two edges join them.
  {
    std::vector<Shape> s;
    s.push_back(Shape::circle_arc(o, 1, 0, pi, even(0, pi, 11)));
    const Point_2 c(0, -0.4);
    s.push_back(Shape::conic(quarter_ellipse(c, 1, 1.2, 2), {0.15, 0.3, 0.5, 0.7, 0.85}));
    s.push_back(Shape::conic(quarter_ellipse(c, 1, 1.2, 3), {0.15, 0.3, 0.5, 0.7, 0.85}));
    add_design(gallery, "Fig. 10: semi-circle and semi-ellipse",
               "The upper unit semi-circle (11 marks; the one at 90 degrees is the join of its two quarter sub-arcs) and "
               "the lower half of an ellipse with semi-axes 1 and 1.2, 0.4 below (two quarter conics, 5 marks each), "
               "closed: the ends are apart, so each join is an edge of the control polygon, along the tangents.",
               s, true);
    // The designer's variant: the four join points pulled outwards; C2 is kept by construction.
    const auto d = fair::basic_shape_design(s, fair::Basic_shape_design_options{true, 1e-9});
    auto edited = d.spline;
    for (const fair::Shape_join& j : d.joins)
      if (j.kind == fair::Shape_join_kind::EDGE)
        for (std::size_t k = j.control_point; k < j.control_point + 2; ++k) {
          const Point_2 p = edited.control_points()[k];
          edited = edited.with_control_point(k, Point_2(1.25 * p.x(), p.y()));
        }
    add_design_case(gallery, "Fig. 10d: the control polygon edited",
                    "The same design after moving the four edge end points outwards by 25 % in x "
                    "(Cubic_spline_2::with_control_point): still C2, the shapes are kept away from the joins.",
                    s, edited, d);
  }
  // Fig. 11: a semi-circle joined to a polynomial cubic, with coarse and dense marks.
  for (int dense = 0; dense < 2; ++dense) {
    std::vector<Shape> s;
    s.push_back(Shape::circle_arc(o, 1, pi, 2 * pi, even(pi, 2 * pi, dense ? 19 : 9)));
    const fair::Rational_bezier_2<Kernel> cubic({Point_2(1, 0), Point_2(1, 1.2), Point_2(-0.4, 1.6), Point_2(-1, 1.1)});
    s.push_back(Shape::cubic(cubic, dense ? std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9}
                                          : std::vector<double>{0.25, 0.5, 0.75}));
    s.push_back(Shape::segment(Point_2(-1, 1.1), Point_2(-1, 0), {0.25, 0.5, 0.75}));
    add_design(gallery, dense ? "Fig. 11d: denser marks" : "Fig. 11: semi-circle and polynomial cubic",
               dense ? "The same design with denser marks: more control points, hence more freedom to edit locally; "
                       "the curve is the same away from the joins."
                     : "The lower unit semi-circle, a polynomial cubic from its end and a segment back: all end "
                       "points agree, so the design closes without edges.",
               s, true);
  }
  // Fig. 12: a circle with one quarter replaced by a hyperbola, and by an ellipse.
  for (int ellipse = 0; ellipse < 2; ++ellipse) {
    const std::vector<Shape> s = fig12_shapes<Kernel>(ellipse);
    const fair::Basic_shape_design_options closed{true, 1e-9};
    const auto d = fair::basic_shape_design(s, closed);
    const auto exact = fair::basic_shape_design(fig12_shapes<EPECK>(ellipse), closed);
    add_design_case(gallery, ellipse ? "Fig. 12d: circle and ellipse" : "Fig. 12a: circle and hyperbola",
                    std::string("Three quarters of the unit circle (17 marks) and, for the fourth quarter, ") +
                        (ellipse ? "an elliptic arc (w = 1/2)" : "a hyperbolic arc (w = 1.6)") +
                        " with unequally spaced marks. Proposition 1, decided on the same design computed in EPECK: "
                        "the joint control polygon is convex, so the curve is locally convex.",
                    s, d.spline, d, &exact.spline);
  }
  // Fig. 14's profile: a quarter circle touching a line segment.
  {
    std::vector<Shape> s;
    s.push_back(Shape::segment(Point_2(-2, 0), Point_2(0, 0), {0.2, 0.4, 0.6, 0.8}));
    s.push_back(Shape::circle_arc(Point_2(0, 1), 1, -pi / 2, 0, even(-pi / 2, 0, 5)));
    add_design(gallery, "Fig. 14: quarter circle and line",
               "A line segment touching a quarter circle (curvature 0 to 1): the points agree up to rounding "
               "and are averaged. The curvature rises through the transition instead of jumping.",
               s);
  }
  // Figs. 5-7 and 1: an Archimedean spiral (Sec. 5: parametric_curve_spline through 13 marks)
  // joined to an involute, a circle, a line and a polynomial cubic.
  const double a = 0.05, b = 0.1, t0 = pi, t1 = 4 * pi, r1 = a + b * t1;  // the spiral ends at (r1, 0)
  const fair::Archimedean_spiral_2 spiral(a, b, t0, t1);
  std::vector<double> spiral_marks;
  for (int k = 0; k <= 12; ++k) spiral_marks.push_back(t0 + (t1 - t0) * k / 12);
  const Shape spiral_shape = Shape::parametric(spiral, spiral_marks, "spiral");
  {
    const double R = 0.12, u0 = 0.6, u1 = 3.0;
    const Point_2 start(r1 + 0.08, 0.15);  // the involute starts here: apart from the spiral's end
    const double cx = start.x() - R * (std::cos(u0) + u0 * std::sin(u0)), cy = start.y() - R * (std::sin(u0) - u0 * std::cos(u0));
    const fair::Circle_involute_2 involute(R, u0, u1, cx, cy);
    std::vector<double> m;
    for (int k = 0; k <= 8; ++k) m.push_back(u0 + (u1 - u0) * k / 8);
    add_design(gallery, "Fig. 5: spiral and circle involute",
               "An Archimedean spiral r = 0.05 + 0.1 theta (theta from pi to 4 pi, 13 marks) and the involute of a "
               "circle of radius 0.12 (9 marks), both by Sec. 5's spline of their 2-jets; their ends are apart, so "
               "an edge joins them.",
               {spiral_shape, Shape::parametric(involute, m, "involute")});
  }
  {
    const double c = 0.4, r = r1 - c + 2e-4;  // the circle starts 2e-4 from the spiral's end
    add_design(gallery, "Fig. 6: spiral and circle",
               "The spiral joined to a half circle whose start is 2e-4 from the spiral's end: with merge "
               "tolerance 1e-3 the two end points are averaged into one control point.",
               {spiral_shape, Shape::circle_arc(Point_2(c, 0), r, 0, pi, even(0, pi, 9))}, false, 1e-3);
  }
  add_design(gallery, "Fig. 7: spiral and line segment",
             "The spiral and a line segment starting near its end (an edge joins them); the segment is kept "
             "straight away from the join.",
             {spiral_shape, Shape::segment(Point_2(r1 + 0.1, 0.25), Point_2(r1 + 0.25, 2.0), {0.2, 0.4, 0.6, 0.8})});
  {
    const fair::Rational_bezier_2<Kernel> cubic(
        {Point_2(r1 + 0.1, 0.2), Point_2(r1 + 0.3, 1.2), Point_2(0.6, 2.1), Point_2(-0.6, 1.7)});
    add_design(gallery, "Fig. 1: spiral and polynomial cubic",
               "The unifying spline of Fig. 1: the spiral's spline and a polynomial cubic (5 marks) that the merged "
               "spline replicates exactly away from the join.",
               {spiral_shape, Shape::cubic(cubic, {1.0 / 6, 2.0 / 6, 3.0 / 6, 4.0 / 6, 5.0 / 6})});
  }
}
FAIR_CURVES_DEMO(64, add_basic_shape_cases)
