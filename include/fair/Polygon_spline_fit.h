// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Splines through every vertex of a polygon: the CAD output of the optimal curves (issue 11 §4,
// fair::Optimal_curve_2 returns a polygon). The cubic is C2 (a Cubic_spline_2, the library's
// NURBS-ready form), the quintic C4 (for the C3 .. C5 curves of the k-th derivative energies).
// Both use cumulative chord-length breakpoints, one per vertex, so every polygon vertex (and so
// every interpolation point of the optimal curve) is a knot. Open ends: the cubic is
// not-a-knot, the quintic clamped to the derivatives of the polynomial through the 6 end
// vertices; closed curves are periodic. Derivations and the measured convergence (O(h^4) cubic,
// O(h^6) quintic on dense samples of smooth curves) are in doc/optimal_curves.md.
//
// Arithmetic: the fit is computed in double from the vertices converted to double (the
// optimiser works in double too); the result is converted to K at the boundary. The cubic is
// built from its B-spline control points, so it is C2 exactly in an exact kernel and passes
// through the vertices to rounding (~1e-15 of the extent); the quintic's pieces start and end
// exactly at the vertices (C0 exact), their inner control points are rounded doubles (C1 .. C4
// to rounding). Complexity O(n): tridiagonal / cyclic tridiagonal (cubic), banded Cholesky of
// half-bandwidth 3 plus a rank-4 Woodbury correction when closed (quintic).
//
// Closed cubics solve the periodic interpolation for the B-spline control points directly
// (internal/spline/polygon_fit.h); open ones (not-a-knot ends) take them from
// Cubic_interpolating_spline_2. max_distance is measured on the spline's own pieces.
//
// Corners (fit_cubic_spline_runs): one C2 run between consecutive corners, G0 there, so that
// the CORNER constraints of an optimal curve survive in the spline; Polygon_spline_runs::nurbs
// is the runs as one NURBS with triple knots at the corners.
//
// Smoothing (fit_smoothing_spline_runs, what Optimal_curve_2::spline() delivers): the same runs and
// knots, but only the given vertices (the optimal curve's input points), the corners and their
// neighbours are interpolated; the others are approached within a distance, by the constrained
// smoothing spline of internal/spline/smoothing_fit.h (Reinsch; doc/optimal_curves.md).
//
// max_distance: the largest distance from a point of the spline to the polygon, measured piece
// by piece against the polygon edge the piece replaces (32 samples per piece refined by golden
// section; relative accuracy ~1e-12 unless a piece's distance has two maxima within 1/32 of it).

#ifndef FAIR_POLYGON_SPLINE_FIT_H
#define FAIR_POLYGON_SPLINE_FIT_H

#include <fair/Bezier_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/Errors.h>
#include <fair/Knot_spacing.h>
#include <fair/internal/common/input_checks.h>
#include <fair/internal/nurbs/assembly.h>
#include <fair/internal/optimal/spline_fit.h>
#include <fair/internal/spline/polygon_fit.h>
#include <fair/internal/spline/smoothing_fit.h>
#include <fair/internal/spline/smoothing_quintic.h>
#include <fair/internal/spline/smoothing_runs.h>

#include <CGAL/Simple_cartesian.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace fair {

/// A C2 cubic spline through every vertex and its measured distance to the polygon.
template <class K>
struct Polygon_spline_fit {
  Cubic_spline_2<K> spline;
  double max_distance;
};

/// A C4 quintic spline through every vertex, as Bezier pieces of degree 5 (piece i from vertex
/// i to vertex i+1; closed: the last piece closes the polygon), and its distance to the polygon.
template <class K>
struct Polygon_quintic_fit {
  std::vector<Bezier_2<K>> pieces;
  double max_distance;
};

