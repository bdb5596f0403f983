// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of fair::Cardinal_spline_2 and of the curvature-variation optimum of J. Li,
// "Curvature variation minimizing Cardinal spline curves" (eqs. 1-20, Tables 1-2).

#include <fair/Cardinal_spline_2.h>
#include <fair/Fairness_metrics.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace fair_test;

template <class K>
std::vector<typename K::Point_2> data_set_1() { // Li, Section 2 / Figures 1-3
  const int px[] = {35, 16, 15, 25, 40, 65, 50, 60, 80}, py[] = {47, 40, 15, 36, 15, 25, 40, 42, 37};
  std::vector<typename K::Point_2> p;
  for (int i = 0; i < 9; ++i) p.emplace_back(px[i], py[i]);
  return p;
}

template <class K>
std::vector<typename K::Point_2> half_circle() { // Li, Section 4, second example
  std::vector<typename K::Point_2> p;
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= 4; ++i) p.emplace_back(std::cos(pi / 4 * i), std::sin(pi / 4 * i));
  return p;
}

template <class K>
double d(const typename K::FT& x) {
  return CGAL::to_double(x);
}

fair::Cardinal_spline_options closed_options() {
  fair::Cardinal_spline_options o;
  o.closed = true;
  return o;
}

template <class K>
class Cardinal_typed : public ::testing::Test {};
TYPED_TEST_SUITE(Cardinal_typed, All_kernels);

// ----------------------------------------------------------------------------------- Table 1
TYPED_TEST(Cardinal_typed, PaperTable1) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const auto p = data_set_1<K>();
  const fair::Cardinal_parameters<K> o = fair::optimal_cardinal_parameters(p);
  // alpha* = 0.7509, p_{-1}* = (46.6047, 26.6438), p_9* = (83.2681, 31.6830) (Section 4).
  EXPECT_NEAR(d<K>(o.alpha), 0.7509, 5e-5);
  if (is_exact<K>()) {
    EXPECT_TRUE(o.alpha == FT(9192) / FT(12241)); // eq. 18 in exact arithmetic
  }
  EXPECT_NEAR(d<K>(o.aux_start.x()), 46.6047, 5e-5);
  EXPECT_NEAR(d<K>(o.aux_start.y()), 26.6438, 5e-5);
  EXPECT_NEAR(d<K>(o.aux_end.x()), 83.2681, 5e-5);
  EXPECT_NEAR(d<K>(o.aux_end.y()), 31.6830, 5e-5);
  // Table 1: 1.9964e5 for the optimum, 2.4081e5 for Catmull-Rom. The paper keeps the optimal
  // auxiliary points p_{-1}*, p_9* for its Catmull-Rom curve (with the Catmull-Rom curve's own optimal
  // auxiliary points, eqs. 19-20 at alpha = 1/2, the figure would be 2.27385e5).
  const fair::Cardinal_spline_2<K> best = fair::Cardinal_spline_2<K>(p);
  EXPECT_NEAR(d<K>(best.approximate_energy()) / 1.9964e5, 1.0, 5e-5);
  EXPECT_NEAR(d<K>(o.energy) / 1.9964e5, 1.0, 5e-5);
  const auto cr = fair::Cardinal_spline_2<K>(p, typename fair::Cardinal_spline_2<K>::FT(0.5), o.aux_start, o.aux_end);
  EXPECT_NEAR(d<K>(cr.approximate_energy()) / 2.4081e5, 1.0, 5e-5);
  const fair::Cardinal_spline_2<K> cr_own(p, FT(1) / FT(2));
  if (is_exact<K>()) {
    EXPECT_TRUE(cr_own.approximate_energy() == FT(227385));
  } else {
    EXPECT_NEAR(d<K>(cr_own.approximate_energy()), 227385.0, 1e-6);
  }
  if (is_exact<K>()) {
    // The energy at the optimum equals the full-curve sum (end segments contribute 0): exact identity.
    EXPECT_TRUE(best.approximate_energy() == o.energy);
    // It is 144 (S - M^2/D) over the interior sums.
    const auto s = fair::internal::cardinal::cardinal_interior_sums<FT>(p, false);
    EXPECT_TRUE(o.energy == FT(144) * (s.S() - s.M() * s.M() / s.D()));
  }
}

