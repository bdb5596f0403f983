// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Nurbs_curve_2 against independent constructions: the Cox-de Boor recursion for the
// basis functions (the NURBS definition, evaluated literally), exactly at rational parameters in
// the exact kernels, for random degrees 1-5, random knots with multiplicities and random
// weights; its pieces against the curve; knot insertion (open and periodic) leaves the curve
// unchanged exactly; the round trip with Cubic_spline_2 (open and closed, polynomial and
// rational); derivatives against Rational_bezier_2 and a cubic's constant third derivative;
// the curvature of an exact circle; bad input.

#include "cox_de_boor.h"
#include "test_support.h"

#include <fair/Cubic_spline_2.h>
#include <fair/Nurbs_curve_2.h>

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace {

using fair_test::cox_de_boor;
using fair_test::q;
using fair_test::same;

template <class K>
class Nurbs_curve : public ::testing::Test {};
TYPED_TEST_SUITE(Nurbs_curve, fair_test::All_kernels);

// A random open curve: degree p, interior knots k/4 with multiplicities 1..p, clamped or not.
template <class K>
fair::Nurbs_curve_2<K> random_open(std::mt19937& rng, std::size_t p, bool clamped, bool rational) {
  typedef typename K::FT FT;
  std::uniform_int_distribution<int> gap(1, 8), coord(-40, 40), weight(1, 12), count(1, 6);
  std::uniform_int_distribution<std::size_t> mult(1, p);
  std::vector<FT> u;
  FT x = q<K>(-1, 2);
  for (std::size_t k = 0; k < (clamped ? p + 1 : 1); ++k) u.push_back(x);
  if (!clamped)
    for (std::size_t k = 0; k < p; ++k) u.push_back(x = x + q<K>(gap(rng), 4));
  for (int j = count(rng); j > 0; --j) {
    x = x + q<K>(gap(rng), 4);
    for (std::size_t m = mult(rng); m > 0; --m) u.push_back(x);
  }
  x = x + q<K>(gap(rng), 4);
  for (std::size_t k = 0; k < (clamped ? p + 1 : 1); ++k) u.push_back(x);
  if (!clamped)
    for (std::size_t k = 0; k < p; ++k) u.push_back(x = x + q<K>(gap(rng), 4));
  const std::size_t n = u.size() - p - 1;
  std::vector<typename K::Point_2> P;
  std::vector<FT> w;
  for (std::size_t k = 0; k < n; ++k) {
    P.emplace_back(q<K>(coord(rng), 8), q<K>(coord(rng), 8));
    w.push_back(rational ? q<K>(weight(rng), 4) : FT(1));
  }
  return fair::Nurbs_curve_2<K>(p, u, P, w);
}

// Rational parameters across the domain, the knots included.
template <class K>
std::vector<typename K::FT> parameters(const fair::Nurbs_curve_2<K>& c, int per_span) {
  typedef typename K::FT FT;
  std::vector<FT> x;
  const std::vector<FT> b = c.breakpoints();
  for (std::size_t j = 0; j + 1 < b.size(); ++j)
    for (int s = 0; s < per_span; ++s) x.push_back(b[j] + (b[j + 1] - b[j]) * q<K>(s, per_span));
  x.push_back(b.back());
  return x;
}

TYPED_TEST(Nurbs_curve, PointIsTheCoxDeBoorDefinition) {
  typedef TypeParam K;
  std::mt19937 rng(2601);
  for (int trial = 0; trial < 24; ++trial) {
    const std::size_t p = 1 + static_cast<std::size_t>(trial % 5);
    const fair::Nurbs_curve_2<K> c = random_open<K>(rng, p, trial % 3 != 0, trial % 2 == 0);
    for (const auto& x : parameters(c, 3)) EXPECT_TRUE(same<K>(c.point(x), cox_de_boor(c, x), 1e-12)) << trial;
  }
}

TYPED_TEST(Nurbs_curve, PiecesAreTheCurve) {
  typedef TypeParam K;
  std::mt19937 rng(2602);
  for (int trial = 0; trial < 16; ++trial) {
    const std::size_t p = 1 + static_cast<std::size_t>(trial % 4);
    const fair::Nurbs_curve_2<K> c = random_open<K>(rng, p, true, trial % 2 == 1);
    const auto b = c.breakpoints();
    ASSERT_EQ(c.pieces().size() + 1, b.size());
    for (std::size_t j = 0; j < c.pieces().size(); ++j) {
      for (int s = 0; s <= 4; ++s) {
        const auto t = q<K>(s, 4);
        EXPECT_TRUE(same<K>(c.pieces()[j].point(t), cox_de_boor(c, b[j] + (b[j + 1] - b[j]) * t), 1e-12));
      }
      if (j > 0) { EXPECT_TRUE(c.pieces()[j].source() == c.pieces()[j - 1].target()); } // bit for bit
    }
  }
}

TYPED_TEST(Nurbs_curve, KnotInsertionKeepsTheCurve) {
  typedef TypeParam K;
  std::mt19937 rng(2603);
  for (int trial = 0; trial < 16; ++trial) {
    const std::size_t p = 1 + static_cast<std::size_t>(trial % 4);
    const fair::Nurbs_curve_2<K> c = random_open<K>(rng, p, trial % 2 == 0, trial % 3 == 0);
    const auto d = c.domain();
    const auto x = d.first + (d.second - d.first) * q<K>(3 + trial, 40);
    const fair::Nurbs_curve_2<K> e = c.with_knot_inserted(x);
    EXPECT_EQ(e.number_of_control_points(), c.number_of_control_points() + 1);
    EXPECT_EQ(e.knots().size(), c.knots().size() + 1);
    for (const auto& y : parameters(c, 3)) EXPECT_TRUE(same<K>(e.point(y), c.point(y), 1e-12));
  }
}

// A closed C2 cubic spline (periodic) with random breakpoints and control points.
template <class K>
fair::Cubic_spline_2<K> random_closed_spline(std::mt19937& rng, std::size_t m, bool rational) {
  typedef typename K::FT FT;
  std::uniform_int_distribution<int> gap(1, 8), coord(-40, 40), weight(1, 12);
  std::vector<FT> t{q<K>(1, 3)};
  for (std::size_t i = 0; i < m; ++i) t.push_back(t.back() + q<K>(gap(rng), 4));
  std::vector<typename K::Point_2> c;
  std::vector<FT> w;
  for (std::size_t i = 0; i < m; ++i) {
    c.emplace_back(q<K>(coord(rng), 8), q<K>(coord(rng), 8));
    w.push_back(q<K>(weight(rng), 4));
  }
  return rational ? fair::Cubic_spline_2<K>(t, c, w, true) : fair::Cubic_spline_2<K>(t, c, true);
}

TYPED_TEST(Nurbs_curve, ClosedSplineRoundTripAndPeriodicInsertion) {
  typedef TypeParam K;
  std::mt19937 rng(2604);
  for (int trial = 0; trial < 8; ++trial) {
    const fair::Cubic_spline_2<K> s = random_closed_spline<K>(rng, 3 + static_cast<std::size_t>(trial), trial % 2 == 1);
    const fair::Nurbs_curve_2<K> c = s.nurbs();
    ASSERT_TRUE(c.is_closed());
    ASSERT_EQ(c.number_of_pieces(), s.number_of_pieces());
    for (std::size_t j = 0; j < s.number_of_pieces(); ++j)
      for (int k = 0; k <= 3; ++k) {
        const auto t = q<K>(k, 3);
        EXPECT_TRUE(same<K>(c.pieces()[j].point(t), s.pieces()[j].point(t), 1e-12));
      }
    EXPECT_TRUE(c.pieces().back().target() == c.pieces().front().source());
    const fair::Cubic_spline_2<K> back = fair::Cubic_spline_2<K>::from_nurbs(c);
    ASSERT_EQ(back.control_points().size(), s.control_points().size());
    for (std::size_t i = 0; i < s.control_points().size(); ++i)
      EXPECT_TRUE(same<K>(back.control_points()[i], s.control_points()[i], 1e-12));
    // insertion in the first span (the wrap of the periodic form is rebuilt), in the middle, at the end
    const auto b = c.breakpoints();
    for (const auto& x : {b[0] + (b[1] - b[0]) * q<K>(1, 3), b[b.size() / 2] + (b[b.size() / 2 + 1] - b[b.size() / 2]) * q<K>(2, 5),
                          b[b.size() - 2] + (b.back() - b[b.size() - 2]) * q<K>(6, 7)}) {
      const fair::Nurbs_curve_2<K> e = c.with_knot_inserted(x);
      EXPECT_TRUE(e.is_closed());
      for (const auto& y : parameters(c, 4)) EXPECT_TRUE(same<K>(e.point(y), c.point(y), 1e-11));
      // and once more on the result (a periodic form built by the insertion is valid input)
      const fair::Nurbs_curve_2<K> f = e.with_knot_inserted(b[1]);
      for (const auto& y : parameters(c, 2)) EXPECT_TRUE(same<K>(f.point(y), c.point(y), 1e-11));
    }
  }
}

TYPED_TEST(Nurbs_curve, OpenSplineRoundTrip) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::vector<FT> t{FT(0), q<K>(1, 2), FT(2), q<K>(9, 4)};
  std::vector<typename K::Point_2> d;
  for (int i = 0; i < 6; ++i) d.emplace_back(q<K>(i * i - 3, 4), q<K>(5 - 2 * i, 3));
  const fair::Cubic_spline_2<K> s(t, d, std::vector<FT>{FT(1), FT(2), q<K>(1, 2), FT(3), FT(1), q<K>(7, 5)});
  const fair::Nurbs_curve_2<K> c = s.nurbs();
  EXPECT_TRUE(c.is_rational());
  EXPECT_EQ(c.knots().size(), 10u);
  for (const auto& x : parameters(c, 5)) EXPECT_TRUE(same<K>(c.point(x), s.point(x), 1e-12));
  const fair::Cubic_spline_2<K> back = fair::Cubic_spline_2<K>::from_nurbs(c);
  for (std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_TRUE(same<K>(back.control_points()[i], d[i], 0));
    EXPECT_TRUE(same<K>(back.weights()[i], s.weights()[i], 0));
  }
  // a double knot is no C2 spline
  EXPECT_THROW(fair::Cubic_spline_2<K>::from_nurbs(c.with_knot_inserted(FT(2)).with_knot_inserted(FT(2))), fair::Precondition_error);
}

