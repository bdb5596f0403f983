// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of fair::Rational_quadratic_bezier_2 (Yan, Schiller, Schaefer, rational kappa-curves:
// eq. 1, 4, 5, 6, 7, 14, 15 and Appendix A), typed over the four kernels.

#include <fair/Rational_quadratic_bezier_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using fair_test::is_exact;
using fair_test::q;
using fair_test::same;

typedef CGAL::Simple_cartesian<CGAL::Gmpq> Kq;

template <class K>
typename K::Point_2 pt(int xn, int xd, int yn, int yd) {
  return typename K::Point_2(q<K>(xn, xd), q<K>(yn, yd));
}

double dbl(const CGAL::Gmpq& x) { return CGAL::to_double(x); }

// A half angle beta with rational cos and sin: cos = c/d, sin = s/d (Pythagorean triple).
struct Half_angle {
  int c, s, d;
};
const Half_angle H0{1, 0, 1};      //   0 deg
const Half_angle H7{24, 7, 25};    //  16.26 deg
const Half_angle Hm7{24, -7, 25};  // -16.26 deg
const Half_angle H8{15, 8, 17};    //  28.07 deg
const Half_angle H3{4, 3, 5};      //  36.87 deg
const Half_angle H4{3, 4, 5};      //  53.13 deg
const Half_angle H15{8, 15, 17};   //  61.93 deg

// The arc of the unit circle from angle 2 beta0 to 2 beta2 (rational points: cos 2b = c^2 - s^2,
// sin 2b = 2 c s), P1 = (U0 + U2) / (1 + U0.U2) (tangent intersection), w = cos(beta2 - beta0),
// rational. With x_scale = 2 the arc of the ellipse x^2/4 + y^2 = 1 (the standard-form weight
// is affinely invariant).
template <class K>
fair::Rational_quadratic_bezier_2<K> circle_arc(Half_angle b0, Half_angle b2, int x_scale = 1) {
  typedef typename K::FT FT;
  const FT c0 = q<K>(b0.c, b0.d), s0 = q<K>(b0.s, b0.d), c2 = q<K>(b2.c, b2.d), s2 = q<K>(b2.s, b2.d);
  const FT u0x = c0 * c0 - s0 * s0, u0y = FT(2) * c0 * s0, u2x = c2 * c2 - s2 * s2, u2y = FT(2) * c2 * s2;
  const FT den = FT(1) + u0x * u2x + u0y * u2y;
  const FT w = c0 * c2 + s0 * s2;
  const FT sx(x_scale);
  return fair::Rational_quadratic_bezier_2<K>(typename K::Point_2(sx * u0x, u0y),
                                              typename K::Point_2(sx * (u0x + u2x) / den, (u0y + u2y) / den),
                                              typename K::Point_2(sx * u2x, u2y), w);
}

// The arc of y = x^2 from x = a to x = b: P1 = ((a+b)/2, ab), w = 1.
template <class K>
fair::Rational_quadratic_bezier_2<K> parabola_arc(int a, int b) {
  return fair::Rational_quadratic_bezier_2<K>(pt<K>(a, 1, a * a, 1), pt<K>(a + b, 2, a * b, 1),
                                              pt<K>(b, 1, b * b, 1), q<K>(1));
}

// The arc of xy = 1 from (a, 1/a) to (b, 1/b), a = an/ad, b = bn/bd with ab a rational square:
// P1 = (2ab/(a+b), 2/(a+b)), w = (a+b) / (2 sqrt(ab)) (derived from the factorisation
// x = (a(1-t) + b k t)^2 / D, y = ((1-t) + k t)^2 / D).
template <class K>
fair::Rational_quadratic_bezier_2<K> hyperbola_arc(int an, int ad, int bn, int bd, int sqrt_ab_n, int sqrt_ab_d) {
  typedef typename K::FT FT;
  const FT a = q<K>(an, ad), b = q<K>(bn, bd), r = q<K>(sqrt_ab_n, sqrt_ab_d);
  return fair::Rational_quadratic_bezier_2<K>(typename K::Point_2(a, FT(1) / a),
                                              typename K::Point_2(FT(2) * a * b / (a + b), FT(2) / (a + b)),
                                              typename K::Point_2(b, FT(1) / b), (a + b) / (FT(2) * r));
}

std::vector<int> kinds_of(const std::vector<fair::Curvature_extremum>& e) {
  std::vector<int> out;
  for (const fair::Curvature_extremum& x : e) out.push_back(static_cast<int>(x.kind));
  return out;
}
const int MAX = static_cast<int>(fair::Curvature_extremum_kind::MAXIMUM);
const int MIN = static_cast<int>(fair::Curvature_extremum_kind::MINIMUM);

// Exact value of the eq.-7 quartic (Bernstein coefficients of eq. A.1), computed independently
// of the library from exact inputs.
CGAL::Gmpq eq7_value(const Kq::Point_2& p0, const Kq::Point_2& qq, const Kq::Point_2& p2, const CGAL::Gmpq& w,
                     const CGAL::Gmpq& t) {
  const Kq::Vector_2 v0 = p0 - qq, v2 = p2 - qq;
  const CGAL::Gmpq A = v0 * v0, B = v0 * v2, C = v2 * v2, s = CGAL::Gmpq(1) - t;
  return -w * A * s * s * s * s - (A + B) * s * s * s * t + (B + C) * s * t * t * t + w * C * t * t * t * t;
}

template <class K>
Kq::Point_2 to_q(const typename K::Point_2& p) {
  return Kq::Point_2(fair::internal::common::to_gmpq(p.x()), fair::internal::common::to_gmpq(p.y()));
}

template <class K>
class Rational_quadratic_test : public ::testing::Test {};

TYPED_TEST_SUITE(Rational_quadratic_test, fair_test::All_kernels);

// ------------------------------------------------------------------ circles
TYPED_TEST(Rational_quadratic_test, CircularArcsHaveConstantCurvature) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const Half_angle arcs[][2] = {{H0, H4}, {H0, H3}, {Hm7, H3}, {H7, H15}, {Hm7, H8}};
  for (const auto& a : arcs) {
    const fair::Rational_quadratic_bezier_2<K> c = circle_arc<K>(a[0], a[1]);
    EXPECT_EQ(c.conic_type(), fair::Conic_type::ELLIPSE);
    EXPECT_EQ(c.orientation(), CGAL::LEFT_TURN);
    for (int i = 0; i <= 8; ++i) {
      const FT t = q<K>(i, 8);
      EXPECT_TRUE(same<K>(c.squared_curvature(t), FT(1), 1e-13));
      EXPECT_NEAR(c.curvature(i / 8.0), 1.0, 1e-14);
      const typename K::Point_2 p = c.point(t);
      EXPECT_TRUE(same<K>(p.x() * p.x() + p.y() * p.y(), FT(1), 1e-13)); // on the unit circle
      EXPECT_TRUE(same<K>(c.implicit_value(p), FT(0), 1e-14));
    }
    // eq. 5
    EXPECT_TRUE(same<K>(c.squared_curvature_at_source(), FT(1), 1e-13));
    EXPECT_TRUE(same<K>(c.squared_curvature_at_target(), FT(1), 1e-13));
    EXPECT_NEAR(c.curvature_at_source(), 1.0, 1e-14);
    EXPECT_NEAR(c.curvature_at_target(), 1.0, 1e-14);
    // eq. 15 reproduces the circle's weight, and the conic is a circle: (a-c)^2 + b^2 = 0.
    EXPECT_TRUE(same<K>(c.minimum_eccentricity_weight_squared(), c.weight() * c.weight(), 1e-13));
    if constexpr (is_exact<K>()) {
      typedef typename fair::Rational_quadratic_bezier_2<K>::Sqrt_extension_FT S;
      EXPECT_EQ(CGAL::compare(c.minimum_eccentricity_weight_sqrt_extension(), S(c.weight())), CGAL::EQUAL);
    }
    EXPECT_NEAR(c.minimum_eccentricity_weight(), CGAL::to_double(c.weight()), 1e-15);
    const std::array<FT, 6> e = c.implicit_coefficients();
    EXPECT_TRUE(same<K>(e[0], e[2], 1e-13));
    EXPECT_TRUE(same<K>(e[1] / e[0], FT(0), 1e-13));
    if (is_exact<K>()) {
      // eq. 4 vanishes IDENTICALLY for a circle.
      const fair::Bernstein_polynomial<FT> E = c.curvature_derivative_numerator();
      for (const FT& x : E.coefficients()) EXPECT_TRUE(CGAL::is_zero(x));
      EXPECT_TRUE(c.has_constant_curvature());
      EXPECT_TRUE(c.curvature_extrema().empty());
      EXPECT_EQ(c.eccentricity(), 0.0);
    } else {
      double scale = 0;
      const fair::Bernstein_polynomial<FT> E = c.curvature_derivative_numerator();
      for (const FT& x : E.coefficients()) scale = std::max(scale, std::fabs(CGAL::to_double(x)));
      EXPECT_LT(scale, 1e-14);
      EXPECT_LT(c.eccentricity(), 1e-6); // sqrt of a rounding-level quantity
    }
  }
  // The 120-degree arc, w = cos 60 = 1/2 (its control triangle is equilateral, so it has no
  // rational coordinates; approximate points in floating kernels only).
  if (!is_exact<K>()) {
    const double r3 = std::sqrt(3.0);
    const fair::Rational_quadratic_bezier_2<K> c(typename K::Point_2(0.5, -r3 / 2), typename K::Point_2(2, 0),
                                                 typename K::Point_2(0.5, r3 / 2), FT(0.5));
    for (int i = 0; i <= 10; ++i) EXPECT_NEAR(c.curvature(i / 10.0), 1.0, 1e-14);
    EXPECT_NEAR(c.minimum_eccentricity_weight(), 0.5, 1e-15);
  }
}

