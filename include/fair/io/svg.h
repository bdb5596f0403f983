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

namespace internal {

/// A pixel coordinate with two decimals.
inline std::string px(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.2f", v);
  return buffer;
}

/// A short human-readable number (4 significant digits), for tick labels and captions.
inline std::string short_number(double v, int digits = 4) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, v == 0 ? 0.0 : v);
  return buffer;
}

inline void require_finite(double v, const char* what) {
  if (!std::isfinite(v))
    throw Precondition_error(fair::internal::message("fair::io SVG: refusing the non-finite ", what, " ", v));
}

/// An axis-aligned box growing to include points.
struct Box {
  double xmin = std::numeric_limits<double>::infinity(), xmax = -std::numeric_limits<double>::infinity();
  double ymin = std::numeric_limits<double>::infinity(), ymax = -std::numeric_limits<double>::infinity();
  bool empty() const { return !(xmin <= xmax); }
  void add(double x, double y) {
    xmin = std::min(xmin, x); xmax = std::max(xmax, x);
    ymin = std::min(ymin, y); ymax = std::max(ymax, y);
  }
};

/// Maps world coordinates into [margin, width - margin] x [margin, height - margin] with one
/// scale for both axes (y up), fitted to a box. See the robustness note at the top.
class View {
public:
  View() = default;
  View(const Box& box, double width, double height, double margin)
    : w_(width), h_(height) {
    if (box.empty()) {
      cx_ = cy_ = 0;
      half_ = 1;
    } else {
      cx_ = 0.5 * box.xmin + 0.5 * box.xmax;
      cy_ = 0.5 * box.ymin + 0.5 * box.ymax;
      const double hx = 0.5 * box.xmax - 0.5 * box.xmin, hy = 0.5 * box.ymax - 0.5 * box.ymin;
      half_ = std::max(hx, hy);
      if (!(half_ > 0)) {
        // A single point: show a neighbourhood proportional to its magnitude.
        const double mag = std::max(std::abs(cx_), std::abs(cy_));
        half_ = mag > 0 ? mag * 1e-3 : 1.0;
        sx_ = sy_ = 1;
      } else {
        sx_ = hx / half_;
        sy_ = hy / half_;
      }
    }
    const double pw = 0.5 * width - margin, ph = 0.5 * height - margin;
    // Pixels per normalised unit: the larger normalised extent fills its pixel extent.
    k_ = std::min(sx_ > 0 ? pw / sx_ : std::numeric_limits<double>::infinity(),
                  sy_ > 0 ? ph / sy_ : std::numeric_limits<double>::infinity());
    if (!std::isfinite(k_)) k_ = std::min(pw, ph);
  }
  double x(double wx) const { return clamp(0.5 * w_ + (wx - cx_) / half_ * k_, w_); }
  double y(double wy) const { return clamp(0.5 * h_ - (wy - cy_) / half_ * k_, h_); }
  /// Pixels per world unit, as a normalised pair (useful for lengths): length_px = l / half * k.
  double length(double world_length) const { return world_length / half_ * k_; }

private:
  static double clamp(double v, double hi) { return std::min(std::max(v, 0.0), hi); }
  double w_ = 1, h_ = 1, cx_ = 0, cy_ = 0, half_ = 1, sx_ = 1, sy_ = 1, k_ = 1;
};

/// Aspect ratio (height / width) of a box, clamped to [lo, hi]; 1 for a degenerate box.
inline double aspect(const Box& b, double lo, double hi) {
  if (b.empty()) return 1;
  const double hx = 0.5 * b.xmax - 0.5 * b.xmin, hy = 0.5 * b.ymax - 0.5 * b.ymin;
  if (!(hx > 0)) return hi;
  return std::min(std::max(hy / hx, lo), hi);
}

