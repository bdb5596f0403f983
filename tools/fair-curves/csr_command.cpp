// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves csr: the curvature-sensitive relaxed spline (Karciauskas & Peters Sec. 4, eq. 6
// corrected; doc/csr_splines.md) of a point file. Writes the cubic C2 B-spline (JSON in the curve
// format with its "bspline" member), the distance to the samples, and the figures.

#include "csr_figure.h"
#include "registry.h"
#include "tool_common.h"

#include <fair/Csr_spline_2.h>
#include <fair/io/enum_names.h>
#include <fair/io/read_points.h>
#include <fair/io/write_json.h>

#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Csr_command_options {
  std::string input, knots = "chordal", json_out, svg_out, plot_out;
  bool closed = false;
};

fair::Knot_spacing knot_spacing_of(const std::string& text) {
  fair::Knot_spacing spacing{};
  if (!fair::io::try_parse_spelling(text, spacing))
    throw CLI::ValidationError("--knots", "expected " + fair::io::spellings_list<fair::Knot_spacing>() + ", got '" + text + "'");
  return spacing;
}

void run_csr(const Csr_command_options& o) {
  typedef fair_curves::Kernel K;
  const fair::Knot_spacing spacing = knot_spacing_of(o.knots);  // usage errors before any work
  const fair::io::Point_file<K> data = fair::io::read_point_file<K>(o.input);
  const bool closed = o.closed || data.closed;
  fair::io::check_point_file(data, closed ? 4 : 3, closed, "fair-curves csr");
  fair::Csr_spline_options options;
  options.closed = closed;
  options.knot_spacing = spacing;
  const fair::Csr_spline_2<K> csr(data.points, options);
  const auto& pieces = csr.pieces();
  const std::vector<double> distances = csr.distances_to_samples();
  const double max_distance = csr.max_distance_to_samples();

  std::string json_text, svg_text, plot_text;
  if (!o.json_out.empty()) {
    nlohmann::json d = nlohmann::json::array(), kappa = nlohmann::json::array();
    for (double v : distances) d.push_back(v);
    for (double v : csr.discrete_curvatures()) kappa.push_back(v);
    const nlohmann::json extra{{"knot_spacing", fair::io::spelling(spacing)},
                               {"epsilon_rule", fair::to_string(options.epsilon_rule)},
                               {"relative_epsilon", options.relative_epsilon},
                               {"discrete_curvatures", kappa},
                               {"distances_to_samples", d},
                               {"max_distance_to_samples", max_distance}};
    std::ostringstream s;
    fair::io::write_json(s, fair::io::family_to_json(csr, "csr", extra));
    json_text = s.str();
  }
  if (!o.svg_out.empty() || !o.plot_out.empty()) {
    fair_curves::Curve_figures f = fair_curves::csr_figures(
        csr, o.input + ": csr-spline, " + fair::to_string(spacing) + " knots, max distance to samples " +
                 fair_curves::format_number(max_distance, 3),
        true);
    svg_text = std::move(f.curve_svg);
    plot_text = std::move(f.curvature_svg);
  }
  std::ostringstream report;
  report << "csr: " << data.points.size() << " samples, " << (closed ? "closed" : "open") << ", " << pieces.size()
         << " cubic pieces, " << fair::to_string(spacing) << " knots\n";
  report << "max distance to samples = " << fair_curves::format_number(max_distance, 10) << "\n";
  fair_curves::write_outputs(report.str(), o.json_out, json_text,
                             fair_curves::export_files(csr.nurbs(), {{o.svg_out, svg_text}, {o.plot_out, plot_text}}));
}

} // namespace

void register_csr_command(CLI::App& app) {
  auto options = std::make_shared<Csr_command_options>();
  CLI::App* sub = app.add_subcommand(
      "csr", "curvature-sensitive relaxed cubic C2 spline of samples (Karciauskas-Peters Sec. 4, eq. 6 corrected); "
             "approximates, does not interpolate: reports the distance to the samples");
  sub->add_option("input", options->input, "the point file (.csv, .txt or .json)")->required();
  sub->add_flag("--closed", options->closed, "closed (periodic) curve, >= 4 samples (also set by JSON \"closed\")");
  sub->add_option("--knots", options->knots, "knot spacing: chordal (default), uniform or centripetal");
  sub->add_option("-o,--output", options->json_out,
                  "write the spline as JSON: pieces, \"bspline\", samples, distances ('-': only JSON on stdout)");
  sub->add_option("--svg", options->svg_out, "draw the curve, its B-spline control polygon, the samples and the curvature comb");
  sub->add_option("--plot", options->plot_out, "plot the curvature against arc length");
  fair_curves::add_export_options(sub);
  sub->callback([options] { run_csr(*options); });
}
FAIR_CURVES_COMMAND(register_csr_command)
