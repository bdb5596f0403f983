// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Gallery cases of the csr-spline (doc/csr_splines.md; Karciauskas & Peters Sec. 4): Fig. 2
// (semi-circle + almost flat parabola: the csr-spline against the classic constructions, with
// certified counts of curvature extrema in the transition), Fig. 4 (half circle + half ellipse,
// then moved samples), Fig. 15 (a minimal convex polygon), Fig. 17 (coarse and fine sampling).

#include "csr_figure.h"
#include "registry.h"
#include "tool_common.h"

#include <fair/Bezier_2.h>
#include <fair/Csr_spline_2.h>
#include <fair/Cubic_bspline_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Cubic_quasi_interpolant_2.h>
#include <fair/Fairness_metrics.h>
#include <fair/Four_point_subdivision_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace {

using fair_curves::Kernel;
using fair_curves::Point_2;
typedef fair::Bezier_2<Kernel> Piece;
typedef fair::Csr_spline_2<Kernel> Csr;

using fair_curves::pi;

// Fig. 2 data (as in test/csr and test/data/csr/fig2.csv): the right half of the unit circle from
// (0, -1) over (1, 0) to (0, 1), then y = 1 - 0.02 x^2 at x = -0.39 k, k = 1..8: the junction is
// sample 8, the transition the pieces 8..13 of a spline with one piece per interval.
std::vector<Point_2> fig2_data() {
  std::vector<Point_2> p;
  for (int k = 0; k <= 8; ++k) p.push_back(Point_2(std::cos(-pi / 2 + pi * k / 8), std::sin(-pi / 2 + pi * k / 8)));
  for (int k = 1; k <= 8; ++k) p.push_back(Point_2(-0.39 * k, 1 - 0.02 * 0.39 * 0.39 * k * k));
  return p;
}
constexpr std::size_t transition_first = 8, transition_last = 14;

fair::Csr_spline_options closed_csr() {
  fair::Csr_spline_options o;
  o.closed = true;
  return o;
}
fair::Cubic_interpolating_spline_options chordal_spline() {
  fair::Cubic_interpolating_spline_options o;
  o.knot_spacing = fair::Knot_spacing::CHORDAL;
  return o;
}
fair::Four_point_subdivision_options relaxed_four_point() {
  fair::Four_point_subdivision_options o;
  o.variant = fair::Four_point_variant::RELAXED;
  return o;
}

std::string count(std::size_t n) { return std::to_string(n); }

// The certified counts of a curve: curvature extrema in the Fig. 2 transition (pieces
// [transition_first, transition_last), when `transition`), in the whole curve, inflections.
void add_counts(const std::vector<Piece>& pieces, bool transition, fair_curves::Curve_case& c) {
  if (transition) {
    FAIR_ASSERT(pieces.size() >= transition_last);
    const std::vector<Piece> window(pieces.begin() + static_cast<std::ptrdiff_t>(transition_first),
                                    pieces.begin() + static_cast<std::ptrdiff_t>(transition_last));
    c.measurements.emplace_back("curvature extrema in the transition (certified)",
                                count(fair::curvature_extrema(window).count()));
  }
  c.measurements.emplace_back("curvature extrema, whole curve (certified)", count(fair::curvature_extrema(pieces).count()));
  c.measurements.emplace_back("inflections (certified)", count(fair::inflections(pieces).count()));
}

void add_baseline(fair_curves::Gallery& g, const std::vector<Piece>& pieces, const std::vector<Point_2>& data,
                  const std::string& title, const std::string& caption, bool transition = true) {
  fair_curves::Curve_case c;
  c.title = title;
  c.caption = caption;
  c.input_points = fair::io::to_xy(data);
  add_counts(pieces, transition, c);
  g.add_case(fair_curves::make_gallery_case(pieces, c));
}

// A csr-spline case: its figures with the B-spline control polygon, the distance to the samples
// and the certified counts (the transition window only when given).
void add_csr(fair_curves::Gallery& g, const Csr& csr, const std::string& title, const std::string& caption,
             bool transition, const std::vector<std::pair<std::string, std::string>>& extra = {}) {
  const std::vector<Piece> pieces = csr.pieces();
  fair_curves::Curve_case c;
  c.measurements = extra;
  add_counts(pieces, transition, c);
  c.measurements.emplace_back("max distance to the samples |s(t_i) - q_i|",
                              fair_curves::format_number(csr.max_distance_to_samples()));
  const fair_curves::Curve_figures f = fair_curves::csr_figures(csr, title, false);
  fair_curves::Gallery_case gc;
  gc.title = title;
  gc.caption = caption;
  gc.images = {{"curve", f.curve_svg}, {"curvature", f.curvature_svg}};
  gc.measurements = c.measurements;
  gc.measurements.emplace_back("arc length (adaptive Gauss-Kronrod)", fair_curves::format_number(f.sampled.length(), 12));
  g.add_case(gc);
}

