// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves points: read a point file (CSV or JSON), validate it as interpolation input, and
// write it back (JSON, CSV) or draw it (SVG). Every later method reads its input the same way.

#include "registry.h"
#include "tool_common.h"

#include <fair/io/read_points.h>
#include <fair/io/svg.h>
#include <fair/io/write_json.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace {

struct Points_options {
  std::string input, json_out, csv_out, svg_out;
  bool closed = false;
  std::size_t minimum = 2;
};

void run_points(const Points_options& o) {
  using namespace fair_curves;
  const fair::io::Point_file<Kernel> data = fair::io::read_point_file<Kernel>(o.input);
  const bool closed = o.closed || data.closed;
  fair::io::check_point_file(data, o.minimum, closed, "fair-curves points");

  std::string json_text, csv_text, svg_text;
  if (!o.json_out.empty()) {
    std::ostringstream out;
    fair::io::write_json(out, fair::io::points_to_json(data.points, closed));
    json_text = out.str();
  }
  if (!o.csv_out.empty()) {
    std::ostringstream out;
    fair::io::write_points_csv(out, data.points);
    csv_text = out.str();
  }
  if (!o.svg_out.empty()) {
    fair::io::Svg_figure figure;
    figure.set_title(o.input + ": " + std::to_string(data.points.size()) + " points" + (closed ? ", closed" : ""));
    std::vector<fair::io::Xy> polygon = fair::io::to_xy(data.points);
    if (closed) polygon.push_back(polygon.front());
    figure.add_polyline(polygon, "#9a9a9a", 0.8, "4 3");
    figure.add_points(fair::io::to_xy(data.points));
    svg_text = figure.str();
  }
  double xmin = data.points[0].x(), xmax = xmin, ymin = data.points[0].y(), ymax = ymin;
  for (const Point_2& p : data.points) {
    xmin = std::min(xmin, p.x()); xmax = std::max(xmax, p.x());
    ymin = std::min(ymin, p.y()); ymax = std::max(ymax, p.y());
  }
  std::ostringstream report;
  report << o.input << ": " << data.points.size() << " points, " << (closed ? "closed" : "open")
         << ", bounding box [" << format_number(xmin, 10) << ", " << format_number(xmax, 10) << "] x ["
         << format_number(ymin, 10) << ", " << format_number(ymax, 10) << "]\n";
  write_outputs(report.str(), o.json_out, json_text, {{o.csv_out, csv_text}, {o.svg_out, svg_text}});
}

} // namespace

void register_points_command(CLI::App& app) {
  auto options = std::make_shared<Points_options>();
  CLI::App* sub = app.add_subcommand(
      "points", "Read and validate a point file (CSV: one x,y per line; JSON: {\"points\": [[x,y],...]}), "
                "then write it back or draw it");
  sub->add_option("input", options->input, "the point file (.csv, .txt or .json)")->required();
  sub->add_flag("--closed", options->closed, "treat the points as a closed polygon (also set by JSON \"closed\")");
  sub->add_option("--min", options->minimum, "minimum number of points (default 2)")->check(CLI::Range(1, 1000000));
  sub->add_option("-o,--output", options->json_out, "write the points as JSON ('-': only the JSON on stdout)");
  sub->add_option("--csv", options->csv_out, "write the points as CSV");
  sub->add_option("--svg", options->svg_out, "draw the points");
  sub->callback([options] { run_points(*options); });
}
FAIR_CURVES_COMMAND(register_points_command)