TYPED_TEST(Nurbs_curve, DerivativesAgainstThePieceAndTheThirdDifference) {
  typedef TypeParam K;
  std::mt19937 rng(2605);
  for (int trial = 0; trial < 8; ++trial) {
    const fair::Nurbs_curve_2<K> c = random_open<K>(rng, 2 + static_cast<std::size_t>(trial % 3), true, trial % 2 == 0);
    const auto b = c.breakpoints();
    for (std::size_t j = 0; j + 1 < b.size(); ++j) {
      const auto h = b[j + 1] - b[j];
      const auto t = q<K>(1, 3);
      const auto x = b[j] + h * t;
      const auto D = c.derivatives(x, 3);
      EXPECT_TRUE(same<K>(typename K::Point_2(CGAL::ORIGIN) + D[0], c.pieces()[j].point(t), 1e-12));
      EXPECT_TRUE(same<K>(D[1], c.pieces()[j].derivative(t) / h, 1e-10));
      EXPECT_TRUE(same<K>(D[2], c.pieces()[j].second_derivative(t) / (h * h), 1e-9));
      if (c.degree() == 3 && !c.is_rational()) { // c''' = 6 (b3 - 3 b2 + 3 b1 - b0) / h^3
        const auto& P = c.pieces()[j].control_points();
        const auto third = ((P[3] - P[0]) - (P[2] - P[1]) * 3) * 6 / (h * h * h);
        EXPECT_TRUE(same<K>(D[3], third, 1e-9));
      }
    }
  }
}

