// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of fair::Rational_bezier_2 (any degree, homogeneous Bernstein evaluation), typed over
// the four kernels: consistency with the closed forms of Rational_quadratic_bezier_2 and with
// the polynomial fair::Bezier_2, exact homogeneous subdivision, curvature, degenerate input.

#include <fair/Bezier_2.h>
#include <fair/Rational_bezier_2.h>
#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/internal/common/curvature.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <cmath>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

namespace {

using fair_test::is_exact;
using fair_test::q;
using fair_test::same;

template <class K>
class Rational_bezier_test : public ::testing::Test {};

TYPED_TEST_SUITE(Rational_bezier_test, fair_test::All_kernels);

// The general homogeneous evaluation (quotient rule on Bernstein polynomials) and the closed
// forms of the conic class are independent derivations: they agree EXACTLY in exact kernels.
TYPED_TEST(Rational_bezier_test, MatchesRationalQuadraticClosedForms) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> c(-30, 30), wn(1, 40);
  int tested = 0;
  while (tested < 20) {
    const P p0(q<K>(c(rng), 7), q<K>(c(rng), 3)), p1(q<K>(c(rng), 5), q<K>(c(rng), 2)), p2(q<K>(c(rng), 9), q<K>(c(rng), 4));
    if (CGAL::orientation(p0, p1, p2) == CGAL::COLLINEAR || p0 == p2) continue;
    ++tested;
    const fair::Rational_quadratic_bezier_2<K> rq(p0, p1, p2, q<K>(wn(rng), 16));
    const fair::Rational_bezier_2<K> rb(rq);
    EXPECT_EQ(rb.degree(), 2u);
    EXPECT_FALSE(rb.is_polynomial() && rq.weight() != FT(1));
    for (int i = 0; i <= 8; ++i) {
      const FT t = q<K>(i, 8);
      EXPECT_TRUE(same<K>(rb.point(t).x(), rq.point(t).x(), 1e-13));
      EXPECT_TRUE(same<K>(rb.point(t).y(), rq.point(t).y(), 1e-13));
      EXPECT_TRUE(same<K>(rb.derivative(t), rq.derivative(t), 1e-13));
      EXPECT_TRUE(same<K>(rb.second_derivative(t), rq.second_derivative(t), 1e-12));
      EXPECT_TRUE(same<K>(rb.squared_curvature(t), rq.squared_curvature(t), 1e-12));
      EXPECT_NEAR(rb.curvature(i / 8.0), rq.curvature(i / 8.0), 1e-12 * (1 + std::fabs(rq.curvature(i / 8.0))));
    }
  }
}

// Unit weights: the polynomial Bezier curve (checked against fair::Bezier_2, any degree).
TYPED_TEST(Rational_bezier_test, UnitWeightsArePolynomialBezier) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> c(-20, 20);
  for (std::size_t n : {1u, 3u, 5u}) {
    std::vector<P> cp;
    for (std::size_t i = 0; i <= n; ++i) cp.push_back(P(q<K>(c(rng), 3), q<K>(c(rng), 5)));
    const fair::Rational_bezier_2<K> rb(cp);
    const fair::Bezier_2<K> b(cp);
    EXPECT_TRUE(rb.is_polynomial());
    // Equal (non-unit) weights give the same curve.
    const fair::Rational_bezier_2<K> rb3(cp, std::vector<FT>(n + 1, q<K>(3, 7)));
    for (int i = 0; i <= 6; ++i) {
      const FT t = q<K>(i, 6);
      EXPECT_TRUE(same<K>(rb.point(t).x(), b.point(t).x(), 1e-13));
      EXPECT_TRUE(same<K>(rb.point(t).y(), b.point(t).y(), 1e-13));
      EXPECT_TRUE(same<K>(rb.derivative(t), b.derivative(t), 1e-13));
      EXPECT_TRUE(same<K>(rb.second_derivative(t), b.second_derivative(t), 1e-13));
      EXPECT_TRUE(same<K>(rb3.point(t).x(), b.point(t).x(), 1e-13));
      EXPECT_TRUE(same<K>(rb3.second_derivative(t), b.second_derivative(t), 1e-13));
    }
  }
}

