// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Demo cases of conic pieces (fair::Rational_quadratic_bezier_2): the three conic types on one
// control triangle, with their certified curvature extrema marked, a circular arc (constant
// curvature, no extrema) and the weight of least eccentricity (eq. 15 of Yan, Schiller,
// Schaefer).

#include "conic_report.h"
#include "registry.h"

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using fair_curves::Conic_piece;
using fair_curves::Point_2;

template <class K>
void add_conic_case(fair_curves::Gallery& gallery, const fair::Rational_quadratic_bezier_2<K>& piece,
                    const std::string& title, const std::string& caption) {
  const fair_curves::Conic_report report = fair_curves::conic_report(piece);
  fair_curves::Curve_case c;
  c.title = title;
  c.caption = caption;
  c.marks = fair_curves::conic_marks(report);
  c.measurements = fair_curves::conic_measurements(report);
  c.samples_per_piece = 160;
  const std::vector<fair::Rational_quadratic_bezier_2<K>> curve = {piece};
  gallery.add_case(fair_curves::make_gallery_case(curve, c));
}

} // namespace

void add_conics_cases(fair_curves::Gallery& gallery) {
  gallery.add_section(
      "Conic pieces (rational quadratic Bezier)",
      "c(t) = ((1-t)^2 P0 + 2(1-t)t w P1 + t^2 P2) / ((1-t)^2 + 2(1-t)t w + t^2). The weight w decides the "
      "conic type exactly: w < 1 ellipse, w = 1 parabola, w > 1 hyperbola. The red rings are the critical "
      "points of curvature in (0,1): the roots of the eq.-4 polynomial of Yan, Schiller and Schaefer, isolated "
      "with certified intervals on the exact values of the inputs.");
  // One asymmetric control triangle, three weights: the extremum moves along the arc.
  const Point_2 p0(4, 0), p1(1, 2), p2(0, 0);
  add_conic_case(gallery, Conic_piece(p0, p1, p2, 0.5), "Ellipse, w = 1/2",
                 "An elliptic arc (w < 1) on the control triangle (4,0), (1,2), (0,0); it turns left, so its curvature is positive.");
  add_conic_case(gallery, Conic_piece(p0, p1, p2, 1.0), "Parabola, w = 1",
                 "The same control triangle with w = 1: a parabolic arc (a polynomial quadratic), whose single "
                 "curvature maximum is its vertex.");
  add_conic_case(gallery, Conic_piece(p0, p1, p2, 2.0), "Hyperbola, w = 2",
                 "The same control triangle with w > 1: a hyperbolic arc, pulled towards P1.");
  // An ellipse arc long enough to contain both a maximum and a minimum of curvature.
  add_conic_case(gallery, Conic_piece(Point_2(3, 0), Point_2(0, 3), Point_2(0, 0), 0.3),
                 "Ellipse, w = 0.3, two extrema",
                 "A long elliptic arc passing over the end of a major and of a minor axis: a curvature maximum "
                 "and a minimum inside the piece (at most two for an ellipse, Sec. 3.1).");
  // A circular arc. In double it cannot be exact (w = cos(theta/2) and the control points are
  // never all representable), and the rounding leaves real but tiny curvature extrema. In exact
  // rational arithmetic: cos(theta/2) = 3/5, tan(theta/2) = 4/3 (the 3-4-5 triangle).
  typedef CGAL::Simple_cartesian<CGAL::Gmpq> Exact;
  typedef Exact::FT Q;
  add_conic_case(gallery,
                 fair::Rational_quadratic_bezier_2<Exact>(Exact::Point_2(1, 0), Exact::Point_2(Q(1), Q(4, 3)),
                                                          Exact::Point_2(Q(-7, 25), Q(24, 25)), Q(3, 5)),
                 "Circular arc, exact rational data",
                 "A circular arc of the unit circle, in Simple_cartesian<Gmpq>: P0 = (1,0), P1 = (1,4/3), "
                 "P2 = (-7/25,24/25), w = 3/5 = cos(theta/2). The eq.-4 polynomial vanishes identically "
                 "(decided exactly): constant curvature 1, eccentricity 0, no curvature extrema.");
  // Eq. 15: the weight of least eccentricity for the first control triangle.
  const double w_hat = std::sqrt(CGAL::to_double(Conic_piece::minimum_eccentricity_weight_squared(p0, p1, p2)));
  add_conic_case(gallery, Conic_piece(p0, p1, p2, w_hat), "Least eccentric conic (eq. 15)",
                 "On the first control triangle, the weight w = |P2-P0| / sqrt(2 (|P0-P1|^2 + |P2-P1|^2)) of eq. 15 "
                 "gives the ellipse of least eccentricity through P0 and P2 tangent to P0P1 and P1P2.");
}
FAIR_CURVES_DEMO(10, add_conics_cases)
