// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact conversion (Karciauskas-Peters Sec. 6, eqs. 9-10 corrected): the spline equals the
// curve at many rational parameters (exactly in EPECK and Simple_cartesian<Gmpq>), the issue's
// exact circle (x^2 + y^2 = 1 exactly), Boehm knot insertion from the single Bezier piece as an
// independent oracle, the paper's d_j coefficients literally, the corrected end conditions,
// circle arcs of 180..240 degrees, the splitting rule, and bad input.

#include "test_support.h"

#include <fair/Exact_spline_conversion.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

using fair_test::q;
using fair_test::same;

template <class K>
class Exact_spline : public ::testing::Test {};
TYPED_TEST_SUITE(Exact_spline, fair_test::All_kernels);

template <class K>
class Exact_spline_exact : public ::testing::Test {};
using fair_test::Exact_kernels;
TYPED_TEST_SUITE(Exact_spline_exact, Exact_kernels);

template <class K>
class Exact_spline_floating : public ::testing::Test {};
TYPED_TEST_SUITE(Exact_spline_floating, fair_test::Floating_kernels);

// The conic of issue 10: w = 3/5, P0 = (1,0), P1 = (1,4/3), P2 = (-7/25,24/25), a unit circle arc.
template <class K>
fair::Rational_quadratic_bezier_2<K> issue_circle() {
  typedef typename K::Point_2 P;
  return fair::Rational_quadratic_bezier_2<K>(P(1, 0), P(1, q<K>(4, 3)), P(q<K>(-7, 25), q<K>(24, 25)), q<K>(3, 5));
}

// Random marks k/64, strictly increasing in (0,1).
template <class K>
std::vector<typename K::FT> random_marks(std::mt19937& rng, std::size_t count) {
  std::vector<int> k(63);
  for (int i = 0; i < 63; ++i) k[i] = i + 1;
  std::shuffle(k.begin(), k.end(), rng);
  k.resize(count);
  std::sort(k.begin(), k.end());
  std::vector<typename K::FT> u;
  for (int x : k) u.push_back(q<K>(x, 64));
  return u;
}

// The spline at global parameter t equals the curve at t, for t = k/37 (not breakpoints).
template <class K, class Curve>
void expect_reproduces(const fair::Cubic_spline_2<K>& s, const Curve& c, double rel) {
  for (int k = 0; k <= 37; ++k) EXPECT_TRUE(same<K>(s.point(q<K>(k, 37)), c.point(q<K>(k, 37)), rel)) << "t = " << k << "/37";
}

TYPED_TEST(Exact_spline, ConicIsReproducedOnAllOfItsDomain) {
  typedef TypeParam K;
  const fair::Rational_quadratic_bezier_2<K> c = issue_circle<K>();
  const std::vector<typename K::FT> u{q<K>(1, 7), q<K>(1, 3), q<K>(1, 2), q<K>(4, 5)};
  const fair::Cubic_spline_2<K> s = fair::exact_spline(c, u);
  EXPECT_TRUE(s.is_rational());
  EXPECT_FALSE(s.is_closed());
  ASSERT_EQ(s.number_of_pieces(), 5u);
  ASSERT_EQ(s.number_of_control_points(), 8u);
  EXPECT_TRUE(same<K>(s.breakpoints()[2], u[1]));
  expect_reproduces(s, c, 1e-14);
  // On the unit circle: x^2 + y^2 = 1, exactly in an exact kernel.
  for (int k = 0; k <= 40; ++k) {
    const typename K::Point_2 p = s.point(q<K>(k, 40));
    EXPECT_TRUE(same<K>(p.x() * p.x() + p.y() * p.y(), typename K::FT(1), 1e-14)) << k;
  }
  for (const typename K::FT& w : s.weights()) EXPECT_GT(w, typename K::FT(0));
}

