// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The Hausdorff distance of hausdorff_distance_bounds() (Fairness_metrics.h), by bounded
// subdivision with certified bounds (doc/fairness_metrics.md, "Hausdorff distance"):
//
// 1. Each curve C becomes a polyline P whose vertices lie on C, with a certified e >= H(C, P).
//    A Bernstein-form piece with control points P_0..P_n and weights w_i > 0 is within
//        delta = max_i |P_i - L(i/n)|,   L(s) = (1 - s) P_0 + s P_n,
//    of its chord, both ways: c(t) - L(s(t)) = sum B_i w_i (P_i - L(i/n)) / W(t) with
//    s(t) = sum B_i w_i (i/n) / W(t), a convex combination, and s maps [0,1] onto [0,1]. The
//    piece with the largest delta is halved (rational de Casteljau in affine form: convex
//    combinations only, no overflow) until every delta <= tolerance / 8 or a cap is met.
// 2. The directed distance h(P_A, P_B) of two polylines, by branch and bound over the segments
//    s = [a0, a1] of P_A: with d = distance to P_B (1-Lipschitz),
//        lower(s) = max(d(a0), d(a1)),
//        upper(s) = min( max(|a0 - t|, |a1 - t|) over the nearest segments t of a0 and a1
//                        (distance to one convex segment is convex along s),
//                        (d(a0) + d(a1) + |s|) / 2 ),
//    halving the segment with the largest upper bound until it is within tolerance / 2 of the
//    largest lower bound. The convex bound is exact wherever one segment of P_B is nearest along
//    s, so only the crossings of the medial axis of P_B are refined, each O(log(|s| / tolerance))
//    times: the work does not grow like 1 / tolerance (a 10^6-long segment, issue 29 #1).
//    Nearest segments come from a bounding-box tree over runs of consecutive segments.
// 3. By the triangle inequality H(A, B) lies in [H_lower - e_A - e_B, H_upper + e_A + e_B].
// Generic pieces (no Bernstein form) are sampled as before (bisection to a chord tolerance) and
// the result is marked not certified. Distances are computed in double: the bounds are certified
// up to a rounding allowance of 64 (n + 1) eps max|coordinate| that is added to e.

#ifndef FAIR_INTERNAL_METRICS_HAUSDORFF_H
#define FAIR_INTERNAL_METRICS_HAUSDORFF_H

#include <fair/Errors.h>
#include <fair/internal/metrics/pieces.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace metrics {

/// Cap on the sub-pieces of one curve's polyline (step 1): a curve of total turning theta needs
/// about theta sqrt(R / tolerance) of them, so 2^12 covers a full circle at tolerance 2.4e-6 R
/// (a quarter circle at 1.5e-7 R); it bounds memory (kB) and the time (a capped pair of curves:
/// about 0.2 s in release, under a second with the sanitizers).
constexpr std::size_t max_hausdorff_segments = std::size_t(1) << 12;
/// Cap on the halvings of polyline segments in step 2, per direction.
constexpr std::size_t max_hausdorff_refinements = std::size_t(1) << 14;
/// Depth cap of the halving of one piece: 2^-50 of a piece is below any tolerance in double.
constexpr int max_hausdorff_depth = 50;
/// Largest ratio of the weights of one rational piece: beyond it the convex combinations of
/// step 1 lose all precision near an end (weights 5e-324, 1, 5e-324: issue 29 #13).
constexpr double max_hausdorff_weight_ratio = 1e100;
/// Largest coordinate magnitude: below DBL_MAX / 8 every difference and distance is finite.
constexpr double max_hausdorff_coordinate = std::numeric_limits<double>::max() / 8;

typedef std::pair<double, double> Point_d;

/// One sub-piece of a Bernstein-form piece in affine form: its m points and weights (max weight
/// 1) are x, y, w at pool[offset], pool[offset + m], pool[offset + 2m] of a Sub_piece_pool. The
/// sub-pieces are small values and the coefficients share one buffer: with three vectors per
/// sub-piece, copied by every heap operation, the allocations were most of a metrics run's time
/// under the sanitizers.
struct Sub_piece {
  std::size_t piece = 0;
  double t0 = 0;  ///< where it starts in its piece (for ordering)
  int depth = 0;
  std::size_t m = 0;       ///< number of control points
  std::size_t offset = 0;  ///< where its coefficients start in the pool
  double delta = 0;  ///< max |P_i - L(i/n)|, the certified distance to the chord both ways
};

