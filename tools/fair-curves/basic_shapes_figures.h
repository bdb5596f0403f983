// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Figures of a basic-shape design (fair-curves shapes and the gallery's basic-shape cases): the
// curve with its curvature comb, the merged spline's control polygon and the marked points, and
// the curvature plot.

#ifndef FAIR_CURVES_BASIC_SHAPES_FIGURES_H
#define FAIR_CURVES_BASIC_SHAPES_FIGURES_H

#include "tool_common.h"

#include <fair/Cubic_spline_2.h>
#include <fair/Spline_convexity.h>
#include <fair/io/svg.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <sstream>
#include <string>
#include <vector>

namespace fair_curves {

/// Proposition 1 (fair::spline_convexity) certified for the spline's own data: its breakpoints,
/// control points and weights taken exactly into EPECK, so that rounding in the pieces of a double
/// spline cannot decide the verdict (the double kernel's predicates are not exact).
template <class K>
fair::Spline_convexity_report<CGAL::Exact_predicates_exact_constructions_kernel> certified_convexity(
    const fair::Cubic_spline_2<K>& s) {
  typedef CGAL::Exact_predicates_exact_constructions_kernel E;
  std::vector<E::FT> t, w;
  std::vector<E::Point_2> p;
  for (const auto& x : s.breakpoints()) t.push_back(E::FT(x));
  for (const auto& x : s.weights()) w.push_back(E::FT(x));
  for (const auto& x : s.control_points()) p.push_back(E::Point_2(E::FT(x.x()), E::FT(x.y())));
  return fair::spline_convexity(fair::Cubic_spline_2<E>(t, p, w, s.is_closed()));
}

/// The curve figure (title, spline control polygon, comb, curve, marks) and the curvature plot.
inline Curve_figures design_figures(const fair::Cubic_spline_2<Kernel>& spline, const std::vector<fair::io::Xy>& marks,
                                    const std::string& title, std::size_t samples_per_piece = 64) {
  Curve_figures out;
  out.sampled = fair::sample_curve(spline.pieces(), samples_per_piece);
  fair::io::Svg_figure figure;
  figure.set_title(title);
  std::vector<fair::io::Xy> polygon = fair::io::to_xy(spline.control_points());
  if (spline.is_closed()) polygon.push_back(polygon.front());
  figure.add_control_polygon(polygon);
  figure.add_curvature_comb(out.sampled);
  figure.add_curve(out.sampled);
  figure.add_points(marks);
  out.curve_svg = figure.str();
  out.curvature_svg = fair::io::curvature_plot_svg(out.sampled);
  return out;
}

/// Two SVG figures of fair/io/svg.h one above the other in one SVG document (nested <svg>).
inline std::string stack_svg(const std::string& top, const std::string& bottom, double width = 720) {
  auto height = [](const std::string& svg) {
    const std::size_t at = svg.find("height=\"");
    FAIR_ASSERT_MSG(at != std::string::npos, "stack_svg: no height in the figure");
    return std::stod(svg.substr(at + 8));
  };
  const double h1 = height(top), h2 = height(bottom);
  auto placed = [](const std::string& svg, double y) {
    return "<svg x=\"0\" y=\"" + format_number(y, 10) + "\"" + svg.substr(4);
  };
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << h1 + h2
      << "\" viewBox=\"0 0 " << width << " " << h1 + h2 << "\">\n"
      << placed(top, 0) << placed(bottom, h1) << "</svg>\n";
  return out.str();
}

} // namespace fair_curves

#endif // FAIR_CURVES_BASIC_SHAPES_FIGURES_H
