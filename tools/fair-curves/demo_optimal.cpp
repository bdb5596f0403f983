// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Gallery of Gumhold's optimal curves (issue 11 section 6; doc/optimal_curves.md): the figures of
// the paper recomputed with fair::Optimal_curve_2, each drawn as the C2 cubic spline through the
// optimal polygon (fair::fit_smoothing_spline_runs: C2, G0 at corners) with its curvature plot and the measured figures of
// the solve (status, levels, vertices, iterations, energy, distance of the spline to the polygon).
// Fig. 3 is computed from the closed form of eq. 7 (true-curvature convention, kappa = f(phi)/s).

#include "registry.h"
#include "tool_common.h"

#include <fair/Bezier_2.h>
#include <fair/Optimal_curve_2.h>
#include <fair/Polygon_spline_fit.h>
#include <fair/io/svg.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace {

using fair_curves::Kernel;
using fair_curves::Point_2;
typedef fair::Bezier_2<Kernel> Segment;

// Five points of an arch and the heart of Fig. 1 (the same data as test/data/optimal).
std::vector<Point_2> arch() { return {Point_2(0, 0), Point_2(1, 1), Point_2(2, 3), Point_2(3, 1), Point_2(4, 0)}; }
std::vector<Point_2> heart() {
  return {Point_2(0, -2), Point_2(1.5, 0.5), Point_2(1, 1.5), Point_2(0, 1), Point_2(-1, 1.5), Point_2(-1.5, 0.5)};
}

fair::Point_constraint constraint(std::size_t i, fair::Point_constraint_kind kind, double x, double y, double ox = 1,
                                  double oy = 0) {
  fair::Point_constraint c;
  c.index = i;
  c.kind = kind;
  c.direction = {{x, y}};
  c.outgoing = {{ox, oy}};
  return c;
}

// The measured figures of a solve.
void solve_figures(const fair::Optimal_curve_2<Kernel>& curve, double fit_distance, fair_curves::Curve_case& c,
                   const std::string& prefix = std::string()) {
  const fair::Optimal_curve_report& r = curve.report();
  std::ostringstream levels;
  for (std::size_t i = 0; i < r.levels.size(); ++i)
    levels << (i ? ", " : "") << r.levels[i].vertices << ":" << r.levels[i].iterations;
  c.measurements.emplace_back(prefix + "status", fair::to_string(r.status));
  c.measurements.emplace_back(prefix + "levels (vertices:Newton steps)", levels.str());
  c.measurements.emplace_back(prefix + "energy", fair_curves::format_number(r.energy, 10));
  c.measurements.emplace_back(prefix + "spline - polygon max distance", fair_curves::format_number(fit_distance, 3));
}

// One solve as a gallery case (the fitted spline, the input points, the measured figures).
void add_solve(fair_curves::Gallery& gallery, const std::vector<Point_2>& points, const fair::Optimal_curve_options& o,
               const std::string& title, const std::string& caption, bool show_vertices = false) {
  const fair::Optimal_curve_2<Kernel> curve(points, o);
  fair_curves::Curve_case c;
  c.title = title;
  c.caption = caption;
  c.input_points = fair::io::to_xy(show_vertices ? curve.polygon() : points);
  c.control_polygons = false;
  c.samples_per_piece = 8;
  solve_figures(curve, curve.spline().max_distance, c);
  c.measurements.emplace_back("vertices of the optimal polygon", std::to_string(curve.polygon().size()));
  gallery.add_case(fair_curves::make_gallery_case(curve.pieces(), c));
}

// A family of solves drawn together (their splines one after the other in the curvature plot).
void add_family(fair_curves::Gallery& gallery, const std::vector<Point_2>& points,
                const std::vector<std::pair<std::string, fair::Optimal_curve_options>>& family, const std::string& title,
                const std::string& caption) {
  std::vector<fair::Bezier_2<Kernel>> pieces;
  fair_curves::Curve_case c;
  c.title = title;
  c.caption = caption;
  c.input_points = fair::io::to_xy(points);
  c.control_polygons = false;
  c.comb = false;
  c.samples_per_piece = 8;
  for (const auto& member : family) {
    const fair::Optimal_curve_2<Kernel> curve(points, member.second);
    pieces.insert(pieces.end(), curve.pieces().begin(), curve.pieces().end());
    const fair::Optimal_curve_report& r = curve.report();
    c.measurements.emplace_back(member.first, std::string(fair::to_string(r.status)) + ", " +
                                                  std::to_string(curve.polygon().size()) + " vertices, energy " +
                                                  fair_curves::format_number(r.energy, 6));
  }
  gallery.add_case(fair_curves::make_gallery_case(pieces, c));
}