// ------------------------------------------------------------------ parabolas
TYPED_TEST(Rational_quadratic_test, ParabolaArcs) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const fair::Rational_quadratic_bezier_2<K> c = parabola_arc<K>(-1, 2);
  EXPECT_EQ(c.conic_type(), fair::Conic_type::PARABOLA);
  EXPECT_TRUE(same<K>(c.conic_discriminant(), FT(0), 1e-13));
  EXPECT_EQ(c.eccentricity(), 1.0);
  for (int i = 0; i <= 12; ++i) {
    const FT t = q<K>(i, 12);
    const typename K::Point_2 p = c.point(t);
    EXPECT_TRUE(same<K>(p.y(), p.x() * p.x(), 1e-13));   // on y = x^2
    EXPECT_TRUE(same<K>(p.x(), FT(-1) + FT(3) * t, 1e-13)); // x is affine in t for w = 1
    const double x = CGAL::to_double(p.x());
    EXPECT_NEAR(c.curvature(i / 12.0), 2.0 / std::pow(1 + 4 * x * x, 1.5), 1e-14); // y = x^2
  }
  // w = 1: the eq.-4 quartic degenerates to a cubic (leading power coefficient 0).
  EXPECT_TRUE(same<K>(c.curvature_derivative_numerator().to_power_basis()[4], FT(0), 1e-12));
  // One maximum of |kappa|, at the vertex x = 0, i.e. t = 1/3.
  const std::vector<fair::Curvature_extremum> e = c.curvature_extrema();
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].kind, fair::Curvature_extremum_kind::MAXIMUM);
  EXPECT_NEAR(e[0].t, 1.0 / 3.0, 1e-15);
  if (is_exact<K>()) {
    EXPECT_TRUE(e[0].t_lower < CGAL::Gmpq(1, 3) && CGAL::Gmpq(1, 3) < e[0].t_upper);
    EXPECT_TRUE(c.point(q<K>(1, 3)) == typename K::Point_2(0, 0));
  }
  // An arc that does not contain the vertex: no critical point of curvature.
  EXPECT_TRUE(parabola_arc<K>(1, 3).curvature_extrema().empty());
  EXPECT_TRUE(parabola_arc<K>(-4, -1).curvature_extrema().empty());
}

// ------------------------------------------------------------------ hyperbolas
TYPED_TEST(Rational_quadratic_test, HyperbolaArcs) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  // Symmetric arc of xy = 1 from (1/2, 2) to (2, 1/2), w = 5/4: one maximum at the vertex (1,1).
  const fair::Rational_quadratic_bezier_2<K> c = hyperbola_arc<K>(1, 2, 2, 1, 1, 1);
  EXPECT_TRUE(same<K>(c.weight(), q<K>(5, 4), 1e-13));
  EXPECT_EQ(c.conic_type(), fair::Conic_type::HYPERBOLA);
  EXPECT_GT(CGAL::to_double(c.conic_discriminant()), 0.0);
  EXPECT_NEAR(c.eccentricity(), std::sqrt(2.0), 1e-14); // rectangular hyperbola
  for (int i = 0; i <= 10; ++i) {
    const typename K::Point_2 p = c.point(q<K>(i, 10));
    EXPECT_TRUE(same<K>(p.x() * p.y(), FT(1), 1e-13));
    const double x = CGAL::to_double(p.x());
    // curvature of y = 1/x: 2/x^3 / (1 + 1/x^4)^(3/2); the arc runs with decreasing y: right turn.
    EXPECT_NEAR(std::fabs(c.curvature(i / 10.0)), 2 / (x * x * x) / std::pow(1 + 1 / (x * x * x * x), 1.5), 1e-13);
  }
  const std::vector<fair::Curvature_extremum> e = c.curvature_extrema();
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].kind, fair::Curvature_extremum_kind::MAXIMUM);
  if (is_exact<K>()) {
    EXPECT_TRUE(e[0].t_lower == CGAL::Gmpq(1, 2) && e[0].t_upper == CGAL::Gmpq(1, 2)); // exact root
    EXPECT_TRUE(c.point(q<K>(1, 2)) == typename K::Point_2(1, 1));
  } else {
    EXPECT_NEAR(e[0].t, 0.5, 1e-15);
  }
  // A wider symmetric arc, w = 17/8, and an arc beside the vertex: 1 and 0 extrema.
  EXPECT_EQ(kinds_of(hyperbola_arc<K>(1, 4, 4, 1, 1, 1).curvature_extrema()), std::vector<int>{MAX});
  const fair::Rational_quadratic_bezier_2<K> side = hyperbola_arc<K>(2, 1, 8, 1, 4, 1);
  EXPECT_TRUE(same<K>(side.weight(), q<K>(5, 4), 1e-13));
  EXPECT_TRUE(side.curvature_extrema().empty());
}

// ------------------------------------------------------------------ ellipses, Fig. 1
TYPED_TEST(Rational_quadratic_test, EllipseArcsHaveZeroOneOrTwoExtrema) {
  typedef TypeParam K;
  // Arcs of x^2/4 + y^2 = 1 (the unit-circle arcs scaled by 2 in x); |kappa| is maximal at
  // (+-2, 0) and minimal at (0, +-1). The angle alpha of the circle runs with t.
  struct Case {
    Half_angle b0, b2;
    std::vector<int> kinds;
  };
  const Case cases[] = {{Hm7, H7, {MAX}},        // alpha in [-32.5, 32.5] deg
                        {H8, H15, {MIN}},        // alpha in [56.1, 123.9] deg
                        {Hm7, H4, {MAX, MIN}},   // alpha in [-32.5, 106.3] deg
                        {H7, H3, {}}};           // alpha in [32.5, 73.7] deg
  for (const Case& cs : cases) {
    const fair::Rational_quadratic_bezier_2<K> c = circle_arc<K>(cs.b0, cs.b2, 2);
    EXPECT_EQ(c.conic_type(), fair::Conic_type::ELLIPSE);
    EXPECT_LT(CGAL::to_double(c.conic_discriminant()), 0.0);
    EXPECT_NEAR(c.eccentricity(), std::sqrt(3.0) / 2, 1e-14);
    EXPECT_FALSE(c.has_constant_curvature());
    const std::vector<fair::Curvature_extremum> e = c.curvature_extrema();
    EXPECT_EQ(kinds_of(e), cs.kinds);
    for (const fair::Curvature_extremum& x : e) {
      const typename K::Point_2 p = c.point(typename K::FT(x.t));
      if (x.kind == fair::Curvature_extremum_kind::MAXIMUM) EXPECT_NEAR(CGAL::to_double(p.y()), 0.0, 1e-12);
      else EXPECT_NEAR(CGAL::to_double(p.x()), 0.0, 1e-12);
      EXPECT_TRUE(dbl(x.t_lower) - 1e-15 <= x.t && x.t <= dbl(x.t_upper) + 1e-15);
    }
  }
}

