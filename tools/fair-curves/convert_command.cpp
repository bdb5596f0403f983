// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves convert: a curve file written earlier by any command (its "bspline" member, read
// by fair::io::read_nurbs_json: typed Parse_error for a missing or malformed one) to the other
// formats: --dxf (write_dxf.h), --svg (the figure) and --svg-path (write_svg_path.h).

#include "registry.h"
#include "tool_common.h"

#include <fair/io/read_nurbs.h>

#include <memory>
#include <sstream>
#include <string>

namespace {

struct Convert_options {
  std::string curve, svg_out;
};

void run_convert(const Convert_options& o) {
  using namespace fair_curves;
  const fair::Nurbs_curve_2<Kernel> c = fair::io::read_nurbs_json<Kernel>(o.curve);
  std::string svg_text;
  if (!o.svg_out.empty()) {
    Curve_case figure;
    figure.title = o.curve;
    figure.title_in_figure = true;
    svg_text = make_curve_figures(c.pieces(), figure).curve_svg;
  }
  std::ostringstream report;
  report << o.curve << ": NURBS of degree " << c.degree() << ", " << c.number_of_control_points()
         << " control points, " << c.knots().size() << " knots, " << c.number_of_pieces() << " pieces, "
         << (c.is_closed() ? "closed" : "open") << ", " << (c.is_rational() ? "rational" : "polynomial") << "\n";
  write_outputs(report.str(), "", "", export_files(c, {{o.svg_out, svg_text}}));
}

} // namespace

void register_convert_command(CLI::App& app) {
  auto options = std::make_shared<Convert_options>();
  CLI::App* sub = app.add_subcommand(
      "convert", "Convert a curve file written by fair-curves (its \"bspline\" member) to DXF, an SVG figure or an SVG path");
  sub->add_option("curve", options->curve, "the curve JSON (written with -o by any curve command)")->required();
  sub->add_option("--svg", options->svg_out, "draw the curve, its control polygons and curvature comb");
  fair_curves::add_export_options(sub);
  sub->callback([options] { run_convert(*options); });
}
FAIR_CURVES_COMMAND(register_convert_command)
