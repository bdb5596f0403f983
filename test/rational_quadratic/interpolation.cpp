// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of fair::Rational_quadratic_bezier_2:
// eq. 6 and eq. 7 (the parameter of a curvature extremum, Appendix A certificate).

#include "support.h"

#include <fair/Rational_quadratic_interpolation.h>

namespace {

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

} // namespace