TYPED_TEST(Exact_spline, RandomRationalCubicsAreReproduced) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  std::mt19937 rng(20261201);
  std::uniform_int_distribution<int> w(1, 12);
  for (int run = 0; run < 6; ++run) {
    const std::vector<P> p = fair_test::random_points<K>(rng, 4);
    const fair::Rational_bezier_2<K> c(p, {q<K>(w(rng), 4), q<K>(w(rng), 4), q<K>(w(rng), 4), q<K>(w(rng), 4)});
    const fair::Cubic_spline_2<K> s = fair::exact_spline(c, random_marks<K>(rng, 1 + run * 3));
    expect_reproduces(s, c, 1e-12);
  }
}

TYPED_TEST(Exact_spline, PolynomialPiecesOfDegreeZeroToThreeGivePolynomialSplines) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  std::mt19937 rng(7);
  for (std::size_t n = 1; n <= 4; ++n) {
    const fair::Bezier_2<K> b(fair_test::random_points<K>(rng, n));
    const std::vector<typename K::FT> u = random_marks<K>(rng, 5);
    const fair::Cubic_spline_2<K> s = fair::exact_spline(b, u);
    EXPECT_FALSE(s.is_rational()) << "degree " << n - 1;
    for (int k = 0; k <= 37; ++k) EXPECT_TRUE(same<K>(s.point(q<K>(k, 37)), b.point(q<K>(k, 37)), 1e-12));
  }
  // No marks: the Bezier piece itself (degree-elevated).
  const fair::Bezier_2<K> line(std::vector<P>{P(0, 0), P(3, 6)});
  const fair::Cubic_spline_2<K> s = fair::exact_spline(line, {});
  ASSERT_EQ(s.number_of_control_points(), 4u);
  EXPECT_TRUE(same<K>(s.control_points()[1], P(1, 2)));
  EXPECT_TRUE(same<K>(s.control_points()[2], P(2, 4)));
}

// Independent oracle: Boehm knot insertion (Cubic_spline_2::with_knot_inserted) of the marks,
// in shuffled order, into the one Bezier piece on breakpoints {0, 1}, gives the same control
// points and weights.
TYPED_TEST(Exact_spline, EqualsKnotInsertionIntoTheBezierPiece) {
  typedef TypeParam K;
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> w(1, 12);
  for (int run = 0; run < 4; ++run) {
    const fair::Rational_bezier_2<K> c(fair_test::random_points<K>(rng, 4),
                                       {q<K>(w(rng), 3), q<K>(w(rng), 3), q<K>(w(rng), 3), q<K>(w(rng), 3)});
    const std::vector<typename K::FT> u = random_marks<K>(rng, 7);
    const fair::Cubic_spline_2<K> s = fair::exact_spline(c, u);
    fair::Cubic_spline_2<K> oracle(std::vector<typename K::FT>{0, 1}, c.control_points(), c.weights());
    std::vector<typename K::FT> order = u;
    std::shuffle(order.begin(), order.end(), rng);
    for (const typename K::FT& x : order) oracle = oracle.with_knot_inserted(x);
    ASSERT_EQ(oracle.number_of_control_points(), s.number_of_control_points());
    for (std::size_t i = 0; i < s.number_of_control_points(); ++i) {
      EXPECT_TRUE(same<K>(s.control_points()[i], oracle.control_points()[i], 1e-12)) << i;
      EXPECT_TRUE(same<K>(s.weights()[i], oracle.weights()[i], 1e-12)) << i;
    }
  }
}

