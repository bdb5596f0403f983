// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Demo cases of the Cardinal splines of J. Li, "Curvature variation minimizing Cardinal spline
// curves": Figures 1-4 and Tables 1-2 of the paper, recomputed, plus a closed curve.

#include "registry.h"
#include "tool_common.h"

#include <fair/Cardinal_spline_2.h>
#include <fair/Fairness_metrics.h>
#include <fair/io/svg.h>
#include <fair/io/write_json.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using fair_curves::Kernel;
using fair_curves::Point_2;
using fair_curves::format_number;
typedef CGAL::Simple_cartesian<CGAL::Gmpq> Exact;

std::vector<Point_2> data_set_1() {
  const double px[] = {35, 16, 15, 25, 40, 65, 50, 60, 80}, py[] = {47, 40, 15, 36, 15, 25, 40, 42, 37};
  std::vector<Point_2> p;
  for (int i = 0; i < 9; ++i) p.emplace_back(px[i], py[i]);
  return p;
}

std::vector<Point_2> half_circle() {
  std::vector<Point_2> p;
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= 4; ++i) p.emplace_back(std::cos(pi / 4 * i), std::sin(pi / 4 * i));
  return p;
}

std::string point_text(const Point_2& p) {
  return "(" + format_number(p.x(), 6) + ", " + format_number(p.y(), 6) + ")";
}

// One case: the curve, its certified inflections marked, and its energies in the table.
void add_case(fair_curves::Gallery& gallery, const fair::Cardinal_spline_2<Kernel>& curve, const std::string& title,
              const std::string& caption, std::vector<std::pair<std::string, std::string>> rows,
              const Point_2* circle_centre = nullptr) {
  const auto& pieces = curve.pieces();
  const fair::Feature_report infl = fair::inflections(pieces);
  fair_curves::Curve_case c;
  c.title = title;
  c.caption = caption;
  c.input_points = fair::io::to_xy(curve.points());
  if (!curve.is_closed()) {
    // Show the auxiliary points too (as input points: they shape the end segments).
    c.input_points.push_back(fair::io::Xy{curve.aux_start().x(), curve.aux_start().y()});
    c.input_points.push_back(fair::io::Xy{curve.aux_end().x(), curve.aux_end().y()});
  }
  for (const fair::Curve_feature& f : infl.features) c.marks.push_back(fair_curves::Curve_mark{f.piece, f.t, "i"});
  rows.emplace_back("alpha", format_number(curve.alpha(), 10));
  if (!curve.is_closed()) {
    rows.emplace_back("p_{-1}", point_text(curve.aux_start()));
    rows.emplace_back("p_{n+1}", point_text(curve.aux_end()));
  }
  rows.emplace_back("curvature variation, eq. 10 (sum int |r'''|^2)", format_number(curve.approximate_energy(), 6));
  rows.emplace_back("curvature variation, eq. 5 (sum int (dk/dt)^2 dt)",
                    format_number(fair::curvature_variation_energy(pieces, fair::Energy_measure::PARAMETER).value, 6));
  rows.emplace_back("int (dk/ds)^2 ds", format_number(fair::curvature_variation_energy(pieces).value, 6));
  rows.emplace_back("bending energy int k^2 ds", format_number(fair::bending_energy(pieces).value, 6));
  rows.emplace_back("inflections (certified interval isolation, marked i)", std::to_string(infl.count()));
  if (circle_centre)
    rows.emplace_back("max deviation from the unit circle",
                      format_number(fair::max_circle_deviation(pieces, *circle_centre, 1.0).max_deviation, 4));
  c.measurements = rows;
  gallery.add_case(fair_curves::make_gallery_case(pieces, c));
}

} // namespace

