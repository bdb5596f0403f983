// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Demo cases of the classic baselines (doc/classic_interpolants.md) on the data of Fig. 2 of
// Karciauskas & Peters: a semicircle joined to an almost flat parabola, sampled uniformly, where
// the abrupt change of curvature makes the classic constructions oscillate.

#include "registry.h"
#include "tool_common.h"

#include <fair/Bezier_2.h>
#include <fair/Catmull_rom_2.h>
#include <fair/Cubic_bspline_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Cubic_quasi_interpolant_2.h>
#include <fair/Fairness_metrics.h>
#include <fair/Four_point_subdivision_2.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using fair_curves::Kernel;
using fair_curves::Point_2;
typedef fair::Bezier_2<Kernel> Piece;

// The upper unit semicircle from (-1,0) over (0,1) to (1,0), 9 samples, continued by the flat
// parabola x = 1 - y^2/20 turning the same way (tangent continuous at (1,0), curvature 1/10
// there instead of 1),
// sampled with about the same spacing.
std::vector<Point_2> semicircle_and_parabola() {
  std::vector<Point_2> p;
  const double pi = std::acos(-1.0);
  for (int k = 0; k <= 8; ++k) {
    const double a = pi - k * pi / 8;
    p.push_back(Point_2(std::cos(a), std::sin(a)));
  }
  for (int k = 1; k <= 6; ++k) {
    const double y = -0.39 * k;
    p.push_back(Point_2(1 - y * y / 20, y));
  }
  return p;
}

std::vector<fair::io::Xy> as_xy(const std::vector<Point_2>& p) {
  std::vector<fair::io::Xy> out;
  for (const Point_2& q : p) out.push_back(fair::io::Xy{q.x(), q.y()});
  return out;
}

// The library's certified inflections (curvature sign changes, also at joins) and its curvature
// range (profile samples and certified extrema), fair/Fairness_metrics.h.
void curvature_figures(const std::vector<Piece>& pieces, fair_curves::Curve_case& c) {
  const fair::Fairness_report r = fair::fairness_report(pieces);
  c.measurements.emplace_back("pieces", std::to_string(pieces.size()));
  c.measurements.emplace_back(std::string("inflections") + (r.certified ? " (certified)" : " (sampled)"),
                              std::to_string(r.inflection_count));
  c.measurements.emplace_back("max |curvature|", fair_curves::format_number(std::max(-r.min_curvature, r.max_curvature)));
}

// Largest distance from a data point to the curve point at its knot (approximating methods).
double knot_deviation(const std::vector<Piece>& pieces, const std::vector<Point_2>& data) {
  double worst = 0;
  for (std::size_t i = 0; i < data.size(); ++i) {
    const Point_2 q = (i < pieces.size()) ? pieces[i].point(0.0) : pieces.back().point(1.0);
    worst = std::max(worst, std::sqrt(CGAL::squared_distance(q, data[i])));
  }
  return worst;
}

void add_piece_case(fair_curves::Gallery& gallery, const std::vector<Piece>& pieces, const std::vector<Point_2>& data,
                    const std::string& title, const std::string& caption, bool approximating) {
  fair_curves::Curve_case c;
  c.title = title;
  c.caption = caption;
  c.input_points = as_xy(data);
  curvature_figures(pieces, c);
  if (approximating)
    c.measurements.emplace_back("max distance data point - curve at its knot",
                                fair_curves::format_number(knot_deviation(pieces, data)));
  gallery.add_case(fair_curves::make_gallery_case(pieces, c));
}

// A refined polyline as degree-1 pieces (curvature 0 on each; drawn without control polygons).
void add_polyline_case(fair_curves::Gallery& gallery, const std::vector<Point_2>& polyline,
                       const std::vector<Point_2>& data, const std::string& title, const std::string& caption) {
  std::vector<Piece> pieces;
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i)
    pieces.push_back(Piece(std::vector<Point_2>{polyline[i], polyline[i + 1]}));
  fair_curves::Curve_case c;
  c.title = title;
  c.caption = caption;
  c.input_points = as_xy(data);
  c.samples_per_piece = 1;
  c.comb = false;
  c.control_polygons = false;
  c.measurements.emplace_back("points after 5 rounds", std::to_string(polyline.size()));
  gallery.add_case(fair_curves::make_gallery_case(pieces, c));
}

} // namespace

