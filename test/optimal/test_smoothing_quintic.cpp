// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The quintic smoothing spline (fair::fit_smoothing_quintic_runs, internal/spline/smoothing_quintic.h;
// issue 25 §3 "the quintic option likewise"): the banded Hermite solve against an independent dense
// construction (monomial pieces, C4 continuity and interpolation as Lagrange constraints, no end
// condition imposed), the limits (zero tolerance: the natural / periodic C4 interpolant, closed equal
// to fit_quintic_spline), and seeded random properties (within the tolerance, the interpolated
// vertices exact, C4 at the knots, a straight line reproduced); and the spline-resolution pass of the
// hierarchy (internal/spline/smoothing_runs.h) on a real stroke.

#include <fair/Optimal_curve_2.h>
#include <fair/Polygon_spline_fit.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> Kd;
typedef Kd::Point_2 Pd;
using fair::internal::optimal::Vec2;

using fair_test::dense_solve;

/// The oracle for one coordinate: piece i is sum_j c_ij (t - t_i)^j, j = 0..5; minimise
/// sum_i int c_i'''^2 + sum_{free k} (c(t_k) - v_k)^2 / d_k subject to c_i(t_i) = v_i at the hard
/// knots and derivatives 0..4 continuous at every interior knot (closed: every knot). Returns the
/// monomial coefficients per piece.
std::vector<std::array<double, 6>> dense_oracle(const std::vector<double>& v, const std::vector<double>& t, bool closed,
                                                const std::vector<double>& d) {
  const std::size_t n = v.size(), m = t.size() - 1, U = 6 * m;
  std::vector<std::vector<double>> rows;  // constraints: row . x = rhs
  std::vector<double> rhs;
  auto deriv = [](int order, int j, double x) {  // d^order/dx^order of x^j
    if (j < order) return 0.0;
    double f = 1;
    for (int q = 0; q < order; ++q) f *= j - q;
    return f * std::pow(x, j - order);
  };
  for (std::size_t i = 0; i < m; ++i) {  // piece i starts at its knot value when hard
    if (!(d[i] > 0)) {
      std::vector<double> r(U, 0.0);
      r[6 * i] = 1;
      rows.push_back(r);
      rhs.push_back(v[i]);
    }
  }
  if (!closed && !(d[n - 1] > 0)) {  // the last knot: end of the last piece
    std::vector<double> r(U, 0.0);
    for (int j = 0; j < 6; ++j) r[6 * (m - 1) + j] = deriv(0, j, t[m] - t[m - 1]);
    rows.push_back(r);
    rhs.push_back(v[n - 1]);
  }
  for (std::size_t i = 0; i < m; ++i) {  // C4 from piece i to the next
    if (!closed && i + 1 == m) break;
    const std::size_t next = (i + 1) % m;
    const double h = t[i + 1] - t[i];
    for (int order = 0; order <= 4; ++order) {
      std::vector<double> r(U, 0.0);
      for (int j = 0; j < 6; ++j) r[6 * i + j] = deriv(order, j, h);
      r[6 * next + order] -= deriv(order, order, 0.0);
      rows.push_back(r);
      rhs.push_back(0);
    }
  }
  // Energy x^T G x - 2 g^T x (+ const): int_0^h c''' ^2 exactly, and the penalties at the knots.
  std::vector<std::vector<double>> G(U, std::vector<double>(U, 0.0));
  std::vector<double> g(U, 0.0);
  for (std::size_t i = 0; i < m; ++i) {
    const double h = t[i + 1] - t[i];
    for (int a = 3; a < 6; ++a)
      for (int b = 3; b < 6; ++b) {
        const double ca = deriv(3, a, 1.0), cb = deriv(3, b, 1.0);  // coefficient of x^(a-3), x^(b-3)
        const int p = (a - 3) + (b - 3);
        G[6 * i + a][6 * i + b] += ca * cb * std::pow(h, p + 1) / (p + 1);
      }
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (!(d[k] > 0)) continue;
    std::vector<double> e(U, 0.0);  // c(t_k) as a row
    if (k < m) e[6 * k] = 1;
    else
      for (int j = 0; j < 6; ++j) e[6 * (m - 1) + j] = deriv(0, j, t[m] - t[m - 1]);
    for (std::size_t a = 0; a < U; ++a) {
      if (e[a] == 0) continue;
      g[a] += e[a] * v[k] / d[k];
      for (std::size_t b = 0; b < U; ++b) G[a][b] += e[a] * e[b] / d[k];
    }
  }
  const std::size_t C = rows.size(), N = U + C;
  std::vector<std::vector<double>> A(N, std::vector<double>(N, 0.0));
  std::vector<double> b(N, 0.0);
  for (std::size_t a = 0; a < U; ++a) {
    for (std::size_t c = 0; c < U; ++c) A[a][c] = G[a][c];
    b[a] = g[a];
  }
  for (std::size_t r = 0; r < C; ++r) {
    for (std::size_t a = 0; a < U; ++a) A[U + r][a] = A[a][U + r] = rows[r][a];
    b[U + r] = rhs[r];
  }
  const std::vector<double> x = dense_solve(A, b);
  std::vector<std::array<double, 6>> out(m);
  for (std::size_t i = 0; i < m; ++i)
    for (int j = 0; j < 6; ++j) out[i][j] = x[6 * i + j];
  return out;
}

