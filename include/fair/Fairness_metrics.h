// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fairness metrics of a planar curve given as a std::vector of CurvePiece_2 pieces (joined end to
// start): fair::Bezier_2, the rational pieces (anything with control_points() and weights(),
// c = sum B_i w_i P_i / sum B_i w_i, w_i > 0) and any other model of the concept.
// The user manual is doc/fairness_metrics.md.
//
//  - curvature_profile: curvature against arc length samples;
//  - arc_length, bending_energy (int kappa^2 ds), curvature_variation_energy (int (dkappa/ds)^2 ds,
//    or int (dkappa/dt)^2 dt per piece): adaptive Gauss-Kronrod quadrature in double with an
//    error estimate (internal/metrics/quadrature.h), capped (Non_convergence_error);
//  - inflections and curvature_extrema: CERTIFIED for Bernstein-form pieces. The piece's
//    homogeneous form (X, Y, W) is converted exactly to rationals and
//        D = det(P, P', P'')                    (P = (X, Y, W); D = x'y'' - y'x'' when W = 1),
//        N = 2 (D' W + 3 D W') |A|^2 - 6 D W (A . A'),   A = (X'W - X W', Y'W - Y W'),
//    satisfy sign(kappa) = sign(D) and sign(dkappa/dt) = sign(N) wherever the piece is regular
//    (kappa = D W^3 / |A|^3). Their roots in [0,1] are isolated by fair::Bernstein_root_isolation
//    and the signs between roots are evaluated exactly, so the counts are exact for the curve
//    with exactly the given (double or rational) control points. Generic pieces fall back to
//    sampling (certified = false);
//  - max_circle_deviation: max | |c(t) - C| - r |, its candidates being the certified roots of
//    d/dt |c - C|^2 and the piece ends;
//  - hausdorff_distance: the discrete Hausdorff distance of two curves sampled to a tolerance.
// Curvature is undefined at a singular point (c' = 0): the quadratures throw Precondition_error
// when they meet one, and the certified features are only meaningful on regular pieces.

#ifndef FAIR_FAIRNESS_METRICS_H
#define FAIR_FAIRNESS_METRICS_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Bernstein_root_isolation.h>
#include <fair/Errors.h>
#include <fair/internal/metrics/pieces.h>
#include <fair/internal/metrics/quadrature.h>

#include <CGAL/Gmpq.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace fair {

/// Measure of the curvature variation energy.
enum class Energy_measure {
  ARC_LENGTH, ///< int (d kappa / ds)^2 ds: geometric, independent of the parametrisation
  PARAMETER   ///< sum over pieces of int_0^1 (d kappa / dt)^2 dt (Li's eq. 5)
};

/// One sample of the curvature profile.
struct Curvature_sample {
  std::size_t piece = 0;
  double t = 0;          ///< parameter in the piece
  double arc_length = 0; ///< arc length from the start of the curve
  double x = 0, y = 0;
  double curvature = 0;  ///< signed
};

/// One curvature feature (inflection or curvature extremum).
struct Curve_feature {
  std::size_t piece = 0;
  /// Parameter in the piece (within one ulp of the certified root when certified).
  double t = 0;
  /// Certified isolating interval of t (point interval when exact); [t,t] when not certified.
  Isolating_interval interval;
  double x = 0, y = 0;
  double curvature = 0;
  /// True when the feature sits at a join of two pieces (a sign change of the curvature across a
  /// join, only possible when the curve is not G2 there).
  bool at_joint = false;
};

/// The features of a curve and how far they can be trusted.
struct Feature_report {
  std::vector<Curve_feature> features;
  /// Pieces on which the defining polynomial vanishes identically: straight pieces for
  /// inflections, pieces of constant curvature (segments, circular arcs) for curvature extrema.
  std::vector<std::size_t> degenerate_pieces;
  /// True when every piece is in Bernstein form with exactly converted coordinates.
  bool certified = true;
  std::size_t count() const { return features.size(); }
};

