// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Self-contained SVG figures of curves (no external dependencies, no scripts, no fonts beyond
// the generic sans-serif):
//  - Svg_figure: the curve polyline, control polygons (thin grey), input points (dots),
//    marked points (e.g. certified curvature extrema, with labels) and a curvature comb;
//  - curvature_plot_svg: signed curvature against arc length, with axes, ticks, piece joins
//    (dashed) and marks.
//
// Robustness. Geometry is kept in world coordinates (double) and mapped to pixels only when the
// SVG text is produced, through a view fitted to everything drawn: the centre and the
// half-extents are computed as 0.5*max - 0.5*min (no overflow near DBL_MAX) and coordinates are
// normalised by the half-extent before scaling (no overflow or loss for extents near
// DBL_MIN), so curves with coordinates around 1e300 or 1e-300 draw like any other. Every
// number written is a finite pixel coordinate inside the view box; a non-finite input value
// throws fair::Precondition_error instead of producing "nan" in the output.

#ifndef FAIR_IO_SVG_H
#define FAIR_IO_SVG_H

#include <fair/Curve_sampling.h>
#include <fair/Errors.h>
#include <fair/io/internal/svg_layout.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace fair {
namespace io {

/// A point in double precision, in world coordinates.
struct Xy {
  double x = 0, y = 0;
};

/// A point to highlight, with an optional label (e.g. "max k=1.25").
struct Svg_mark {
  double x = 0, y = 0;
  std::string label;
};

/// `s` with & < > " ' replaced by their entities: safe as SVG/HTML character data and as a
/// quoted attribute value. Linear in the length of `s`.
inline std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

/// Converts any range of kernel points to double points.
template <class PointRange>
std::vector<Xy> to_xy(const PointRange& points) {
  std::vector<Xy> out;
  for (const auto& p : points) out.push_back(Xy{CGAL::to_double(p.x()), CGAL::to_double(p.y())});
  return out;
}

/// A figure of a curve in the plane. Add elements in world coordinates, then call str().
class Svg_figure {
public:
  /// A figure `width` pixels wide; its height follows the aspect ratio of the content
  /// (between 0.35 and 1.1 times the width).
  explicit Svg_figure(double width = 720) : width_(width) {
    fair::internal::require(width >= 100 && std::isfinite(width), "Svg_figure: width must be >= 100, got ", width);
  }

  void set_title(const std::string& title) { title_ = title; }

  /// The curve itself, one polyline per piece.
  void add_curve(const Sampled_curve& curve, const std::string& color = "#1f4e9c", double stroke = 2.0) {
    std::vector<Xy> line;
    for (std::size_t i = 0; i < curve.samples.size(); ++i) {
      const Curve_sample& s = curve.samples[i];
      line.push_back(Xy{s.x, s.y});
      const bool last = i + 1 == curve.samples.size() || curve.samples[i + 1].piece != s.piece;
      if (last) {
        add_polyline(line, color, stroke);
        line.clear();
      }
    }
  }

  /// A polyline in world coordinates.
  void add_polyline(const std::vector<Xy>& points, const std::string& color, double stroke,
                    const std::string& dash = std::string()) {
    for (const Xy& p : points) {
      internal::require_finite(p.x, "polyline x");
      internal::require_finite(p.y, "polyline y");
    }
    lines_.push_back(Line{points, color, stroke, dash, 1.0});
    for (const Xy& p : points) box_.add(p.x, p.y);
  }

  /// The control polygon of one piece (thin grey, with small squares at the control points).
  void add_control_polygon(const std::vector<Xy>& points) {
    add_polyline(points, "#9a9a9a", 0.8, "4 3");
    for (const Xy& p : points) squares_.push_back(p);
  }

  /// The control polygons of every piece of a curve.
  template <class PieceRange>
  void add_control_polygons(const PieceRange& pieces) {
    for (const auto& piece : pieces) add_control_polygon(to_xy(piece.control_points()));
  }

  /// Input (data) points, drawn as dots.
  void add_points(const std::vector<Xy>& points, const std::string& color = "#111111") {
    for (const Xy& p : points) {
      internal::require_finite(p.x, "point x");
      internal::require_finite(p.y, "point y");
      dots_.push_back(Dot{p, color, 3.2, std::string()});
      box_.add(p.x, p.y);
    }
  }

