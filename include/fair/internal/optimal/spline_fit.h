// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Interpolating splines through every vertex of a polygon (issue 11 §4, the CAD output of the
// optimal curves), in double. The derivations are in doc/optimal_curves.md.
//
// Parameter: cumulative chord length, t_0 = 0, t_{i+1} = t_i + |p_{i+1} - p_i| (closed: one more
// interval p_{n-1} -> p_0). For a polygon sampled densely from a smooth curve the chord length
// approximates arc length to O(h^3) per edge, which keeps the fits O(h^4) (cubic) and better
// (quintic); uniform parameters would not on non-uniform polygons.
//
// Cubic (C2): the chordal interpolating cubic spline, not-a-knot ends (open, from
// fair::Cubic_interpolating_spline_2) or periodic (closed, solved for its B-spline control points
// in internal/spline/polygon_fit.h), in double (fair::fit_cubic_spline).
//
// Quintic (C4): piecewise quintic Hermite in (p_i, m_i, s_i) (value, first and second
// derivative at the knots, so C2 by construction); the m_i, s_i minimise the sum over pieces of
// int |c'''|^2 dt, whose stationarity conditions are exactly the continuity of c''' and c''''
// at the free knots (integration by parts). Open ends are clamped: m, s at t_0 (t_m) are the
// derivatives of the polynomial interpolating the first (last) min(6, n) vertices (error
// O(h^5), O(h^4): the fit stays O(h^6)). The system is symmetric positive definite with
// half-bandwidth 3 in the unknowns (m_0, H_0 s_0, m_1, H_1 s_1, ...), H_i the mean adjacent
// interval: banded Cholesky, O(n). Closed: A = B + W M W^T with B the open chain of the pieces
// 0..n-2 (positive definite for n >= 3: a quadratic vanishing at 3 points is 0) and M the 4x4
// matrix of the closing piece; Sherman-Morrison-Woodbury with 4 extra banded solves, O(n).
//
// Distance: for each piece, the largest distance of a point of the piece to the polygon edge
// it replaces. Cubic pieces that project inside their edge: in closed form (the extrema of a
// cubic, cubic_chord_distance_closed_form). Otherwise (the piece evaluated by Horner in the
// power basis), from 32 uniform samples refined by golden-section search around the largest
// (40 steps: the location to 1e-9 of the piece, the value to ~1e-16 relative); it misses a
// maximum only if the distance has two bumps closer than 1/32 of the piece apart.

#ifndef FAIR_INTERNAL_OPTIMAL_SPLINE_FIT_H
#define FAIR_INTERNAL_OPTIMAL_SPLINE_FIT_H

#include <fair/Errors.h>
#include <fair/internal/linear_algebra/banded_cholesky.h>
#include <fair/internal/optimal/vec2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {


/// Samples per piece of the distance measurement (see the header comment).
constexpr int fit_distance_samples = 32;
/// Golden-section steps refining the largest sample (0.618^40 ~ 4e-9 of the bracket).
constexpr int fit_distance_refinements = 40;
/// Vertices of the polynomial that clamps an open quintic end (degree 5: O(h^6) fit).
constexpr std::size_t quintic_end_points = 6;

/// Cumulative chord-length breakpoints (size n + 1 open, n + 1 closed with the closing edge).
/// Throws Invalid_input_error for a zero-length edge (in double), one too short to advance the
/// breakpoint it starts at, or a non-finite length.
inline std::vector<double> chord_breakpoints(const std::vector<Vec2>& p, bool closed, const char* fn) {
  const std::size_t n = p.size(), edges = closed ? n : n - 1;
  std::vector<double> t(1, 0.0);
  t.reserve(edges + 1);
  for (std::size_t i = 0; i < edges; ++i) {
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % n];
    const double h = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (!(h > 0) || !std::isfinite(h) || !std::isfinite(t.back() + h))
      throw Invalid_input_error(message(fn, ": edge ", i, " from (", a[0], ", ", a[1], ") to (", b[0], ", ", b[1],
                                        ") has length ", h, " (vertices must be distinct and finite in double)"));
    // An edge shorter than the rounding of the breakpoint before it would give two equal breakpoints
    // (a piece of length 0: 1/h infinite in every system built on t).
    if (!(t.back() + h > t.back()))
      throw Invalid_input_error(message(fn, ": edge ", i, " from (", a[0], ", ", a[1], ") to (", b[0], ", ", b[1],
                                        ") has length ", h, ", below the resolution of double at the chord parameter ",
                                        t.back(), " it starts at: its vertices coincide to working precision"));
    t.push_back(t.back() + h);
  }
  return t;
}

