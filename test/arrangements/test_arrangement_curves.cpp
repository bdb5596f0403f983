// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair/cgal/Arrangement_curves.h (issue 26 §2): designed curves in CGAL 2D arrangements, exactly.
//  - the intersections of a kappa-curve (unit weights) and a cubic interpolating spline as
//    Arr_Bezier_curve_traits_2 curves: counted, and each checked against a floating
//    computation (dense polylines of the two curves);
//  - an exact circle (a closed rational quadratic NURBS, integer weights) as Arr_conic_traits_2
//    arcs: the supporting conics are circles, the diagonal meets it where x^2 = 1/2 exactly;
//  - a self-intersection check of outlines: a simple closed curve (closed kappa-curve with
//    automatic weights, conic arcs; closed cubic spline, Bezier curves) has two faces and every
//    vertex of degree 2, a figure-eight three faces and one vertex of degree 4;
//  - the typed errors for a curve the traits cannot take.

#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Kappa_curve_2.h>
#include <fair/Nurbs_curve_2.h>
#include <fair/cgal/Arrangement_curves.h>

#include <CGAL/Arr_Bezier_curve_traits_2.h>
#include <CGAL/Arr_conic_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/CORE_algebraic_number_traits.h>
#include <CGAL/Cartesian.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <utility>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
typedef K::Point_2 Point;

typedef CGAL::CORE_algebraic_number_traits Nt_traits;
typedef Nt_traits::Rational Rational;
typedef Nt_traits::Algebraic Algebraic;
typedef CGAL::Cartesian<Rational> Rat_kernel;
typedef CGAL::Cartesian<Algebraic> Alg_kernel;
typedef CGAL::Arr_Bezier_curve_traits_2<Rat_kernel, Alg_kernel, Nt_traits> Bezier_traits;
typedef CGAL::Arr_conic_traits_2<Rat_kernel, Alg_kernel, Nt_traits> Conic_traits;
typedef CGAL::Arrangement_2<Bezier_traits> Bezier_arrangement;
typedef CGAL::Arrangement_2<Conic_traits> Conic_arrangement;

// The kappa-curve as a degree-2 NURBS (double knots at the integers; closed: the periodic form),
// built from its pieces here, independently of the family's nurbs().
fair::Nurbs_curve_2<K> kappa_nurbs(const fair::Kappa_curve_2<K>& c) {
  const std::size_t m = c.number_of_pieces();
  std::vector<Point> P;
  std::vector<double> w, u;
  for (std::size_t j = 0; j < m; ++j) {
    P.push_back(c.piece(j).source());
    w.push_back(1);
    P.push_back(c.piece(j).control_point(1));
    w.push_back(c.piece(j).weight());
  }
  if (c.is_closed()) {
    u.push_back(-1);
    for (std::size_t j = 0; j <= m + 1; ++j) u.insert(u.end(), 2, static_cast<double>(j));
    for (std::size_t k = 0; k < 2; ++k) {
      P.push_back(P[k]);
      w.push_back(w[k]);
    }
  } else {
    P.push_back(c.piece(m - 1).target());
    w.push_back(1);
    u.push_back(0);
    for (std::size_t j = 0; j <= m; ++j) u.insert(u.end(), 2, static_cast<double>(j));
    u.push_back(static_cast<double>(m));
  }
  return fair::Nurbs_curve_2<K>(2, u, P, w, c.is_closed());
}

// The floating oracle of the crossings of two curves: the crossings of dense polylines of
// them, each refined by Newton's method on A(u) - B(v) = 0 (the 2x2 Jacobian [A'(u), -B'(v)])
// from the polyline segments' parameters, to full double precision.
struct Sample {
  Point p;
  double u;
};

std::vector<Sample> polyline(const fair::Nurbs_curve_2<K>& c, int per_piece) {
  std::vector<Sample> out;
  const std::vector<double> b = c.breakpoints();
  for (std::size_t j = 0; j + 1 < b.size(); ++j)
    for (int s = 0; s < per_piece; ++s) {
      const double u = b[j] + (b[j + 1] - b[j]) * s / per_piece;
      out.push_back({c.point(u), u});
    }
  out.push_back({c.point(b.back()), b.back()});
  return out;
}