// ----------------------------------------------------------------------------------- Table 2
TYPED_TEST(Cardinal_typed, PaperTable2HalfCircle) {
  typedef TypeParam K;
  const auto p = half_circle<K>();
  const fair::Cardinal_parameters<K> o = fair::optimal_cardinal_parameters(p);
  // alpha* = 0.5858 = 2 - sqrt 2 = 1 / (1 + cos(pi/4)) (see doc/cardinal_splines.md).
  EXPECT_NEAR(d<K>(o.alpha), 2 - std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(d<K>(o.aux_start.x()), std::sqrt(0.5), 1e-14);
  EXPECT_NEAR(d<K>(o.aux_start.y()), -std::sqrt(0.5), 1e-14);
  EXPECT_NEAR(d<K>(o.aux_end.x()), -std::sqrt(0.5), 1e-14);
  EXPECT_NEAR(d<K>(o.aux_end.y()), -std::sqrt(0.5), 1e-14);
  // Energy ~ 0 (the paper's 1.8087e-7 comes from its 4-digit inputs); Catmull-Rom 7.2364.
  const auto best = fair::Cardinal_spline_2<K>(p);
  EXPECT_LT(std::fabs(d<K>(best.approximate_energy())), 1e-12);
  const auto cr = fair::Cardinal_spline_2<K>(p, typename fair::Cardinal_spline_2<K>::FT(0.5), o.aux_start, o.aux_end);
  EXPECT_NEAR(d<K>(cr.approximate_energy()), 7.2364, 5e-5);
}

// ------------------------------------------------------------------------ structural identities
TYPED_TEST(Cardinal_typed, InterpolatesAndIsC1AndMatchesBezierPieces) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const auto p = data_set_1<K>();
  const auto c = fair::Cardinal_spline_2<K>(p);
  ASSERT_EQ(c.number_of_pieces(), p.size() - 1);
  const auto pieces = c.pieces();
  const FT ts[] = {FT(0), FT(1) / FT(3), FT(1) / FT(2), FT(7) / FT(8), FT(1)};
  for (std::size_t i = 0; i < c.number_of_pieces(); ++i) {
    // eq. 3: r_i(0) = p_i, r_i(1) = p_{i+1} (with this class's numbering).
    if (is_exact<K>()) {
      EXPECT_TRUE(c.point(i, FT(0)) == p[i]);
      EXPECT_TRUE(c.point(i, FT(1)) == p[i + 1]);
    } else {
      EXPECT_NEAR(d<K>(c.point(i, FT(1)).x()), d<K>(p[i + 1].x()), 1e-12);
      EXPECT_NEAR(d<K>(c.point(i, FT(1)).y()), d<K>(p[i + 1].y()), 1e-12);
    }
    for (const FT& t : ts) {
      const auto a = c.point(i, t), b = pieces[i].point(t);
      const auto da = c.derivative(i, t), db = pieces[i].derivative(t);
      const auto sa = c.second_derivative(i, t), sb = pieces[i].second_derivative(t);
      if (is_exact<K>()) {
        EXPECT_TRUE(a == b);
        EXPECT_TRUE(da == db);
        EXPECT_TRUE(sa == sb);
        EXPECT_TRUE(c.third_derivative(i) == pieces[i].nth_derivative(t, 3));
      } else {
        EXPECT_NEAR(d<K>(a.x()), d<K>(b.x()), 1e-11);
        EXPECT_NEAR(d<K>(da.y()), d<K>(db.y()), 1e-10);
        EXPECT_NEAR(d<K>(sa.x()), d<K>(sb.x()), 1e-9);
      }
    }
    if (i + 1 < c.number_of_pieces() && is_exact<K>()) {
      // eq. 4: tangent alpha (p_{i+1} - p_{i-1}) at p_i from both sides: C1.
      EXPECT_TRUE(c.derivative(i, FT(1)) == c.derivative(i + 1, FT(0)));
      EXPECT_TRUE(c.derivative(i + 1, FT(0)) == c.alpha() * (p[i + 2] - p[i]));
    }
  }
  if (is_exact<K>()) {
    // At the optimum the two end segments are parabolic: r''' = 0 (eqs. 16-17).
    EXPECT_TRUE(c.third_derivative(0) == typename K::Vector_2(0, 0));
    EXPECT_TRUE(c.third_derivative(c.number_of_pieces() - 1) == typename K::Vector_2(0, 0));
    // eq. 10 equals the sum over segments of |r'''|^2 (eq. 9; r''' is constant on a segment).
    FT sum(0);
    for (std::size_t i = 0; i < c.number_of_pieces(); ++i) sum += c.third_derivative(i).squared_length();
    EXPECT_TRUE(sum == c.approximate_energy());
    // Global parameter.
    EXPECT_TRUE(c.point(FT(5) / FT(2)) == c.point(2, FT(1) / FT(2)));
    EXPECT_TRUE(c.point(FT(8)) == p.back());
    EXPECT_TRUE(c.tension() == FT(1) - FT(2) * c.alpha());
  }
  EXPECT_THROW(c.point(FT(9)), fair::Precondition_error);
  EXPECT_THROW(c.point(c.number_of_pieces(), FT(0)), fair::Precondition_error);
  EXPECT_EQ(c.points().size(), p.size());
  EXPECT_TRUE(c.points() == p);  // the input, without the auxiliary points
}