/// The monomial coefficients (in t - t_i, not u) of a Bezier piece of degree 5 over an interval h.
std::array<double, 6> monomial(const std::array<Vec2, 6>& b, std::size_t c, double h) {
  const std::array<Vec2, 6> a = fair::internal::optimal::power_coefficients(b);
  std::array<double, 6> out;
  for (int j = 0; j < 6; ++j) out[j] = a[j][c] / std::pow(h, j);
  return out;
}

std::vector<Vec2> wobbly(std::mt19937& rng, std::size_t n, bool closed) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec2> v;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = (closed ? 2 * M_PI : 4.0) * static_cast<double>(k) / n + 0.15 * u(rng);
    v.push_back(Vec2{{std::cos(a) * (1 + 0.1 * u(rng)), 0.7 * std::sin(a) + 0.05 * u(rng)}});
  }
  return v;
}

// The banded Hermite solve equals the dense constrained minimiser of another parametrisation
// (monomials, C4 and interpolation as Lagrange constraints), open (the natural ends c''' = c'''' = 0
// emerge) and closed (periodic), hard and free vertices at irregular spacing, and the limit d = 0.
TEST(Optimal_fit_smoothing_quintic, BandedSolveMatchesTheDenseConstrainedMinimiser) {
  std::mt19937 rng(2503);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const bool closed : {false, true})
    for (const bool all_hard : {false, true}) {
      const std::size_t n = 11;
      const std::vector<Vec2> v = wobbly(rng, n, closed);
      const std::vector<double> t = fair::internal::optimal::chord_breakpoints(v, closed, "test");
      std::vector<double> d(n, 0.0);
      if (!all_hard)
        for (std::size_t k = 0; k < n; ++k) d[k] = (k % 3 == 0 || (!closed && k + 1 == n)) ? 0 : 1e-5 * (1 + 0.5 * u(rng));
      std::vector<std::array<Vec2, 6>> pieces;
      std::vector<Vec2> y;
      ASSERT_TRUE(fair::internal::spline::smoothing_quintic_solve(v, t, closed, d, pieces, y));
      ASSERT_EQ(pieces.size(), t.size() - 1);
      double worst = 0, moved = 0;
      for (std::size_t c = 0; c < 2; ++c) {
        std::vector<double> vc;
        for (const Vec2& q : v) vc.push_back(q[c]);
        const auto oracle = dense_oracle(vc, t, closed, d);
        for (std::size_t i = 0; i < pieces.size(); ++i) {
          const std::array<double, 6> mine = monomial(pieces[i], c, t[i + 1] - t[i]);
          for (int j = 0; j < 6; ++j)  // scale-free: coefficient j times h^j
            worst = std::max(worst, std::fabs(mine[j] - oracle[i][j]) * std::pow(t[i + 1] - t[i], j));
        }
      }
      EXPECT_LT(worst, 1e-8) << "closed " << closed << " all hard " << all_hard;
      for (std::size_t k = 0; k < n; ++k) {
        const double r = std::hypot(y[k][0] - v[k][0], y[k][1] - v[k][1]);
        if (!(d[k] > 0)) {
          EXPECT_EQ(r, 0) << k;  // exact on the hard knots
        }
        moved = std::max(moved, r);
      }
      if (all_hard) EXPECT_EQ(moved, 0);
      else EXPECT_GT(moved, 1e-4);  // the free vertices are smoothed
    }
}

