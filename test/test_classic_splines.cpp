// Tests of the classic interpolating splines: Cubic_interpolating_spline_2 (natural, clamped,
// periodic, not-a-knot; uniform, centripetal, chordal knots), Catmull_rom_2, and the O(n) tridiagonal solvers.

#include <fair/Catmull_rom_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/internal/classic/tridiagonal.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using namespace fair_test;

// The options the tests build most often (doc/concepts.md: closed is an option of every family).
fair::Cubic_interpolating_spline_options spline_options(fair::Spline_end_condition end,
                                                        fair::Knot_spacing spacing = fair::Knot_spacing::UNIFORM) {
  fair::Cubic_interpolating_spline_options o;
  o.end_condition = end;
  o.knot_spacing = spacing;
  return o;
}
fair::Cubic_interpolating_spline_options periodic_options(fair::Knot_spacing spacing = fair::Knot_spacing::UNIFORM) {
  fair::Cubic_interpolating_spline_options o;
  o.closed = true;
  o.knot_spacing = spacing;
  return o;
}
fair::Catmull_rom_options cr_options(bool closed, fair::Knot_spacing spacing = fair::Knot_spacing::UNIFORM) {
  fair::Catmull_rom_options o;
  o.closed = closed;
  o.knot_spacing = spacing;
  return o;
}

const fair::Knot_spacing all_spacings[] = {fair::Knot_spacing::UNIFORM, fair::Knot_spacing::CENTRIPETAL,
                                           fair::Knot_spacing::CHORDAL};

// Interpolation, and C1/C2 continuity in the knot parameter u: piece i has local parameter
// t = (u - u_i)/h_i, so d/du = (1/h_i) d/dt and d2/du2 = (1/h_i^2) d2/dt2.
template <class K, class Curve>
void check_interpolation_and_continuity(const Curve& c, int order) {
  typedef typename K::FT FT;
  const auto& p = c.points();
  const auto& pieces = c.pieces();
  const auto& u = c.knots();
  const std::size_t n = p.size();
  ASSERT_EQ(pieces.size(), c.is_closed() ? n : n - 1);
  ASSERT_EQ(u.size(), pieces.size() + 1);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    EXPECT_TRUE(same<K>(pieces[i].point(FT(0)), p[i], 1e-11)) << "interpolates start";
    EXPECT_TRUE(same<K>(pieces[i].point(FT(1)), p[(i + 1) % n], 1e-11)) << "interpolates end";
  }
  const std::size_t joins = c.is_closed() ? pieces.size() : pieces.size() - 1;
  for (std::size_t i = 0; i < joins; ++i) {
    const std::size_t j = (i + 1) % pieces.size();
    const FT hi = u[i + 1] - u[i], hj = u[j + 1] - u[j];
    const auto d1 = pieces[i].derivative(FT(1)), d2 = pieces[j].derivative(FT(0));
    EXPECT_TRUE(same<K>(d1.x() / hi, d2.x() / hj, 1e-11)) << "C1 x";
    EXPECT_TRUE(same<K>(d1.y() / hi, d2.y() / hj, 1e-11)) << "C1 y";
    // The derivative reported for the point agrees with the pieces.
    EXPECT_TRUE(same<K>(c.derivatives()[(i + 1) % n].x(), d2.x() / hj, 1e-11)) << "derivative() x";
    if (order >= 2) {
      const auto s1 = pieces[i].second_derivative(FT(1)), s2 = pieces[j].second_derivative(FT(0));
      EXPECT_TRUE(same<K>(s1.x() / (hi * hi), s2.x() / (hj * hj), 1e-11)) << "C2 x";
      EXPECT_TRUE(same<K>(s1.y() / (hi * hi), s2.y() / (hj * hj), 1e-11)) << "C2 y";
    }
  }
}

template <class K>
class Classic_splines : public ::testing::Test {};
TYPED_TEST_SUITE(Classic_splines, All_kernels);

// ---------------------------------------------------------------------------------------------
// Cubic_interpolating_spline_2

