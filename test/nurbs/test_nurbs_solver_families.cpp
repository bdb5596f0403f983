// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// nurbs() of the solver families is their pieces (issue 26 §1), open and closed, exactly in EPECK
// and Simple_cartesian<Gmpq> (to rounding in double): Kappa_curve_2 (degree 2, knots at the piece
// indices, interior ones double, weights 1 at the joins and w_j between; polynomial with unit
// weights, rational with automatic ones; closed: the periodic form -1, 0, 0, 1, 1, ..., m, m,
// m + 1, m + 1) and Optimal_curve_2 (its spline runs: single knots inside a run, multiplicity 3 at the
// corners; closed with corners: the seam at the first corner). The solves run in double whatever
// the kernel; the pieces, and so the NURBS, are built in the kernel.

#include "family_checks.h"

#include <fair/Kappa_curve_2.h>
#include <fair/Optimal_curve_2.h>

#include <gtest/gtest.h>

#include <vector>

namespace {

using fair_test::expect_nurbs_is_pieces;
using fair_test::interior_multiplicities;

template <class K>
class Nurbs_solver_families : public ::testing::Test {};
TYPED_TEST_SUITE(Nurbs_solver_families, fair_test::Family_kernels);

template <class K>
std::vector<typename K::Point_2> hexagon() {
  typedef typename K::Point_2 P;
  return {P(0, 0), P(4, -1), P(7, 1), P(6, 5), P(2, 6), P(-1, 3)};
}

TYPED_TEST(Nurbs_solver_families, KappaIsDegree2WithDoubleKnotsAtThePieceIndices) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  for (bool closed : {false, true}) {
    fair::Kappa_curve_options o;
    o.closed = closed;
    o.weights = closed ? fair::Kappa_weights::AUTOMATIC : fair::Kappa_weights::UNIT;
    const fair::Kappa_curve_2<K> c(hexagon<K>(), o);
    const std::size_t m = c.number_of_pieces();
    ASSERT_EQ(m, closed ? 6u : 4u);
    const fair::Nurbs_curve_2<K> n = c.nurbs();
    EXPECT_EQ(n.degree(), 2u);
    EXPECT_EQ(n.is_closed(), closed);
    EXPECT_EQ(n.is_rational(), closed) << "unit weights: polynomial; automatic ones: rational";
    std::vector<FT> knots;  // the documented knot vector
    if (closed) {
      knots.push_back(FT(-1));  // -1, 0, 0, 1, 1, ..., m, m, m + 1, m + 1: 2m + 5 knots for 2m + 2 points
      for (std::size_t j = 0; j <= m + 1; ++j) knots.insert(knots.end(), 2, FT(static_cast<int>(j)));
    } else {
      knots.push_back(FT(0));
      for (std::size_t j = 0; j <= m; ++j) knots.insert(knots.end(), 2, FT(static_cast<int>(j)));
      knots.push_back(FT(static_cast<int>(m)));
    }
    EXPECT_EQ(n.knots(), knots);
    EXPECT_EQ(n.number_of_control_points(), closed ? 2 * m + 2 : 2 * m + 1);
    // the control points: the pieces' P_{j,0}, P_{j,1} in turn, weights 1 and w_j
    for (std::size_t j = 0; j < m; ++j) {
      EXPECT_EQ(n.control_points()[2 * j], c.piece(j).control_point(0));
      EXPECT_EQ(n.control_points()[2 * j + 1], c.piece(j).control_point(1));
      EXPECT_EQ(n.weights()[2 * j], FT(1));
      EXPECT_EQ(n.weights()[2 * j + 1], c.piece(j).weight());
    }
    expect_nurbs_is_pieces(n, c.pieces(), closed ? "closed, automatic weights" : "open, unit weights");
    // point(j + t) is piece j at t, in particular the interpolated point at t_j (to the solve)
    for (std::size_t j = 0; j < m; ++j) {
      const typename K::Point_2 q = n.point(FT(static_cast<int>(j)) + FT(c.t(j)));
      EXPECT_NEAR(CGAL::to_double(q.x()), CGAL::to_double(c.points()[c.point_index(j)].x()), 1e-9);
      EXPECT_NEAR(CGAL::to_double(q.y()), CGAL::to_double(c.points()[c.point_index(j)].y()), 1e-9);
    }
  }
}