namespace internal {

template <class Piece>
const char* metrics_check_curve(const std::vector<Piece>& curve, const char* what) {
  require(!curve.empty(), what, ": the curve has no piece");
  return what;
}

// Quadrature of f(jet) over every piece.
template <class Piece, class F>
Quadrature_estimate integrate_over_curve(const std::vector<Piece>& curve, F f, const Quadrature_options& o,
                                         const char* what) {
  metrics_check_curve(curve, what);
  Quadrature_estimate total;
  for (const Piece& piece : curve) {
    metrics::Piece_jet<Piece> jet(piece);
    total += metrics::adaptive_integral([&](double t) { return f(jet(t)); }, 0.0, 1.0, o, what);
  }
  return total;
}

/// Exact sign of a Gmpq polynomial at x.
inline int exact_sign_at(const Bernstein_polynomial<CGAL::Gmpq>& p, const CGAL::Gmpq& x) {
  return CGAL::sign(p.evaluate(x));
}

/// The roots of p in [0,1] with the sign of p on each gap between consecutive roots (and before
/// the first / after the last). gaps[k] is the sign on the gap just before root k
/// (gaps.size() == roots + 1); an empty gap (root at 0 or at 1) has sign 0.
struct Signed_roots {
  std::vector<Isolating_interval> roots;
  std::vector<double> approximations;
  std::vector<int> gaps;
};

inline Signed_roots signed_roots(const Bernstein_polynomial<CGAL::Gmpq>& p) {
  Signed_roots out;
  Bernstein_root_isolation iso(p);
  const std::size_t k = iso.number_of_roots();
  for (std::size_t i = 0; i < k; ++i) out.approximations.push_back(iso.root_approximation(i));
  out.roots = iso.intervals();
  const CGAL::Gmpq zero(0), one(1);
  for (std::size_t g = 0; g <= k; ++g) {
    // Find an exact rational strictly inside the gap between root g-1 and root g.
    int sign = 0;
    for (int attempt = 0; attempt < 200; ++attempt) {
      const std::vector<Isolating_interval>& R = iso.intervals();
      const bool has_prev = g > 0, has_next = g < k;
      if (has_prev && !has_next && R[g - 1].is_point() && R[g - 1].lower == one) break;  // empty gap at 1
      if (!has_prev && has_next && R[g].is_point() && R[g].lower == zero) break;        // empty gap at 0
      const CGAL::Gmpq left = has_prev ? R[g - 1].upper : zero;
      const CGAL::Gmpq right = has_next ? R[g].lower : one;
      CGAL::Gmpq x = (left + right) / 2;
      sign = exact_sign_at(p, x);
      if (sign != 0) break;
      // x is a root: it is the end of a neighbouring point interval; shrink the other neighbour.
      if (has_next && !R[g].is_point()) iso.refine(g, R[g].width() / 2);
      else if (has_prev && !R[g - 1].is_point()) iso.refine(g - 1, R[g - 1].width() / 2);
      else break;
    }
    out.gaps.push_back(sign);
  }
  out.roots = iso.intervals();
  return out;
}

inline Bernstein_polynomial<CGAL::Gmpq> dot2(const Bernstein_polynomial<CGAL::Gmpq>& ax, const Bernstein_polynomial<CGAL::Gmpq>& ay,
                                             const Bernstein_polynomial<CGAL::Gmpq>& bx, const Bernstein_polynomial<CGAL::Gmpq>& by) {
  return ax * bx + ay * by;
}

/// D = det(P, P', P'') of the homogeneous form (sign of the curvature).
template <class ET>
Bernstein_polynomial<ET> curvature_sign_polynomial(const metrics::Homogeneous_form<ET>& h) {
  const Bernstein_polynomial<ET> X1 = h.X.derivative(), Y1 = h.Y.derivative(), W1 = h.W.derivative();
  const Bernstein_polynomial<ET> X2 = X1.derivative(), Y2 = Y1.derivative(), W2 = W1.derivative();
  return h.X * (Y1 * W2 - W1 * Y2) - h.Y * (X1 * W2 - W1 * X2) + h.W * (X1 * Y2 - Y1 * X2);
}

/// N, with sign(N) = sign(d kappa / dt) on regular points (see the file comment).
template <class ET>
Bernstein_polynomial<ET> curvature_derivative_sign_polynomial(const metrics::Homogeneous_form<ET>& h) {
  const Bernstein_polynomial<ET> D = curvature_sign_polynomial(h);
  const Bernstein_polynomial<ET> X1 = h.X.derivative(), Y1 = h.Y.derivative(), W1 = h.W.derivative();
  const Bernstein_polynomial<ET> Ax = X1 * h.W - h.X * W1, Ay = Y1 * h.W - h.Y * W1;
  const Bernstein_polynomial<ET> Ax1 = Ax.derivative(), Ay1 = Ay.derivative();
  const Bernstein_polynomial<ET> A2 = Ax * Ax + Ay * Ay, AA1 = Ax * Ax1 + Ay * Ay1;
  return ET(2) * (D.derivative() * h.W + ET(3) * D * W1) * A2 - ET(6) * D * h.W * AA1;
}

inline bool is_zero_polynomial(const Bernstein_polynomial<CGAL::Gmpq>& p) {
  for (const CGAL::Gmpq& c : p.coefficients())
    if (!CGAL::is_zero(c)) return false;
  return true;
}

template <class Piece>
Curve_feature make_feature(const Piece& piece, std::size_t index, double t, const Isolating_interval& I, bool joint) {
  Curve_feature f;
  f.piece = index;
  f.t = t;
  f.interval = I;
  metrics::Piece_jet<Piece> jet(piece);
  const metrics::Jet j = jet(t);
  f.x = j.x;
  f.y = j.y;
  const double s2 = j.x1 * j.x1 + j.y1 * j.y1;
  f.curvature = s2 > 0 ? j.curvature() : 0.0;
  f.at_joint = joint;
  return f;
}

// Which polynomial: 0 = D (inflections), 1 = N (curvature extrema).
template <class Piece>
Feature_report certified_features(const std::vector<Piece>& curve, int which, const char* what) {
  metrics_check_curve(curve, what);
  Feature_report report;
  if constexpr (metrics::Piece_kind<Piece>::value == 0) {
    // Generic pieces: sign changes of kappa (or dkappa/dt) on 512 samples per piece.
    report.certified = false;
    int last = 0;
    for (std::size_t i = 0; i < curve.size(); ++i) {
      metrics::Piece_jet<Piece> jet(curve[i]);
      const int m = 512;
      for (int k = 0; k <= m; ++k) {
        const double t = double(k) / m;
        const metrics::Jet j = jet(t);
        const double v = which == 0 ? (j.x1 * j.y2 - j.y1 * j.x2) : j.curvature_derivative();
        const int s = (v > 0) - (v < 0);
        if (s != 0 && last != 0 && s != last) {
          Isolating_interval I;
          I.lower = CGAL::Gmpq(t);
          I.upper = CGAL::Gmpq(t);
          report.features.push_back(make_feature(curve[i], i, t, I, k == 0));
        }
        if (s != 0) last = s;
      }
    }
    return report;
  } else {
    int last = 0;          // last nonzero gap sign along the curve
    int first = 0;         // first nonzero gap sign along the curve
    for (std::size_t i = 0; i < curve.size(); ++i) {
      const metrics::Homogeneous_form<CGAL::Gmpq> h = metrics::homogeneous_exact(curve[i]);
      report.certified = report.certified && h.exact;
      const Bernstein_polynomial<CGAL::Gmpq> p =
          which == 0 ? curvature_sign_polynomial(h) : curvature_derivative_sign_polynomial(h);
      if (is_zero_polynomial(p)) {
        report.degenerate_pieces.push_back(i);
        continue;
      }
      const Signed_roots s = signed_roots(p);
      // A piece that certifies its own curvature extrema provides the interior ones; the signs
      // computed here still decide the changes at the joins.
      bool own = false;
      if constexpr (metrics::Has_own_curvature_extrema<Piece>::value) own = (which == 1);
      for (std::size_t g = 0; g < s.gaps.size(); ++g) {
        const int sign = s.gaps[g];
        if (sign == 0) continue;
        if (first == 0) first = sign;
        if (last != 0 && sign != last) {
          // The sign changed since the last nonempty gap: at root g-1 of this piece when it is an
          // interior one, otherwise across the join into this piece.
          if (g > 0) {
            const bool at_start = s.roots[g - 1].is_point() && CGAL::is_zero(s.roots[g - 1].lower);
            if (!own || at_start)
              report.features.push_back(make_feature(curve[i], i, s.approximations[g - 1], s.roots[g - 1], at_start));
          } else {
            Isolating_interval I;
            report.features.push_back(make_feature(curve[i], i, 0.0, I, true));
          }
        }
        last = sign;
      }
      if constexpr (metrics::Has_own_curvature_extrema<Piece>::value) {
        if (own) {
          for (const auto& x : curve[i].curvature_extrema()) {
            if (x.multiplicity % 2 == 0) continue; // no sign change of kappa': not an extremum
            Isolating_interval I;
            I.lower = x.t_lower;
            I.upper = x.t_upper;
            I.multiplicity = x.multiplicity;
            report.features.push_back(make_feature(curve[i], i, x.t, I, false));
          }
        }
      }
    }
    // A closed curve (last end point == first start point, exactly): the closing join too.
    if (first != 0 && last != first &&
        curve.back().control_points().back() == curve.front().control_points().front()) {
      Isolating_interval I;
      report.features.push_back(make_feature(curve.front(), 0, 0.0, I, true));
    }
    return report;
  }
}

// Sampling of a piece into a polyline with chord <= h (recursive bisection, depth-capped).
template <class Piece>
void sample_piece(const metrics::Piece_jet<Piece>& jet, double t0, double t1, double x0, double y0, double x1, double y1,
                  double h, int depth, std::vector<std::pair<double, double>>& out) {
  const double tm = 0.5 * (t0 + t1);
  const metrics::Jet m = jet(tm);
  const double chord = std::hypot(x1 - x0, y1 - y0);
  const double sag = std::hypot(m.x - 0.5 * (x0 + x1), m.y - 0.5 * (y0 + y1));
  if (depth >= 40 || (chord <= h && sag <= 0.25 * h)) {
    out.emplace_back(x1, y1);
    return;
  }
  sample_piece(jet, t0, tm, x0, y0, m.x, m.y, h, depth + 1, out);
  sample_piece(jet, tm, t1, m.x, m.y, x1, y1, h, depth + 1, out);
}

template <class Piece>
std::vector<std::pair<double, double>> sample_curve(const std::vector<Piece>& curve, double h) {
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i < curve.size(); ++i) {
    metrics::Piece_jet<Piece> jet(curve[i]);
    const metrics::Jet a = jet(0.0), b = jet(1.0);
    if (i == 0) out.emplace_back(a.x, a.y);
    else if (out.back().first != a.x || out.back().second != a.y) out.emplace_back(a.x, a.y);
    // Split each piece in 4 first so that a closed loop piece is not mistaken for a short chord.
    double tx = 0, px = a.x, py = a.y;
    for (int q = 1; q <= 4; ++q) {
      const double tq = q / 4.0;
      const metrics::Jet e = q == 4 ? b : jet(tq);
      sample_piece(jet, tx, tq, px, py, e.x, e.y, h, 0, out);
      tx = tq; px = e.x; py = e.y;
    }
  }
  return out;
}