// Hand solution. Natural uniform spline through p0 = (0,0), p1 = (1,1), p2 = (2,0).
// Rows: 2 m0 + m1 = 3 (p1 - p0), m0 + 4 m1 + m2 = 3 (p2 - p0), m1 + 2 m2 = 3 (p2 - p1).
// x: 2a + b = 3, a + 4b + c = 6, b + 2c = 3  ->  a = b = c = 1 (x(u) = u).
// y: 2a + b = 3, a + 4b + c = 0, b + 2c = -3 ->  by antisymmetry c = -a, so b = 0, a = 3/2.
// On [0,1]: y(u) = 3u/2 - u^3/2 (y(0) = 0, y(1) = 1, y'(1) = 0, y''(0) = 0), Bezier ordinates
// 0, 1/2, 1, 1, and y(1/2) = 3/4 - 1/16 = 11/16.
TYPED_TEST(Classic_splines, NaturalSplineThroughThreePointsByHand) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  fair::Cubic_interpolating_spline_2<K> s({P(0, 0), P(1, 1), P(2, 0)});
  ASSERT_EQ(s.pieces().size(), 2u);
  const auto& m = s.derivatives();
  EXPECT_TRUE(same<K>(m[0], typename K::Vector_2(1, FT(3) / 2), 1e-11)) << "m0";
  EXPECT_TRUE(same<K>(m[1], typename K::Vector_2(1, 0), 1e-11)) << "m1";
  EXPECT_TRUE(same<K>(m[2], typename K::Vector_2(1, FT(-3) / 2), 1e-11)) << "m2";
  const auto cp = s.pieces()[0].control_points();
  EXPECT_TRUE(same<K>(cp[1], P(FT(1) / 3, FT(1) / 2), 1e-11)) << "P1";
  EXPECT_TRUE(same<K>(cp[2], P(FT(2) / 3, 1), 1e-11)) << "P2";
  EXPECT_TRUE(same<K>(s.pieces()[0].point(FT(1) / 2), P(FT(1) / 2, FT(11) / 16), 1e-11)) << "c(1/2)";
  // Mirror symmetry: second piece is the first reflected in x = 1.
  EXPECT_TRUE(same<K>(s.pieces()[1].point(FT(1) / 2), P(FT(3) / 2, FT(11) / 16), 1e-11)) << "c(3/2)";
}

// Periodic spline through the square (1,0), (0,1), (-1,0), (0,-1). The uniform periodic rows are
// m_{i-1} + 4 m_i + m_{i+1} = 3 (p_{i+1} - p_{i-1}). With p_{i+1} = R p_i (R = rotation by 90
// degrees) try m_i = lambda R p_i: then m_{i-1} + m_{i+1} = lambda R (p_{i-1} + p_{i+1}) = 0 and
// p_{i+1} - p_{i-1} = 2 R p_i, so 4 lambda = 6, lambda = 3/2: m_0 = (0, 3/2), m_1 = (-3/2, 0).
TYPED_TEST(Classic_splines, PeriodicSplineThroughSquareByHand) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  fair::Cubic_interpolating_spline_2<K> s({P(1, 0), P(0, 1), P(-1, 0), P(0, -1)}, periodic_options());
  ASSERT_EQ(s.pieces().size(), 4u);
  EXPECT_TRUE(s.is_closed());
  EXPECT_TRUE(same<K>(s.derivatives()[0], typename K::Vector_2(0, FT(3) / 2), 1e-11)) << "m0";
  EXPECT_TRUE(same<K>(s.derivatives()[1], typename K::Vector_2(FT(-3) / 2, 0), 1e-11)) << "m1";
  check_interpolation_and_continuity<K>(s, 2);
  // c(1/2) on the first piece: Bezier (1,0), (1,1/2), (1/2,1), (0,1) -> (11/16, 11/16).
  EXPECT_TRUE(same<K>(s.pieces()[0].point(FT(1) / 2), P(FT(11) / 16, FT(11) / 16), 1e-11)) << "c(1/2)";
}

