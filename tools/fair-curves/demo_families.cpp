// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The gallery's first section (issue 25 §4): one real hand-drawn sketch solved by every family,
// side by side with their curvature combs on one scale, and the table of the shape figures of
// tools/fair-curves/family_comparison.h (the same code as test/test_real_data_families.cpp; the
// summary over all the real data is doc/real_data.md, "Every family on the same data").
// The drawing: Quick, Draw! "angel" key_id 6665588124418048 (Google, CC BY 4.0; the file
// test/data/real/quickdraw_angel.json, its origin in test/data/real/SOURCES.md), y negated (the
// data are y-down), consecutive repeats dropped, a stroke closed when it ends within 5 % of its
// size of its start -- the rules of test/kappa_real/data_sets.h.

#include "family_comparison.h"
#include "registry.h"
#include "tool_common.h"

#include <fair/io/svg.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace {

using fair_curves::Kernel;
using fair_curves::Point_2;

struct Stroke {
  std::vector<Point_2> points;
  bool closed = false;
};

std::vector<Stroke> angel() {
  // [x...], [y...] per stroke, as in the data file
  const std::vector<std::vector<std::vector<double>>> raw = {
      {{128, 116, 99, 87, 77, 75, 80, 90, 114, 130, 145, 147, 139}, {40, 36, 36, 42, 56, 73, 84, 91, 92, 85, 69, 50, 38}},
      {{89, 56, 19, 18, 23, 43, 85, 91, 93, 88, 78, 61, 25, 37, 53, 60, 69,
        86, 95, 113, 120, 163, 176, 193, 207, 209, 204, 148, 143, 205, 218, 219, 179, 129},
       {91, 124, 155, 159, 162, 163, 130, 127, 130, 153, 179, 207, 252, 252, 243, 242, 251,
        249, 255, 249, 251, 249, 255, 250, 252, 239, 224, 141, 123, 155, 155, 145, 112, 83}},
      {{109, 87, 69, 53, 52, 58, 82, 109, 144, 145, 139, 112, 99}, {0, 0, 8, 20, 24, 27, 28, 24, 13, 9, 7, 6, 11}},
      {{151, 150, 173, 197, 222, 225, 202, 194, 193}, {71, 65, 39, 26, 23, 34, 76, 103, 122}},
      {{76, 58, 33, 12, 5, 1, 1, 9, 57}, {80, 57, 35, 27, 28, 33, 48, 67, 139}}};
  std::vector<Stroke> out;
  for (const auto& s : raw) {
    Stroke k;
    double x0 = s[0][0], x1 = x0, y0 = -s[1][0], y1 = y0;
    for (std::size_t i = 0; i < s[0].size(); ++i) {
      const Point_2 p(s[0][i], -s[1][i]);
      if (k.points.empty() || k.points.back() != p) k.points.push_back(p);
      x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
    }
    const Point_2 &a = k.points.front(), &b = k.points.back();
    k.closed = k.points.size() >= 4 && std::hypot(b.x() - a.x(), b.y() - a.y()) <= 0.05 * std::hypot(x1 - x0, y1 - y0);
    if (k.closed && k.points.back() == k.points.front()) k.points.pop_back();
    out.push_back(k);
  }
  return out;
}

// Several SVG figures in one: `columns` per row, each at its own width (nested <svg> elements).
std::string side_by_side(const std::vector<std::string>& panels, std::size_t columns, double panel_width) {
  std::vector<double> heights;
  for (const std::string& p : panels) {
    const std::size_t h = p.find("height=\"");
    heights.push_back(std::stod(p.substr(h + 8)));
  }
  const std::size_t rows = (panels.size() + columns - 1) / columns;
  std::vector<double> row_top(rows + 1, 0);
  for (std::size_t r = 0; r < rows; ++r) {
    double h = 0;
    for (std::size_t c = 0; c < columns && r * columns + c < panels.size(); ++c) h = std::max(h, heights[r * columns + c]);
    row_top[r + 1] = row_top[r] + h;
  }
  const std::string W = fair::io::internal::px(panel_width * double(columns)), H = fair::io::internal::px(row_top[rows]);
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + W + "\" height=\"" + H + "\" viewBox=\"0 0 " + W +
                    " " + H + "\">\n<rect x=\"0\" y=\"0\" width=\"" + W + "\" height=\"" + H + "\" fill=\"white\"/>\n";
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const std::size_t r = i / columns, c = i % columns;
    out += "<svg x=\"" + fair::io::internal::px(panel_width * double(c)) + "\" y=\"" + fair::io::internal::px(row_top[r]) +
           "\"" + panels[i].substr(4);  // "<svg" + the panel's own attributes and content
  }
  return out + "</svg>\n";
}

