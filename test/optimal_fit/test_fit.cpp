// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::fit_cubic_spline / fit_quintic_spline (issue 11 §4): interpolation of every vertex,
// C2 (exactly in the exact kernels) and C4 at the knots, the ends (not-a-knot: one cubic over
// the first two pieces; quintic: clamped to the end polynomial), reproduction of a straight line,
// the convergence orders on dense samples of a circle and an ellipse (measured over three
// resolutions against the exact curves), reversal symmetry, the measured max_distance against
// a brute-force oracle, and the typed errors for degenerate input.

#include "test_support.h"

#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Fairness_metrics.h>
#include <fair/Polygon_spline_fit.h>
#include <fair/io/write_json.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

namespace {

using fair_test::same;

template <class K>
class Optimal_fit : public ::testing::Test {};
TYPED_TEST_SUITE(Optimal_fit, fair_test::All_kernels);

template <class K>
class Optimal_fit_floating : public ::testing::Test {};
TYPED_TEST_SUITE(Optimal_fit_floating, fair_test::Floating_kernels);

typedef fair_test::SC_double Kd;
typedef Kd::Point_2 Pd;


template <class P>
std::array<double, 2> d2(const P& p) {
  return {{CGAL::to_double(p.x()), CGAL::to_double(p.y())}};
}

template <class V>
std::array<double, 2> dv(const V& v) {
  return {{CGAL::to_double(v.x()), CGAL::to_double(v.y())}};
}

template <class K>
std::vector<double> chord_parameters(const std::vector<typename K::Point_2>& p, bool closed) {
  std::vector<double> t{0};
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < (closed ? n : n - 1); ++i) {
    const auto a = d2(p[i]), b = d2(p[(i + 1) % n]);
    t.push_back(t.back() + std::hypot(b[0] - a[0], b[1] - a[1]));
  }
  return t;
}

// The cubic passes through every vertex (to rounding of the extent) and is C2 at every join;
// in the exact kernels the joins are exact identities (the spline is built from control points).
TYPED_TEST(Optimal_fit, CubicInterpolatesEveryVertexAndIsC2) {
  typedef TypeParam K;
  std::mt19937 rng(11);
  for (bool closed : {false, true}) {
    const std::vector<typename K::Point_2> p = fair_test::random_points<K>(rng, 9);
    const fair::Polygon_spline_fit<K> fit = fair::fit_cubic_spline<K>(p, closed);
    const std::vector<typename K::FT>& t = fit.spline.breakpoints();
    ASSERT_EQ(t.size(), closed ? p.size() + 1 : p.size());
    const std::vector<double> chord = chord_parameters<K>(p, closed);
    for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(CGAL::to_double(t[i]), chord[i], 1e-12 * chord.back());
    const std::vector<fair::Bezier_2<K>> pieces = fit.spline.polynomial_pieces();
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const auto a = d2(pieces[i].source()), b = d2(p[i]);
      EXPECT_NEAR(a[0], b[0], 1e-13 * 100) << "piece " << i;
      EXPECT_NEAR(a[1], b[1], 1e-13 * 100) << "piece " << i;
    }
    const std::size_t joins = closed ? pieces.size() : pieces.size() - 1;
    for (std::size_t j = 0; j < joins; ++j) {
      const std::size_t i = j, k = (j + 1) % pieces.size();
      const typename K::FT h0 = t[i + 1] - t[i], h1 = t[k + 1] - t[k];
      EXPECT_TRUE(same<K>(pieces[i].target(), pieces[k].source()));
      EXPECT_TRUE(same<K>(pieces[i].derivative(1) / h0, pieces[k].derivative(0) / h1, 1e-12));
      EXPECT_TRUE(same<K>(pieces[i].second_derivative(1) / (h0 * h0), pieces[k].second_derivative(0) / (h1 * h1), 1e-11));
    }
  }
}

// Collinear vertices at irregular spacing: the fits are the straight segment (every control
// point on the line, zero distance to the polygon).
TYPED_TEST(Optimal_fit, ReproducesAStraightLine) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const std::vector<int> s{0, 1, 3, 4, 9, 10, 17};
  std::vector<typename K::Point_2> p;
  for (int k : s) p.push_back(typename K::Point_2(FT(1) + FT(3 * k) / 4, FT(-2) + FT(k) / 2));
  const fair::Polygon_spline_fit<K> cubic = fair::fit_cubic_spline<K>(p, false);
  for (const auto& c : cubic.spline.control_points()) {
    const auto q = d2(c);
    EXPECT_NEAR((q[0] - 1) / 1.5 - (q[1] + 2), 0, 1e-13) << q[0] << " " << q[1];
  }
  EXPECT_LE(cubic.max_distance, 1e-13);
  const fair::Polygon_quintic_fit<K> quintic = fair::fit_quintic_spline<K>(p, false);
  ASSERT_EQ(quintic.pieces.size(), p.size() - 1);
  for (const auto& piece : quintic.pieces)
    for (const auto& c : piece.control_points()) {
      const auto q = d2(c);
      EXPECT_NEAR((q[0] - 1) / 1.5 - (q[1] + 2), 0, 1e-12) << q[0] << " " << q[1];
    }
  EXPECT_LE(quintic.max_distance, 1e-12);
}

