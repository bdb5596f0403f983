// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves optimal: Gumhold's optimal curve through a point file (fair::Optimal_curve_2,
// issue 11; doc/optimal_curves.md), delivered as the optimal polygon and the C2 cubic spline
// through it (fair::fit_cubic_spline_runs: C2 between corners, G0 at them; with a derivative term k >= 1 also the C4 quintic). The
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
#include <fair/io/read_points.h>
#include <fair/io/svg.h>
#include <fair/io/write_json.h>

#include <cmath>
#include <fstream>
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

/// The whitespace-separated fields of the lines of `file` ('#' starts a comment, blank lines
/// are skipped), each with its 1-based line number. Parse_error if the file cannot be read.
std::vector<std::pair<std::size_t, std::vector<std::string>>> read_fields(const std::string& file, const char* what) {
  std::ifstream in(file);
  if (!in) throw fair::Parse_error(file, 0, std::string("cannot open the ") + what);
  std::vector<std::pair<std::size_t, std::vector<std::string>>> out;
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream in_line(line);
    std::vector<std::string> fields;
    for (std::string f; in_line >> f;) fields.push_back(f);
    if (!fields.empty()) out.emplace_back(number, std::move(fields));
  }
  return out;
}

/// A finite number in a data file (Parse_error naming FILE:LINE otherwise).
double file_number(const std::string& text, const std::string& file, std::size_t line) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || used == 0 || !std::isfinite(v))
    throw fair::Parse_error(file, line, "expected a finite number, got '" + text + "'");
  return v;
}

/// The lambda_i of --lambda-file: one number in [0, 1] per line, one line per input segment
/// (n - 1 open, n closed).
std::vector<double> read_lambdas(const std::string& file, std::size_t segments) {
  std::vector<double> out;
  for (const auto& l : read_fields(file, "lambda file")) {
    if (l.second.size() != 1)
      throw fair::Parse_error(file, l.first, "expected one lambda per line, got " + std::to_string(l.second.size()) +
                                                 " fields");
    const double v = file_number(l.second[0], file, l.first);
    if (!(v >= 0 && v <= 1)) throw fair::Parse_error(file, l.first, "lambda " + l.second[0] + " is not in [0, 1]");
    out.push_back(v);
  }
  if (out.size() != segments)
    throw fair::Parse_error(file, 0, "expected one lambda per input segment: " + std::to_string(segments) +
                                         " lines, got " + std::to_string(out.size()));
  return out;
}

/// Constraints from a file of lines "i x y" (TANGENT, NORMAL) or "i tx_in ty_in tx_out ty_out"
/// (CORNER); i a 0-based input index < points.
void read_constraints(const std::string& file, fair::Point_constraint_kind kind, std::size_t points,
                      std::vector<fair::Point_constraint>& out, std::vector<std::size_t>& seen_line,
                      std::vector<std::string>& seen_file) {
  const bool corner = kind == fair::Point_constraint_kind::CORNER;
  const std::size_t fields = corner ? 5 : 3;
  const char* layout = corner ? "i tx_in ty_in tx_out ty_out" : (kind == fair::Point_constraint_kind::TANGENT ? "i tx ty" : "i nx ny");
  for (const auto& l : read_fields(file, corner ? "corner file" : "constraint file")) {
    const std::vector<std::string>& f = l.second;
    if (f.size() != fields)
      throw fair::Parse_error(file, l.first, std::string("expected '") + layout + "', got " + std::to_string(f.size()) +
                                                 " fields");
    const double index = file_number(f[0], file, l.first);
    if (!(index >= 0) || index != std::floor(index))
      throw fair::Parse_error(file, l.first, "the point index '" + f[0] + "' is not an integer >= 0");
    if (index >= static_cast<double>(points))
      throw fair::Parse_error(file, l.first, "point index " + f[0] + " is out of range (the input has " +
                                                 std::to_string(points) + " points)");
    fair::Point_constraint c;
    c.index = static_cast<std::size_t>(index);
    c.kind = kind;
    c.direction = {{file_number(f[1], file, l.first), file_number(f[2], file, l.first)}};
    if (corner) c.outgoing = {{file_number(f[3], file, l.first), file_number(f[4], file, l.first)}};
    const bool zero = (c.direction[0] == 0 && c.direction[1] == 0) || (corner && c.outgoing[0] == 0 && c.outgoing[1] == 0);
    if (zero) throw fair::Parse_error(file, l.first, "a direction is the zero vector");
    if (seen_line[c.index])
      throw fair::Parse_error(file, l.first, "point " + f[0] + " is already constrained (" + seen_file[c.index] + ":" +
                                                 std::to_string(seen_line[c.index]) + ")");
    seen_line[c.index] = l.first;
    seen_file[c.index] = file;
    out.push_back(c);
  }
}

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
    options.resolution = ranged_option(o.resolution, "--resolution", 1e-300, inf, "a resolution > 0 (pixels)");
  if (o.solver == "cg") options.solver = fair::Optimal_curve_solver::CONJUGATE_GRADIENT;
  else if (o.solver != "newton") throw CLI::ValidationError("--solver", "expected newton or cg, got '" + o.solver + "'");
  return options;
}

bool has_derivative_term(const fair::Optimal_curve_options& o) {
  for (std::size_t k = 1; k <= 4; ++k)
    if (o.derivative_weight[k] > 0) return true;
  return false;
}