TYPED_TEST(Classic_splines, NaturalClampedPeriodicOnRandomData) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Vector_2 V;
  std::mt19937 rng(20261126);
  const int trials = is_exact<K>() ? 3 : 40;
  for (int trial = 0; trial < trials; ++trial) {
    const std::size_t n = 2 + static_cast<std::size_t>(trial % 9);
    const auto p = random_points<K>(rng, n);
    for (fair::Knot_spacing sp : all_spacings) {
      fair::Cubic_interpolating_spline_2<K> nat(p, spline_options(fair::Spline_end_condition::NATURAL, sp));
      check_interpolation_and_continuity<K>(nat, 2);
      // Natural ends: zero second derivative.
      EXPECT_TRUE(same<K>(nat.pieces().front().second_derivative(FT(0)), V(0, 0), 1e-11)) << "natural start";
      EXPECT_TRUE(same<K>(nat.pieces().back().second_derivative(FT(1)), V(0, 0), 1e-11)) << "natural end";

      const V t0(FT(3) / 2, FT(-1) / 4), t1(FT(-2), FT(5) / 8);
      fair::Cubic_interpolating_spline_2<K> cl(p, t0, t1, spline_options(fair::Spline_end_condition::NATURAL, sp));
      EXPECT_EQ(cl.options().end_condition, fair::Spline_end_condition::CLAMPED);
      check_interpolation_and_continuity<K>(cl, 2);
      const auto& u = cl.knots();
      const FT h0 = u[1] - u[0], hn = u.back() - u[u.size() - 2];
      // Clamped ends: c'(u_0) = t0, c'(u_n) = t1, i.e. piece derivatives h t.
      EXPECT_TRUE(same<K>(cl.pieces().front().derivative(FT(0)), t0 * h0, 1e-11)) << "clamped start";
      EXPECT_TRUE(same<K>(cl.pieces().back().derivative(FT(1)), t1 * hn, 1e-11)) << "clamped end";

      if (n >= 3) {
        fair::Cubic_interpolating_spline_2<K> per(p, periodic_options(sp));
        check_interpolation_and_continuity<K>(per, 2);
        EXPECT_TRUE(per.pieces().back().point(FT(1)) == p.front()) << "periodic closure";
      }
    }
  }
}

// Clamped spline with the exact end derivatives reproduces a cubic polynomial (the cubic
// satisfies every equation of the system, and the system is non-singular).
TYPED_TEST(Classic_splines, ClampedSplineReproducesCubics) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  auto q = [](const FT& u) { return P(u * u * u - 2 * u * u + 3, FT(1) / 2 * u * u * u + u - 1); };
  auto dq = [](const FT& u) { return typename K::Vector_2(3 * u * u - 4 * u, FT(3) / 2 * u * u + 1); };
  std::vector<P> p;
  for (int i = 0; i <= 6; ++i) p.push_back(q(FT(i)));
  fair::Cubic_interpolating_spline_2<K> s(p, dq(FT(0)), dq(FT(6)));
  for (std::size_t i = 0; i < s.pieces().size(); ++i)
    for (int k = 0; k <= 4; ++k)
      EXPECT_TRUE(same<K>(s.pieces()[i].point(FT(k) / 4), q(FT(static_cast<int>(i)) + FT(k) / 4), 1e-11)) << "cubic";
  // The natural spline does not: q''(0) = (-4, 0) != 0, so it must differ somewhere.
  fair::Cubic_interpolating_spline_2<K> nat(p);
  EXPECT_FALSE(nat.pieces()[0].point(FT(1) / 2) == q(FT(1) / 2));
  // ... but it reproduces straight lines, with any spacing (uniform knots: exactly).
  std::vector<P> line;
  for (int i = 0; i <= 5; ++i) line.push_back(P(FT(2 * i - 3), FT(-i) / 2));
  fair::Cubic_interpolating_spline_2<K> ls(line);
  for (std::size_t i = 0; i < ls.pieces().size(); ++i)
    EXPECT_TRUE(same<K>(ls.pieces()[i].point(FT(1) / 3), P(FT(2) * (FT(static_cast<int>(i)) + FT(1) / 3) - 3, -(FT(static_cast<int>(i)) + FT(1) / 3) / 2), 1e-11)) << "line";
}