/// A spline interpolant on strictly increasing breakpoints t is positive definite, but its system
/// is built from powers of 1/h: edges spread over too many orders of magnitude (vertices that
/// coincide to working precision, with long edges elsewhere) leave it singular in double.
/// Throws Invalid_input_error naming the shortest edge against the length (`what`: "cubic" or
/// "quintic").
[[noreturn]] inline void interpolant_unsolvable(const std::vector<double>& t, const char* fn, const char* what) {
  std::size_t shortest = 0;
  for (std::size_t i = 1; i + 1 < t.size(); ++i)
    if (t[i + 1] - t[i] < t[shortest + 1] - t[shortest]) shortest = i;
  const double length = t.back() - t.front();
  throw Invalid_input_error(message(fn, ": the interpolating ", what, " of ", t.size() - 1,
                                    " edges is singular to working precision: its edge ", shortest, " is ",
                                    (t[shortest + 1] - t[shortest]) / length,
                                    " of the length (vertices that close together are not resolved; merge them)"));
}

/// The 6x6 matrix of int_0^1 (q'''(u))^2 du for the quintic Hermite piece q with the data
/// v = (p0, p1, a0, b0, a1, b1) (a = q'(0 or 1), b = q''(0 or 1) in u): q''' = 6 c3 + 24 c4 u +
/// 60 c5 u^2 with c3 = 10D - 4E + G/2, c4 = -15D + 7E - G, c5 = 6D - 3E + G/2, D = p1 - p0 - a0 -
/// b0/2, E = a1 - a0 - b0, G = b1 - b0 (the Taylor coefficients matching p1, a1, b1 at u = 1).
inline std::array<std::array<double, 6>, 6> quintic_jerk_matrix() {
  const double D[6] = {-1, 1, -1, -0.5, 0, 0}, E[6] = {0, 0, -1, -1, 1, 0}, G[6] = {0, 0, 0, -1, 0, 1};
  double C3[6], C4[6], C5[6];
  for (int k = 0; k < 6; ++k) {
    C3[k] = 10 * D[k] - 4 * E[k] + 0.5 * G[k];
    C4[k] = -15 * D[k] + 7 * E[k] - G[k];
    C5[k] = 6 * D[k] - 3 * E[k] + 0.5 * G[k];
  }
  // 3-point Gauss-Legendre on [0, 1]: exact for the degree-4 integrand.
  const double r = std::sqrt(0.6);
  const double nodes[3] = {0.5 * (1 - r), 0.5, 0.5 * (1 + r)}, weights[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  std::array<std::array<double, 6>, 6> M{};
  for (int q = 0; q < 3; ++q) {
    const double u = nodes[q];
    double w[6];
    for (int k = 0; k < 6; ++k) w[k] = 6 * C3[k] + 24 * C4[k] * u + 60 * C5[k] * u * u;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) M[i][j] += weights[q] * w[i] * w[j];
  }
  return M;
}