// The quintic passes through every vertex (exactly: its pieces end at the vertices) and is C4
// at every join (to rounding; derivatives of order k scaled by h^k, compared relative to the
// largest of them).
TYPED_TEST(Optimal_fit, QuinticInterpolatesEveryVertexAndIsC4) {
  typedef TypeParam K;
  std::mt19937 rng(12);
  for (bool closed : {false, true}) {
    const std::vector<typename K::Point_2> p = fair_test::random_points<K>(rng, 10);
    const fair::Polygon_quintic_fit<K> fit = fair::fit_quintic_spline<K>(p, closed);
    ASSERT_EQ(fit.pieces.size(), closed ? p.size() : p.size() - 1);
    const std::vector<double> t = chord_parameters<K>(p, closed);
    for (std::size_t i = 0; i < fit.pieces.size(); ++i) {
      EXPECT_TRUE(fit.pieces[i].source() == p[i]);
      EXPECT_TRUE(fit.pieces[i].target() == p[(i + 1) % p.size()]);
      EXPECT_EQ(fit.pieces[i].degree(), 5u);
    }
    const std::size_t joins = closed ? fit.pieces.size() : fit.pieces.size() - 1;
    for (std::size_t j = 0; j < joins; ++j) {
      const std::size_t k = (j + 1) % fit.pieces.size();
      const double h0 = t[j + 1] - t[j], h1 = t[k + 1] - t[k];
      for (std::size_t order = 1; order <= 4; ++order) {
        const auto a = dv(fit.pieces[j].nth_derivative(typename K::FT(1), order));
        const auto b = dv(fit.pieces[k].nth_derivative(typename K::FT(0), order));
        const double sa = std::pow(h0, -static_cast<double>(order)), sb = std::pow(h1, -static_cast<double>(order));
        const double scale = std::max({std::hypot(a[0], a[1]) * sa, std::hypot(b[0], b[1]) * sb, 1.0});
        EXPECT_NEAR(a[0] * sa, b[0] * sb, 1e-9 * scale) << "join " << j << " order " << order << " closed " << closed;
        EXPECT_NEAR(a[1] * sa, b[1] * sb, 1e-9 * scale) << "join " << j << " order " << order << " closed " << closed;
      }
    }
  }
}

// Not-a-knot: the open cubic is one cubic polynomial over its first two and its last two pieces
// (c''' continuous at t_1 and t_{m-1}); 3 vertices give one parabola (c''' = 0).
TEST(Optimal_fit_ends, NotAKnotAndParabola) {
  std::mt19937 rng(13);
  const std::vector<Pd> p = fair_test::random_points<Kd>(rng, 8);
  const fair::Polygon_spline_fit<Kd> fit = fair::fit_cubic_spline<Kd>(p, false);
  const std::vector<double>& t = fit.spline.breakpoints();
  const auto pieces = fit.spline.polynomial_pieces();
  const std::size_t m = pieces.size();
  for (std::size_t j : {std::size_t(0), m - 2}) {
    const auto a = pieces[j].nth_derivative(1, 3) / std::pow(t[j + 1] - t[j], 3);
    const auto b = pieces[j + 1].nth_derivative(0, 3) / std::pow(t[j + 2] - t[j + 1], 3);
    EXPECT_NEAR(a.x(), b.x(), 1e-9 * (1 + std::fabs(a.x())));
    EXPECT_NEAR(a.y(), b.y(), 1e-9 * (1 + std::fabs(a.y())));
  }
  const std::vector<Pd> three{Pd(0, 0), Pd(1, 2), Pd(3, 1)};
  const auto parabola = fair::fit_cubic_spline<Kd>(three, false).spline.polynomial_pieces();
  ASSERT_EQ(parabola.size(), 2u);
  for (const auto& piece : parabola) {
    EXPECT_NEAR(piece.nth_derivative(0.5, 3).x(), 0, 1e-12);
    EXPECT_NEAR(piece.nth_derivative(0.5, 3).y(), 0, 1e-12);
  }
  // the quintic through at most 6 open vertices is their interpolating polynomial: c^(5) is
  // continuous at every join (one polynomial)
  const std::vector<Pd> six{Pd(0, 0), Pd(1, 2), Pd(3, 1), Pd(4, 3), Pd(6, 2), Pd(7, 5)};
  const fair::Polygon_quintic_fit<Kd> q = fair::fit_quintic_spline<Kd>(six, false);
  const std::vector<double> c = chord_parameters<Kd>(six, false);
  for (std::size_t j = 0; j + 1 < q.pieces.size(); ++j) {
    const auto a = q.pieces[j].nth_derivative(1, 5) / std::pow(c[j + 1] - c[j], 5);
    const auto b = q.pieces[j + 1].nth_derivative(0, 5) / std::pow(c[j + 2] - c[j + 1], 5);
    EXPECT_NEAR(a.x(), b.x(), 1e-7 * (1 + std::fabs(a.x()))) << j;
    EXPECT_NEAR(a.y(), b.y(), 1e-7 * (1 + std::fabs(a.y()))) << j;
  }
}

// Distance of x to the curve: circle of radius r (exact), ellipse with semi-axes a, b (the
// first-order distance |F| / |grad F|, F = x^2/a^2 + y^2/b^2 - 1, accurate to O(dist^2)).
struct Smooth_curve {
  double a, b;
  bool circle() const { return a == b; }
  Pd at(double theta) const { return Pd(a * std::cos(theta), b * std::sin(theta)); }
  double distance(const std::array<double, 2>& x) const {
    if (circle()) return std::fabs(std::hypot(x[0], x[1]) - a);
    const double F = x[0] * x[0] / (a * a) + x[1] * x[1] / (b * b) - 1;
    const double gx = 2 * x[0] / (a * a), gy = 2 * x[1] / (b * b);
    return std::fabs(F) / std::hypot(gx, gy);
  }
};

// The largest distance of the fitted pieces (65 samples each) from the curve.
template <class Pieces>
double fit_error(const Smooth_curve& c, const Pieces& pieces) {
  double e = 0;
  for (const auto& piece : pieces)
    for (int k = 0; k <= 64; ++k) e = std::max(e, c.distance(d2(piece.point(k / 64.0))));
  return e;
}