// Not-a-knot ends reproduce cubics from the data alone (no end derivatives): exactly in an exact
// kernel (uniform knots, rational data), and they keep c''' continuous at u_1 and u_{n-1} on any
// data. Three points give the parabola through them, two the segment.
TYPED_TEST(Classic_splines, NotAKnotSplineReproducesCubicsAndParabolas) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  const auto nak = fair::Spline_end_condition::NOT_A_KNOT;
  auto q = [](const FT& u) { return P(u * u * u - 2 * u * u + 3, FT(1) / 2 * u * u * u + u - 1); };
  for (int last = 3; last <= 7; ++last) {  // 4 .. 8 points
    std::vector<P> p;
    for (int i = 0; i <= last; ++i) p.push_back(q(FT(i)));
    fair::Cubic_interpolating_spline_2<K> s(p, spline_options(nak));
    check_interpolation_and_continuity<K>(s, 2);
    for (std::size_t i = 0; i < s.pieces().size(); ++i)
      for (int k = 0; k <= 4; ++k)
        EXPECT_TRUE(same<K>(s.pieces()[i].point(FT(k) / 4), q(FT(static_cast<int>(i)) + FT(k) / 4), 1e-11))
            << "cubic, " << last + 1 << " points, piece " << i;
  }
  auto parabola = [](const FT& u) { return P(3 * u * u - u + 2, -u * u + 4); };
  fair::Cubic_interpolating_spline_2<K> s3({parabola(FT(0)), parabola(FT(1)), parabola(FT(2))}, spline_options(nak));
  for (std::size_t i = 0; i < 2; ++i)
    for (int k = 0; k <= 4; ++k)
      EXPECT_TRUE(same<K>(s3.pieces()[i].point(FT(k) / 4), parabola(FT(static_cast<int>(i)) + FT(k) / 4), 1e-11))
          << "parabola";
  fair::Cubic_interpolating_spline_2<K> s2({P(1, 2), P(4, -2)}, spline_options(nak));
  EXPECT_TRUE(same<K>(s2.pieces()[0].point(FT(1) / 4), P(FT(7) / 4, 1), 1e-11)) << "segment";
  EXPECT_TRUE(same<K>(s2.pieces()[0].point(FT(1) / 2), P(FT(5) / 2, 0), 1e-11)) << "segment";

  // Random data, every spacing: C2 everywhere, and c''' continuous across u_1 and u_{n-1}
  // (piece third derivative 6 (b3 - 3 b2 + 3 b1 - b0) in t, over h^3 in u).
  std::mt19937_64 rng(417);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  for (fair::Knot_spacing sp : all_spacings)
    for (int round = 0; round < 4; ++round) {
      std::vector<P> p;
      for (int i = 0; i < 5 + round; ++i) p.push_back(P(FT(coordinate(rng)), FT(coordinate(rng))));
      fair::Cubic_interpolating_spline_2<K> s(p, spline_options(nak, sp));
      check_interpolation_and_continuity<K>(s, 2);
      const auto& b = s.pieces();
      const auto& u = s.knots();
      auto third = [&](std::size_t i) {
        const FT h = u[i + 1] - u[i];
        return (b[i].control_point(3) - b[i].control_point(0) + FT(3) * (b[i].control_point(1) - b[i].control_point(2))) /
               (h * h * h);
      };
      const std::size_t m = b.size();
      EXPECT_TRUE(same<K>(third(0).x(), third(1).x(), 1e-9)) << "c''' at u_1";
      EXPECT_TRUE(same<K>(third(0).y(), third(1).y(), 1e-9)) << "c''' at u_1";
      EXPECT_TRUE(same<K>(third(m - 2).x(), third(m - 1).x(), 1e-9)) << "c''' at u_{n-1}";
      EXPECT_TRUE(same<K>(third(m - 2).y(), third(m - 1).y(), 1e-9)) << "c''' at u_{n-1}";
    }
}

// Long systems (520 rows) take the solvers' DAG-pruning path for lazy exact numbers (see
// classic_tridiagonal.h); the result must still be exact.
TYPED_TEST(Classic_splines, LongNaturalAndPeriodicSplinesStayExact) {
  typedef TypeParam K;
  std::mt19937 rng(520);
  const auto p = random_points<K>(rng, 520);
  fair::Cubic_interpolating_spline_2<K> nat(p);
  check_interpolation_and_continuity<K>(nat, 2);
  fair::Cubic_interpolating_spline_2<K> per(p, periodic_options());
  check_interpolation_and_continuity<K>(per, 2);
}

// Collinear data: every construction is an affine combination along the line, so all control
// points stay on it (exactly in an exact kernel, decided by the exact orientation predicate).
TYPED_TEST(Classic_splines, CollinearDataStayOnTheLine) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  std::vector<P> p;
  for (int x : {0, 1, 3, 4, 9, 10, 14}) p.push_back(P(FT(x), FT(2 * x + 1)));
  const P a(0, 1), b(1, 3);
  for (const bool closed : {false, true}) {
    fair::Cubic_interpolating_spline_2<K> s(p, closed ? periodic_options() : spline_options(fair::Spline_end_condition::NATURAL));
    fair::Catmull_rom_2<K> c(p, cr_options(closed));
    for (const auto* pieces : {&s.pieces(), &c.pieces()})
      for (const auto& piece : *pieces)
        for (const P& q : piece.control_points()) {
          if (is_exact<K>())
            EXPECT_EQ(CGAL::orientation(a, b, q), CGAL::COLLINEAR);
          else
            EXPECT_NEAR(CGAL::to_double(q.y()), 2 * CGAL::to_double(q.x()) + 1, 1e-12 * (1 + std::fabs(CGAL::to_double(q.y()))));
        }
  }
}