/// Value, first and second derivative at `at` of the polynomial interpolating p[first ..
/// first + k) at t[first ..] (Newton's divided differences; k >= 2).
inline void polynomial_end_jet(const std::vector<Vec2>& p, const std::vector<double>& t, std::size_t first,
                               std::size_t k, double at, Vec2& d1, Vec2& d2) {
  std::vector<Vec2> dd(p.begin() + static_cast<std::ptrdiff_t>(first),
                       p.begin() + static_cast<std::ptrdiff_t>(first + k));
  std::vector<Vec2> coef(k);
  coef[0] = dd[0];
  for (std::size_t level = 1; level < k; ++level) {
    for (std::size_t i = 0; i + level < k; ++i)
      for (int c = 0; c < 2; ++c)
        dd[i][c] = (dd[i + 1][c] - dd[i][c]) / (t[first + i + level] - t[first + i]);
    coef[level] = dd[0];
  }
  double w = 1, w1 = 0, w2 = 0; // omega_j and its derivatives at `at`
  d1 = Vec2{{0, 0}};
  d2 = Vec2{{0, 0}};
  for (std::size_t j = 0; j < k; ++j) {
    for (int c = 0; c < 2; ++c) {
      d1[c] += coef[j][c] * w1;
      d2[c] += coef[j][c] * w2;
    }
    const double x = at - t[first + j];
    w2 = w2 * x + 2 * w1;
    w1 = w1 * x + w;
    w *= x;
  }
}

