// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves kappa: the (rational) kappa-curve through a point file (fair::Kappa_curve_2;
// Yan, Schiller, Schaefer; doc/kappa_curves.md). Weights: "1" (polynomial kappa-curves),
// "auto" (clamped minimum-eccentricity weights, eq. 16, optional per-point tension file) or a
// number W used for every point; with "auto", --clamp sets the lower clamp of eq. 16 (default
// 1/2). Writes the pieces and the solve report as JSON and a figure. The outcome (interior, on
// joins, unsolved: fair::Kappa_curve_status) is one line on stdout; unsolved also on stderr (by its
// reason: on data beyond the density limit, that no kappa-curve exists and which commands are made
// for dense samples), and the exit code is then unsolved_exit_code unless --allow-unsolved.

#include "kappa_output.h"
#include "registry.h"
#include "tool_common.h"

#include <fair/Kappa_curve_2.h>
#include <fair/io/enum_names.h>
#include <fair/io/read_numbers.h>
#include <fair/io/read_points.h>
#include <fair/io/svg.h>
#include <fair/io/write_json.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace fair_curves::kappa;

/// The curve, its control polygons and curvature comb as the SVG figure of --svg.
std::string curve_svg(const Kappa_command_options& o, const fair::io::Point_file<fair_curves::Kernel>& data,
                      const fair::Kappa_curve_2<fair_curves::Kernel>& curve) {
  using namespace fair_curves;
  Curve_case c;
  c.title = o.input + ": kappa-curve, weights " + o.weights;
  c.title_in_figure = true;
  c.input_points = fair::io::to_xy(data.points);
  return make_curve_figures(curve.pieces(), c).curve_svg;
}

void run_kappa(const Kappa_command_options& o) {
  using namespace fair_curves;
  const fair::Kappa_curve_options asked = curve_options(o);
  const fair::io::Point_file<Kernel> data = fair::io::read_point_file<Kernel>(o.input);
  const fair::Kappa_curve_options options = solve_options(
      o, asked, data, [&](std::size_t points) { return fair::io::read_tensions(o.tension_file, points); });

  const fair::Kappa_curve_2<Kernel> curve(data.points, options);
  const std::string json_text = o.json_out.empty() ? std::string() : curve_json(o, curve);
  const std::string svg_text = o.svg_out.empty() ? std::string() : curve_svg(o, data, curve);
  write_outputs(summary(o, curve), o.json_out, json_text, export_files(curve.nurbs(), {{o.svg_out, svg_text}}));
  if (curve.report().status == fair::Kappa_curve_status::UNSOLVED) {
    std::cerr << "fair-curves kappa: " << o.input << ": " << unsolved_line(curve)
              << (o.allow_unsolved ? "" : " (exit code 3; --allow-unsolved to exit 0)") << '\n';
    if (!o.allow_unsolved) throw fair_curves::Exit_code{unsolved_exit_code};
  }
}

} // namespace

// The kappa sessions' curve of fair-curves serve (kappa_session.h): here, where the command
// instantiates the solver and the JSON writer already; the same reader, checks and writer as
// run_kappa.
namespace fair_curves {
namespace kappa {
struct Kappa_session_curve::Impl {
  Kappa_command_options o;
  fair::Kappa_curve_options options;
  std::unique_ptr<fair::Kappa_curve_2<Kernel>> curve;
};

Kappa_session_curve::Kappa_session_curve(const Kappa_command_options& o, const std::string& points,
                                         const std::string& tensions)
    : impl_(new Impl) {
  impl_->o = o;
  const fair::Kappa_curve_options asked = curve_options(o);
  const fair::io::Point_file<Kernel> data = fair::io::parse_points_json<Kernel>(points, o.input);
  impl_->options = solve_options(
      o, asked, data, [&](std::size_t n) { return fair::io::parse_tensions(tensions, o.tension_file, n); });
  impl_->curve.reset(new fair::Kappa_curve_2<Kernel>(data.points, impl_->options));
}

Kappa_session_curve::~Kappa_session_curve() = default;

void Kappa_session_curve::move_point(const std::string& points, std::size_t i) {
  const fair::io::Point_file<Kernel> data = fair::io::parse_points_json<Kernel>(points, impl_->o.input);
  fair::io::check_point_file(data, minimum_points, impl_->options.closed, "fair-curves kappa");
  fair::internal::require(i < data.points.size() && data.points.size() == impl_->curve->points().size(),
                          "Kappa_session_curve::move_point: point ", i, " of ", data.points.size());
  impl_->curve->move_point(i, data.points[i]);
}

std::string Kappa_session_curve::json() const { return curve_json(impl_->o, *impl_->curve); }
} // namespace kappa
} // namespace fair_curves

void register_kappa_command(CLI::App& app) {
  auto options = std::make_shared<Kappa_command_options>();
  CLI::App* sub = app.add_subcommand(
      "kappa", "Rational kappa-curve through a point file: one conic piece per point, each point a curvature "
               "extremum of its piece, |kappa| continuous (Yan, Schiller, Schaefer)");
  sub->add_option("input", options->input, "the point file (.csv, .txt or .json)")->required();
  sub->add_flag("--closed", options->closed, "closed curve (also set by JSON \"closed\")");
  sub->add_option("--weights", options->weights,
                  "1 (polynomial kappa-curve, default), auto (minimum-eccentricity weights, eq. 16) or a weight W > 0");
  sub->add_option("--tension", options->tension_file, "with --weights auto: one tension mu_i > 0 per point per line");
  CLI::Option* clamp = sub->add_option("--clamp", options->clamp,
                  "with --weights auto: the lower clamp of eq. 16, a number > 0 (default 1/2; small values approach "
                  "the unclamped minimum-eccentricity weights of eq. 15)");
  sub->add_option("--max-iterations", options->max_iterations,
                  "cap on the Jacobians of the solve, an integer >= 0 (default 200)");
  sub->add_flag("--allow-unsolved", options->allow_unsolved,
                "exit 0 even when the solve is unsolved (default: exit code 3, outputs still written)");
  sub->add_option("-o,--output", options->json_out, "write the pieces and the report as JSON ('-': only JSON on stdout)");
  sub->add_option("--svg", options->svg_out, "draw the curve, its control polygons and curvature comb");
  fair_curves::add_export_options(sub);
  sub->callback([options, clamp] {
    options->clamp_given = clamp->count() > 0;
    run_kappa(*options);
  });
}
FAIR_CURVES_COMMAND(register_kappa_command)