TYPED_TEST(Cardinal_typed, ClosedSquareIsExactCircleLike) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  // Regular N-gon on a circle, angle theta: alpha* = 1 / (1 + cos theta) and eq. 10 vanishes
  // (doc/cardinal_splines.md). Square: alpha* = 1 exactly.
  const std::vector<P> sq{P(1, 0), P(0, 1), P(-1, 0), P(0, -1)};
  const auto o = fair::optimal_cardinal_parameters(sq, true);
  EXPECT_TRUE(o.alpha == FT(1));
  EXPECT_TRUE(o.energy == FT(0));
  const auto c = fair::Cardinal_spline_2<K>(sq, closed_options());
  EXPECT_TRUE(c.is_closed());
  EXPECT_EQ(c.number_of_pieces(), 4u);
  EXPECT_TRUE(c.point(3, FT(1)) == sq[0]);
  EXPECT_TRUE(c.derivative(3, FT(1)) == c.derivative(0, FT(0)));
  EXPECT_TRUE(c.approximate_energy() == FT(0));
  EXPECT_THROW(c.aux_start(), fair::Precondition_error);
  // The closed optimum is the minimiser of the closed energy: a parabola in alpha.
  const FT a = o.alpha;
  const fair::Cardinal_spline_2<K> lo(sq, a - FT(1) / FT(64), closed_options()), hi(sq, a + FT(1) / FT(64), closed_options());
  EXPECT_TRUE(lo.approximate_energy() > c.approximate_energy());
  EXPECT_TRUE(hi.approximate_energy() > c.approximate_energy());
}

TYPED_TEST(Cardinal_typed, CollinearEvenlySpacedIsCatmullRom) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  // d_i = 4h and m_i = -h: eq. 18 gives alpha* = 1/2 exactly (the denominator does not vanish),
  // the auxiliary points continue the progression, and eq. 10 is 0.
  std::vector<P> p;
  for (int i = 0; i < 6; ++i) p.emplace_back(3 + 2 * i, -1 + i);
  const auto o = fair::optimal_cardinal_parameters(p);
  EXPECT_TRUE(o.alpha == FT(1) / FT(2));
  EXPECT_TRUE(o.aux_start == P(1, -2));
  EXPECT_TRUE(o.aux_end == P(15, 5));
  EXPECT_TRUE(o.energy == FT(0));
}