// A circular arc as a rational quadratic: end tangents meeting at P1 and the middle weight
// cos(theta), theta the half angle of the arc. With cos theta = 3/5 (sin theta = 4/5) all is
// rational: radius 5 about the origin, P0 = 5 (3/5, -4/5), P2 = 5 (3/5, 4/5), P1 = (5 / cos theta, 0),
// counterclockwise. On the span [0, h].
template <class K>
fair::Nurbs_curve_2<K> circle_arc(const typename K::FT& h) {
  typedef typename K::FT FT;
  std::vector<typename K::Point_2> P{{q<K>(3, 1), q<K>(-4, 1)}, {q<K>(25, 3), FT(0)}, {q<K>(3, 1), q<K>(4, 1)}};
  return fair::Nurbs_curve_2<K>(2, {FT(0), FT(0), FT(0), h, h, h}, P, {FT(1), q<K>(3, 5), FT(1)});
}

TYPED_TEST(Nurbs_curve, CurvatureOfAnExactCircle) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const FT r(5);
  // h = 1: the unit span; h = 1e-300: c' and c'' in u are 1e300 and 1e600 times those in the
  // piece's parameter, and the curvature from them overflowed (review finding 4)
  for (const FT& h : {FT(1), FT(1e-300)}) {
    const fair::Nurbs_curve_2<K> c = circle_arc<K>(h);
    for (int s = 0; s <= 8; ++s) {
      const auto x = h * q<K>(s, 8);
      const auto pt = c.point(x);
      EXPECT_TRUE(same<K>(pt.x() * pt.x() + pt.y() * pt.y(), r * r, 1e-12)); // on the circle, exactly
      EXPECT_NEAR(c.curvature(x), 1.0 / 5.0, 1e-12) << "h = " << CGAL::to_double(h) << ", s = " << s;
      if (h == FT(1)) { // the tangent is perpendicular to the radius, exactly, and turns counterclockwise
        const auto d = c.derivative(x);
        EXPECT_TRUE(same<K>(d * (pt - CGAL::ORIGIN), FT(0), 1e-12)) << s;
        EXPECT_GT(CGAL::to_double((pt - CGAL::ORIGIN).x() * d.y() - (pt - CGAL::ORIGIN).y() * d.x()), 0.0) << s;
      }
    }
  }
}

