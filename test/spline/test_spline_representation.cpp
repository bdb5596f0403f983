// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The spline core's representation (issue 23 §4): Cubic_spline_2 stores breakpoints, control
// points and (rational only) weights, and computes the Bezier points of a piece on demand;
// Rational_bezier_2 stores control points and weights and evaluates by de Casteljau on demand.
// Oracles: de Casteljau on the control points of pieces() (an independent evaluation: the
// textbook triangle written here), the Bernstein derivative polynomials, and, for the periodic
// polygon fit and Li's alpha*, the earlier algorithms (Cubic_interpolating_spline_2, the two-pass
// scaled sums) on seeded random data.

#include "test_support.h"

#include <fair/Cardinal_spline_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/Polygon_spline_fit.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using fair_test::q;
using fair_test::same;

template <class K>
class Spline_representation : public ::testing::Test {};
TYPED_TEST_SUITE(Spline_representation, fair_test::All_kernels);

// Random data with dyadic values (exact in every kernel).
template <class K>
fair::Cubic_spline_2<K> random_dyadic_spline(std::mt19937& rng, std::size_t m, bool closed, bool rational) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  std::uniform_int_distribution<int> gap(1, 12), coordinate(-40, 40), weight(1, 9);
  std::vector<FT> t{q<K>(-3, 2)};
  for (std::size_t i = 0; i < m; ++i) t.push_back(t.back() + q<K>(gap(rng), 4));
  const std::size_t n = closed ? m : m + 3;
  std::vector<P> d;
  std::vector<FT> w;
  for (std::size_t i = 0; i < n; ++i) {
    d.push_back(P(q<K>(coordinate(rng), 8), q<K>(coordinate(rng), 8)));
    w.push_back(q<K>(weight(rng), 4));
  }
  if (rational) return fair::Cubic_spline_2<K>(t, d, w, closed);
  return fair::Cubic_spline_2<K>(t, d, closed);
}

// The de Casteljau triangle of the homogeneous control points (w P, w) at u: the oracle.
template <class K>
typename K::Point_2 de_casteljau(const fair::Rational_bezier_2<K>& piece, const typename K::FT& u) {
  typedef typename K::FT FT;
  std::vector<FT> x, y, w;
  for (std::size_t i = 0; i <= piece.degree(); ++i) {
    w.push_back(piece.weights()[i]);
    x.push_back(w.back() * piece.control_points()[i].x());
    y.push_back(w.back() * piece.control_points()[i].y());
  }
  for (std::size_t r = 1; r < x.size(); ++r)
    for (std::size_t i = 0; i + r < x.size(); ++i) {
      x[i] = (FT(1) - u) * x[i] + u * x[i + 1];
      y[i] = (FT(1) - u) * y[i] + u * y[i + 1];
      w[i] = (FT(1) - u) * w[i] + u * w[i + 1];
    }
  return typename K::Point_2(x[0] / w[0], y[0] / w[0]);
}

TYPED_TEST(Spline_representation, PointAgreesWithDeCasteljauOfPieces) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::mt19937 rng(2301);
  for (int trial = 0; trial < 12; ++trial) {
    const bool closed = trial % 2 == 1, rational = trial % 4 >= 2;
    const fair::Cubic_spline_2<K> s = random_dyadic_spline<K>(rng, 3 + static_cast<std::size_t>(trial), closed, rational);
    EXPECT_EQ(s.is_rational(), rational);
    const std::vector<typename fair::Cubic_spline_2<K>::Piece> pieces = s.pieces();
    ASSERT_EQ(pieces.size(), s.number_of_pieces());
    const std::vector<FT>& t = s.breakpoints();
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (!rational) {
        EXPECT_TRUE(pieces[i].is_polynomial());
      }
      for (int k = 0; k <= 4; ++k) {
        const FT u = q<K>(k, 4), x = t[i] + u * (t[i + 1] - t[i]);
        // at a breakpoint point() takes the piece on the right: compare with it
        if (k == 4 && i + 1 < pieces.size()) continue;
        EXPECT_TRUE(same<K>(s.point(x), de_casteljau<K>(pieces[i], u), 1e-13)) << trial << " " << i << " " << k;
        EXPECT_TRUE(same<K>(s.point(x), pieces[i].point(u), 1e-13)) << trial << " " << i << " " << k;
        // d/dt = (d/du) / h
        const typename K::Vector_2 d = pieces[i].derivative(u), e = pieces[i].second_derivative(u);
        const FT h = t[i + 1] - t[i];
        EXPECT_TRUE(same<K>(s.derivative(x), d / h, 1e-11)) << trial << " " << i << " " << k;
        EXPECT_TRUE(same<K>(s.second_derivative(x), e / (h * h), 1e-10)) << trial << " " << i << " " << k;
      }
      if (!rational) {
        EXPECT_EQ(s.polynomial_piece(i).control_points(), pieces[i].control_points());
      }
    }
  }
}

