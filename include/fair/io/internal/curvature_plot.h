// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The definition of fair::io::curvature_plot_svg (fair/io/svg.h), one function per part of the
// figure: the curvature range, the frame mapping (s, kappa) to pixels, the axes, the zero line
// and piece joins, the curve and the marks. Each part returns its SVG text.

#ifndef FAIR_IO_INTERNAL_CURVATURE_PLOT_H
#define FAIR_IO_INTERNAL_CURVATURE_PLOT_H

#include <fair/Curve_sampling.h>
#include <fair/Errors.h>
#include <fair/io/internal/svg_layout.h>
#include <fair/io/svg.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace fair {
namespace io {
namespace internal {

// Margins of the plot area in pixels: room for the tick labels (left, bottom) and the title (top).
constexpr double plot_margin_left = 64, plot_margin_right = 16, plot_margin_top = 26, plot_margin_bottom = 34;
// The curvature axis spans 8% more than the data, so that extrema do not touch the frame.
constexpr double plot_curvature_headroom = 1.08;
// About how many ticks each axis gets (nice_step rounds the step to 1, 2 or 5 times 10^k).
constexpr int plot_arc_length_ticks = 6, plot_curvature_ticks = 5;
// More ticks than any "nice" step gives over its range: a guard against a degenerate step.
constexpr int plot_max_ticks = 40;
// A tick this close (relative) past the end of the arc is still drawn: it is the end, rounded.
constexpr double plot_end_tick_slack = 1e-9;
// A curvature tick within this fraction of a step from 0 is 0 (labelled "0", not "-1.2e-17").
constexpr double plot_zero_tick_fraction = 1e-12;

/// The smallest and largest curvature of the samples and the marks (0 included, so that the
/// zero line is always in range). Throws Precondition_error on a non-finite value.
struct Curvature_range {
  double kmin = 0, kmax = 0;
};

inline Curvature_range curvature_range(const Sampled_curve& curve, const std::vector<Plot_mark>& marks) {
  Curvature_range r;
  for (const Curve_sample& s : curve.samples) {
    require_finite(s.curvature, "curvature");
    require_finite(s.arc_length, "arc length");
    r.kmin = std::min(r.kmin, s.curvature);
    r.kmax = std::max(r.kmax, s.curvature);
  }
  for (const Plot_mark& m : marks) {
    require_finite(m.s, "mark arc length");
    require_finite(m.kappa, "mark curvature");
    r.kmin = std::min(r.kmin, m.kappa);
    r.kmax = std::max(r.kmax, m.kappa);
  }
  return r;
}

/// The plot area: arc length [0, length] left to right, curvature [kmid - khalf, kmid + khalf]
/// bottom to top; x() and y() clamp to the frame.
class Plot_frame {
public:
  Plot_frame(double width, double height, double curve_length, const Curvature_range& r)
    : width(width), height(height), pw(width - left - right), ph(height - top - bottom) {
    length = curve_length > 0 ? curve_length : 1;
    // Half-range arithmetic avoids overflow for |kappa| near DBL_MAX.
    khalf = 0.5 * r.kmax - 0.5 * r.kmin;
    if (!(khalf > 0)) khalf = 1;  // straight curve: kappa = 0 everywhere
    kmid = 0.5 * r.kmax + 0.5 * r.kmin;
    khalf *= plot_curvature_headroom;
  }
  double x(double s) const { return left + std::min(std::max(s / length, 0.0), 1.0) * pw; }
  double y(double k) const {
    const double u = (k - kmid) / khalf;  // in [-1, 1]
    return top + (0.5 - 0.5 * std::min(std::max(u, -1.0), 1.0)) * ph;
  }
  double klo() const { return kmid - khalf; }
  double khi() const { return kmid + khalf; }