std::vector<Pd> samples(const Smooth_curve& c, std::size_t n, double start, double span, bool closed) {
  const double two_pi = 2 * std::acos(-1.0);
  std::vector<Pd> p;
  const std::size_t count = closed ? n : n + 1;
  for (std::size_t i = 0; i < count; ++i) {
    const double x = static_cast<double>(i) / static_cast<double>(n);
    p.push_back(c.at(start + span * (x + 0.4 / two_pi * std::sin(two_pi * x)))); // spacing varies 1 +- 0.4
  }
  return p;
}

// O(h^4) for the cubic, O(h^6) for the quintic: the measured error ratios per halving of h over
// three resolutions, on the closed circle (n = 16, 32, 64), the closed ellipse 2 x 0.7 and an
// open arc of it (theta in [0.5, 3]; n = 96, 192, 384: the ellipse's curvature reaches 4.1, the
// ratios are asymptotic from about n = 48 on), vertices spaced smoothly 1 +- 0.4 (measured:
// cubic 15 .. 18.5, quintic 55 .. 140; 2^4 = 16, 2^6 = 64).
TEST(Optimal_fit_convergence, CubicIsFourthOrderQuinticSixthOrder) {
  const double pi = std::acos(-1.0);
  struct Case { Smooth_curve curve; double start, span; bool closed; std::size_t n0; };
  const Case cases[] = {{{1.5, 1.5}, 0, 2 * pi, true, 16}, {{2.0, 0.7}, 0, 2 * pi, true, 96},
                        {{2.0, 0.7}, 0.5, 2.5, false, 96}};
  for (const Case& c : cases) {
    double cubic[3], quintic[3];
    for (int r = 0; r < 3; ++r) {
      const std::vector<Pd> p = samples(c.curve, c.n0 << r, c.start, c.span, c.closed);
      cubic[r] = fit_error(c.curve, fair::fit_cubic_spline<Kd>(p, c.closed).spline.polynomial_pieces());
      quintic[r] = fit_error(c.curve, fair::fit_quintic_spline<Kd>(p, c.closed).pieces);
    }
    for (int r = 0; r < 2; ++r) {
      const double rc = cubic[r] / cubic[r + 1], rq = quintic[r] / quintic[r + 1];
      EXPECT_GT(rc, 12.0) << "cubic ratio " << rc << " at level " << r << " (errors " << cubic[r] << ", " << cubic[r + 1]
                          << ") a=" << c.curve.a << " closed=" << c.closed;
      EXPECT_LT(rc, 22.0) << "cubic ratio " << rc;
      EXPECT_GT(rq, 40.0) << "quintic ratio " << rq << " at level " << r << " (errors " << quintic[r] << ", "
                          << quintic[r + 1] << ") a=" << c.curve.a << " closed=" << c.closed;
    }
  }
}

// max_distance against a brute-force oracle: 20000 samples per piece of the distance to the
// piece's own edge (the oracle can only be smaller, by at most |f''| (1/20000)^2 / 8).
TEST(Optimal_fit_distance, MaxDistanceMatchesBruteForce) {
  std::mt19937 rng(14);
  for (bool closed : {false, true}) {
    const std::vector<Pd> p = fair_test::random_points<Kd>(rng, 7);
    const auto cubic = fair::fit_cubic_spline<Kd>(p, closed);
    const auto quintic = fair::fit_quintic_spline<Kd>(p, closed);
    auto brute = [&](const auto& pieces) {
      double d = 0;
      for (std::size_t i = 0; i < pieces.size(); ++i) {
        const auto a = d2(p[i]), b = d2(p[(i + 1) % p.size()]);
        for (int k = 0; k <= 20000; ++k)
          d = std::max(d, fair::internal::optimal::distance_to_segment(d2(pieces[i].point(k / 20000.0)), a, b));
      }
      return d;
    };
    const double bc = brute(cubic.spline.polynomial_pieces()), bq = brute(quintic.pieces);
    EXPECT_GT(bc, 0);
    EXPECT_LE(bc, cubic.max_distance * (1 + 1e-12));
    EXPECT_NEAR(bc, cubic.max_distance, 1e-7 * cubic.max_distance);
    EXPECT_LE(bq, quintic.max_distance * (1 + 1e-12));
    EXPECT_NEAR(bq, quintic.max_distance, 1e-7 * quintic.max_distance);
  }
}

// Reversing the vertices gives the same curve traversed backwards (both end conditions are
// symmetric): c_rev(T - t) = c(t) at the knots' midpoints.
TEST(Optimal_fit_symmetry, ReversalGivesTheSameCurve) {
  std::mt19937 rng(15);
  std::vector<Pd> p = fair_test::random_points<Kd>(rng, 9);
  std::vector<Pd> r(p.rbegin(), p.rend());
  const auto a = fair::fit_cubic_spline<Kd>(p, false).spline.polynomial_pieces();
  const auto b = fair::fit_cubic_spline<Kd>(r, false).spline.polynomial_pieces();
  const auto qa = fair::fit_quintic_spline<Kd>(p, false).pieces, qb = fair::fit_quintic_spline<Kd>(r, false).pieces;
  const std::size_t m = a.size();
  for (std::size_t i = 0; i < m; ++i)
    for (double u : {0.25, 0.5, 0.8}) {
      EXPECT_TRUE(same<Kd>(a[i].point(u), b[m - 1 - i].point(1 - u), 1e-12));
      EXPECT_TRUE(same<Kd>(qa[i].point(u), qb[m - 1 - i].point(1 - u), 1e-11));
    }
}