// Classification of random pieces checked by sampling |kappa| in double around each extremum,
// and the Sec. 3.1 bounds: at most 2 critical points for an ellipse, 1 for w >= 1.
TYPED_TEST(Rational_quadratic_test, ExtremaClassificationMatchesSampling) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::mt19937_64 rng(314159);
  std::uniform_real_distribution<double> u(-1.0, 1.0), lw(-2.0, 1.5);
  int tested = 0, classified = 0, two = 0;
  while (tested < (is_exact<K>() ? 60 : 300)) {
    const typename K::Point_2 p0(u(rng), u(rng)), p1(u(rng), u(rng)), p2(u(rng), u(rng));
    if (std::fabs(CGAL::to_double(CGAL::area(p0, p1, p2))) < 1e-2) continue;
    ++tested;
    const double wd = std::pow(2.0, lw(rng));
    const fair::Rational_quadratic_bezier_2<K> c(p0, p1, p2, FT(wd));
    const std::vector<fair::Curvature_extremum> e = c.curvature_extrema();
    EXPECT_LE(e.size(), wd < 1 ? 2u : 1u);
    if (e.size() == 2) {
      ++two;
      EXPECT_NE(e[0].kind, e[1].kind); // one maximum and one minimum
    }
    for (std::size_t i = 0; i < e.size(); ++i) {
      const double t = e[i].t;
      double gap = std::min(t, 1 - t);
      if (i > 0) gap = std::min(gap, t - e[i - 1].t);
      if (i + 1 < e.size()) gap = std::min(gap, e[i + 1].t - t);
      const double d = std::min(1e-2, gap / 2);
      const double k0 = std::fabs(c.curvature(t)), ka = std::fabs(c.curvature(t - d)), kb = std::fabs(c.curvature(t + d));
      if (std::fabs(ka - k0) < 1e-9 * k0 || std::fabs(kb - k0) < 1e-9 * k0) continue; // too flat to sample
      ++classified;
      if (e[i].kind == fair::Curvature_extremum_kind::MAXIMUM) {
        EXPECT_LT(ka, k0) << c;
        EXPECT_LT(kb, k0) << c;
      } else {
        EXPECT_EQ(e[i].kind, fair::Curvature_extremum_kind::MINIMUM);
        EXPECT_GT(ka, k0) << c;
        EXPECT_GT(kb, k0) << c;
      }
    }
    // Between the extrema |kappa| is monotone: sampled increments have the sign predicted by
    // the kinds (checked on a coarse grid away from the extrema).
    for (int j = 0; j < 40; ++j) {
      const double a = j / 40.0, b = (j + 1) / 40.0;
      bool near = false;
      for (const fair::Curvature_extremum& x : e) near = near || (x.t > a - 0.02 && x.t < b + 0.02);
      if (near) continue;
      int rising = 0; // |kappa| rises on (a,b) iff the next extremum to the right is a maximum
      for (const fair::Curvature_extremum& x : e) {
        if (x.t > b) { rising = x.kind == fair::Curvature_extremum_kind::MAXIMUM ? 1 : -1; break; }
      }
      if (rising == 0 && !e.empty()) rising = e.back().kind == fair::Curvature_extremum_kind::MAXIMUM ? -1 : 1;
      const double ka = std::fabs(c.curvature(a)), kb = std::fabs(c.curvature(b));
      if (rising == 0 || std::fabs(kb - ka) < 1e-9 * ka) continue;
      EXPECT_EQ(kb > ka ? 1 : -1, rising) << c << " on [" << a << ", " << b << "]";
    }
  }
  EXPECT_GT(classified, tested / 3);
  EXPECT_GT(two, 0);
}

// ------------------------------------------------------------------ implicit equation, eq. 14
TYPED_TEST(Rational_quadratic_test, ImplicitEquationAndDiscriminant) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::mt19937_64 rng(20260514);
  std::uniform_int_distribution<int> coord(-40, 40), wnum(1, 30);
  int tested = 0;
  while (tested < 40) {
    const typename K::Point_2 p0 = pt<K>(coord(rng), 7, coord(rng), 3), p1 = pt<K>(coord(rng), 5, coord(rng), 9),
                              p2 = pt<K>(coord(rng), 11, coord(rng), 2);
    if (CGAL::orientation(p0, p1, p2) == CGAL::COLLINEAR || p0 == p2) continue;
    const FT w = q<K>(wnum(rng), 10);
    const fair::Rational_quadratic_bezier_2<K> c(p0, p1, p2, w);
    ++tested;
    const FT D = c.twice_signed_area();
    const std::array<FT, 6> e = c.implicit_coefficients();
    double scale = 0;
    for (const FT& x : e) scale = std::max(scale, std::fabs(CGAL::to_double(x)));
    for (int i = 0; i <= 6; ++i) {
      const typename K::Point_2 p = c.point(q<K>(i, 6));
      const double norm = scale * (1 + CGAL::to_double(p.x() * p.x() + p.y() * p.y()));
      EXPECT_TRUE(same<K>(c.implicit_value(p) / FT(norm), FT(0), 1e-14));
    }
    // b^2 - 4ac = 16 w^2 (w^2 - 1) D^2 (the conic type, exactly).
    if (is_exact<K>()) {
      EXPECT_TRUE(c.conic_discriminant() == FT(16) * w * w * (w * w - FT(1)) * D * D);
    } else { // b^2 - 4ac cancels: compare relative to b^2 + 4|ac|
      const double a = CGAL::to_double(e[0]), b = CGAL::to_double(e[1]), cc = CGAL::to_double(e[2]);
      EXPECT_NEAR(CGAL::to_double(c.conic_discriminant()), CGAL::to_double(FT(16) * w * w * (w * w - FT(1)) * D * D),
                  1e-14 * (b * b + 4 * std::fabs(a * cc)));
    }
    const int sign_disc = CGAL::sign(c.conic_discriminant());
    if (is_exact<K>()) {
      EXPECT_EQ(sign_disc, c.conic_type() == fair::Conic_type::ELLIPSE ? -1
                           : c.conic_type() == fair::Conic_type::PARABOLA ? 0 : 1);
      EXPECT_TRUE(c.implicit_value(p1) == D * D); // normalisation F(P1) = D^2
    }
    EXPECT_EQ(c.orientation(), CGAL::orientation(p0, p1, p2));
    EXPECT_EQ(c.curvature(0.5) > 0, c.orientation() == CGAL::LEFT_TURN);
    // Eccentricity: 1 for w = 1, in (0,1) for w < 1, > 1 for w > 1.
    const double ecc = c.eccentricity();
    if (c.conic_type() == fair::Conic_type::ELLIPSE) { EXPECT_LT(ecc, 1.0); EXPECT_GE(ecc, 0.0); }
    else if (c.conic_type() == fair::Conic_type::PARABOLA) EXPECT_EQ(ecc, 1.0);
    else EXPECT_GT(ecc, 1.0);
    // Squared curvature exactly vs signed double curvature; eq. 5 vs kappa(0), kappa(1).
    EXPECT_TRUE(same<K>(c.squared_curvature(FT(0)), c.squared_curvature_at_source(), 1e-13));
    EXPECT_TRUE(same<K>(c.squared_curvature(FT(1)), c.squared_curvature_at_target(), 1e-13));
    EXPECT_NEAR(c.curvature_at_source() / c.curvature(0.0), 1.0, 1e-13);
    EXPECT_NEAR(c.curvature_at_target() / c.curvature(1.0), 1.0, 1e-13);
    const double k3 = c.curvature(0.3);
    EXPECT_NEAR(k3 * k3 / CGAL::to_double(c.squared_curvature(q<K>(3, 10))), 1.0, 1e-13);
  }
}