  const double left = plot_margin_left, right = plot_margin_right, top = plot_margin_top, bottom = plot_margin_bottom;
  const double width, height, pw, ph;
  double length = 1, kmid = 0, khalf = 1;
};

/// The opening <svg> element, the white background and the title.
inline std::string plot_header(const Plot_frame& f, const std::string& title) {
  std::string out;
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(f.width) + "\" height=\"" + px(f.height) +
         "\" viewBox=\"0 0 " + px(f.width) + " " + px(f.height) + "\">\n";
  out += "<rect x=\"0\" y=\"0\" width=\"" + px(f.width) + "\" height=\"" + px(f.height) + "\" fill=\"white\"/>\n";
  out += "<text x=\"" + px(f.left) + "\" y=\"16\" font-family=\"sans-serif\" font-size=\"13\">" +
         xml_escape(title) + "</text>\n";
  return out;
}

/// The frame, the arc-length ticks and label (bottom), the curvature ticks and label (left).
inline std::string plot_axes(const Plot_frame& f) {
  std::string out;
  out += "<rect x=\"" + px(f.left) + "\" y=\"" + px(f.top) + "\" width=\"" + px(f.pw) + "\" height=\"" + px(f.ph) +
         "\" fill=\"none\" stroke=\"#444\" stroke-width=\"0.8\"/>\n";
  const double sstep = nice_step(f.length, plot_arc_length_ticks);
  for (int i = 0; i <= plot_max_ticks; ++i) {
    const double s = i * sstep;
    if (s > f.length * (1 + plot_end_tick_slack)) break;
    out += "<line x1=\"" + px(f.x(s)) + "\" y1=\"" + px(f.top + f.ph) + "\" x2=\"" + px(f.x(s)) + "\" y2=\"" +
           px(f.top + f.ph + 4) + "\" stroke=\"#444\" stroke-width=\"0.8\"/>\n";
    out += "<text x=\"" + px(f.x(s)) + "\" y=\"" + px(f.top + f.ph + 16) +
           "\" font-family=\"sans-serif\" font-size=\"10\" text-anchor=\"middle\">" + short_number(s) + "</text>\n";
  }
  out += "<text x=\"" + px(f.left + f.pw) + "\" y=\"" + px(f.height - 4) +
         "\" font-family=\"sans-serif\" font-size=\"11\" text-anchor=\"end\">arc length s</text>\n";
  const double kstep = nice_step(2 * f.khalf, plot_curvature_ticks);
  if (std::isfinite(kstep) && kstep > 0) {
    const double first = std::ceil(f.klo() / kstep);
    for (int i = 0; i <= plot_max_ticks; ++i) {
      const double k = (first + i) * kstep;
      if (k > f.khi()) break;
      out += "<line x1=\"" + px(f.left - 4) + "\" y1=\"" + px(f.y(k)) + "\" x2=\"" + px(f.left) + "\" y2=\"" +
             px(f.y(k)) + "\" stroke=\"#444\" stroke-width=\"0.8\"/>\n";
      out += "<text x=\"" + px(f.left - 6) + "\" y=\"" + px(f.y(k) + 3) +
             "\" font-family=\"sans-serif\" font-size=\"10\" text-anchor=\"end\">" +
             short_number(std::abs(k) < plot_zero_tick_fraction * kstep ? 0.0 : k) + "</text>\n";
    }
  }
  out += "<text x=\"12\" y=\"" + px(f.top + 0.5 * f.ph) + "\" font-family=\"sans-serif\" font-size=\"11\" "
         "transform=\"rotate(-90 12 " + px(f.top + 0.5 * f.ph) + ")\" text-anchor=\"middle\">curvature</text>\n";
  return out;
}

/// The zero line (when 0 is in range) and a dashed vertical line at each interior piece join.
inline std::string plot_zero_line_and_joins(const Plot_frame& f, const std::vector<double>& piece_start) {
  std::string out;
  if (f.klo() <= 0 && 0 <= f.khi())
    out += "<line x1=\"" + px(f.left) + "\" y1=\"" + px(f.y(0)) + "\" x2=\"" + px(f.left + f.pw) + "\" y2=\"" +
           px(f.y(0)) + "\" stroke=\"#bbb\" stroke-width=\"0.8\"/>\n";
  for (std::size_t j = 1; j + 1 < piece_start.size(); ++j)
    out += "<line x1=\"" + px(f.x(piece_start[j])) + "\" y1=\"" + px(f.top) + "\" x2=\"" + px(f.x(piece_start[j])) +
           "\" y2=\"" + px(f.top + f.ph) + "\" stroke=\"#7a7a7a\" stroke-width=\"0.8\" stroke-dasharray=\"3 3\"/>\n";
  return out;
}

/// The curvature of each piece as its own polyline, so that jumps at the joins show.
inline std::string plot_curvature_polylines(const Plot_frame& f, const Sampled_curve& curve) {
  std::string out, points;
  for (std::size_t i = 0; i < curve.samples.size(); ++i) {
    const Curve_sample& s = curve.samples[i];
    if (!points.empty()) points += ' ';
    points += px(f.x(s.arc_length)) + "," + px(f.y(s.curvature));
    const bool last = i + 1 == curve.samples.size() || curve.samples[i + 1].piece != s.piece;
    if (last) {
      out += "<polyline fill=\"none\" stroke=\"#1f4e9c\" stroke-width=\"1.6\" points=\"" + points + "\"/>\n";
      points.clear();
    }
  }
  return out;
}

/// The marks as rings with their labels, kept inside the frame.
inline std::string plot_marks(const Plot_frame& f, const std::vector<Plot_mark>& marks) {
  std::string out;
  for (const Plot_mark& m : marks) {
    out += "<circle cx=\"" + px(f.x(m.s)) + "\" cy=\"" + px(f.y(m.kappa)) +
           "\" r=\"4.5\" fill=\"none\" stroke=\"#c0392b\" stroke-width=\"2\"/>\n";
    if (!m.label.empty()) {
      const bool to_left = f.x(m.s) > f.left + 0.75 * f.pw;
      // Above the ring, or below it when the ring is near the top of the frame.
      const double label_y = f.y(m.kappa) - 7 < f.top + 12 ? f.y(m.kappa) + 16 : f.y(m.kappa) - 7;
      out += "<text x=\"" + px(to_left ? f.x(m.s) - 7 : f.x(m.s) + 7) + "\" y=\"" + px(label_y) +
             "\" font-family=\"sans-serif\" font-size=\"10\" fill=\"#c0392b\"" +
             (to_left ? " text-anchor=\"end\"" : "") + ">" + xml_escape(m.label) + "</text>\n";
    }
  }
  return out;
}

} // namespace internal

inline std::string curvature_plot_svg(const Sampled_curve& curve, const std::vector<Plot_mark>& marks,
                                      const std::string& title, double width, double height) {
  fair::internal::require(width >= 200 && height >= 120 && std::isfinite(width) && std::isfinite(height),
                          "curvature_plot_svg: figure too small (", width, " x ", height, ")");
  fair::internal::require(!curve.samples.empty(), "curvature_plot_svg: the curve has no samples");
  const internal::Plot_frame frame(width, height, curve.length(), internal::curvature_range(curve, marks));
  return internal::plot_header(frame, title) + internal::plot_axes(frame) +
         internal::plot_zero_line_and_joins(frame, curve.piece_start) +
         internal::plot_curvature_polylines(frame, curve) + internal::plot_marks(frame, marks) + "</svg>\n";
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_INTERNAL_CURVATURE_PLOT_H