// Zero tolerance: closed, fit_quintic_spline's periodic C4 interpolant (an independent solve: its
// Woodbury correction of the open chain); open, the natural interpolant (c''' = c'''' = 0 at the
// ends, where fit_quintic_spline clamps).
TEST(Optimal_fit_smoothing_quintic, ZeroToleranceIsTheInterpolant) {
  std::mt19937 rng(2504);
  for (const bool closed : {false, true}) {
    const std::vector<Pd> p = fair_test::random_points<Kd>(rng, 9);
    const auto fit = fair::fit_smoothing_quintic_runs<Kd>(p, closed, {}, {}, 0.0);
    ASSERT_EQ(fit.fit.pieces.size(), closed ? p.size() : p.size() - 1);
    for (std::size_t i = 0; i < fit.fit.pieces.size(); ++i) {
      EXPECT_EQ(fit.fit.pieces[i].control_points().front(), p[i]);
      EXPECT_EQ(fit.fit.pieces[i].control_points().back(), p[(i + 1) % p.size()]);
    }
    if (closed) {
      const auto reference = fair::fit_quintic_spline<Kd>(p, true);
      for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t k = 0; k < 6; ++k)
          EXPECT_LT(CGAL::to_double(CGAL::squared_distance(fit.fit.pieces[i].control_points()[k],
                                                           reference.pieces[i].control_points()[k])),
                    1e-18);
    } else {
      for (const auto* piece : {&fit.fit.pieces.front(), &fit.fit.pieces.back()}) {
        std::array<Vec2, 6> b;
        for (std::size_t k = 0; k < 6; ++k) b[k] = Vec2{{piece->control_points()[k].x(), piece->control_points()[k].y()}};
        const auto a = fair::internal::optimal::power_coefficients(b);
        const double at = piece == &fit.fit.pieces.front() ? 0.0 : 1.0;  // c''' and c'''' there
        for (int c = 0; c < 2; ++c) {
          const double d3 = 6 * a[3][c] + 24 * a[4][c] * at + 60 * a[5][c] * at * at, d4 = 24 * a[4][c] + 120 * a[5][c] * at;
          EXPECT_NEAR(d3, 0, 1e-6 * (1 + std::fabs(6 * a[3][c])));
          EXPECT_NEAR(d4, 0, 1e-6 * (1 + std::fabs(24 * a[4][c])));
        }
      }
    }
    EXPECT_TRUE(fit.report.tolerance_met || fit.fit.max_distance > 0);
  }
}