// The parabola y = x^2, x in [-1, 2], as one quadratic on the knots 0^3, 3^3 (x = u - 1):
// P0 = (a, a^2), P1 = ((a + b)/2, a b), P2 = (b, b^2) with a = -1, b = 2. Then c'(u) = (1, 2x) and
// c''(u) = (0, 2) exactly, and kappa(x) = 2 / (1 + 4 x^2)^(3/2) (review finding 11: an analytic
// value, with the tangent checked). Twice: as given, and with knots inserted (three pieces),
// and once more on spans scaled by 1e-300 (c' and c'' in u scale by 1e300 and 1e600; kappa not).
TYPED_TEST(Nurbs_curve, CurvatureOfAParabolaAgainstTheFormula) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  const std::vector<P> cp{P(-1, 1), P(q<K>(1, 2), FT(-2)), P(2, 4)};
  const fair::Nurbs_curve_2<K> c(2, {FT(0), FT(0), FT(0), FT(3), FT(3), FT(3)}, cp);
  const fair::Nurbs_curve_2<K> refined = c.with_knot_inserted(FT(1)).with_knot_inserted(q<K>(5, 2));
  ASSERT_EQ(refined.number_of_pieces(), 3u);
  const FT tiny(1e-300);
  const fair::Nurbs_curve_2<K> small(2, {FT(0), FT(0), FT(0), 3 * tiny, 3 * tiny, 3 * tiny}, cp);
  for (int s = 0; s <= 12; ++s) {
    const FT u = q<K>(s, 4), x = u - 1;
    const double xd = CGAL::to_double(x), kappa = 2 / std::pow(1 + 4 * xd * xd, 1.5);
    for (const fair::Nurbs_curve_2<K>* n : {&c, &refined}) {
      EXPECT_TRUE(same<K>(n->point(u), P(x, x * x), 1e-14)) << s;
      EXPECT_TRUE(same<K>(n->derivative(u), typename K::Vector_2(FT(1), 2 * x), 1e-14)) << s;
      EXPECT_TRUE(same<K>(n->second_derivative(u), typename K::Vector_2(FT(0), FT(2)), 1e-13)) << s;
      EXPECT_NEAR(n->curvature(u), kappa, 1e-15 * kappa) << s;
    }
    EXPECT_NEAR(small.curvature(u * tiny), kappa, 1e-15 * kappa) << s;
  }
}

TYPED_TEST(Nurbs_curve, BadInputNamesTheProblem) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  const std::vector<P> pts{P(0, 0), P(1, 1), P(2, 0), P(3, 1)};
  const std::vector<FT> clamped{FT(0), FT(0), FT(0), FT(0), FT(1), FT(1), FT(1), FT(1)};
  auto message = [&](auto make) {
    try {
      make();
    } catch (const fair::Precondition_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([&] { fair::Nurbs_curve_2<K>(0, clamped, pts); }).find("degree 0"), std::string::npos);
  EXPECT_NE(message([&] { fair::Nurbs_curve_2<K>(3, std::vector<FT>(clamped.begin(), clamped.end() - 1), pts); }).find("7 knots"), std::string::npos);
  EXPECT_NE(message([&] { fair::Nurbs_curve_2<K>(3, {FT(0), FT(0), FT(0), FT(1), FT(0), FT(1), FT(1), FT(1)}, pts); }).find("decrease"), std::string::npos);
  EXPECT_NE(message([&] { fair::Nurbs_curve_2<K>(3, clamped, pts, {FT(1), FT(0), FT(1), FT(1)}); }).find("weight 1"), std::string::npos);
  EXPECT_NE(message([&] { fair::Nurbs_curve_2<K>(3, clamped, pts, {FT(1), FT(1)}); }).find("2 weights"), std::string::npos);
  EXPECT_NE(message([&] { fair::Nurbs_curve_2<K>(3, {FT(0), FT(0), FT(0), FT(0), FT(0), FT(1), FT(1), FT(1), FT(1)}, {P(0, 0), P(1, 1), P(2, 0), P(3, 1), P(4, 0)}); }).find("multiplicity 5"), std::string::npos);
  EXPECT_NE(message([&] { fair::Nurbs_curve_2<K>(1, {FT(0), FT(1), FT(2), FT(3), FT(4)}, std::vector<P>{P(0, 0), P(1, 1), P(2, 0)}, {}, true); }).find("must repeat"), std::string::npos);
  const fair::Nurbs_curve_2<K> c(3, clamped, pts);
  EXPECT_NE(message([&] { c.point(FT(2)); }).find("outside the domain"), std::string::npos);
  EXPECT_NE(message([&] { c.with_knot_inserted(FT(0)); }).find("multiplicity 4"), std::string::npos);
  if (!fair_test::is_exact<K>()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(message([&] { fair::Nurbs_curve_2<K>(3, clamped, {P(0, 0), P(nan, 1), P(2, 0), P(3, 1)}); }).find("control point 1"), std::string::npos);
    EXPECT_NE(message([&] { fair::Nurbs_curve_2<K>(3, {FT(0), FT(0), FT(0), FT(0), FT(nan), FT(1), FT(1), FT(1)}, pts); }).find("knot 4"), std::string::npos);
  }
}