// Scale invariance over 600 orders of magnitude (double kernels): the same data scaled by
// 1e-150 and 1e150 give the same curve scaled, to rounding.
TYPED_TEST(Classic_splines, TinyAndHugeCoordinates) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  if (is_exact<K>()) return;  // the exact kernels are scale-exact by construction
  std::mt19937 rng(3);
  const auto base = random_points<K>(rng, 9);
  for (double scale : {1e-150, 1e150}) {
    std::vector<P> p;
    for (const P& q : base) p.push_back(P(q.x() * scale, q.y() * scale));
    for (fair::Knot_spacing sp : all_spacings) {
      fair::Cubic_interpolating_spline_2<K> s0(base, spline_options(fair::Spline_end_condition::NATURAL, sp));
      fair::Cubic_interpolating_spline_2<K> s1(p, spline_options(fair::Spline_end_condition::NATURAL, sp));
      fair::Catmull_rom_2<K> c0(base, cr_options(true, sp)), c1(p, cr_options(true, sp));
      for (std::size_t i = 0; i < s0.pieces().size(); ++i) {
        const P a = s0.pieces()[i].point(FT(0.3)), b = s1.pieces()[i].point(FT(0.3));
        EXPECT_NEAR(CGAL::to_double(b.x()) / scale, CGAL::to_double(a.x()), 1e-9 * (1 + std::fabs(CGAL::to_double(a.x()))));
        EXPECT_NEAR(CGAL::to_double(b.y()) / scale, CGAL::to_double(a.y()), 1e-9 * (1 + std::fabs(CGAL::to_double(a.y()))));
        const P c = c0.pieces()[i].point(FT(0.7)), d = c1.pieces()[i].point(FT(0.7));
        EXPECT_NEAR(CGAL::to_double(d.x()) / scale, CGAL::to_double(c.x()), 1e-9 * (1 + std::fabs(CGAL::to_double(c.x()))));
      }
    }
  }
}