/// The coefficients of every sub-piece of one curve (x, y, w of a sub-piece contiguous).
struct Sub_piece_pool {
  std::vector<double> values;
  std::vector<double> scratch;
  const double* x(const Sub_piece& s) const { return values.data() + s.offset; }
  const double* y(const Sub_piece& s) const { return values.data() + s.offset + s.m; }
  const double* w(const Sub_piece& s) const { return values.data() + s.offset + 2 * s.m; }
  /// Room for m more control points; returns their offset.
  std::size_t allocate(std::size_t m) {
    const std::size_t offset = values.size();
    values.resize(offset + 3 * m);
    return offset;
  }
};

inline double chord_deviation(const Sub_piece& s, const Sub_piece_pool& pool) {
  const double *x = pool.x(s), *y = pool.y(s);
  const std::size_t n = s.m - 1;
  double d = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const double u = double(i) / double(n);
    d = std::max(d, std::hypot(x[i] - ((1 - u) * x[0] + u * x[n]), y[i] - ((1 - u) * y[0] + u * y[n])));
  }
  return d;
}

/// Halves a sub-piece at t = 1/2 by the rational de Casteljau algorithm in affine form: the
/// left half takes the sub-piece's place in the pool, the right half new room at its end.
inline std::pair<Sub_piece, Sub_piece> halve(const Sub_piece& s, Sub_piece_pool& pool) {
  const std::size_t m = s.m;
  pool.scratch.assign(pool.values.begin() + static_cast<std::ptrdiff_t>(s.offset),
                      pool.values.begin() + static_cast<std::ptrdiff_t>(s.offset + 3 * m));
  double *x = pool.scratch.data(), *y = x + m, *w = y + m;
  Sub_piece l = s, r = s;
  l.depth = r.depth = s.depth + 1;
  r.t0 = s.t0 + std::ldexp(1.0, -(s.depth + 1));
  r.offset = pool.allocate(m);
  double *lx = pool.values.data() + l.offset, *ly = lx + m, *lw = ly + m;
  double *rx = pool.values.data() + r.offset, *ry = rx + m, *rw = ry + m;
  for (std::size_t k = 0; k < m; ++k) {
    lx[k] = x[0]; ly[k] = y[0]; lw[k] = w[0];
    rx[m - 1 - k] = x[m - 1 - k]; ry[m - 1 - k] = y[m - 1 - k]; rw[m - 1 - k] = w[m - 1 - k];
    for (std::size_t i = 0; i + 1 < m - k; ++i) {
      const double wn = 0.5 * (w[i] + w[i + 1]), a = 0.5 * w[i] / wn, b = 1 - a;
      x[i] = a * x[i] + b * x[i + 1];
      y[i] = a * y[i] + b * y[i + 1];
      w[i] = wn;
    }
  }
  for (Sub_piece* p : {&l, &r}) {
    // Renormalise the weights (an exact power of two keeps them in range, the curve unchanged).
    double* pw = pool.values.data() + p->offset + 2 * m;
    const double wmax = *std::max_element(pw, pw + m);
    int e;
    std::frexp(wmax, &e);
    for (std::size_t k = 0; k < m; ++k) pw[k] = std::ldexp(pw[k], -e);
    p->delta = chord_deviation(*p, pool);
  }
  return {l, r};
}

/// A polyline through points of a curve and a bound e of the Hausdorff distance between them.
struct Certified_polyline {
  std::vector<Point_d> vertices;
  double error = 0;
  double rounding = 0;    ///< the part of `error` that is the rounding allowance
  bool converged = true;  ///< every sub-piece within the target (no cap met)
  bool certified = true;  ///< e is a certified bound (Bernstein-form pieces)
};