// Smallest inputs: the segment (2 vertices) and the triangle (3 vertices, closed).
TYPED_TEST(Optimal_fit, SmallestInputs) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  const std::vector<P> two{P(0, 0), P(3, 4)};
  const auto c = fair::fit_cubic_spline<K>(two, false);
  EXPECT_EQ(c.spline.number_of_pieces(), 1u);
  EXPECT_LE(c.max_distance, 1e-14 * 5); // rounding of the extent (5)
  EXPECT_TRUE(same<K>(c.spline.point(typename K::FT(5) / 2), P(typename K::FT(3) / 2, 2)));
  const auto q = fair::fit_quintic_spline<K>(two, false);
  ASSERT_EQ(q.pieces.size(), 1u);
  EXPECT_LE(q.max_distance, 1e-14 * 5);
  const std::vector<P> triangle{P(0, 0), P(4, 0), P(0, 3)};
  const auto ct = fair::fit_cubic_spline<K>(triangle, true);
  EXPECT_EQ(ct.spline.number_of_pieces(), 3u);
  EXPECT_TRUE(ct.spline.is_closed());
  EXPECT_GT(ct.max_distance, 0.1);
  const auto qt = fair::fit_quintic_spline<K>(triangle, true);
  EXPECT_EQ(qt.pieces.size(), 3u);
  EXPECT_GT(qt.max_distance, 0.1);
}

// Degenerate input: typed errors naming the function and the offending data.
TYPED_TEST(Optimal_fit, DegenerateInputThrowsTypedErrors) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  const std::vector<P> one{P(1, 2)};
  EXPECT_THROW(fair::fit_cubic_spline<K>(one, false), fair::Invalid_input_error);
  EXPECT_THROW(fair::fit_quintic_spline<K>(one, false), fair::Invalid_input_error);
  const std::vector<P> two{P(0, 0), P(1, 0)};
  EXPECT_THROW(fair::fit_cubic_spline<K>(two, true), fair::Invalid_input_error);
  EXPECT_THROW(fair::fit_quintic_spline<K>(two, true), fair::Invalid_input_error);
  const std::vector<P> duplicate{P(0, 0), P(1, 0), P(1, 0), P(2, 1)};
  const std::string m = fair_test::invalid_input_message([&] { fair::fit_cubic_spline<K>(duplicate, false); });
  EXPECT_NE(m.find("fair::fit_cubic_spline"), std::string::npos) << m;
  EXPECT_NE(m.find("1 and 2"), std::string::npos) << m;
  EXPECT_THROW(fair::fit_quintic_spline<K>(duplicate, false), fair::Invalid_input_error);
  const std::vector<P> repeated_close{P(0, 0), P(1, 0), P(1, 1), P(0, 0)};
  EXPECT_THROW(fair::fit_cubic_spline<K>(repeated_close, true), fair::Invalid_input_error);
  EXPECT_NO_THROW(fair::fit_cubic_spline<K>(repeated_close, false));
}

TYPED_TEST(Optimal_fit_floating, NonFiniteInputThrows) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::vector<P> with_nan{P(0, 0), P(nan, 1), P(2, 0)};
  const std::string m = fair_test::invalid_input_message([&] { fair::fit_cubic_spline<K>(with_nan, false); });
  EXPECT_NE(m.find("point 1"), std::string::npos) << m;
  EXPECT_THROW(fair::fit_quintic_spline<K>(with_nan, false), fair::Invalid_input_error);
  const std::vector<P> with_inf{P(0, 0), P(1, 1), P(2, inf)};
  EXPECT_THROW(fair::fit_cubic_spline<K>(with_inf, true), fair::Invalid_input_error);
  // distinct in double but the chord overflows
  const std::vector<P> huge{P(-1e308, 0), P(1e308, 0), P(1e308, 1e308)};
  EXPECT_THROW(fair::fit_cubic_spline<K>(huge, false), fair::Invalid_input_error);
}

} // namespace

// ---------------------------------------------------------------------------------------------
// fit_cubic_spline_runs: C2 runs between corners, G0 at the corners (reviewer finding 4: one C2
// spline through an optimal polygon with CORNER constraints rounds the corners off).

namespace runs {

// The closed lens of two circular arcs of radius R = sqrt(1 + c^2) about (0, -c) and (0, c)
// through (1, 0) and (-1, 0), each sampled at m + 1 points (uniform in angle): corners at
// vertex 0 = (1, 0) and vertex m = (-1, 0), where the true tangents of the upper arc are
// (-sin a0, cos a0) leaving (1, 0) and (-sin a1, cos a1) arriving at (-1, 0).
constexpr double c = 0.5;
inline double radius() { return std::sqrt(1 + c * c); }
inline double a0() { return std::atan2(c, 1.0); }
inline std::vector<Pd> lens(int m) {
  const double R = radius(), pi = std::acos(-1.0), from = a0(), to = pi - a0();
  std::vector<Pd> p;
  for (int k = 0; k <= m; ++k) {  // upper arc, (1, 0) -> (-1, 0)
    const double a = from + (to - from) * k / m;
    p.push_back(k == 0 ? Pd(1, 0) : k == m ? Pd(-1, 0) : Pd(R * std::cos(a), -c + R * std::sin(a)));
  }
  for (int k = 1; k < m; ++k) {  // lower arc, (-1, 0) -> (1, 0), the mirror image
    const double a = to - (to - from) * k / m;
    p.push_back(Pd(R * std::cos(a), c - R * std::sin(a)));
  }
  return p;
}

// de Boor's algorithm on a degree-3 knot vector u and control points d (independent of the
// library's piece construction): the point at x.
inline std::array<double, 2> de_boor(const std::vector<double>& u, const std::vector<std::array<double, 2>>& d,
                                     double x) {
  std::size_t k = 3;
  while (k + 1 < u.size() - 4 && !(x < u[k + 1])) ++k;
  std::array<std::array<double, 2>, 4> q;
  for (int j = 0; j < 4; ++j) q[j] = d[k - 3 + j];
  for (int r = 1; r <= 3; ++r)
    for (int j = 3; j >= r; --j) {
      const std::size_t i = k - 3 + j;
      const double alpha = (x - u[i]) / (u[i + 4 - r] - u[i]);
      for (int e = 0; e < 2; ++e) q[j][e] = (1 - alpha) * q[j - 1][e] + alpha * q[j][e];
    }
  return q[3];
}

inline double angle_between(const std::array<double, 2>& a, const std::array<double, 2>& b) {
  return std::fabs(std::atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]));
}

} // namespace runs