// ------------------------------------------------------------------ min-eccentricity weight, eq. 15
TYPED_TEST(Rational_quadratic_test, MinimumEccentricityWeight) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::mt19937_64 rng(77);
  std::uniform_int_distribution<int> coord(-50, 50);
  for (int n = 0; n < 25; ++n) {
    const typename K::Point_2 p0 = pt<K>(coord(rng), 10, coord(rng), 10), p1 = pt<K>(coord(rng), 10, coord(rng), 10),
                              p2 = pt<K>(coord(rng), 10, coord(rng), 10);
    if (CGAL::orientation(p0, p1, p2) == CGAL::COLLINEAR || p0 == p2) continue;
    const FT w2 = fair::Rational_quadratic_bezier_2<K>::minimum_eccentricity_weight_squared(p0, p1, p2);
    const FT expected = ((p2 - p0) * (p2 - p0)) / (FT(2) * ((p0 - p1) * (p0 - p1) + (p2 - p1) * (p2 - p1)));
    EXPECT_TRUE(same<K>(w2, expected, 1e-13));
    EXPECT_LT(CGAL::to_double(w2), 1.0); // < 1 in general position (the paper, after eq. 15)
    if constexpr (is_exact<K>()) { // exact clamp decision of eq. 16: w_hat > 1/2 iff w_hat^2 > 1/4
      typedef typename fair::Rational_quadratic_bezier_2<K>::Sqrt_extension_FT S;
      const fair::Rational_quadratic_bezier_2<K> piece(p0, p1, p2, FT(1));
      EXPECT_EQ(CGAL::compare(piece.minimum_eccentricity_weight_sqrt_extension(), S(q<K>(1, 2))),
                CGAL::compare(w2, q<K>(1, 4)));
      EXPECT_NEAR(CGAL::to_double(piece.minimum_eccentricity_weight_sqrt_extension()), piece.minimum_eccentricity_weight(), 1e-15);
    }
    const double w = std::sqrt(CGAL::to_double(w2));
    const double e0 = fair::Rational_quadratic_bezier_2<K>(p0, p1, p2, FT(w)).eccentricity();
    for (double f : {0.9, 0.99, 1.01, 1.1})
      EXPECT_LE(e0, fair::Rational_quadratic_bezier_2<K>(p0, p1, p2, FT(w * f)).eccentricity() + 1e-12);
  }
  // Isosceles control triangles carry a tangent circle: eq. 15 finds it (eccentricity ~ 0).
  const fair::Rational_quadratic_bezier_2<K> iso(pt<K>(0, 1, 0, 1), pt<K>(1, 1, 3, 1), pt<K>(2, 1, 0, 1), FT(0.5));
  const fair::Rational_quadratic_bezier_2<K> circ(iso.source(), iso.control_point(1), iso.target(),
                                                  FT(iso.minimum_eccentricity_weight()));
  EXPECT_LT(circ.eccentricity(), 1e-6);
  for (int i = 0; i <= 4; ++i) EXPECT_NEAR(circ.curvature(i / 4.0) / circ.curvature(0.0), 1.0, 1e-12);
}

// ------------------------------------------------------------------ split and reversal
TYPED_TEST(Rational_quadratic_test, SplitAndReverse) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  // s with W(s) = 1 + 2(w-1)s(1-s) a rational square: on the line r = 1 + m s through (0,1) of
  // r^2 = W(s), s = 2(w-1-m) / (m^2 + 2(w-1)).
  auto square_parameter = [](const FT& w, const FT& m) { return FT(2) * (w - FT(1) - m) / (m * m + FT(2) * (w - FT(1))); };
  std::vector<std::pair<fair::Rational_quadratic_bezier_2<K>, FT>> cases;
  cases.push_back({parabola_arc<K>(-1, 2), q<K>(1, 3)});
  cases.push_back({parabola_arc<K>(-1, 2), q<K>(5, 7)});
  const fair::Rational_quadratic_bezier_2<K> circle = circle_arc<K>(H0, H4); // w = 3/5
  cases.push_back({circle, square_parameter(circle.weight(), q<K>(-1, 5))}); // s = 10/19
  const fair::Rational_quadratic_bezier_2<K> hyp = hyperbola_arc<K>(1, 2, 2, 1, 1, 1); // w = 5/4
  cases.push_back({hyp, square_parameter(hyp.weight(), q<K>(1, 8))}); // s = 16/33
  for (const auto& cs : cases) {
    const fair::Rational_quadratic_bezier_2<K>& c = cs.first;
    const FT s = cs.second;
    ASSERT_TRUE(s > FT(0) && s < FT(1)) << CGAL::to_double(s);
    const auto parts = c.split(s);
    const fair::Rational_quadratic_bezier_2<K>& l = parts.first;
    const fair::Rational_quadratic_bezier_2<K>& r = parts.second;
    EXPECT_TRUE(l.source() == c.source());
    EXPECT_TRUE(r.target() == c.target());
    EXPECT_TRUE(l.target() == r.source());
    EXPECT_TRUE(same<K>(l.target().x(), c.point(s).x(), 1e-13) && same<K>(l.target().y(), c.point(s).y(), 1e-13));
    // Same conic: every point of both pieces satisfies the original implicit equation.
    for (int i = 0; i <= 5; ++i) {
      EXPECT_TRUE(same<K>(c.implicit_value(l.point(q<K>(i, 5))), FT(0), 1e-13));
      EXPECT_TRUE(same<K>(c.implicit_value(r.point(q<K>(i, 5))), FT(0), 1e-13));
    }
    // G1 and curvature continuity at the joint (exact in exact kernels).
    if (is_exact<K>()) {
      EXPECT_EQ(CGAL::orientation(l.control_point(1), l.target(), r.control_point(1)), CGAL::COLLINEAR);
    }
    EXPECT_TRUE(same<K>(l.squared_curvature_at_target(), r.squared_curvature_at_source(), 1e-12));
    EXPECT_TRUE(same<K>(l.squared_curvature_at_target(), c.squared_curvature(s), 1e-12));
    EXPECT_EQ(l.conic_type(), c.conic_type());
    EXPECT_EQ(r.conic_type(), c.conic_type());
    EXPECT_EQ(l.orientation(), c.orientation());
    // Homogeneous split: exact, and with the affine parametrisation t = s u.
    const auto hp = c.split_homogeneous(s);
    for (int i = 0; i <= 4; ++i) {
      const FT u = q<K>(i, 4);
      EXPECT_TRUE(same<K>(hp.first.point(u).x(), c.point(s * u).x(), 1e-13));
      EXPECT_TRUE(same<K>(hp.second.point(u).y(), c.point(s + (FT(1) - s) * u).y(), 1e-13));
    }
  }
  // Circle pieces stay circles: constant curvature, exact eq.-4 zero in exact kernels.
  const auto cp = circle.split(square_parameter(circle.weight(), q<K>(-1, 5)));
  EXPECT_TRUE(same<K>(cp.first.squared_curvature(q<K>(1, 3)), FT(1), 1e-13));
  EXPECT_TRUE(same<K>(cp.second.squared_curvature(q<K>(2, 3)), FT(1), 1e-13));
  if (is_exact<K>()) {
    EXPECT_TRUE(cp.first.has_constant_curvature());
    EXPECT_TRUE(cp.second.has_constant_curvature());
    // W(1/2) = 4/5 is not a rational square: the standard form would need an irrational weight.
    EXPECT_THROW(circle.split(q<K>(1, 2)), fair::Precondition_error);
  } else {
    const auto half = circle.split(q<K>(1, 2)); // cos(quarter of the 106.26-degree arc)
    EXPECT_NEAR(CGAL::to_double(half.first.weight()), std::cos(std::atan2(4.0, 3.0) / 2), 1e-15);
    EXPECT_NEAR(CGAL::to_double(half.second.weight()), std::cos(std::atan2(4.0, 3.0) / 2), 1e-15);
  }
  EXPECT_THROW(circle.split(FT(0)), fair::Precondition_error);
  EXPECT_THROW(circle.split(FT(1)), fair::Precondition_error);
  // Reversal: c_rev(t) = c(1 - t), curvature changes sign, orientation flips.
  const fair::Rational_quadratic_bezier_2<K> e = circle_arc<K>(Hm7, H4, 2), er = e.reversed();
  for (int i = 0; i <= 6; ++i) {
    const FT t = q<K>(i, 6);
    EXPECT_TRUE(same<K>(er.point(t).x(), e.point(FT(1) - t).x(), 1e-13));
    EXPECT_TRUE(same<K>(er.point(t).y(), e.point(FT(1) - t).y(), 1e-13));
    EXPECT_NEAR(er.curvature(i / 6.0), -e.curvature(1 - i / 6.0), 1e-13);
  }
  EXPECT_EQ(er.orientation(), CGAL::RIGHT_TURN);
  EXPECT_EQ(kinds_of(er.curvature_extrema()), (std::vector<int>{MIN, MAX}));
}