/// "Nice" tick step (1, 2 or 5 times a power of ten) for about `count` ticks over `range`.
inline double nice_step(double range, int count) {
  const double raw = range / count;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / p;
  const double m = f < 1.5 ? 1 : (f < 3.5 ? 2 : (f < 7.5 ? 5 : 10));
  return m * p;
}

} // namespace internal

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
/// a zero line, and `marks` (e.g. curvature extrema) as rings.
inline std::string curvature_plot_svg(const Sampled_curve& curve,
                                      const std::vector<Plot_mark>& marks = {},
                                      const std::string& title = "curvature against arc length",
                                      double width = 720, double height = 280) {
  using internal::px;
  fair::internal::require(width >= 200 && height >= 120 && std::isfinite(width) && std::isfinite(height),
                    "curvature_plot_svg: figure too small (", width, " x ", height, ")");
  fair::internal::require(!curve.samples.empty(), "curvature_plot_svg: the curve has no samples");
  double kmin = 0, kmax = 0;
  for (const Curve_sample& s : curve.samples) {
    internal::require_finite(s.curvature, "curvature");
    internal::require_finite(s.arc_length, "arc length");
    kmin = std::min(kmin, s.curvature);
    kmax = std::max(kmax, s.curvature);
  }
  for (const Plot_mark& m : marks) {
    internal::require_finite(m.s, "mark arc length");
    internal::require_finite(m.kappa, "mark curvature");
    kmin = std::min(kmin, m.kappa);
    kmax = std::max(kmax, m.kappa);
  }
  double length = curve.length();
  if (!(length > 0)) length = 1;
  // Half-range arithmetic avoids overflow for |kappa| near DBL_MAX.
  double khalf = 0.5 * kmax - 0.5 * kmin;
  if (!(khalf > 0)) khalf = 1;  // straight curve: kappa = 0 everywhere
  double kmid = 0.5 * kmax + 0.5 * kmin;
  khalf *= 1.08;  // headroom
  const double left = 64, right = 16, top = 26, bottom = 34;
  const double pw = width - left - right, ph = height - top - bottom;
  auto X = [&](double s) { return left + std::min(std::max(s / length, 0.0), 1.0) * pw; };
  auto Y = [&](double k) {
    const double u = (k - kmid) / khalf;  // in [-1, 1]
    return top + (0.5 - 0.5 * std::min(std::max(u, -1.0), 1.0)) * ph;
  };
  std::string out;
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(width) + "\" height=\"" + px(height) +
         "\" viewBox=\"0 0 " + px(width) + " " + px(height) + "\">\n";
  out += "<rect x=\"0\" y=\"0\" width=\"" + px(width) + "\" height=\"" + px(height) + "\" fill=\"white\"/>\n";
  out += "<text x=\"" + px(left) + "\" y=\"16\" font-family=\"sans-serif\" font-size=\"13\">" +
         xml_escape(title) + "</text>\n";
  // Frame and ticks.
  out += "<rect x=\"" + px(left) + "\" y=\"" + px(top) + "\" width=\"" + px(pw) + "\" height=\"" + px(ph) +
         "\" fill=\"none\" stroke=\"#444\" stroke-width=\"0.8\"/>\n";
  const double sstep = internal::nice_step(length, 6);
  for (int i = 0; i <= 40; ++i) {
    const double s = i * sstep;
    if (s > length * (1 + 1e-9)) break;
    out += "<line x1=\"" + px(X(s)) + "\" y1=\"" + px(top + ph) + "\" x2=\"" + px(X(s)) + "\" y2=\"" +
           px(top + ph + 4) + "\" stroke=\"#444\" stroke-width=\"0.8\"/>\n";
    out += "<text x=\"" + px(X(s)) + "\" y=\"" + px(top + ph + 16) +
           "\" font-family=\"sans-serif\" font-size=\"10\" text-anchor=\"middle\">" +
           internal::short_number(s) + "</text>\n";
  }
  out += "<text x=\"" + px(left + pw) + "\" y=\"" + px(height - 4) +
         "\" font-family=\"sans-serif\" font-size=\"11\" text-anchor=\"end\">arc length s</text>\n";
  const double klo = kmid - khalf, khi = kmid + khalf;
  const double kstep = internal::nice_step(2 * khalf, 5);
  if (std::isfinite(kstep) && kstep > 0) {
    const double first = std::ceil(klo / kstep);
    for (int i = 0; i <= 40; ++i) {
      const double k = (first + i) * kstep;
      if (k > khi) break;
      out += "<line x1=\"" + px(left - 4) + "\" y1=\"" + px(Y(k)) + "\" x2=\"" + px(left) + "\" y2=\"" +
             px(Y(k)) + "\" stroke=\"#444\" stroke-width=\"0.8\"/>\n";
      out += "<text x=\"" + px(left - 6) + "\" y=\"" + px(Y(k) + 3) +
             "\" font-family=\"sans-serif\" font-size=\"10\" text-anchor=\"end\">" +
             internal::short_number(std::abs(k) < 1e-12 * kstep ? 0.0 : k) + "</text>\n";
    }
  }
  out += "<text x=\"12\" y=\"" + px(top + 0.5 * ph) + "\" font-family=\"sans-serif\" font-size=\"11\" "
         "transform=\"rotate(-90 12 " + px(top + 0.5 * ph) + ")\" text-anchor=\"middle\">curvature</text>\n";
  // Zero line and joins.
  if (klo <= 0 && 0 <= khi)
    out += "<line x1=\"" + px(left) + "\" y1=\"" + px(Y(0)) + "\" x2=\"" + px(left + pw) + "\" y2=\"" +
           px(Y(0)) + "\" stroke=\"#bbb\" stroke-width=\"0.8\"/>\n";
  for (std::size_t j = 1; j + 1 < curve.piece_start.size(); ++j)
    out += "<line x1=\"" + px(X(curve.piece_start[j])) + "\" y1=\"" + px(top) + "\" x2=\"" +
           px(X(curve.piece_start[j])) + "\" y2=\"" + px(top + ph) +
           "\" stroke=\"#7a7a7a\" stroke-width=\"0.8\" stroke-dasharray=\"3 3\"/>\n";
  // One polyline per piece.
  std::string points;
  for (std::size_t i = 0; i < curve.samples.size(); ++i) {
    const Curve_sample& s = curve.samples[i];
    if (!points.empty()) points += ' ';
    points += px(X(s.arc_length)) + "," + px(Y(s.curvature));
    const bool last = i + 1 == curve.samples.size() || curve.samples[i + 1].piece != s.piece;
    if (last) {
      out += "<polyline fill=\"none\" stroke=\"#1f4e9c\" stroke-width=\"1.6\" points=\"" + points + "\"/>\n";
      points.clear();
    }
  }
  for (const Plot_mark& m : marks) {
    out += "<circle cx=\"" + px(X(m.s)) + "\" cy=\"" + px(Y(m.kappa)) +
           "\" r=\"4.5\" fill=\"none\" stroke=\"#c0392b\" stroke-width=\"2\"/>\n";
    if (!m.label.empty()) {
      const bool to_left = X(m.s) > left + 0.75 * pw;
      // Above the ring, or below it when the ring is near the top of the frame.
      const double label_y = Y(m.kappa) - 7 < top + 12 ? Y(m.kappa) + 16 : Y(m.kappa) - 7;
      out += "<text x=\"" + px(to_left ? X(m.s) - 7 : X(m.s) + 7) + "\" y=\"" + px(label_y) +
             "\" font-family=\"sans-serif\" font-size=\"10\" fill=\"#c0392b\"" +
             (to_left ? " text-anchor=\"end\"" : "") + ">" + xml_escape(m.label) + "</text>\n";
    }
  }
  out += "</svg>\n";
  return out;
}

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

#endif // FAIR_IO_SVG_H
