// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Demo cases of the exact conversion (doc/exact_conversion.md, Karciauskas & Peters Sec. 6, 7):
// the exact circle arc w = 3/5 as a rational C2 spline, a conic and a 200-degree circle arc with
// uneven marks, and the quadratic design of Figs. 16/19 from 8 sparse points, each with its
// Proposition-1 report. The exact work runs in Simple_cartesian<Gmpq>; the drawing in double.

#include "registry.h"
#include "tool_common.h"

#include <fair/Exact_spline_conversion.h>
#include <fair/Quadratic_design.h>
#include <fair/Spline_convexity.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using fair_curves::Kernel;
using fair_curves::Point_2;
typedef CGAL::Simple_cartesian<CGAL::Gmpq> Exact;
typedef Exact::FT Q;
typedef Exact::Point_2 Exact_point;

template <class K>
void add_convexity(const fair::Cubic_spline_2<K>& s, fair_curves::Curve_case& c) {
  const fair::Spline_convexity_report<K> r = fair::spline_convexity(s);
  c.measurements.emplace_back("control polygon convex (exact predicates)",
                              r.polygon_convex ? "yes" : "no, at control point " + std::to_string(r.polygon_violation));
  c.measurements.emplace_back("curve locally convex (certified)", r.curve_locally_convex ? "yes" : "no");
  c.measurements.emplace_back("pieces certified by the interval filter / exactly",
                              std::to_string(r.pieces_by_filter) + " / " + std::to_string(r.pieces_exact));
}

void add_spline_case(fair_curves::Gallery& gallery, const fair::Cubic_spline_2<Kernel>& s, fair_curves::Curve_case c) {
  for (const Point_2& p : s.control_points()) c.input_points.push_back(fair::io::Xy{p.x(), p.y()});
  c.measurements.emplace_back("pieces / control points",
                              std::to_string(s.number_of_pieces()) + " / " + std::to_string(s.number_of_control_points()));
  gallery.add_case(fair_curves::make_gallery_case(s.pieces(), c));
}

void exact_circle(fair_curves::Gallery& gallery) {
  const fair::Rational_quadratic_bezier_2<Exact> arc(Exact_point(1, 0), Exact_point(Q(1), Q(4) / 3),
                                                     Exact_point(Q(-7) / 25, Q(24) / 25), Q(3) / 5);
  const std::vector<Q> u{Q(1) / 7, Q(1) / 3, Q(1) / 2, Q(4) / 5};
  const fair::Cubic_spline_2<Exact> s = fair::exact_spline(arc, u);
  int on_circle = 0, equal = 0;
  for (int k = 0; k <= 100; ++k) {
    const Exact_point p = s.point(Q(k) / 100);
    on_circle += (p.x() * p.x() + p.y() * p.y() == Q(1));
    equal += (p == arc.point(Q(k) / 100));
  }
  fair_curves::Curve_case c;
  c.title = "Exact circle arc (w = 3/5) as a rational C2 cubic spline";
  c.caption = "The conic P0 = (1,0), P1 = (1,4/3), P2 = (-7/25,24/25), w = 3/5 (a unit-circle arc of 106.26 degrees) "
              "with marks 1/7, 1/3, 1/2, 4/5, converted by eq. 9 (the blossom of the degree-elevated homogeneous cubic) "
              "and the corrected eq. 10, in Simple_cartesian<Gmpq>. The dots are the B-spline control points. The "
              "curvature is 1 everywhere: the spline is the arc, not an approximation.";
  c.measurements.emplace_back("rational parameters k/100 with x^2 + y^2 = 1 exactly", std::to_string(on_circle) + " of 101");
  c.measurements.emplace_back("rational parameters where spline = conic exactly", std::to_string(equal) + " of 101");
  add_convexity(s, c);
  add_spline_case(gallery, fair_curves::to_double_spline(s), c);
}