/// The C2 cubic interpolant of `polygon` (open: n >= 2 vertices, closed: n >= 3, without a
/// repeated last vertex) on cumulative chord length: breakpoint i at vertex i (closed: one more
/// breakpoint closing the polygon, m = n pieces; open m = n - 1). 2 vertices give the segment,
/// 3 open vertices the parabola.
/// \throws Invalid_input_error for too few vertices, a non-finite coordinate or two consecutive
/// vertices that coincide (also in double: a zero chord).
template <class K>
Polygon_spline_fit<K> fit_cubic_spline(const std::vector<typename K::Point_2>& polygon, bool closed) {
  using namespace internal::spline;
  const char* fn = "fair::fit_cubic_spline";
  const std::vector<Vec2> raw = polygon_to_double<K>(polygon, closed, fn);
  const double scale = fit_scale(raw);  // computed on raw / scale, mapped back exactly
  const std::vector<Vec2> p = scaled(raw, 1 / scale);
  std::vector<double> t;
  std::vector<Vec2> control;
  // Closed: the periodic interpolant's control points directly (internal/spline/polygon_fit.h),
  // unless a knot interval dwarfs its neighbours (then the Hermite form below).
  if (closed) {
    t = internal::optimal::chord_breakpoints(p, true, fn);
    if (!periodic_interpolation_control(p, t, control)) t.clear();
  }
  if (t.empty()) {
    typedef CGAL::Simple_cartesian<double> Kd;
    std::vector<Kd::Point_2> q;  // a chord that vanishes in double: the spline's Invalid_input_error
    q.reserve(p.size());
    for (const Vec2& v : p) q.emplace_back(v[0], v[1]);
    Cubic_interpolating_spline_options options;  // closed: periodic; open: not-a-knot ends
    options.closed = closed;
    options.end_condition = Spline_end_condition::NOT_A_KNOT;
    options.knot_spacing = Knot_spacing::CHORDAL;
    const Cubic_interpolating_spline_2<Kd> c(std::move(q), options);
    t = c.knots();
    control.clear();
    for (const Kd::Point_2& d : c.spline().control_points()) control.push_back(Vec2{{d.x(), d.y()}});
  }
  const double distance = scale * internal::optimal::max_chord_distance(bezier_pieces(t, control, closed));
  return Polygon_spline_fit<K>{internal::spline::spline_from_control<K>(t, control, closed, scale, fn), distance};
}

/// Splines through every vertex that keep the polygon's corners: one C2 cubic per run between
/// consecutive corners, joined with G0 there (the curve of an optimal polygon with CORNER
/// constraints must not be smoothed across them). Run r covers the vertices first_vertex[r] ..
/// first_vertex[r + 1] (the last run of a closed polygon wraps to first_vertex[0]; without corners
/// the one run is the whole polygon, periodic when closed).
template <class K>
struct Polygon_spline_runs {
  std::vector<Cubic_spline_2<K>> splines;
  std::vector<std::size_t> first_vertex;
  double max_distance;
  /// The pieces of all runs in order (run 0 first).
  std::vector<typename Cubic_spline_2<K>::Piece> pieces() const {
    std::vector<typename Cubic_spline_2<K>::Piece> out;
    for (const Cubic_spline_2<K>& s : splines) {
      const std::vector<typename Cubic_spline_2<K>::Piece> p = s.pieces();
      out.insert(out.end(), p.begin(), p.end());
    }
    return out;
  }
  /// The runs as one NURBS (fair/Nurbs_curve_2.h; doc/nurbs.md): degree 3, single knots inside a
  /// run, multiplicity 3 at the corners (C0), each run's breakpoints shifted to start where the
  /// previous run ends; `closed` (the polygon's): the periodic form, its seam at the first corner
  /// (C0 there), or the one periodic run. \throws Precondition_error without runs.
  Nurbs_curve_2<K> nurbs(bool closed) const {
    return internal::nurbs::spline_runs_nurbs<K>(splines, closed, "fair::Polygon_spline_runs::nurbs");
  }
};

