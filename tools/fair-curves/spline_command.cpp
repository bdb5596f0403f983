// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves spline: the classic baselines through (or, for bspline and quasi, near) a point
// file, each the library's family with its default options (doc/classic_interpolants.md):
//   cubic        fair::Cubic_interpolating_spline_2 (C2; --end natural | not-a-knot | clamped with
//                --start-derivative and --end-derivative; periodic when closed)
//   catmull-rom  fair::Catmull_rom_2 (uniform knots)
//   four-point   fair::Four_point_subdivision_2 (the interpolatory 4-point scheme, 5 rounds: a polyline)
//   quasi        fair::Cubic_quasi_interpolant_2
//   bspline      fair::Cubic_bspline_2 (the points as control points)
// Writes the curve JSON (fair::io::family_to_json: pieces and "bspline"), the figure, and the
// exports (--dxf, --svg-path: export_options.h).

#include "registry.h"
#include "tool_common.h"

#include <fair/Catmull_rom_2.h>
#include <fair/Cubic_bspline_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Cubic_quasi_interpolant_2.h>
#include <fair/Four_point_subdivision_2.h>
#include <fair/io/read_points.h>
#include <fair/io/write_json.h>

#include <memory>
#include <sstream>
#include <string>

namespace {

struct Spline_command_options {
  std::string input, method, end = "natural", start_derivative, end_derivative, json_out, svg_out;
  bool closed = false;
};

template <class Curve>
void write_curve(const Spline_command_options& o, const fair::io::Point_file<fair_curves::Kernel>& data,
                 const Curve& curve) {
  using namespace fair_curves;
  std::string json_text, svg_text;
  if (!o.json_out.empty()) {
    std::ostringstream out;
    const nlohmann::json extra = o.method == "cubic" && !curve.is_closed() ? nlohmann::json{{"end", o.end}}
                                                                           : nlohmann::json::object();
    fair::io::write_json(out, fair::io::family_to_json(curve, o.method, extra));
    json_text = out.str();
  }
  if (!o.svg_out.empty()) {
    Curve_case c;
    c.title = o.input + ": " + o.method + (curve.is_closed() ? ", closed" : "");
    c.title_in_figure = true;
    c.input_points = fair::io::to_xy(data.points);
    svg_text = make_curve_figures(curve.pieces(), c).curve_svg;
  }
  std::ostringstream report;
  report << o.input << ": " << o.method << ", " << data.points.size() << " points, "
         << (curve.is_closed() ? "closed" : "open") << ", " << curve.number_of_pieces() << " pieces of degree "
         << curve.nurbs().degree() << "\n";
  write_outputs(report.str(), o.json_out, json_text, export_files(curve.nurbs(), {{o.svg_out, svg_text}}));
}

void run_spline(const Spline_command_options& o) {
  using namespace fair_curves;
  // usage first (exit 2): the end condition and its derivatives
  const bool clamped = o.end == "clamped";
  if (o.end != "natural" && o.end != "not-a-knot" && !clamped)
    throw CLI::ValidationError("--end", "expected natural, not-a-knot or clamped, got '" + o.end + "'");
  if (o.end != "natural" && o.method != "cubic") throw CLI::ValidationError("--end", "applies to --method cubic only");
  if (clamped != (!o.start_derivative.empty() || !o.end_derivative.empty()) ||
      (clamped && (o.start_derivative.empty() || o.end_derivative.empty())))
    throw CLI::ValidationError("--start-derivative/--end-derivative", "give both with --end clamped, and only then");
  Point_2 d0, d1;
  if (clamped) {
    d0 = option_point(o.start_derivative, "--start-derivative");
    d1 = option_point(o.end_derivative, "--end-derivative");
  }
  const fair::io::Point_file<Kernel> data = fair::io::read_point_file<Kernel>(o.input);
  const bool closed = o.closed || data.closed;
  if (clamped && closed) throw CLI::ValidationError("--end", "a closed spline has no ends");
  const std::size_t minimum = o.method == "four-point" ? (closed ? 3 : 4) : (closed ? 3 : 2);
  fair::io::check_point_file(data, minimum, closed, "fair-curves spline");
  if (o.method == "cubic") {
    fair::Cubic_interpolating_spline_options options;
    options.closed = closed;
    options.end_condition = o.end == "not-a-knot" ? fair::Spline_end_condition::NOT_A_KNOT : fair::Spline_end_condition::NATURAL;
    if (clamped)
      write_curve(o, data, fair::Cubic_interpolating_spline_2<Kernel>(data.points, d0 - CGAL::ORIGIN, d1 - CGAL::ORIGIN, options));
    else write_curve(o, data, fair::Cubic_interpolating_spline_2<Kernel>(data.points, options));
  } else if (o.method == "catmull-rom") {
    fair::Catmull_rom_options options;
    options.closed = closed;
    write_curve(o, data, fair::Catmull_rom_2<Kernel>(data.points, options));
  } else if (o.method == "four-point") {
    fair::Four_point_subdivision_options options;
    options.closed = closed;
    write_curve(o, data, fair::Four_point_subdivision_2<Kernel>(data.points, options));
  } else if (o.method == "quasi") {
    fair::Cubic_quasi_interpolant_options options;
    options.closed = closed;
    write_curve(o, data, fair::Cubic_quasi_interpolant_2<Kernel>(data.points, options));
  } else {
    fair::Cubic_bspline_options options;
    options.closed = closed;
    write_curve(o, data, fair::Cubic_bspline_2<Kernel>(data.points, options));
  }
}

} // namespace

void register_spline_command(CLI::App& app) {
  auto options = std::make_shared<Spline_command_options>();
  CLI::App* sub = app.add_subcommand(
      "spline", "The classic curves through a point file: C2 cubic interpolating spline, Catmull-Rom, the 4-point "
                "scheme, the cubic quasi-interpolant and the uniform cubic B-spline of the points");
  sub->add_option("input", options->input, "the point file (.csv, .txt or .json)")->required();
  sub->add_option("--method", options->method, "cubic, catmull-rom, four-point, quasi or bspline")
      ->required()
      ->check(CLI::IsMember({"cubic", "catmull-rom", "four-point", "quasi", "bspline"}));
  sub->add_flag("--closed", options->closed, "closed (periodic) curve (also set by JSON \"closed\")");
  sub->add_option("--end", options->end, "cubic, open: natural (default), not-a-knot or clamped");
  sub->add_option("--start-derivative", options->start_derivative, "with --end clamped: c'(u_0) \"x,y\"");
  sub->add_option("--end-derivative", options->end_derivative, "with --end clamped: c'(u_n) \"x,y\"");
  sub->add_option("-o,--output", options->json_out, "write the curve (pieces and \"bspline\") as JSON ('-': only JSON on stdout)");
  sub->add_option("--svg", options->svg_out, "draw the curve, its control polygons and curvature comb");
  fair_curves::add_export_options(sub);
  sub->callback([options] { run_spline(*options); });
}
FAIR_CURVES_COMMAND(register_spline_command)