template <class Piece>
void sample_generic_piece(const Piece_jet<Piece>& jet, double t0, double t1, const Jet& a, const Jet& b, double h,
                          int depth, std::vector<Point_d>& out, double& err) {
  const double tm = 0.5 * (t0 + t1);
  const Jet m = jet(tm, 1);
  const double sag = std::hypot(m.x - 0.5 * (a.x + b.x), m.y - 0.5 * (a.y + b.y));
  if (depth >= 24 || sag <= h) {
    err = std::max(err, 2 * sag);  // an estimate only: a generic piece has no certificate
    out.emplace_back(b.x, b.y);
    return;
  }
  sample_generic_piece(jet, t0, tm, a, m, h, depth + 1, out, err);
  sample_generic_piece(jet, tm, t1, m, b, h, depth + 1, out, err);
}

/// Step 1 for one curve: its polyline with e <= `target` unless a cap is met.
template <class Piece>
Certified_polyline certified_polyline(const std::vector<Piece>& curve, double target, const char* which) {
  Certified_polyline out;
  if constexpr (is_bernstein_form(kind_of<Piece>)) {
    auto cmp = [](const Sub_piece& a, const Sub_piece& b) { return a.delta < b.delta; };
    Sub_piece_pool pool;
    std::vector<Sub_piece> open, done; // open: a max-heap on delta
    double magnitude = 0;
    std::size_t degree = 1;
    for (std::size_t i = 0; i < curve.size(); ++i) {
      std::vector<typename Piece::Point_2> cp;
      std::vector<typename Piece::FT> w;
      bernstein_form(curve[i], cp, w);
      Sub_piece s;
      s.piece = i;
      s.m = cp.size();
      s.offset = pool.allocate(s.m);
      double* sx = pool.values.data() + s.offset;
      double *sy = sx + s.m, *sw = sy + s.m;
      double wmin = std::numeric_limits<double>::infinity(), wmax = 0;
      for (std::size_t k = 0; k < cp.size(); ++k) {
        sx[k] = CGAL::to_double(cp[k].x());
        sy[k] = CGAL::to_double(cp[k].y());
        sw[k] = CGAL::to_double(w[k]);
        wmin = std::min(wmin, sw[k]);
        wmax = std::max(wmax, sw[k]);
        magnitude = std::max({magnitude, std::fabs(sx[k]), std::fabs(sy[k])});
      }
      if (!(magnitude <= max_hausdorff_coordinate))
        throw Invalid_input_error(message("hausdorff_distance: ", which, ", piece ", i, ", has a coordinate ",
                                          magnitude, " beyond ", max_hausdorff_coordinate,
                                          " (DBL_MAX / 8), where distances may overflow double precision"));
      if (!(wmin > 0) || !(wmax / wmin <= max_hausdorff_weight_ratio))
        throw Invalid_input_error(message("hausdorff_distance: ", which, ", piece ", i, ", has weights from ", wmin,
                                          " to ", wmax, "; their ratio must be at most ", max_hausdorff_weight_ratio));
      for (std::size_t k = 0; k < s.m; ++k) sw[k] /= wmax;
      degree = std::max(degree, s.m - 1);
      s.delta = s.m > 2 ? chord_deviation(s, pool) : 0.0;
      open.push_back(s);
      std::push_heap(open.begin(), open.end(), cmp);
    }
    // Halve the worst sub-piece until all are within the target or a cap is met.
    while (!open.empty() && open.front().delta > target) {
      if (open.size() + done.size() >= max_hausdorff_segments) {
        out.converged = false;
        break;
      }
      std::pop_heap(open.begin(), open.end(), cmp);
      const Sub_piece s = open.back();
      open.pop_back();
      if (s.depth >= max_hausdorff_depth) {
        out.converged = false;
        done.push_back(s);
        continue;
      }
      const std::pair<Sub_piece, Sub_piece> h = halve(s, pool);
      open.push_back(h.first);
      std::push_heap(open.begin(), open.end(), cmp);
      open.push_back(h.second);
      std::push_heap(open.begin(), open.end(), cmp);
    }
    done.insert(done.end(), open.begin(), open.end());
    std::sort(done.begin(), done.end(),
              [](const Sub_piece& a, const Sub_piece& b) { return a.piece != b.piece ? a.piece < b.piece : a.t0 < b.t0; });
    double err = 0;
    for (const Sub_piece& s : done) {
      err = std::max(err, s.delta);
      const Point_d a(pool.x(s)[0], pool.y(s)[0]), b(pool.x(s)[s.m - 1], pool.y(s)[s.m - 1]);
      if (out.vertices.empty() || out.vertices.back() != a) out.vertices.push_back(a);
      out.vertices.push_back(b);
    }
    // Rounding allowance of the double de Casteljau steps and chord deviations; a curve of
    // straight pieces has its control points as the polyline, exactly (e = 0).
    out.rounding = degree <= 1 ? 0.0 : 64 * double(degree + 1) * std::numeric_limits<double>::epsilon() * magnitude;
    out.error = err + out.rounding;
  } else {
    out.certified = false;
    double err = 0;
    for (std::size_t i = 0; i < curve.size(); ++i) {
      Piece_jet<Piece> jet(curve[i]);
      const Jet a = jet(0.0, 1), b = jet(1.0, 1);
      if (out.vertices.empty() || out.vertices.back() != Point_d(a.x, a.y)) out.vertices.emplace_back(a.x, a.y);
      Jet prev = a;
      for (int q = 1; q <= 4; ++q) {
        const Jet e = q == 4 ? b : jet(q / 4.0, 1);
        sample_generic_piece(jet, (q - 1) / 4.0, q / 4.0, prev, e, target, 0, out.vertices, err);
        prev = e;
      }
    }
    out.error = err;
  }
  for (const Point_d& p : out.vertices)
    if (!std::isfinite(p.first) || !std::isfinite(p.second))
      throw Invalid_input_error(message("hausdorff_distance: ", which, " has a point (", p.first, ", ",
                                        p.second, ") that is not finite"));
  return out;
}