void conic_and_wide_arc(fair_curves::Gallery& gallery) {
  {
    // a hyperbola arc (w = 2) with marks crowded towards its end
    const fair::Rational_quadratic_bezier_2<Exact> h(Exact_point(0, 0), Exact_point(2, 3), Exact_point(4, 0), Q(2));
    std::vector<Q> u;
    for (int k = 1; k <= 7; ++k) u.push_back(Q(1) - Q(1) / Q(k + 1) / Q(k + 1) - Q(1) / 100);
    std::sort(u.begin(), u.end());
    const fair::Cubic_spline_2<Exact> s = fair::exact_spline(h, u);
    fair_curves::Curve_case c;
    c.title = "Hyperbola arc (w = 2) with uneven marks";
    c.caption = "A rational quadratic with weight 2 (a hyperbola arc) marked more densely towards its end: the "
                "breakpoints follow the marks, the control polygon refines there, the curve stays exactly the conic.";
    add_convexity(s, c);
    add_spline_case(gallery, fair_curves::to_double_spline(s), c);
  }
  {
    const double deg = std::acos(-1.0) / 180;
    const fair::Rational_bezier_2<Kernel> a = fair::circle_arc_cubic<Kernel>(Point_2(0, 0), 1.0, -10 * deg, 190 * deg);
    const fair::Cubic_spline_2<Kernel> s = fair::exact_spline(a, {0.1, 0.25, 0.5, 0.75, 0.9});
    double worst = 0;
    for (int k = 0; k <= 200; ++k) {
      const Point_2 p = s.point(k / 200.0);
      worst = std::max(worst, std::fabs(std::hypot(p.x(), p.y()) - 1));
    }
    fair_curves::Curve_case c;
    c.title = "A 200-degree circle arc: beyond the quadratic, still one rational cubic";
    c.caption = "circle_arc_cubic builds the cubic from the homogeneous quadratic, so a 200-degree arc (w = cos 100 deg "
                "< 0, no standard quadratic) has positive cubic weights (1 + 2w)/3 = 0.22; its inner Bezier points lie "
                "3 radii out along the end tangents, which is why circle_arc_split cuts arcs of more than 180 degrees "
                "(here into two 100-degree arcs). Marked at 0.1, 0.25, 0.5, 0.75, 0.9.";
    c.measurements.emplace_back("max | |p| - 1 | over 201 parameters (double)", fair_curves::format_number(worst));
    add_convexity(s, c);
    add_spline_case(gallery, s, c);
  }
}

void quadratic_design(fair_curves::Gallery& gallery) {
  const std::vector<Exact_point> q{Exact_point(0, 0), Exact_point(1, 2),  Exact_point(3, 3),  Exact_point(5, 2),
                                   Exact_point(6, 0), Exact_point(8, -1), Exact_point(10, 0), Exact_point(11, 2)};
  fair::Quadratic_design_options o;
  o.spacing = fair::Knot_spacing::UNIFORM;
  const std::vector<fair::Bezier_2<Exact>> shapes = fair::quadratic_design_shapes<Exact>(q, false, o);
  const fair::Cubic_spline_2<Exact> s = fair::quadratic_design_spline<Exact>(q, false, o);
  fair_curves::Curve_case c;
  c.title = "Quadratic design from 8 sparse points (eq. 12, Figs. 16 and 19)";
  c.caption = "Each data segment gets the quadratic {q_i, m_i, q_{i+1}}, m_i the curvature-weighted average (eq. 6 "
              "weights) of the middle coefficients of the two local interpolating quadratics (one-sided at the "
              "ends). The chain is converted with rounding marks {1/8, 1/4, 3/4, 7/8}: every quadratic is retained "
              "exactly on [1/4, 3/4] and the joins are rounded C2. Dots: the spline's control points (which include "
              "the data points).";
  c.measurements.emplace_back("quadratic shapes", std::to_string(shapes.size()));
  add_convexity(s, c);
  add_spline_case(gallery, fair_curves::to_double_spline(s), c);
}

} // namespace

void add_exact_conversion_cases(fair_curves::Gallery& gallery) {
  gallery.add_section(
      "Exact conversion and design with basic shapes",
      "Karciauskas and Peters, Sec. 6 and 7: rational curves of degree at most 3 (conics, circle arcs, rational "
      "cubics) converted exactly into the C2 cubic spline by marking points on them, the convexity certificate of "
      "Proposition 1, and quadratic shapes designed from sparse data. See doc/exact_conversion.md.");
  exact_circle(gallery);
  conic_and_wide_arc(gallery);
  quadratic_design(gallery);
}

FAIR_CURVES_DEMO(62, add_exact_conversion_cases)
