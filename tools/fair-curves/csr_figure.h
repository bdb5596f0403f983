// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The figures of a csr-spline, shared by `fair-curves csr` and the csr gallery cases: the curve
// with its curvature comb, its B-spline control polygon (not the Bezier polygons of the pieces)
// and the samples; and the curvature plot.

#ifndef FAIR_CURVES_CSR_FIGURE_H
#define FAIR_CURVES_CSR_FIGURE_H

#include "tool_common.h"

#include <fair/Csr_spline_2.h>
#include <fair/io/svg.h>

#include <string>
#include <vector>

namespace fair_curves {

template <class K>
Curve_figures csr_figures(const fair::Csr_spline_2<K>& csr, const std::string& title, bool title_in_figure) {
  // Sampled once here (not through make_curve_figures, whose own curve figure would be drawn and
  // thrown away: issue 29 #21, the memory of --svg).
  Curve_figures f;
  f.sampled = fair::sample_curve(csr.pieces(), Curve_case().samples_per_piece);
  f.curvature_svg = fair::io::curvature_plot_svg(f.sampled);
  fair::io::Svg_figure figure;
  if (title_in_figure) figure.set_title(title);
  std::vector<fair::io::Xy> polygon = fair::io::to_xy(csr.spline().control_points());
  if (csr.is_closed()) polygon.push_back(polygon.front());
  figure.add_control_polygon(polygon);
  figure.add_curvature_comb(f.sampled);
  figure.add_curve(f.sampled);
  figure.add_points(fair::io::to_xy(csr.points()));
  f.curve_svg = figure.str();
  return f;
}

} // namespace fair_curves

#endif // FAIR_CURVES_CSR_FIGURE_H