void add_family_cases(fair_curves::Gallery& gallery) {
  gallery.add_section(
      "Every family on one real drawing",
      "One hand-drawn sketch (Quick, Draw! 'angel', 5 strokes, 78 points) through every family of the library, each at "
      "its defaults: the kappa-curve with unit and automatic weights, the Cardinal spline at its optimal alpha, the "
      "classic C2 spline (chordal), Catmull-Rom (centripetal), the csr-spline and the optimal curve. The panels show "
      "the longest stroke; its combs share one scale (the 95th percentile of the kappa-curve's curvature is 6 % of the "
      "stroke's diagonal); a red tooth with a dot is clipped at twice that length. The table is the drawing's worst stroke for the extent, and sums "
      "over its strokes for the counts (doc/real_data.md has the same figures over all the real data).");
  const std::vector<Stroke> strokes = angel();
  std::size_t points = 0, polygon_crossings = 0;
  for (const Stroke& s : strokes) {
    points += s.points.size();
    polygon_crossings += fair::internal::metrics::polygon_self_intersections(s.points, s.closed);
  }
  std::vector<std::string> panels;
  const Stroke& body = strokes[1];  // the longest stroke, 34 points
  const double comb_fraction = 0.06;
  double common_scale = 0;
  std::vector<fair::Sampled_curve> body_curves;
  fair_curves::Gallery_case g;
  g.title = "Quick, Draw! angel 6665588124418048, every family";
  g.table.push_back({"method", "outcome (per stroke)", "max extent ratio", "length / polygon", "median E L",
                     "inflections / point", "extrema / point", "self-intersections (polygon: " +
                     std::to_string(polygon_crossings) + ")", "ms"});
  for (const std::string& method : fair_curves::family_methods()) {
    double extent = 0, length = 0, polygon = 0;
    std::vector<double> EL;
    std::size_t inflections = 0, extrema = 0, crossings = 0, undecided = 0;
    std::string outcomes;
    const auto t0 = std::chrono::steady_clock::now();
    for (const Stroke& s : strokes) {
      const fair_curves::Family_row r = fair_curves::solve_family<Kernel>(method, s.points, s.closed);
      outcomes += (outcomes.empty() ? "" : ", ") + (r.solved ? r.outcome : std::string("rejected"));
      if (!r.solved) continue;
      extent = std::max(extent, r.extent_ratio);
      const double P = fair_curves::polygon_length(s.points, s.closed);
      length += r.length_ratio * P;
      polygon += P;
      EL.push_back(r.bending_EL);
      inflections += r.inflections, extrema += r.extrema;
      crossings += r.self_intersections.crossings, undecided += r.self_intersections.undecided;
    }
    const double ms = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::sort(EL.begin(), EL.end());
    g.table.push_back({method, outcomes, fair_curves::family_number(extent), fair_curves::family_number(length / polygon),
                       EL.empty() ? "-" : fair_curves::family_number(EL[EL.size() / 2]),
                       fair_curves::family_number(double(inflections) / double(points), 2),
                       fair_curves::family_number(double(extrema) / double(points), 2),
                       std::to_string(crossings) + (undecided ? " (+" + std::to_string(undecided) + " undecided)" : ""),
                       fair_curves::family_number(ms, 3)});
    // The panel: the longest stroke alone (the whole drawing's combs overlap each other), its comb
    // on the scale of the kappa-curve's (w = 1), whose 95th-percentile tooth is 6 % of the diagonal.
    const fair::Sampled_curve body_curve = fair_curves::sample_family<Kernel>(method, body.points, body.closed);
    fair::io::Svg_figure figure(400);
    figure.set_title(method);
    if (common_scale == 0) common_scale = fair::io::Svg_figure().add_curvature_comb(body_curve, 0, comb_fraction);
    figure.add_curvature_comb(body_curve, common_scale, comb_fraction);
    figure.add_curve(body_curve);
    figure.add_points(fair::io::to_xy(body.points), "#111111");
    panels.push_back(figure.str());
    body_curves.push_back(body_curve);
  }
  g.caption = "Each panel: one family through the drawing's longest stroke (its 34 points in black), its curve (blue) "
              "and curvature comb (orange; clipped teeth red), the combs on one scale. The table covers all 5 strokes "
              "(78 points). Extent ratio: diagonal of the curve's bounding box over the points'; E L: bending "
              "energy times length (scale free, 4 pi^2 for a circle); inflections and curvature extrema certified "
              "(fair/Fairness_metrics.h) per input point; self-intersections certified "
              "(internal/metrics/self_intersections.h). The optimal curve is at the defaults of the build.";
  g.images = {{"every family side by side", side_by_side(panels, 2, 400)}};
  // The same stroke's curvature for every family (the second figure of the case).
  std::vector<std::string> plots;
  for (std::size_t m = 0; m < body_curves.size(); ++m)
    plots.push_back(fair::io::curvature_plot_svg(body_curves[m], {}, fair_curves::family_methods()[m] +
                                                 ": curvature of the body stroke (34 points)", 400, 200));
  g.images.push_back({"curvature of the longest stroke", side_by_side(plots, 2, 400)});
  gallery.add_case(std::move(g));
}

} // namespace

FAIR_CURVES_DEMO(1, add_family_cases)