// ------------------------------------------------------------------ eq. 6 and eq. 7
TYPED_TEST(Rational_quadratic_test, Eq7KnownRoots) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  // Parabola y = x^2 with its vertex Q = (0,0) between P0 = (-1,1) and P2 = (2,4): t = 1/3 and
  // P1 = (1/2, -2) (eq. 6).
  {
    const typename K::Point_2 p0 = pt<K>(-1, 1, 1, 1), qq = pt<K>(0, 1, 0, 1), p2 = pt<K>(2, 1, 4, 1);
    const fair::Curvature_extremum_parameter<K> r = fair::curvature_extremum_parameter<K>(p0, qq, p2, FT(1));
    EXPECT_EQ(r.sign_variations, 1);
    EXPECT_TRUE(r.t_lower <= CGAL::Gmpq(1, 3) && CGAL::Gmpq(1, 3) <= r.t_upper);
    EXPECT_LT(dbl(r.t_upper - r.t_lower), 1e-14);
    EXPECT_NEAR(r.t, 1.0 / 3, 1e-15);
    EXPECT_TRUE(eq7_value(to_q<K>(p0), to_q<K>(qq), to_q<K>(p2), CGAL::Gmpq(1), CGAL::Gmpq(1, 3)) == 0);
    const fair::Rational_quadratic_bezier_2<K> c = fair::rational_quadratic_through<K>(p0, qq, p2, FT(1), q<K>(1, 3));
    EXPECT_TRUE(same<K>(c.control_point(1).x(), q<K>(1, 2), 1e-13));
    EXPECT_TRUE(same<K>(c.control_point(1).y(), q<K>(-2), 1e-13));
    EXPECT_TRUE(c.point(q<K>(1, 3)) == qq || !is_exact<K>());
  }
  // xy = 1, Q = (1,1) at the vertex, w = 5/4: t = 1/2 exactly, P1 = (4/5, 4/5).
  {
    const typename K::Point_2 p0 = pt<K>(1, 2, 2, 1), qq = pt<K>(1, 1, 1, 1), p2 = pt<K>(2, 1, 1, 2);
    const fair::Curvature_extremum_parameter<K> r = fair::curvature_extremum_parameter<K>(p0, qq, p2, q<K>(5, 4));
    EXPECT_TRUE(r.t_lower <= CGAL::Gmpq(1, 2) && CGAL::Gmpq(1, 2) <= r.t_upper);
    EXPECT_NEAR(r.t, 0.5, 1e-15);
    const fair::Rational_quadratic_bezier_2<K> c = fair::rational_quadratic_through<K>(p0, qq, p2, q<K>(5, 4), q<K>(1, 2));
    EXPECT_TRUE(same<K>(c.control_point(1).x(), q<K>(4, 5), 1e-13));
    EXPECT_TRUE(same<K>(c.control_point(1).y(), q<K>(4, 5), 1e-13));
    const std::vector<fair::Curvature_extremum> e = c.curvature_extrema();
    ASSERT_EQ(e.size(), 1u);
    EXPECT_NEAR(e[0].t, 0.5, 1e-15);
    EXPECT_EQ(e[0].kind, fair::Curvature_extremum_kind::MAXIMUM);
  }
  // The ellipse x^2/4 + y^2 = 1 through its vertex Q = (2,0) from circle angles -32.5..32.5 deg.
  {
    const fair::Rational_quadratic_bezier_2<K> arc = circle_arc<K>(Hm7, H7, 2);
    const typename K::Point_2 qq = pt<K>(2, 1, 0, 1);
    const fair::Curvature_extremum_parameter<K> r =
      fair::curvature_extremum_parameter<K>(arc.source(), qq, arc.target(), arc.weight());
    EXPECT_TRUE(r.t_lower <= CGAL::Gmpq(1, 2) && CGAL::Gmpq(1, 2) <= r.t_upper); // symmetric
    const fair::Rational_quadratic_bezier_2<K> c =
      fair::rational_quadratic_through<K>(arc.source(), qq, arc.target(), arc.weight(), q<K>(1, 2));
    EXPECT_TRUE(same<K>(c.control_point(1).x(), arc.control_point(1).x(), 1e-13));
    EXPECT_TRUE(same<K>(c.control_point(1).y(), arc.control_point(1).y(), 1e-13));
  }
}