TYPED_TEST(Spline_representation, WeightsAreNotStoredForAPolynomialSpline) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::mt19937 rng(2302);
  const fair::Cubic_spline_2<K> p = random_dyadic_spline<K>(rng, 5, false, false);
  EXPECT_FALSE(p.is_rational());
  EXPECT_EQ(p.weights(), std::vector<FT>(p.number_of_control_points(), FT(1)));
  EXPECT_EQ(p.weight(3), FT(1));
  EXPECT_THROW(p.weight(p.number_of_control_points()), fair::Precondition_error);
  // equal weights: the same curve, polynomial form, bit for bit the same pieces
  const fair::Cubic_spline_2<K> e(p.breakpoints(), p.control_points(),
                                  std::vector<FT>(p.number_of_control_points(), q<K>(7, 4)));
  EXPECT_FALSE(e.is_rational());
  EXPECT_EQ(e.weight(0), FT(1));
  for (std::size_t i = 0; i < p.number_of_pieces(); ++i)
    EXPECT_EQ(e.piece(i).control_points(), p.piece(i).control_points()) << i;
  const fair::Cubic_spline_2<K> r = random_dyadic_spline<K>(rng, 5, true, true);
  EXPECT_TRUE(r.is_rational());
  EXPECT_EQ(r.knot_vector_weights().size(), r.knot_vector_control_points().size());
  // a weight count that does not match
  EXPECT_THROW(fair::Cubic_spline_2<K>(p.breakpoints(), p.control_points(), std::vector<FT>(2, FT(1))),
               fair::Precondition_error);
}

TYPED_TEST(Spline_representation, KnotInsertionKeepsTheRepresentation) {
  typedef TypeParam K;
  std::mt19937 rng(2303);
  for (int trial = 0; trial < 4; ++trial) {
    const bool closed = trial % 2 == 1, rational = trial >= 2;
    const fair::Cubic_spline_2<K> s = random_dyadic_spline<K>(rng, 6, closed, rational);
    const typename K::FT x = (s.breakpoints()[2] + s.breakpoints()[3]) / 2;
    const fair::Cubic_spline_2<K> r = s.with_knot_inserted(x);
    EXPECT_EQ(r.is_rational(), rational);
    for (int k = 0; k <= 8; ++k) {
      const typename K::FT y = s.breakpoints().front() + (s.breakpoints().back() - s.breakpoints().front()) * q<K>(k, 8);
      EXPECT_TRUE(same<K>(r.point(y), s.point(y), 1e-12)) << trial << " " << k;
    }
  }
}

TYPED_TEST(Spline_representation, RationalPieceEvaluatesItsBernsteinForms) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  const fair::Rational_bezier_2<K> c({P(0, 0), P(1, 2), P(3, 3), P(4, q<K>(1, 2)), P(5, 1)},
                                     {FT(1), q<K>(3, 2), q<K>(1, 4), FT(2), q<K>(5, 4)});
  const fair::Bernstein_polynomial<FT> X = c.homogeneous_x(), Y = c.homogeneous_y(), W = c.homogeneous_w();
  EXPECT_EQ(X.degree(), 4u);
  EXPECT_EQ(W.coefficients(), c.weights());
  for (int k = 0; k <= 6; ++k) {
    const FT u = q<K>(k, 6);
    const FT w = W.evaluate(u), w1 = W.derivative().evaluate(u), w2 = W.derivative().derivative().evaluate(u);
    const FT cx = X.evaluate(u) / w, cy = Y.evaluate(u) / w;
    EXPECT_TRUE(same<K>(c.point(u), P(cx, cy), 1e-15)) << k;
    const FT dx = (X.derivative().evaluate(u) - w1 * cx) / w, dy = (Y.derivative().evaluate(u) - w1 * cy) / w;
    EXPECT_TRUE(same<K>(c.derivative(u), typename K::Vector_2(dx, dy), 1e-14)) << k;
    const FT ex = (X.derivative().derivative().evaluate(u) - FT(2) * w1 * dx - w2 * cx) / w;
    const FT ey = (Y.derivative().derivative().evaluate(u) - FT(2) * w1 * dy - w2 * cy) / w;
    EXPECT_TRUE(same<K>(c.second_derivative(u), typename K::Vector_2(ex, ey), 1e-13)) << k;
  }
  // degree 0 and 1: the derivatives of low degree vanish
  const fair::Rational_bezier_2<K> point({P(2, 3)}, {FT(2)});
  EXPECT_EQ(point.derivative(q<K>(1, 3)), typename K::Vector_2(0, 0));
  const fair::Rational_bezier_2<K> segment({P(0, 0), P(2, 4)});
  EXPECT_EQ(segment.second_derivative(q<K>(1, 3)), typename K::Vector_2(0, 0));
  EXPECT_TRUE(same<K>(segment.derivative(q<K>(1, 3)), typename K::Vector_2(2, 4)));
  // a degree above the inline buffer (8 coefficients)
  std::vector<P> many;
  for (int i = 0; i < 11; ++i) many.push_back(P(i, (i * i) % 7));
  const fair::Rational_bezier_2<K> high(many);
  EXPECT_TRUE(same<K>(high.point(q<K>(1, 3)), de_casteljau<K>(high, q<K>(1, 3)), 1e-14));
}

