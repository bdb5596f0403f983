// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair/occt/Geom2d_conversion.h against OpenCASCADE itself (issue 26 §2): OCCT evaluates the
// converted curve (D0, D2) and measures its curvature (Geom2dLProp_CLProps2d) as the library
// does, on open and closed, polynomial and rational curves of several families; OCCT's own
// curvature analysis (Geom2dLProp_CurAndInf2d) finds the maxima of a kappa-curve at its input
// points; the round trip returns the same knots, control points and weights; a curve made by
// OCCT (periodic, multiple knots) converts to the library's form with OCCT's parametrisation.
// Built only where OCCT is found (test/CMakeLists.txt, target fair::occt).

#include <fair/Cubic_bspline_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/Kappa_curve_2.h>
#include <fair/Nurbs_curve_2.h>
#include <fair/occt/Geom2d_conversion.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Geom2dLProp_CLProps2d.hxx>
#include <Geom2dLProp_CurAndInf2d.hxx>
#include <LProp_CIType.hxx>
#include <gp_Vec2d.hxx>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
typedef K::Point_2 Point;
typedef fair::Nurbs_curve_2<K> Nurbs;

// The kappa-curve as a degree-2 NURBS built here from its pieces (double interior knots at the
// integers, piece j on [j, j+1]; closed: the periodic form with u_p the last copy of its knot),
// independently of the family's own nurbs().
template <class Kernel>
fair::Nurbs_curve_2<Kernel> kappa_nurbs(const fair::Kappa_curve_2<Kernel>& c) {
  typedef typename Kernel::FT FT;
  const std::size_t m = c.number_of_pieces();
  std::vector<typename Kernel::Point_2> P;
  std::vector<FT> w;
  for (std::size_t j = 0; j < m; ++j) {
    P.push_back(c.piece(j).source());
    w.push_back(FT(1));
    P.push_back(c.piece(j).control_point(1));
    w.push_back(c.piece(j).weight());
  }
  std::vector<FT> u;
  if (c.is_closed()) {  // (-1, 0,0, 1,1, ..., m,m, m+1,m+1): n + p + 1 = 2m + 5 knots
    u.push_back(FT(-1));
    for (std::size_t j = 0; j <= m + 1; ++j) u.insert(u.end(), 2, FT(static_cast<int>(j)));
    for (std::size_t k = 0; k < 2; ++k) {
      P.push_back(P[k]);
      w.push_back(w[k]);
    }
  } else {  // (0,0,0, 1,1, ..., m-1,m-1, m,m,m)
    P.push_back(c.piece(m - 1).target());
    w.push_back(FT(1));
    u.push_back(FT(0));
    for (std::size_t j = 0; j <= m; ++j) u.insert(u.end(), 2, FT(static_cast<int>(j)));
    u.push_back(FT(static_cast<int>(m)));
  }
  return fair::Nurbs_curve_2<Kernel>(2, u, P, w, c.is_closed());
}

const std::vector<Point> outline = {{4, 0}, {2.8, 2.1}, {0, 3}, {-2.9, 2}, {-4, 0.2}, {-2.7, -2.2}, {0.3, -3}, {2.9, -2}};

fair::Kappa_curve_options kappa_options(bool closed, bool rational, std::size_t points = outline.size()) {
  fair::Kappa_curve_options o;
  o.closed = closed;
  if (rational) {  // weights != 1: 1.2 (hyperbolic pieces; INTERIOR on the data below)
    o.weights = fair::Kappa_weights::FIXED;
    o.fixed_weights.assign(points, 1.2);
  }
  return o;
}

double extent(const Nurbs& c) {
  double e = 0;
  for (const Point& p : c.control_points()) e = std::max({e, std::abs(p.x()), std::abs(p.y())});
  return e;
}

