// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The engine of fair::fit_smoothing_spline_runs (include/fair/Polygon_spline_fit.h): the C2 cubic
// smoothing spline of one run of polygon vertices v_0..v_N (closed: v_0..v_{n-1}, periodic) on
// the chord-length knots t_k, which interpolates the "hard" vertices exactly and minimises
//   J(c) = int |c''(t)|^2 dt + sum_{k free} w_k |c(t_k) - v_k|^2,   w_k = hbar^3 / (sigma a_k^2),
// a_k = (h_{k-1} + h_k) / 2 the mean interval at t_k, hbar the run's mean interval, h_k = t_{k+1} - t_k.
// The weight grows as the polygon is refined (w ~ 1/a^2): the adaptive polygon of an optimal
// curve is fine where its curvature varies fast (next to the input points), and there the fit
// must follow it; the trapezoid weight w ~ a (the discretised int |c - v|^2 dt) did the opposite
// and measured more inflections. Derivation (doc/optimal_curves.md, "The smoothing spline"):
// Reinsch's form. A cubic spline with values y_k and second derivatives g_k at
// the knots is C2 iff, at every interior knot j (closed: every knot, indices mod n),
//   (Q^T y)_j := (y_{j+1} - y_j)/h_j - (y_j - y_{j-1})/h_{j-1}
//             = h_{j-1} g_{j-1}/6 + (h_{j-1} + h_j) g_j/3 + h_j g_{j+1}/6 =: (R g)_j,
// and then int |c''|^2 = g^T R g. Open runs have natural ends (g_0 = g_N = 0): the minimiser over
// free end values and slopes has c'' = 0 there (the boundary term of the first variation).
// Minimising over y with g = R^{-1} Q^T y: W (v - y) = Q g on the free rows and y_k = v_k on the
// hard ones, i.e. y = v - D Q g with D = diag(1 / w_k) (0 on hard rows); substituted into
// Q^T y = R g:
//   (R + Q^T D Q) g = Q^T v,        y = v - D Q g,
// one symmetric positive definite (R is, Q^T D Q >= 0) pentadiagonal system per coordinate
// (cyclic when closed), solved by banded Cholesky (linear_algebra/symmetric_band.h): O(n).
// (Q g)_k is the jump of c''' at t_k, so the spline is C3 where a vertex is met (y_k = v_k).
// sigma = 0 gives the natural (periodic) C2 interpolant of every vertex.
//
// The smoothing weight sigma is chosen per run by bisection on log sigma so that the distance
// (max over pieces of the largest distance of the piece from the polygon edge it replaces, and
// over vertices of |c(t_k) - v_k|) is at most the tolerance and, when the bisection can, within
// [0.9, 1] of it: the most smoothing the tolerance allows. The distance refines a piece only when
// its Bezier hull can exceed the largest distance found so far (polygon_distance).
//
// Per-vertex weights (the band). The tolerance asks for the band-constrained spline
//   min int |c''|^2  subject to  |c(t_k) - v_k| <= tau at the free vertices, c(t_k) = v_k at the hard ones.
// Its Lagrangian int |c''|^2 + sum mu_k (|c(t_k) - v_k|^2 - tau^2), mu_k >= 0, is J with w_k = mu_k,
// so for fixed multipliers the minimiser is the smoothing spline above with d_k = 1/mu_k, whose
// residual is r_k = c(t_k) - v_k = -d_k (Q g)_k; complementary slackness asks |r_k| = tau wherever
// mu_k > 0, i.e. mu_k = |(Q g)_k| / tau: a fixed point of d_k <- d_k tau / |r_k|. A single sigma
// spends the tolerance only at the few vertices that bind (the weight law a_k^-2 is a guess of
// where the fit may move); after the bisection, smoothing_band_steps (25) damped steps
//   d_k <- d_k (tau / |r_k|)^(1/2),  the factor clamped to [1/4, 4],  tau = 0.9 tolerance,
// let every free vertex use it. A step is kept only when the whole distance (pieces included: a
// piece between two vertices at tau can bulge beyond it) stays within the tolerance; otherwise
// tau shrinks by 0.9 and the step is retried from the last kept weights. (No convergence proof:
// measured on the 117 Quick, Draw! strokes, doc/optimal_curves.md.)