TYPED_TEST(Spline_representation, FiniteBezierPiecesCheck) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  std::mt19937 rng(2304);
  EXPECT_NO_THROW(random_dyadic_spline<K>(rng, 7, false, false).check_finite_pieces("test"));
  EXPECT_NO_THROW(random_dyadic_spline<K>(rng, 7, true, false).check_finite_pieces("test"));
  // Coordinates of both signs near DBL_MAX / 20 (accepted by the constructor) give second
  // differences 6 (b0 - 2 b1 + b2) beyond DBL_MAX.
  const double big = std::numeric_limits<double>::max() / 20;
  const fair::Cubic_spline_2<K> s({FT(0), FT(1)}, {P(big, 0), P(-big, 0), P(big, 0), P(-big, 0)});
  if (!fair_test::is_exact<K>()) { // (exact pieces are exact; their doubles are the number type's business)
    const std::string m = fair_test::invalid_input_message([&] { s.check_finite_pieces("test"); });
    EXPECT_NE(m.find("derivatives are not finite"), std::string::npos) << m;
  }
}

template <class K>
class Spline_representation_floating : public ::testing::Test {};
TYPED_TEST_SUITE(Spline_representation_floating, fair_test::Floating_kernels);

// The periodic fit solved for its control points is the periodic interpolant of
// Cubic_interpolating_spline_2 (the same unique spline), and interpolates every vertex.
TYPED_TEST(Spline_representation_floating, PeriodicFitIsThePeriodicInterpolant) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  std::mt19937 rng(2305);
  std::uniform_real_distribution<double> radius(0.7, 1.3), jitter(0.2, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<P> p;
    double a = 0;
    const std::size_t n = 5 + 7 * static_cast<std::size_t>(trial);
    for (std::size_t i = 0; i < n; ++i) {
      a += jitter(rng) * 2 * M_PI / static_cast<double>(n) / 0.6;
      const double r = radius(rng);
      p.push_back(P(r * std::cos(a), r * std::sin(a)));
    }
    const fair::Polygon_spline_fit<K> fit = fair::fit_cubic_spline<K>(p, true);
    fair::Cubic_interpolating_spline_options periodic;
    periodic.closed = true;
    periodic.knot_spacing = fair::Knot_spacing::CHORDAL;
    const fair::Cubic_interpolating_spline_2<K> classic(p, periodic);
    ASSERT_EQ(fit.spline.number_of_control_points(), classic.spline().number_of_control_points());
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_TRUE(same<K>(fit.spline.control_points()[i], classic.spline().control_points()[i], 1e-12)) << trial;
      EXPECT_TRUE(same<K>(fit.spline.point(fit.spline.breakpoints()[i]), p[i], 1e-13)) << trial << " " << i;
    }
    EXPECT_GT(fit.max_distance, 0);
  }
  // An edge far longer than its neighbours: the rows are not diagonally dominant, the Hermite
  // form is used; the result is still the interpolant.
  const std::vector<P> lopsided{P(0, 0), P(100, 0), P(100.5, 0.5), P(100, 1), P(0, 1), P(-0.5, 0.5)};
  const fair::Polygon_spline_fit<K> fit = fair::fit_cubic_spline<K>(lopsided, true);
  for (std::size_t i = 0; i < lopsided.size(); ++i)
    EXPECT_TRUE(same<K>(fit.spline.point(fit.spline.breakpoints()[i]), lopsided[i], 1e-12)) << i;
}