// OCCT's D0, D2 and CLProps2d curvature agree with point(), derivatives(), curvature() at
// parameters off the knots (at a C0 knot the one-sided derivatives differ by design).
void expect_same_evaluation(const Nurbs& c, const Handle(Geom2d_BSplineCurve)& g, const std::string& what) {
  SCOPED_TRACE(what);
  const auto dom = c.domain();
  ASSERT_EQ(g->FirstParameter(), dom.first);
  ASSERT_EQ(g->LastParameter(), dom.second);
  EXPECT_EQ(g->IsPeriodic(), c.is_closed());
  EXPECT_EQ(g->IsRational(), c.is_rational());
  const double e = extent(c);
  const int samples = 97;
  for (int s = 0; s < samples; ++s) {
    const double u = dom.first + (dom.second - dom.first) * (s + 0.3183098861837907) / samples;
    const std::vector<K::Vector_2> d = c.derivatives(u, 2);
    gp_Pnt2d p;
    gp_Vec2d d1, d2;
    g->D2(u, p, d1, d2);
    EXPECT_NEAR(p.X(), d[0].x(), 1e-13 * e) << "u = " << u;
    EXPECT_NEAR(p.Y(), d[0].y(), 1e-13 * e) << "u = " << u;
    const double s1 = std::hypot(d[1].x(), d[1].y()), s2 = std::hypot(d[2].x(), d[2].y()) + s1;
    EXPECT_NEAR(d1.X(), d[1].x(), 1e-11 * s1) << "u = " << u;
    EXPECT_NEAR(d1.Y(), d[1].y(), 1e-11 * s1) << "u = " << u;
    EXPECT_NEAR(d2.X(), d[2].x(), 1e-10 * s2) << "u = " << u;
    EXPECT_NEAR(d2.Y(), d[2].y(), 1e-10 * s2) << "u = " << u;
    Geom2dLProp_CLProps2d props(g, u, 2, 1e-12);
    ASSERT_TRUE(props.IsTangentDefined());
    const double k = c.curvature(u);
    // OCCT's Curvature() is unsigned (|d1 x d2| / |d1|^3); the sign is in its Normal()
    EXPECT_NEAR(props.Curvature(), std::abs(k), 1e-10 * (std::abs(k) + 1 / e)) << "u = " << u;
  }
}

void expect_same_form(const Nurbs& a, const Nurbs& b) {
  EXPECT_EQ(a.degree(), b.degree());
  EXPECT_EQ(a.is_closed(), b.is_closed());
  EXPECT_EQ(a.knots(), b.knots());
  EXPECT_EQ(a.control_points(), b.control_points());
  EXPECT_EQ(a.weights(), b.weights());
}

struct Case {
  std::string name;
  Nurbs curve;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (bool closed : {false, true}) {
    const std::string tag = closed ? "closed" : "open";
    fair::Cubic_interpolating_spline_options io;
    io.closed = closed;
    const fair::Cubic_interpolating_spline_2<K> interpolating(outline, io);
    out.push_back({"interpolating spline " + tag, interpolating.spline().nurbs()});
    fair::Cubic_bspline_options bo;
    bo.closed = closed;
    out.push_back({"B-spline " + tag, fair::Cubic_bspline_2<K>(outline, bo).spline().nurbs()});
    // a rational cubic spline: the interpolating spline's control points with weights 0.5 .. 2
    const fair::Cubic_spline_2<K>& s = interpolating.spline();
    std::vector<double> w;
    for (std::size_t i = 0; i < s.control_points().size(); ++i) w.push_back(i % 3 == 0 ? 0.5 : (i % 3 == 1 ? 2.0 : 1.25));
    out.push_back({"rational cubic spline " + tag,
                   fair::Cubic_spline_2<K>(s.breakpoints(), s.control_points(), w, closed).nurbs()});
    out.push_back({"kappa " + tag, kappa_nurbs(fair::Kappa_curve_2<K>(outline, kappa_options(closed, false)))});
    out.push_back({"rational kappa " + tag, kappa_nurbs(fair::Kappa_curve_2<K>(outline, kappa_options(closed, true)))});
  }
  // degree 4, rational, knots of multiplicity 1..3, open (clamped) and closed (periodic; the
  // domain starts at the last copy of a double knot)
  out.push_back({"degree 4 open",
                 Nurbs(4, {0, 0, 0, 0, 0, 1, 1, 2, 2, 2, 3.5, 5, 5, 5, 5, 5},
                       {{0, 0}, {1, 2}, {2, -1}, {4, 1}, {5, 3}, {4, 5}, {2, 4}, {1, 6}, {-1, 3}, {-2, 1}, {-1, -1}},
                       {1, 0.5, 2, 1, 0.75, 1.5, 1, 3, 0.8, 1, 1}, false)});
  {
    const std::vector<Point> P = {{0, 0}, {3, -1}, {5, 1}, {6, 4}, {3, 6}, {0, 5}, {-2, 2}};
    const std::vector<double> W = {1, 0.5, 2, 1.5, 1, 0.7, 1.2};
    // p = 3, N = 7 unique points, one period of knots 0 (double), 1, 2, 3, 4, 5 (T = 6, multiplicities summing to 7)
    std::vector<double> u = {-2, -1, 0, 0, 1, 2, 3, 4, 5, 6, 6, 7, 8, 9};  // u_3 = 0 is the last copy
    std::vector<Point> Pc = P;
    std::vector<double> Wc = W;
    for (int k = 0; k < 3; ++k) {
      Pc.push_back(P[static_cast<std::size_t>(k)]);
      Wc.push_back(W[static_cast<std::size_t>(k)]);
    }
    out.push_back({"degree 3 closed double knots", Nurbs(3, u, Pc, Wc, true)});
  }
  return out;
}