inline double point_segment_distance(const Point_d& p, const Point_d& a, const Point_d& b) {
  const double dx = b.first - a.first, dy = b.second - a.second, l2 = dx * dx + dy * dy;
  double u = l2 > 0 ? ((p.first - a.first) * dx + (p.second - a.second) * dy) / l2 : 0.0;
  u = std::min(1.0, std::max(0.0, u));
  return std::hypot(p.first - (a.first + u * dx), p.second - (a.second + u * dy));
}

/// Nearest-segment queries on a polyline through a bounding-box tree over runs of consecutive
/// segments (a polyline is spatially coherent in its own order): a node's box is skipped when it
/// cannot hold a segment nearer than the best found, the nearer child is visited first. Exact;
/// O(log n) per query on a fair curve, and, unlike a uniform grid, not slowed down where the
/// segments cluster (the tip of a hairpin: a fuzz finding of issue 29).
class Polyline_grid {
public:
  explicit Polyline_grid(const std::vector<Point_d>& v) : v_(v) {
    segments_ = v.size() > 1 ? v.size() - 1 : 1;
    box_.resize(4 * segments_);
    build(1, 0, segments_);
  }

  /// Distance from p to segment s.
  double segment_distance(const Point_d& p, std::size_t s) const {
    return point_segment_distance(p, v_[s], v_.size() == 1 ? v_[0] : v_[s + 1]);
  }

  /// The distance from p to the polyline and the index of a nearest segment.
  std::pair<double, std::size_t> nearest(const Point_d& p) const {
    std::pair<double, std::size_t> best(std::numeric_limits<double>::infinity(), 0);
    visit(1, 0, segments_, p, best);
    return best;
  }

private:
  struct Box {
    double x0, y0, x1, y1;
    double distance(const Point_d& p) const {
      const double dx = std::max({0.0, x0 - p.first, p.first - x1}), dy = std::max({0.0, y0 - p.second, p.second - y1});
      return std::hypot(dx, dy);
    }
  };
  static constexpr std::size_t leaf_size = 4;

  const Point_d& end(std::size_t s) const { return v_.size() == 1 ? v_[0] : v_[s + 1]; }