/// The C2 cubic interpolant of each run of `polygon` between consecutive `corners` (vertex
/// indices, any order; repeated indices and, for an open polygon, its two end vertices are
/// ignored): each run is fit_cubic_spline of its vertices as an open polygon (chordal, not-a-knot
/// ends; 2 vertices: the segment). At a corner the two runs meet with G0; each run's end tangent
/// is that of the not-a-knot cubic through its first vertices, which for an optimal polygon (its
/// first edge lies on the corner's tangent ray) approximates the corner tangent to O(h^2) of the
/// edge length h. No corners: fit_cubic_spline(polygon, closed) as the one run.
/// max_distance: the largest of the runs'.
/// \throws Invalid_input_error as fit_cubic_spline; Precondition_error for a corner index >= n.
/// Complexity O(n).
template <class K>
Polygon_spline_runs<K> fit_cubic_spline_runs(const std::vector<typename K::Point_2>& polygon, bool closed,
                                             std::vector<std::size_t> corners) {
  const std::size_t n = polygon.size();
  for (std::size_t c : corners)
    internal::require(c < n, "fair::fit_cubic_spline_runs: corner vertex ", c, " is not a vertex of the polygon of ", n,
                      " vertices");
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  if (!closed)
    corners.erase(std::remove_if(corners.begin(), corners.end(), [n](std::size_t c) { return c == 0 || c + 1 == n; }),
                  corners.end());
  Polygon_spline_runs<K> out{{}, {}, 0.0};
  if (corners.empty()) {
    Polygon_spline_fit<K> whole = fit_cubic_spline<K>(polygon, closed);
    out.splines.push_back(std::move(whole.spline));
    out.first_vertex.push_back(0);
    out.max_distance = whole.max_distance;
    return out;
  }
  std::vector<std::size_t> ends;  // run r from ends[r] to ends[r + 1]
  if (!closed) ends.push_back(0);
  ends.insert(ends.end(), corners.begin(), corners.end());
  if (closed) ends.push_back(corners.front() + n);  // wraps around
  else ends.push_back(n - 1);
  for (std::size_t r = 0; r + 1 < ends.size(); ++r) {
    std::vector<typename K::Point_2> run;
    for (std::size_t i = ends[r]; i <= ends[r + 1]; ++i) run.push_back(polygon[i % n]);
    Polygon_spline_fit<K> fit = fit_cubic_spline<K>(run, false);
    out.splines.push_back(std::move(fit.spline));
    out.first_vertex.push_back(ends[r] % n);
    out.max_distance = std::max(out.max_distance, fit.max_distance);
  }
  return out;
}

/// How fit_smoothing_spline_runs chose its smoothing, run by run (doc/optimal_curves.md, "The
/// smoothing spline").
struct Spline_smoothing_report {
  double tolerance = 0;  ///< the distance to the polygon asked for
  /// Per run: sigma / L^4 (L the run's chord length; scale-free): 0 when every vertex is interpolated.
  std::vector<double> smoothing;
  std::vector<int> solves;  ///< per run: linear solves of the bisection and the band steps (at most 40 together)
  bool tolerance_met = true;  ///< false when a run's interpolant of every vertex is already farther
};

/// The smoothing spline runs of a polygon and how they were chosen.
template <class K>
struct Polygon_smoothing_fit {
  Polygon_spline_runs<K> runs;
  Spline_smoothing_report report;
};

