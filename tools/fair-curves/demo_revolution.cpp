// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Demo cases of the surface-of-revolution renderer (doc/surfaces_of_revolution.md): the
// situation of Fig. 14 of Karciauskas & Peters, a line segment joined tangentially to a quarter
// circle, rotated about the axis through the circle's centre. The curvature jumps from 0 to 1 at
// the join and the reflection lines kink there; a C2 spline through samples of the same curve
// has continuous curvature and smooth stripes.

#include "registry.h"
#include "tool_common.h"

#include <fair/Basic_shape_design.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Rational_bezier_2.h>
#include <fair/io/surface_of_revolution.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using fair_curves::Kernel;
using fair_curves::Point_2;
typedef fair::Rational_bezier_2<Kernel> Rational_piece;

// The line from (1,-1) up to (1,0) (a quadratic with collinear control points, so that both
// pieces are of one type) and the quarter circle about the origin from (1,0) to (0,1), in the
// standard rational form (weights 1, sqrt(2)/2, 1).
std::vector<Rational_piece> line_and_quarter_circle() {
  const double w = std::sqrt(0.5);
  return {Rational_piece({Point_2(1, -1), Point_2(1, -0.5), Point_2(1, 0)}, {1.0, 1.0, 1.0}),
          Rational_piece({Point_2(1, 0), Point_2(1, 1), Point_2(0, 1)}, {1.0, w, 1.0})};
}

// Samples of the same curve: 4 on the line (spacing 1/4), 7 on the arc (every 15 degrees), the
// join (1,0) being sample 4, hence the start of piece 4 of a spline through them.
std::vector<Point_2> samples() {
  std::vector<Point_2> p;
  for (int k = 0; k < 4; ++k) p.push_back(Point_2(1, -1 + 0.25 * k));
  const double half_pi = 2 * std::atan(1.0);
  for (int k = 0; k <= 6; ++k) p.push_back(Point_2(std::cos(half_pi * k / 6), std::sin(half_pi * k / 6)));
  return p;
}

fair::io::Surface_of_revolution_options view() {
  fair::io::Surface_of_revolution_options o;
  o.width = o.height = 360;
  return o;
}

template <class Pieces>
void add_revolution_case(fair_curves::Gallery& gallery, const Pieces& pieces, std::size_t join_piece,
                         const std::vector<Point_2>& data, const std::string& title, const std::string& caption) {
  fair_curves::Curve_case c;
  c.title = title;
  c.caption = caption;
  for (const Point_2& p : data) c.input_points.push_back(fair::io::Xy{p.x(), p.y()});
  const double left = pieces[join_piece - 1].curvature(1.0), right = pieces[join_piece].curvature(0.0);
  c.measurements.emplace_back("curvature just before / after the join (1,0)",
                              fair_curves::format_number(left) + " / " + fair_curves::format_number(right));
  fair_curves::Gallery_case g = fair_curves::make_gallery_case(pieces, c);
  const fair::io::Surface_of_revolution_options o = view();
  const fair::io::Surface_of_revolution_render r = fair::io::render_surface_of_revolution(pieces, o);
  g.images.emplace_back("surface of revolution with reflection lines", fair::io::png_svg(r.image, title));
  const fair::io::Stripe_kink k = fair::io::stripe_kink(r, static_cast<double>(join_piece), o.stripes);
  g.measurements.emplace_back("stripe kink at the join: max |second difference| of the stripe function (periods/px^2, " +
                                  std::to_string(k.columns) + " columns)",
                              fair_curves::format_number(k.kink, 3));
  gallery.add_case(std::move(g));
}

} // namespace

void add_revolution_cases(fair_curves::Gallery& gallery) {
  gallery.add_section(
      "Surfaces of revolution: reflection lines",
      "The test by which Karciauskas and Peters judge a profile (Fig. 14): rotate it about an axis and look at the "
      "reflection lines of parallel light tubes on the surface. The stripes follow the surface normal, which the "
      "renderer computes per pixel from the profile's exact derivative: where the profile is only tangent "
      "continuous and its curvature jumps, the stripes kink; where the curvature is continuous they bend smoothly. "
      "Rendered in software (doc/surfaces_of_revolution.md), axis x = 0, viewer 20 degrees above the equator.");
  const std::vector<Rational_piece> g1 = line_and_quarter_circle();
  add_revolution_case(gallery, g1, 1, {}, "Line segment + quarter circle, joined G1 (Fig. 14a, d)",
                      "Two rational pieces made by hand: the segment from (1,-1) to (1,0) and the quarter circle to "
                      "(0,1). Tangent continuous, the curvature jumps from 0 to 1 at (1,0): the reflection lines kink "
                      "along the circle where the cylinder meets the hemisphere.");
  const std::vector<Point_2> data = samples();
  fair::Cubic_interpolating_spline_options chordal;  // natural ends
  chordal.knot_spacing = fair::Knot_spacing::CHORDAL;
  const fair::Cubic_interpolating_spline_2<Kernel> c2(data, chordal);
  add_revolution_case(gallery, c2.pieces(), 4, data, "Classic C2 interpolant through samples of it",
                      "The natural C2 cubic spline with chordal knots through 11 samples of the same curve (the join "
                      "is a sample). Curvature continuous: the stripes bend without kinks at the join, at the price "
                      "of the spline's small overshoot on the cylinder (the waves in the stripes there).");
  // Fig. 14b, e: the same two basic shapes, marked and converted exactly (Sec. 6), merged into
  // one C2 spline (doc/basic_shapes.md); each shape is kept exactly away from the transition.
  typedef fair::Basic_shape_2<Kernel> Shape;
  const double half_pi = 2 * std::atan(1.0);
  std::vector<double> angles;
  for (int k = 1; k < 6; ++k) angles.push_back(half_pi * k / 6);
  const std::vector<Shape> shapes{Shape::segment(Point_2(1, -1), Point_2(1, 0), {0.25, 0.5, 0.75}),
                                  Shape::circle_arc(Point_2(0, 0), 1, 0, half_pi, angles)};
  const fair::Basic_shape_design_2<Kernel> design = fair::basic_shape_design(shapes);
  const std::size_t join = design.spans.at(1).first_piece;
  add_revolution_case(gallery, design.spline.pieces(), join, {},
                      "The C2 spline of Sec. 6 from the marked line and quarter circle (Fig. 14b, e)",
                      "The segment (3 marks) and the quarter circle (5 marks, every 15 degrees) converted exactly "
                      "and merged with the join point shared (basic_shape_design): the curvature rises from 0 to 1 "
                      "over the transition pieces, positive throughout, and the stripes pass the join without a "
                      "kink, as in the paper's Fig. 14e.");
}

FAIR_CURVES_DEMO(70, add_revolution_cases)