/// First and second derivatives (m_i, s_i) at the knots of the C4 quintic interpolant
/// (open n >= 2, closed n >= 3). Throws Internal_error if the SPD system is not (cannot happen
/// for distinct parameters: see the header comment).
inline void quintic_derivatives(const std::vector<Vec2>& p, const std::vector<double>& t, bool closed,
                                std::vector<Vec2>& m, std::vector<Vec2>& s) {
  const std::size_t n = p.size(), edges = t.size() - 1;
  m.assign(n, Vec2{{0, 0}});
  s.assign(n, Vec2{{0, 0}});
  std::vector<double> h(edges), H(n);
  for (std::size_t i = 0; i < edges; ++i) h[i] = t[i + 1] - t[i];
  for (std::size_t i = 0; i < n; ++i) {
    const bool has_left = closed || i > 0, has_right = closed || i < edges;
    const double left = has_left ? h[(i + edges - 1) % edges] : h[0];
    const double right = has_right ? h[i % edges] : h[edges - 1];
    H[i] = 0.5 * (left + right);
  }
  if (!closed) { // clamped ends from the end polynomials
    const std::size_t k = std::min(quintic_end_points, n);
    polynomial_end_jet(p, t, 0, k, t[0], m[0], s[0]);
    polynomial_end_jet(p, t, n - k, k, t[n - 1], m[n - 1], s[n - 1]);
    if (n == 2) return;
  }
  // Unknown numbering: knot j -> 2 (j - offset), 2 (j - offset) + 1; open: knots 1..n-2.
  const std::size_t offset = closed ? 0 : 1, knots = closed ? n : n - 2, size = 2 * knots;
  auto unknown = [&](std::size_t knot, int which) -> long {
    if (!closed && (knot == 0 || knot == n - 1)) return -1;
    return static_cast<long>(2 * (knot - offset) + static_cast<std::size_t>(which));
  };
  const std::array<std::array<double, 6>, 6> M = quintic_jerk_matrix();
  linear_algebra::Banded_cholesky B;
  B.reset(size, 3);
  std::array<std::vector<double>, 2> rhs{{std::vector<double>(size, 0.0), std::vector<double>(size, 0.0)}};
  std::array<std::array<double, 4>, 4> closing{}; // the closing piece's block (closed only)
  for (std::size_t i = 0; i < edges; ++i) {
    const std::size_t j = (i + 1) % n;
    const double hi = h[i], scale = 1 / (hi * hi * hi * hi * hi);
    // z = (p0, p1, m0, sigma0, m1, sigma1), v = S z
    const double S[6] = {1, 1, hi, hi * hi / H[i], hi, hi * hi / H[j]};
    const std::size_t knot_of[6] = {i, j, i, i, j, j};
    const int which[6] = {0, 0, 0, 1, 0, 1};
    double K[6][6];
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) K[a][b] = S[a] * M[a][b] * S[b] * scale;
    const bool is_closing = closed && i + 1 == edges;
    for (int a = 2; a < 6; ++a) {
      const long ua = unknown(knot_of[a], which[a]);
      if (ua < 0) continue;
      for (int c = 0; c < 2; ++c) { // known data: the points, and the clamped end derivatives
        double r = -K[a][0] * p[i][c] - K[a][1] * p[j][c];
        for (int b = 2; b < 6; ++b)
          if (unknown(knot_of[b], which[b]) < 0) {
            const Vec2& known = which[b] == 0 ? m[knot_of[b]] : s[knot_of[b]];
            r -= K[a][b] * known[c] * (which[b] == 1 ? H[knot_of[b]] : 1.0);
          }
        rhs[c][static_cast<std::size_t>(ua)] += r;
      }
      for (int b = 2; b < 6; ++b) {
        const long ub = unknown(knot_of[b], which[b]);
        if (ub < 0) continue;
        if (is_closing) closing[a - 2][b - 2] = K[a][b];
        else if (ua >= ub) B.add_lower(static_cast<std::size_t>(ua), static_cast<std::size_t>(ub), K[a][b]);
      }
    }
  }
  // Positive definite for distinct breakpoints, but not always to working precision: an edge of a
  // few ulps of the length beside long ones (review of session 19) leaves a non-positive pivot.
  if (!B.factor()) interpolant_unsolvable(t, "fair::fit_quintic_spline", "quintic");
  std::array<std::vector<double>, 2> x = rhs;
  for (int c = 0; c < 2; ++c) B.solve(x[c].data());
  if (closed) {
    // A = B + W M W^T, W picks the unknowns of knots n-1 (rows 0, 1 of `closing`) and 0 (rows 2, 3).
    const std::size_t pick[4] = {2 * (n - 1), 2 * (n - 1) + 1, 0, 1};
    std::array<std::vector<double>, 4> Z;
    for (int q = 0; q < 4; ++q) {
      Z[q].assign(size, 0.0);
      Z[q][pick[q]] = 1;
      B.solve(Z[q].data());
    }
    // capacitance C = I + M W^T Z (4x4), solved densely with partial pivoting
    double C[4][4];
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        double v = a == b ? 1.0 : 0.0;
        for (int q = 0; q < 4; ++q) v += closing[a][q] * Z[b][pick[q]];
        C[a][b] = v;
      }
    for (int c = 0; c < 2; ++c) {
      double y[4], A[4][5];
      for (int a = 0; a < 4; ++a) {
        double v = 0;
        for (int q = 0; q < 4; ++q) v += closing[a][q] * x[c][pick[q]];
        for (int b = 0; b < 4; ++b) A[a][b] = C[a][b];
        A[a][4] = v;
      }
      for (int col = 0; col < 4; ++col) {
        int best = col;
        for (int r = col + 1; r < 4; ++r)
          if (std::fabs(A[r][col]) > std::fabs(A[best][col])) best = r;
        if (!(std::fabs(A[best][col]) > 0)) interpolant_unsolvable(t, "fair::fit_quintic_spline", "quintic");
        for (int k = 0; k < 5; ++k) std::swap(A[col][k], A[best][k]);
        for (int r = col + 1; r < 4; ++r) {
          const double f = A[r][col] / A[col][col];
          for (int k = col; k < 5; ++k) A[r][k] -= f * A[col][k];
        }
      }
      for (int r = 3; r >= 0; --r) {
        double v = A[r][4];
        for (int k = r + 1; k < 4; ++k) v -= A[r][k] * y[k];
        y[r] = v / A[r][r];
      }
      for (std::size_t u = 0; u < size; ++u)
        for (int q = 0; q < 4; ++q) x[c][u] -= Z[q][u] * y[q];
    }
  }
  for (std::size_t j = 0; j < n; ++j) {
    if (unknown(j, 0) < 0) continue;
    const std::size_t u = static_cast<std::size_t>(unknown(j, 0));
    for (int c = 0; c < 2; ++c) {
      m[j][c] = x[c][u];
      s[j][c] = x[c][u + 1] / H[j];
    }
  }
}

