// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of fair::Bezier_2: exact identities (de Casteljau, subdivision, hodograph, elevation) in
// exact kernels, closed-form curvature, random property tests and bad input.

#include <fair/Bezier_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace fair_test;

// Binomial-sum (power of t, 1-t) evaluation: an independent formula for c(t).
template <class K>
typename K::Point_2 bernstein_sum(const std::vector<typename K::Point_2>& P, const typename K::FT& t) {
  typedef typename K::FT FT;
  const std::size_t n = P.size() - 1;
  FT x(0), y(0);
  for (std::size_t i = 0; i <= n; ++i) {
    FT b(1);
    for (std::size_t k = 0; k < i; ++k) b = b * FT(static_cast<int>(n - k)) / FT(static_cast<int>(k + 1));
    for (std::size_t k = 0; k < i; ++k) b *= t;
    for (std::size_t k = i; k < n; ++k) b *= FT(1) - t;
    x += b * P[i].x();
    y += b * P[i].y();
  }
  return typename K::Point_2(x, y);
}

template <class K>
class Bezier_typed : public ::testing::Test {};
TYPED_TEST_SUITE(Bezier_typed, All_kernels);

TYPED_TEST(Bezier_typed, ExactIdentitiesOnRandomPieces) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(-20, 20);
  for (std::size_t n : {1u, 2u, 3u, 5u, 8u}) {
    std::vector<P> cp;
    for (std::size_t i = 0; i <= n; ++i) cp.emplace_back(FT(coord(rng)) / FT(3), FT(coord(rng)) / FT(7));
    const fair::Bezier_2<K> c(cp);
    ASSERT_EQ(c.degree(), n);
    EXPECT_TRUE(same<K>(c.point(FT(0)), cp.front()));
    EXPECT_TRUE(same<K>(c.point(FT(1)), cp.back()));
    const FT ts[] = {FT(1) / FT(5), FT(1) / FT(2), FT(5) / FT(6)};
    const auto h = c.hodograph();
    const auto e = c.elevated();
    EXPECT_EQ(e.degree(), n + 1);
    for (const FT& t : ts) {
      EXPECT_TRUE(same<K>(c.point(t), bernstein_sum<K>(cp, t)));
      EXPECT_TRUE(same<K>(c.point(t), P(c.x_polynomial().evaluate(t), c.y_polynomial().evaluate(t))));
      EXPECT_TRUE(same<K>(c.derivative(t), typename K::Vector_2(c.x_polynomial().derivative().evaluate(t),
                                                           c.y_polynomial().derivative().evaluate(t))));
      // The hodograph evaluates to c'(t); its hodograph to c''(t).
      EXPECT_TRUE(same<K>(h.point(t) - CGAL::ORIGIN, c.derivative(t)));
      EXPECT_TRUE(same<K>(h.hodograph().point(t) - CGAL::ORIGIN, c.second_derivative(t)));
      EXPECT_TRUE(same<K>(e.point(t), c.point(t)));
      EXPECT_TRUE(same<K>(c.reversed().point(FT(1) - t), c.point(t)));
      // Subdivision: left(u) = c(t u), right(u) = c(t + (1-t) u); derivatives scale by t, 1-t.
      const auto s = c.split(t);
      const FT u = FT(2) / FT(3);
      EXPECT_TRUE(same<K>(s.first.point(u), c.point(t * u)));
      EXPECT_TRUE(same<K>(s.second.point(u), c.point(t + (FT(1) - t) * u)));
      EXPECT_TRUE(same<K>(s.first.derivative(u), c.derivative(t * u) * t));
      EXPECT_TRUE(same<K>(s.second.second_derivative(u), c.second_derivative(t + (FT(1) - t) * u) * ((FT(1) - t) * (FT(1) - t))));
      EXPECT_TRUE(same<K>(c.subcurve(t / FT(2), t).point(FT(1)), c.point(t)));
    }
    EXPECT_TRUE(c.nth_derivative(FT(1) / FT(3), n + 1) == typename K::Vector_2(0, 0));
    EXPECT_TRUE(c.nth_derivative(FT(1) / FT(3), 0) == c.point(FT(1) / FT(3)) - CGAL::ORIGIN);
  }
}