// Each run interpolates its vertices and is C2 inside; at the corners the runs meet (G0) and
// each run's end tangent converges to the true arc tangent (the one C2 spline does not: its
// tangent at (1, 0) is vertical by symmetry, 26.6 degrees off both).
TEST(Optimal_fit_runs, CornersAreKeptAndTheirTangentsConverge) {
  double previous_error = 0;
  for (int m : {8, 16, 32}) {
    const std::vector<Pd> p = runs::lens(m);
    const auto fit = fair::fit_cubic_spline_runs<Kd>(p, true, {static_cast<std::size_t>(m), 0, 0});
    ASSERT_EQ(fit.splines.size(), 2u);
    EXPECT_EQ(fit.first_vertex, (std::vector<std::size_t>{0, static_cast<std::size_t>(m)}));
    const auto pieces = fit.pieces();
    ASSERT_EQ(pieces.size(), p.size());  // one piece per edge of the closed polygon
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      EXPECT_TRUE(same<Kd>(pieces[i].point(0.0), p[i], 1e-14)) << "piece " << i << " starts at vertex " << i;
      EXPECT_TRUE(same<Kd>(pieces[i].point(1.0), p[(i + 1) % p.size()], 1e-14)) << "piece " << i;
    }
    const auto t0 = dv(fit.splines[0].derivative(fit.splines[0].breakpoints().front()));
    const std::array<double, 2> true_t0{{-std::sin(runs::a0()), std::cos(runs::a0())}};
    const double error = runs::angle_between(t0, true_t0);
    const auto whole = fair::fit_cubic_spline<Kd>(p, true);
    const double smoothed = runs::angle_between(dv(whole.spline.derivative(0.0)), true_t0);
    EXPECT_NEAR(smoothed, runs::a0(), 1e-9) << "the single C2 spline rounds the corner off";
    EXPECT_LT(error, 0.01) << m;
    if (previous_error > 0) {
      EXPECT_GT(previous_error / error, 3.0) << "tangent error ratio per halving, m = " << m;
    }
    previous_error = error;
    EXPECT_LE(fit.max_distance, whole.max_distance);
  }
}

// The stitched NURBS of Polygon_spline_runs::nurbs, as the "bspline" member writes it
// (io::nurbs_to_json): #knots = #control points + 4, knot multiplicity 3 at the corner, and de
// Boor's algorithm on the written numbers reproduces the middle of every piece. A closed polygon
// with corners is the periodic form whose seam is the first corner (C0 there).
TEST(Optimal_fit_runs, StitchedNurbsReproducesThePieces) {
  const std::vector<Pd> p = runs::lens(6);
  const auto fit = fair::fit_cubic_spline_runs<Kd>(p, true, {0, 6});
  const fair::Nurbs_curve_2<Kd> nurbs = fit.nurbs(true);
  const nlohmann::json j = fair::io::nurbs_to_json(nurbs);
  EXPECT_TRUE(j["closed"].get<bool>());
  EXPECT_EQ(j["degree"], 3);
  EXPECT_FALSE(j.contains("weights"));
  std::vector<double> u;
  for (const auto& x : j["knots"]) u.push_back(x.get<double>());
  std::vector<std::array<double, 2>> d;
  for (const auto& x : j["control_points"]) d.push_back({{x[0].get<double>(), x[1].get<double>()}});
  ASSERT_EQ(u.size(), d.size() + 4);
  const std::vector<double> t = nurbs.breakpoints();
  const auto pieces = fit.pieces();
  ASSERT_EQ(t.size(), pieces.size() + 1);
  ASSERT_EQ(fit.splines.size(), 2u);
  const std::size_t corner = fit.splines[0].number_of_pieces();  // the second corner's breakpoint
  EXPECT_EQ(corner, 6u);
  EXPECT_EQ(std::count(u.begin(), u.end(), t[corner]), 3) << "C0 at the corner: multiplicity 3";
  EXPECT_EQ(std::count(u.begin(), u.end(), t[0]), 3) << "C0 at the seam, the first corner: multiplicity 3";
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const auto expected = d2(pieces[i].point(0.5));
    const auto got = runs::de_boor(u, d, 0.5 * (t[i] + t[i + 1]));
    EXPECT_NEAR(got[0], expected[0], 1e-12) << "piece " << i;
    EXPECT_NEAR(got[1], expected[1], 1e-12) << "piece " << i;
  }
  // A closed polygon with one corner: one open run from the corner round to itself, written as a
  // closed curve whose corner is its seam.
  const auto one = fair::fit_cubic_spline_runs<Kd>(p, true, {3});
  ASSERT_EQ(one.splines.size(), 1u);
  EXPECT_EQ(one.first_vertex.front(), 3u);
  const fair::Nurbs_curve_2<Kd> n1 = one.nurbs(true);
  const nlohmann::json j1 = fair::io::nurbs_to_json(n1);
  EXPECT_TRUE(j1["closed"].get<bool>());
  EXPECT_EQ(std::count(n1.knots().begin(), n1.knots().end(), n1.domain().first), 3) << "the corner is the seam";
  EXPECT_EQ(j1["knots"].size(), j1["control_points"].size() + 4);
  // One run (no corners): the periodic spline's own NURBS, single knots (C2 at the seam too).
  const auto whole = fair::fit_cubic_spline_runs<Kd>(p, true, {});
  ASSERT_EQ(whole.splines.size(), 1u);
  const fair::Nurbs_curve_2<Kd> nw = whole.nurbs(true);
  EXPECT_TRUE(nw.is_closed());
  EXPECT_EQ(std::count(nw.knots().begin(), nw.knots().end(), nw.domain().first), 1);
  EXPECT_EQ(fair::io::nurbs_to_json(nw), fair::io::nurbs_to_json(whole.splines.front().nurbs()));
}

