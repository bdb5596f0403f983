// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Certified self-intersections of a curve made of Bernstein-form pieces (fair::Bezier_2, the
// rational pieces with positive weights), and of a polygon. Issue 25 §2/§4: a loop the data do not
// force must be reported, not inferred from a picture. Documented in doc/fairness_metrics.md,
// "Self-intersections".
//
// Method: recursive subdivision (de Casteljau at t = sqrt(2) - 1, not 1/2: see split_parameter, on
// the homogeneous form (w x, w y, w), in double,
// coordinates taken relative to the centre of the curve's control points) with two certificates,
// both resting on the convex-hull property of Bernstein form with positive weights and on the
// variation-diminishing property (a line meets the curve at most as often as the control polygon):
//  - NO intersection of two sub-pieces: their control-point boxes, widened by the rounding margin
//    m, are disjoint; or all control points of one lie beyond the flatness strip of the other.
//    For a sub-piece against itself, or two sub-pieces that share an end point (consecutive parts,
//    the join of two pieces): the control polygon (of both, in order) is strictly monotone along a
//    direction d, so the projection onto d is injective except at the shared point.
//  - an intersection: both sub-pieces are flat (every control point within eps_A of the chord of
//    A, eps_B of B) and each chord's end points lie on opposite sides of the other's strip, beyond
//    it by the margin (signs by the exact orientation predicate, distances in double). Then A
//    contains a path inside its strip joining the two sides of B's strip and B one joining the
//    two sides of A's, both inside the parallelogram where the strips meet: they cross (the
//    crossing lemma of the square, a Poincare-Miranda argument). The crossing is interior to both
//    parameter intervals, so distinct sub-piece pairs certify distinct crossings.
// The margin m = 1e-12 R (R: the largest distance of a control point from the centre) bounds the
// rounding of at most `max_depth` splits in double (each adds a few ulps of R). A pair that
// reaches `max_depth` splits, or sizes below 1e3 m (both sub-pieces), or the cap on the number of
// pair tests, is undecided: tangential contacts, crossings at a join of pieces (no certificate
// above holds for a point at a sub-piece's end), overlapping pieces (a curve retracing itself)
// and cusps end there.
// Work: O(pieces^2) box tests, then proportional to the crossings times max_depth.

#ifndef FAIR_INTERNAL_METRICS_SELF_INTERSECTIONS_H
#define FAIR_INTERNAL_METRICS_SELF_INTERSECTIONS_H

#include <fair/Curve_traits.h>
#include <fair/Errors.h>
#include <fair/internal/common/polygon_crossings.h>
#include <fair/internal/metrics/pieces.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace metrics {

/// What self_intersections() found.
struct Self_intersection_report {
  /// Certified crossings: each is a distinct point where the curve meets itself (a lower bound of
  /// their number when `undecided` > 0; tangential contacts are not counted).
  std::size_t crossings = 0;
  /// Sub-piece pairs left open at the depth cap or the work cap (0: the count is complete, and 0
  /// crossings certifies a simple curve).
  std::size_t undecided = 0;
  /// The work cap was reached (the remaining pairs are counted in `undecided`).
  bool capped = false;
  bool certified() const { return undecided == 0; }
};

/// Caps of self_intersections().
struct Self_intersection_options {
  int max_depth = 60;               ///< splits of a sub-piece (t resolution 0.586^60 = 1.2e-14)
  std::size_t max_pair_tests = 2000000; ///< pair tests over the whole curve
};

namespace self_intersection_detail {

/// A sub-piece in homogeneous form: (w x, w y, w) per control point, w > 0.
struct Hpiece {
  std::vector<double> X, Y, W;
  int depth = 0;
  std::size_t size() const { return W.size(); }
  double x(std::size_t i) const { return X[i] / W[i]; }
  double y(std::size_t i) const { return Y[i] / W[i]; }
};

/// Where sub-pieces are split: not 1/2, so that a crossing at a dyadic parameter (a symmetric
/// curve's crossing in the middle of its pieces) does not stay on sub-piece ends, where no
/// certificate holds, down to the depth cap. sqrt(2) - 1.
constexpr double split_parameter = 0.41421356237309503;

inline void split(const Hpiece& a, Hpiece& left, Hpiece& right) {
  const double s = split_parameter, u = 1 - s;
  const std::size_t n = a.size();
  left.X.resize(n), left.Y.resize(n), left.W.resize(n), right.X.resize(n), right.Y.resize(n), right.W.resize(n);
  std::vector<double> x = a.X, y = a.Y, w = a.W;
  for (std::size_t r = 0; r < n; ++r) {
    left.X[r] = x[0], left.Y[r] = y[0], left.W[r] = w[0];
    right.X[n - 1 - r] = x[n - 1 - r], right.Y[n - 1 - r] = y[n - 1 - r], right.W[n - 1 - r] = w[n - 1 - r];
    for (std::size_t i = 0; i + 1 < n - r; ++i) {
      x[i] = u * x[i] + s * x[i + 1], y[i] = u * y[i] + s * y[i + 1], w[i] = u * w[i] + s * w[i + 1];
    }
  }
  left.depth = right.depth = a.depth + 1;
}

struct Box {
  double x0, y0, x1, y1;
};

inline Box box(const Hpiece& a) {
  Box b{a.x(0), a.y(0), a.x(0), a.y(0)};
  for (std::size_t i = 1; i < a.size(); ++i) {
    b.x0 = std::min(b.x0, a.x(i)), b.x1 = std::max(b.x1, a.x(i));
    b.y0 = std::min(b.y0, a.y(i)), b.y1 = std::max(b.y1, a.y(i));
  }
  return b;
}

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;

class Search {
public:
  Search(double margin, const Self_intersection_options& o) : m_(margin), o_(o) {}
  Self_intersection_report report;