TYPED_TEST(Classic_splines, SplineRejectsBadInput) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef typename K::Vector_2 V;
  typedef fair::Cubic_interpolating_spline_2<K> S;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(S({P(0, 0)}), fair::Invalid_input_error);
  EXPECT_THROW(S({P(0, 0), P(1, 0)}, periodic_options()), fair::Invalid_input_error);
  EXPECT_THROW(S({P(0, 0), P(1, 0), P(1, 0), P(2, 1)}), fair::Invalid_input_error);
  EXPECT_THROW(S({P(0, 0), P(1, 0), P(1, 1), P(0, 0)}, periodic_options()),
               fair::Invalid_input_error);
  EXPECT_THROW(S({P(0, 0), P(1, 0)}, spline_options(fair::Spline_end_condition::CLAMPED)), fair::Precondition_error);
  // The one rule for closed curves: periodic, the end condition ignored; no end derivatives.
  fair::Cubic_interpolating_spline_options closed_clamped = periodic_options();
  closed_clamped.end_condition = fair::Spline_end_condition::CLAMPED;
  EXPECT_TRUE(S({P(0, 0), P(1, 0), P(1, 1)}, closed_clamped).is_closed());
  EXPECT_THROW(S({P(0, 0), P(1, 0), P(1, 1)}, V(1, 0), V(0, 1), periodic_options()), fair::Precondition_error);
  if (!is_exact<K>()) {  // NaN and infinity exist only in the double kernels
    EXPECT_THROW(S({P(0, 0), P(nan, 1), P(2, 0)}), fair::Invalid_input_error);
    EXPECT_THROW(S({P(0, 0), P(1, inf), P(2, 0)}), fair::Invalid_input_error);
    EXPECT_THROW(S({P(0, 0), P(1, 1)}, V(nan, 0), V(1, 0)), fair::Invalid_input_error);
    // Finite but too large: the chord length overflows double, and so does 3 (p1 - p0).
    EXPECT_THROW(S({P(-1e308, 0), P(1e308, 0), P(1e308, 1)}, spline_options(fair::Spline_end_condition::NATURAL, fair::Knot_spacing::CHORDAL)),
                 fair::Invalid_input_error);
    EXPECT_THROW(S({P(-1e308, 0), P(1e308, 0), P(1e308, 1)}), fair::Invalid_input_error);
  }
  // The messages name the method and the offending index.
  try {
    S({P(0, 0), P(1, 0), P(1, 0)});
    FAIL() << "no throw";
  } catch (const fair::Invalid_input_error& e) {
    EXPECT_NE(std::string(e.what()).find("Cubic_interpolating_spline_2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("1 and 2"), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------------------------------------
// Catmull_rom_2

// Hand values: uniform Catmull-Rom through (0,0), (1,1), (2,0), (3,1).
// Piece 1: P1 = p1 + (p2 - p0)/6 = (4/3, 1), P2 = p2 - (p3 - p1)/6 = (5/3, 0).
// Quadratic end: m0 = (-3 p0 + 4 p1 - p2)/2 = (1, 2), so piece 0 has P1 = p0 + m0/3 = (1/3, 2/3).
TYPED_TEST(Classic_splines, CatmullRomByHand) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  fair::Catmull_rom_2<K> c({P(0, 0), P(1, 1), P(2, 0), P(3, 1)});
  ASSERT_EQ(c.pieces().size(), 3u);
  const auto cp1 = c.pieces()[1].control_points();
  EXPECT_TRUE(same<K>(cp1[1], P(FT(4) / 3, 1), 1e-11)) << "piece 1 P1";
  EXPECT_TRUE(same<K>(cp1[2], P(FT(5) / 3, 0), 1e-11)) << "piece 1 P2";
  EXPECT_TRUE(same<K>(c.pieces()[0].control_points()[1], P(FT(1) / 3, FT(2) / 3), 1e-11)) << "piece 0 P1";
  // C1 but not C2. Tangents m1 = (p2 - p0)/2 = (1,0), m2 = (p3 - p1)/2 = (1,0), and the quadratic
  // end m3 = (p1 - 4 p2 + 3 p3)/2 = (1,2). A unit-interval Hermite cubic has c''(1) =
  // 6 (p_a - p_b) + 2 m_a + 4 m_b and c''(0) = 6 (p_b - p_a) - 4 m_a - 2 m_b, so at p2:
  // left  = 6 (p1 - p2) + 2 m1 + 4 m2 = (-6,6) + (2,0) + (4,0) = (0,6),
  // right = 6 (p3 - p2) - 4 m2 - 2 m3 = (6,6) - (4,0) - (2,4) = (0,2).
  EXPECT_TRUE(same<K>(c.pieces()[1].second_derivative(FT(1)), typename K::Vector_2(0, 6), 1e-11)) << "left c'' at p2";
  EXPECT_TRUE(same<K>(c.pieces()[2].second_derivative(FT(0)), typename K::Vector_2(0, 2), 1e-11)) << "right c'' at p2";
  check_interpolation_and_continuity<K>(c, 1);
}

// Samples of a quadratic at the (uniform) knots are reproduced, end pieces included.
TYPED_TEST(Classic_splines, CatmullRomReproducesQuadraticsButNotCubics) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  auto q = [](const FT& u) { return P(u * u - u, 3 - FT(2) / 3 * u * u + u / 5); };
  std::vector<P> p;
  for (int i = 0; i <= 5; ++i) p.push_back(q(FT(i)));
  fair::Catmull_rom_2<K> c(p);
  for (std::size_t i = 0; i < c.pieces().size(); ++i)
    for (int k = 0; k <= 3; ++k)
      EXPECT_TRUE(same<K>(c.pieces()[i].point(FT(k) / 3), q(FT(static_cast<int>(i)) + FT(k) / 3), 1e-11)) << "quadratic";
  // Cubic data: m_i = q'(i) + q'''/6 (see Catmull_rom_2.h), so interior derivatives are off by 1.
  std::vector<P> cubic;
  for (int i = 0; i <= 5; ++i) cubic.push_back(P(FT(i * i * i), FT(i)));
  fair::Catmull_rom_2<K> cc(cubic);
  EXPECT_TRUE(same<K>(cc.derivatives()[2], typename K::Vector_2(3 * 4 + 1, 1), 1e-11)) << "q'(2) + q'''/6";
}

// Chordal knots on collinear points with chord lengths 5, 10, 5 (3-4-5 triangles: exact in
// double): the data are linear in the chord-length parameter, so the curve is the polyline
// traversed at unit speed -- exactly, in an exact kernel.
TYPED_TEST(Classic_splines, CatmullRomChordalOnCollinearData) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  const std::vector<P> p = {P(0, 0), P(3, 4), P(9, 12), P(12, 16)};
  fair::Catmull_rom_2<K> c(p, cr_options(false, fair::Knot_spacing::CHORDAL));
  EXPECT_TRUE(same<K>(c.knots()[2], FT(15), 1e-11)) << "knot u_2";
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(same<K>(c.derivatives()[i], typename K::Vector_2(FT(3) / 5, FT(4) / 5), 1e-11)) << "unit tangent";
    const P mid = c.pieces()[i].point(FT(1) / 4);
    EXPECT_TRUE(same<K>(mid, p[i] + (p[i + 1] - p[i]) / 4, 1e-11)) << "unit speed";
  }
  // Centripetal knots are sqrt(5), sqrt(10), sqrt(5): not representable, but C1 in u holds.
  fair::Catmull_rom_2<K> cc(p, cr_options(false, fair::Knot_spacing::CENTRIPETAL));
  check_interpolation_and_continuity<K>(cc, 1);
}