void add_cardinal_cases(fair_curves::Gallery& gallery) {
  gallery.add_section(
      "Cardinal splines with minimum curvature variation (Li)",
      "r_i(t) = b0 p_i + b1 p_{i+1} + b2 p_{i+2} + b3 p_{i+3} with the basis of eq. 2 and parameter alpha = (1 - T)/2 "
      "(alpha = 1/2: Catmull-Rom). The open curve needs two auxiliary points p_{-1}, p_{n+1} (shown as input points "
      "beyond the ends). Li minimises the approximation eq. 10 of the curvature variation in closed form: alpha* of "
      "eq. 18 and the auxiliary points of eqs. 19-20. Figures 1-4 and Tables 1-2 of the paper are recomputed here.");
  const std::vector<Point_2> p = data_set_1();
  typedef fair::Cardinal_spline_2<Kernel> Spline;
  // Figure 1: the effect of alpha, with p_{-1} = p_0 and p_9 = p_8.
  add_case(gallery, Spline(p, 0.5, p.front(), p.back()), "Figure 1: alpha = 0.5, p_{-1} = p_0, p_9 = p_8",
           "Li's first data set with the Catmull-Rom parameter and the auxiliary points doubled onto the ends.", {});
  add_case(gallery, Spline(p, 0.8, p.front(), p.back()), "Figure 1: alpha = 0.8, p_{-1} = p_0, p_9 = p_8",
           "The same data with alpha = 0.8: longer tangents, rounder turns.", {});
  // Figure 2: the effect of the auxiliary points at alpha = 0.5.
  add_case(gallery, Spline(p, 0.5, Point_2(50, 60), Point_2(95, 20)),
           "Figure 2: alpha = 0.5, p_{-1} = (50, 60), p_9 = (95, 20)",
           "Other auxiliary points change only the first and the last segment.", {});
  // Figure 3 and Table 1: the optimum against Catmull-Rom with the same auxiliary points.
  std::vector<Exact::Point_2> pe;
  for (const Point_2& q : p) pe.emplace_back(q.x(), q.y());
  const fair::Cardinal_spline_report<Exact> oe = fair::Cardinal_spline_2<Exact>(pe).report();
  const Spline optimum(p);
  const fair::Cardinal_spline_report<Kernel>& o = optimum.report();
  add_case(gallery, optimum, "Figure 3 / Table 1: minimum curvature variation",
           "alpha* = 9192/12241 (exact) and p_{-1}*, p_9* of eqs. 18-20. Table 1 of the paper: alpha 0.7509, energy "
           "1.9964e5. The two end segments are parabolic (r''' = 0) and add nothing to eq. 10.",
           {{"alpha* (exact rational, eq. 18)", fair::io::number_text(oe.alpha)},
            {"eq. 10 at the optimum (exact)", fair::io::number_text(oe.energy)},
            {"Table 1 (paper)", "0.7509, 1.9964e5"}});
  add_case(gallery, Spline(p, 0.5, o.aux_start, o.aux_end), "Figure 3 / Table 1: Catmull-Rom",
           "alpha = 0.5 with the same auxiliary points p_{-1}*, p_9* (the paper's comparison). Table 1 of the paper: "
           "energy 2.4081e5.",
           {{"Table 1 (paper)", "0.5, 2.4081e5"}});
  // Figure 4 and Table 2: the half circle.
  const std::vector<Point_2> c = half_circle();
  const Spline circle_optimum(c);
  const fair::Cardinal_spline_report<Kernel>& oc = circle_optimum.report();
  const Point_2 origin(0, 0);
  add_case(gallery, circle_optimum, "Figure 4 / Table 2: half circle, minimum curvature variation",
           "Five points of the unit half circle. alpha* = 2 - sqrt 2 = 1/(1 + cos(pi/4)): every segment has "
           "r''' = 0 and eq. 10 vanishes (the paper prints 1.8087e-7 from 4-digit inputs).",
           {{"Table 2 (paper)", "0.5858, 1.8087e-7"}}, &origin);
  add_case(gallery, Spline(c, 0.5, oc.aux_start, oc.aux_end), "Figure 4 / Table 2: half circle, Catmull-Rom",
           "alpha = 0.5 with the same auxiliary points: visibly off the circle. Table 2 of the paper: 7.2364.",
           {{"Table 2 (paper)", "0.5, 7.2364"}}, &origin);
  // A closed curve: the closed analogue of eq. 18 (doc/cardinal_splines.md).
  const std::vector<Point_2> loop{Point_2(0, 0), Point_2(4, -1), Point_2(7, 1), Point_2(6, 4), Point_2(3, 3),
                                  Point_2(1, 5), Point_2(-2, 3)};
  fair::Cardinal_spline_options closed;
  closed.closed = true;
  const Spline loop_optimum(loop, closed);
  const fair::Cardinal_spline_report<Kernel>& ol = loop_optimum.report();
  add_case(gallery, loop_optimum, "Closed curve, minimum curvature variation",
           "Seven points, periodic: alpha* = -2 sum d_i.m_i / sum |d_i|^2 over all segments; no auxiliary points.",
           {{"eq. 10 at alpha*", format_number(ol.energy, 8)},
            {"eq. 10 at alpha = 0.5", format_number(Spline(loop, 0.5, closed).approximate_energy(), 8)}});
}
FAIR_CURVES_DEMO(40, add_cardinal_cases)