inline double point_segment_distance(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
  double u = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0.0;
  u = std::min(1.0, std::max(0.0, u));
  return std::hypot(px - (ax + u * dx), py - (ay + u * dy));
}

/// max over the points of `a` of the distance to the polyline `b`, with a uniform grid.
inline double directed_polyline_distance(const std::vector<std::pair<double, double>>& a,
                                         const std::vector<std::pair<double, double>>& b) {
  if (b.size() == 1) {
    double best = 0;
    for (const auto& p : a) best = std::max(best, std::hypot(p.first - b[0].first, p.second - b[0].second));
    return best;
  }
  double xmin = b[0].first, xmax = xmin, ymin = b[0].second, ymax = ymin;
  for (const auto& p : b) {
    xmin = std::min(xmin, p.first); xmax = std::max(xmax, p.first);
    ymin = std::min(ymin, p.second); ymax = std::max(ymax, p.second);
  }
  const std::size_t segs = b.size() - 1;
  const double extent = std::max(xmax - xmin, ymax - ymin);
  const double side = std::max(1.0, std::ceil(std::sqrt(double(segs))));
  const double cell = extent > 0 ? extent / side : 1.0;
  const long nx = std::max(1L, long(std::floor((xmax - xmin) / cell)) + 1), ny = std::max(1L, long(std::floor((ymax - ymin) / cell)) + 1);
  std::vector<std::vector<std::size_t>> grid(std::size_t(nx * ny));
  auto cx = [&](double x) { return std::min(nx - 1, std::max(0L, long(std::floor((x - xmin) / cell)))); };
  auto cy = [&](double y) { return std::min(ny - 1, std::max(0L, long(std::floor((y - ymin) / cell)))); };
  for (std::size_t s = 0; s < segs; ++s) {
    const long i0 = cx(std::min(b[s].first, b[s + 1].first)), i1 = cx(std::max(b[s].first, b[s + 1].first));
    const long j0 = cy(std::min(b[s].second, b[s + 1].second)), j1 = cy(std::max(b[s].second, b[s + 1].second));
    for (long i = i0; i <= i1; ++i)
      for (long j = j0; j <= j1; ++j) grid[std::size_t(j * nx + i)].push_back(s);
  }
  // The nonempty cells; for each query they are visited in increasing order of their distance to
  // the query point, stopping as soon as that lower bound exceeds the best distance found: exact
  // (the true minimum over all segments) and O(C log C) per query for C nonempty cells.
  std::vector<long> cells;
  for (long c = 0; c < nx * ny; ++c)
    if (!grid[std::size_t(c)].empty()) cells.push_back(c);
  std::vector<std::pair<double, long>> order(cells.size());
  double result = 0;
  for (const auto& p : a) {
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const long i = cells[k] % nx, j = cells[k] / nx;
      const double x0 = xmin + double(i) * cell, y0 = ymin + double(j) * cell;
      const double dx = std::max({0.0, x0 - p.first, p.first - (x0 + cell)});
      const double dy = std::max({0.0, y0 - p.second, p.second - (y0 + cell)});
      order[k] = std::make_pair(std::hypot(dx, dy), cells[k]);
    }
    std::sort(order.begin(), order.end());
    double best = std::numeric_limits<double>::infinity();
    for (const auto& o : order) {
      // Segments are registered in every cell their bounding box meets (the last cells are clamped
      // to include the box edges), so the cell's lower bound holds for the segment parts inside it.
      if (o.first > best) break;
      for (std::size_t s : grid[std::size_t(o.second)])
        best = std::min(best, point_segment_distance(p.first, p.second, b[s].first, b[s].second, b[s + 1].first,
                                                     b[s + 1].second));
    }
    result = std::max(result, best);
  }
  return result;
}

} // namespace internal