  /// The sub-piece against itself.
  void self(const Hpiece& a) {
    if (!tick()) return;
    if (monotone(a, nullptr)) return;
    if (a.depth >= o_.max_depth || unresolved(a, a)) { ++report.undecided; return; }
    Hpiece l, r;
    split(a, l, r);
    self(l);
    self(r);
    adjacent(l, r);
  }

  /// Two sub-pieces, a's end being b's start.
  void adjacent(const Hpiece& a, const Hpiece& b) {
    if (!tick()) return;
    if (monotone(a, &b)) return;
    if (std::max(a.depth, b.depth) >= o_.max_depth || unresolved(a, b)) { ++report.undecided; return; }
    Hpiece l, r;
    if (a.depth <= b.depth) {
      split(a, l, r);
      apart(l, b);
      adjacent(r, b);
    } else {
      split(b, l, r);
      adjacent(a, l);
      apart(a, r);
    }
  }

  /// Two sub-pieces that share no end point.
  void apart(const Hpiece& a, const Hpiece& b) {
    if (!tick()) return;
    const Box p = box(a), q = box(b);
    if (p.x1 + m_ < q.x0 || q.x1 + m_ < p.x0 || p.y1 + m_ < q.y0 || q.y1 + m_ < p.y0) return;
    const double ea = flatness(a), eb = flatness(b);
    if (beyond_strip(a, ea, b) || beyond_strip(b, eb, a)) return;
    if (crosses(a, ea, b) && crosses(b, eb, a)) { ++report.crossings; return; }
    if (std::max(a.depth, b.depth) >= o_.max_depth || unresolved(a, b)) { ++report.undecided; return; }
    Hpiece l, r;
    if (a.depth <= b.depth) {
      split(a, l, r);
      apart(l, b);
      apart(r, b);
    } else {
      split(b, l, r);
      apart(a, l);
      apart(a, r);
    }
  }

private:
  // Both sub-pieces within 1e3 margins: below what the margin lets a certificate decide (a
  // contact, or a crossing at a join). Without this stop every pair of their descendants would
  // overlap within the margin down to the depth cap: 2^(2 k) pairs for the last k levels.
  bool unresolved(const Hpiece& a, const Hpiece& b) const {
    const Box p = box(a), q = box(b);
    const double r = 1e3 * m_;
    return std::hypot(p.x1 - p.x0, p.y1 - p.y0) < r && std::hypot(q.x1 - q.x0, q.y1 - q.y0) < r;
  }

  bool tick() {
    if (report.capped) { ++report.undecided; return false; }
    if (++tests_ > o_.max_pair_tests) { report.capped = true; ++report.undecided; return false; }
    return true;
  }

  // The control polygon of a (followed by b's, if given) strictly monotone along one of a few
  // directions: the chord of the whole, and the chords of a and of b.
  bool monotone(const Hpiece& a, const Hpiece* b) const {
    std::vector<double> x, y;
    for (std::size_t i = 0; i < a.size(); ++i) x.push_back(a.x(i)), y.push_back(a.y(i));
    if (b)
      for (std::size_t i = 1; i < b->size(); ++i) x.push_back(b->x(i)), y.push_back(b->y(i));
    const std::size_t n = x.size(), k = a.size() - 1;
    const double dirs[3][2] = {{x[n - 1] - x[0], y[n - 1] - y[0]}, {x[k] - x[0], y[k] - y[0]},
                               {x[n - 1] - x[k], y[n - 1] - y[k]}};
    for (const auto& d : dirs) {
      const double len = std::hypot(d[0], d[1]);
      if (!(len > 0)) continue;
      bool ok = true;
      for (std::size_t i = 0; i + 1 < n && ok; ++i)
        ok = ((x[i + 1] - x[i]) * d[0] + (y[i + 1] - y[i]) * d[1]) / len > m_;
      if (ok) return true;
    }
    return false;
  }

  // Signed distance of (px, py) from the line through a's chord (positive on the left).
  static double distance(const Hpiece& a, double px, double py) {
    const std::size_t k = a.size() - 1;
    const double dx = a.x(k) - a.x(0), dy = a.y(k) - a.y(0), len = std::hypot(dx, dy);
    if (!(len > 0)) return std::hypot(px - a.x(0), py - a.y(0)); // a closed chord: no strip
    return (dx * (py - a.y(0)) - dy * (px - a.x(0))) / len;
  }