void add_classic(fair_curves::Gallery& g, const std::vector<Point_2>& data, bool closed, const std::string& title,
                 const std::string& caption) {
  fair::Cubic_interpolating_spline_options o;  // natural when open, periodic when closed
  o.closed = closed;
  o.knot_spacing = fair::Knot_spacing::CHORDAL;
  const fair::Cubic_interpolating_spline_2<Kernel> s(data, o);
  fair_curves::Curve_case c;
  c.title = title;
  c.caption = caption;
  c.input_points = fair::io::to_xy(data);
  add_counts(s.pieces(), false, c);
  g.add_case(fair_curves::make_gallery_case(s.pieces(), c));
}

// Fig. 2 with the relaxed 4-point scheme: its limit is not piecewise polynomial, so its count is
// sampled: sign changes of the differences of the discrete curvature (turning angle over mean edge
// length) of the refined polygon in the transition, ignoring changes below 1e-6.
void add_four_point(fair_curves::Gallery& g, const std::vector<Point_2>& data) {
  const std::vector<Point_2> poly =
      fair::Four_point_subdivision_2<Kernel>(data, relaxed_four_point()).refine(5);
  std::vector<Piece> pieces;
  for (std::size_t i = 0; i + 1 < poly.size(); ++i) pieces.push_back(Piece(std::vector<Point_2>{poly[i], poly[i + 1]}));
  const std::size_t intervals = data.size() - 1;
  const std::size_t a = poly.size() * transition_first / intervals, b = poly.size() * transition_last / intervals;
  std::vector<double> kappa;
  for (std::size_t i = std::max<std::size_t>(a, 1); i < b && i + 1 < poly.size(); ++i) {
    const double ux = poly[i].x() - poly[i - 1].x(), uy = poly[i].y() - poly[i - 1].y();
    const double vx = poly[i + 1].x() - poly[i].x(), vy = poly[i + 1].y() - poly[i].y();
    const double turn = std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
    kappa.push_back(2 * turn / (std::hypot(ux, uy) + std::hypot(vx, vy)));
  }
  std::size_t extrema = 0;
  int last = 0;
  for (std::size_t i = 1; i < kappa.size(); ++i) {
    const double d = kappa[i] - kappa[i - 1];
    const int s = d > 1e-6 ? 1 : (d < -1e-6 ? -1 : 0);
    if (s != 0 && last != 0 && s != last) ++extrema;
    if (s != 0) last = s;
  }
  fair_curves::Curve_case c;
  c.title = "Fig. 2d: relaxed 4-point subdivision, 5 rounds";
  c.caption = "The relaxed C2 4-point scheme (gamma = -3/128; the paper uses the variant of Augsdorfer, Dodgson and "
              "Sabin) as a refined polygon. Not a piecewise polynomial: its count is sampled, not certified.";
  c.input_points = fair::io::to_xy(data);
  c.samples_per_piece = 1;
  c.comb = false;
  c.control_polygons = false;
  c.measurements.emplace_back("extrema of the discrete curvature in the transition (sampled)", count(extrema));
  g.add_case(fair_curves::make_gallery_case(pieces, c));
}

void add_fig2(fair_curves::Gallery& g) {
  const std::vector<Point_2> data = fig2_data();
  add_baseline(g,
               fair::Cubic_interpolating_spline_2<Kernel>(data, chordal_spline()).pieces(),
               data, "Fig. 2c: classic C2 cubic interpolation, chordal knots",
               "Interpolates, and oscillates after the junction: its curvature undershoots below 0 (inflections) and "
               "swings from piece to piece on the flat side. The transition is the six pieces after the junction.");
  add_four_point(g, data);
  add_baseline(g, fair::Cubic_quasi_interpolant_2<Kernel>(data).pieces(), data,
               "Fig. 2e: cubic (-1,8,-1)/6 quasi-interpolant",
               "What the csr-spline reduces to for beta = 1 without the curvature averaging.");
  add_baseline(g, fair::Cubic_bspline_2<Kernel>(data).pieces(), data,
               "Fig. 2f (red): C2 cubic B-spline with the data as control points",
               "Smooth but far from the data on the circle.");
  add_csr(g, Csr(data), "Fig. 2f: csr-spline, chordal knots",
          "Control points by eq. 6 (corrected), weighed by the curvatures of the local quadratics: the curvature "
          "falls from the circle's to the parabola's without oscillating, close to the samples.",
          true);
}