// eq. 9 read literally: c_i = sum_j d_j b_j with the paper's d_0, d_2, d_3 and d_1 = 1 - d_0 - d_2 - d_3,
// coordinatewise in homogeneous space, equals control point i + 1.
TYPED_TEST(Exact_spline, PaperCoefficientsOfEq9AreTheBlossom) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const fair::Rational_bezier_2<K> c(issue_circle<K>());
  const std::vector<FT> u{q<K>(1, 9), q<K>(2, 7), q<K>(1, 2), q<K>(5, 8), q<K>(9, 10)};
  const fair::Cubic_spline_2<K> s = fair::exact_spline(c, u);
  const std::vector<FT> t{0, u[0], u[1], u[2], u[3], u[4], 1};
  // homogeneous Bezier points of the degree-elevated conic
  const FT w = q<K>(3, 5), we = (FT(1) + FT(2) * w) / FT(3);
  const FT bx[4] = {FT(1), (FT(1) + FT(2) * w * FT(1)) / FT(3), (FT(2) * w * FT(1) + q<K>(-7, 25)) / FT(3), q<K>(-7, 25)};
  const FT by[4] = {FT(0), (FT(0) + FT(2) * w * q<K>(4, 3)) / FT(3), (FT(2) * w * q<K>(4, 3) + q<K>(24, 25)) / FT(3), q<K>(24, 25)};
  const FT bw[4] = {FT(1), we, we, FT(1)};
  for (std::size_t i = 1; i + 1 < t.size(); ++i) {
    const FT a = t[i - 1], b = t[i], e = t[i + 1];
    const FT d0 = (FT(1) - a) * (FT(1) - b) * (FT(1) - e);
    const FT d2 = a * b + a * e + b * e - FT(3) * a * b * e;
    const FT d3 = a * b * e;
    const FT d1 = FT(1) - d0 - d2 - d3;
    const FT X = d0 * bx[0] + d1 * bx[1] + d2 * bx[2] + d3 * bx[3];
    const FT Y = d0 * by[0] + d1 * by[1] + d2 * by[2] + d3 * by[3];
    const FT W = d0 * bw[0] + d1 * bw[1] + d2 * bw[2] + d3 * bw[3];
    EXPECT_TRUE(same<K>(s.weights()[i + 1], W, 1e-14)) << i;
    EXPECT_TRUE(same<K>(s.control_points()[i + 1], typename K::Point_2(X / W, Y / W), 1e-14)) << i;
  }
}

// eq. 10 as corrected: c_{-1} = b_0^0, c_0 = b_1^0, b_2^0 = (beta_1 b_1^0 + c_1)/(1 + beta_1), and
// mirrored b_1^{m-1} = (beta_{m-1} c_{m-1} + b_2^{m-1})/(1 + beta_{m-1}) -- in homogeneous coordinates.
TYPED_TEST(Exact_spline, CorrectedEndConditionsOfEq10) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const fair::Rational_quadratic_bezier_2<K> c = issue_circle<K>();
  const std::vector<FT> u{q<K>(1, 5), q<K>(1, 2), q<K>(3, 4)};
  const fair::Cubic_spline_2<K> s = fair::exact_spline(c, u);
  const std::size_t m = s.number_of_pieces(), n = s.number_of_control_points();
  auto H = [&](std::size_t i, FT& x, FT& y, FT& w) {
    w = s.weights()[i];
    x = w * s.control_points()[i].x();
    y = w * s.control_points()[i].y();
  };
  auto Hp = [&](const fair::Rational_bezier_2<K>& p, std::size_t i, FT& x, FT& y, FT& w) {
    w = p.weights()[i];
    x = w * p.control_points()[i].x();
    y = w * p.control_points()[i].y();
  };
  const fair::Rational_bezier_2<K> first = s.piece(0), last = s.piece(m - 1);
  EXPECT_TRUE(same<K>(s.control_points()[0], c.source()));
  EXPECT_TRUE(same<K>(s.control_points()[1], first.control_points()[1]));
  EXPECT_TRUE(same<K>(s.control_points()[n - 1], c.target()));
  EXPECT_TRUE(same<K>(s.control_points()[n - 2], last.control_points()[2]));
  FT x0, y0, w0, x1, y1, w1, x2, y2, w2;
  const FT b1 = s.beta(1), bl = s.beta(m - 1);
  EXPECT_TRUE(same<K>(b1, (u[1] - u[0]) / u[0]));
  H(1, x0, y0, w0);      // b_1^0
  H(2, x1, y1, w1);      // c_1
  Hp(first, 2, x2, y2, w2);
  EXPECT_TRUE(same<K>(x2, (b1 * x0 + x1) / (FT(1) + b1), 1e-14));
  EXPECT_TRUE(same<K>(y2, (b1 * y0 + y1) / (FT(1) + b1), 1e-14));
  EXPECT_TRUE(same<K>(w2, (b1 * w0 + w1) / (FT(1) + b1), 1e-14));
  H(n - 3, x0, y0, w0);  // c_{m-1}
  H(n - 2, x1, y1, w1);  // b_2^{m-1}
  Hp(last, 1, x2, y2, w2);
  EXPECT_TRUE(same<K>(x2, (bl * x0 + x1) / (FT(1) + bl), 1e-14));
  EXPECT_TRUE(same<K>(y2, (bl * y0 + y1) / (FT(1) + bl), 1e-14));
  EXPECT_TRUE(same<K>(w2, (bl * w0 + w1) / (FT(1) + bl), 1e-14));
}