// The unique-sign-change certificate and the certified bracket on seeded random inputs; the
// bracket is checked against an independent exact evaluation of eq. 7, and against eq. 4 of the
// piece rebuilt by eq. 6 at the bracket ends (E(P1(t))(t) = f(t) W(t)^2 / (2 t^2 (1-t)^2), so
// the signs must be -, + exactly).
TYPED_TEST(Rational_quadratic_test, Eq7CertificateOnRandomInputs) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::mt19937_64 rng(1234567);
  std::uniform_real_distribution<double> u(-1.0, 1.0), lw(-3.0, 3.0);
  const int n = is_exact<K>() ? 150 : 3000;
  int exact_checks = 0;
  for (int i = 0; i < n; ++i) {
    const double scale = (i % 10 == 0) ? std::pow(10.0, 200 * u(rng)) : 1.0; // huge / tiny coordinates
    typename K::Point_2 p0(scale * u(rng), scale * u(rng)), qq(scale * u(rng), scale * u(rng)),
      p2(scale * u(rng), scale * u(rng));
    if (i % 17 == 0) p2 = typename K::Point_2(CGAL::to_double(qq.x()) * 2 - CGAL::to_double(p0.x()),
                                              CGAL::to_double(qq.y()) * 2 - CGAL::to_double(p0.y())); // A+B+B+C ~ 0
    if (i % 23 == 0) p2 = p0;                                                   // P0 == P2: t = 1/2
    const FT w(std::pow(2.0, lw(rng)));
    const fair::Curvature_extremum_parameter<K> r = fair::curvature_extremum_parameter<K>(p0, qq, p2, w);
    ASSERT_EQ(r.sign_variations, 1);
    ASSERT_EQ(fair::sign_variations(fair::Bernstein_polynomial<CGAL::Gmpq>(std::vector<CGAL::Gmpq>{
                [&] { return -fair::internal::common::to_gmpq(w) * (to_q<K>(p0) - to_q<K>(qq)).squared_length(); }(),
                -((to_q<K>(p0) - to_q<K>(qq)) * ((to_q<K>(p0) - to_q<K>(qq)) + (to_q<K>(p2) - to_q<K>(qq)))),
                CGAL::Gmpq(0),
                (to_q<K>(p2) - to_q<K>(qq)) * ((to_q<K>(p0) - to_q<K>(qq)) + (to_q<K>(p2) - to_q<K>(qq))),
                fair::internal::common::to_gmpq(w) * (to_q<K>(p2) - to_q<K>(qq)).squared_length()})),
              1);
    ASSERT_TRUE(r.t_lower <= r.t_upper);
    ASSERT_TRUE(CGAL::Gmpq(r.t) >= r.t_lower && CGAL::Gmpq(r.t) <= r.t_upper);
    EXPECT_LT(dbl(r.t_upper - r.t_lower), 1e-13 * (1 + r.t));
    const CGAL::Gmpq wq = fair::internal::common::to_gmpq(w);
    const Kq::Point_2 a = to_q<K>(p0), b = to_q<K>(qq), c = to_q<K>(p2);
    if (r.t_lower == r.t_upper) {
      EXPECT_EQ(CGAL::sign(eq7_value(a, b, c, wq, r.t_lower)), CGAL::ZERO);
    } else {
      EXPECT_EQ(CGAL::sign(eq7_value(a, b, c, wq, r.t_lower)), CGAL::NEGATIVE);
      EXPECT_EQ(CGAL::sign(eq7_value(a, b, c, wq, r.t_upper)), CGAL::POSITIVE);
    }
    if (i % 23 == 0) {
      EXPECT_TRUE(r.t_lower <= CGAL::Gmpq(1, 2) && CGAL::Gmpq(1, 2) <= r.t_upper);
    }
    // eq. 4 of the piece rebuilt by eq. 6 at both bracket ends (exact, in Simple_cartesian<Gmpq>).
    if (i % 5 == 0 && r.t_lower != r.t_upper && CGAL::orientation(a, b, c) != CGAL::COLLINEAR && a != c) {
      const fair::Rational_quadratic_bezier_2<Kq> lo = fair::rational_quadratic_through<Kq>(a, b, c, wq, r.t_lower);
      const fair::Rational_quadratic_bezier_2<Kq> hi = fair::rational_quadratic_through<Kq>(a, b, c, wq, r.t_upper);
      EXPECT_TRUE(lo.point(r.t_lower) == b);
      EXPECT_EQ(CGAL::sign(lo.curvature_derivative_numerator().evaluate(r.t_lower)), CGAL::NEGATIVE);
      EXPECT_EQ(CGAL::sign(hi.curvature_derivative_numerator().evaluate(r.t_upper)), CGAL::POSITIVE);
      ++exact_checks;
    }
    // The rebuilt piece has a critical point of curvature at Q; a maximum when w >= 1.
    if (i % 10 != 0 && i % 23 != 0 && i % 17 != 0 && CGAL::orientation(p0, qq, p2) != CGAL::COLLINEAR && i % 3 == 0) {
      const fair::Rational_quadratic_bezier_2<K> piece = fair::rational_quadratic_through<K>(p0, qq, p2, w, FT(r.t));
      const std::vector<fair::Curvature_extremum> e = piece.curvature_extrema();
      bool found = false;
      for (const fair::Curvature_extremum& x : e) {
        if (std::fabs(x.t - r.t) < 1e-9) {
          found = true;
          if (CGAL::to_double(w) >= 1) {
            EXPECT_EQ(x.kind, fair::Curvature_extremum_kind::MAXIMUM);
          }
        }
      }
      EXPECT_TRUE(found) << piece << " t = " << r.t;
      EXPECT_LE(e.size(), CGAL::to_double(w) < 1 ? 2u : 1u); // Sec. 3.1 bound
    }
  }
  EXPECT_GT(exact_checks, 10);
}

TYPED_TEST(Rational_quadratic_test, Eq7DegenerateInputsThrow) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const typename K::Point_2 a = pt<K>(0, 1, 0, 1), b = pt<K>(1, 1, 1, 1), c = pt<K>(2, 1, 0, 1);
  EXPECT_THROW(fair::curvature_extremum_parameter<K>(a, a, c, FT(1)), fair::Precondition_error);
  EXPECT_THROW(fair::curvature_extremum_parameter<K>(a, c, c, FT(1)), fair::Precondition_error);
  EXPECT_THROW(fair::curvature_extremum_parameter<K>(a, b, c, FT(0)), fair::Precondition_error);
  EXPECT_THROW(fair::curvature_extremum_parameter<K>(a, b, c, FT(-1)), fair::Precondition_error);
  EXPECT_THROW(fair::rational_quadratic_through<K>(a, b, c, FT(1), FT(0)), fair::Precondition_error);
  EXPECT_THROW(fair::rational_quadratic_through<K>(a, b, c, FT(1), FT(1)), fair::Precondition_error);
  // Q on the chord: eq. 7 is fine (t = 1/2) but the rebuilt piece is degenerate (collinear).
  const typename K::Point_2 mid = pt<K>(1, 1, 0, 1);
  const fair::Curvature_extremum_parameter<K> r = fair::curvature_extremum_parameter<K>(a, mid, c, FT(1));
  EXPECT_TRUE(r.t_lower <= CGAL::Gmpq(1, 2) && CGAL::Gmpq(1, 2) <= r.t_upper);
  EXPECT_THROW(fair::rational_quadratic_through<K>(a, mid, c, FT(1), q<K>(1, 2)), fair::Precondition_error);
  if (!is_exact<K>()) {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(fair::curvature_extremum_parameter<K>(a, b, c, FT(nan)), fair::Precondition_error);
    EXPECT_THROW(fair::curvature_extremum_parameter<K>(a, b, c, FT(inf)), fair::Precondition_error);
    EXPECT_THROW(fair::curvature_extremum_parameter<K>(typename K::Point_2(nan, 0), b, c, FT(1)), fair::Precondition_error);
    EXPECT_THROW(fair::curvature_extremum_parameter<K>(a, typename K::Point_2(0, inf), c, FT(1)), fair::Precondition_error);
  }
  try {
    fair::curvature_extremum_parameter<K>(a, b, c, FT(-2));
    ADD_FAILURE() << "no exception";
  } catch (const fair::Precondition_error& e) {
    EXPECT_NE(std::string(e.what()).find("-2"), std::string::npos) << e.what();
  }
}

// ------------------------------------------------------------------ degenerate pieces
// Orientation beyond the interval filter: in exact kernels thirds are not dyadic, so the filter
// on their enclosures cannot decide a determinant of 1e-40 / 3 and the exact fallback must (a
// correct turn, and an exactly collinear triple rejected). In double kernels the 1e-40 is
// rounded away and 2 * fl(1/3) == fl(2/3): all three triples are collinear, decided exactly.
TYPED_TEST(Rational_quadratic_test, OrientationBeyondTheIntervalFilter) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  typedef fair::Rational_quadratic_bezier_2<K> Rq;
  const FT third = q<K>(1, 3), tiny = FT(1e-40);
  const P a(FT(0), FT(0)), b(third, third), c(FT(2) * third, FT(2) * third + tiny), d(FT(2) * third, FT(2) * third - tiny);
  if (is_exact<K>()) {
    EXPECT_EQ(Rq(a, b, c, FT(1)).orientation(), CGAL::LEFT_TURN);
    EXPECT_EQ(Rq(a, b, d, FT(1)).orientation(), CGAL::RIGHT_TURN);
  } else {
    EXPECT_THROW(Rq(a, b, c, FT(1)), fair::Precondition_error);
    EXPECT_THROW(Rq(a, b, d, FT(1)), fair::Precondition_error);
  }
  EXPECT_THROW(Rq(a, b, P(FT(2) * third, FT(2) * third), FT(1)), fair::Precondition_error);
}