  /// Marked points (e.g. curvature extrema), drawn as rings with their labels.
  void add_marks(const std::vector<Svg_mark>& marks, const std::string& color = "#c0392b") {
    for (const Svg_mark& m : marks) {
      internal::require_finite(m.x, "mark x");
      internal::require_finite(m.y, "mark y");
      rings_.push_back(Dot{Xy{m.x, m.y}, color, 5.5, m.label});
      box_.add(m.x, m.y);
    }
  }

  /// A curvature comb: at each sample a tooth from c(t) to c(t) - kappa(t) * scale * n(t)
  /// (pointing away from the centre of curvature), and the envelope joining the tooth tips of
  /// each piece. With scale <= 0 the scale is chosen so that the longest tooth is
  /// `fraction` of the diagonal of the curve's bounding box. Returns the scale used (0 when
  /// the curve is straight, in which case no comb is drawn).
  double add_curvature_comb(const Sampled_curve& curve, double scale = 0, double fraction = 0.15) {
    double kmax = 0;
    internal::Box b;
    for (const Curve_sample& s : curve.samples) {
      internal::require_finite(s.curvature, "curvature");
      kmax = std::max(kmax, std::abs(s.curvature));
      b.add(s.x, s.y);
    }
    if (!(kmax > 0) || b.empty()) return 0;
    const double diag = std::hypot(0.5 * b.xmax - 0.5 * b.xmin, 0.5 * b.ymax - 0.5 * b.ymin) * 2;
    // Teeth are computed as (kappa / kmax) * (fraction * diag): bounded, no overflow.
    const double longest = scale > 0 ? kmax * scale : fraction * diag;
    fair::internal::require(std::isfinite(longest), "add_curvature_comb: non-finite comb length (scale = ",
                      scale, ", kmax = ", kmax, ")");
    std::vector<Xy> envelope;
    for (std::size_t i = 0; i < curve.samples.size(); ++i) {
      const Curve_sample& s = curve.samples[i];
      const double len = s.curvature / kmax * longest;
      const Xy tip{s.x - len * s.nx, s.y - len * s.ny};
      lines_.push_back(Line{{Xy{s.x, s.y}, tip}, "#e08a2c", 0.6, std::string(), 0.8});
      box_.add(tip.x, tip.y);
      envelope.push_back(tip);
      const bool last = i + 1 == curve.samples.size() || curve.samples[i + 1].piece != s.piece;
      if (last) {
        lines_.push_back(Line{envelope, "#e08a2c", 1.0, std::string(), 1.0});
        envelope.clear();
      }
    }
    return longest / kmax;
  }

  /// The SVG text.
  std::string str() const {
    const double width = width_;
    const double height = std::round(width * internal::aspect(box_, 0.35, 1.1));
    const double title_height = title_.empty() ? 0 : 22;
    const double margin = 16;
    // The view leaves room for the title at the top.
    internal::View view(box_, width, height - title_height, margin);
    std::string out;
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + internal::px(width) +
           "\" height=\"" + internal::px(height) + "\" viewBox=\"0 0 " + internal::px(width) + " " +
           internal::px(height) + "\">\n";
    out += "<rect x=\"0\" y=\"0\" width=\"" + internal::px(width) + "\" height=\"" +
           internal::px(height) + "\" fill=\"white\"/>\n";
    if (!title_.empty())
      out += "<text x=\"" + internal::px(margin) + "\" y=\"16\" font-family=\"sans-serif\" "
             "font-size=\"13\">" + xml_escape(title_) + "</text>\n";
    out += "<g transform=\"translate(0," + internal::px(title_height) + ")\">\n";
    for (const Line& l : lines_) {
      out += "<polyline fill=\"none\" stroke=\"" + l.color + "\" stroke-width=\"" +
             internal::px(l.stroke) + "\"";
      if (l.opacity < 1) out += " stroke-opacity=\"" + internal::px(l.opacity) + "\"";
      if (!l.dash.empty()) out += " stroke-dasharray=\"" + l.dash + "\"";
      out += " stroke-linejoin=\"round\" points=\"";
      for (std::size_t i = 0; i < l.points.size(); ++i) {
        if (i) out += ' ';
        out += internal::px(view.x(l.points[i].x)) + "," + internal::px(view.y(l.points[i].y));
      }
      out += "\"/>\n";
    }
    for (const Xy& p : squares_)
      out += "<rect x=\"" + internal::px(view.x(p.x) - 2) + "\" y=\"" + internal::px(view.y(p.y) - 2) +
             "\" width=\"4\" height=\"4\" fill=\"white\" stroke=\"#9a9a9a\" stroke-width=\"0.8\"/>\n";
    for (const Dot& d : dots_)
      out += "<circle cx=\"" + internal::px(view.x(d.p.x)) + "\" cy=\"" + internal::px(view.y(d.p.y)) +
             "\" r=\"" + internal::px(d.r) + "\" fill=\"" + d.color + "\"/>\n";
    for (const Dot& d : rings_) {
      const double x = view.x(d.p.x), y = view.y(d.p.y);
      out += "<circle cx=\"" + internal::px(x) + "\" cy=\"" + internal::px(y) + "\" r=\"" +
             internal::px(d.r) + "\" fill=\"none\" stroke=\"" + d.color + "\" stroke-width=\"2\"/>\n";
      if (!d.label.empty()) {
        // Keep the label inside the figure: right of the mark unless too close to the edge.
        const bool left = x > 0.75 * width;
        out += "<text x=\"" + internal::px(left ? x - 8 : x + 8) + "\" y=\"" + internal::px(y - 8) +
               "\" font-family=\"sans-serif\" font-size=\"11\" fill=\"" + d.color + "\"" +
               (left ? " text-anchor=\"end\"" : "") + ">" + xml_escape(d.label) + "</text>\n";
      }
    }
    out += "</g>\n</svg>\n";
    return out;
  }