/// A C2 cubic smoothing spline through `polygon`, run by run between the `corners` (G0 there, as
/// fit_cubic_spline_runs), with a knot at every vertex (chordal breakpoints) that passes exactly
/// through the `interpolated` vertices (indices, any order, repeats ignored), the corners and their
/// two neighbours (so each run leaves a corner along its polygon edge), the two ends of an open
/// polygon, and elsewhere minimises
///   int |c''|^2 dt + sum_k hbar^3 |c(t_k) - v_k|^2 / (sigma a_k^2)   (Reinsch; a_k the mean
/// interval at vertex k, hbar the run's mean: the fit follows the polygon where it is fine),
/// with the largest sigma (bisection on log sigma; at most 40 solves per run with the band steps) whose distance to the
/// polygon (each piece from the edge it replaces, and |c(t_k) - v_k|) is <= `max_distance`, and
/// within 0.9 of it where the bisection reaches it; then up to 25 band steps re-weight the free
/// vertices one by one towards the band-constrained spline (every free vertex up to 0.9
/// max_distance away; internal/spline/smoothing_fit.h), each kept only within `max_distance`. Open runs have natural ends (c'' = 0),
/// closed ones without corners are periodic. max_distance = 0 gives the natural C2 interpolant of
/// every vertex. When that interpolant is already farther than `max_distance`, a run keeps it and
/// report.tolerance_met is false. Derivation: internal/spline/smoothing_fit.h and the doc.
/// \throws Invalid_input_error as fit_cubic_spline; Precondition_error for an index >= n or a
/// negative or non-finite max_distance. Complexity O(n) per solve (pentadiagonal Cholesky).
template <class K>
Polygon_smoothing_fit<K> fit_smoothing_spline_runs(const std::vector<typename K::Point_2>& polygon, bool closed,
                                                   std::vector<std::size_t> interpolated,
                                                   std::vector<std::size_t> corners, double max_distance) {
  using namespace internal::spline;
  typedef internal::optimal::Vec2 V;
  const char* fn = "fair::fit_smoothing_spline_runs";
  internal::require(std::isfinite(max_distance) && max_distance >= 0, fn, ": max_distance ", max_distance,
                    " must be finite and >= 0");
  const std::vector<V> raw = polygon_to_double<K>(polygon, closed, fn);
  const std::size_t n = polygon.size();
  for (std::size_t c : corners) internal::require(c < n, fn, ": corner vertex ", c, " is not a vertex of the polygon of ", n, " vertices");
  for (std::size_t c : interpolated)
    internal::require(c < n, fn, ": interpolated vertex ", c, " is not a vertex of the polygon of ", n, " vertices");
  const double scale = fit_scale(raw);
  const std::vector<V> p = scaled(raw, 1 / scale);
  corners = normalised_corners(std::move(corners), n, closed);
  std::vector<bool> hard(n, false);
  for (std::size_t c : interpolated) hard[c] = true;
  // At a corner the run's first edge is kept too (its other vertex interpolated): the optimal
  // polygon's edge at a CORNER lies on the constraint's tangent ray, and with the natural end the
  // run leaves the corner along it (doc/optimal_curves.md, "The smoothing spline").
  for (std::size_t c : corners) {
    hard[c] = true;
    hard[(c + 1) % n] = true;
    hard[(c + n - 1) % n] = true;
  }
  if (!closed) hard.front() = hard.back() = true;
  const Run_layout layout = run_layout(n, closed, corners);  // run r from ends[r] to ends[r + 1]
  const std::vector<std::size_t>& ends = layout.ends;
  const bool periodic = layout.periodic;
  Polygon_smoothing_fit<K> out{{{}, {}, 0.0}, {}};
  out.report.tolerance = max_distance;
  for (std::size_t r = 0; r + 1 < ends.size(); ++r) {
    std::vector<V> v;
    std::vector<bool> h;
    for (std::size_t i = ends[r]; i <= ends[r + 1]; ++i) {
      v.push_back(p[i % n]);
      h.push_back(hard[i % n]);
    }
    const std::vector<double> t = internal::optimal::chord_breakpoints(v, periodic, fn);
    const Smoothing_run fit = smoothing_fit_run(v, t, periodic, h, max_distance / scale);
    std::vector<std::array<Homogeneous_point<double>, 4>> b;
    b.reserve(fit.pieces.size());
    for (const std::array<V, 4>& piece : fit.pieces) {
      std::array<Homogeneous_point<double>, 4> q;
      for (std::size_t k = 0; k < 4; ++k) q[k] = Homogeneous_point<double>{piece[k][0], piece[k][1], 1.0};
      b.push_back(q);
    }
    std::vector<V> control;
    for (const Homogeneous_point<double>& c : control_from_bezier(t, b, periodic)) control.push_back(V{{c.x / c.w, c.y / c.w}});
    out.runs.splines.push_back(spline_from_control<K>(t, control, periodic, scale, fn));
    out.runs.first_vertex.push_back(ends[r] % n);
    out.runs.max_distance = std::max(out.runs.max_distance, scale * fit.distance);
    const double length = t.back() - t.front();
    out.report.smoothing.push_back(fit.sigma / (length * length * length * length));
    out.report.solves.push_back(fit.solves);
    out.report.tolerance_met = out.report.tolerance_met && fit.met;
  }
  return out;
}