TEST(Occt_geom2d, EvaluationAndCurvatureAgree) {
  for (const Case& c : cases()) {
    const Handle(Geom2d_BSplineCurve) g = fair::occt::to_geom2d_bspline(c.curve);
    ASSERT_FALSE(g.IsNull());
    expect_same_evaluation(c.curve, g, c.name);
  }
}

TEST(Occt_geom2d, RoundTripIsTheIdentity) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    expect_same_form(c.curve, fair::occt::from_geom2d_bspline<K>(fair::occt::to_geom2d_bspline(c.curve)));
  }
}

// The kappa-curve's curvature maxima are its input points (Yan et al., Theorem: |kappa| has
// exactly one maximum per piece, at its interpolated point). OCCT's analysis of the converted
// curve, knowing nothing of that, finds a curvature maximum at every input point's parameter,
// and no other. (OCCT's types name the radius of curvature: LProp_MinCur is a minimum of the
// radius, a maximum of |kappa| -- LProp_CurAndInf.hxx.)
TEST(Occt_geom2d, CurAndInfFindsTheKappaMaximaAtTheInputPoints) {
  for (bool closed : {false, true})
    for (bool rational : {false, true}) {
      SCOPED_TRACE(std::string(closed ? "closed" : "open") + (rational ? " rational" : " polynomial"));
      // open: a wave (an S-shaped run of inflections between the maxima)
      const std::vector<Point> wave = {{0, 0}, {2, 1.5}, {4, 0.5}, {6, 2}, {8, 0}, {10, 1.5}};
      const std::vector<Point>& points = closed ? outline : wave;
      const fair::Kappa_curve_2<K> kappa(points, kappa_options(closed, rational, points.size()));
      ASSERT_EQ(kappa.status(), fair::Kappa_curve_status::INTERIOR);
      const Nurbs c = kappa_nurbs(kappa);
      EXPECT_EQ(c.is_rational(), rational);
      const Handle(Geom2d_BSplineCurve) g = fair::occt::to_geom2d_bspline(c);
      Geom2dLProp_CurAndInf2d analysis;
      analysis.PerformCurExt(g);
      ASSERT_TRUE(analysis.IsDone());
      std::vector<double> maxima;
      for (int i = 1; i <= analysis.NbPoints(); ++i)
        if (analysis.Type(i) == LProp_MinCur) maxima.push_back(analysis.Parameter(i));
      std::sort(maxima.begin(), maxima.end());
      ASSERT_EQ(maxima.size(), kappa.number_of_pieces());
      for (std::size_t j = 0; j < kappa.number_of_pieces(); ++j) {
        const double u = static_cast<double>(j) + kappa.t(j);
        EXPECT_NEAR(maxima[j], u, 1e-7) << "piece " << j;
        const gp_Pnt2d p = g->Value(maxima[j]);
        const Point& q = kappa.points()[kappa.point_index(j)];
        // OCCT locates an extremum to about 1e-9 in u (its own tolerance): 2e-9 in the point here
        EXPECT_NEAR(p.X(), q.x(), 1e-8) << "piece " << j;
        EXPECT_NEAR(p.Y(), q.y(), 1e-8) << "piece " << j;
      }
    }
}