#ifndef FAIR_INTERNAL_SPLINE_SMOOTHING_FIT_H
#define FAIR_INTERNAL_SPLINE_SMOOTHING_FIT_H

#include <fair/Errors.h>
#include <fair/internal/linear_algebra/symmetric_band.h>
#include <fair/internal/linear_algebra/tridiagonal.h>
#include <fair/internal/optimal/spline_fit.h>
#include <fair/internal/optimal/vec2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace spline {

/// Values y and second derivatives g at the knots of a C2 cubic spline (Reinsch form).
struct Reinsch_spline {
  std::vector<optimal::Vec2> y, g;
};

/// The smoothing spline of v on the knots t (open: t.size() == v.size(); closed: v.size() + 1,
/// t.back() closing the polygon) for d_k = 1 / w_k (0: v_k interpolated), as the
/// header derives, in `out`. False when the system is not positive definite to working precision
/// (it is, mathematically, for strictly increasing t; a large sigma drowns R in rounding).
inline bool smoothing_spline_solve(const std::vector<optimal::Vec2>& v, const std::vector<double>& t, bool closed,
                                   const std::vector<double>& d, Reinsch_spline& out) {
  const std::size_t nv = v.size();
  out = Reinsch_spline{v, std::vector<optimal::Vec2>(nv, optimal::Vec2{{0, 0}})};
  // Unknowns g_j: open j = 1..N-1 (row j - 1), closed j = 0..n-1 (row j).
  const std::size_t unknowns = closed ? nv : (nv >= 2 ? nv - 2 : 0);
  if (unknowns == 0) return true;  // two open vertices: the segment, y = v
  auto h = [&](long k) {          // h_k, periodic when closed
    const long m = static_cast<long>(t.size()) - 1;
    if (closed) k = ((k % m) + m) % m;
    return t[static_cast<std::size_t>(k) + 1] - t[static_cast<std::size_t>(k)];
  };
  auto knot = [&](long k) {  // knot index k (mod n when closed) -> row, or -1 if g_k is fixed at 0
    if (closed) return static_cast<long>(((k % static_cast<long>(nv)) + static_cast<long>(nv)) % static_cast<long>(nv));
    return (k >= 1 && k + 1 < static_cast<long>(nv)) ? k - 1 : -1L;
  };
  linear_algebra::Banded_symmetric a;
  a.reset(unknowns, 2, closed);
  // R: diagonal (h_{j-1} + h_j)/3, neighbours h_j / 6.
  for (std::size_t r = 0; r < unknowns; ++r) {
    const long j = closed ? static_cast<long>(r) : static_cast<long>(r) + 1;
    a.at(r, r) += (h(j - 1) + h(j)) / 3;
    const long next = knot(j + 1);
    if (next >= 0) a.at(r, static_cast<std::size_t>(next)) += h(j) / 6;  // closed: each cyclic pair once
  }
  // Q^T D Q = sum_k d_k q_k q_k^T, q_k the row of vertex k: 1/h_{k-1}, -(1/h_{k-1} + 1/h_k), 1/h_k at g_{k-1}, g_k, g_{k+1}.
  auto q_row = [&](long k, long (&idx)[3], double (&q)[3]) {
    const double il = (closed || k > 0) ? 1 / h(k - 1) : 0, ir = (closed || k + 1 < static_cast<long>(nv)) ? 1 / h(k) : 0;
    idx[0] = knot(k - 1);
    idx[1] = knot(k);
    idx[2] = knot(k + 1);
    q[0] = il;
    q[1] = -(il + ir);
    q[2] = ir;
  };
  for (std::size_t k = 0; k < nv; ++k) {
    if (!(d[k] > 0)) continue;
    long idx[3];
    double q[3];
    q_row(static_cast<long>(k), idx, q);
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j)
        if (idx[i] >= 0 && idx[j] >= 0)
          a.at(static_cast<std::size_t>(idx[i]), static_cast<std::size_t>(idx[j])) += d[k] * q[i] * q[j];
  }
  for (int c = 0; c < 2; ++c) {
    std::vector<double> rhs(unknowns, 0.0);  // Q^T v
    for (std::size_t k = 0; k < nv; ++k) {
      long idx[3];
      double q[3];
      q_row(static_cast<long>(k), idx, q);
      for (int i = 0; i < 3; ++i)
        if (idx[i] >= 0) rhs[static_cast<std::size_t>(idx[i])] += q[i] * v[k][static_cast<std::size_t>(c)];
    }
    if (!linear_algebra::solve_banded_positive_definite(a, rhs)) return false;
    for (std::size_t r = 0; r < unknowns; ++r) out.g[closed ? r : r + 1][static_cast<std::size_t>(c)] = rhs[r];
  }
  for (std::size_t k = 0; k < nv; ++k) {  // y = v - D Q g
    if (!(d[k] > 0)) continue;
    long idx[3];
    double q[3];
    q_row(static_cast<long>(k), idx, q);
    for (int c = 0; c < 2; ++c) {
      double qg = 0;
      for (int i = 0; i < 3; ++i)
        if (idx[i] >= 0) qg += q[i] * out.g[closed ? static_cast<std::size_t>(idx[i]) : static_cast<std::size_t>(idx[i]) + 1][static_cast<std::size_t>(c)];
      out.y[k][static_cast<std::size_t>(c)] -= d[k] * qg;
    }
  }
  // g again from y: R g = Q^T y (tridiagonal, strictly diagonally dominant: well conditioned), so
  // that the pieces of (y, g) are C2 to rounding whatever the condition of the system above (weights
  // spread over many orders, as the band steps make them, leave its g accurate only to ~1e-10; its
  // pieces then miss C1 by that much and the B-spline conversion moves the interpolated vertices).
  std::vector<double> ra(unknowns), rb(unknowns), rc(unknowns);
  for (std::size_t r = 0; r < unknowns; ++r) {
    const long j = closed ? static_cast<long>(r) : static_cast<long>(r) + 1;
    ra[r] = h(j - 1) / 6;
    rb[r] = (h(j - 1) + h(j)) / 3;
    rc[r] = h(j) / 6;
  }
  for (std::size_t c = 0; c < 2; ++c) {
    std::vector<double> qy(unknowns);
    for (std::size_t r = 0; r < unknowns; ++r) {
      const long j = closed ? static_cast<long>(r) : static_cast<long>(r) + 1;
      const std::size_t jm = static_cast<std::size_t>(closed ? (j + static_cast<long>(nv) - 1) % static_cast<long>(nv) : j - 1);
      const std::size_t jp = static_cast<std::size_t>(closed ? (j + 1) % static_cast<long>(nv) : j + 1);
      const std::size_t jj = static_cast<std::size_t>(j);
      qy[r] = (out.y[jp][c] - out.y[jj][c]) / h(j) - (out.y[jj][c] - out.y[jm][c]) / h(j - 1);
    }
    const std::vector<double> g = closed && unknowns >= 3 ? linear_algebra::solve_cyclic_tridiagonal(ra, rb, rc, qy)
                                  : closed ? std::vector<double>() : linear_algebra::solve_tridiagonal(ra, rb, rc, qy);
    if (g.empty()) continue;  // closed runs have >= 3 vertices (fit_smoothing_spline_runs); kept as solved
    for (std::size_t r = 0; r < unknowns; ++r) out.g[closed ? r : r + 1][c] = g[r];
  }
  return true;
}