TYPED_TEST(Bezier_typed, ParabolaCurvature) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  // x = 2t - 1, y = (2t - 1)^2: the parabola y = x^2, kappa = 2 / (1 + 4x^2)^(3/2).
  const fair::Bezier_2<K> c(std::vector<P>{P(-1, 1), P(0, -1), P(1, 1)});
  for (double t : {0.0, 0.1, 0.5, 0.77, 1.0}) {
    const double x = 2 * t - 1;
    EXPECT_NEAR(c.curvature(t), 2 / std::pow(1 + 4 * x * x, 1.5), 1e-14);
  }
  // Cubic control polygon of a quarter circle approximation turns left: positive curvature.
  const fair::Bezier_2<K> q(P(1, 0), P(1, 1), P(0, 1), P(-1, 1));
  EXPECT_GT(q.curvature(0.3), 0);
  EXPECT_LT(q.reversed().curvature(0.7), 0);
}

TYPED_TEST(Bezier_typed, BadArguments) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  EXPECT_THROW(fair::Bezier_2<K>(std::vector<P>{}), fair::Precondition_error);
  const fair::Bezier_2<K> c(P(0, 0), P(1, 0), P(2, 0), P(3, 0));
  EXPECT_THROW(c.split(FT(0)), fair::Precondition_error);
  EXPECT_THROW(c.split(FT(1)), fair::Precondition_error);
  EXPECT_THROW(c.subcurve(FT(1) / FT(2), FT(1) / FT(4)), fair::Precondition_error);
  EXPECT_THROW(c.control_point(4), fair::Precondition_error);
  // A cusp: c'(1/2) = 0 -> curvature is undefined there, reported, never NaN.
  const fair::Bezier_2<K> cusp(P(0, 0), P(2, 2), P(-1, 2), P(3, 0));
  EXPECT_THROW(cusp.curvature(0.5), fair::Precondition_error);
  // Degree 0: a point, zero derivative; its hodograph is the origin.
  const fair::Bezier_2<K> pt(std::vector<P>{P(3, 4)});
  EXPECT_TRUE(pt.point(FT(1) / FT(3)) == P(3, 4));
  EXPECT_TRUE(pt.derivative(FT(0)) == typename K::Vector_2(0, 0));
  EXPECT_EQ(pt.hodograph().degree(), 0u);
}

TEST(Bezier, DerivativesMatchFiniteDifferences) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<SC_double::Point_2> cp;
    for (int i = 0; i < 6; ++i) cp.emplace_back(u(rng), u(rng));
    const fair::Bezier_2<SC_double> c(cp);
    const double t = 0.37, h = 1e-5;
    const auto fd = (c.point(t + h) - c.point(t - h)) / (2 * h);
    const auto d = c.derivative(t);
    EXPECT_NEAR(fd.x(), d.x(), 1e-5 * (1 + std::fabs(d.x())));
    const auto fd2 = (c.derivative(t + h) - c.derivative(t - h)) / (2 * h);
    EXPECT_NEAR(fd2.y(), c.second_derivative(t).y(), 1e-5 * (1 + std::fabs(fd2.y())));
    double d1x, d1y, d2x, d2y;
    c.derivatives_double(t, d1x, d1y, d2x, d2y);
    EXPECT_NEAR(d1y, d.y(), 1e-9 * (1 + std::fabs(d.y())));
  }
}

TEST(Bezier, HugeAndTinyCoordinates) {
  typedef SC_double::Point_2 P;
  for (double s : {1e150, 1e-150}) {
    const fair::Bezier_2<SC_double> c(P(0, 0), P(s, 0), P(s, s), P(0, s));
    // Curvature scales as 1/s.
    const fair::Bezier_2<SC_double> unit(P(0, 0), P(1, 0), P(1, 1), P(0, 1));
    EXPECT_NEAR(c.curvature(0.4) * s, unit.curvature(0.4), 1e-12);
    EXPECT_NEAR(c.point(0.5).y() / s, 0.5, 1e-15);
  }
  // Powers of two scale every intermediate of the curvature exactly (internal/common/curvature.h):
  // the same value bit for bit, also where |c'|^3 is far outside the double range.
  const fair::Bezier_2<SC_double> unit(P(0, 0), P(1, 0.25), P(1.5, 1), P(0, 1));
  for (double s : {0x1p-900, 0x1p-500, 0x1p500, 0x1p900}) {
    const fair::Bezier_2<SC_double> c(P(0, 0), P(s, 0.25 * s), P(1.5 * s, s), P(0, s));
    for (double t : {0.0, 0.3, 0.5, 1.0}) EXPECT_EQ(c.curvature(t) * s, unit.curvature(t)) << s << " " << t;
  }
}

} // namespace
