// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of fair::Rational_quadratic_bezier_2: split and reversal.

#include "support.h"

namespace {

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

} // namespace