std::vector<Point> crossings_of(const fair::Nurbs_curve_2<K>& a, const fair::Nurbs_curve_2<K>& b) {
  const std::vector<Sample> pa = polyline(a, 64), pb = polyline(b, 64);
  std::vector<Point> out;
  for (std::size_t i = 0; i + 1 < pa.size(); ++i)
    for (std::size_t j = 0; j + 1 < pb.size(); ++j) {
      const K::Segment_2 s(pa[i].p, pa[i + 1].p), t(pb[j].p, pb[j + 1].p);
      if (!CGAL::do_intersect(s, t)) continue;
      double u = 0.5 * (pa[i].u + pa[i + 1].u), v = 0.5 * (pb[j].u + pb[j + 1].u);
      for (int k = 0; k < 30; ++k) {
        const K::Vector_2 g = a.point(u) - b.point(v), da = a.derivative(u), db = b.derivative(v);
        const double det = -da.x() * db.y() + da.y() * db.x();  // det [da, -db]
        u -= (-g.x() * db.y() + g.y() * db.x()) / det;
        v -= (da.x() * g.y() - da.y() * g.x()) / det;
      }
      EXPECT_LT(CGAL::squared_distance(a.point(u), b.point(v)), 1e-26) << "Newton did not converge";
      out.push_back(a.point(u));
    }
  return out;
}

// The vertices of an arrangement of A and B that neither arrangement of A alone nor of B alone
// has: the crossings of A and B (the x-monotone splits are the same in the three).
template <class Arrangement, class Curves>
std::size_t new_vertices(const Curves& a, const Curves& b) {
  Arrangement arr_a, arr_b, arr_ab;
  CGAL::insert(arr_a, a.begin(), a.end());
  CGAL::insert(arr_b, b.begin(), b.end());
  Curves ab = a;
  ab.insert(ab.end(), b.begin(), b.end());
  CGAL::insert(arr_ab, ab.begin(), ab.end());
  return arr_ab.number_of_vertices() - arr_a.number_of_vertices() - arr_b.number_of_vertices();
}

// A kappa-curve (unit weights: parabolic pieces, polynomial) and a cubic interpolating spline,
// both as Bezier curves with rational control points: the arrangement finds the four crossings
// exactly; computed exactly (CORE algebraic coordinates), each is the Newton-refined floating
// crossing to 1e-12.
TEST(Arrangement_curves, KappaCurveAndCubicSplineIntersectExactly) {
  const fair::Kappa_curve_2<K> kappa({{0, 0}, {2, 2}, {4, 0}, {6, 2}, {8, 0}});
  const fair::Nurbs_curve_2<K> a = kappa_nurbs(kappa);
  ASSERT_FALSE(a.is_rational());
  const fair::Nurbs_curve_2<K> b =
      fair::Cubic_interpolating_spline_2<K>({{-1, 1}, {1.5, 1.3}, {3, 0.7}, {5, 1.2}, {7, 0.8}, {9, 1}}).spline().nurbs();
  std::vector<Bezier_traits::Curve_2> ca, cb;
  fair::to_arrangement_curves<Bezier_traits>(a, std::back_inserter(ca));
  fair::to_arrangement_curves<Bezier_traits>(b, std::back_inserter(cb));
  ASSERT_EQ(ca.size(), a.number_of_pieces());
  ASSERT_EQ(cb.size(), b.number_of_pieces());

  const std::vector<Point> floating = crossings_of(a, b);
  ASSERT_EQ(floating.size(), 4u);  // the two humps of the wave cross the wavy line y ~ 1 twice each
  EXPECT_EQ((new_vertices<Bezier_arrangement>(ca, cb)), floating.size());

  Bezier_arrangement arr;
  std::vector<Bezier_traits::Curve_2> all = ca;
  all.insert(all.end(), cb.begin(), cb.end());
  CGAL::insert(arr, all.begin(), all.end());
  Bezier_traits::Bezier_cache cache;
  std::size_t crossings = 0;
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    if (v->degree() != 4) continue;
    ++crossings;
    // An intersection point of two Bezier curves is held as an isolating box until a predicate
    // needs more (x() and y() have the precondition is_exact()): compute it exactly.
    v->point().make_exact(cache);
    ASSERT_TRUE(v->point().is_exact());
    const Point p(CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y()));
    double best = HUGE_VAL;
    for (const Point& q : floating) best = std::min(best, std::sqrt(CGAL::squared_distance(p, q)));
    EXPECT_LT(best, 1e-12) << p;
  }
  EXPECT_EQ(crossings, floating.size());
}