TYPED_TEST(Cardinal_typed, DegenerateOptimaAreTypedErrors) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  // Denominator of eq. 18 vanishes: p2 + p3 = p0 + p1.
  EXPECT_THROW(fair::optimal_cardinal_parameters(std::vector<P>{P(0, 0), P(1, 0), P(0, 1), P(1, -1)}),
               fair::Invalid_input_error);
  // Alternating closed data: every d_i = 0.
  EXPECT_THROW(fair::optimal_cardinal_parameters(std::vector<P>{P(0, 0), P(1, 0), P(0, 0), P(1, 0)}, true),
               fair::Invalid_input_error);
  // alpha* = 0 exactly (d.m = 0) and alpha* < 0 (data folding back).
  EXPECT_THROW(fair::optimal_cardinal_parameters(std::vector<P>{P(0, 0), P(1, 0), P(2, 0), P(-1, 1)}),
               fair::Invalid_input_error);
  EXPECT_THROW(fair::optimal_cardinal_parameters(std::vector<P>{P(-10, 0), P(1, 0), P(0, 0), P(5, 0)}),
               fair::Invalid_input_error);
  try {
    fair::optimal_cardinal_parameters(std::vector<P>{P(-10, 0), P(1, 0), P(0, 0), P(5, 0)});
    FAIL();
  } catch (const fair::Invalid_input_error& e) {
    EXPECT_NE(std::string(e.what()).find("alpha* = -0.1428"), std::string::npos) << e.what();
  }
}

TYPED_TEST(Cardinal_typed, BadInputIsRejected) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  const std::vector<P> three{P(0, 0), P(1, 0), P(1, 1)};
  EXPECT_THROW(fair::optimal_cardinal_parameters(three), fair::Invalid_input_error);   // open needs 4
  EXPECT_NO_THROW(fair::optimal_cardinal_parameters(three, true));                      // closed needs 3
  EXPECT_THROW(fair::optimal_cardinal_parameters(std::vector<P>{P(0, 0), P(1, 0)}, true), fair::Invalid_input_error);
  EXPECT_THROW(fair::optimal_cardinal_parameters(std::vector<P>{P(0, 0), P(1, 0), P(1, 0), P(2, 1)}),
               fair::Invalid_input_error);
  // Closed: the last point repeats the first.
  EXPECT_THROW(fair::optimal_cardinal_parameters(std::vector<P>{P(0, 0), P(1, 0), P(1, 1), P(0, 0)}, true),
               fair::Invalid_input_error);
  EXPECT_THROW(fair::Cardinal_spline_2<K>(std::vector<P>{P(0, 0)}, FT(1) / FT(2), P(0, 0), P(0, 0)),
               fair::Invalid_input_error);
  EXPECT_THROW(fair::Cardinal_spline_2<K>(three, FT(0), P(0, 0), P(0, 0)), fair::Precondition_error);
  EXPECT_THROW(fair::Cardinal_spline_2<K>(three, FT(-1), closed_options()), fair::Precondition_error);
  EXPECT_THROW(fair::cardinal_auxiliary_points(three, FT(0)), fair::Precondition_error);
  // Two points with explicit auxiliary points: one segment.
  const fair::Cardinal_spline_2<K> two(std::vector<P>{P(0, 0), P(1, 0)}, FT(1) / FT(2), P(-1, 1), P(2, 1));
  EXPECT_EQ(two.number_of_pieces(), 1u);
}