/// The Bezier points of the pieces of s (piece i over [t_i, t_{i+1}]): with d = (y_{i+1} - y_i)/h,
/// c'(t_i+) = d - h (2 g_i + g_{i+1})/6 and c'(t_{i+1}-) = d + h (g_i + 2 g_{i+1})/6,
/// b_1 = y_i + h c'(t_i+)/3, b_2 = y_{i+1} - h c'(t_{i+1}-)/3.
inline std::vector<std::array<optimal::Vec2, 4>> reinsch_bezier_pieces(const Reinsch_spline& s,
                                                                       const std::vector<double>& t) {
  const std::size_t m = t.size() - 1, n = s.y.size();
  std::vector<std::array<optimal::Vec2, 4>> out(m);
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t j = (i + 1) % n;
    const double h = t[i + 1] - t[i];
    for (std::size_t c = 0; c < 2; ++c) {
      const double y0 = s.y[i][c], y1 = s.y[j][c], g0 = s.g[i][c], g1 = s.g[j][c], dd = (y1 - y0) / h;
      out[i][0][c] = y0;
      out[i][1][c] = y0 + h * (dd - h * (2 * g0 + g1) / 6) / 3;
      out[i][2][c] = y1 - h * (dd + h * (g0 + 2 * g1) / 6) / 3;
      out[i][3][c] = y1;
    }
  }
  return out;
}