TYPED_TEST(Rational_quadratic_test, DegeneratePiecesThrow) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef fair::Rational_quadratic_bezier_2<K> Rq;
  const typename K::Point_2 a = pt<K>(0, 1, 0, 1), b = pt<K>(1, 1, 1, 1), c = pt<K>(2, 1, 0, 1);
  EXPECT_NO_THROW(Rq(a, b, c, FT(1)));
  EXPECT_THROW(Rq(a, b, a, FT(1)), fair::Precondition_error);                 // P0 == P2
  EXPECT_THROW(Rq(a, a, c, FT(1)), fair::Precondition_error);                 // P0 == P1
  EXPECT_THROW(Rq(a, c, c, FT(1)), fair::Precondition_error);                 // P1 == P2
  EXPECT_THROW(Rq(a, pt<K>(1, 1, 0, 1), c, FT(1)), fair::Precondition_error); // collinear
  EXPECT_THROW(Rq(a, pt<K>(3, 1, 0, 1), c, FT(1)), fair::Precondition_error); // collinear, P1 outside
  EXPECT_THROW(Rq(a, b, c, FT(0)), fair::Precondition_error);
  EXPECT_THROW(Rq(a, b, c, FT(-1)), fair::Precondition_error);
  try {
    Rq(a, pt<K>(1, 1, 0, 1), c, FT(1));
  } catch (const fair::Precondition_error& e) {
    EXPECT_NE(std::string(e.what()).find("collinear"), std::string::npos) << e.what();
  }
  try {
    Rq(a, b, c, FT(-3));
  } catch (const fair::Precondition_error& e) {
    EXPECT_NE(std::string(e.what()).find("w = -3"), std::string::npos) << e.what();
  }
  if (!is_exact<K>()) {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(Rq(a, b, c, FT(nan)), fair::Precondition_error);
    EXPECT_THROW(Rq(a, b, c, FT(inf)), fair::Precondition_error);
    EXPECT_THROW(Rq(typename K::Point_2(nan, 0), b, c, FT(1)), fair::Precondition_error);
    EXPECT_THROW(Rq(a, typename K::Point_2(0, inf), c, FT(1)), fair::Precondition_error);
    // Nearly collinear but not exactly: accepted (exact orientation), curvature finite.
    const Rq thin(a, typename K::Point_2(1, 1e-300), c, FT(1));
    EXPECT_TRUE(std::isfinite(thin.curvature(0.5)));
  }
  const Rq ok(a, b, c, FT(1));
  EXPECT_THROW(ok.point(FT(-1)), fair::Precondition_error);
  EXPECT_THROW(ok.derivative(FT(2)), fair::Precondition_error);
  EXPECT_THROW(ok.curvature(1.5), fair::Precondition_error);
  EXPECT_THROW(ok.control_point(3), fair::Precondition_error);
  EXPECT_THROW(Rq::minimum_eccentricity_weight_squared(a, a, a), fair::Precondition_error);
}

// ------------------------------------------------------------------ 256-bit reference
// Independent evaluation with CGAL::Gmpfr at 256 bits from the quotient rule on
// X(t) = sum b_i w_i P_i, W(t) = sum b_i w_i (not the closed forms the class uses).
TYPED_TEST(Rational_quadratic_test, AgreesWithGmpfrReference) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef CGAL::Gmpfr R;
  const auto old = R::set_default_precision(256);
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-10.0, 10.0), lw(-2.0, 2.0);
  int tested = 0;
  double worst = 0;
  while (tested < 300) {
    const double x[3] = {u(rng), u(rng), u(rng)}, y[3] = {u(rng), u(rng), u(rng)}, wd = std::pow(2.0, lw(rng));
    const double area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    if (std::fabs(area) < 1.0) continue; // keep the conditioning moderate
    ++tested;
    const fair::Rational_quadratic_bezier_2<K> c(typename K::Point_2(x[0], y[0]), typename K::Point_2(x[1], y[1]),
                                                 typename K::Point_2(x[2], y[2]), FT(wd));
    for (double td : {0.0, 0.125, 0.3, 0.5, 0.77, 1.0}) {
      const R t(td), s = R(1) - t, w(wd);
      const R b0 = s * s, b1 = R(2) * s * t * w, b2 = t * t;
      const R db0 = R(-2) * s, db1 = R(2) * w * (s - t), db2 = R(2) * t;
      const R d2b0(2), d2b1 = R(-4) * w, d2b2(2);
      const R W = b0 + b1 + b2, W1 = db0 + db1 + db2, W2 = d2b0 + d2b1 + d2b2;
      R cx[3], cy[3];
      for (int k = 0; k < 3; ++k) {
        const R bb[3] = {k == 0 ? b0 : (k == 1 ? db0 : d2b0), k == 0 ? b1 : (k == 1 ? db1 : d2b1),
                         k == 0 ? b2 : (k == 1 ? db2 : d2b2)};
        cx[k] = bb[0] * R(x[0]) + bb[1] * R(x[1]) + bb[2] * R(x[2]);
        cy[k] = bb[0] * R(y[0]) + bb[1] * R(y[1]) + bb[2] * R(y[2]);
      }
      const R px = cx[0] / W, py = cy[0] / W;
      const R dx = (cx[1] - W1 * px) / W, dy = (cy[1] - W1 * py) / W;
      const R ex = (cx[2] - R(2) * W1 * dx - W2 * px) / W, ey = (cy[2] - R(2) * W1 * dy - W2 * py) / W;
      const R n2 = dx * dx + dy * dy;
      const double kappa = CGAL::to_double((dx * ey - dy * ex) / (n2 * CGAL::sqrt(n2)));
      const typename K::Point_2 p = c.point(FT(td));
      const typename K::Vector_2 d = c.derivative(FT(td)), e = c.second_derivative(FT(td));
      const double dn = std::sqrt(CGAL::to_double(n2)), en = std::hypot(CGAL::to_double(ex), CGAL::to_double(ey));
      const double errs[] = {std::hypot(CGAL::to_double(p.x()) - CGAL::to_double(px), CGAL::to_double(p.y()) - CGAL::to_double(py)) / 10.0,
                             std::hypot(CGAL::to_double(d.x()) - CGAL::to_double(dx), CGAL::to_double(d.y()) - CGAL::to_double(dy)) / dn,
                             std::hypot(CGAL::to_double(e.x()) - CGAL::to_double(ex), CGAL::to_double(e.y()) - CGAL::to_double(ey)) / en,
                             std::fabs(c.curvature(td) - kappa) / std::fabs(kappa),
                             std::fabs(CGAL::to_double(c.squared_curvature(FT(td))) / (kappa * kappa) - 1)};
      for (double err : errs) {
        worst = std::max(worst, err);
        EXPECT_LT(err, 1e-13) << c << " t = " << td;
      }
    }
  }
  R::set_default_precision(old);
  ::testing::Test::RecordProperty("worst_relative_error", std::to_string(worst));
}

// ---------------------------------------------------------------- scale robustness (double kernels)
// The geometry is scale-covariant: scaling the control points by lambda leaves the weight,
// eccentricity, eq.-15 weight and extremum parameters unchanged and divides the curvature by
// lambda. In a double kernel this must hold at every scale where the true values are
// representable, including 2^+-1000 and 1e+-300 where the naive formulas overflow/underflow.
template <class K>
class Rational_quadratic_scale_test : public ::testing::Test {};
TYPED_TEST_SUITE(Rational_quadratic_scale_test, fair_test::Floating_kernels);