/// Arc length of the curve, int |c'(t)| dt over every piece.
template <class Piece>
Quadrature_estimate arc_length(const std::vector<Piece>& curve, const Quadrature_options& options = Quadrature_options()) {
  return internal::integrate_over_curve(curve, [](const internal::metrics::Jet& j) { return j.speed(); }, options, "arc_length");
}

/// Bending (strain) energy int kappa^2 ds = sum over pieces of int_0^1 kappa(t)^2 |c'(t)| dt.
template <class Piece>
Quadrature_estimate bending_energy(const std::vector<Piece>& curve, const Quadrature_options& options = Quadrature_options()) {
  return internal::integrate_over_curve(
      curve, [](const internal::metrics::Jet& j) { const double k = j.curvature(); return k * k * j.speed(); }, options,
      "bending_energy");
}

/// Curvature variation energy: int (dkappa/ds)^2 ds = sum int_0^1 (dkappa/dt)^2 / |c'| dt
/// (Energy_measure::ARC_LENGTH), or sum int_0^1 (dkappa/dt)^2 dt (Energy_measure::PARAMETER, eq. 5
/// of Li's paper). Derivatives of order 3 are exact for Bernstein-form pieces.
template <class Piece>
Quadrature_estimate curvature_variation_energy(const std::vector<Piece>& curve,
                                               Energy_measure measure = Energy_measure::ARC_LENGTH,
                                               const Quadrature_options& options = Quadrature_options()) {
  if (measure == Energy_measure::ARC_LENGTH)
    return internal::integrate_over_curve(
        curve, [](const internal::metrics::Jet& j) { const double k = j.curvature_derivative(); return k * k / j.speed(); },
        options, "curvature_variation_energy");
  return internal::integrate_over_curve(
      curve, [](const internal::metrics::Jet& j) { const double k = j.curvature_derivative(); return k * k; }, options,
      "curvature_variation_energy");
}