/// The largest distance of a point of the piece b from the segment [e0, e1]: 32 samples, then
/// golden-section refinement around the largest (as optimal::piece_chord_distance).
template <std::size_t N>
double piece_edge_distance(const std::array<optimal::Vec2, N>& b, const optimal::Vec2& e0, const optimal::Vec2& e1) {
  return optimal::sampled_segment_distance(optimal::power_coefficients(b), e0, e1);
}

/// The largest squared distance of the Bezier points of b from the segment [e0, e1]: the square of
/// an upper bound of the piece's distance from it (convex hull; without hypot, which was half the
/// time of a band step).
template <std::size_t N>
double hull_bound_squared(const std::array<optimal::Vec2, N>& b, const optimal::Vec2& e0, const optimal::Vec2& e1) {
  const double ex = e1[0] - e0[0], ey = e1[1] - e0[1], l2 = ex * ex + ey * ey;
  double out = 0;
  for (const optimal::Vec2& x : b) {
    double s = l2 > 0 ? ((x[0] - e0[0]) * ex + (x[1] - e0[1]) * ey) / l2 : 0;
    s = std::min(1.0, std::max(0.0, s));
    const double dx = x[0] - e0[0] - s * ex, dy = x[1] - e0[1] - s * ey;
    out = std::max(out, dx * dx + dy * dy);
  }
  return out;
}

/// The distance of the smoothing spline's pieces (degree N - 1) to the polygon v: the largest of
/// the pieces' distances to their edges and of |c(t_k) - v_k|. A piece is refined only when the
/// distance of its farthest Bezier point from the edge exceeds the largest found so far: the
/// distance to a segment is convex and the piece lies in the convex hull of its Bezier points, so
/// that bound is an upper bound (most pieces are skipped; the result is the same).
template <std::size_t N>
double polygon_distance(const std::vector<std::array<optimal::Vec2, N>>& pieces, const std::vector<optimal::Vec2>& v) {
  double out = 0;
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < pieces.size(); ++i) {  // the vertices: |c(t_k) - v_k| (open: the last point of the last)
    const optimal::Vec2 &a = pieces[i][0], &b = pieces[i][N - 1], &p = v[i], &q = v[(i + 1) % n];
    out = std::max({out, std::hypot(a[0] - p[0], a[1] - p[1]), std::hypot(b[0] - q[0], b[1] - q[1])});
  }
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const optimal::Vec2 &e0 = v[i], &e1 = v[(i + 1) % n];
    // (the bound's rounding differs from the distance's: a piece within an ulp of `out` may be
    // searched or not, with the same result)
    if (hull_bound_squared(pieces[i], e0, e1) > out * out) out = std::max(out, piece_edge_distance(pieces[i], e0, e1));
  }
  return out;
}

