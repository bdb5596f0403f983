// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Self-contained SVG figures of curves (no external dependencies, no scripts, no fonts beyond
// the generic sans-serif):
//  - Svg_figure: the curve polyline, control polygons (thin grey), input points (dots),
//    marked points (e.g. certified curvature extrema, with labels) and a curvature comb scaled
//    from a robust curvature (the 95th percentile) with its longest teeth clipped and marked;
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
//
// Memory (issue 29 #21). A figure keeps what it draws and nothing else: the points of its
// polylines, two points and a flag per comb tooth (all teeth of a comb are one <path>, not one
// element each), and the text is produced once, appended to one string allocated to its final
// size (str()) or streamed to a file (write()).

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
#include <ostream>
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
  /// each piece. With scale <= 0 the scale is robust (issue 25 §5): the 95th percentile of
  /// |kappa| over the samples (the largest |kappa| if that is 0) gets a tooth of `fraction` of the
  /// diagonal of the curve's bounding box, so that a few curvature spikes do not shrink the comb
  /// of the rest of the curve to nothing. Whatever the scale, a tooth longer than `comb_clip`
  /// times that reference length is clipped to it and marked (drawn in red, a dot at its tip):
  /// the comb never hides the curve. Returns the scale used (0 when the curve is straight, in
  /// which case no comb is drawn). At most max_comb_teeth teeth are drawn (every k-th sample); the
  /// envelope joins the tips at every sample. Linear in the samples; keeps 2 points and a flag per
  /// tooth drawn and one point per sample.
  double add_curvature_comb(const Sampled_curve& curve, double scale = 0, double fraction = comb_fraction) {
    double kmax = 0;
    internal::Box b;
    std::vector<double> magnitudes;
    magnitudes.reserve(curve.samples.size());
    for (const Curve_sample& s : curve.samples) {
      internal::require_finite(s.curvature, "curvature");
      kmax = std::max(kmax, std::abs(s.curvature));
      magnitudes.push_back(std::abs(s.curvature));
      b.add(s.x, s.y);
    }
    if (!(kmax > 0) || b.empty()) return 0;
    fair::internal::require(fraction > 0 && std::isfinite(fraction), "add_curvature_comb: fraction must be > 0, got ",
                            fraction);
    const std::size_t k95 = static_cast<std::size_t>(std::floor(0.95 * double(magnitudes.size() - 1)));
    std::nth_element(magnitudes.begin(), magnitudes.begin() + static_cast<std::ptrdiff_t>(k95), magnitudes.end());
    const double kref = magnitudes[k95] > 0 ? magnitudes[k95] : kmax;
    std::vector<double>().swap(magnitudes);
    const double diag = std::hypot(0.5 * b.xmax - 0.5 * b.xmin, 0.5 * b.ymax - 0.5 * b.ymin) * 2;
    const double reference = fraction * diag;  // the tooth of kref
    const double clip = comb_clip * reference;
    // Teeth are computed as (kappa / kref) * reference (bounded by the clip, no overflow); an
    // explicit scale becomes the reference tooth of kref.
    const double ref_len = scale > 0 ? kref * scale : reference;
    fair::internal::require(std::isfinite(ref_len) && std::isfinite(clip), "add_curvature_comb: non-finite comb length (scale = ",
                            scale, ", kref = ", kref, ")");
    // At most max_comb_teeth teeth (every stride-th sample): more cannot be told apart in a
    // figure a few hundred pixels wide, and they would make the text and the memory of a curve of
    // 10^4 pieces a multiple of the curve's own (issue 29 #21). The envelope keeps every sample.
    const std::size_t stride = (curve.samples.size() + max_comb_teeth - 1) / max_comb_teeth;
    Comb comb;
    comb.teeth.reserve(curve.samples.size() / stride + 1);
    std::vector<Xy> envelope;
    for (std::size_t i = 0; i < curve.samples.size(); ++i) {
      const Curve_sample& s = curve.samples[i];
      double len = s.curvature / kref * ref_len;
      const bool clipped = std::abs(len) > clip;
      if (clipped) len = len > 0 ? clip : -clip;
      const Xy tip{s.x - len * s.nx, s.y - len * s.ny};
      if (i % stride == 0) {
        comb.teeth.push_back(Tooth{Xy{s.x, s.y}, tip, clipped});
        comb.clipped += clipped ? 1 : 0;
      }
      clipped_teeth_ += clipped ? 1 : 0;
      box_.add(tip.x, tip.y);
      envelope.push_back(tip);
      const bool last = i + 1 == curve.samples.size() || curve.samples[i + 1].piece != s.piece;
      if (last) {
        lines_.push_back(Line{std::move(envelope), "#e08a2c", 1.0, std::string(), 1.0});
        envelope = std::vector<Xy>();
      }
    }
    combs_.push_back(std::move(comb));
    return ref_len / kref;
  }

  /// Teeth clipped so far by add_curvature_comb (drawn red with a dot at the tip; counted at every
  /// sample, drawn at the teeth kept).
  std::size_t clipped_teeth() const { return clipped_teeth_; }

  /// The SVG text.
  std::string str() const {
    std::string out;
    out.reserve(text_size_estimate());
    emit([&out](const std::string& piece) { out += piece; });
    return out;
  }

  /// Writes the SVG text to `out` as it is produced (no copy of the whole text in memory).
  void write(std::ostream& out) const {
    std::string buffer;
    emit([&](const std::string& piece) {
      buffer += piece;
      if (buffer.size() >= (1u << 16)) {
        out << buffer;
        buffer.clear();
      }
    });
    out << buffer;
  }

  /// Writes the SVG text to a file as it is produced; throws fair::Error if it cannot.
  void write(const std::string& file) const {
    std::ofstream out(file);
    if (!out) throw Error("fair::io: cannot open " + file + " for writing");
    write(out);
    out.close();
    if (!out) throw Error("fair::io: error while writing " + file);
  }

  /// Length of the reference tooth as a fraction of the bounding-box diagonal (add_curvature_comb).
  static constexpr double comb_fraction = 0.1;
  /// Teeth longer than comb_clip reference teeth are clipped and marked.
  static constexpr double comb_clip = 2.0;
  /// The most teeth a comb draws (evenly spaced in the samples); the envelope has every sample.
  static constexpr std::size_t max_comb_teeth = 4096;

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
  struct Tooth {
    Xy base, tip;
    bool clipped;
  };
  struct Comb {
    std::vector<Tooth> teeth;
    std::size_t clipped = 0;
  };

  // An upper estimate of the text's length (bytes per element written), to allocate it once.
  std::size_t text_size_estimate() const {
    std::size_t n = 1024 + title_.size() + 64 * (squares_.size() + dots_.size()) + 200 * rings_.size();
    for (const Line& l : lines_) n += 160 + 16 * l.points.size();
    for (const Comb& c : combs_) n += 400 + 32 * c.teeth.size() + 64 * c.clipped;
    return n;
  }

  // The SVG text, handed to `sink` in pieces of at most a few hundred bytes (one element, or a
  // few teeth): str() appends them, write() streams them, so no element list is duplicated.
  template <class Sink>
  void emit(Sink&& sink) const {
    const double width = width_;
    const double height = std::round(width * internal::aspect(box_, 0.35, 1.1));
    const double title_height = title_.empty() ? 0 : 22;
    const double margin = 16;
    // The view leaves room for the title at the top.
    internal::View view(box_, width, height - title_height, margin);
    sink("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + internal::px(width) + "\" height=\"" +
         internal::px(height) + "\" viewBox=\"0 0 " + internal::px(width) + " " + internal::px(height) + "\">\n");
    sink("<rect x=\"0\" y=\"0\" width=\"" + internal::px(width) + "\" height=\"" + internal::px(height) +
         "\" fill=\"white\"/>\n");
    if (!title_.empty())
      sink("<text x=\"" + internal::px(margin) + "\" y=\"16\" font-family=\"sans-serif\" "
           "font-size=\"13\">" + xml_escape(title_) + "</text>\n");
    sink("<g transform=\"translate(0," + internal::px(title_height) + ")\">\n");
    auto pair = [&view](const Xy& p) { return internal::px(view.x(p.x)) + "," + internal::px(view.y(p.y)); };
    // The teeth first (under the curve): one path per comb and kind, a tooth a "M base L tip".
    for (const Comb& c : combs_)
      for (int kind = 0; kind < 2; ++kind) {
        const bool clipped = kind == 1;
        if ((clipped ? c.clipped : c.teeth.size() - c.clipped) == 0) continue;
        sink(std::string("<path fill=\"none\" stroke=\"") + (clipped ? "#c0392b" : "#e08a2c") +
             "\" stroke-width=\"0.6\" stroke-opacity=\"0.8\" d=\"");
        std::string chunk;
        for (const Tooth& t : c.teeth) {
          if (t.clipped != clipped) continue;
          chunk += "M" + pair(t.base) + "L" + pair(t.tip);
          if (chunk.size() > 512) { sink(chunk); chunk.clear(); }
        }
        sink(chunk + "\"/>\n");
      }
    for (const Line& l : lines_) {
      std::string head = "<polyline fill=\"none\" stroke=\"" + l.color + "\" stroke-width=\"" + internal::px(l.stroke) + "\"";
      if (l.opacity < 1) head += " stroke-opacity=\"" + internal::px(l.opacity) + "\"";
      if (!l.dash.empty()) head += " stroke-dasharray=\"" + l.dash + "\"";
      sink(head + " stroke-linejoin=\"round\" points=\"");
      std::string chunk;
      for (std::size_t i = 0; i < l.points.size(); ++i) {
        if (i) chunk += ' ';
        chunk += pair(l.points[i]);
        if (chunk.size() > 512) { sink(chunk); chunk.clear(); }
      }
      sink(chunk + "\"/>\n");
    }
    // The marks of the clipped teeth: a small red dot at the clipped tip.
    for (const Comb& c : combs_)
      for (const Tooth& t : c.teeth)
        if (t.clipped)
          sink("<circle cx=\"" + internal::px(view.x(t.tip.x)) + "\" cy=\"" + internal::px(view.y(t.tip.y)) +
               "\" r=\"1.6\" fill=\"#c0392b\"/>\n");
    for (const Xy& p : squares_)
      sink("<rect x=\"" + internal::px(view.x(p.x) - 2) + "\" y=\"" + internal::px(view.y(p.y) - 2) +
           "\" width=\"4\" height=\"4\" fill=\"white\" stroke=\"#9a9a9a\" stroke-width=\"0.8\"/>\n");
    for (const Dot& d : dots_)
      sink("<circle cx=\"" + internal::px(view.x(d.p.x)) + "\" cy=\"" + internal::px(view.y(d.p.y)) + "\" r=\"" +
           internal::px(d.r) + "\" fill=\"" + d.color + "\"/>\n");
    for (const Dot& d : rings_) {
      const double x = view.x(d.p.x), y = view.y(d.p.y);
      std::string ring = "<circle cx=\"" + internal::px(x) + "\" cy=\"" + internal::px(y) + "\" r=\"" +
                         internal::px(d.r) + "\" fill=\"none\" stroke=\"" + d.color + "\" stroke-width=\"2\"/>\n";
      if (!d.label.empty()) {
        // Keep the label inside the figure: right of the mark unless too close to the edge.
        const bool left = x > 0.75 * width;
        ring += "<text x=\"" + internal::px(left ? x - 8 : x + 8) + "\" y=\"" + internal::px(y - 8) +
                "\" font-family=\"sans-serif\" font-size=\"11\" fill=\"" + d.color + "\"" +
                (left ? " text-anchor=\"end\"" : "") + ">" + xml_escape(d.label) + "</text>\n";
      }
      sink(ring);
    }
    sink("</g>\n</svg>\n");
  }

  double width_;
  std::string title_;
  internal::Box box_;
  std::vector<Line> lines_;
  std::vector<Xy> squares_;
  std::vector<Dot> dots_, rings_;
  std::vector<Comb> combs_;
  std::size_t clipped_teeth_ = 0;
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