/// Curvature against arc length at samples_per_piece + 1 uniform parameters of every piece (the
/// first sample of a piece after the first is the previous piece's end, so both one-sided values
/// at a join appear). Arc length by the adaptive quadrature of `options`.
/// \throws Precondition_error at a singular sample point.
template <class Piece>
std::vector<Curvature_sample> curvature_profile(const std::vector<Piece>& curve, std::size_t samples_per_piece = 64,
                                                const Quadrature_options& options = Quadrature_options()) {
  internal::metrics_check_curve(curve, "curvature_profile");
  internal::require(samples_per_piece >= 1, "curvature_profile: samples_per_piece must be >= 1");
  std::vector<Curvature_sample> out;
  double s = 0;
  Quadrature_options o = options;
  o.initial_subintervals = 1;
  for (std::size_t i = 0; i < curve.size(); ++i) {
    internal::metrics::Piece_jet<Piece> jet(curve[i]);
    double prev = 0;
    for (std::size_t k = 0; k <= samples_per_piece; ++k) {
      const double t = double(k) / double(samples_per_piece);
      if (k > 0)
        s += internal::metrics::adaptive_integral([&](double u) { return jet(u).speed(); }, prev, t, o, "curvature_profile").value;
      const internal::metrics::Jet j = jet(t);
      const double s2 = j.x1 * j.x1 + j.y1 * j.y1;
      internal::require(s2 > 0, "curvature_profile: singular point (c' = 0) on piece ", i, " at t = ", t);
      out.push_back(Curvature_sample{i, t, s, j.x, j.y, j.curvature()});
      prev = t;
    }
  }
  return out;
}