/// The Bezier points of the quintic Hermite pieces: b1 = p0 + a0/5, b2 = p0 + 2 a0/5 + b0/20
/// (a = h m, b = h^2 s) and mirrored at the end.
inline std::vector<std::array<Vec2, 6>> quintic_bezier_pieces(const std::vector<Vec2>& p, const std::vector<double>& t,
                                                              const std::vector<Vec2>& m, const std::vector<Vec2>& s) {
  const std::size_t n = p.size(), edges = t.size() - 1;
  std::vector<std::array<Vec2, 6>> out(edges);
  for (std::size_t i = 0; i < edges; ++i) {
    const std::size_t j = (i + 1) % n;
    const double h = t[i + 1] - t[i];
    std::array<Vec2, 6>& b = out[i];
    b[0] = p[i];
    b[5] = p[j];
    for (int c = 0; c < 2; ++c) {
      b[1][c] = p[i][c] + h * m[i][c] / 5;
      b[2][c] = p[i][c] + 2 * h * m[i][c] / 5 + h * h * s[i][c] / 20;
      b[3][c] = p[j][c] - 2 * h * m[j][c] / 5 + h * h * s[j][c] / 20;
      b[4][c] = p[j][c] - h * m[j][c] / 5;
    }
  }
  return out;
}

/// de Casteljau in double.
template <std::size_t N>
Vec2 bezier_point(const std::array<Vec2, N>& b, double u) {
  std::array<Vec2, N> w = b;
  for (std::size_t r = 1; r < N; ++r)
    for (std::size_t i = 0; i + r < N; ++i)
      for (int c = 0; c < 2; ++c) w[i][c] = (1 - u) * w[i][c] + u * w[i + 1][c];
  return w[0];
}

/// Distance of x to the segment [a, b].
inline double distance_to_segment(const Vec2& x, const Vec2& a, const Vec2& b) {
  const double ex = b[0] - a[0], ey = b[1] - a[1], l2 = ex * ex + ey * ey;
  double s = l2 > 0 ? ((x[0] - a[0]) * ex + (x[1] - a[1]) * ey) / l2 : 0;
  s = std::min(1.0, std::max(0.0, s));
  return std::hypot(x[0] - a[0] - s * ex, x[1] - a[1] - s * ey);
}

/// The largest distance of a point of the piece to its chord b.front() b.back() (see the header).
/// The power-basis coefficients a_k of a Bezier piece of degree N - 1 (c(u) = sum a_k u^k):
/// a_k = C(n, k) sum_i (-1)^(k-i) C(k, i) b_i. For degree <= 5 the cancellation costs at most
/// a few bits of the extent; used for the many evaluations of the distance search (Horner).
template <std::size_t N>
std::array<Vec2, N> power_coefficients(const std::array<Vec2, N>& b) {
  const std::size_t n = N - 1;
  std::array<Vec2, N> a{};
  double cnk = 1; // C(n, k)
  for (std::size_t k = 0; k <= n; ++k) {
    double cki = 1, sign = (k % 2 == 0) ? 1.0 : -1.0; // C(k, i) (-1)^(k-i), i = 0
    Vec2 sum{{0, 0}};
    for (std::size_t i = 0; i <= k; ++i) {
      for (int c = 0; c < 2; ++c) sum[c] += sign * cki * b[i][c];
      cki = cki * static_cast<double>(k - i) / static_cast<double>(i + 1);
      sign = -sign;
    }
    for (int c = 0; c < 2; ++c) a[k][c] = cnk * sum[c];
    cnk = cnk * static_cast<double>(n - k) / static_cast<double>(k + 1);
  }
  return a;
}

