// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves metrics: the fairness figures (include/fair/Fairness_metrics.h, doc/fairness_metrics.md)
// of any curve JSON the program writes, read by fair::io::read_curve_json. Coordinates are read
// exactly (decimal numbers as the nearest double, "p/q" strings as rationals), so the feature
// counts are certified for exactly the curve in the file.

#include "registry.h"
#include "tool_common.h"

#include <fair/Fairness_metrics.h>
#include <fair/io/read_curve.h>
#include <fair/io/svg.h>
#include <fair/io/write_json.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<CGAL::Gmpq> Exact_kernel;

typedef fair::io::Curve_file<Exact_kernel> File_curve;

struct Metrics_options {
  std::string input, json_out, circle, hausdorff, profile_out;
  double tolerance = 0;
  std::size_t samples = 64;
};

/// The --circle value "cx,cy,r" (r >= 0); anything else is a usage error.
std::vector<double> circle_option(const std::string& text) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) v.push_back(fair_curves::option_number(item, "--circle"));
  if (v.size() != 3 || !(v[2] >= 0))
    throw CLI::ValidationError("--circle", "expected \"cx,cy,r\" with r >= 0, got '" + text + "'");
  return v;
}

std::string features_text(const fair::Feature_report& r) {
  std::ostringstream out;
  for (const fair::Curve_feature& f : r.features)
    out << "  piece " << f.piece << " t = " << fair_curves::format_number(f.t, 12) << " at ("
        << fair_curves::format_number(f.x, 8) << ", " << fair_curves::format_number(f.y, 8)
        << "), curvature " << fair_curves::format_number(f.curvature, 8) << (f.at_joint ? " (at a join)" : "") << "\n";
  return out.str();
}

nlohmann::json features_json(const fair::Feature_report& r) {
  nlohmann::json a = nlohmann::json::array();
  for (const fair::Curve_feature& f : r.features)
    a.push_back({{"piece", f.piece}, {"t", f.t}, {"t_lower", CGAL::to_double(f.interval.lower)},
                 {"t_upper", CGAL::to_double(f.interval.upper)}, {"x", f.x}, {"y", f.y},
                 {"curvature", f.curvature}, {"at_joint", f.at_joint}});
  return a;
}