// A curve made by OCCT: periodic, degree 3, knots 0 (mult 2), 1, 2, 3, 4, 5 (mult 2): the
// library's form (u_p at the last copy of its knot) evaluates as OCCT does.
TEST(Occt_geom2d, FromAnOcctPeriodicCurve) {
  TColgp_Array1OfPnt2d poles(1, 6);
  TColStd_Array1OfReal weights(1, 6);
  const double xy[6][2] = {{0, 0}, {2, -1}, {4, 0.5}, {4.5, 3}, {2, 4}, {-0.5, 2}};
  for (int j = 1; j <= 6; ++j) {
    poles(j) = gp_Pnt2d(xy[j - 1][0], xy[j - 1][1]);
    weights(j) = 0.5 + 0.25 * j;
  }
  TColStd_Array1OfReal knots(1, 6);
  TColStd_Array1OfInteger mults(1, 6);
  for (int i = 1; i <= 6; ++i) {
    knots(i) = i - 1;
    mults(i) = (i == 1 || i == 6) ? 2 : 1;
  }
  const Handle(Geom2d_BSplineCurve) g = new Geom2d_BSplineCurve(poles, weights, knots, mults, 3, true);
  const Nurbs c = fair::occt::from_geom2d_bspline<K>(g);
  EXPECT_TRUE(c.is_closed());
  EXPECT_EQ(c.number_of_control_points(), 6u + 3u);
  // the library's knots: OCCT's flat sequence -2 -1 0 0 1 2 3 4 5 5 6 7, extended by the period
  EXPECT_EQ(c.knots(), (std::vector<double>{-2, -1, 0, 0, 1, 2, 3, 4, 5, 5, 6, 7, 8}));
  expect_same_evaluation(c, g, "OCCT periodic");
  // and back: OCCT's own form again
  const Handle(Geom2d_BSplineCurve) h = fair::occt::to_geom2d_bspline(c);
  ASSERT_EQ(h->NbPoles(), 6);
  for (int j = 1; j <= 6; ++j) {
    EXPECT_EQ(h->Pole(j).X(), g->Pole(j).X());
    EXPECT_EQ(h->Pole(j).Y(), g->Pole(j).Y());
    EXPECT_EQ(h->Weight(j), g->Weight(j));
    EXPECT_EQ(h->Knot(j), g->Knot(j));
    EXPECT_EQ(h->Multiplicity(j), g->Multiplicity(j));
  }
}