// Seeded random properties: within the tolerance whenever it is met, the interpolated vertices and
// the ends exact, C4 at every knot of a run (derivatives of neighbouring pieces, in t), G0 at corners.
TEST(Optimal_fit_smoothing_quintic, RandomPolygonsStayWithinTheToleranceAndAreC4) {
  std::mt19937 rng(2505);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 40; ++trial) {
    const bool closed = trial % 2 == 1;
    const std::size_t n = 6 + static_cast<std::size_t>(u(rng) * 30);
    const std::vector<Vec2> v = wobbly(rng, n, closed);
    std::vector<Pd> p;
    for (const Vec2& q : v) p.push_back(Pd(q[0], q[1]));
    std::vector<std::size_t> interpolated, corners;
    for (std::size_t k = 0; k < n; ++k)
      if (u(rng) < 0.2) interpolated.push_back(k);
    if (trial % 4 == 3) corners.push_back(n / 2);
    const double tolerance = 1e-3 * std::pow(10.0, 2 * u(rng));
    const auto fit = fair::fit_smoothing_quintic_runs<Kd>(p, closed, interpolated, corners, tolerance);
    ASSERT_EQ(fit.fit.pieces.size(), closed ? n : n - 1) << trial;
    if (fit.report.tolerance_met) {
      EXPECT_LE(fit.fit.max_distance, tolerance * (1 + 1e-12)) << trial;
    }
    // Piece r of the fit is edge (first + r) mod n: a closed polygon's runs start at its first corner.
    const std::size_t first = closed && !corners.empty() ? corners.front() : 0;
    std::vector<bool> hard(n, false);
    for (std::size_t k : interpolated) hard[k] = true;
    if (!closed) hard.front() = hard.back() = true;
    for (std::size_t r = 0; r < fit.fit.pieces.size(); ++r) {
      const std::size_t k = (first + r) % n;
      if (hard[k]) {
        EXPECT_EQ(fit.fit.pieces[r].control_points().front(), p[k]) << trial;
      }
    }
    const std::vector<double> t = fair::internal::optimal::chord_breakpoints(v, closed, "test");
    for (std::size_t i = 0; i + 1 < fit.fit.pieces.size() || (closed && i < fit.fit.pieces.size()); ++i) {
      const std::size_t j = (i + 1) % fit.fit.pieces.size();
      const bool corner = std::find(corners.begin(), corners.end(), (first + i + 1) % n) != corners.end();
      std::array<Vec2, 6> bi, bj;
      for (std::size_t k = 0; k < 6; ++k) {
        bi[k] = Vec2{{fit.fit.pieces[i].control_points()[k].x(), fit.fit.pieces[i].control_points()[k].y()}};
        bj[k] = Vec2{{fit.fit.pieces[j].control_points()[k].x(), fit.fit.pieces[j].control_points()[k].y()}};
      }
      const std::size_t ei = (first + i) % n, ej = (first + j) % n;  // their edges
      const double hi = t[ei + 1] - t[ei], hj = t[ej + 1] - t[ej];
      const auto ai = fair::internal::optimal::power_coefficients(bi), aj = fair::internal::optimal::power_coefficients(bj);
      for (int order = 0; order <= (corner ? 0 : 4); ++order)
        for (int c = 0; c < 2; ++c) {
          double left = 0, scale = 0;  // derivative `order` at u = 1 of piece i, in t
          for (int q = order; q < 6; ++q) {
            double f = 1;
            for (int r = 0; r < order; ++r) f *= q - r;
            left += f * ai[q][c];
            scale += std::fabs(f * ai[q][c]);
          }
          double ff = 1;
          for (int r = 1; r <= order; ++r) ff *= r;
          const double right = ff * aj[order][c];
          // to rounding: the order-4 derivative of the Bezier points differences 5 of them (up to
          // 1.6e-6 of the terms measured)
          EXPECT_NEAR(left / std::pow(hi, order), right / std::pow(hj, order),
                      1e-5 * (1 + scale / std::pow(hi, order))) << trial << " knot " << i + 1 << " order " << order;
        }
    }
  }
}