/// The largest distance of a cubic piece to its chord in closed form, when the projection of
/// every point of the piece onto the chord's line falls inside the chord: the Bernstein
/// coefficients q_k = e.(b_k - b_0) of the projection (e = b_3 - b_0) all in [0, |e|^2] (convex
/// hull property). Then the distance is |f(u)| / |e| with f(u) = e x (c(u) - b_0), a cubic with
/// Bernstein coefficients (0, f_1, f_2, 0), f_k = e x (b_k - b_0); |f| is largest where
/// f'(u) = 3 [f_1 + 2 (f_2 - 2 f_1) u + 3 (f_1 - f_2) u^2] vanishes in (0, 1). Returns -1 when
/// the projection may leave the chord or a value is not finite (the sampled search then).
/// ~60 operations instead of ~70 evaluations of the sampled search (issue 23 §4: 73 % of
/// fit_cubic_spline's instructions were that search).
inline double cubic_chord_distance_closed_form(const std::array<Vec2, 4>& b) {
  const double ex = b[3][0] - b[0][0], ey = b[3][1] - b[0][1], l2 = ex * ex + ey * ey;
  double f[2], q[2];
  for (int k = 0; k < 2; ++k) {
    const double dx = b[k + 1][0] - b[0][0], dy = b[k + 1][1] - b[0][1];
    q[k] = ex * dx + ey * dy;
    f[k] = ex * dy - ey * dx;
  }
  if (!(l2 > 0) || !std::isfinite(l2) || !std::isfinite(f[0] * f[1]) || !(q[0] >= 0 && q[0] <= l2) ||
      !(q[1] >= 0 && q[1] <= l2))
    return -1;
  // g(u) = f(u) / 3 = f1 u (1 - u)^2 + f2 u^2 (1 - u); roots of g'(u) = A u^2 + B u + C.
  const double f1 = f[0], f2 = f[1];
  auto g = [&](double u) { const double v = 1 - u; return u * v * (f1 * v + f2 * u); };
  const double A = 3 * (f1 - f2), B = 2 * (f2 - 2 * f1), C = f1;
  double best = 0;
  auto consider = [&](double u) {
    if (u > 0 && u < 1) best = std::max(best, std::fabs(g(u)));
  };
  if (A == 0) {
    if (B != 0) consider(-C / B);
  } else {
    const double disc = B * B - 4 * A * C;
    if (disc >= 0) {
      const double r = std::sqrt(disc), qq = -0.5 * (B + (B >= 0 ? r : -r)); // no cancellation
      consider(qq / A);
      if (qq != 0) consider(C / qq);
    }
  }
  return 3 * best / std::sqrt(l2);
}

/// The largest distance from the segment [e0, e1] of the polynomial piece with power
/// coefficients a on [0, 1]: fit_distance_samples + 1 samples, then fit_distance_refinements
/// golden-section steps around the largest (located to about 4e-9 of the piece; it can miss a
/// maximum only where the distance has two bumps closer than 1/fit_distance_samples).
template <std::size_t N>
double sampled_segment_distance(const std::array<Vec2, N>& a, const Vec2& e0, const Vec2& e1) {
  auto f = [&](double u) {
    Vec2 x = a[N - 1];
    for (std::size_t k = N - 1; k-- > 0;)
      for (int c = 0; c < 2; ++c) x[c] = x[c] * u + a[k][c];
    return distance_to_segment(x, e0, e1);
  };
  const int q = fit_distance_samples;
  int best = 0;
  double best_value = -1;
  for (int k = 0; k <= q; ++k) {
    const double v = f(static_cast<double>(k) / q);
    if (v > best_value) {
      best_value = v;
      best = k;
    }
  }
  double lo = std::max(0.0, (best - 1.0) / q), hi = std::min(1.0, (best + 1.0) / q);
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < fit_distance_refinements; ++it) {
    if (f1 > f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = f(x2);
    }
  }
  return std::max(best_value, std::max(f1, f2));
}

template <std::size_t N>
double piece_chord_distance(const std::array<Vec2, N>& b) {
  if constexpr (N == 4) {
    const double d = cubic_chord_distance_closed_form(b);
    if (d >= 0) return d;
  }
  return sampled_segment_distance(power_coefficients(b), b.front(), b.back());
}

template <std::size_t N>
double max_chord_distance(const std::vector<std::array<Vec2, N>>& pieces) {
  double d = 0;
  for (const std::array<Vec2, N>& b : pieces) d = std::max(d, piece_chord_distance(b));
  return d;
}

} // namespace optimal
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_OPTIMAL_SPLINE_FIT_H