// ------------------------------------------------------------------------ random property tests
TYPED_TEST(Cardinal_typed, RandomOptimumIsTheMinimum) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  std::mt19937 rng(20260311);
  std::uniform_int_distribution<int> coord(-50, 50);
  int tested = 0;
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<P> p;
    const int n = 4 + trial % 5;
    for (int i = 0; i < n; ++i) p.emplace_back(coord(rng), coord(rng));
    fair::Cardinal_parameters<K> o;
    try {
      o = fair::optimal_cardinal_parameters(p);
    } catch (const fair::Invalid_input_error&) {
      continue; // duplicates or a fold-back optimum: covered by the degenerate tests
    }
    ++tested;
    const fair::Cardinal_spline_2<K> best(p, o.alpha, o.aux_start, o.aux_end);
    const FT E = best.approximate_energy();
    const FT tol = is_exact<K>() ? FT(0) : FT(1e-9) * (E + FT(1));
    // Perturbing alpha (with or without re-optimising the auxiliary points) or either auxiliary
    // point never lowers eq. 10.
    for (const FT& da : {FT(-1) / FT(16), FT(1) / FT(1024), FT(1) / FT(8)}) {
      const FT a = o.alpha + da;
      EXPECT_TRUE(fair::Cardinal_spline_2<K>(p, a, o.aux_start, o.aux_end).approximate_energy() + tol >= E);
      EXPECT_TRUE(fair::Cardinal_spline_2<K>(p, a).approximate_energy() + tol >= E);
    }
    const typename K::Vector_2 v(FT(1) / FT(4), FT(-3) / FT(8));
    EXPECT_TRUE(fair::Cardinal_spline_2<K>(p, o.alpha, o.aux_start + v, o.aux_end).approximate_energy() + tol >= E);
    EXPECT_TRUE(fair::Cardinal_spline_2<K>(p, o.alpha, o.aux_start, o.aux_end - v).approximate_energy() + tol >= E);
    // Similarity invariance of alpha*: translation and uniform scaling (exact in exact kernels).
    std::vector<P> q;
    for (const P& x : p) q.emplace_back(FT(3) * x.x() + FT(7), FT(3) * x.y() - FT(2));
    const auto oq = fair::optimal_cardinal_parameters(q);
    if (is_exact<K>()) {
      EXPECT_TRUE(oq.alpha == o.alpha);
    } else {
      EXPECT_NEAR(d<K>(oq.alpha), d<K>(o.alpha), 1e-13 * std::fabs(d<K>(o.alpha)));
    }
  }
  EXPECT_GE(tested, 8);
}

TEST(Cardinal, ClosedRegularPolygons) {
  for (int N : {5, 6, 8, 12}) {
    std::vector<SC_double::Point_2> p;
    const double pi = std::acos(-1.0), th = 2 * pi / N;
    for (int i = 0; i < N; ++i) p.emplace_back(2 * std::cos(th * i), 2 * std::sin(th * i));
    const auto o = fair::optimal_cardinal_parameters(p, true);
    EXPECT_NEAR(o.alpha, 1 / (1 + std::cos(th)), 1e-14) << N;
    EXPECT_NEAR(o.energy, 0.0, 1e-12) << N;
  }
}

TEST(Cardinal, HugeAndTinyCoordinates) {
  const auto base = fair::optimal_cardinal_parameters(data_set_1<SC_double>());
  for (double s : {1e100, 1e-100, 1e300, 1e-300, 3e-320}) {
    std::vector<SC_double::Point_2> p;
    for (const auto& x : data_set_1<SC_double>()) p.emplace_back(s * x.x(), s * x.y());
    if (s == 1e300) {
      // eq. 10 scales as s^2 and overflows double: refused, not returned as inf (doc/fuzzing.md).
      EXPECT_THROW(fair::optimal_cardinal_parameters(p), fair::Invalid_input_error);
      continue;
    }
    const auto o = fair::optimal_cardinal_parameters(p);
    EXPECT_NEAR(o.alpha, base.alpha, s < 1e-300 ? 1e-2 : 1e-14); // 3e-320 is subnormal: ~4 digits
    if (s >= 1e-300) {
      EXPECT_NEAR(o.aux_start.x() / s, base.aux_start.x(), 1e-11);
    }
    // eq. 10 scales as s^2: finite, 0 (1e-300), never NaN.
    EXPECT_FALSE(std::isnan(o.energy));
    if (s == 1e100 || s == 1e-100) {
      EXPECT_NEAR(o.energy / (s * s), base.energy, 1e-9 * base.energy);
    }
  }
}