// A straight line (unevenly spaced) is reproduced at every tolerance, and a 2-vertex run is the segment.
// To rounding: with free vertices the energy alone places them (c''' = 0 between the hard ones), and
// its banded system is ill-conditioned (measured 2e-9 of the extent for any weight of the free
// vertices, 1e-15 when every vertex is hard) -- far below any tolerance the fit is asked for.
TEST(Optimal_fit_smoothing_quintic, ReproducesAStraightLine) {
  const std::vector<Pd> p = {Pd(0, 0), Pd(1, 0.5), Pd(1.5, 0.75), Pd(4, 2), Pd(4.2, 2.1), Pd(7, 3.5)};
  for (const double tolerance : {0.0, 1e-3, 1.0}) {
    const auto fit = fair::fit_smoothing_quintic_runs<Kd>(p, false, {2}, {}, tolerance);
    for (const auto& piece : fit.fit.pieces)
      for (const Pd& q : piece.control_points()) EXPECT_NEAR(q.y(), 0.5 * q.x(), 1e-7);
    EXPECT_LE(fit.fit.max_distance, tolerance > 0 ? 1e-7 : 1e-14);
  }
  // Only the ends hard (review of issue 25 §3, H1: the quadratic null space of int |c'''|^2 was
  // held by rounding and the fit was an arc filling the tolerance, 5e-3 .. 1e-2 at 1e-2): the
  // middle vertex is met too, and the line comes out, unevenly spaced, at n = 12. Longer runs are
  // still off by rounding amplified to 1.4e-7 (n = 50) and 8.1e-6 (n = 100) of the extent: open
  // (doc/optimal_curves.md, "The quintic smoothing spline").
  for (const std::size_t n : {12u}) {
    std::vector<Pd> line;
    double x = 0;
    for (std::size_t k = 0; k < n; ++k, x += 0.3 + 0.7 * double((k * 7) % 5) / 4) line.push_back(Pd(x, 0.5 * x));
    const auto fit = fair::fit_smoothing_quintic_runs<Kd>(line, false, {}, {}, 1e-2 * x);
    EXPECT_LE(fit.fit.max_distance, 1e-9 * x) << n;
  }
  const auto two = fair::fit_smoothing_quintic_runs<Kd>({Pd(0, 0), Pd(2, 1)}, false, {}, {}, 0.1);
  ASSERT_EQ(two.fit.pieces.size(), 1u);
  EXPECT_EQ(two.fit.pieces[0].control_points()[2], Pd(0.8, 0.4));
  EXPECT_THROW(fair::fit_smoothing_quintic_runs<Kd>(p, false, {}, {}, -1.0), fair::Precondition_error);
  EXPECT_THROW(fair::fit_smoothing_quintic_runs<Kd>(p, false, {9}, {}, 0.1), fair::Precondition_error);
  EXPECT_THROW(fair::fit_smoothing_quintic_runs<Kd>({Pd(0, 0)}, false, {}, {}, 0.1), fair::Invalid_input_error);
}

// The hierarchy's spline-resolution pass: on every curve the delivered cubic is within the fit's
// tolerance (0.9 of the resolution): the interpolant of every vertex is admissible (tolerance_met).
TEST(Optimal_fit_smoothing_quintic, OptimalSplineIsAlwaysWithinTheResolution) {
  std::mt19937 rng(2506);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 6; ++trial) {
    std::vector<Pd> p;
    for (int k = 0; k < 7; ++k) p.push_back(Pd(k + 0.3 * u(rng), (k % 2 ? 1.0 : -1.0) * (0.5 + 0.4 * u(rng))));
    fair::Optimal_curve_options o;
    o.closed = trial % 3 == 2;
    if (trial % 2) o.lambda = 0.5;
    const fair::Optimal_curve_2<Kd> c(p, o);
    ASSERT_EQ(c.status(), fair::Optimal_curve_status::CONVERGED) << trial;
    EXPECT_TRUE(c.spline_smoothing().tolerance_met) << trial;
    EXPECT_LE(c.spline().max_distance, c.spline_smoothing().tolerance * (1 + 1e-12)) << trial;
  }
}

}  // namespace

// Vertices that coincide to working precision (fuzz finding of session 19, corpus
// optimal/regress-points-one-ulp-apart): typed errors, not an internal error.
TEST(Optimal_fit_smoothing_errors, AnEdgeBelowTheBreakpointResolutionIsRefused) {
  // 1e-16 is below half an ulp of the breakpoint 4 it would start at: t + h == t.
  const std::vector<Vec2> p = {{{0, 0}}, {{4, 0}}, {{4, 1e-16}}};
  try {
    fair::internal::optimal::chord_breakpoints(p, false, "test");
    ADD_FAILURE() << "no error for an edge that does not advance its breakpoint";
  } catch (const fair::Invalid_input_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("edge 1 from (4, 0)"), std::string::npos) << what;
    EXPECT_NE(what.find("below the resolution of double"), std::string::npos) << what;
  }
  // The same edge from 0 advances its breakpoint and is accepted.
  const std::vector<double> t = fair::internal::optimal::chord_breakpoints({{{0, 0}}, {{0, 1e-16}}, {{4, 1e-16}}}, false, "test");
  ASSERT_EQ(t.size(), 3u);
  EXPECT_LT(t[0], t[1]);
  EXPECT_LT(t[1], t[2]);
}

