// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of fair::Rational_quadratic_bezier_2:
// scale robustness of the double-valued functions in floating kernels.

#include "support.h"

namespace {

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

// c'(t) = V(t) / W(t)^2 with V(0) = 2w (P1 - P0), V(1) = 2w (P2 - P1): a huge weight on huge
// differences has no derivative in double, and the piece says so instead of returning inf (fuzz
// finding conic/open-derivative-overflow, this piece); the same piece scaled down by 2^-600 has
// finite derivatives, c'(1) = 2w (P2 - P1) 2^-600 among them.
TYPED_TEST(Rational_quadratic_scale_test, UnrepresentableDerivativeThrows) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef fair::Rational_quadratic_bezier_2<K> C;
  const P p0(-0.0, 5.2584254243822787e+104), p1(1e16, -4.8369999999999991e+23), p2(-2.5891e-146, 2.3065373667657711e+267);
  const double w = 2.3124999999999999e+154;
  const C piece(p0, p1, p2, w);
  // c'(0) = 2w (P1 - P0), about 2.4e259: representable; c''(0) has w^2 (P1 - P0) ~ 1e414: not.
  const auto d0 = piece.derivative(0.0);
  EXPECT_NEAR(d0.y(), 2 * w * (p1.y() - p0.y()), 1e-14 * std::abs(d0.y()));
  EXPECT_THROW(piece.second_derivative(0.0), fair::Precondition_error);
  EXPECT_TRUE(std::isfinite(piece.point(0.5).x()) && std::isfinite(piece.point(0.5).y()));
  const double down = std::ldexp(1.0, -600);
  const C scaled(P(p0.x() * down, p0.y() * down), P(p1.x() * down, p1.y() * down), P(p2.x() * down, p2.y() * down), w);
  for (const double t : {0.0, 0.5, 1.0}) {
    const auto d = scaled.derivative(t);
    EXPECT_TRUE(std::isfinite(d.x()) && std::isfinite(d.y())) << t;
  }
  // At t = 1: c'(1) = 2w (P2 - P1), about 1.1e422 unscaled: beyond double; scaled, exactly 2^-600 of it.
  EXPECT_THROW(piece.derivative(1.0), fair::Precondition_error);
  const auto d1 = scaled.derivative(1.0);
  EXPECT_NEAR(d1.y(), 2 * w * ((p2.y() - p1.y()) * down), 1e-14 * std::abs(d1.y()));
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