template <class Piece>
void report(const std::vector<Piece>& curve, const Metrics_options& o, const File_curve* other) {
  const fair::Fairness_report r = fair::fairness_report(curve);
  const fair::Feature_report infl = fair::inflections(curve), ext = fair::curvature_extrema(curve);
  const fair::Quadrature_estimate cv_t = fair::curvature_variation_energy(curve, fair::Energy_measure::PARAMETER);
  using fair_curves::format_number;
  std::ostringstream text; // the report: on stdout unless stdout is the JSON ("-o -")
  text << o.input << ": " << r.pieces << " pieces\n"
            << "arc length = " << format_number(r.length.value, 12) << "\n"
            << "bending energy int k^2 ds = " << format_number(r.bending.value, 12) << " (error estimate "
            << format_number(r.bending.error_bound, 2) << ")\n"
            << "curvature variation int (dk/ds)^2 ds = " << format_number(r.curvature_variation.value, 12)
            << " (error estimate " << format_number(r.curvature_variation.error_bound, 2) << ")\n"
            << "curvature variation sum int (dk/dt)^2 dt = " << format_number(cv_t.value, 12) << "\n"
            << "curvature range = [" << format_number(r.min_curvature, 8) << ", " << format_number(r.max_curvature, 8)
            << "]\n"
            << "inflections: " << infl.count() << (infl.certified ? " (certified)" : " (sampled)") << "\n"
            << features_text(infl) << "curvature extrema: " << ext.count()
            << (ext.certified ? " (certified)" : " (sampled)") << "\n"
            << features_text(ext);
  nlohmann::json j{{"pieces", r.pieces},
                   {"arc_length", r.length.value},
                   {"bending_energy", r.bending.value},
                   {"bending_energy_error", r.bending.error_bound},
                   {"curvature_variation_arc_length", r.curvature_variation.value},
                   {"curvature_variation_arc_length_error", r.curvature_variation.error_bound},
                   {"curvature_variation_parameter", cv_t.value},
                   {"min_curvature", r.min_curvature},
                   {"max_curvature", r.max_curvature},
                   {"certified", infl.certified && ext.certified},
                   {"inflections", features_json(infl)},
                   {"curvature_extrema", features_json(ext)}};
  if (!o.circle.empty()) {
    const std::vector<double> v = circle_option(o.circle);
    const fair::Circle_deviation d =
        fair::max_circle_deviation(curve, typename Piece::Point_2(v[0], v[1]), v[2]);
    text << "max deviation from the circle = " << format_number(d.max_deviation, 12) << " (piece " << d.piece
              << ", t = " << format_number(d.t, 10) << ")\n";
    j["circle_deviation"] = d.max_deviation;
  }
  if (other) {
    // Default tolerance: 1e-5 of the diagonal of the bounding box of both curves' control
    // points (halved coordinates: no overflow), or of the largest coordinate when that box is a
    // point, so that a degenerate curve does not ask for a tolerance of 1e-300.
    double tol = o.tolerance;
    if (!(tol > 0)) {
      double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300, big = 0;
      auto extend = [&](const auto& pieces) {
        for (const auto& p : pieces)
          for (const auto& q : p.control_points()) {
            const double x = CGAL::to_double(q.x()), y = CGAL::to_double(q.y());
            xmin = std::min(xmin, x); xmax = std::max(xmax, x); ymin = std::min(ymin, y); ymax = std::max(ymax, y);
            big = std::max({big, std::fabs(x), std::fabs(y)});
          }
      };
      extend(curve);
      extend(other->pieces);
      const double diagonal = 2 * std::hypot(0.5 * xmax - 0.5 * xmin, 0.5 * ymax - 0.5 * ymin);
      tol = 1e-5 * (diagonal > 0 ? diagonal : big);
      if (!(tol > 0) || !std::isfinite(tol)) tol = 1e-5;
    }
    const fair::Hausdorff_bounds h = other->rational ? fair::hausdorff_distance_bounds(curve, other->pieces, tol)
                                                     : fair::hausdorff_distance_bounds(curve, other->polynomial_pieces(), tol);
    text << "Hausdorff distance to " << o.hausdorff << " = " << format_number(h.value(), 10) << " (certified in ["
         << format_number(h.lower, 10) << ", " << format_number(h.upper, 10) << "], tolerance "
         << format_number(tol, 3)
         << (h.converged                        ? ""
             : h.rounding_allowance > tol / 2 ? "; bounds wider than the tolerance: it is below the rounding allowance of the coordinates"
                                              : "; work cap reached, bounds wider than the tolerance")
         << ")\n";
    j["hausdorff_distance"] = h.value();
    j["hausdorff_lower"] = h.lower;
    j["hausdorff_upper"] = h.upper;
    j["hausdorff_converged"] = h.converged;
    j["hausdorff_tolerance"] = tol;
  }
  std::string profile_text;
  if (!o.profile_out.empty()) {
    std::ostringstream out;
    out.precision(17);
    out << "piece,t,arc_length,x,y,curvature\n";
    for (const fair::Curvature_sample& s : fair::curvature_profile(curve, o.samples))
      out << s.piece << ',' << s.t << ',' << s.arc_length << ',' << s.x << ',' << s.y << ',' << s.curvature << '\n';
    profile_text = out.str();
  }
  std::string json_text;
  if (!o.json_out.empty()) {
    std::ostringstream out;
    fair::io::write_json(out, j);
    json_text = out.str();
  }
  fair_curves::write_outputs(text.str(), o.json_out, json_text, {{o.profile_out, profile_text}});
}

void run_metrics(const Metrics_options& o) {
  if (!o.circle.empty()) circle_option(o.circle); // usage error before reading any file
  const File_curve curve = fair::io::read_curve_json<Exact_kernel>(o.input);
  File_curve other;
  if (!o.hausdorff.empty()) other = fair::io::read_curve_json<Exact_kernel>(o.hausdorff);
  const File_curve* second = o.hausdorff.empty() ? nullptr : &other;
  if (curve.rational) report(curve.pieces, o, second);
  else report(curve.polynomial_pieces(), o, second);
}

} // namespace

void register_metrics_command(CLI::App& app) {
  auto options = std::make_shared<Metrics_options>();
  CLI::App* sub = app.add_subcommand(
      "metrics", "Fairness figures of a curve JSON written by fair-curves: length, bending energy, curvature "
                 "variation, curvature range, certified inflections and curvature extrema");
  sub->add_option("curve", options->input, "the curve file: JSON with \"pieces\" written by fair-curves (conic, cardinal, kappa, ...)")->required();
  sub->add_option("--circle", options->circle, "also the largest deviation from the circle \"cx,cy,r\"");
  sub->add_option("--hausdorff", options->hausdorff, "also the Hausdorff distance to another curve file");
  sub->add_option("--tolerance", options->tolerance,
                  "sampling tolerance of the Hausdorff distance (default 1e-5 of the bounding box diagonal)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--profile", options->profile_out, "write curvature against arc length samples as CSV");
  sub->add_option("--samples", options->samples, "profile samples per piece (default 64)")->check(CLI::Range(1, 100000));
  sub->add_option("-o,--output", options->json_out, "write the figures as JSON ('-' for stdout)");
  sub->callback([options] { run_metrics(*options); });
}
FAIR_CURVES_COMMAND(register_metrics_command)