// Review finding 5: the homogeneous form w x overflowed for control points near DBL_MAX and a
// weight > 1, and underflowed for tiny weights. The weights are scaled by one power of two
// before w x is formed (exact), so: the curve scaled by 2^1000 is the curve's values times 2^1000
// bit for bit, finite, near DBL_MAX; the weights scaled by 2^-1000 (or 2^1000) change nothing,
// bit for bit; kappa of the big curve is 2^-1000 times the small one's.
TEST(Nurbs_curve_double, NearTheDoubleRangeValuesAreFiniteAndScaleExactly) {
  typedef fair_test::SC_double K;
  typedef K::Point_2 P;
  std::mt19937 rng(2606);
  for (int trial = 0; trial < 8; ++trial) {
    const std::size_t p = 2 + static_cast<std::size_t>(trial % 3);
    const fair::Nurbs_curve_2<K> c = random_open<K>(rng, p, trial % 2 == 0, true);
    double m = 0; // the largest |coordinate|: the big curve's reaches 2^1023 (DBL_MAX is just below 2^1024)
    for (const P& x : c.control_points()) m = std::max({m, std::fabs(x.x()), std::fabs(x.y())});
    const int e = 1023 - std::ilogb(m);
    std::vector<P> big;
    for (const P& x : c.control_points()) big.emplace_back(std::ldexp(x.x(), e), std::ldexp(x.y(), e));
    std::vector<double> w4 = c.weights(), tiny = c.weights(), huge = c.weights();
    for (std::size_t k = 0; k < w4.size(); ++k) {
      w4[k] *= 4; // the largest weight is at least 1: w x overflowed
      tiny[k] = std::ldexp(tiny[k], -1000);
      huge[k] = std::ldexp(huge[k], 1000);
    }
    const fair::Nurbs_curve_2<K> b(p, c.knots(), big, w4);
    const fair::Nurbs_curve_2<K> t(p, c.knots(), c.control_points(), tiny), h(p, c.knots(), c.control_points(), huge);
    const fair::Nurbs_curve_2<K> bi = b.with_knot_inserted((c.domain().first + c.domain().second) / 2);
    for (const double u : parameters(c, 3)) {
      const P x = c.point(u), y = b.point(u);
      ASSERT_TRUE(std::isfinite(y.x()) && std::isfinite(y.y())) << trial << " u = " << u;
      EXPECT_EQ(y, P(std::ldexp(x.x(), e), std::ldexp(x.y(), e))) << trial << " u = " << u;
      EXPECT_TRUE(same<K>(bi.point(u), y, 1e-13)) << trial << " u = " << u; // insertion: the same curve, finite
      EXPECT_EQ(t.point(u), x) << trial;
      EXPECT_EQ(h.point(u), x) << trial;
      const double k = c.curvature(u), kb = b.curvature(u);
      EXPECT_TRUE(fair_test::same_ulps(kb, std::ldexp(k, -e), 0)) << trial << " u = " << u;
    }
    for (std::size_t k = 0; k < b.weights().size(); ++k) EXPECT_EQ(b.weights()[k], w4[k]); // stored unscaled
  }
}

}  // namespace