TYPED_TEST(Nurbs_solver_families, OptimalIsItsSplineWithTripleKnotsAtTheCorners) {
  typedef TypeParam K;
  for (int variant = 0; variant < 3; ++variant) {  // open, closed, closed with two corners
    fair::Optimal_curve_options o;
    o.closed = variant > 0;
    o.resolution = 24;
    const std::vector<typename K::Point_2> p = hexagon<K>();
    if (variant == 2) {
      for (std::size_t i : {0u, 3u}) {
        fair::Point_constraint corner;
        corner.index = i;
        corner.kind = fair::Point_constraint_kind::CORNER;
        const std::size_t prev = (i + p.size() - 1) % p.size(), next = (i + 1) % p.size();
        corner.direction = {{CGAL::to_double(p[i].x() - p[prev].x()), CGAL::to_double(p[i].y() - p[prev].y())}};
        corner.outgoing = {{CGAL::to_double(p[next].x() - p[i].x()), CGAL::to_double(p[next].y() - p[i].y())}};
        o.constraints.push_back(corner);
      }
    }
    const fair::Optimal_curve_2<K> c(p, o);
    ASSERT_GT(c.number_of_pieces(), 0u) << c.report();
    const fair::Nurbs_curve_2<K> n = c.nurbs();
    SCOPED_TRACE(variant);
    EXPECT_EQ(n.degree(), 3u);
    EXPECT_EQ(n.is_closed(), o.closed);
    EXPECT_FALSE(n.is_rational());
    const std::vector<std::size_t> m = interior_multiplicities(n);
    if (variant < 2) {
      EXPECT_EQ(m, std::vector<std::size_t>(c.number_of_pieces() - 1, 1));
      EXPECT_EQ(n.breakpoints(), c.spline().splines.front().breakpoints());
    } else {
      ASSERT_EQ(c.spline().splines.size(), 2u);
      // one corner inside the domain (multiplicity 3), the other at the seam (3 as well)
      std::vector<std::size_t> expected(c.number_of_pieces() - 1, 1);
      expected[c.spline().splines.front().number_of_pieces() - 1] = 3;
      EXPECT_EQ(m, expected);
      EXPECT_EQ(std::count(n.knots().begin(), n.knots().end(), n.domain().first), 3);
    }
    expect_nurbs_is_pieces(n, c.pieces(), "optimal");
  }
}

// Review finding 9: one periodic run asked for an open curve came back closed. Now it is opened
// at its seam: clamped, not closed, the same pieces (exactly in the exact kernels) and the same
// interior knots; asked for closed it is the run's own periodic NURBS. An open clamped curve
// opened is itself.
TYPED_TEST(Nurbs_solver_families, OnePeriodicRunAskedOpenIsOpened) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const std::vector<FT> t{FT(0), FT(1), FT(5) / FT(2), FT(3), FT(9) / FT(2), FT(6), FT(7)};
  const fair::Cubic_spline_2<K> s(t, hexagon<K>(), true);
  const fair::Polygon_spline_runs<K> runs{{s}, {0}, 0.0};
  const fair::Nurbs_curve_2<K> closed = runs.nurbs(true), open = runs.nurbs(false);
  EXPECT_TRUE(closed.is_closed());
  EXPECT_EQ(closed.knots(), s.nurbs().knots());
  EXPECT_FALSE(open.is_closed());
  std::vector<FT> knots(4, FT(0));  // clamped at the seam, the run's breakpoints inside
  knots.insert(knots.end(), t.begin() + 1, t.end() - 1);
  knots.insert(knots.end(), 4, FT(7));
  EXPECT_EQ(open.knots(), knots);
  expect_nurbs_is_pieces(open, s.pieces(), "one periodic run, opened");
  // a rational periodic run opens the same way (weights: the same up to one factor per piece)
  const std::vector<FT> w{FT(1), FT(3) / FT(2), FT(1) / FT(2), FT(2), FT(1), FT(5) / FT(4)};
  const fair::Cubic_spline_2<K> r(t, hexagon<K>(), w, true);
  const fair::Nurbs_curve_2<K> ro = fair::Polygon_spline_runs<K>{{r}, {0}, 0.0}.nurbs(false);
  EXPECT_FALSE(ro.is_closed());
  EXPECT_TRUE(ro.is_rational());
  EXPECT_EQ(ro.knots(), knots);
  expect_nurbs_is_pieces(ro, r.pieces(), "one rational periodic run, opened");
  const fair::Nurbs_curve_2<K> again = fair::internal::nurbs::opened(open);
  EXPECT_EQ(again.knots(), open.knots());
  for (std::size_t k = 0; k < open.number_of_control_points(); ++k)
    EXPECT_TRUE(fair_test::same<K>(again.control_points()[k], open.control_points()[k])) << k;
}

}  // namespace