// The closed-form chord distance of a cubic piece against the sampled search it replaces.
TYPED_TEST(Spline_representation_floating, ChordDistanceClosedForm) {
  std::mt19937 rng(2306);
  std::uniform_real_distribution<double> c(-1, 1);
  typedef fair::internal::optimal::Vec2 V;
  int closed_form = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const std::array<V, 4> b{{V{{0, 0}}, V{{0.3 + 0.2 * c(rng), 0.5 * c(rng)}}, V{{0.7 + 0.2 * c(rng), 0.5 * c(rng)}},
                              V{{1, 0.1 * c(rng)}}}};
    const double d = fair::internal::optimal::cubic_chord_distance_closed_form(b);
    if (d < 0) continue;
    ++closed_form;
    // brute force: 20001 samples of the distance to the segment
    double best = 0;
    for (int k = 0; k <= 20000; ++k)
      best = std::max(best, fair::internal::optimal::distance_to_segment(
                                fair::internal::optimal::bezier_point(b, k / 20000.0), b[0], b[3]));
    EXPECT_GE(d, best - 1e-15) << trial;
    EXPECT_LE(d, best + 1e-8) << trial;  // the samples miss the maximum by O(step^2)
  }
  EXPECT_GT(closed_form, 1500);
  // a piece that overshoots the chord's end: not in closed form
  EXPECT_LT(fair::internal::optimal::cubic_chord_distance_closed_form(
                std::array<V, 4>{{V{{0, 0}}, V{{-1, 1}}, V{{2, 1}}, V{{1, 0}}}}),
            0);
}

// One pass over the points gives the two-pass scaled sums, bit for bit, and the checks' errors.
TYPED_TEST(Spline_representation_floating, CardinalSumsInOnePass) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  std::mt19937 rng(2307);
  std::uniform_real_distribution<double> c(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    const double scale = std::ldexp(1.0, 40 * (trial % 5) - 80);
    std::vector<P> p;
    for (int i = 0; i < 50 + trial; ++i) p.push_back(P(scale * (3 + c(rng)), scale * c(rng)));
    for (bool closed : {false, true}) {
      const auto one = fair::internal::cardinal::checked_cardinal_interior_sums<double>(p, 3, closed, "test");
      const auto two = fair::internal::cardinal::cardinal_interior_sums_scaled<double>(p, closed);
      EXPECT_EQ(one.D(), two.D()) << trial << closed;
      EXPECT_EQ(one.M(), two.M()) << trial << closed;
      EXPECT_EQ(one.S(), two.S()) << trial << closed;
      EXPECT_EQ(one.energy(0.3), two.energy(0.3)) << trial << closed;
    }
  }
  // extreme extents take the scaled path and agree as well
  std::vector<P> tiny{P(0, 0), P(1e-300, 2e-300), P(3e-300, 2e-300), P(4e-300, 0), P(5e-300, 1e-300)};
  EXPECT_EQ(fair::internal::cardinal::checked_cardinal_interior_sums<double>(tiny, 4, false, "test").M(),
            fair::internal::cardinal::cardinal_interior_sums_scaled<double>(tiny, false).M());
  // the checks' errors, naming the point
  std::vector<P> bad{P(0, 0), P(1, 0), P(2, std::numeric_limits<double>::quiet_NaN()), P(3, 1)};
  std::string m = fair_test::invalid_input_message([&] { fair::optimal_cardinal_parameters(bad); });
  EXPECT_NE(m.find("point 2"), std::string::npos) << m;
  std::vector<P> twice{P(0, 0), P(1, 0), P(1, 0), P(3, 1), P(4, 0)};
  m = fair_test::invalid_input_message([&] { fair::optimal_cardinal_parameters(twice); });
  EXPECT_NE(m.find("1 and 2"), std::string::npos) << m;
  std::vector<P> closing{P(0, 0), P(1, 0), P(2, 1), P(0, 0)};
  m = fair_test::invalid_input_message([&] { fair::optimal_cardinal_parameters(closing, true); });
  EXPECT_NE(m.find("3 and 0"), std::string::npos) << m;
}

} // namespace
