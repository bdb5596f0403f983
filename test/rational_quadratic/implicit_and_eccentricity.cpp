// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of fair::Rational_quadratic_bezier_2:
// the implicit equation (eq. 14) and the minimum-eccentricity weight (eq. 15).

#include "support.h"

namespace {

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

} // namespace