void add_classic_cases(fair_curves::Gallery& gallery) {
  gallery.add_section(
      "Classic baselines",
      "The classic constructions the fair methods are compared with, on the data of Fig. 2 of Karciauskas and "
      "Peters: a semicircle (curvature 1) joined to an almost flat parabola (curvature 1/10), sampled uniformly. "
      "Where the curvature of the data changes abruptly, these constructions overshoot and their curvature "
      "oscillates. See doc/classic_interpolants.md for continuity, reproduction and exactness of each.");
  const std::vector<Point_2> data = semicircle_and_parabola();
  fair::Cubic_interpolating_spline_options chordal;
  chordal.knot_spacing = fair::Knot_spacing::CHORDAL;
  fair::Catmull_rom_options centripetal;
  centripetal.knot_spacing = fair::Knot_spacing::CENTRIPETAL;
  fair::Four_point_subdivision_options relaxed;
  relaxed.variant = fair::Four_point_variant::RELAXED;

  add_piece_case(gallery, fair::Cubic_interpolating_spline_2<Kernel>(data).pieces(), data,
                 "C2 cubic interpolating spline, natural, uniform knots",
                 "The classic C2 cubic spline (Fig. 2c of Karciauskas and Peters): interpolating, C2, solved in O(n) "
                 "by the Thomas algorithm; zero curvature at both ends (natural end conditions).",
                 false);
  add_piece_case(gallery,
                 fair::Cubic_interpolating_spline_2<Kernel>(data, chordal).pieces(),
                 data, "C2 cubic interpolating spline, natural, chordal knots",
                 "The same spline with knot intervals equal to the chord lengths.", false);
  add_piece_case(gallery, fair::Catmull_rom_2<Kernel>(data, centripetal).pieces(), data,
                 "Catmull-Rom spline, centripetal knots",
                 "Local C1 interpolation: the tangent at each point is that of the parabola through it and its two "
                 "neighbours. Curvature jumps at every data point.",
                 false);
  add_piece_case(gallery, fair::Cubic_quasi_interpolant_2<Kernel>(data).pieces(), data,
                 "Cubic (-1,8,-1)/6 quasi-interpolant",
                 "The uniform C2 cubic B-spline with control points (-p[i-1] + 8 p[i] - p[i+1])/6 (Fig. 2e of "
                 "Karciauskas and Peters). It reproduces cubics but does not interpolate: at the knot of p[i] it "
                 "misses the data by a 36th of the fourth difference.",
                 true);
  add_piece_case(gallery, fair::Cubic_bspline_2<Kernel>(data).pieces(), data,
                 "C2 cubic B-spline with the data as control points",
                 "The red curve of Fig. 2f of Karciauskas and Peters: smooth but far from the data where the "
                 "polygon turns sharply.",
                 true);
  add_polyline_case(gallery, fair::Four_point_subdivision_2<Kernel>(data).refine(5), data,
                    "4-point subdivision (Dyn, Levin, Gregory), w = 1/16, 5 rounds",
                    "The interpolatory 4-point scheme: C1 limit, reproduces cubics.");
  add_polyline_case(gallery,
                    fair::Four_point_subdivision_2<Kernel>(data, relaxed).refine(5),
                    data, "Relaxed 4-point subdivision, gamma = -3/128, 5 rounds",
                    "Old points move by gamma times their fourth difference: C2 limit, reproduces cubics, does not "
                    "interpolate (compare Fig. 2d of Karciauskas and Peters, which uses the relaxed scheme of "
                    "Augsdorfer, Dodgson and Sabin).");
}
FAIR_CURVES_DEMO(80, add_classic_cases)
