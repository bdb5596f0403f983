// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Proposition 1 (spline_convexity): exact polygon convexity (collinear runs, reversals, double
// winding), convex and non-convex joins of two conic arcs (at their end points and by an edge),
// the proposition's implication on seeded random convex polygons (open and closed, rational),
// singular curves (cusp, reversal, coincident Bezier points at a join) never locally convex,
// a counterexample with a non-convex polygon, the filter / exact split. Quadratic design
// (eq. 12): m_i^L and m_i^R against the Lagrange interpolant, parabola reproduction, reversal
// symmetry, and the chain spline's exact reproduction of its shapes.

#include "test_support.h"

#include <fair/Exact_spline_conversion.h>
#include <fair/Quadratic_design.h>
#include <fair/Spline_convexity.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace {

using fair_test::q;
using fair_test::same;

using fair_test::Exact_kernels;

template <class K>
class Convexity : public ::testing::Test {};
TYPED_TEST_SUITE(Convexity, fair_test::All_kernels);
template <class K>
class Convexity_exact : public ::testing::Test {};
TYPED_TEST_SUITE(Convexity_exact, Exact_kernels);
template <class K>
class Design : public ::testing::Test {};
TYPED_TEST_SUITE(Design, fair_test::All_kernels);
template <class K>
class Design_exact : public ::testing::Test {};
TYPED_TEST_SUITE(Design_exact, Exact_kernels);

template <class K>
fair::internal::exact_conversion::Polygon_convexity polygon(const std::vector<std::vector<int>>& xy, bool closed) {
  std::vector<typename K::Point_2> p;
  for (const std::vector<int>& v : xy) p.push_back(typename K::Point_2(v[0], v[1]));
  return fair::internal::exact_conversion::polygon_convexity<K>(p, closed);
}

