// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of fair::Rational_quadratic_bezier_2:
// circular, parabolic and hyperbolic arcs with exact rational data.

#include "support.h"

namespace {

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

} // namespace