TYPED_TEST(Classic_splines, CatmullRomRandomOpenClosedAndAuxiliaryPoints) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  std::mt19937 rng(7);
  const int trials = is_exact<K>() ? 3 : 40;
  for (int trial = 0; trial < trials; ++trial) {
    const std::size_t n = 3 + static_cast<std::size_t>(trial % 8);
    const auto p = random_points<K>(rng, n);
    for (fair::Knot_spacing sp : all_spacings) {
      check_interpolation_and_continuity<K>(fair::Catmull_rom_2<K>(p, cr_options(false, sp)), 1);
      check_interpolation_and_continuity<K>(fair::Catmull_rom_2<K>(p, cr_options(true, sp)), 1);
    }
  }
  // Auxiliary points p_{-1} = p_0, p_{n+1} = p_n (Li et al., Fig. 1) with uniform knots:
  // eq. (4) with alpha = 1/2 gives m_0 = (p_1 - p_0)/2 and m_n = (p_n - p_{n-1})/2.
  const std::vector<P> p = {P(35, 47), P(16, 40), P(15, 15), P(25, 36), P(40, 15)};
  fair::Catmull_rom_2<K> c(p, p.front(), p.back());
  EXPECT_TRUE(same<K>(c.derivatives().front(), (p[1] - p[0]) / 2, 1e-11)) << "m0";
  EXPECT_TRUE(same<K>(c.derivatives().back(), (p[4] - p[3]) / 2, 1e-11)) << "mn";
  EXPECT_TRUE(same<K>(c.derivatives()[2], (p[3] - p[1]) / 2, 1e-11)) << "m2";
  check_interpolation_and_continuity<K>(c, 1);
  // Non-uniform knots need distinct auxiliary points.
  EXPECT_THROW(fair::Catmull_rom_2<K>(p, p.front(), p.back(), cr_options(false, fair::Knot_spacing::CHORDAL)),
               fair::Invalid_input_error);
  // Two points: the straight segment.
  fair::Catmull_rom_2<K> seg({P(1, 2), P(4, 8)});
  EXPECT_TRUE(same<K>(seg.pieces()[0].point(FT(1) / 3), P(2, 4), 1e-11)) << "segment";
}

// Independent check of the non-uniform tangent formula: the Barry-Goldman pyramid (three linear
// interpolations, two of those, one of those) evaluated in double on knots t0..t3 must give the
// same point as our Hermite piece, for centripetal and chordal knots on random data.
TEST(Classic_catmull_rom, NonUniformPiecesMatchTheBarryGoldmanPyramid) {
  typedef SC_double K;
  typedef K::Point_2 P;
  auto lerp = [](const P& a, double ta, const P& b, double tb, double t) {
    const double s = (t - ta) / (tb - ta);
    return P((1 - s) * a.x() + s * b.x(), (1 - s) * a.y() + s * b.y());
  };
  std::mt19937 rng(41);
  for (int trial = 0; trial < 50; ++trial) {
    const auto p = random_points<K>(rng, 7);
    for (fair::Knot_spacing sp : {fair::Knot_spacing::CENTRIPETAL, fair::Knot_spacing::CHORDAL}) {
      fair::Catmull_rom_2<K> c(p, cr_options(false, sp));
      const auto& u = c.knots();
      for (std::size_t i = 1; i + 2 < p.size(); ++i) {  // interior pieces: p_{i-1}..p_{i+2} exist
        const double t0 = u[i - 1], t1 = u[i], t2 = u[i + 1], t3 = u[i + 2];
        for (double s : {0.2, 0.5, 0.9}) {
          const double t = t1 + s * (t2 - t1);
          const P a1 = lerp(p[i - 1], t0, p[i], t1, t), a2 = lerp(p[i], t1, p[i + 1], t2, t),
                  a3 = lerp(p[i + 1], t2, p[i + 2], t3, t);
          const P b1 = lerp(a1, t0, a2, t2, t), b2 = lerp(a2, t1, a3, t3, t);
          const P bg = lerp(b1, t1, b2, t2, t);
          const P ours = c.pieces()[i].point(s);
          EXPECT_NEAR(ours.x(), bg.x(), 1e-9 * (1 + std::fabs(bg.x())));
          EXPECT_NEAR(ours.y(), bg.y(), 1e-9 * (1 + std::fabs(bg.y())));
        }
      }
    }
  }
}