nlohmann::json xy(const fair_curves::Point_2& p) { return nlohmann::json::array({p.x(), p.y()}); }

std::string curve_json(const fair::Optimal_curve_2<fair_curves::Kernel>& curve,
                       const fair::Polygon_spline_runs<fair_curves::Kernel>& fit,
                       const fair::Polygon_quintic_fit<fair_curves::Kernel>* quintic) {
  const fair::Optimal_curve_report& r = curve.report();
  nlohmann::json levels = nlohmann::json::array(), polygon = nlohmann::json::array();
  for (const fair::Optimal_curve_level& l : r.levels)
    levels.push_back({{"vertices", l.vertices}, {"iterations", l.iterations}, {"energy", l.energy},
                      {"gradient_norm", l.gradient_norm}, {"status", fair::to_string(l.status)}});
  for (const fair_curves::Point_2& p : curve.polygon()) polygon.push_back(xy(p));
  nlohmann::json extra{{"method", "optimal"},
                       {"closed", curve.options().closed},
                       {"status", fair::to_string(r.status)},
                       {"energy", r.energy},
                       {"iterations", r.iterations},
                       {"gradient_norm", r.gradient_norm},
                       {"levels", levels},
                       {"polygon", polygon},
                       {"interpolation_indices", curve.interpolation_indices()},
                       {"curvatures", curve.curvatures()},
                       {"fit_max_distance", fit.max_distance}};
  if (quintic) {
    nlohmann::json pieces = nlohmann::json::array();
    for (const auto& piece : quintic->pieces) {
      nlohmann::json cp = nlohmann::json::array();
      for (const auto& p : piece.control_points()) cp.push_back(xy(p));
      pieces.push_back(cp);
    }
    extra["quintic"] = {{"degree", 5}, {"pieces", pieces}, {"max_distance", quintic->max_distance}};
  }
  std::ostringstream out;
  // The curve format of the fit's pieces with its "bspline" member: one spline, or (with corners)
  // the C2 runs between them as one NURBS with triple knots at the corners.
  nlohmann::json j = fair::io::curve_to_json(fit.pieces(), extra);
  j["bspline"] = fair::io::spline_runs_to_json(fit.splines, curve.options().closed);
  fair::io::write_json(out, j);
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
  return s.str();
}

void run_optimal(const Optimal_command_options& o) {
  using namespace fair_curves;
  fair::Optimal_curve_options options = curve_options(o);
  const fair::io::Point_file<Kernel> data = fair::io::read_point_file<Kernel>(o.input);
  options.closed = options.closed || data.closed;
  fair::io::check_point_file(data, options.closed ? 3 : 2, options.closed, "fair-curves optimal");
  const std::size_t n = data.points.size();
  if (!o.lambda_file.empty()) options.segment_lambda = read_lambdas(o.lambda_file, options.closed ? n : n - 1);
  std::vector<std::size_t> seen_line(n, 0);
  std::vector<std::string> seen_file(n);
  if (!o.tangents.empty())
    read_constraints(o.tangents, fair::Point_constraint_kind::TANGENT, n, options.constraints, seen_line, seen_file);
  if (!o.normals.empty())
    read_constraints(o.normals, fair::Point_constraint_kind::NORMAL, n, options.constraints, seen_line, seen_file);
  if (!o.corners.empty())
    read_constraints(o.corners, fair::Point_constraint_kind::CORNER, n, options.constraints, seen_line, seen_file);

  const fair::Optimal_curve_2<Kernel> curve(data.points, options);
  const fair::Polygon_spline_runs<Kernel> fit =
      fair::fit_cubic_spline_runs<Kernel>(curve.polygon(), options.closed, curve.corner_vertices());
  std::unique_ptr<fair::Polygon_quintic_fit<Kernel>> quintic;
  if (has_derivative_term(options))
    quintic.reset(new fair::Polygon_quintic_fit<Kernel>(fair::fit_quintic_spline<Kernel>(curve.polygon(), options.closed)));
  const std::string json_text = o.json_out.empty() ? std::string() : curve_json(curve, fit, quintic.get());
  std::string svg_text;
  if (!o.svg_out.empty()) {
    Curve_case c;
    c.title = o.input + ": optimal curve (" + fair::to_string(curve.report().status) + ")";
    c.title_in_figure = true;
    c.input_points = fair::io::to_xy(data.points);
    c.control_polygons = false;
    svg_text = make_curve_figures(fit.pieces(), c).curve_svg;
  }
  write_outputs(summary(o, curve, n, fit.max_distance), o.json_out, json_text, {{o.svg_out, svg_text}});
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
  sub->add_option("--lambda", options->lambda, "the trade-off of eq. 10 in [0, 1] (0: the polygon, 1: int kappa^2)");
  sub->add_option("--lambda-file", options->lambda_file, "one lambda_i in [0, 1] per input segment, one a line");
  sub->add_option("--length-weight", options->length_weight, "beta of eq. 5 (>= 0, default 1)");
  sub->add_option("--curvature-weight", options->curvature_weight, "beta_0 of eq. 5 (>= 0, default 1)");
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
  sub->callback([options] { run_optimal(*options); });
}
FAIR_CURVES_COMMAND(register_optimal_command)
