// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves optimal: Gumhold's optimal curve through a point file (fair::Optimal_curve_2,
// issue 11; doc/optimal_curves.md), delivered as the optimal polygon and the C2 cubic spline
// through it (fair::fit_smoothing_spline_runs: C2 between corners, G0 at them; with a derivative term k >= 1 also the C4
// quintic smoothing spline, fair::fit_smoothing_quintic_runs). The
// weights of eq. 5 (--length-weight, --curvature-weight, --curvature-exponent,
// --derivative-weight K:BK[:AK]) or the lambda trade-off of eq. 10 (--lambda, or one lambda per
// input segment from --lambda-file); tangent, normal and corner constraints from files (formats
// in doc/optimal_curves.md). Writes the JSON curve format with "pieces" and "bspline",
// the polygon, the solve report and the fit's distance, and an SVG figure. A solve that did not
// converge (status capped or diverging) still writes its outputs and exits with
// not_converged_exit_code.

#include "registry.h"
#include "tool_common.h"

#include <fair/Optimal_curve_2.h>
#include <fair/Polygon_spline_fit.h>
#include <fair/io/enum_names.h>
#include <fair/io/read_constraints.h>
#include <fair/io/read_numbers.h>
#include <fair/io/read_points.h>
#include <fair/io/svg.h>
#include <fair/io/write_json.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

/// Exit code of a solve that is capped or diverging (outputs written, "status" says which).
constexpr int not_converged_exit_code = 3;

struct Optimal_command_options {
  std::string input, lambda, lambda_file, length_weight, curvature_weight, curvature_exponent, tangents, normals,
      corners, resolution, solver = "newton", json_out, svg_out;
  std::vector<std::string> derivative_weights;
  bool closed = false;
};

/// A number option in [low, high] (usage error otherwise).
double ranged_option(const std::string& text, const std::string& option, double low, double high, const char* domain) {
  const double v = fair_curves::option_number(text, option);
  if (!(v >= low && v <= high)) throw CLI::ValidationError(option, std::string("expected ") + domain + ", got '" + text + "'");
  return v;
}

/// The curve options the command line asks for, before any file is read (usage errors).
fair::Optimal_curve_options curve_options(const Optimal_command_options& o) {
  const double inf = HUGE_VAL;
  fair::Optimal_curve_options options;
  options.closed = o.closed;
  if (!o.lambda.empty() && !o.lambda_file.empty())
    throw CLI::ValidationError("--lambda", "--lambda and --lambda-file exclude each other");
  const bool design = !o.lambda.empty() || !o.lambda_file.empty();
  if (design && (!o.length_weight.empty() || !o.curvature_weight.empty()))
    throw CLI::ValidationError(!o.lambda.empty() ? "--lambda" : "--lambda-file",
                               "the lambda design sets beta and beta_0 (eq. 10): drop --length-weight/--curvature-weight");
  if (!o.lambda.empty()) options.lambda = ranged_option(o.lambda, "--lambda", 0, 1, "a lambda in [0, 1]");
  // The defaults are the lambda design at fair::default_optimal_lambda (issue 25 §1); the raw
  // weights of eq. 5 when one of them is given, or with --lambda-file (segment_lambda).
  if (!o.length_weight.empty() || !o.curvature_weight.empty() || !o.lambda_file.empty()) options.lambda = -1;
  if (!o.length_weight.empty())
    options.length_weight = ranged_option(o.length_weight, "--length-weight", 0, inf, "a weight >= 0");
  if (!o.curvature_weight.empty())
    options.curvature_weight = ranged_option(o.curvature_weight, "--curvature-weight", 0, inf, "a weight >= 0");
  if (!o.curvature_exponent.empty())
    options.curvature_exponent = ranged_option(o.curvature_exponent, "--curvature-exponent", 1, inf, "an exponent >= 1");
  for (const std::string& d : o.derivative_weights) {
    std::vector<std::string> parts;
    std::stringstream in(d);
    for (std::string part; std::getline(in, part, ':');) parts.push_back(part);
    if (parts.size() < 2 || parts.size() > 3 || (parts[0] != "1" && parts[0] != "2" && parts[0] != "3" && parts[0] != "4"))
      throw CLI::ValidationError("--derivative-weight", "expected K:BK[:AK] with K in 1..4, got '" + d + "'");
    const std::size_t k = static_cast<std::size_t>(parts[0][0] - '0');
    options.derivative_weight[k] = ranged_option(parts[1], "--derivative-weight", 0, inf, "a weight BK >= 0");
    if (parts.size() == 3)
      options.derivative_exponent[k] = ranged_option(parts[2], "--derivative-weight", 1, inf, "an exponent AK >= 1");
  }
  if (!o.tangents.empty() && !o.normals.empty())
    throw CLI::ValidationError("--tangents", "--tangents and --normals exclude each other (give a normal as a tangent)");
  if (!o.resolution.empty())
    options.resolution = ranged_option(o.resolution, "--resolution", 1e-300, fair::max_optimal_resolution,
                                       "a resolution in (0, 1e10] (pixels per extent; the cap: doc/optimal_curves.md)");
  if (!fair::io::try_parse_spelling(o.solver, options.solver))
    throw CLI::ValidationError("--solver", "expected " + fair::io::spellings_list<fair::Optimal_curve_solver>() +
                                               ", got '" + o.solver + "'");
  return options;
}