TYPED_TEST(Classic_splines, CatmullRomRejectsBadInput) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef fair::Catmull_rom_2<K> C;
  EXPECT_THROW(C({P(0, 0)}), fair::Invalid_input_error);
  EXPECT_THROW(C({P(0, 0), P(1, 0)}, cr_options(true)), fair::Invalid_input_error);
  EXPECT_THROW(C({P(0, 0), P(1, 0), P(2, 1)}, P(-1, 0), P(3, 1), cr_options(true)), fair::Precondition_error);  // no auxiliary points when closed
  EXPECT_THROW(C({P(0, 0), P(1, 0), P(1, 0)}, cr_options(false, fair::Knot_spacing::CHORDAL)), fair::Invalid_input_error);
  EXPECT_THROW(C({P(0, 0), P(1, 0), P(1, 0)}), fair::Invalid_input_error);
  if (!is_exact<K>()) {
    EXPECT_THROW(C({P(0, 0), P(std::nan(""), 0), P(2, 0)}), fair::Invalid_input_error);
    EXPECT_THROW(C({P(0, 0), P(1, 0), P(2, -std::numeric_limits<double>::infinity())}), fair::Invalid_input_error);
    EXPECT_THROW(C({P(0, 0), P(1, 0)}, P(std::nan(""), 0), P(2, 0)), fair::Invalid_input_error);
  }
}

// ---------------------------------------------------------------------------------------------
// The solvers, checked through the residual A x - d (exactly zero in Gmpq).

TEST(Classic_tridiagonal, ThomasAndShermanMorrisonSolveExactlyInGmpq) {
  typedef CGAL::Gmpq Q;
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> d(-9, 9);
  for (std::size_t n : {1u, 2u, 3u, 4u, 7u, 20u}) {
    std::vector<Q> a(n), b(n), c(n), r(n);
    for (std::size_t i = 0; i < n; ++i) {
      a[i] = Q(d(rng), 4);
      c[i] = Q(d(rng), 3);
      b[i] = Q(20 + d(rng), 1);  // strictly diagonally dominant
      r[i] = Q(d(rng), 7);
    }
    const std::vector<Q> x = fair::internal::classic::solve_tridiagonal(a, b, c, r);
    for (std::size_t i = 0; i < n; ++i) {
      Q lhs = b[i] * x[i];
      if (i > 0) lhs += a[i] * x[i - 1];
      if (i + 1 < n) lhs += c[i] * x[i + 1];
      EXPECT_EQ(lhs, r[i]) << "tridiagonal row " << i << " of " << n;
    }
    if (n < 3) {
      EXPECT_THROW(fair::internal::classic::solve_cyclic_tridiagonal(a, b, c, r), fair::Precondition_error);
      continue;
    }
    const std::vector<Q> y = fair::internal::classic::solve_cyclic_tridiagonal(a, b, c, r);
    for (std::size_t i = 0; i < n; ++i) {
      const Q lhs = a[i] * y[(i + n - 1) % n] + b[i] * y[i] + c[i] * y[(i + 1) % n];
      EXPECT_EQ(lhs, r[i]) << "cyclic row " << i << " of " << n;
    }
  }
}

TEST(Classic_tridiagonal, LargeDoubleSystemHasSmallResidualAndZeroPivotThrows) {
  const std::size_t n = 100000;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-1, 1);
  std::vector<double> a(n), b(n), c(n), r(n);
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = d(rng);
    c[i] = d(rng);
    b[i] = 2.5 + d(rng);
    r[i] = d(rng);
  }
  const auto y = fair::internal::classic::solve_cyclic_tridiagonal(a, b, c, r);
  double worst = 0;
  for (std::size_t i = 0; i < n; ++i)
    worst = std::max(worst, std::fabs(a[i] * y[(i + n - 1) % n] + b[i] * y[i] + c[i] * y[(i + 1) % n] - r[i]));
  EXPECT_LT(worst, 1e-13);
  EXPECT_THROW(fair::internal::classic::solve_tridiagonal<double>({0, 1}, {1, 1}, {1, 0}, {1, 1}), fair::Precondition_error);
  EXPECT_THROW(fair::internal::classic::solve_tridiagonal<double>({0}, {1, 2}, {0}, {1}), fair::Precondition_error);
}

} // namespace