/// The inflections: the points where the signed curvature changes sign (odd-multiplicity roots of
/// D inside pieces, and sign changes across joins). Certified for Bernstein-form pieces
/// (see the file comment); an even-multiplicity root (curvature touching 0) is not an inflection.
template <class Piece>
Feature_report inflections(const std::vector<Piece>& curve) {
  return internal::certified_features(curve, 0, "inflections");
}

/// The curvature extrema: the points where dkappa/dt changes sign inside a piece or across a join
/// (a join where kappa is continuous but kappa' changes sign; a C1 join with a curvature jump is
/// reported only when the one-sided slopes differ in sign). Certified for Bernstein-form pieces.
template <class Piece>
Feature_report curvature_extrema(const std::vector<Piece>& curve) {
  return internal::certified_features(curve, 1, "curvature_extrema");
}

/// The largest deviation of a curve from a reference circle.
struct Circle_deviation {
  double max_deviation = 0; ///< max over the curve of | |c(t) - center| - radius |
  std::size_t piece = 0;    ///< where it is reached
  double t = 0;
  bool certified = true;    ///< candidates from certified root isolation (else 4096 samples per piece)
};

/// max | |c(t) - center| - radius | over the curve. For Bernstein-form pieces the candidates are the
/// piece ends and the certified roots of d/dt |c - C|^2 (numerator (B . B') W - |B|^2 W',
/// B = (X - Cx W, Y - Cy W)), so the maximum is exact up to rounding of the final evaluation.
template <class Piece>
Circle_deviation max_circle_deviation(const std::vector<Piece>& curve, const typename Piece::Point_2& center,
                                      double radius) {
  internal::metrics_check_curve(curve, "max_circle_deviation");
  internal::require(std::isfinite(radius) && radius >= 0, "max_circle_deviation: radius ", radius,
                    " must be finite and >= 0");
  Circle_deviation out;
  const double cx = CGAL::to_double(center.x()), cy = CGAL::to_double(center.y());
  for (std::size_t i = 0; i < curve.size(); ++i) {
    internal::metrics::Piece_jet<Piece> jet(curve[i]);
    std::vector<double> ts{0.0, 1.0};
    if constexpr (internal::metrics::Piece_kind<Piece>::value != 0) {
      typedef internal::metrics::Exact_rational_of<typename Piece::FT> Conv;
      const internal::metrics::Homogeneous_form<CGAL::Gmpq> h = internal::metrics::homogeneous_exact(curve[i]);
      out.certified = out.certified && h.exact && Conv::exact;
      const CGAL::Gmpq Cx = Conv::convert(center.x()), Cy = Conv::convert(center.y());
      const Bernstein_polynomial<CGAL::Gmpq> Bx = h.X - Cx * h.W, By = h.Y - Cy * h.W;
      const Bernstein_polynomial<CGAL::Gmpq> G =
          (Bx * Bx.derivative() + By * By.derivative()) * h.W - (Bx * Bx + By * By) * h.W.derivative();
      if (!internal::is_zero_polynomial(G)) {
        Bernstein_root_isolation iso(G);
        for (std::size_t k = 0; k < iso.number_of_roots(); ++k) ts.push_back(iso.root_approximation(k));
      } // else |c - C| is constant on the piece: the ends suffice
    } else {
      out.certified = false;
      for (int k = 1; k < 4096; ++k) ts.push_back(k / 4096.0);
    }
    for (double t : ts) {
      const internal::metrics::Jet j = jet(t);
      const double d = std::fabs(std::hypot(j.x - cx, j.y - cy) - radius);
      if (d > out.max_deviation || (i == 0 && t == 0.0)) {
        out.max_deviation = d;
        out.piece = i;
        out.t = t;
      }
    }
  }
  return out;
}