  /// Writes str() to a file; throws fair::Error if it cannot.
  void write(const std::string& file) const {
    std::ofstream out(file);
    if (!out) throw Error("fair::io: cannot open " + file + " for writing");
    out << str();
    out.close();
    if (!out) throw Error("fair::io: error while writing " + file);
  }

private:
  struct Line {
    std::vector<Xy> points;
    std::string color;
    double stroke;
    std::string dash;
    double opacity;
  };
  struct Dot {
    Xy p;
    std::string color;
    double r;
    std::string label;
  };
  double width_;
  std::string title_;
  internal::Box box_;
  std::vector<Line> lines_;
  std::vector<Xy> squares_;
  std::vector<Dot> dots_, rings_;
};

/// A mark on the curvature plot: at arc length s, curvature kappa.
struct Plot_mark {
  double s = 0, kappa = 0;
  std::string label;
};

/// SVG plot of signed curvature against arc length: axes with ticks, the curvature of each
/// piece as its own polyline (so jumps at joins show), dashed vertical lines at the joins,
/// a zero line, and `marks` (e.g. curvature extrema) as rings. Linear in the number of samples
/// and marks. Throws Precondition_error if the figure is smaller than 200 x 120, the curve has
/// no samples, or a curvature, arc length or mark is not finite.
inline std::string curvature_plot_svg(const Sampled_curve& curve, const std::vector<Plot_mark>& marks = {},
                                      const std::string& title = "curvature against arc length",
                                      double width = 720, double height = 280);

/// Arc length at parameter t of piece `piece` of a sampled curve, by linear interpolation of the
/// samples (for placing marks on the curvature plot; error below the sampling resolution).
inline double arc_length_at(const Sampled_curve& curve, std::size_t piece, double t) {
  const Curve_sample* previous = nullptr;
  for (const Curve_sample& s : curve.samples) {
    if (s.piece != piece) continue;
    if (s.t >= t) {
      if (!previous || s.t == previous->t) return s.arc_length;
      const double u = (t - previous->t) / (s.t - previous->t);
      return previous->arc_length + u * (s.arc_length - previous->arc_length);
    }
    previous = &s;
  }
  fair::internal::require(previous != nullptr, "arc_length_at: no piece ", piece, " in the sampled curve");
  return previous->arc_length;
}

/// Writes SVG text to a file; throws fair::Error if it cannot.
inline void write_text_file(const std::string& file, const std::string& text) {
  std::ofstream out(file);
  if (!out) throw Error("fair::io: cannot open " + file + " for writing");
  out << text;
  out.close();
  if (!out) throw Error("fair::io: error while writing " + file);
}

} // namespace io
} // namespace fair

// The definition of curvature_plot_svg.
#include <fair/io/internal/curvature_plot.h>

#endif // FAIR_IO_SVG_H