bool has_derivative_term(const fair::Optimal_curve_options& o) {
  for (std::size_t k = 1; k <= 4; ++k)
    if (o.derivative_weight[k] > 0) return true;
  return false;
}

/// The curve JSON of -o (fair::io::curve_to_json): the pieces of the spline through the optimal
/// polygon with its "bspline", the status and the solve report, the polygon and its data.
std::string curve_json(const fair::Optimal_curve_2<fair_curves::Kernel>& curve,
                       const fair::Polygon_quintic_fit<fair_curves::Kernel>* quintic) {
  const nlohmann::json extra = fair::io::optimal_curve_members(curve, quintic);
  std::ostringstream out;
  // "bspline": the C2 runs between corners as one NURBS with triple knots at the corners.
  fair::io::write_json(out, fair::io::family_to_json(curve, "optimal", extra));
  return out.str();
}

std::string summary(const Optimal_command_options& o, const fair::Optimal_curve_2<fair_curves::Kernel>& curve,
                    std::size_t points, double fit_distance) {
  using namespace fair_curves;
  const fair::Optimal_curve_report& r = curve.report();
  std::ostringstream s;
  s << o.input << ": optimal curve, " << (curve.options().closed ? "closed" : "open") << ", " << points << " points -> "
    << curve.polygon().size() << " vertices in " << r.levels.size() << " levels, " << r.iterations
    << " iterations, energy " << format_number(r.energy, 10) << ", spline fit within " << format_number(fit_distance, 3)
    << "; " << r.status << "\n";
  // Never a silent "converged" on a balloon (issue 25 §2): say when the curve swings out of its
  // data or crosses itself where the input polygon does not.
  if (r.extent_ratio > 1.5 || r.self_intersections > r.input_self_intersections)
    s << o.input << ": warning: the curve reaches " << format_number(r.extent_ratio, 3)
      << " times the extent of its points and has " << r.self_intersections << " self-intersection"
      << (r.self_intersections == 1 ? "" : "s") << " (the input polygon " << r.input_self_intersections
      << "): not a fair curve for these data and weights\n";
  return s.str();
}