TEST(Cardinal, NonFiniteInput) {
  typedef SC_double::Point_2 P;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(fair::optimal_cardinal_parameters(std::vector<P>{P(0, 0), P(nan, 0), P(1, 1), P(2, 0)}),
               fair::Invalid_input_error);
  EXPECT_THROW(fair::optimal_cardinal_parameters(std::vector<P>{P(0, 0), P(1, 0), P(1, inf), P(2, 0)}, true),
               fair::Invalid_input_error);
  EXPECT_THROW(fair::Cardinal_spline_2<SC_double>(std::vector<P>{P(0, 0), P(1, 0)}, 0.5, P(inf, 0), P(0, 0)),
               fair::Invalid_input_error);
  EXPECT_THROW(fair::Cardinal_spline_2<SC_double>(std::vector<P>{P(0, 0), P(1, 0), P(2, 1)}, nan, closed_options()),
               fair::Precondition_error);
}

// ------------------------------------------------------------------------ true energy (eq. 5)
TEST(Cardinal, TrueCurvatureVariation) {
  // The optimum of eq. 10 also has a lower true curvature variation than Catmull-Rom on both data
  // sets (eq. 5 per segment, and int (dkappa/ds)^2 ds).
  for (int set = 0; set < 2; ++set) {
    const auto p = set == 0 ? data_set_1<SC_double>() : half_circle<SC_double>();
    const auto o = fair::optimal_cardinal_parameters(p);
    const auto best = fair::Cardinal_spline_2<SC_double>(p);
    const auto cr = fair::Cardinal_spline_2<SC_double>(p, typename fair::Cardinal_spline_2<SC_double>::FT(0.5), o.aux_start, o.aux_end);
    for (auto m : {fair::Energy_measure::PARAMETER, fair::Energy_measure::ARC_LENGTH}) {
      const fair::Quadrature_estimate eb = fair::curvature_variation_energy(best.pieces(), m),
                                      ec = fair::curvature_variation_energy(cr.pieces(), m);
      EXPECT_LE(eb.error_bound, 1e-9 * eb.value + 1e-13);
      EXPECT_LT(eb.value, ec.value) << set;
    }
  }
  // A unit-speed-free check of the quadrature: a parabolic end segment y = x^2 has
  // kappa = 2 / (1 + 4x^2)^(3/2); for the segment of the collinear-free data below compare with the
  // closed form int (dkappa/ds)^2 ds computed by high-order Simpson on the closed form.
  typedef SC_double::Point_2 P;
  const fair::Bezier_2<SC_double> parabola(std::vector<P>{P(-1, 1), P(0, -1), P(1, 1)});
  const auto e = fair::curvature_variation_energy(std::vector<fair::Bezier_2<SC_double>>{parabola});
  // dkappa/ds = dkappa/dx / sqrt(1+4x^2) = -24x / (1+4x^2)^3; int over x in [-1,1] of
  // (dkappa/ds)^2 sqrt(1+4x^2) dx = int 576 x^2 (1+4x^2)^(-11/2) dx.
  double ref = 0;
  const int m = 200000;
  for (int k = 0; k <= m; ++k) {
    const double x = -1 + 2.0 * k / m, w = (k == 0 || k == m) ? 1 : (k % 2 ? 4 : 2);
    ref += w * 576 * x * x * std::pow(1 + 4 * x * x, -5.5);
  }
  ref *= (2.0 / m) / 3;
  EXPECT_NEAR(e.value, ref, 1e-9 * ref);
}