  // Half-width of the strip around a's chord holding every control point (so the sub-piece).
  double flatness(const Hpiece& a) const {
    const std::size_t k = a.size() - 1;
    if (!(std::hypot(a.x(k) - a.x(0), a.y(k) - a.y(0)) > 0)) return HUGE_VAL;
    double e = 0;
    for (std::size_t i = 1; i < k; ++i) e = std::max(e, std::fabs(distance(a, a.x(i), a.y(i))));
    return e + m_;
  }

  // Every control point of b beyond a's strip on one side: b misses a.
  bool beyond_strip(const Hpiece& a, double ea, const Hpiece& b) const {
    if (!std::isfinite(ea)) return false;
    bool left = true, right = true;
    for (std::size_t i = 0; i < b.size(); ++i) {
      const double d = distance(a, b.x(i), b.y(i));
      left = left && d > ea + m_;
      right = right && d < -(ea + m_);
    }
    return left || right;
  }

  // b's end points on opposite sides of a's chord (exact orientation), both beyond a's strip.
  bool crosses(const Hpiece& a, double ea, const Hpiece& b) const {
    if (!std::isfinite(ea)) return false;
    const std::size_t k = a.size() - 1, j = b.size() - 1;
    const Epick::Point_2 p(a.x(0), a.y(0)), q(a.x(k), a.y(k));
    const CGAL::Orientation s0 = CGAL::orientation(p, q, Epick::Point_2(b.x(0), b.y(0)));
    const CGAL::Orientation s1 = CGAL::orientation(p, q, Epick::Point_2(b.x(j), b.y(j)));
    if (s0 == CGAL::COLLINEAR || s1 == CGAL::COLLINEAR || s0 == s1) return false;
    return std::fabs(distance(a, b.x(0), b.y(0))) > ea + m_ && std::fabs(distance(a, b.x(j), b.y(j))) > ea + m_;
  }

  double m_;
  Self_intersection_options o_;
  std::size_t tests_ = 0;
};

} // namespace self_intersection_detail

/// Certified self-intersections of the curve `pieces` (Bernstein-form pieces joined end to start;
/// `closed`: the last piece's end is the first piece's start). Points where consecutive pieces
/// meet are not intersections. See the file comment for the certificates and the caps.
template <class Piece>
Self_intersection_report self_intersections(const std::vector<Piece>& pieces, bool closed,
                                            const Self_intersection_options& options = {}) {
  static_assert(is_bernstein_form(kind_of<Piece>), "self_intersections: Bernstein-form pieces only");
  namespace d = self_intersection_detail;
  require(!pieces.empty(), "self_intersections: the curve has no piece");
  std::vector<d::Hpiece> h;
  double cx = 0, cy = 0, count = 0;
  for (const Piece& p : pieces)
    for (const auto& q : p.control_points()) cx += CGAL::to_double(q.x()), cy += CGAL::to_double(q.y()), ++count;
  cx /= count, cy /= count;
  double R = 0;
  for (const Piece& p : pieces) {
    std::vector<typename Piece::Point_2> cp;
    std::vector<typename Piece::FT> w;
    bernstein_form(p, cp, w);
    d::Hpiece a;
    for (std::size_t i = 0; i < cp.size(); ++i) {
      const double wi = CGAL::to_double(w[i]), x = CGAL::to_double(cp[i].x()) - cx, y = CGAL::to_double(cp[i].y()) - cy;
      require(wi > 0 && std::isfinite(wi) && std::isfinite(x) && std::isfinite(y),
              "self_intersections: a control point or weight is not finite or a weight is not positive");
      R = std::max(R, std::hypot(x, y));
      a.X.push_back(wi * x), a.Y.push_back(wi * y), a.W.push_back(wi);
    }
    // Two parts, so that even a closed curve of two pieces has no pair sharing both end points.
    d::Hpiece l, r;
    d::split(a, l, r);
    l.depth = r.depth = 0;
    h.push_back(l), h.push_back(r);
  }
  d::Search search(1e-12 * R, options);
  const std::size_t n = h.size();
  for (std::size_t i = 0; i < n; ++i) {
    search.self(h[i]);
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1) search.adjacent(h[i], h[j]);
      else if (closed && i == 0 && j == n - 1) search.adjacent(h[j], h[i]);
      else search.apart(h[i], h[j]);
    }
  }
  return search.report;
}

/// Crossings of the polygon through `points` (closed: with its closing edge), certified on the
/// points rounded to double (`common::polygon_crossings`): two non-consecutive edges that meet,
/// and two consecutive edges that overlap (the polygon doubling back), each count once.
template <class Point>
std::size_t polygon_self_intersections(const std::vector<Point>& points, bool closed) {
  std::vector<common::Xy> p;
  p.reserve(points.size());
  for (const Point& q : points) p.push_back({{CGAL::to_double(q.x()), CGAL::to_double(q.y())}});
  return common::polygon_crossings(p, closed);
}

} // namespace metrics
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_METRICS_SELF_INTERSECTIONS_H