TYPED_TEST(Convexity, PolygonConvexityIsExact) {
  typedef TypeParam K;
  EXPECT_TRUE(polygon<K>({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, true).convex);
  EXPECT_EQ(polygon<K>({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, true).orientation, CGAL::LEFT_TURN);
  EXPECT_EQ(polygon<K>({{0, 2}, {2, 2}, {2, 0}, {0, 0}}, false).orientation, CGAL::RIGHT_TURN);
  // collinear runs and repeated points are allowed (Lemma 1)
  EXPECT_TRUE(polygon<K>({{0, 0}, {1, 0}, {2, 0}, {2, 0}, {2, 2}, {0, 2}}, true).convex);
  // an open polygon is closed by its closing edge
  EXPECT_TRUE(polygon<K>({{0, 0}, {4, 0}, {5, 2}, {4, 4}}, false).convex);
  // a reflex vertex, reported by index
  const fair::internal::exact_conversion::Polygon_convexity r = polygon<K>({{0, 0}, {4, 0}, {2, 1}, {4, 4}, {0, 4}}, true);
  EXPECT_FALSE(r.convex);
  EXPECT_EQ(r.violation, 2u);
  // a reversal (spike) on a line
  EXPECT_FALSE(polygon<K>({{0, 0}, {3, 0}, {1, 0}, {1, 2}}, true).convex);
  // the pentagram turns left at every vertex but winds twice
  const fair::internal::exact_conversion::Polygon_convexity star =
      polygon<K>({{0, 10}, {6, -8}, {-10, 3}, {10, 3}, {-6, -8}}, true);
  EXPECT_FALSE(star.convex);
  // all collinear: an open straight run is convex, a closed one reverses
  EXPECT_TRUE(polygon<K>({{0, 0}, {1, 1}, {3, 3}}, false).convex);
  EXPECT_FALSE(polygon<K>({{0, 0}, {1, 1}, {3, 3}}, true).convex);
  EXPECT_FALSE(polygon<K>({{0, 0}, {3, 3}, {1, 1}, {4, 4}}, false).convex);
}

// Unit-circle arc with quarter-angle tangents q0 < q1 about `center`, radius r.
template <class K>
fair::Rational_bezier_2<K> arc(const typename K::Point_2& center, const typename K::FT& r, const typename K::FT& q0,
                               const typename K::FT& q1) {
  return fair::rational_circle_arc_cubic<K>(center, r, q0, q1);
}

// Two circle arcs meeting at J = (-7/25, 24/25), the end of the unit arc (q from 0 to 1/2).
// Convex: continued by the radius-2 circle tangent to it from inside (centre -J), turning the
// same way. Non-convex: the radius-2 circle on the other side (centre 3 J), turning back.
TYPED_TEST(Convexity_exact, JoinsOfTwoConicArcs) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  const P O(0, 0), J(q<K>(-7, 25), q<K>(24, 25));
  const fair::Rational_bezier_2<K> a1 = arc<K>(O, 1, 0, q<K>(1, 2));
  const std::vector<FT> marks{q<K>(1, 5), q<K>(2, 5), q<K>(3, 5), q<K>(4, 5)};
  {
    const fair::Rational_bezier_2<K> a2 = arc<K>(P(-J.x(), -J.y()), 2, q<K>(1, 2), q<K>(3, 5));
    ASSERT_EQ(a2.source(), J);
    const fair::Cubic_spline_2<K> s = fair::bezier_chain_spline<K>({a1, a2}, marks);
    const fair::Spline_convexity_report<K> r = fair::spline_convexity(s);
    EXPECT_TRUE(r.polygon_convex) << r.polygon_violation;
    EXPECT_TRUE(r.curve_locally_convex);
    EXPECT_EQ(r.curve_orientation, CGAL::LEFT_TURN);
    EXPECT_EQ(r.pieces_by_filter + r.pieces_exact, s.number_of_pieces());
    EXPECT_TRUE(r.inflected_pieces.empty());
  }
  {
    // the same turn, joined by an edge of length 1 along the common tangent
    const FT tx = -J.y(), ty = J.x(); // unit tangent at J (counter-clockwise)
    const P E(J.x() + tx, J.y() + ty);
    const fair::Rational_bezier_2<K> edge(std::vector<P>{J, E});
    const fair::Rational_bezier_2<K> a2 = arc<K>(P(E.x() - FT(2) * J.x(), E.y() - FT(2) * J.y()), 2, q<K>(1, 2), q<K>(3, 5));
    ASSERT_EQ(a2.source(), E);
    const fair::Cubic_spline_2<K> s = fair::bezier_chain_spline<K>({a1, edge, a2}, marks);
    const fair::Spline_convexity_report<K> r = fair::spline_convexity(s);
    EXPECT_TRUE(r.polygon_convex) << r.polygon_violation;
    EXPECT_TRUE(r.curve_locally_convex);
    EXPECT_EQ(r.curve_orientation, CGAL::LEFT_TURN);
    EXPECT_NE(std::count(r.piece_signs.begin(), r.piece_signs.end(), 0), 0); // the straight pieces
  }
  {
    const fair::Rational_bezier_2<K> back = arc<K>(P(3 * J.x(), 3 * J.y()), 2, q<K>(5, 2), FT(3)).reversed(); // J is at q = 3 on it
    ASSERT_EQ(back.source(), J);
    const fair::Cubic_spline_2<K> s = fair::bezier_chain_spline<K>({a1, back}, marks);
    const fair::Spline_convexity_report<K> r = fair::spline_convexity(s);
    EXPECT_FALSE(r.polygon_convex);
    EXPECT_GE(r.polygon_violation, 6u); // at the join, not before
    EXPECT_FALSE(r.curve_locally_convex);
    // The curvature vanishes at the shared point (its two neighbours in the polygon lie on the
    // common tangent) and changes sign there: a piece turning left, a later one turning right.
    EXPECT_NE(std::count(r.piece_signs.begin(), r.piece_signs.end(), 1), 0);
    EXPECT_NE(std::count(r.piece_signs.begin(), r.piece_signs.end(), -1), 0);
    EXPECT_TRUE(r.proposition_holds());
  }
}

// Seeded random convex polygons: points on an ellipse in angular order (rational
// parametrisation, less than one turn), sometimes with a collinear midpoint, random breakpoints,
// random positive weights: Proposition 1 says the curve is locally convex.
TYPED_TEST(Convexity, PropositionOnRandomConvexPolygons) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> s(-40, 40), gap(1, 8), w(1, 9), coin(0, 3);
  for (int run = 0; run < 24; ++run) {
    const bool closed = run % 2 == 1, rational = run % 3 != 0;
    std::vector<int> ks;
    while (ks.size() < std::size_t(6 + run % 5)) {
      const int k = s(rng);
      if (std::find(ks.begin(), ks.end(), k) == ks.end()) ks.push_back(k);
    }
    std::sort(ks.begin(), ks.end());
    std::vector<P> p;
    for (int k : ks) {
      const FT t = q<K>(k, 8), d = FT(1) + t * t;
      const P next(FT(3) * (FT(1) - t * t) / d, FT(2) * FT(2) * t / d);
      // collinear midpoints only where they stay collinear (exact constructions)
      if (fair_test::is_exact<K>() && !p.empty() && coin(rng) == 0) p.push_back(CGAL::midpoint(p.back(), next));
      p.push_back(next);
    }
    const std::size_t m = closed ? p.size() : p.size() - 3;
    std::vector<FT> t{0};
    for (std::size_t i = 0; i < m; ++i) t.push_back(t.back() + q<K>(gap(rng), 4));
    std::vector<FT> weights;
    for (std::size_t i = 0; i < p.size(); ++i) weights.push_back(rational ? q<K>(w(rng), 3) : FT(1));
    const fair::Cubic_spline_2<K> sp(t, p, weights, closed);
    const fair::Spline_convexity_report<K> r = fair::spline_convexity(sp);
    if (fair_test::is_exact<K>()) {
      EXPECT_TRUE(r.polygon_convex) << "run " << run << " vertex " << r.polygon_violation;
    }
    if (r.polygon_convex) {
      EXPECT_TRUE(r.curve_locally_convex) << "run " << run;
      EXPECT_EQ(r.curve_orientation, r.polygon_orientation) << "run " << run;
    }
    EXPECT_TRUE(r.undecided_pieces.empty());
  }
}