TYPED_TEST(Exact_spline, BadInputIsATypedError) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  const fair::Rational_quadratic_bezier_2<K> c = issue_circle<K>();
  auto message_of = [&](const std::vector<typename K::FT>& u) {
    try {
      fair::exact_spline(c, u);
    } catch (const fair::Invalid_input_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message_of({q<K>(1, 2), q<K>(1, 2)}).find("increase strictly"), std::string::npos);
  EXPECT_NE(message_of({q<K>(1, 2), q<K>(1, 3)}).find("u[0] = 0.5"), std::string::npos);
  EXPECT_NE(message_of({typename K::FT(0)}).find("not in the open interval"), std::string::npos);
  EXPECT_NE(message_of({typename K::FT(1)}).find("exact_spline"), std::string::npos);
  const fair::Bezier_2<K> quartic(std::vector<P>{P(0, 0), P(1, 1), P(2, 0), P(3, 1), P(4, 0)});
  EXPECT_THROW(fair::exact_spline(quartic, {q<K>(1, 2)}), fair::Precondition_error);
  if (!fair_test::is_exact<K>()) {
    EXPECT_THROW(fair::exact_spline(c, {typename K::FT(std::nan(""))}), fair::Invalid_input_error);
  }
}

// Rational data: the quarter-angle tangents q = 0, 1/2 give the issue's conic, exactly.
TYPED_TEST(Exact_spline_exact, RationalCircleArcIsTheIssuesConic) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  const fair::Rational_bezier_2<K> a = fair::rational_circle_arc_cubic<K>(P(0, 0), 1, 0, q<K>(1, 2));
  const fair::Rational_bezier_2<K> b = fair::exact_spline(issue_circle<K>(), {}).piece(0);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(a.control_points()[i], b.control_points()[i]) << i;
    EXPECT_EQ(a.weights()[i], b.weights()[i]) << i;
  }
}

// An exact arc of about 200 degrees (q = tan(theta/4) from -1/5 to 1): beyond the standard
// quadratic (w < 0) but representable as a cubic; converted with marks it stays on its circle
// of centre (1/2, -3) and radius 7/4 exactly.
TYPED_TEST(Exact_spline_exact, ArcBeyondHalfCircleStaysExactlyOnTheCircle) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  const P center(q<K>(1, 2), -3);
  const FT r = q<K>(7, 4);
  const fair::Rational_bezier_2<K> a = fair::rational_circle_arc_cubic<K>(center, r, q<K>(-1, 5), FT(1));
  EXPECT_LT(a.weights()[1], FT(1) / FT(3)); // w = cos(alpha/2) < 0
  const fair::Cubic_spline_2<K> s = fair::exact_spline(a, {q<K>(1, 10), q<K>(1, 3), q<K>(1, 2), q<K>(7, 9)});
  for (int k = 0; k <= 50; ++k) {
    const P p = s.point(q<K>(k, 50));
    EXPECT_EQ(CGAL::squared_distance(p, center), r * r) << k;
  }
  // 4 (atan 1 - atan(-1/5)) = 3.93 rad > 240 deg: not representable.
  EXPECT_THROW(fair::rational_circle_arc_cubic<K>(center, r, q<K>(-2, 5), FT(1)), fair::Precondition_error);
  EXPECT_THROW(fair::rational_circle_arc_cubic<K>(center, r, FT(1), FT(1)), fair::Precondition_error);
  EXPECT_THROW(fair::rational_circle_arc_cubic<K>(center, FT(0), FT(0), FT(1)), fair::Precondition_error);
}