/// Whether polygon_distance(pieces, v) <= tolerance, without its value: only the pieces whose
/// Bezier hull reaches beyond the tolerance are searched, and the first one beyond stops it (the
/// band steps need no more; most of their pieces are within the tolerance by their hull).
template <std::size_t N>
bool polygon_distance_within(const std::vector<std::array<optimal::Vec2, N>>& pieces,
                             const std::vector<optimal::Vec2>& v, double tolerance) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const optimal::Vec2 &a = pieces[i][0], &b = pieces[i][N - 1], &p = v[i], &q = v[(i + 1) % n];
    if (!(std::hypot(a[0] - p[0], a[1] - p[1]) <= tolerance && std::hypot(b[0] - q[0], b[1] - q[1]) <= tolerance))
      return false;
  }
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const optimal::Vec2 &e0 = v[i], &e1 = v[(i + 1) % n];
    if (hull_bound_squared(pieces[i], e0, e1) > tolerance * tolerance &&
        !(piece_edge_distance(pieces[i], e0, e1) <= tolerance))
      return false;
  }
  return true;
}

/// One run's fit (pieces of degree N - 1) and how its smoothing weight was found.
template <std::size_t N>
struct Smoothing_run_of {
  std::vector<std::array<optimal::Vec2, N>> pieces;
  double sigma = 0;     ///< the smoothing weight of the bisection (0: every vertex interpolated)
  double distance = 0;  ///< polygon_distance of the pieces
  int solves = 0;       ///< linear solves (bisection and band steps) spent
  bool met = true;      ///< distance <= tolerance
  std::vector<double> d;         ///< the inverse weights d_k = 1 / w_k used (0: interpolated)
  std::vector<double> residual;  ///< |c(t_k) - v_k|
};
typedef Smoothing_run_of<4> Smoothing_run;

/// The caps of the bisection: log10(sigma / L^(p+1)) in [-20, 0] (L the run's chord length, p = 3
/// cubic, 5 quintic; at 0 the free vertices barely pull: nearly the natural spline through the hard
/// ones, and larger sigma drowns the energy matrix in rounding), at most smoothing_max_solves
/// solves (bisection and band steps together), stopping once the distance is within [0.9, 1] of
/// the tolerance.
constexpr double smoothing_log_sigma_min = -20, smoothing_log_sigma_max = 0;
constexpr int smoothing_max_solves = 40;
/// The band steps after the bisection (file comment, "Per-vertex weights"): at most
/// smoothing_band_steps solves (and smoothing_max_solves in all), the residual aimed at smoothing_band_target of the tolerance (and
/// that factor again after a step that left the tolerance), each weight changed by at most
/// smoothing_band_clamp per step.
constexpr int smoothing_band_steps = 25;
constexpr double smoothing_band_target = 0.9, smoothing_band_clamp = 4;

