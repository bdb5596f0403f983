// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Layout helpers of the SVG figures of fair/io/svg.h: pixel and label formatting, the bounding
// box and the overflow-safe view of Svg_figure (see the robustness note of svg.h), tick steps.

#ifndef FAIR_IO_INTERNAL_SVG_LAYOUT_H
#define FAIR_IO_INTERNAL_SVG_LAYOUT_H

#include <fair/Errors.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace fair {
namespace io {
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

} // namespace io
} // namespace fair

#endif // FAIR_IO_INTERNAL_SVG_LAYOUT_H