/// The smoothing quintic runs of a polygon (pieces run after run, as fit_quintic_spline's) and how
/// they were chosen.
template <class K>
struct Polygon_smoothing_quintic_fit {
  Polygon_quintic_fit<K> fit;
  Spline_smoothing_report report;
};

/// A C4 quintic smoothing spline through `polygon`: fit_smoothing_spline_runs with the quintic's
/// energy (same runs, hard vertices, distance rule, bisection and band steps; natural ends
/// c''' = c'''' = 0 at the run ends, periodic without corners), minimising
///   int |c'''|^2 dt + sum_k hbar^5 |c(t_k) - v_k|^2 / (sigma a_k^2)
/// (internal/spline/smoothing_quintic.h; doc/optimal_curves.md, "The quintic smoothing spline").
/// max_distance = 0 gives the natural (periodic) C4 quintic interpolant of every vertex (closed:
/// fit_quintic_spline's; open: natural instead of clamped ends). Runs of 2 vertices: the segment.
/// report.smoothing is sigma / L^6. \throws as fit_smoothing_spline_runs. Complexity O(n) per solve
/// (banded Cholesky of half-bandwidth 5, cyclic when closed).
template <class K>
Polygon_smoothing_quintic_fit<K> fit_smoothing_quintic_runs(const std::vector<typename K::Point_2>& polygon,
                                                            bool closed, std::vector<std::size_t> interpolated,
                                                            std::vector<std::size_t> corners, double max_distance) {
  using namespace internal::spline;
  typedef internal::optimal::Vec2 V;
  const char* fn = "fair::fit_smoothing_quintic_runs";
  internal::require(std::isfinite(max_distance) && max_distance >= 0, fn, ": max_distance ", max_distance,
                    " must be finite and >= 0");
  const std::vector<V> raw = polygon_to_double<K>(polygon, closed, fn);
  const std::size_t n = polygon.size();
  for (std::size_t c : corners) internal::require(c < n, fn, ": corner vertex ", c, " is not a vertex of the polygon of ", n, " vertices");
  for (std::size_t c : interpolated)
    internal::require(c < n, fn, ": interpolated vertex ", c, " is not a vertex of the polygon of ", n, " vertices");
  const double scale = fit_scale(raw);
  const std::vector<V> p = scaled(raw, 1 / scale);
  corners = normalised_corners(std::move(corners), n, closed);
  std::vector<bool> hard(n, false);
  for (std::size_t c : interpolated) hard[c] = true;
  for (std::size_t c : corners) hard[c] = hard[(c + 1) % n] = hard[(c + n - 1) % n] = true;  // as the cubic
  if (!closed) hard.front() = hard.back() = true;
  const Run_layout layout = run_layout(n, closed, corners);
  Polygon_smoothing_quintic_fit<K> out{{{}, 0.0}, {}};
  out.report.tolerance = max_distance;
  for (std::size_t r = 0; r + 1 < layout.ends.size(); ++r) {
    std::vector<V> v;
    std::vector<bool> h;
    std::vector<std::size_t> index;
    for (std::size_t i = layout.ends[r]; i <= layout.ends[r + 1]; ++i) {
      v.push_back(p[i % n]);
      h.push_back(hard[i % n]);
      index.push_back(i % n);
    }
    const std::vector<double> t = internal::optimal::chord_breakpoints(v, layout.periodic, fn);
    Smoothing_run_of<6> fit;
    if (v.size() == 2) {  // the segment
      fit.pieces.push_back({{v[0], v[0], v[0], v[1], v[1], v[1]}});
      for (int k = 1; k < 5; ++k)
        for (int x = 0; x < 2; ++x) fit.pieces[0][k][x] = v[0][x] + (v[1][x] - v[0][x]) * k / 5;
    } else {
      fit = smoothing_fit_run_with<6>(v, t, layout.periodic, h, max_distance / scale, 5,
                                      [&](const std::vector<double>& d, std::vector<std::array<V, 6>>& pieces,
                                          std::vector<V>& y) { return smoothing_quintic_solve(v, t, layout.periodic, d, pieces, y); });
    }
    for (std::size_t i = 0; i < fit.pieces.size(); ++i) {
      std::vector<typename K::Point_2> q;
      for (std::size_t k = 0; k < 6; ++k) q.push_back(to_point<K>(V{{fit.pieces[i][k][0] * scale, fit.pieces[i][k][1] * scale}}));
      // the pieces of a hard vertex start and end at it exactly (in every kernel)
      if (h[i]) q.front() = polygon[index[i]];
      if (h[(i + 1) % v.size()]) q.back() = polygon[index[(i + 1) % v.size()]];
      out.fit.pieces.push_back(Bezier_2<K>(std::move(q)));
    }
    out.fit.max_distance = std::max(out.fit.max_distance, scale * fit.distance);
    const double length = t.back() - t.front();
    out.report.smoothing.push_back(fit.sigma / std::pow(length, 6));
    out.report.solves.push_back(fit.solves);
    out.report.tolerance_met = out.report.tolerance_met && fit.met;
  }
  return out;
}