// Fig. 3: d kappa / dx at x = 0 of eq. 7 with l = s = 1 for kappa = f(phi)/s (true curvature):
// d/dx = f(phi) sin(phi/2) - 2 f'(phi) cos(phi/2) (eq. 8 times 2), by central differences of eq. 7.
double gradient_of_eq7(double (*f)(double), double phi) {
  const double gamma = 0.5 * (std::acos(-1.0) - phi), h = 1e-6;
  auto kappa = [&](double x) {
    const double c = std::cos(gamma) - x, s = std::sin(gamma);
    const double turn = std::acos(-1.0) - 2 * std::atan2(s, c);
    return f(turn) / std::sqrt(s * s + c * c);
  };
  return (kappa(h) - kappa(-h)) / (2 * h);
}
double f_circumcircle(double phi) { return 2 * std::sin(phi / 2); }
double f_turning_angle(double phi) { return phi; }
double f_regularised(double phi) { return phi / std::cos(phi / 2.1); }

void add_fig3(fair_curves::Gallery& gallery) {
  const double pi = std::acos(-1.0);
  struct Curve { const char* name; double (*f)(double); };
  const Curve curves[] = {{"circumcircle kappa_o", f_circumcircle}, {"turning angle kappa^phi", f_turning_angle},
                          {"regularised (eq. 9)", f_regularised}};
  std::vector<Segment> pieces;
  fair_curves::Curve_case c;
  c.title = "Fig. 3: the curvature gradient of the three discretisations against phi";
  c.caption = "d kappa_j / dx at the symmetric vertex of Fig. 3a (edges of length 1, turning angle phi from 0 to 0.98 pi; "
              "x along the bisector), in the true-curvature convention kappa = f(phi)/s: the circumcircle and the "
              "turning-angle curvature lose their restoring gradient (it changes sign) near phi = pi/2, the "
              "regularised curvature phi/(s cos(phi/2.1)) of eq. 9 keeps it negative much longer (with 2 instead of "
              "2.1 it would be the constant -2; 2.1 keeps kappa finite at phi = pi). Drawn as the graphs "
              "(phi, gradient/4), one after the other; the plot below is their curvature, of no meaning here.";
  c.control_polygons = false;
  c.comb = false;
  c.samples_per_piece = 1;
  for (const Curve& k : curves) {
    double crossing = -1, previous = gradient_of_eq7(k.f, 0.01);
    Point_2 last(0.01, previous / 4);
    for (int i = 2; i <= 98; ++i) {
      const double phi = pi * i / 100, g = gradient_of_eq7(k.f, phi);
      if (crossing < 0 && previous < 0 && g >= 0) crossing = phi;
      previous = g;
      const Point_2 next(phi, g / 4);
      pieces.push_back(Segment(std::vector<Point_2>{last, next}));
      last = next;
    }
    c.measurements.emplace_back(std::string(k.name) + ": gradient at phi = 0",
                                fair_curves::format_number(gradient_of_eq7(k.f, 1e-4), 6));
    c.measurements.emplace_back(std::string(k.name) + ": sign change at phi / pi",
                                crossing < 0 ? std::string("none below 0.98") : fair_curves::format_number(crossing / pi, 3));
  }
  gallery.add_case(fair_curves::make_gallery_case(pieces, c));
}

} // namespace