// Homogeneous de Casteljau split: exact, parametrisation-preserving, weights stay positive.
TYPED_TEST(Rational_bezier_test, SplitIsExact) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  const std::vector<P> cp = {P(0, 0), P(1, 3), P(4, 4), P(6, -1), P(8, 2)};
  const std::vector<FT> w = {q<K>(1), q<K>(3, 2), q<K>(1, 4), q<K>(5), q<K>(2, 3)};
  const fair::Rational_bezier_2<K> c(cp, w);
  for (const FT& s : {q<K>(1, 3), q<K>(5, 8)}) {
    const auto parts = c.split(s);
    for (const FT& x : parts.first.weights()) EXPECT_GT(CGAL::to_double(x), 0.0);
    for (int i = 0; i <= 5; ++i) {
      const FT u = q<K>(i, 5);
      const P a = parts.first.point(u), b = c.point(s * u);
      const P d = parts.second.point(u), e = c.point(s + (FT(1) - s) * u);
      EXPECT_TRUE(same<K>(a.x(), b.x(), 1e-13) && same<K>(a.y(), b.y(), 1e-13));
      EXPECT_TRUE(same<K>(d.x(), e.x(), 1e-13) && same<K>(d.y(), e.y(), 1e-13));
      // Chain rule: left'(u) = s c'(s u).
      EXPECT_TRUE(same<K>(parts.first.derivative(u), c.derivative(s * u) * s, 1e-12));
    }
  }
  // Reversal.
  const fair::Rational_bezier_2<K> r = c.reversed();
  for (int i = 0; i <= 4; ++i) {
    const FT t = q<K>(i, 4);
    EXPECT_TRUE(same<K>(r.point(t).x(), c.point(FT(1) - t).x(), 1e-13));
    EXPECT_TRUE(same<K>(r.derivative(t), -c.derivative(FT(1) - t), 1e-13));
  }
  EXPECT_THROW(c.split(FT(0)), fair::Precondition_error);
  EXPECT_THROW(c.split(FT(1)), fair::Precondition_error);
}

// A full circle quadrant as a rational cubic (the degree-elevated quarter circle of weight
// sqrt(2)/2 is irrational; the cubic below with weights 1, 1/3, 1/3, 1 is exact): its points
// are on the unit circle, and the curvature is 1 in double.
TYPED_TEST(Rational_bezier_test, RationalCubicCircle) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  // Semicircle through (1,0), (0,1), (-1,0): control points (1,0), (1,2), (-1,2), (-1,0),
  // weights (1, 1/3, 1/3, 1).
  const fair::Rational_bezier_2<K> c({P(1, 0), P(1, 2), P(-1, 2), P(-1, 0)}, {FT(1), q<K>(1, 3), q<K>(1, 3), FT(1)});
  for (int i = 0; i <= 10; ++i) {
    const P p = c.point(q<K>(i, 10));
    EXPECT_TRUE(same<K>(p.x() * p.x() + p.y() * p.y(), FT(1), 1e-13));
    EXPECT_TRUE(same<K>(c.squared_curvature(q<K>(i, 10)), FT(1), 1e-12));
    EXPECT_NEAR(c.curvature(i / 10.0), 1.0, 1e-13);
  }
  EXPECT_TRUE(same<K>(c.point(q<K>(1, 2)).y(), FT(1), 1e-13));
}

TYPED_TEST(Rational_bezier_test, BadInputThrows) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  typedef fair::Rational_bezier_2<K> Rb;
  EXPECT_THROW(Rb(std::vector<P>{}), fair::Precondition_error);
  EXPECT_THROW(Rb({P(0, 0), P(1, 1)}, {FT(1)}), fair::Precondition_error);
  EXPECT_THROW(Rb({P(0, 0), P(1, 1)}, {FT(1), FT(0)}), fair::Precondition_error);
  EXPECT_THROW(Rb({P(0, 0), P(1, 1)}, {FT(-1), FT(1)}), fair::Precondition_error);
  if (!is_exact<K>()) {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(Rb({P(0, 0), P(1, 1)}, {FT(1), FT(nan)}), fair::Precondition_error);
    EXPECT_THROW(Rb({P(0, 0), P(1, 1)}, {FT(inf), FT(1)}), fair::Precondition_error);
    EXPECT_THROW(Rb({P(0, nan), P(1, 1)}), fair::Precondition_error);
  }
  const Rb c({P(0, 0), P(0, 0), P(1, 1), P(2, 0)}, {FT(1), FT(2), FT(1), FT(1)}); // c'(0) = 0: cusp
  EXPECT_THROW(c.curvature(0.0), fair::Precondition_error);
  EXPECT_THROW(c.squared_curvature(FT(0)), fair::Precondition_error);
  EXPECT_NO_THROW(c.curvature(0.5));
  EXPECT_THROW(c.point(FT(2)), fair::Precondition_error);
  EXPECT_THROW(c.curvature(-0.1), fair::Precondition_error);
  EXPECT_THROW(c.control_point(4), fair::Precondition_error);
  EXPECT_THROW(c.weight(4), fair::Precondition_error);
  const Rb point({P(3, 4)});
  EXPECT_TRUE(point.point(q<K>(1, 2)) == P(3, 4));
  EXPECT_THROW(point.curvature(0.5), fair::Precondition_error);
}