/// The C4 quintic interpolant of `polygon` (same vertices, breakpoints and errors as
/// fit_cubic_spline); 2 vertices give the segment, open polygons of 3 .. 6 vertices reproduce
/// their interpolating polynomial (in the chord-length parameter).
template <class K>
Polygon_quintic_fit<K> fit_quintic_spline(const std::vector<typename K::Point_2>& polygon, bool closed) {
  using namespace internal::optimal;
  using internal::spline::polygon_to_double;
  using internal::spline::to_point;
  const char* fn = "fair::fit_quintic_spline";
  const std::vector<Vec2> raw = polygon_to_double<K>(polygon, closed, fn);
  const double scale = internal::spline::fit_scale(raw);  // as in fit_cubic_spline
  const std::vector<Vec2> p = internal::spline::scaled(raw, 1 / scale);
  const std::vector<double> t = chord_breakpoints(p, closed, fn);
  std::vector<Vec2> m, s;
  quintic_derivatives(p, t, closed, m, s);
  std::vector<std::array<Vec2, 6>> b = quintic_bezier_pieces(p, t, m, s);
  Polygon_quintic_fit<K> out{{}, scale * max_chord_distance(b)};
  for (std::array<Vec2, 6>& piece : b)
    for (Vec2& v : piece) v = {{v[0] * scale, v[1] * scale}};
  out.pieces.reserve(b.size());
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < b.size(); ++i) {
    std::vector<typename K::Point_2> q{polygon[i]};
    for (std::size_t k = 1; k < 5; ++k) q.push_back(to_point<K>(b[i][k]));
    q.push_back(polygon[(i + 1) % n]);
    out.pieces.push_back(Bezier_2<K>(std::move(q)));
  }
  return out;
}

} // namespace fair

#endif // FAIR_POLYGON_SPLINE_FIT_H