// A closed curve whose u_p is the first copy of its knot (the other legal placement): the same
// kappa-curve with the window shifted by one, u' = (-1,-1, 0,0, 1,1, ..., m,m, m+1) and
// P'_k = P_{k-1} (P'_0 the last middle point). The conversion shifts OCCT's pole numbering by
// s = a - (p + 1 - m_1) = 2 - 1 = 1 (0 for the last-copy form) and OCCT traces the same curve;
// back, the same curve in the last-copy form, exactly.
TEST(Occt_geom2d, ClosedFormWithTheDomainAtTheFirstCopy) {
  const fair::Kappa_curve_2<K> kappa(outline, kappa_options(true, true));
  const Nurbs last = kappa_nurbs(kappa);
  const std::size_t N = last.number_of_control_points() - 2, m = N / 2;
  std::vector<Point> P;
  std::vector<double> w;
  for (std::size_t k = 0; k < N + 2; ++k) {
    const std::size_t i = (k + N - 1) % N;
    P.push_back(last.control_points()[i]);
    w.push_back(last.weights()[i]);
  }
  std::vector<double> u = {-1, -1};
  for (std::size_t j = 0; j <= m; ++j) u.insert(u.end(), 2, static_cast<double>(j));
  u.push_back(static_cast<double>(m + 1));
  ASSERT_EQ(u.size(), N + 2 + 3);
  const Nurbs first(2, u, P, w, true);
  for (double x : {0.1, 0.5, 1.7, 2.25, 3.9, 6.5})
    EXPECT_LT(CGAL::squared_distance(first.point(x), last.point(x)), 1e-28) << "u = " << x;
  const Handle(Geom2d_BSplineCurve) g = fair::occt::to_geom2d_bspline(first);
  expect_same_evaluation(first, g, "first copy");
  expect_same_form(fair::occt::from_geom2d_bspline<K>(g), last);
}

// Exact kernels: to_geom2d_bspline rounds each number once, from_geom2d_bspline is exact.
TEST(Occt_geom2d, ExactKernel) {
  const fair::Nurbs_curve_2<EK> c(2, {0, 0, 0, EK::FT(1) / 3, 1, 1, 1},
                                  {{0, 0}, {EK::FT(1) / 3, 1}, {1, 1}, {2, 0}}, {1, EK::FT(2) / 3, 1, 1}, false);
  const Handle(Geom2d_BSplineCurve) g = fair::occt::to_geom2d_bspline(c);
  // CGAL::to_double: within one ulp (not necessarily the nearest double)
  const auto ulp = [](double x) { return std::nextafter(x, 2 * x) - x; };
  EXPECT_NEAR(g->Knot(2), 1.0 / 3, ulp(1.0 / 3));
  EXPECT_NEAR(g->Pole(2).X(), 1.0 / 3, ulp(1.0 / 3));
  EXPECT_NEAR(g->Weight(2), 2.0 / 3, ulp(2.0 / 3));
  const fair::Nurbs_curve_2<EK> back = fair::occt::from_geom2d_bspline<EK>(g);
  EXPECT_EQ(back.knots()[3], EK::FT(g->Knot(2)));  // the double, exactly
  EXPECT_EQ(back.weights()[1], EK::FT(g->Weight(2)));
  EXPECT_NE(back.knots()[3], EK::FT(1) / 3);
  for (double x : {0.1, 0.5, 0.9}) {
    const gp_Pnt2d p = g->Value(x);
    EXPECT_NEAR(p.X(), CGAL::to_double(back.point(x).x()), 1e-15);
    EXPECT_NEAR(p.Y(), CGAL::to_double(back.point(x).y()), 1e-15);
  }
}

TEST(Occt_geom2d, Errors) {
  EXPECT_THROW(fair::occt::from_geom2d_bspline<K>(Handle(Geom2d_BSplineCurve)()), fair::Precondition_error);
  // two exact knots 1/3 and 1/3 + 2^-80 become one double knot of multiplicity 2 > p = 1
  const EK::FT third = EK::FT(1) / 3, eps = EK::FT(std::ldexp(1.0, -80));
  const fair::Nurbs_curve_2<EK> fold(1, {0, 0, third, third + eps, 1, 1}, {{0, 0}, {1, 1}, {2, 0}, {3, 1}});
  EXPECT_THROW(fair::occt::to_geom2d_bspline(fold), fair::Precondition_error);
  // degree 26 > Geom2d_BSplineCurve::MaxDegree() = 25
  std::vector<double> u(27, 0.0);
  u.insert(u.end(), 27, 1.0);
  std::vector<Point> P;
  for (int k = 0; k < 27; ++k) P.push_back(Point(k, k % 2));
  EXPECT_THROW(fair::occt::to_geom2d_bspline(Nurbs(26, u, P)), fair::Precondition_error);
}

}  // namespace