TYPED_TEST(Optimal_fit, SplineRunsOfOpenPolygonsAndBadCorners) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  const std::vector<P> p{P(0, 0), P(1, 1), P(2, 0), P(3, 1), P(4, 0)};
  // The ends of an open polygon are no corners; an interior corner splits it in two runs.
  const auto plain = fair::fit_cubic_spline_runs<K>(p, false, {0, 4});
  ASSERT_EQ(plain.splines.size(), 1u);
  const auto split = fair::fit_cubic_spline_runs<K>(p, false, {2});
  ASSERT_EQ(split.splines.size(), 2u);
  EXPECT_EQ(split.splines[0].number_of_pieces(), 2u);
  EXPECT_TRUE(same<K>(split.splines[0].point(split.splines[0].breakpoints().back()), p[2]));
  EXPECT_TRUE(same<K>(split.splines[1].point(split.splines[1].breakpoints().front()), p[2]));
  // Adjacent corners: the run between them is the segment.
  const auto segment = fair::fit_cubic_spline_runs<K>(p, false, {1, 2});
  ASSERT_EQ(segment.splines.size(), 3u);
  EXPECT_EQ(segment.splines[1].number_of_pieces(), 1u);
  EXPECT_THROW(fair::fit_cubic_spline_runs<K>(p, false, {5}), fair::Precondition_error);
}

// ---------------------------------------------------------------------------------------------
// The smoothing spline (fit_smoothing_spline_runs; internal/spline/smoothing_fit.h, issue 25 §3).

namespace smoothing {

typedef std::array<double, 2> V2;

using fair_test::dense_solve;

/// The independent oracle: Hermite form (value y_k and slope m_k per knot, C1 by construction),
/// int |c''|^2 exact per piece (c'' linear: h (A^2 + AB + B^2) / 3 with the end values
/// A = (6d - 4m_0 - 2m_1)/h, B = (-6d + 2m_0 + 4m_1)/h), C2 and the hard vertices as equality
/// constraints (Lagrange multipliers), no end condition imposed (natural ends must come out of
/// the minimisation). Returns the Bezier points of the pieces, one coordinate.
std::vector<std::array<double, 4>> dense_oracle(const std::vector<double>& v, const std::vector<double>& t, bool closed,
                                                const std::vector<double>& d) {
  const std::size_t K = v.size(), m = t.size() - 1, n = 2 * K;
  std::vector<std::vector<double>> H(n, std::vector<double>(n, 0.0));
  std::vector<double> rhs(n, 0.0);
  std::vector<std::vector<double>> rows;  // constraints
  std::vector<double> r;
  auto ends = [&](std::size_t i, std::vector<double>& A, std::vector<double>& B) {  // c''(t_i+), c''(t_{i+1}-)
    const std::size_t j = (i + 1) % K;
    const double h = t[i + 1] - t[i];
    A.assign(n, 0.0);
    B.assign(n, 0.0);
    A[j] += 6 / (h * h); A[i] -= 6 / (h * h); A[K + i] -= 4 / h; A[K + j] -= 2 / h;
    B[j] -= 6 / (h * h); B[i] += 6 / (h * h); B[K + i] += 2 / h; B[K + j] += 4 / h;
  };
  for (std::size_t i = 0; i < m; ++i) {
    std::vector<double> A, B;
    ends(i, A, B);
    const double h = t[i + 1] - t[i];
    for (std::size_t p = 0; p < n; ++p)
      for (std::size_t q = 0; q < n; ++q) H[p][q] += h / 3 * (A[p] * A[q] + 0.5 * (A[p] * B[q] + B[p] * A[q]) + B[p] * B[q]);
  }
  for (std::size_t k = 0; k < K; ++k) {
    if (d[k] > 0) {
      H[k][k] += 1 / d[k];
      rhs[k] += v[k] / d[k];
    } else {
      rows.push_back(std::vector<double>(n, 0.0));
      rows.back()[k] = 1;
      r.push_back(v[k]);
    }
  }
  for (std::size_t k = closed ? 0 : 1; k < (closed ? K : K - 1); ++k) {  // C2 at knot k
    std::vector<double> A, B, A2, B2;
    ends((k + m - 1) % m, A, B);
    ends(k, A2, B2);
    rows.push_back(std::vector<double>(n, 0.0));
    for (std::size_t p = 0; p < n; ++p) rows.back()[p] = B[p] - A2[p];
    r.push_back(0);
  }
  const std::size_t c = rows.size(), N = n + c;
  std::vector<std::vector<double>> kkt(N, std::vector<double>(N, 0.0));
  std::vector<double> b(N, 0.0);
  for (std::size_t p = 0; p < n; ++p) {
    for (std::size_t q = 0; q < n; ++q) kkt[p][q] = 2 * H[p][q];
    b[p] = 2 * rhs[p];
  }
  for (std::size_t i = 0; i < c; ++i) {
    for (std::size_t p = 0; p < n; ++p) kkt[n + i][p] = kkt[p][n + i] = rows[i][p];
    b[n + i] = r[i];
  }
  const std::vector<double> x = dense_solve(kkt, b);
  std::vector<std::array<double, 4>> out(m);
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t j = (i + 1) % K;
    const double h = t[i + 1] - t[i];
    out[i] = {{x[i], x[i] + h * x[K + i] / 3, x[j] - h * x[K + j] / 3, x[j]}};
  }
  return out;
}

}  // namespace smoothing

