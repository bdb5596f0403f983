// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves conic: one rational quadratic (conic) piece from its control points and weight:
// its type, eccentricity, end curvatures and certified curvature extrema; optionally as JSON
// and SVG figures.

#include "conic_report.h"
#include "registry.h"

#include <fair/io/svg.h>
#include <fair/Nurbs_curve_2.h>
#include <fair/io/write_json.h>

#include <iostream>
#include <memory>
#include <string>

namespace {

struct Conic_options {
  std::string p0, p1, p2, w;
  std::string json_out, svg_out, plot_out;
  std::size_t samples = 128;
};

void run_conic(const Conic_options& o) {
  using namespace fair_curves;
  // Option values first (usage errors, exit 2), then the geometry (input errors, exit 1).
  const Point_2 p0 = option_point(o.p0, "--p0"), p1 = option_point(o.p1, "--p1"), p2 = option_point(o.p2, "--p2");
  const double w = option_number(o.w, "--w");
  if (o.samples < 2 || o.samples > 100000)
    throw CLI::ValidationError("--samples", "must be in [2, 100000], got " + std::to_string(o.samples));
  const Conic_piece piece(p0, p1, p2, w);
  const Conic_report report = conic_report(piece);
  const std::vector<Conic_piece> curve = {piece};

  // Produce every output in memory before writing any file.
  std::string json_text, svg_text, plot_text;
  if (!o.json_out.empty()) {
    const std::vector<Point_2> points = {p0, p2};  // the arc's end points: what it interpolates
    nlohmann::json j = fair::io::curve_to_json("conic", false, points, curve, nlohmann::json{{"conic", conic_json(report)}});
    j["bspline"] = fair::io::nurbs_to_json(fair::Nurbs_curve_2<Kernel>(2, {0, 0, 0, 1, 1, 1}, piece.control_points(), piece.weights()));
    std::ostringstream out;
    fair::io::write_json(out, j);
    json_text = out.str();
  }
  if (!o.svg_out.empty() || !o.plot_out.empty()) {
    Curve_case c;
    c.title = report.type + " arc, w = " + format_number(report.weight);
    c.title_in_figure = true;
    c.marks = conic_marks(report);
    c.samples_per_piece = o.samples;
    const Curve_figures f = make_curve_figures(curve, c);
    svg_text = f.curve_svg;
    plot_text = f.curvature_svg;
  }
  write_outputs(conic_text(piece, report), o.json_out, json_text,
                export_files(fair::Nurbs_curve_2<Kernel>(2, {0, 0, 0, 1, 1, 1}, piece.control_points(), piece.weights()), {{o.svg_out, svg_text}, {o.plot_out, plot_text}}));
}

} // namespace

void register_conic_command(CLI::App& app) {
  auto options = std::make_shared<Conic_options>();
  CLI::App* sub = app.add_subcommand(
      "conic", "One conic arc c(t) = ((1-t)^2 P0 + 2(1-t)t w P1 + t^2 P2) / W(t): type, eccentricity and "
               "certified curvature extrema");
  sub->add_option("--p0", options->p0, "start point x,y")->required();
  sub->add_option("--p1", options->p1, "middle control point x,y (not collinear with P0, P2)")->required();
  sub->add_option("--p2", options->p2, "end point x,y")->required();
  sub->add_option("--w", options->w, "weight of P1, > 0 (< 1 ellipse, 1 parabola, > 1 hyperbola)")->required();
  sub->add_option("-o,--output", options->json_out, "write the piece and its report as JSON ('-': only the JSON on stdout)");
  sub->add_option("--svg", options->svg_out, "write a figure of the arc (control polygon, comb, extrema)");
  sub->add_option("--plot", options->plot_out, "write the curvature against arc length plot");
  sub->add_option("--samples", options->samples, "samples for the figures (default 128)");
  fair_curves::add_export_options(sub);
  sub->callback([options] { run_conic(*options); });
}
FAIR_CURVES_COMMAND(register_conic_command)