// The implication needs the hypothesis: a zig-zag polygon gives an inflection (exactly
// certified), and a convex curve can still have a non-convex polygon (the converse fails).
TYPED_TEST(Convexity, CounterexamplesWithoutAConvexPolygon) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  const fair::Cubic_spline_2<K> zig(std::vector<FT>{0, 1, 3}, std::vector<P>{P(0, 0), P(1, 2), P(2, 0), P(3, 2), P(4, 0)});
  const fair::Spline_convexity_report<K> r = fair::spline_convexity(zig);
  EXPECT_FALSE(r.polygon_convex);
  EXPECT_EQ(r.polygon_violation, 2u);
  EXPECT_FALSE(r.curve_locally_convex);
  EXPECT_EQ(r.curve_orientation, CGAL::COLLINEAR);
  EXPECT_FALSE(r.inflected_pieces.empty());
  // The converse fails: a spiral-like polygon turning left at every vertex but winding more
  // than once is not convex, and its curve is still locally convex.
  const std::vector<P> spiral{P(4, 0), P(4, 4), P(-4, 4), P(-4, -4), P(3, -4), P(3, 3), P(-3, 3), P(-3, -2)};
  std::vector<FT> t{0};
  for (std::size_t i = 0; i + 3 < spiral.size(); ++i) t.push_back(t.back() + FT(1));
  const fair::Spline_convexity_report<K> s = fair::spline_convexity(fair::Cubic_spline_2<K>(t, spiral));
  EXPECT_FALSE(s.polygon_convex);
  EXPECT_TRUE(s.curve_locally_convex);
  EXPECT_EQ(s.curve_orientation, CGAL::LEFT_TURN);
  EXPECT_TRUE(s.proposition_holds());
}

// A zero curvature coefficient from non-dyadic data (three collinear control points with
// coordinates k/3): the interval filter cannot see the exact zero, the exact fallback can;
// without the fallback the piece is reported undecided.
TYPED_TEST(Convexity_exact, FilterThenExactFallback) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  const fair::Cubic_spline_2<K> s(std::vector<FT>{0, 1},
                                  std::vector<P>{P(0, 0), P(q<K>(1, 3), q<K>(1, 3)), P(q<K>(2, 3), q<K>(2, 3)), P(1, 0)});
  const fair::Spline_convexity_report<K> r = fair::spline_convexity(s);
  EXPECT_EQ(r.pieces_exact, 1u);
  EXPECT_EQ(r.pieces_by_filter, 0u);
  EXPECT_TRUE(r.curve_locally_convex);
  EXPECT_EQ(r.curve_orientation, CGAL::RIGHT_TURN);
  fair::Spline_convexity_options no_fallback;
  no_fallback.exact_fallback = false;
  const fair::Spline_convexity_report<K> u = fair::spline_convexity(s, no_fallback);
  EXPECT_EQ(u.undecided_pieces, std::vector<std::size_t>{0});
  EXPECT_FALSE(u.curve_locally_convex);
}