TYPED_TEST(Rational_quadratic_scale_test, ScaleCovariance) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef fair::Rational_quadratic_bezier_2<K> C;
  std::mt19937 rng(20261126);
  std::uniform_real_distribution<double> U(-1.0, 1.0), Wd(0.2, 3.0);
  // (at 2^+-1000 the scaled coordinates are exact; 1e+-300 rounds each coordinate once)
  const double scales[] = {0x1p1000, 0x1p-1000, 1e300, 1e-300};
  auto rel = [](double a, double b) { return std::fabs(a - b) / std::fabs(b); };
  int checked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const double x[3] = {U(rng), U(rng), U(rng)}, y[3] = {U(rng), U(rng), U(rng)};
    const double w = trial == 0 ? 1.0 : Wd(rng);
    if (std::fabs((x[1] - x[0]) * (y[2] - y[1]) - (y[1] - y[0]) * (x[2] - x[1])) < 1e-3) continue;
    const C base(P(x[0], y[0]), P(x[1], y[1]), P(x[2], y[2]), w);
    const std::vector<fair::Curvature_extremum> be = base.curvature_extrema();
    for (double lambda : scales) {
      const C c(P(lambda * x[0], lambda * y[0]), P(lambda * x[1], lambda * y[1]), P(lambda * x[2], lambda * y[2]), w);
      SCOPED_TRACE(::testing::Message() << base << " scaled by " << lambda);
      const bool pow2 = lambda == 0x1p1000 || lambda == 0x1p-1000;
      const double tol = pow2 ? 4e-15 : 1e-12; // rounding of the scaled inputs, det >= 1e-3
      ASSERT_EQ(c.orientation(), base.orientation());
      for (double t : {0.0, 0.125, 0.5, 0.875, 1.0}) {
        const double k = c.curvature(t) * lambda, kb = base.curvature(t);
        if (pow2) {
          EXPECT_EQ(k, kb) << "t = " << t; // exact power-of-two rescaling
        }
        EXPECT_LT(rel(k, kb), tol) << "t = " << t;
      }
      EXPECT_LT(rel(c.curvature_at_source() * lambda, base.curvature_at_source()), tol);
      EXPECT_LT(rel(c.curvature_at_target() * lambda, base.curvature_at_target()), tol);
      EXPECT_NEAR(c.eccentricity(), base.eccentricity(), 1e-10 * (1 + base.eccentricity()));
      EXPECT_LT(rel(c.minimum_eccentricity_weight(), base.minimum_eccentricity_weight()), tol);
      EXPECT_LT(rel(CGAL::to_double(C::minimum_eccentricity_weight_squared(c.source(), c.control_point(1), c.target())),
                    CGAL::to_double(base.minimum_eccentricity_weight_squared())),
                tol);
      {
        const std::vector<fair::Curvature_extremum> e = c.curvature_extrema();
        ASSERT_EQ(kinds_of(e), kinds_of(be));
        for (std::size_t i = 0; i < e.size(); ++i) EXPECT_NEAR(e[i].t, be[i].t, 1e-12);
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 200);
}

TYPED_TEST(Rational_quadratic_scale_test, TinyAndHugeTrianglesAreNotCollinear) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef fair::Rational_quadratic_bezier_2<K> C;
  // det = 1e-600 (underflows in double) and 1e600 (overflows): decided exactly.
  const C tiny(P(0, 0), P(1e-300, 1e-300), P(2e-300, 0), 0.5);
  EXPECT_EQ(tiny.orientation(), CGAL::RIGHT_TURN);
  const C huge(P(-1e300, 0), P(0, 1e300), P(1e300, 0), 2.0);
  EXPECT_EQ(huge.orientation(), CGAL::RIGHT_TURN);
  // kappa(0) = -Delta / (w^2 |P1-P0|^3) = -(1e600 / 2) ... computed without overflow.
  // Delta = -1e600, |P1-P0| = sqrt(2) 1e300, w = 2: kappa(0) = -1e-300 / (4 2^1.5).
  const double k0 = -1e-300 / (4.0 * std::pow(2.0, 1.5));
  EXPECT_LT(std::fabs(huge.curvature_at_source() - k0), 1e-14 * std::fabs(k0));
  EXPECT_LT(std::fabs(huge.curvature(0.0) - k0), 1e-14 * std::fabs(k0));
  // Nearly collinear at unit scale: det = 2^-1074 * 1, still a genuine piece.
  const C flat(P(0, 0), P(1, 0x1p-1074), P(2, 0), 1.0);
  EXPECT_EQ(flat.orientation(), CGAL::RIGHT_TURN);
  EXPECT_THROW(C(P(0, 0), P(1e-300, 1e-300), P(2e-300, 2e-300), 1.0), fair::Precondition_error);
  EXPECT_THROW(C(P(0, 0), P(1e300, 1e300), P(1.5e300, 1.5e300), 1.0), fair::Precondition_error);
}

// Huge weights: the conic tends to the pair of lines P0P1, P1P2, a hyperbola whose asymptotes
// enclose the control polygon's angle theta at P1, so eps -> 1 / cos(theta / 2); the implicit
// coefficients (u + 4 w^2 v, eq. 14) must neither overflow (w up to 1e300) nor lose u needlessly.
// Tiny weights: a flat ellipse, eps in [0, 1].
TYPED_TEST(Rational_quadratic_scale_test, EccentricityOfExtremeWeights) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef fair::Rational_quadratic_bezier_2<K> C;
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const P p0(U(rng), U(rng)), p1(U(rng), U(rng)), p2(U(rng), U(rng));
    const double ax = p0.x() - p1.x(), ay = p0.y() - p1.y(), bx = p2.x() - p1.x(), by = p2.y() - p1.y();
    const double la = std::hypot(ax, ay), lb = std::hypot(bx, by);
    if (std::fabs(ax * by - ay * bx) < 1e-2 * la * lb) continue;  // keep theta away from 0 and pi
    const double theta = std::acos((ax * bx + ay * by) / (la * lb));
    const double limit = 1.0 / std::cos(theta / 2);
    for (const double w : {1e8, 1e100, 1e200, 1e300}) {
      const double e = C(p0, p1, p2, w).eccentricity();
      EXPECT_NEAR(e, limit, 1e-10 * limit) << "w " << w << " theta " << theta;
    }
    for (const double w : {1e-8, 1e-150, 1e-300}) {
      const double e = C(p0, p1, p2, w).eccentricity();
      EXPECT_GE(e, 0.0);
      EXPECT_LE(e, 1.0);
    }
    ++checked;
  }
  EXPECT_GE(checked, 20);
}

TYPED_TEST(Rational_quadratic_scale_test, UnrepresentableCurvatureThrows) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef fair::Rational_quadratic_bezier_2<K> C;
  // |kappa(0)| = |D| / (2 w^2 |P1-P0|^3), D = det(P1-P0, P2-P1).
  // Tiny piece, D = -2^-1999, |P1-P0| = 2^-999.5: |kappa(0)| = 2^998.5 / w^2 ~ 2.3e320 for w = 1e-10.
  const C big(P(0, 0), P(0x1p-1000, 0x1p-1000), P(0x1p-999, 0), 1e-10);
  EXPECT_THROW(big.curvature_at_source(), fair::Precondition_error);
  EXPECT_THROW(big.curvature(0.0), fair::Precondition_error);
  // Huge piece, D = -2^2001, |P1-P0| = 2^1000.5: |kappa(0)| = 2^-1001.5 / w^2 ~ 2.6e-342 for w = 1e20.
  const C small(P(0, 0), P(0x1p1000, 0x1p1000), P(0x1p1001, 0), 1e20);
  EXPECT_THROW(small.curvature_at_target(), fair::Precondition_error);
  EXPECT_THROW(small.curvature(1.0), fair::Precondition_error);
  // The scale-independent eq.-15 weight still works.
  EXPECT_NEAR(small.minimum_eccentricity_weight(), std::sqrt(4.0 / (2.0 * 4.0)), 1e-15);
  // Mid-arc curvature of the big-weight piece is representable: kappa(1/2) = 4 w D W^3 / |V|^3
  // ~ -w 2^-1000 (W ~ w/2, |V| ~ w 2^1000).
  EXPECT_NEAR(small.curvature(0.5) / (-1e20 * 0x1p-1000), 1.0, 1e-12);
}

} // namespace