/// The discrete Hausdorff distance of two curves: both are sampled into polylines with chords
/// <= tolerance (and midpoint sagitta <= tolerance/4), and the result is the larger of the two
/// directed distances from the samples of one curve to the polyline of the other. For curves whose
/// pieces are sampled to that criterion the result is within about `tolerance` of the true
/// Hausdorff distance (the sampling of the source curve loses at most tolerance/2, the polyline
/// of the target deviates from it by about its sagitta).
template <class PieceA, class PieceB>
double hausdorff_distance(const std::vector<PieceA>& a, const std::vector<PieceB>& b, double tolerance) {
  internal::metrics_check_curve(a, "hausdorff_distance");
  internal::metrics_check_curve(b, "hausdorff_distance");
  internal::require(std::isfinite(tolerance) && tolerance > 0, "hausdorff_distance: tolerance ", tolerance,
                    " must be finite and > 0");
  const auto sa = internal::sample_curve(a, tolerance), sb = internal::sample_curve(b, tolerance);
  return std::max(internal::directed_polyline_distance(sa, sb), internal::directed_polyline_distance(sb, sa));
}

/// The headline fairness figures of a curve.
struct Fairness_report {
  std::size_t pieces = 0;
  Quadrature_estimate length, bending, curvature_variation;
  double min_curvature = 0, max_curvature = 0; ///< over the profile samples and the extrema
  std::size_t inflection_count = 0, curvature_extremum_count = 0;
  bool certified = true; ///< counts certified (see Feature_report::certified)
};

template <class Piece>
Fairness_report fairness_report(const std::vector<Piece>& curve, const Quadrature_options& options = Quadrature_options()) {
  Fairness_report r;
  r.pieces = curve.size();
  r.length = arc_length(curve, options);
  r.bending = bending_energy(curve, options);
  r.curvature_variation = curvature_variation_energy(curve, Energy_measure::ARC_LENGTH, options);
  const std::vector<Curvature_sample> prof = curvature_profile(curve, 64, options);
  r.min_curvature = r.max_curvature = prof.front().curvature;
  for (const Curvature_sample& s : prof) {
    r.min_curvature = std::min(r.min_curvature, s.curvature);
    r.max_curvature = std::max(r.max_curvature, s.curvature);
  }
  const Feature_report infl = inflections(curve), ext = curvature_extrema(curve);
  for (const Curve_feature& f : ext.features) {
    r.min_curvature = std::min(r.min_curvature, f.curvature);
    r.max_curvature = std::max(r.max_curvature, f.curvature);
  }
  r.inflection_count = infl.count();
  r.curvature_extremum_count = ext.count();
  r.certified = infl.certified && ext.certified;
  return r;
}

} // namespace fair

#endif // FAIR_FAIRNESS_METRICS_H