// The curvature is scale-safe (internal/common/curvature.h): scaling the control points by lambda
// divides it by lambda, also at 2^+-500 and 1e+-150 where |c'|^3 overflows or underflows (the
// former formula det / |c'|^3 returned 0, inf or NaN there). Powers of two scale every
// intermediate exactly, so the result is the same bit for bit.
template <class K>
class Rational_bezier_scale_test : public ::testing::Test {};
TYPED_TEST_SUITE(Rational_bezier_scale_test, fair_test::Floating_kernels);

TYPED_TEST(Rational_bezier_scale_test, CurvatureIsScaleCovariant) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef fair::Rational_bezier_2<K> Rb;
  std::mt19937 rng(20261201);
  std::uniform_real_distribution<double> U(-1.0, 1.0), Wd(0.25, 4.0);
  int checked = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t n = 2 + trial % 4;  // degrees 2..5
    std::vector<double> x(n + 1), y(n + 1), w(n + 1);
    for (std::size_t i = 0; i <= n; ++i) { x[i] = U(rng); y[i] = U(rng); w[i] = Wd(rng); }
    auto scaled = [&](double lambda) {
      std::vector<P> cp;
      for (std::size_t i = 0; i <= n; ++i) cp.push_back(P(lambda * x[i], lambda * y[i]));
      return Rb(cp, std::vector<typename K::FT>(w.begin(), w.end()));
    };
    const Rb base = scaled(1.0);
    for (const double lambda : {0x1p500, 0x1p-500, 1e150, 1e-150}) {
      const Rb c = scaled(lambda);
      const bool pow2 = lambda == 0x1p500 || lambda == 0x1p-500;
      for (int i = 0; i <= 8; ++i) {
        const double t = i / 8.0, kb = base.curvature(t);
        if (std::fabs(kb) < 1e-6) continue;  // nearly straight: the relative test is meaningless
        const double k = c.curvature(t);
        ASSERT_TRUE(std::isfinite(k)) << lambda << " " << t;
        if (pow2) {
          EXPECT_EQ(k * lambda, kb) << lambda << " " << t;
        } else {
          // each coordinate is rounded once by the decimal scaling
          EXPECT_NEAR(k * lambda / kb, 1.0, 1e-9) << lambda << " " << t;
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(Signed_curvature, ScaleSafeAndDefinedAtASingularPoint) {
  using fair::internal::common::signed_curvature;
  // Unit circle at (1, 0): c' = (0, 1), c'' = (-1, 0): kappa = 1.
  EXPECT_EQ(signed_curvature(0, 1, -1, 0), 1.0);
  for (const double s : {0x1p-1000, 0x1p-500, 0x1p500, 0x1p1000}) {
    // c' scaled by s, c'' by s: kappa / s, exact for powers of two.
    EXPECT_EQ(signed_curvature(0, s, -s, 0), 1.0 / s);
    EXPECT_EQ(signed_curvature(3 * s, 4 * s, -4 * s, 3 * s), 1.0 / (5 * s)) << s;
  }
  // A singular point (c' = 0) gives 0, never NaN; a straight piece (c'' = 0) too.
  EXPECT_EQ(signed_curvature(0, 0, 1, 2), 0.0);
  EXPECT_EQ(signed_curvature(1, 2, 0, 0), 0.0);
  EXPECT_TRUE(std::isnan(signed_curvature(std::numeric_limits<double>::infinity(), 0, 1, 0)));
}

} // namespace