// The pentadiagonal Reinsch solve equals the dense constrained minimiser of a different
// parametrisation (Hermite + Lagrange), open (natural ends emerge) and closed (periodic), with
// hard and free vertices at irregular spacing.
TEST(Optimal_fit_smoothing, ReinschSolveMatchesTheDenseConstrainedMinimiser) {
  using fair::internal::optimal::Vec2;
  std::mt19937 rng(25);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const bool closed : {false, true}) {
    const std::size_t n = 13;
    std::vector<Vec2> v;
    for (std::size_t k = 0; k < n; ++k) {
      const double a = 6.0 * static_cast<double>(k) / n + 0.2 * u(rng);
      v.push_back(Vec2{{std::cos(a) * (1 + 0.1 * u(rng)), 0.7 * std::sin(a) + 0.05 * u(rng)}});
    }
    const std::vector<double> t = fair::internal::optimal::chord_breakpoints(v, closed, "test");
    std::vector<double> d(n);
    for (std::size_t k = 0; k < n; ++k) d[k] = (k % 4 == 0) ? 0 : 1e-3 * (1 + 0.5 * u(rng));
    fair::internal::spline::Reinsch_spline s;
    ASSERT_TRUE(fair::internal::spline::smoothing_spline_solve(v, t, closed, d, s));
    const auto pieces = fair::internal::spline::reinsch_bezier_pieces(s, t);
    for (std::size_t c = 0; c < 2; ++c) {
      std::vector<double> vc;
      for (const Vec2& q : v) vc.push_back(q[c]);
      const auto oracle = smoothing::dense_oracle(vc, t, closed, d);
      ASSERT_EQ(oracle.size(), pieces.size());
      for (std::size_t i = 0; i < pieces.size(); ++i)
        for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(pieces[i][k][c], oracle[i][k], 1e-10) << closed << " " << i;
    }
    for (std::size_t k = 0; k < n; k += 4) EXPECT_NEAR(std::hypot(s.y[k][0] - v[k][0], s.y[k][1] - v[k][1]), 0, 1e-14);
    if (!closed) {  // natural ends
      EXPECT_EQ(std::hypot(s.g.front()[0], s.g.front()[1]), 0);
      EXPECT_EQ(std::hypot(s.g.back()[0], s.g.back()[1]), 0);
    }
  }
}

// Tolerance 0: the natural (open) or periodic (closed) C2 interpolant of every vertex, the same
// curve as Cubic_interpolating_spline_2 with chordal knots.
TEST(Optimal_fit_smoothing, ZeroToleranceIsTheNaturalInterpolant) {
  std::mt19937 rng(26);
  for (const bool closed : {false, true}) {
    const std::vector<Pd> p = fair_test::random_points<Kd>(rng, 10);
    const fair::Polygon_smoothing_fit<Kd> fit = fair::fit_smoothing_spline_runs<Kd>(p, closed, {}, {}, 0.0);
    fair::Cubic_interpolating_spline_options o;
    o.closed = closed;
    o.end_condition = fair::Spline_end_condition::NATURAL;
    o.knot_spacing = fair::Knot_spacing::CHORDAL;
    const fair::Cubic_interpolating_spline_2<Kd> ref(p, o);
    ASSERT_EQ(fit.runs.splines.size(), 1u);
    EXPECT_TRUE(fit.report.tolerance_met);
    EXPECT_EQ(fit.report.smoothing, std::vector<double>{0.0});
    const auto a = fit.runs.pieces(), b = ref.spline().pieces();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t k = 0; k < 4; ++k) EXPECT_TRUE(same<Kd>(a[i].control_points()[k], b[i].control_points()[k], 1e-11));
  }
}