// Proposition 1 needs a regular curve: the sign of D says nothing where c' = 0. A cusp (D =
// 18 (1 - 2t)^2 >= 0, c' = 3 ((1 - 2t)^2, 1 - 2t) vanishes at 1/2), a straight polygon that
// reverses (D == 0, c' = (3 (2t - 1)(4t - 3), 0) vanishes at 1/2 and 3/4), and a C2 join whose Bezier points coincide (b_2^0 = b_3^0 = b_1^1,
// c' = 0 at the join) are singular, never locally convex.
TYPED_TEST(Convexity, SingularCurvesAreNotLocallyConvex) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  const fair::Cubic_spline_2<K> cusp(std::vector<FT>{0, 1}, std::vector<P>{P(0, 0), P(1, 1), P(0, 1), P(1, 0)});
  const fair::Spline_convexity_report<K> a = fair::spline_convexity(cusp);
  EXPECT_FALSE(a.curve_locally_convex);
  EXPECT_EQ(a.curve_orientation, CGAL::COLLINEAR);
  EXPECT_EQ(a.singular_pieces, std::vector<std::size_t>{0});
  EXPECT_TRUE(a.inflected_pieces.empty());
  EXPECT_EQ(a.piece_signs, std::vector<int>{0});
  const fair::Cubic_spline_2<K> back(std::vector<FT>{0, 1}, std::vector<P>{P(0, 0), P(3, 0), P(1, 0), P(2, 0)});
  const fair::Spline_convexity_report<K> b = fair::spline_convexity(back);
  EXPECT_FALSE(b.polygon_convex);
  EXPECT_FALSE(b.curve_locally_convex);
  EXPECT_EQ(b.singular_pieces, std::vector<std::size_t>{0});
  // A straight run that does not reverse stays regular and convex.
  const fair::Cubic_spline_2<K> run(std::vector<FT>{0, 1}, std::vector<P>{P(0, 0), P(1, 0), P(2, 0), P(4, 0)});
  const fair::Spline_convexity_report<K> c = fair::spline_convexity(run);
  EXPECT_TRUE(c.curve_locally_convex);
  EXPECT_TRUE(c.singular_pieces.empty());
  // C2 join of two cubics (h = 1) at J = b_3^0 = b_2^0 = b_1^1; C2 (b_1^0 - J = b_2^1 - J, the
  // second derivatives) gives b_2^1 = b_1^0: the join is a cusp (c' = 0, c'' != 0).
  const P J(2, 1);
  const std::vector<fair::Bezier_2<K>> pieces{fair::Bezier_2<K>(std::vector<P>{P(0, 0), P(1, 0), J, J}),
                                              fair::Bezier_2<K>(std::vector<P>{J, J, P(1, 0), P(0, 1)})};
  const fair::Cubic_spline_2<K> joined = fair::Cubic_spline_2<K>::from_bezier_pieces(std::vector<FT>{0, 1, 2}, pieces);
  const fair::Spline_convexity_report<K> d = fair::spline_convexity(joined);
  EXPECT_FALSE(d.curve_locally_convex);
  EXPECT_EQ(d.singular_pieces, (std::vector<std::size_t>{0, 1}));
  fair::Spline_convexity_options no_fallback;
  no_fallback.exact_fallback = false;
  EXPECT_FALSE(fair::spline_convexity(cusp, no_fallback).curve_locally_convex);
  // A control point repeated three times: the polygon is convex once repeats are skipped, but
  // b_1^0 = b_2^0 = b_3^0 = b_0^1 = b_1^1 = (4,0), so c' = 0 at t_1. Outside the certificate.
  const fair::Cubic_spline_2<K> triple(std::vector<FT>{0, 1, 2, 3},
                                       std::vector<P>{P(0, 0), P(4, 0), P(4, 0), P(4, 0), P(4, 4), P(0, 4)});
  const fair::Spline_convexity_report<K> e = fair::spline_convexity(triple);
  EXPECT_TRUE(e.polygon_convex);
  EXPECT_FALSE(e.curve_locally_convex);
  EXPECT_EQ(e.singular_pieces, (std::vector<std::size_t>{0, 1}));
  EXPECT_FALSE(e.proposition_holds());
}