TEST(Optimal_fit_smoothing_errors, AnInterpolantSingularToWorkingPrecisionNamesItsShortestEdge) {
  // The solve is the fit's parameter: one that reports a singular system (as the banded Cholesky
  // does for a non-positive pivot) must end in Invalid_input_error naming the shortest edge,
  // whatever the order of the energy.
  const std::vector<Vec2> v = {{{0, 0}}, {{1, 0}}, {{1, 1e-9}}, {{2, 0}}};
  const std::vector<double> t = fair::internal::optimal::chord_breakpoints(v, false, "test");
  const std::vector<bool> hard = {true, false, false, true};
  auto singular = [](const std::vector<double>&, std::vector<std::array<Vec2, 6>>&, std::vector<Vec2>&) { return false; };
  for (int order : {3, 5}) {
    try {
      fair::internal::spline::smoothing_fit_run_with<6>(v, t, false, hard, 0.1, order, singular);
      ADD_FAILURE() << "no error for a singular interpolant, order " << order;
    } catch (const fair::Invalid_input_error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(order == 3 ? "interpolating cubic" : "interpolating quintic"), std::string::npos) << what;
      EXPECT_NE(what.find("its edge 1 is"), std::string::npos) << what;  // 1e-9 of the length
    }
  }
}

// The closed C4 quintic interpolant with an edge of a few ulps of the length beside long ones
// (review of session 19): its banded system is positive definite only mathematically. The answer
// is a fit or an Invalid_input_error naming the edge, never an internal error; the open fit of the
// same points and the fuzz input through the smoothing quintic likewise.
TEST(Optimal_fit_smoothing_errors, QuinticInterpolantWithAnEdgeOfAFewUlps) {
  int refused = 0;
  for (int k = 1; k <= 4; ++k)
    for (const bool closed : {true, false}) {
      const double e = k * 0x1p-51;
      const std::vector<Pd> p = {Pd(0, 0), Pd(1, 1), Pd(2, 0), Pd(2 + e, e), Pd(1, -1)};
      try {
        const auto fit = fair::fit_quintic_spline<Kd>(p, closed);
        EXPECT_EQ(fit.pieces.size(), closed ? 5u : 4u);
        for (const auto& piece : fit.pieces)
          for (const Pd& q : piece.control_points()) EXPECT_TRUE(std::isfinite(q.x()) && std::isfinite(q.y()));
      } catch (const fair::Invalid_input_error& e) {
        ++refused;
        EXPECT_NE(std::string(e.what()).find("fair::fit_quintic_spline: the interpolating quintic of"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("its edge 2 is"), std::string::npos) << e.what();
      }
    }
  EXPECT_GE(refused, 1);  // e = 2^-51 closed was an Internal_error
  const std::vector<Pd> fuzz = {Pd(4.6972831674499663e-294, 0), Pd(2e-08, 3.0000000000000004e-08),
                                Pd(-4.696323204354239e-261, -4.6963232011388926e-261), Pd(2e-08, 3.0000000000000004e-08),
                                Pd(2e-08, 3.0000000000000011e-08)};
  for (const bool closed : {true, false})
    for (const double tolerance : {0.0, 1e-9}) {
      try {
        fair::fit_smoothing_quintic_runs<Kd>(fuzz, closed, {}, {}, tolerance);
        fair::fit_quintic_spline<Kd>(fuzz, closed);
      } catch (const fair::Invalid_input_error& e) {
        const std::string what = e.what();
        EXPECT_TRUE(what.find("singular to working precision") != std::string::npos ||
                    what.find("below the resolution of double") != std::string::npos)
            << what;
      }
    }
}
