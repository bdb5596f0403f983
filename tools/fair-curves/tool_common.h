// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Helpers shared by the subcommands and the demo cases of fair-curves: strict parsing of
// option values, and figures (curve + curvature plot + measured figures) for any curve made
// of CurvePiece_2 pieces.

#ifndef FAIR_CURVES_TOOL_COMMON_H
#define FAIR_CURVES_TOOL_COMMON_H

#include "export_options.h"
#include "gallery.h"

#include <fair/Cubic_spline_2.h>
#include <fair/Curve_sampling.h>
#include <fair/Errors.h>
#include <fair/io/parsing.h>
#include <fair/io/svg.h>

#include <CGAL/Simple_cartesian.h>

#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace fair_curves {

/// The kernel of the program: points typed on the command line or read from files are doubles.
typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_2 Point_2;

/// The double nearest to pi, for the program's cases (once: the program may be built as unity
/// translation units, where two file-local definitions would clash).
constexpr double pi = 3.14159265358979323846;

/// The spline in double, for drawing.
template <class K>
fair::Cubic_spline_2<Kernel> to_double_spline(const fair::Cubic_spline_2<K>& s) {
  std::vector<double> t, w;
  std::vector<Point_2> p;
  for (const auto& x : s.breakpoints()) t.push_back(CGAL::to_double(x));
  for (const auto& x : s.weights()) w.push_back(CGAL::to_double(x));
  for (const auto& x : s.control_points()) p.push_back(Point_2(CGAL::to_double(x.x()), CGAL::to_double(x.y())));
  return fair::Cubic_spline_2<Kernel>(t, p, w, s.is_closed());
}

/// Writes what a subcommand computed, only once everything has been computed (a failure leaves
/// no partial output): the text report on stdout unless the JSON goes there (`-o -`: stdout
/// carries only the JSON, so that it can be piped), the JSON to stdout or to its file, and each
/// (file, text) of `files` whose file name is not empty.
inline void write_outputs(const std::string& report, const std::string& json_out, const std::string& json_text,
                          const std::vector<std::pair<std::string, std::string>>& files = {}) {
  if (json_out == "-") std::cout << json_text;
  else {
    std::cout << report;
    if (!json_out.empty()) fair::io::write_text_file(json_out, json_text);
  }
  for (const auto& file : files)
    if (!file.first.empty()) fair::io::write_text_file(file.first, file.second);
}

/// A finite number given as an option value; anything else is a usage error (exit code 2).
inline double option_number(const std::string& text, const std::string& option) {
  try {
    return fair::io::parse_number(text, option, 0, "value").value;
  } catch (const fair::Parse_error& e) {
    throw CLI::ValidationError(option, std::string(e.what()).substr(option.size() + 2));
  }
}

/// A point "x,y" given as an option value.
inline Point_2 option_point(const std::string& text, const std::string& option) {
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
    throw CLI::ValidationError(option, "expected a point \"x,y\", got '" + text + "'");
  return Point_2(option_number(text.substr(0, comma), option), option_number(text.substr(comma + 1), option));
}

/// A number for tables and captions: `digits` significant digits.
inline std::string format_number(double v, int digits = 6) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
  return buffer;
}

/// A point of a curve to highlight: piece index, parameter, label.
struct Curve_mark {
  std::size_t piece = 0;
  double t = 0;
  std::string label;
};

/// What to show for one curve.
struct Curve_case {
  std::string title, caption;
  bool title_in_figure = false;  ///< also print the title inside the curve figure
  std::vector<fair::io::Xy> input_points;
  std::vector<Curve_mark> marks;
  std::vector<std::pair<std::string, std::string>> measurements;
  std::size_t samples_per_piece = 96;
  bool comb = true;
  bool control_polygons = true;
};

/// The figures of a curve: the plane figure and the curvature plot, as SVG text.
struct Curve_figures {
  std::string curve_svg, curvature_svg;
  fair::Sampled_curve sampled;
};

template <class PieceRange>
Curve_figures make_curve_figures(const PieceRange& pieces, const Curve_case& c) {
  Curve_figures out;
  out.sampled = fair::sample_curve(pieces, c.samples_per_piece);
  fair::io::Svg_figure figure;
  if (c.title_in_figure) figure.set_title(c.title);
  if (c.control_polygons) figure.add_control_polygons(pieces);
  if (c.comb) figure.add_curvature_comb(out.sampled);
  figure.add_curve(out.sampled);
  figure.add_points(c.input_points);
  std::vector<fair::io::Svg_mark> marks;
  std::vector<fair::io::Plot_mark> plot_marks;
  for (const Curve_mark& m : c.marks) {
    auto it = std::begin(pieces);
    // The marks come from the program's own cases: one off the curve is a bug of the program.
    FAIR_ASSERT_MSG(m.piece < out.sampled.number_of_pieces(), "make_curve_figures: mark on piece ", m.piece,
                    " of a curve of ", out.sampled.number_of_pieces(), " pieces");
    std::advance(it, static_cast<std::ptrdiff_t>(m.piece));
    typedef typename std::iterator_traits<decltype(it)>::value_type Piece;
    const auto p = it->point(typename Piece::FT(m.t));
    marks.push_back(fair::io::Svg_mark{CGAL::to_double(p.x()), CGAL::to_double(p.y()), m.label});
    const double s = out.sampled.piece_start[m.piece] + fair::piece_arc_length(*it, 0.0, m.t);
    plot_marks.push_back(fair::io::Plot_mark{s, it->curvature(m.t), m.label});
  }
  figure.add_marks(marks);
  out.curve_svg = figure.str();
  out.curvature_svg = fair::io::curvature_plot_svg(out.sampled, plot_marks);
  return out;
}

/// A gallery case: both figures, the caption and the measured figures (the curve's length is
/// added to the measurements).
template <class PieceRange>
fair_curves::Gallery_case make_gallery_case(const PieceRange& pieces, const Curve_case& c) {
  const Curve_figures f = make_curve_figures(pieces, c);
  fair_curves::Gallery_case g;
  g.title = c.title;
  g.caption = c.caption;
  g.images = {{"curve", f.curve_svg}, {"curvature", f.curvature_svg}};
  g.measurements = c.measurements;
  g.measurements.emplace_back("arc length (adaptive Gauss-Kronrod)", format_number(f.sampled.length(), 12));
  return g;
}

} // namespace fair_curves

#endif // FAIR_CURVES_TOOL_COMMON_H