// ----------------------------------------------------------------- quadratic design (eq. 12)

// The quadratic through (t_k, q_k), k = 0..2, at t (Lagrange, an independent formula).
template <class K>
typename K::Point_2 lagrange(const typename K::FT* t, const typename K::Point_2* p, const typename K::FT& x) {
  typedef typename K::FT FT;
  FT X(0), Y(0);
  for (int k = 0; k < 3; ++k) {
    FT l(1);
    for (int j = 0; j < 3; ++j)
      if (j != k) l = l * (x - t[j]) / (t[k] - t[j]);
    X = X + l * p[k].x();
    Y = Y + l * p[k].y();
  }
  return typename K::Point_2(X, Y);
}

// The middle Bezier coefficient of a quadratic on [a, b]: 2 f((a+b)/2) - (f(a) + f(b))/2.
template <class K, class F>
typename K::Point_2 middle_coefficient(const F& f, const typename K::FT& a, const typename K::FT& b) {
  typedef typename K::FT FT;
  const typename K::Point_2 m = f((a + b) / FT(2)), pa = f(a), pb = f(b);
  return typename K::Point_2(FT(2) * m.x() - (pa.x() + pb.x()) / FT(2), FT(2) * m.y() - (pa.y() + pb.y()) / FT(2));
}

TYPED_TEST(Design_exact, MiddleCoefficientsAreThoseOfTheInterpolatingQuadratics) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  namespace ec = fair::internal::exact_conversion;
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> gap(1, 20);
  for (int run = 0; run < 10; ++run) {
    const std::vector<P> p = fair_test::random_points<K>(rng, 4);
    FT t[4] = {q<K>(-1, 3), FT(0), FT(0), FT(0)};
    for (int i = 1; i < 4; ++i) t[i] = t[i - 1] + q<K>(gap(rng), 7);
    // segment [t_1, t_2]: m^L from f_1 (points 0,1,2), m^R from f_2 (points 1,2,3)
    const P L = ec::middle_left<K>(p[0], p[1], p[2], (t[2] - t[1]) / (t[1] - t[0]));
    const P R = ec::middle_right<K>(p[1], p[2], p[3], (t[3] - t[2]) / (t[2] - t[1]));
    EXPECT_EQ(L, middle_coefficient<K>([&](const FT& x) { return lagrange<K>(t, p.data(), x); }, t[1], t[2]));
    EXPECT_EQ(R, middle_coefficient<K>([&](const FT& x) { return lagrange<K>(t + 1, p.data() + 1, x); }, t[1], t[2]));
  }
}

// Points on one parabola at compatible (given) parameters: every local quadratic is that
// parabola, m^L = m^R, and the shapes are exactly its restrictions.
TYPED_TEST(Design, ParabolaIsReproduced) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  auto f = [](const FT& t) { return P(FT(2) * t + FT(1), t * t - t); };
  const std::vector<FT> t{q<K>(-2), q<K>(-3, 2), q<K>(-1, 4), q<K>(0), q<K>(3, 2), q<K>(2), q<K>(9, 2)};
  std::vector<P> p;
  for (const FT& x : t) p.push_back(f(x));
  const std::vector<fair::Bezier_2<K>> shapes = fair::quadratic_design_shapes<K>(p, t);
  ASSERT_EQ(shapes.size(), p.size() - 1);
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    ASSERT_EQ(shapes[i].degree(), 2u);
    EXPECT_TRUE(same<K>(shapes[i].control_points()[1], middle_coefficient<K>(f, t[i], t[i + 1]), 1e-13)) << i;
    EXPECT_TRUE(same<K>(shapes[i].control_points()[0], p[i]));
    EXPECT_TRUE(same<K>(shapes[i].control_points()[2], p[i + 1]));
  }
}