// Fig. 4: the upper unit half circle joined to the lower half of the ellipse x^2 + 4 y^2 = 1
// (closed, 16 samples); then three samples moved.
void add_fig4(fair_curves::Gallery& g) {
  std::vector<Point_2> data;
  for (int k = 0; k < 8; ++k) data.push_back(Point_2(std::cos(pi * k / 8), std::sin(pi * k / 8)));
  for (int k = 0; k < 8; ++k) data.push_back(Point_2(std::cos(pi + pi * k / 8), 0.5 * std::sin(pi + pi * k / 8)));
  std::vector<Point_2> moved = data;
  moved[3] = Point_2(1.08 * data[3].x(), 1.08 * data[3].y());
  moved[9] = Point_2(data[9].x(), data[9].y() - 0.06);
  moved[12] = Point_2(0.9 * data[12].x(), 0.8 * data[12].y());
  add_classic(g, data, true, "Fig. 4a: half circle + half ellipse, classic periodic C2 interpolation",
              "The classic spline copes well with the input.");
  add_classic(g, moved, true, "Fig. 4b: the same with three samples moved, classic",
              "Moving samples 3, 9 and 12 makes the classic spline oscillate: inflections appear.");
  add_csr(g, Csr(data, closed_csr()), "Fig. 4c: half circle + half ellipse, closed csr-spline",
          "The csr-spline of the same samples.", false);
  add_csr(g, Csr(moved, closed_csr()), "Fig. 4d: the same with three samples moved, csr",
          "The csr-spline keeps its quality under the modification: fewer inflections than the classic spline.", false);
}

// Fig. 15: a minimal convex polygon -- interpolation, convexity and smoothness are incompatible.
void add_fig15(fair_curves::Gallery& g) {
  const std::vector<Point_2> data = {Point_2(0, 0), Point_2(0, 1), Point_2(1, 1.2), Point_2(3, 1.2), Point_2(4, 0)};
  add_classic(g, data, false, "Fig. 15: minimal convex polygon, classic C2 interpolation",
              "Interpolating the five points of a convex polygon forces inflections.");
  add_csr(g, Csr(data), "Fig. 15: minimal convex polygon, csr-spline",
          "The csr-spline relaxes interpolation and stays convex (no inflection).", false);
  add_baseline(g, fair::Cubic_bspline_2<Kernel>(data).pieces(), data,
               "Fig. 15: minimal convex polygon, the data as B-spline control points", "Far from the data.", false);
}

// Fig. 17: three quarters of the unit circle sampled coarsely (5 samples) and finely (25).
void add_fig17(fair_curves::Gallery& g) {
  for (int n : {4, 24}) {
    std::vector<Point_2> data;
    for (int k = 0; k <= n; ++k) data.push_back(Point_2(std::cos(1.5 * pi * k / n), std::sin(1.5 * pi * k / n)));
    const Csr csr(data);
    const double d = fair::max_circle_deviation(csr.pieces(), Point_2(0, 0), 1.0).max_deviation;
    add_csr(g, csr, "Fig. 17" + std::string(n == 4 ? "a: coarse" : "b: fine") + " sampling of a 270 degree arc, " +
                        std::to_string(n + 1) + " samples",
            n == 4 ? "Too coarse: the csr-spline does not reproduce the arc well."
                   : "Finer sampling: the arc is reproduced closely (the error is O(h^3)).",
            false, {{"max deviation from the circle (certified candidates)", fair_curves::format_number(d)}});
  }
}

void add_csr_cases(fair_curves::Gallery& gallery) {
  gallery.add_section(
      "csr-splines (Karciauskas-Peters, Sec. 4)",
      "The curvature-sensitive relaxed cubic C2 spline: each B-spline control point averages the blossoms of the "
      "three local quadratic interpolants, weighed by their curvatures (eq. 6 with the corrected coefficients, "
      "doc/csr_splines.md). Local, O(n), no solve; it approximates the samples and reports how closely.");
  add_fig2(gallery);
  add_fig4(gallery);
  add_fig15(gallery);
  add_fig17(gallery);
}

} // namespace

FAIR_CURVES_DEMO(58, add_csr_cases)