// x^2 + y^2 = 1 as four rational quadratic pieces with joint weights 1, 2, 1, 2 and middle
// weights 1: each piece has w1^2 / (w0 w2) = 1/2, the standard weight 1/sqrt(2) of a quarter circle.
fair::Nurbs_curve_2<EK> unit_circle() {
  const std::vector<EK::Point_2> P = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}, {1, 1}};
  const std::vector<EK::FT> w = {1, 1, 2, 1, 1, 1, 2, 1, 1, 1};
  std::vector<EK::FT> u = {-1};
  for (int j = 0; j <= 5; ++j) u.insert(u.end(), 2, EK::FT(j));
  return fair::Nurbs_curve_2<EK>(2, u, P, w, true);
}

TEST(Arrangement_curves, ExactCircleMeetsTheDiagonalAtTheSquareRootOfOneHalf) {
  const fair::Nurbs_curve_2<EK> circle = unit_circle();
  EXPECT_EQ(CGAL::squared_distance(circle.point(EK::FT(1) / 3), EK::Point_2(0, 0)), EK::FT(1));
  std::vector<Conic_traits::Curve_2> arcs;
  fair::to_arrangement_curves<Conic_traits>(circle, std::back_inserter(arcs));
  ASSERT_EQ(arcs.size(), 4u);
  for (const auto& arc : arcs) {  // supporting conic r x^2 + s y^2 + t xy + u x + v y + w: a circle
    EXPECT_EQ(arc.r(), arc.s());
    EXPECT_EQ(CGAL::sign(arc.t()), CGAL::ZERO);
    EXPECT_EQ(CGAL::sign(arc.u()), CGAL::ZERO);
    EXPECT_EQ(CGAL::sign(arc.v()), CGAL::ZERO);
    EXPECT_EQ(arc.w(), -arc.r());
  }
  Conic_arrangement arr;
  CGAL::insert(arr, arcs.begin(), arcs.end());
  EXPECT_EQ(arr.number_of_faces(), 2u);
  CGAL::insert(arr, Conic_traits::Curve_2(Rat_kernel::Segment_2(Rat_kernel::Point_2(-2, -2), Rat_kernel::Point_2(2, 2))));
  std::size_t on_diagonal = 0;
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v)
    if (v->degree() == 4) {
      ++on_diagonal;
      EXPECT_EQ(v->point().x() * v->point().x(), Algebraic(1) / 2);  // exactly
      EXPECT_EQ(v->point().x(), v->point().y());
    }
  EXPECT_EQ(on_diagonal, 2u);
  EXPECT_EQ(arr.number_of_faces(), 3u);
}

template <class Arrangement>
void expect_simple_closed(const Arrangement& arr, std::size_t crossings) {
  std::size_t degree4 = 0;
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    EXPECT_TRUE(v->degree() == 2 || v->degree() == 4) << "a loose end: the pieces do not meet exactly";
    degree4 += v->degree() == 4;
  }
  EXPECT_EQ(degree4, crossings);
  EXPECT_EQ(arr.number_of_faces(), 2u + crossings);  // Euler: V - E + F = 2 with E = V + crossings
}

// Few points, so few pieces: the conic arcs' predicates are computed with CORE algebraic
// numbers of the arcs' full-precision coefficients, about a second per piece.
const std::vector<Point> simple_outline = {{4, 0}, {1, 3}, {-3, 2}, {-3, -2}, {1, -3}};
// a bow tie: the point order crosses itself once, at the origin
const std::vector<Point> figure_eight = {{4, 1}, {4, -1}, {-4, 1}, {-4, -1}};

// minimum-eccentricity weights (eq. 16): elliptic pieces
fair::Kappa_curve_2<K> closed_kappa(const std::vector<Point>& points) {
  fair::Kappa_curve_options o;
  o.closed = true;
  o.weights = fair::Kappa_weights::AUTOMATIC;
  return fair::Kappa_curve_2<K>(points, o);
}