// Reversing the polygon (and mirroring the parameters) reverses the design: m_i goes to the
// mirrored segment (mu and 1 - mu swap; equal up to the rounding of mu).
TYPED_TEST(Design, ReversalSymmetry) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  std::mt19937 rng(77);
  for (int run = 0; run < 4; ++run) {
    const bool closed = run % 2 == 1;
    const std::vector<P> p = fair_test::random_points<K>(rng, 8);
    std::vector<P> r(p.rbegin(), p.rend());
    if (closed) std::rotate(r.begin(), r.end() - 1, r.end()); // keep q_0 first: r = q0, q_{n-1}, ..., q_1
    const std::vector<fair::Bezier_2<K>> a = fair::quadratic_design_shapes<K>(p, closed), b = fair::quadratic_design_shapes<K>(r, closed);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::size_t j = closed ? (a.size() - i) % a.size() : a.size() - 1 - i;
      const fair::Bezier_2<K>& x = a[i];
      const fair::Bezier_2<K>& y = b[closed ? (j + a.size() - 1) % a.size() : j];
      EXPECT_TRUE(same<K>(x.control_points()[0], y.control_points()[2])) << run << " " << i;
      const P mx = x.control_points()[1], my = y.control_points()[1];
      EXPECT_TRUE(fair_test::same_double(CGAL::to_double(mx.x()), CGAL::to_double(my.x()), 1e-12)) << run << " " << i;
      EXPECT_TRUE(fair_test::same_double(CGAL::to_double(mx.y()), CGAL::to_double(my.y()), 1e-12)) << run << " " << i;
    }
  }
}

TYPED_TEST(Design, BadInput) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  EXPECT_THROW(fair::quadratic_design_shapes<K>(std::vector<P>{P(0, 0)}), fair::Invalid_input_error);
  EXPECT_THROW(fair::quadratic_design_shapes<K>(std::vector<P>{P(0, 0), P(0, 0), P(1, 1)}), fair::Invalid_input_error);
  EXPECT_THROW(fair::quadratic_design_shapes<K>(std::vector<P>{P(0, 0), P(1, 0), P(2, 1)}, std::vector<FT>{0, 1, 1}),
               fair::Invalid_input_error);
  EXPECT_THROW(fair::quadratic_design_shapes<K>(std::vector<P>{P(0, 0), P(1, 0), P(2, 1)}, std::vector<FT>{0, 1}),
               fair::Invalid_input_error);
  // the local quadratic through (0,0), (1,0), (0,0) at uniform parameters turns back at its middle
  EXPECT_THROW(fair::quadratic_design_shapes<K>(std::vector<P>{P(0, 0), P(1, 0), P(0, 0), P(1, 1)}, std::vector<FT>{0, 1, 2, 3}),
               fair::Invalid_input_error);
  EXPECT_THROW(fair::rounding_marks(FT(1) / FT(2)), fair::Precondition_error);
  const fair::Bezier_2<K> a(std::vector<P>{P(0, 0), P(1, 1), P(2, 0)}), b(std::vector<P>{P(3, 0), P(4, 1), P(5, 0)});
  EXPECT_THROW(fair::bezier_chain_spline<K>({a, b}, fair::rounding_marks(q<K>(1, 4))), fair::Invalid_input_error);
  EXPECT_THROW(fair::bezier_chain_spline<K>(std::vector<fair::Bezier_2<K>>{}, {}), fair::Invalid_input_error);
}

