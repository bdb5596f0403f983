// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of fair::Rational_quadratic_bezier_2:
// construction: exact orientation and degenerate pieces.

#include "support.h"

namespace {

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

} // namespace