void conic_outline(const std::vector<Point>& points, std::size_t crossings) {
  const fair::Nurbs_curve_2<K> curve = kappa_nurbs(closed_kappa(points));
  ASSERT_TRUE(curve.is_rational());
  for (double w : curve.weights()) EXPECT_LE(w, 1.0);
  std::vector<Conic_traits::Curve_2> arcs;
  fair::to_arrangement_curves<Conic_traits>(curve, std::back_inserter(arcs));
  ASSERT_EQ(arcs.size(), points.size());
  Conic_arrangement arr;
  CGAL::insert(arr, arcs.begin(), arcs.end());
  expect_simple_closed(arr, crossings);
}

void bezier_outline(const std::vector<Point>& points, std::size_t crossings) {
  fair::Cubic_interpolating_spline_options o;
  o.closed = true;
  const fair::Nurbs_curve_2<K> curve = fair::Cubic_interpolating_spline_2<K>(points, o).spline().nurbs();
  std::vector<Bezier_traits::Curve_2> curves;
  fair::to_arrangement_curves<Bezier_traits>(curve, std::back_inserter(curves));
  ASSERT_EQ(curves.size(), points.size());
  Bezier_arrangement arr;
  CGAL::insert(arr, curves.begin(), curves.end());
  expect_simple_closed(arr, crossings);
}

TEST(Arrangement_curves, SimpleOutlineConicArcsHasTwoFaces) { conic_outline(simple_outline, 0); }
TEST(Arrangement_curves, FigureEightConicArcsCrossesOnce) { conic_outline(figure_eight, 1); }
TEST(Arrangement_curves, SimpleOutlineBezierCurvesHasTwoFaces) { bezier_outline(simple_outline, 0); }
TEST(Arrangement_curves, FigureEightBezierCurvesCrossesOnce) { bezier_outline(figure_eight, 1); }

// Hyperbolic pieces: axis-parallel ones become arcs on the right branch; rotated ones are refused
// (CGAL 5.5's branch test, Arrangement_curves.h).
TEST(Arrangement_curves, HyperbolicPieces) {
  std::vector<Conic_traits::Curve_2> c;
  const fair::Nurbs_curve_2<K> upright(2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}}, {1, 2, 1});
  fair::to_arrangement_curves<Conic_traits>(upright, std::back_inserter(c));
  ASSERT_EQ(c.size(), 1u);
  EXPECT_LT(CGAL::sign(4 * c[0].r() * c[0].s() - c[0].t() * c[0].t()), 0);  // a hyperbola
  Conic_arrangement arr;
  CGAL::insert(arr, c.begin(), c.end());
  // its apex c(1/2) = (1, w / (1 + w)) = (1, 2/3): the line x = 1 meets the arc there only
  CGAL::insert(arr, Conic_traits::Curve_2(Rat_kernel::Segment_2(Rat_kernel::Point_2(1, -1), Rat_kernel::Point_2(1, 3))));
  std::size_t crossings = 0;
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v)
    if (v->degree() == 4) {
      ++crossings;
      EXPECT_EQ(v->point().y(), Algebraic(2) / 3);
    }
  EXPECT_EQ(crossings, 1u);
  const fair::Nurbs_curve_2<K> rotated(2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0.5}}, {1, 1.2, 1});
  EXPECT_THROW(fair::to_arrangement_curves<Conic_traits>(rotated, std::back_inserter(c)), fair::Precondition_error);
}

TEST(Arrangement_curves, Errors) {
  std::vector<Bezier_traits::Curve_2> b;
  EXPECT_THROW(fair::to_arrangement_curves<Bezier_traits>(unit_circle(), std::back_inserter(b)), fair::Precondition_error);
  std::vector<Conic_traits::Curve_2> c;
  const fair::Nurbs_curve_2<K> cubic(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {1, 1}, {2, -1}, {3, 0}});
  EXPECT_THROW(fair::to_arrangement_curves<Conic_traits>(cubic, std::back_inserter(c)), fair::Precondition_error);
  // a straight quadratic piece that folds back: P1 beyond P2
  const fair::Nurbs_curve_2<K> fold(2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {3, 0}, {1, 0}});
  EXPECT_THROW(fair::to_arrangement_curves<Conic_traits>(fold, std::back_inserter(c)), fair::Precondition_error);
  // a straight one that does not: the segment
  const fair::Nurbs_curve_2<K> straight(2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 0}, {3, 0}}, {1, 2, 1});
  c.clear();
  fair::to_arrangement_curves<Conic_traits>(straight, std::back_inserter(c));
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].orientation(), CGAL::COLLINEAR);
}

}  // namespace