// The chain spline equals every shape exactly between its marks u_2 and u_{m-2} (and up to the
// clamped ends), open and closed, with symmetric and asymmetric marks.
TYPED_TEST(Design, ChainSplineReproducesItsShapes) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  const std::vector<P> sparse{P(0, 0), P(2, 3), P(5, 4), P(8, 2), P(9, -2), P(6, -5), P(2, -4)};
  for (int variant = 0; variant < 4; ++variant) {
    const bool closed = variant % 2 == 1;
    const std::vector<FT> u = variant < 2 ? fair::rounding_marks(q<K>(1, 4))
                                          : std::vector<FT>{q<K>(1, 10), q<K>(1, 5), q<K>(1, 2), q<K>(2, 3), q<K>(5, 6)};
    std::vector<FT> t;
    for (std::size_t i = 0; i < sparse.size() + (closed ? 1 : 0); ++i) t.push_back(q<K>(int(i * i) + 3 * int(i), 4));
    const std::vector<fair::Bezier_2<K>> shapes = fair::quadratic_design_shapes<K>(sparse, t, closed);
    const fair::Cubic_spline_2<K> s = fair::bezier_chain_spline(shapes, u, closed);
    EXPECT_FALSE(s.is_rational());
    EXPECT_EQ(s.is_closed(), closed);
    const std::size_t m = u.size() + 1;
    const FT P_len = FT(2) + u.front() - u.back(), start = closed ? u.front() : FT(0);
    // beta = 1 at the three control points of every junction (at the shared point only for
    // symmetric marks): breakpoint index of d^j_{m+1} in shape j's block
    for (std::size_t j = 0; j + 1 < shapes.size(); ++j) {
      const std::size_t first = closed ? j * (m + 2) + m + 1 : (j == 0 ? m : m + j * (m + 2));
      EXPECT_TRUE(same<K>(s.beta(first), FT(1))) << variant << " " << j;
      EXPECT_TRUE(same<K>(s.beta(first + 2), FT(1))) << variant << " " << j;
      EXPECT_TRUE(same<K>(s.beta(first + 1), u.front() / (FT(1) - u.back()))) << variant << " " << j;
    }
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      const FT o = start + FT(int(j)) * P_len;
      const FT lo = (!closed && j == 0) ? FT(0) : u[1], hi = (!closed && j + 1 == shapes.size()) ? FT(1) : u[m - 3];
      for (int k = 0; k <= 8; ++k) {
        const FT x = lo + (hi - lo) * q<K>(k, 8);
        EXPECT_TRUE(same<K>(s.point(o + x), shapes[j].point(x), 1e-12)) << "variant " << variant << " shape " << j << " k " << k;
      }
    }
  }
}

// The pipeline on the eight sparse points of a Fig. 16-like data set: a closed C2 spline whose
// control polygon contains every data point and which retains every shape on [1/4, 3/4]. The
// design is not convex although the data are: the quadratics meet at q_1 with a reflex corner
// (m_0, q_1, m_1 turn right), which spline_convexity reports at control point 7 = q_1.
TYPED_TEST(Design, PipelineOnSparseConvexData) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  const std::vector<P> sparse{P(0, 0), P(4, -1), P(8, 0), P(10, 3), P(9, 7), P(6, 9), P(2, 8), P(-1, 4)};
  fair::Quadratic_design_options o;
  o.spacing = fair::Knot_spacing::UNIFORM;
  const std::vector<fair::Bezier_2<K>> shapes = fair::quadratic_design_shapes<K>(sparse, true, o);
  const fair::Cubic_spline_2<K> s = fair::quadratic_design_spline<K>(sparse, true, o);
  ASSERT_EQ(shapes.size(), 8u);
  EXPECT_EQ(s.number_of_control_points(), 8u * 7u);
  const FT P_len = FT(2) + q<K>(1, 8) - q<K>(7, 8);
  for (std::size_t j = 0; j < shapes.size(); ++j)
    for (int k = 0; k <= 4; ++k) {
      const FT x = q<K>(1, 4) + q<K>(k, 8);
      EXPECT_TRUE(same<K>(s.point(q<K>(1, 8) + FT(int(j)) * P_len + x), shapes[j].point(x), 1e-12)) << j << " " << k;
    }
  for (std::size_t j = 0; j < sparse.size(); ++j) EXPECT_TRUE(same<K>(s.control_points()[7 * j], sparse[j])) << j;
  const fair::Spline_convexity_report<K> r = fair::spline_convexity(s);
  EXPECT_FALSE(r.polygon_convex);
  EXPECT_EQ(r.polygon_violation, 7u);
  EXPECT_FALSE(r.curve_locally_convex);
  EXPECT_EQ(r.inflected_pieces, (std::vector<std::size_t>{6, 7}));
  fair::Quadratic_design_options bad = o;
  bad.rounding = 0.5;
  EXPECT_THROW(fair::quadratic_design_spline<K>(sparse, true, bad), fair::Precondition_error);
}

} // namespace