// ------------------------------------------------------------------------ the family contract
// The constructor is the optimum of optimal_cardinal_parameters (exactly in an exact kernel),
// with status OPTIMAL; options.alpha gives GIVEN_ALPHA with the auxiliary points optimal for it.
TYPED_TEST(Cardinal_typed, ReportIsTheOptimumOrTheGivenAlpha) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const auto p = data_set_1<K>();
  const fair::Cardinal_parameters<K> o = fair::optimal_cardinal_parameters(p);
  const fair::Cardinal_spline_2<K> c(p);
  EXPECT_EQ(c.status(), fair::Cardinal_spline_status::OPTIMAL);
  EXPECT_EQ(c.report().status, c.status());
  EXPECT_FALSE(c.is_closed());
  EXPECT_FALSE(c.options().alpha.has_value());
  EXPECT_TRUE(same<K>(c.report().alpha, o.alpha));
  EXPECT_TRUE(same<K>(c.report().aux_start, o.aux_start));
  EXPECT_TRUE(same<K>(c.report().aux_end, o.aux_end));
  EXPECT_TRUE(same<K>(c.report().energy, o.energy, 1e-9));
  EXPECT_TRUE(c.aux_start() == c.report().aux_start);
  EXPECT_EQ(c.number_of_pieces(), c.pieces().size());
  EXPECT_TRUE(c.piece(3).control_points() == c.pieces()[3].control_points());
  EXPECT_THROW(c.piece(c.number_of_pieces()), fair::Precondition_error);
  // options.alpha = 1/2: the Catmull-Rom spline with its own optimal auxiliary points (eqs. 16-17),
  // eq. 10 = 227385 (Table 1's note), the same curve as the expert constructor with FT(1/2).
  fair::Cardinal_spline_options half;
  half.alpha = 0.5;
  const fair::Cardinal_spline_2<K> cr(p, half), cr_ft(p, FT(1) / FT(2));
  EXPECT_EQ(cr.status(), fair::Cardinal_spline_status::GIVEN_ALPHA);
  EXPECT_TRUE(cr.report() == cr_ft.report());
  EXPECT_TRUE(cr.alpha() == FT(1) / FT(2));
  const std::pair<typename K::Point_2, typename K::Point_2> aux = fair::cardinal_auxiliary_points(p, FT(1) / FT(2));
  EXPECT_TRUE(cr.report().aux_start == aux.first);
  EXPECT_TRUE(cr.report().aux_end == aux.second);
  EXPECT_TRUE(same<K>(cr.report().energy, FT(227385), 1e-12));
  // Closed: the auxiliary members are the first and last point.
  const fair::Cardinal_spline_2<K> closed(p, closed_options());
  EXPECT_TRUE(closed.is_closed());
  EXPECT_EQ(closed.number_of_pieces(), p.size());
  EXPECT_TRUE(closed.report().aux_start == p.front());
  EXPECT_TRUE(closed.report().aux_end == p.back());
  // alpha given twice, auxiliary points for a closed curve, alpha <= 0 in the options.
  EXPECT_THROW(fair::Cardinal_spline_2<K>(p, FT(1) / FT(2), half), fair::Precondition_error);
  EXPECT_THROW(fair::Cardinal_spline_2<K>(p, FT(1) / FT(2), p[1], p[2], closed_options()), fair::Precondition_error);
  fair::Cardinal_spline_options bad;
  bad.alpha = -0.25;
  EXPECT_THROW(fair::Cardinal_spline_2<K>(p, bad), fair::Precondition_error);
}