/// The smoothing fit of one run (t: its chord breakpoints; hard[k]: v_k interpolated) with the
/// most smoothing whose distance to the polygon is <= tolerance, for the energy of order p
/// (3: the cubic's int |c''|^2; 5: the quintic's int |c'''|^2; the weights scale as h^-p).
/// solve(d, pieces, values) solves the smoothing system for the inverse weights d (false when it
/// is not positive definite to working precision). When even the interpolant of every vertex
/// (sigma = 0) is farther, that interpolant is returned with met = false.
template <std::size_t N, class Solve>
Smoothing_run_of<N> smoothing_fit_run_with(const std::vector<optimal::Vec2>& v, const std::vector<double>& t, bool closed,
                                           const std::vector<bool>& hard, double tolerance, int p, Solve solve) {
  typedef Smoothing_run_of<N> Run;
  const std::size_t n = v.size();
  const double length = t.back() - t.front();
  std::vector<double> a(n), d(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double hl = (closed || k > 0) ? t[k > 0 ? k : t.size() - 1] - t[k > 0 ? k - 1 : t.size() - 2] : 0;
    const double hr = (closed || k + 1 < n) ? t[k + 1] - t[k] : 0;
    a[k] = (hl + hr) / 2;
  }
  const double mean = length / static_cast<double>(t.size() - 1);
  const double unit_weight = std::pow(mean, p), unit = std::pow(length, p + 1);
  Run out;
  // One solve with the inverse weights dd: the pieces, their distance (exact, or with `within` only
  // whether it is <= tolerance: 0 then, else infinity) and the residuals in r.
  auto solve_with = [&](const std::vector<double>& dd, Run& r, bool within = false) {
    std::vector<optimal::Vec2> y;
    ++out.solves;
    r.distance = std::numeric_limits<double>::infinity();  // too much smoothing for double: not taken
    if (!solve(dd, r.pieces, y)) return false;
    if (within) r.distance = polygon_distance_within(r.pieces, v, tolerance) ? 0 : std::numeric_limits<double>::infinity();
    else r.distance = polygon_distance(r.pieces, v);
    r.d = dd;
    r.residual.resize(n);
    for (std::size_t k = 0; k < n; ++k) r.residual[k] = std::hypot(y[k][0] - v[k][0], y[k][1] - v[k][1]);
    return true;
  };
  auto evaluate = [&](double sigma, Run& r) {
    for (std::size_t k = 0; k < n; ++k) d[k] = (hard[k] || !(sigma > 0)) ? 0 : sigma * a[k] * a[k] / unit_weight;
    const bool solved = solve_with(d, r);
    if (!solved && !(sigma > 0))
      optimal::interpolant_unsolvable(t, p == 3 ? "fair::fit_smoothing_spline_runs" : "fair::fit_smoothing_quintic_runs",
                                      p == 3 ? "cubic" : "quintic");
    r.sigma = sigma;
  };
  evaluate(0, out);
  if (!(tolerance > 0)) return out;  // interpolation of every vertex asked for
  if (!(out.distance <= tolerance)) {
    out.met = false;
    return out;
  }
  Run best = out, trial;
  double lo = smoothing_log_sigma_min, hi = smoothing_log_sigma_max;
  evaluate(unit * std::pow(10.0, hi), trial);
  if (trial.distance <= tolerance) best = trial;
  else
    while (out.solves < smoothing_max_solves && !(best.sigma > 0 && best.distance >= 0.9 * tolerance)) {
      const double mid = 0.5 * (lo + hi);
      evaluate(unit * std::pow(10.0, mid), trial);
      if (trial.distance <= tolerance) {
        lo = mid;
        best = trial;
      } else {
        hi = mid;
      }
    }
  // The band (file comment, "Per-vertex weights"): d_k <- d_k (tau / r_k)^(1/2), each step
  // accepted only when the whole distance stays within the tolerance, else tau shrinks.
  double target = smoothing_band_target * tolerance;
  Run current = best;
  for (int it = 0; it < smoothing_band_steps && best.sigma > 0 && out.solves < smoothing_max_solves; ++it) {
    for (std::size_t k = 0; k < n; ++k) {
      if (!(current.d[k] > 0)) {
        d[k] = 0;
        continue;
      }
      const double f = std::sqrt(target / std::max(current.residual[k], 1e-6 * tolerance));
      d[k] = current.d[k] * std::min(smoothing_band_clamp, std::max(1 / smoothing_band_clamp, f));
    }
    solve_with(d, trial, true);
    if (trial.distance <= tolerance) {
      best = trial;
      current = trial;
    } else {
      target *= smoothing_band_target;
    }
  }
  if (best.distance == 0) best.distance = polygon_distance(best.pieces, v);  // a band step's value, once
  best.solves = out.solves;
  best.met = true;
  return best;
}

/// The cubic smoothing spline of one run (smoothing_fit_run_with, p = 3, Reinsch's system).
inline Smoothing_run smoothing_fit_run(const std::vector<optimal::Vec2>& v, const std::vector<double>& t, bool closed,
                                       const std::vector<bool>& hard, double tolerance) {
  return smoothing_fit_run_with<4>(v, t, closed, hard, tolerance, 3,
                                   [&](const std::vector<double>& d, std::vector<std::array<optimal::Vec2, 4>>& pieces,
                                       std::vector<optimal::Vec2>& y) {
                                     Reinsch_spline s;
                                     if (!smoothing_spline_solve(v, t, closed, d, s)) return false;
                                     pieces = reinsch_bezier_pieces(s, t);
                                     y = s.y;
                                     return true;
                                   });
}

} // namespace spline
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_SPLINE_SMOOTHING_FIT_H