  void build(std::size_t node, std::size_t lo, std::size_t hi) {
    Box b{v_[lo].first, v_[lo].second, v_[lo].first, v_[lo].second};
    if (hi - lo <= leaf_size) {
      for (std::size_t s = lo; s < hi; ++s)
        for (const Point_d* q : {&v_[s], &end(s)}) {
          b.x0 = std::min(b.x0, q->first); b.x1 = std::max(b.x1, q->first);
          b.y0 = std::min(b.y0, q->second); b.y1 = std::max(b.y1, q->second);
        }
    } else {
      const std::size_t mid = lo + (hi - lo) / 2;
      build(2 * node, lo, mid);
      build(2 * node + 1, mid, hi);
      const Box &l = box_[2 * node], &r = box_[2 * node + 1];
      b = Box{std::min(l.x0, r.x0), std::min(l.y0, r.y0), std::max(l.x1, r.x1), std::max(l.y1, r.y1)};
    }
    box_[node] = b;
  }

  void visit(std::size_t node, std::size_t lo, std::size_t hi, const Point_d& p, std::pair<double, std::size_t>& best) const {
    if (box_[node].distance(p) > best.first) return;
    if (hi - lo <= leaf_size) {
      for (std::size_t s = lo; s < hi; ++s) {
        const double d = segment_distance(p, s);
        if (d < best.first) best = {d, s};
      }
      return;
    }
    const std::size_t mid = lo + (hi - lo) / 2;
    const double dl = box_[2 * node].distance(p), dr = box_[2 * node + 1].distance(p);
    if (dl <= dr) {
      visit(2 * node, lo, mid, p, best);
      visit(2 * node + 1, mid, hi, p, best);
    } else {
      visit(2 * node + 1, mid, hi, p, best);
      visit(2 * node, lo, mid, p, best);
    }
  }

  const std::vector<Point_d>& v_;
  std::size_t segments_ = 1;
  std::vector<Box> box_;
};

/// Bounds of the directed distance h(P_A, P_B) of two polylines (step 2).
struct Directed_bounds {
  double lower = 0, upper = 0;
  bool converged = true;
};

inline Directed_bounds directed_polyline_bounds(const std::vector<Point_d>& a, const Polyline_grid& b, double gap) {
  struct Node {
    Point_d p0, p1;
    double d0, d1;
    std::size_t s0, s1;
    double upper;
    bool operator<(const Node& o) const { return upper < o.upper; }
  };
  Directed_bounds out;
  std::vector<std::pair<double, std::size_t>> near(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    near[i] = b.nearest(a[i]);
    out.lower = std::max(out.lower, near[i].first);
  }
  auto make = [&](const Point_d& p0, const Point_d& p1, const std::pair<double, std::size_t>& n0,
                  const std::pair<double, std::size_t>& n1) {
    Node n{p0, p1, n0.first, n1.first, n0.second, n1.second, 0};
    const double len = std::hypot(p1.first - p0.first, p1.second - p0.second);
    n.upper = std::min({std::max(b.segment_distance(p0, n.s0), b.segment_distance(p1, n.s0)),
                        std::max(b.segment_distance(p0, n.s1), b.segment_distance(p1, n.s1)),
                        0.5 * (n.d0 + n.d1 + len)});
    n.upper = std::max(n.upper, std::max(n.d0, n.d1));
    return n;
  };
  std::priority_queue<Node> open;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    const Node n = make(a[i], a[i + 1], near[i], near[i + 1]);
    if (n.upper > out.lower + gap) open.push(n);
  }
  std::size_t refinements = 0;
  while (!open.empty() && open.top().upper > out.lower + gap) {
    if (refinements++ >= max_hausdorff_refinements) {
      out.converged = false;
      break;
    }
    const Node n = open.top();
    open.pop();
    const Point_d m(0.5 * (n.p0.first + n.p1.first), 0.5 * (n.p0.second + n.p1.second));
    const std::pair<double, std::size_t> nm = b.nearest(m);
    out.lower = std::max(out.lower, nm.first);
    const Node l = make(n.p0, m, {n.d0, n.s0}, nm), r = make(m, n.p1, nm, {n.d1, n.s1});
    if (l.upper > out.lower + gap) open.push(l);
    if (r.upper > out.lower + gap) open.push(r);
  }
  out.upper = std::max(out.lower, open.empty() ? out.lower : open.top().upper);
  return out;
}

} // namespace metrics
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_METRICS_HAUSDORFF_H