TYPED_TEST(Exact_spline_floating, CircleArcsUpTo240Degrees) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  const double deg = fair::internal::exact_conversion::pi / 180;
  const P center(2, -1);
  for (double opening : {10.0, 90.0, 179.0, 180.0, 200.0, 239.0}) {
    const fair::Rational_bezier_2<K> a = fair::circle_arc_cubic<K>(center, 3, 30 * deg, (30 + opening) * deg);
    for (int k = 0; k <= 20; ++k) {
      const P p = a.point(k / 20.0);
      EXPECT_TRUE(fair_test::same_double(std::sqrt(CGAL::to_double(CGAL::squared_distance(p, center))), 3.0, 1e-13))
          << opening << " deg, t = " << k / 20.0;
    }
    // the end points and the mid-parameter point (symmetric form: angle 30 + opening / 2)
    EXPECT_TRUE(same<K>(a.point(0.5), P(2 + 3 * std::cos((30 + opening / 2) * deg), -1 + 3 * std::sin((30 + opening / 2) * deg)), 1e-13));
    EXPECT_TRUE(same<K>(a.target(), P(2 + 3 * std::cos((30 + opening) * deg), -1 + 3 * std::sin((30 + opening) * deg)), 1e-15));
  }
  EXPECT_THROW(fair::circle_arc_cubic<K>(center, 3, 0, 240 * deg), fair::Precondition_error);
  EXPECT_THROW(fair::circle_arc_cubic<K>(center, 3, 1, 1), fair::Precondition_error);
  EXPECT_THROW(fair::circle_arc_cubic<K>(center, -3, 0, 1), fair::Precondition_error);
  EXPECT_THROW(fair::circle_arc_cubic<K>(center, 3, 0, std::nan("")), fair::Precondition_error);
  // a 90 degree arc equals its standard quadratic
  const fair::Rational_quadratic_bezier_2<K> quarter(P(5, -1), P(5, 2), P(2, 2), std::sqrt(0.5));
  const fair::Rational_bezier_2<K> a = fair::circle_arc_cubic<K>(center, 3, 0, 90 * deg);
  for (int k = 0; k <= 10; ++k) EXPECT_TRUE(same<K>(a.point(k / 10.0), quarter.point(k / 10.0), 1e-14));
  try {
    fair::circle_arc_cubic<K>(center, 3, 0, 250 * deg);
    ADD_FAILURE() << "no error";
  } catch (const fair::Precondition_error& e) {
    EXPECT_NE(std::string(e.what()).find("circle_arc_cubic"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("250"), std::string::npos) << e.what();
  }
}

TEST(Circle_arc_split, SplitsOpeningsAbove180DegreesIntoEqualSubarcs) {
  const double pi = fair::internal::exact_conversion::pi;
  typedef std::vector<std::pair<double, double>> Arcs;
  const Arcs whole = fair::circle_arc_split(0.5, 0.5 + pi);
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_EQ(whole[0], std::make_pair(0.5, 0.5 + pi));
  for (double opening : {pi + 1e-9, 1.2 * pi, 239.0 / 180 * pi, 1.9 * pi, 2 * pi}) {
    const Arcs a = fair::circle_arc_split(-1, -1 + opening);
    ASSERT_EQ(a.size(), 2u) << opening;
    EXPECT_EQ(a.front().first, -1.0);
    EXPECT_EQ(a.back().second, -1 + opening);
    EXPECT_EQ(a[0].second, a[1].first);
    EXPECT_NEAR(a[0].second - a[0].first, a[1].second - a[1].first, 1e-15);
    for (const std::pair<double, double>& s : a) {
      EXPECT_LE(s.second - s.first, pi);
      EXPECT_NO_THROW(fair::circle_arc_cubic<fair_test::SC_double>(fair_test::SC_double::Point_2(0, 0), 1, s.first, s.second));
    }
  }
  EXPECT_THROW(fair::circle_arc_split(0, 0), fair::Precondition_error);
  EXPECT_THROW(fair::circle_arc_split(0, 2 * pi + 0.1), fair::Precondition_error);
  EXPECT_THROW(fair::circle_arc_split(0, HUGE_VAL), fair::Precondition_error);
}

} // namespace