void add_optimal_cases(fair_curves::Gallery& gallery) {
  gallery.add_section(
      "Optimal curves (Gumhold)",
      "Minimisers of F = int beta + beta_0 |kappa L0|^alpha_0 (+ curvature-derivative terms) ds on adaptive polygons "
      "(fair::Optimal_curve_2, hierarchical Newton), delivered as the C2 cubic spline through the optimal polygon "
      "(fair::fit_smoothing_spline_runs: C2 through the points within the polygon's resolution, G0 at corners). The figures of Gumhold's paper, recomputed; see doc/optimal_curves.md.");
  fair::Optimal_curve_options base;
  base.lambda = -1;  // the paper's figures state their weights: the raw weights of eq. 5 unless lambda is set

  fair::Optimal_curve_options normal = base;
  normal.lambda = 0.5;
  normal.constraints = {constraint(2, fair::Point_constraint_kind::NORMAL, 0.3, 1)};
  add_solve(gallery, arch(), normal, "Fig. 1: a normal constraint",
            "lambda = 0.5; at the apex the left normal of the direction of travel is prescribed as (0.3, 1): the "
            "curve leans over while still interpolating every point.");
  fair::Optimal_curve_options corners = base;
  corners.closed = true;
  corners.lambda = 0.3;
  corners.constraints = {constraint(0, fair::Point_constraint_kind::CORNER, 1, -1, 1, 1),
                         constraint(3, fair::Point_constraint_kind::CORNER, -1, -1, -1, 1)};
  add_solve(gallery, heart(), corners, "Fig. 1: the heart with two corners",
            "Closed, lambda = 0.3, corners (incoming and outgoing tangents) at the bottom tip and the top dip: curvature "
            "0 at each corner (natural boundary, Sec. 3.1), smooth everywhere else.");

  add_fig3(gallery);

  fair::Optimal_curve_options fine = base;
  fine.resolution = 1000;
  add_solve(gallery, arch(), fine, "Fig. 4b: adaptive subdivision at rho = 1000",
            "beta = beta_0 = 1; the dots are the vertices of the optimal polygon: edges are split where "
            "eps = (l/2) tan(phi/4) exceeds the extent / rho, so the vertices crowd where the curve bends.",
            true);

  std::vector<std::pair<std::string, fair::Optimal_curve_options>> family;
  for (int i = 0; i <= 10; ++i) {
    fair::Optimal_curve_options o = base;
    o.lambda = i / 10.0;
    family.emplace_back("lambda = " + fair_curves::format_number(o.lambda, 2), o);
  }
  std::vector<std::pair<std::string, fair::Optimal_curve_options>> fixed_family = family;
  for (auto& f : fixed_family) f.second.lambda_length_scale = 400;  // the paper's q = 100, times 4
  add_family(gallery, arch(), fixed_family, "Fig. 6a: the lambda family with q = 100",
             "lambda = 0, 0.1, ..., 1 with q held at the paper's 100 (400 in the true-curvature convention, "
             "lambda_length_scale): most curves crowd near the int kappa^2 curve, the uneven control of Fig. 6a.");
  add_family(gallery, arch(), family, "Fig. 6b: the lambda family with q(eta)",
             "lambda = 0, 0.1, ..., 1 (eq. 10 with the fitted q(eta) of eq. 12, times 4 for the true curvature): from "
             "the polygon (lambda = 0) to the int kappa^2 curve (lambda = 1). The curvature plot shows "
             "the eleven curves one after the other.");

  fair::Optimal_curve_options local = base;
  local.segment_lambda = {0.5, 1, 1, 0.5};
  fair::Optimal_curve_options local0 = base;
  local0.segment_lambda = {0.5, 0, 0, 0.5};
  fair::Optimal_curve_options uniform = base;
  uniform.segment_lambda = {0.5, 0.5, 0.5, 0.5};
  add_family(gallery, arch(),
             {{"lambda_i = 0.5, 0.5, 0.5, 0.5", uniform}, {"lambda_i = 0.5, 1, 1, 0.5", local},
              {"lambda_i = 0.5, 0, 0, 0.5", local0}},
             "Fig. 8: local lambda_i",
             "Per-segment lambda_i (Sec. 3.2, blended along the curve with phi_4): all 0.5; the two middle segments at "
             "1 (dragged towards the int kappa^2 curve); the same two at 0 (dragged towards the polygon).");

  const std::vector<Point_2> a = arch();
  double L0 = 0; // the input polygon's length
  for (std::size_t i = 0; i + 1 < a.size(); ++i) L0 += std::sqrt(CGAL::squared_distance(a[i], a[i + 1]));
  for (std::size_t k = 1; k <= 4; ++k) {
    fair::Optimal_curve_options o = base;
    o.curvature_weight = 0;
    o.length_weight = 0.03 * std::pow(L0, static_cast<double>(2 * k + 2)); // eq. 5 weighs |kappa^(k) L0^(k+1)|^2
    o.derivative_weight[k] = 1;
    o.resolution = 300;
    add_solve(gallery, arch(), o, "Fig. 9: minimising int (kappa^(" + std::to_string(k) + "))^2",
              "beta_" + std::to_string(k) + " = 1 with a length term beta = 0.03 L0^" + std::to_string(2 * k + 2) +
                  " (without it the pure derivative energies stall); the minimiser is a C" + std::to_string(k + 1) + " curve. The spline drawn is the C2 "
              "cubic smoothing spline; Optimal_curve_2::quintic_spline() gives the C4 quintic smoothing spline for CAD.");
  }
}
FAIR_CURVES_DEMO(80, add_optimal_cases)
