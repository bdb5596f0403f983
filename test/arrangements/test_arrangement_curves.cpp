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

// Dense polyline of a curve (the floating oracle).
std::vector<Point> polyline(const fair::Nurbs_curve_2<K>& c, int per_piece) {
  std::vector<Point> out;
  const std::vector<double> b = c.breakpoints();
  for (std::size_t j = 0; j + 1 < b.size(); ++j)
    for (int s = 0; s < per_piece; ++s) out.push_back(c.point(b[j] + (b[j + 1] - b[j]) * s / per_piece));
  out.push_back(c.point(b.back()));
  return out;
}

std::vector<std::pair<double, double>> polyline_crossings(const std::vector<Point>& a, const std::vector<Point>& b) {
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i + 1 < a.size(); ++i)
    for (std::size_t j = 0; j + 1 < b.size(); ++j) {
      const K::Segment_2 s(a[i], a[i + 1]), t(b[j], b[j + 1]);
      if (const auto x = CGAL::intersection(s, t))
        if (const Point* p = boost::get<Point>(&*x)) out.push_back({p->x(), p->y()});
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

  const std::vector<std::pair<double, double>> floating = polyline_crossings(polyline(a, 400), polyline(b, 400));
  ASSERT_EQ(floating.size(), 4u);  // the two humps of the wave cross the wavy line y ~ 1 twice each
  EXPECT_EQ((new_vertices<Bezier_arrangement>(ca, cb)), floating.size());

  // every exact crossing is near a floating one
  Bezier_arrangement arr;
  std::vector<Bezier_traits::Curve_2> all = ca;
  all.insert(all.end(), cb.begin(), cb.end());
  CGAL::insert(arr, all.begin(), all.end());
  std::size_t crossings = 0;
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    if (v->degree() != 4) continue;
    ++crossings;
    const std::pair<double, double> p(CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y()));
    double best = 1e300;
    for (const auto& q : floating) best = std::min(best, std::hypot(p.first - q.first, p.second - q.second));
    EXPECT_LT(best, 1e-4) << "(" << p.first << ", " << p.second << ")";
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

const std::vector<Point> simple_outline = {{4, 0}, {2.8, 2.1}, {0, 3}, {-2.9, 2}, {-4, 0.2}, {-2.7, -2.2}, {0.3, -3}, {2.9, -2}};
// a lemniscate-like outline: the point order crosses itself once, near the origin
const std::vector<Point> figure_eight = {{2, 1.5}, {4, 0}, {2, -1.5}, {-2, 1.5}, {-4, 0}, {-2, -1.5}};

// minimum-eccentricity weights (eq. 16): elliptic pieces
fair::Kappa_curve_2<K> closed_kappa(const std::vector<Point>& points) {
  fair::Kappa_curve_options o;
  o.closed = true;
  o.weights = fair::Kappa_weights::AUTOMATIC;
  return fair::Kappa_curve_2<K>(points, o);
}

TEST(Arrangement_curves, SelfIntersectionOfOutlinesConicArcs) {
  for (const auto& c : {std::make_pair(&simple_outline, std::size_t(0)), std::make_pair(&figure_eight, std::size_t(1))}) {
    const fair::Nurbs_curve_2<K> curve = kappa_nurbs(closed_kappa(*c.first));
    ASSERT_TRUE(curve.is_rational());
    for (double w : curve.weights()) EXPECT_LE(w, 1.0);
    std::vector<Conic_traits::Curve_2> arcs;
    fair::to_arrangement_curves<Conic_traits>(curve, std::back_inserter(arcs));
    Conic_arrangement arr;
    CGAL::insert(arr, arcs.begin(), arcs.end());
    expect_simple_closed(arr, c.second);
  }
}

TEST(Arrangement_curves, SelfIntersectionOfOutlinesBezierCurves) {
  for (const auto& c : {std::make_pair(&simple_outline, std::size_t(0)), std::make_pair(&figure_eight, std::size_t(1))}) {
    fair::Cubic_interpolating_spline_options o;
    o.closed = true;
    const fair::Nurbs_curve_2<K> curve = fair::Cubic_interpolating_spline_2<K>(*c.first, o).spline().nurbs();
    std::vector<Bezier_traits::Curve_2> curves;
    fair::to_arrangement_curves<Bezier_traits>(curve, std::back_inserter(curves));
    Bezier_arrangement arr;
    CGAL::insert(arr, curves.begin(), curves.end());
    expect_simple_closed(arr, c.second);
  }
}

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