// Eq. 18 without a positive optimum (D = 0; alpha* = 0; alpha* < 0; closed alternating data):
// the curve is Catmull-Rom (alpha = 1/2, the auxiliary points optimal for it), status NO_OPTIMUM,
// no throw; with throw_on_failure a Solve_error carrying that same report.
TYPED_TEST(Cardinal_typed, NoOptimumFallsBackToCatmullRomOrThrows) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  const std::vector<std::pair<std::vector<P>, bool>> cases = {
      {{P(0, 0), P(1, 0), P(0, 1), P(1, -1)}, false},   // D = 0
      {{P(0, 0), P(1, 0), P(2, 0), P(-1, 1)}, false},   // alpha* = 0
      {{P(-10, 0), P(1, 0), P(0, 0), P(5, 0)}, false},  // alpha* = -1/7
      {{P(0, 0), P(1, 0), P(0, 0), P(1, 0)}, true}};    // closed, alternating: every d_i = 0
  for (const auto& c : cases) {
    const std::vector<P>& p = c.first;
    fair::Cardinal_spline_options o;
    o.closed = c.second;
    const fair::Cardinal_spline_2<K> curve(p, o);
    EXPECT_EQ(curve.status(), fair::Cardinal_spline_status::NO_OPTIMUM) << curve.report();
    EXPECT_TRUE(curve.alpha() == FT(1) / FT(2));
    const fair::Cardinal_spline_2<K> catmull_rom(p, FT(1) / FT(2), o);
    EXPECT_TRUE(curve.report().aux_start == catmull_rom.report().aux_start);
    EXPECT_TRUE(curve.report().aux_end == catmull_rom.report().aux_end);
    EXPECT_TRUE(curve.report().energy == catmull_rom.report().energy);
    ASSERT_EQ(curve.number_of_pieces(), catmull_rom.number_of_pieces());
    for (std::size_t i = 0; i < curve.number_of_pieces(); ++i)
      EXPECT_TRUE(curve.pieces()[i].control_points() == catmull_rom.pieces()[i].control_points()) << i;
    o.throw_on_failure = true;
    try {
      const fair::Cardinal_spline_2<K> thrown(p, o);
      ADD_FAILURE() << "NO_OPTIMUM with throw_on_failure did not throw";
    } catch (const fair::Solve_error& e) {
      ASSERT_NE(e.report<fair::Cardinal_spline_report<K>>(), nullptr);
      EXPECT_TRUE(*e.report<fair::Cardinal_spline_report<K>>() == curve.report()) << e.what();
      EXPECT_NE(std::string(e.what()).find("no positive optimum"), std::string::npos) << e.what();
    }
  }
  // A given alpha never fails, even with throw_on_failure.
  fair::Cardinal_spline_options given;
  given.alpha = 0.75;
  given.throw_on_failure = true;
  EXPECT_EQ(fair::Cardinal_spline_2<K>(cases[0].first, given).status(), fair::Cardinal_spline_status::GIVEN_ALPHA);
}

TEST(Cardinal, ReportSpellingsAndPrinting) {
  EXPECT_STREQ(fair::to_string(fair::Cardinal_spline_status::OPTIMAL), "optimal");
  EXPECT_STREQ(fair::to_string(fair::Cardinal_spline_status::GIVEN_ALPHA), "given_alpha");
  EXPECT_STREQ(fair::to_string(fair::Cardinal_spline_status::NO_OPTIMUM), "no_optimum");
  const fair::Cardinal_spline_report<SC_double> empty;  // every member initialised
  EXPECT_EQ(empty.status, fair::Cardinal_spline_status::NO_OPTIMUM);
  EXPECT_EQ(empty.alpha, 0.5);
  EXPECT_EQ(empty.energy, 0.0);
  EXPECT_TRUE(empty.aux_start == SC_double::Point_2(0, 0));
  std::ostringstream out;
  const fair::Cardinal_spline_2<SC_double> square(
      std::vector<SC_double::Point_2>{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}, closed_options());
  out << square.report();
  EXPECT_EQ(out.str(), "Cardinal_spline_report{optimal, alpha 1, aux_start (1, 0), aux_end (0, -1), energy 0}");
}

} // namespace
