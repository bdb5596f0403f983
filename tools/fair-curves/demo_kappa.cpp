// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Demo cases of rational kappa-curves (fair::Kappa_curve_2; Yan, Schiller, Schaefer): Fig. 3
// (uniform weights 0.6, 1, 2 and the automatic weights on the same points), Fig. 9 (a cusp
// forming as two points approach) and Fig. 12 (circle reproduction from non-uniform points on a
// circle, and the failure case with a central angle above pi).

#include "registry.h"
#include "tool_common.h"

#include <fair/Kappa_curve_2.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using fair_curves::Point_2;

std::string report_text(const fair::Kappa_solve_report& r) {
  return std::string(r.converged ? "converged" : "not converged") + ", " + std::to_string(r.refinement_passes) +
         " passes + " + std::to_string(r.iterations) + " iterations";
}

void add_kappa_case(fair::io::Gallery& gallery, const std::vector<Point_2>& points, const fair::Kappa_curve_options& o,
                    const std::string& title, const std::string& caption) {
  const fair::Kappa_curve_2<fair_curves::Kernel> curve(points, o);
  fair_curves::Curve_case c;
  c.title = title;
  c.caption = caption;
  c.input_points = fair::io::to_xy(points);
  c.samples_per_piece = 96;
  for (std::size_t j = 0; j < curve.number_of_pieces(); ++j)
    c.marks.push_back(fair_curves::Curve_mark{j, curve.t(j), std::string()});
  const fair::Kappa_solve_report& r = curve.report();
  c.measurements.emplace_back("solve", report_text(r));
  c.measurements.emplace_back("max residual", fair_curves::format_number(r.residual, 3));
  c.measurements.emplace_back("energy (eqs. 11-13 + interpolation)", fair_curves::format_number(r.energy(), 3));
  double wmin = 1e300, wmax = 0;
  for (std::size_t j = 0; j < curve.number_of_pieces(); ++j) {
    wmin = std::min(wmin, curve.weight(j));
    wmax = std::max(wmax, curve.weight(j));
  }
  c.measurements.emplace_back("weights", fair_curves::format_number(wmin, 4) + " .. " + fair_curves::format_number(wmax, 4));
  gallery.add_case(fair_curves::make_gallery_case(curve.pieces(), c));
}

std::vector<Point_2> on_circle(const std::vector<double>& degrees) {
  std::vector<Point_2> p;
  for (double d : degrees) p.push_back(Point_2(std::cos(d * M_PI / 180), std::sin(d * M_PI / 180)));
  return p;
}

} // namespace

void add_kappa_cases(fair::io::Gallery& gallery) {
  gallery.add_section(
      "Rational kappa-curves",
      "One rational quadratic piece per input point; each input point is a curvature extremum of its piece "
      "(eq. 7), consecutive pieces join G1 with |kappa| continuous (eqs. 9, 10). Weights 1 give the polynomial "
      "kappa-curves; the automatic (clamped minimum-eccentricity, eq. 16) weights reproduce circles. The marks "
      "are the input points at their parameters t_i.");
  // Fig. 3: the same closed points, uniform weights 0.6, 1, 2 and automatic weights (top row: a
  // kite; bottom row: four non-uniformly spaced points on a circle, reproduced by the automatic
  // weights).
  const std::vector<Point_2> kite = {Point_2(0, 0), Point_2(2, -1), Point_2(4, 0), Point_2(2, 3)};
  for (double w : {0.6, 1.0, 2.0}) {
    fair::Kappa_curve_options o;
    o.closed = true;
    o.weights = w == 1.0 ? fair::Kappa_weights::UNIT : fair::Kappa_weights::FIXED;
    o.fixed_weights.assign(kite.size(), w);
    add_kappa_case(gallery, kite, o, "Fig. 3: weights " + fair_curves::format_number(w, 2),
                   "Every weight w_i = " + fair_curves::format_number(w, 2) +
                       (w == 1.0 ? ": the polynomial kappa-curve." : ". Larger weights give sharper corners."));
  }
  const std::vector<Point_2> circle4 = on_circle({0, 80, 170, 260});
  for (int k = 0; k < 2; ++k) {
    fair::Kappa_curve_options o;
    o.closed = true;
    o.weights = fair::Kappa_weights::AUTOMATIC;
    add_kappa_case(gallery, k == 0 ? kite : circle4, o,
                   std::string("Fig. 3: automatic weights") + (k == 0 ? "" : ", co-circular points"),
                   k == 0 ? "Clamped minimum-eccentricity weights (eq. 16, tension 1, clamp 1/2), chosen by the solver."
                          : "Four non-uniformly spaced points on the unit circle (0, 80, 170, 260 degrees): the "
                            "automatic weights reproduce the circle.");
  }
  {
    fair::Kappa_curve_options o;
    o.closed = true;
    add_kappa_case(gallery, circle4, o, "Fig. 3: weights 1, co-circular points",
                   "The same four co-circular points with unit weights (polynomial kappa-curve): not a circle.");
  }
  // Fig. 9: the 2nd and 4th points approach each other: a cusp forms at the 3rd (an input point).
  for (double d : {0.6, 0.15, 0.02}) {
    const std::vector<Point_2> p = {Point_2(-2, 0), Point_2(-d, 1), Point_2(0, 2.5), Point_2(d, 1), Point_2(2, 0)};
    fair::Kappa_curve_options o;
    o.weights = fair::Kappa_weights::AUTOMATIC;
    add_kappa_case(gallery, p, o, "Fig. 9: cusp, gap " + fair_curves::format_number(2 * d, 2),
                   "Open curve, automatic weights; as the 2nd and 4th points approach, the curvature maximum at the "
                   "top input point grows into a cusp -- cusps appear only at input points.");
  }
  // Fig. 12: circle reproduction and its failure.
  {
    fair::Kappa_curve_options o;
    o.closed = true;
    o.weights = fair::Kappa_weights::AUTOMATIC;
    add_kappa_case(gallery, on_circle({0, 70, 150, 200, 280}), o, "Fig. 12: circle from non-uniform points",
                   "Five points on the unit circle at 0, 70, 150, 200, 280 degrees (central angles < 180): the "
                   "automatic weights reproduce the circle (constant curvature 1).");
    add_kappa_case(gallery, on_circle({0, 30, 80, 120}), o, "Fig. 12: failure, central angle > 180",
                   "Four points on the unit circle at 0, 30, 80, 120 degrees: the last central angle is 240 "
                   "degrees > 180, a piece would have to span more than the clamp allows, and the curve is not "
                   "the circle (Sec. 8).");
  }
}
FAIR_CURVES_DEMO(50, add_kappa_cases)