// A noisy sample of an ellipse with every 5th vertex interpolated: the input vertices are met to
// rounding, the distance to the polygon is within the tolerance and (the bisection's stop) at
// least 0.9 of it, max_distance bounds a brute-force sampling, the curve is C2, and the smoothing
// removes curvature extrema that the not-a-knot interpolant of every vertex has (the noise).
TEST(Optimal_fit_smoothing, KeepsTheInputPointsWithinTheToleranceAndSmooths) {
  std::mt19937 rng(27);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const bool closed : {false, true}) {
    std::vector<Pd> p;
    const std::size_t n = 60;
    for (std::size_t k = 0; k < n; ++k) {
      const double a = (closed ? 6.283185307179586 : 4.0) * static_cast<double>(k) / n;
      p.push_back(Pd(2 * std::cos(a) + 2e-3 * u(rng), std::sin(a) + 2e-3 * u(rng)));
    }
    std::vector<std::size_t> hard;
    for (std::size_t k = 0; k < n; k += 5) hard.push_back(k);
    const double tolerance = 4e-3;
    const fair::Polygon_smoothing_fit<Kd> fit = fair::fit_smoothing_spline_runs<Kd>(p, closed, hard, {}, tolerance);
    ASSERT_TRUE(fit.report.tolerance_met);
    EXPECT_LE(fit.runs.max_distance, tolerance);
    EXPECT_GE(fit.runs.max_distance, 0.9 * tolerance);
    EXPECT_GT(fit.report.smoothing[0], 0);
    EXPECT_LE(fit.report.solves[0], 40);
    const auto pieces = fit.runs.splines[0].polynomial_pieces();
    ASSERT_EQ(pieces.size(), closed ? n : n - 1);
    for (std::size_t k : hard) {
      const auto a = d2(pieces[k % pieces.size()].source()), b = d2(p[k]);
      EXPECT_NEAR(std::hypot(a[0] - b[0], a[1] - b[1]), 0, 1e-13) << k;
    }
    double brute = 0;
    for (std::size_t i = 0; i < pieces.size(); ++i)
      for (int s = 0; s <= 2000; ++s) {
        const auto x = d2(pieces[i].point(s / 2000.0));
        const auto a = d2(p[i]), b = d2(p[(i + 1) % n]);
        const double ex = b[0] - a[0], ey = b[1] - a[1];
        const double w = std::clamp(((x[0] - a[0]) * ex + (x[1] - a[1]) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
        brute = std::max(brute, std::hypot(x[0] - a[0] - w * ex, x[1] - a[1] - w * ey));
      }
    EXPECT_LE(brute, fit.runs.max_distance * (1 + 1e-7));
    for (std::size_t j = 0; j + 1 < pieces.size(); ++j) {  // C2 (to rounding)
      const double h0 = CGAL::to_double(fit.runs.splines[0].breakpoints()[j + 1] - fit.runs.splines[0].breakpoints()[j]);
      const double h1 = CGAL::to_double(fit.runs.splines[0].breakpoints()[j + 2] - fit.runs.splines[0].breakpoints()[j + 1]);
      EXPECT_TRUE(same<Kd>(pieces[j].second_derivative(1) / (h0 * h0), pieces[j + 1].second_derivative(0) / (h1 * h1), 1e-8));
    }
    const std::size_t smoothed = fair::curvature_extrema(pieces).count();
    const std::size_t interpolated =
        fair::curvature_extrema(fair::fit_cubic_spline<Kd>(p, closed).spline.polynomial_pieces()).count();
    // Measured: 21 against 41 (open), 16 against 48 (closed); asserted: at least a third fewer.
    EXPECT_LE(3 * smoothed, 2 * interpolated) << smoothed << " " << interpolated;
  }
}

// Collinear vertices at irregular spacing with any smoothing: the straight line (zero cost,
// zero residual), every control point on it.
TEST(Optimal_fit_smoothing, ReproducesAStraightLine) {
  const std::vector<int> s{0, 1, 3, 4, 9, 10, 17};
  std::vector<Pd> p;
  for (int k : s) p.push_back(Pd(1 + 0.75 * k, -2 + 0.5 * k));
  const fair::Polygon_smoothing_fit<Kd> fit = fair::fit_smoothing_spline_runs<Kd>(p, false, {3}, {}, 0.1);
  for (const auto& c : fit.runs.splines[0].control_points()) {
    const auto q = d2(c);
    EXPECT_NEAR((q[0] - 1) / 1.5 - (q[1] + 2), 0, 1e-13);
  }
  EXPECT_LE(fit.runs.max_distance, 1e-13);
}

// Bad arguments: typed errors.
TEST(Optimal_fit_smoothing, BadArgumentsAreTypedErrors) {
  const std::vector<Pd> p{Pd(0, 0), Pd(1, 0), Pd(2, 1), Pd(3, 0)};
  EXPECT_THROW(fair::fit_smoothing_spline_runs<Kd>(p, false, {}, {}, -1.0), fair::Precondition_error);
  EXPECT_THROW(fair::fit_smoothing_spline_runs<Kd>(p, false, {}, {}, std::nan("")), fair::Precondition_error);
  EXPECT_THROW(fair::fit_smoothing_spline_runs<Kd>(p, false, {4}, {}, 0.1), fair::Precondition_error);
  EXPECT_THROW(fair::fit_smoothing_spline_runs<Kd>(p, false, {}, {9}, 0.1), fair::Precondition_error);
  EXPECT_THROW(fair::fit_smoothing_spline_runs<Kd>({Pd(0, 0), Pd(0, 0), Pd(1, 1)}, false, {}, {}, 0.1),
               fair::Invalid_input_error);
}

// Corners: the runs meet with G0 at the corners, which (and their neighbours, so that each run
// leaves a corner along its polygon edge) are interpolated; on exact samples of the two arcs of a
// lens the corner tangent error falls with the edge length (O(h): the edge's half turning angle).
TEST(Optimal_fit_smoothing, CornersAreKeptAndTheirTangentsConverge) {
  double previous_error = 0;
  for (int m : {8, 16, 32}) {
    const std::vector<Pd> p = runs::lens(m);
    const std::vector<std::size_t> corners{static_cast<std::size_t>(m), 0};
    // A tolerance above the interpolant's distance (the lens' coarse edges bulge), so that it smooths.
    const double tolerance = 1.5 * fair::fit_cubic_spline_runs<Kd>(p, true, corners).max_distance;
    const auto fit = fair::fit_smoothing_spline_runs<Kd>(p, true, {}, corners, tolerance);
    ASSERT_EQ(fit.runs.splines.size(), 2u);
    EXPECT_EQ(fit.runs.first_vertex, (std::vector<std::size_t>{0, static_cast<std::size_t>(m)}));
    EXPECT_TRUE(fit.report.tolerance_met);
    EXPECT_LE(fit.runs.max_distance, tolerance);
    const auto first = fit.runs.splines[0].polynomial_pieces(), second = fit.runs.splines[1].polynomial_pieces();
    EXPECT_TRUE(same<Kd>(first.front().point(0.0), p[0], 1e-14));
    EXPECT_TRUE(same<Kd>(first.front().point(1.0), p[1], 1e-14));  // the corner's neighbour
    EXPECT_TRUE(same<Kd>(second.front().point(0.0), p[static_cast<std::size_t>(m)], 1e-14));
    EXPECT_TRUE(same<Kd>(second.back().point(1.0), p[0], 1e-14));
    const auto t0 = dv(fit.runs.splines[0].derivative(fit.runs.splines[0].breakpoints().front()));
    const std::array<double, 2> true_t0{{-std::sin(runs::a0()), std::cos(runs::a0())}};
    const double error = runs::angle_between(t0, true_t0);
    const auto e = d2(p[1]), o = d2(p[0]);
    const double edge = runs::angle_between({{e[0] - o[0], e[1] - o[1]}}, true_t0);  // the first edge's
    // Measured 0.080, 0.040, 0.021 rad against the first edge's 0.138, 0.069, 0.035 (half the angle step).
    EXPECT_LE(error, 0.7 * edge) << m;
    if (previous_error > 0) {
      EXPECT_GT(previous_error / error, 1.8) << "tangent error ratio per halving, m = " << m;
    }
    previous_error = error;
  }
}