void run_optimal(const Optimal_command_options& o) {
  using namespace fair_curves;
  fair::Optimal_curve_options options = curve_options(o);
  const fair::io::Point_file<Kernel> data = fair::io::read_point_file<Kernel>(o.input);
  options.closed = options.closed || data.closed;
  fair::io::check_point_file(data, options.closed ? 3 : 2, options.closed, "fair-curves optimal");
  const std::size_t n = data.points.size();
  if (!o.lambda_file.empty()) options.segment_lambda = fair::io::read_segment_lambdas(o.lambda_file, options.closed ? n : n - 1);
  std::vector<fair::io::Constraint_file> constraints;
  if (!o.tangents.empty()) constraints.push_back(fair::io::read_constraints(o.tangents, fair::Point_constraint_kind::TANGENT, n));
  if (!o.normals.empty()) constraints.push_back(fair::io::read_constraints(o.normals, fair::Point_constraint_kind::NORMAL, n));
  if (!o.corners.empty()) constraints.push_back(fair::io::read_constraints(o.corners, fair::Point_constraint_kind::CORNER, n));
  options.constraints = fair::io::merge_constraint_files(constraints);

  const fair::Optimal_curve_2<Kernel> curve(data.points, options);
  std::unique_ptr<fair::Polygon_quintic_fit<Kernel>> quintic;
  if (has_derivative_term(options))
    // The C4 quintic smoothing spline under the cubic's distance rule (issue 25 §3)
    quintic.reset(new fair::Polygon_quintic_fit<Kernel>(curve.quintic_spline()));
  const std::string json_text = o.json_out.empty() ? std::string() : curve_json(curve, quintic.get());
  std::string svg_text;
  if (!o.svg_out.empty()) {
    Curve_case c;
    c.title = o.input + ": optimal curve (" + fair::to_string(curve.report().status) + ")";
    c.title_in_figure = true;
    c.input_points = fair::io::to_xy(data.points);
    c.control_polygons = false;
    svg_text = make_curve_figures(curve.pieces(), c).curve_svg;
  }
  write_outputs(summary(o, curve, n, curve.spline().max_distance), o.json_out, json_text,
                export_files(curve.nurbs(), {{o.svg_out, svg_text}}));
  if (curve.report().status != fair::Optimal_curve_status::CONVERGED) {
    std::cerr << "fair-curves optimal: " << o.input << ": the solve is " << curve.report().status
              << " (outputs written; exit code " << not_converged_exit_code << ")\n";
    throw fair_curves::Exit_code{not_converged_exit_code};
  }
}

} // namespace

void register_optimal_command(CLI::App& app) {
  auto options = std::make_shared<Optimal_command_options>();
  CLI::App* sub = app.add_subcommand(
      "optimal", "Gumhold's optimal curve through a point file: the minimiser of int beta + beta_0 |kappa L0|^alpha_0 "
                 "(+ derivative terms) ds on an adaptive polygon, delivered with its C2 cubic spline");
  sub->add_option("input", options->input, "the point file (.csv, .txt or .json)")->required();
  sub->add_flag("--closed", options->closed, "closed curve (also set by JSON \"closed\")");
  sub->add_option("--lambda", options->lambda, "the trade-off of eq. 10 in [0, 1] (0: the polygon, 1: int kappa^2; default 0.7 unless --length-weight or --curvature-weight is given)");
  sub->add_option("--lambda-file", options->lambda_file, "one lambda_i in [0, 1] per input segment, one a line");
  sub->add_option("--length-weight", options->length_weight, "beta of eq. 5 (>= 0, default 1): the raw weights instead of the lambda design");
  sub->add_option("--curvature-weight", options->curvature_weight, "beta_0 of eq. 5 (>= 0, default 1): the raw weights instead of the lambda design");
  sub->add_option("--curvature-exponent", options->curvature_exponent, "alpha_0 of eq. 5 (>= 1, default 2)");
  sub->add_option("--derivative-weight", options->derivative_weights,
                  "K:BK[:AK]: the weight beta_K and exponent alpha_K (default 2) of the kappa^(K) term of eq. 5, K in 1..4 (repeatable)");
  sub->add_option("--tangents", options->tangents, "tangent constraints, lines 'i tx ty' (direction of travel)");
  sub->add_option("--normals", options->normals, "normal constraints, lines 'i nx ny' (left normal of the direction of travel)");
  sub->add_option("--corners", options->corners, "corners, lines 'i tx_in ty_in tx_out ty_out'");
  sub->add_option("--resolution", options->resolution, "rho: pixels per extent (twice the largest distance of a vertex from the centroid; > 0, default 500)");
  sub->add_option("--solver", options->solver, "newton (default) or cg (the paper's conjugate gradients)");
  sub->add_option("-o,--output", options->json_out, "write the curve and the report as JSON ('-': only JSON on stdout)");
  sub->add_option("--svg", options->svg_out, "draw the spline through the optimal polygon and its curvature comb");
  fair_curves::add_export_options(sub);
  sub->callback([options] { run_optimal(*options); });
}
FAIR_CURVES_COMMAND(register_optimal_command)
