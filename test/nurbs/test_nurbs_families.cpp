// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// nurbs() of the constructive families is their pieces (issue 26 §1), open and closed, exactly
// in EPECK and Simple_cartesian<Gmpq> (and to rounding in double): Cardinal_spline_2 and
// Catmull_rom_2 (degree 3, C1: interior knots of multiplicity 2, the seam of a closed curve too),
// the C2 cubics Cubic_interpolating_spline_2, Cubic_bspline_2, Cubic_quasi_interpolant_2 and
// Csr_spline_2 (single knots, the spline's breakpoints), Four_point_subdivision_2 (degree 1 on
// the segment indices), the basic-shape designs and the exact conversion of a conic (checked
// against the conic's own evaluation on all of [0, 1]). Each family's documented knots are
// checked value by value. Data: a few small integer points, so the exact cases stay cheap.

#include "family_checks.h"

#include <fair/Basic_shape_design.h>
#include <fair/Cardinal_spline_2.h>
#include <fair/Catmull_rom_2.h>
#include <fair/Csr_spline_2.h>
#include <fair/Cubic_bspline_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Cubic_quasi_interpolant_2.h>
#include <fair/Exact_spline_conversion.h>
#include <fair/Four_point_subdivision_2.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using fair_test::expect_nurbs_is_pieces;
using fair_test::interior_multiplicities;
using fair_test::same;

template <class K>
class Nurbs_families : public ::testing::Test {};
TYPED_TEST_SUITE(Nurbs_families, fair_test::Family_kernels);

template <class K>
std::vector<typename K::Point_2> open_points() {
  typedef typename K::Point_2 P;
  return {P(0, 0), P(1, 2), P(3, 3), P(5, 1), P(6, -1)};
}
template <class K>
std::vector<typename K::Point_2> closed_points() {
  typedef typename K::Point_2 P;
  return {P(0, 0), P(4, 0), P(5, 3), P(2, 5), P(-1, 3)};
}

template <class K>
std::vector<typename K::FT> indices(std::size_t m) {
  std::vector<typename K::FT> t;
  for (std::size_t j = 0; j <= m; ++j) t.push_back(typename K::FT(static_cast<int>(j)));
  return t;
}

TYPED_TEST(Nurbs_families, CardinalIsDegree3WithDoubleKnotsAtTheSegmentIndices) {
  typedef TypeParam K;
  for (bool closed : {false, true}) {
    fair::Cardinal_spline_options o;
    o.closed = closed;
    const fair::Cardinal_spline_2<K> c(closed ? closed_points<K>() : open_points<K>(), o);
    const fair::Nurbs_curve_2<K> n = c.nurbs();
    EXPECT_EQ(n.degree(), 3u);
    EXPECT_EQ(n.is_closed(), closed);
    EXPECT_FALSE(n.is_rational());
    EXPECT_EQ(n.breakpoints(), indices<K>(c.number_of_pieces()));
    EXPECT_EQ(interior_multiplicities(n), std::vector<std::size_t>(c.number_of_pieces() - 1, 2)) << "C1";
    if (closed) {  // the seam is a double knot as well (C1 there too)
      EXPECT_EQ(std::count(n.knots().begin(), n.knots().end(), n.domain().first), 2);
      EXPECT_EQ(n.number_of_control_points(), 2 * c.number_of_pieces() + 3);
    } else {
      EXPECT_EQ(n.number_of_control_points(), 2 * c.number_of_pieces() + 2);
    }
    expect_nurbs_is_pieces(n, c.pieces(), closed ? "closed" : "open");
  }
}

TYPED_TEST(Nurbs_families, CatmullRomIsDegree3WithDoubleKnotsAtItsKnots) {
  typedef TypeParam K;
  for (bool closed : {false, true}) {
    fair::Catmull_rom_options o;
    o.closed = closed;
    o.knot_spacing = closed ? fair::Knot_spacing::CHORDAL : fair::Knot_spacing::UNIFORM;
    const fair::Catmull_rom_2<K> c(closed ? closed_points<K>() : open_points<K>(), o);
    const fair::Nurbs_curve_2<K> n = c.nurbs();
    EXPECT_EQ(n.degree(), 3u);
    EXPECT_EQ(n.is_closed(), closed);
    EXPECT_EQ(n.breakpoints(), c.knots());
    EXPECT_EQ(interior_multiplicities(n), std::vector<std::size_t>(c.number_of_pieces() - 1, 2));
    // the derivative with respect to u at a knot is the family's derivative m_i (C1 in u)
    for (std::size_t i = 1; i < c.number_of_pieces(); ++i)
      EXPECT_TRUE(same<K>(n.derivative(c.knots()[i]), c.derivatives()[i], 1e-11)) << "knot " << i;
    expect_nurbs_is_pieces(n, c.pieces(), closed ? "closed chordal" : "open uniform");
  }
}

// The C2 families are their spline: single interior knots at its breakpoints.
template <class K, class Curve>
void expect_c2_family(const Curve& c, const std::string& what) {
  const fair::Nurbs_curve_2<K> n = c.nurbs();
  SCOPED_TRACE(what);
  EXPECT_EQ(n.degree(), 3u);
  EXPECT_EQ(n.is_closed(), c.is_closed());
  EXPECT_FALSE(n.is_rational());
  EXPECT_EQ(n.breakpoints(), c.spline().breakpoints());
  EXPECT_EQ(interior_multiplicities(n), std::vector<std::size_t>(c.number_of_pieces() - 1, 1));
  expect_nurbs_is_pieces(n, c.pieces(), what);
}

TYPED_TEST(Nurbs_families, TheC2CubicsAreTheirSplineWithSingleKnots) {
  typedef TypeParam K;
  for (bool closed : {false, true}) {
    const std::vector<typename K::Point_2> p = closed ? closed_points<K>() : open_points<K>();
    fair::Cubic_interpolating_spline_options io;
    io.closed = closed;
    io.end_condition = fair::Spline_end_condition::NOT_A_KNOT;
    expect_c2_family<K>(fair::Cubic_interpolating_spline_2<K>(p, io), "interpolating");
    fair::Cubic_bspline_options bo;
    bo.closed = closed;
    expect_c2_family<K>(fair::Cubic_bspline_2<K>(p, bo), "bspline");
    fair::Cubic_quasi_interpolant_options qo;
    qo.closed = closed;
    expect_c2_family<K>(fair::Cubic_quasi_interpolant_2<K>(p, qo), "quasi");
    fair::Csr_spline_options co;
    co.closed = closed;
    co.knot_spacing = fair::Knot_spacing::UNIFORM;
    expect_c2_family<K>(fair::Csr_spline_2<K>(p, co), "csr");
  }
}

TYPED_TEST(Nurbs_families, FourPointIsItsPolylineOfDegree1) {
  typedef TypeParam K;
  for (bool closed : {false, true}) {
    fair::Four_point_subdivision_options o;
    o.closed = closed;
    o.rounds = 2;
    const fair::Four_point_subdivision_2<K> c(closed ? closed_points<K>() : open_points<K>(), o);
    const fair::Nurbs_curve_2<K> n = c.nurbs();
    EXPECT_EQ(n.degree(), 1u);
    EXPECT_EQ(n.is_closed(), closed);
    EXPECT_EQ(n.breakpoints(), indices<K>(c.number_of_pieces()));
    std::vector<typename K::Point_2> polygon = c.polyline();
    if (closed) polygon.push_back(polygon.front());  // the periodic form repeats p = 1 point
    EXPECT_EQ(n.control_points(), polygon);
    expect_nurbs_is_pieces(n, c.pieces(), closed ? "closed" : "open");
  }
}

TYPED_TEST(Nurbs_families, BasicShapeDesignsAndShapes) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  typedef fair::Basic_shape_2<K> Shape;
  // a quarter ellipse (w = 1/2) and two segments, closed: one periodic C2 spline
  const fair::Rational_quadratic_bezier_2<K> arc(P(1, 0), P(1, 1), P(0, 1), FT(1) / FT(2));
  const std::vector<Shape> shapes{Shape::conic(arc, {FT(1) / FT(2)}), Shape::segment(P(0, 1), P(0, 0)),
                                  Shape::segment(P(0, 0), P(1, 0), {FT(1) / FT(3)})};
  fair::Basic_shape_design_options o;
  o.closed = true;
  const fair::Basic_shape_design_2<K> d = fair::basic_shape_design(shapes, o);
  const fair::Nurbs_curve_2<K> n = d.nurbs();
  EXPECT_TRUE(n.is_closed());
  EXPECT_TRUE(n.is_rational());
  EXPECT_EQ(n.breakpoints(), d.spline.breakpoints());
  expect_nurbs_is_pieces(n, d.spline.pieces(), "closed design");
  // A shape of several parts: a circle arc of 270 degrees, split into two sub-arcs of 135.
  const Shape c = Shape::circle_arc(P(0, 0), FT(2), 0.0, 1.5 * M_PI);
  ASSERT_EQ(c.parts().size(), 2u);
  const fair::Nurbs_curve_2<K> s = c.nurbs();
  std::vector<fair::Rational_bezier_2<K>> pieces;
  for (const auto& part : c.parts())
    for (const auto& piece : part.pieces()) pieces.push_back(piece);
  EXPECT_FALSE(s.is_closed());
  // knot multiplicity 3 where the sub-arcs meet (C0 in u there), the parts' own knots elsewhere
  const std::vector<std::size_t> m = interior_multiplicities(s);
  EXPECT_EQ(std::count(m.begin(), m.end(), 3u), 1);
  expect_nurbs_is_pieces(s, pieces, "circle arc of two parts");
}

// The exact conversion of a conic arc: the NURBS of exact_spline(f, marks) is f on all of [0, 1]
// (the breakpoints 0, 1/3, 1/2, 1), checked against f's own evaluation.
TYPED_TEST(Nurbs_families, ExactConversionIsTheConicEverywhere) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  const fair::Rational_quadratic_bezier_2<K> f(P(0, 0), P(2, 3), P(5, 1), FT(3) / FT(4));
  const fair::Nurbs_curve_2<K> n = fair::exact_spline(f, {FT(1) / FT(3), FT(1) / FT(2)}).nurbs();
  EXPECT_TRUE(n.is_rational());
  EXPECT_EQ(n.breakpoints(), (std::vector<FT>{FT(0), FT(1) / FT(3), FT(1) / FT(2), FT(1)}));
  for (int k = 0; k <= 12; ++k) {
    const FT u = FT(k) / FT(12);
    EXPECT_TRUE(same<K>(n.point(u), f.point(u), 1e-13)) << "u = " << k << "/12";
  }
  // a polynomial cubic converts to a polynomial NURBS
  const fair::Bezier_2<K> g(std::vector<P>{P(0, 0), P(1, 3), P(4, 3), P(5, 0)});
  const fair::Nurbs_curve_2<K> m = fair::exact_spline(g, {FT(2) / FT(5)}).nurbs();
  EXPECT_FALSE(m.is_rational());
  for (int k = 0; k <= 10; ++k) EXPECT_TRUE(same<K>(m.point(FT(k) / FT(10)), g.point(FT(k) / FT(10)), 1e-13));
}

// The assembly's checks (internal/nurbs/assembly.h; review findings 6, 7, 8): pieces that do not
// join, a closed loop that does not close, Hermite pieces that are not C1, and a closed rational
// loop whose end-weight ratios do not multiply to 1 are Precondition_errors naming the pieces;
// a closed rational loop with end weights != 1 whose ratios multiply to 1 is accepted and is its
// pieces. Gaps of 1/1024; in double a gap of 1e-14 (rounding) is accepted, in the exact
// kernels refused.
template <class F>
std::string message_of(F make) {
  try {
    make();
  } catch (const fair::Precondition_error& e) {
    return e.what();
  }
  return "no error";
}

TYPED_TEST(Nurbs_families, AssemblyChecksTheJoins) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  typedef fair::Bezier_2<K> B;
  using fair::internal::nurbs::bezier_pieces_nurbs;
  using fair::internal::nurbs::hermite_cubic_nurbs;
  const FT gap = FT(1) / FT(1024);
  const std::vector<B> loop{B({P(0, 0), P(1, 1), P(2, 0)}), B({P(2, 0), P(3, 1), P(4, 0)}), B({P(4, 0), P(3, -2), P(0, 0)})};
  expect_nurbs_is_pieces(bezier_pieces_nurbs<K>(loop, true, "loop"), loop, "the loop");
  std::vector<B> broken = loop;  // piece 1 starts off piece 0's end
  broken[1] = B({P(2, gap), P(3, 1), P(4, 0)});
  const std::string m = message_of([&] { bezier_pieces_nurbs<K>(broken, false, "who"); });
  EXPECT_NE(m.find("who: piece 0 ends at (2, 0) but piece 1 starts at (2, 0.0009765625)"), std::string::npos) << m;
  EXPECT_NE(m.find("not continuous (C0)"), std::string::npos) << m;
  std::vector<B> open = loop;  // the last piece ends off the first's start: open is fine, closed is not
  open[2] = B({P(4, 0), P(3, -2), P(0, gap)});
  EXPECT_NO_THROW(bezier_pieces_nurbs<K>(open, false, "who"));
  const std::string c = message_of([&] { bezier_pieces_nurbs<K>(open, true, "who"); });
  EXPECT_NE(c.find("piece 2 ends at (0, 0.0009765625) but piece 0 starts at (0, 0): the closed loop does not close"), std::string::npos) << c;
  // a gap of rounding size: accepted in double (2^-36 of the extent 4), refused exactly
  std::vector<B> near = loop;
  near[1] = B({P(FT(2) + FT(1e-14), FT(0)), P(3, 1), P(4, 0)});
  if (fair_test::is_exact<K>()) {
    EXPECT_THROW(bezier_pieces_nurbs<K>(near, true, "who"), fair::Precondition_error);
  } else {
    EXPECT_NO_THROW(bezier_pieces_nurbs<K>(near, true, "who"));
  }

  // Hermite cubics on t = 0, 1, 3: C1 in t when (b3 - b2) / 1 = (b1' - b0') / 2
  const std::vector<FT> t{FT(0), FT(1), FT(3)};
  const std::vector<B> c1{B(P(0, 0), P(1, 1), P(2, 1), P(3, 0)), B(P(3, 0), P(5, -2), P(6, 0), P(7, 2))};
  EXPECT_NO_THROW(hermite_cubic_nurbs<K>(c1, t, false, "who"));
  std::vector<B> kink = c1;
  kink[1] = B(P(3, 0), P(5, -1), P(6, 0), P(7, 2));
  const std::string k = message_of([&] { hermite_cubic_nurbs<K>(kink, t, false, "who"); });
  EXPECT_NE(k.find("piece 0 ends at (3, 0) but the join the NURBS forms, (h_{j+1} b^j_2 + h_j b^{j+1}_1) / (h_j + h_{j+1}), of pieces 0 and 1 is (3, 0.333"),
            std::string::npos) << k;
  EXPECT_NE(k.find("the pieces are not C1 in the parameter there"), std::string::npos) << k;
  std::vector<B> apart = c1;
  apart[1] = B(P(FT(3), gap), P(5, -2), P(6, 0), P(7, 2));
  EXPECT_NE(message_of([&] { hermite_cubic_nurbs<K>(apart, t, false, "who"); }).find("not continuous (C0)"), std::string::npos);
  EXPECT_NE(message_of([&] { hermite_cubic_nurbs<K>(c1, t, true, "who"); }).find("piece 1 ends at (7, 2) but piece 0 starts at (0, 0): the closed loop does not close"),
            std::string::npos);

  // Rational loops: the weights are scaled to agree at each join; around the loop the scale is
  // the product of w_2 / w_0 over the pieces (here 2 * 1/2 * 1 = 1: accepted, end weights != 1)
  typedef fair::Rational_bezier_2<K> R;
  const std::vector<R> rational{R({P(0, 0), P(1, 1), P(2, 0)}, {FT(1), FT(3), FT(2)}),
                                R({P(2, 0), P(3, 1), P(4, 0)}, {FT(4), FT(1), FT(2)}),
                                R({P(4, 0), P(3, -2), P(0, 0)}, {FT(3), FT(1), FT(3)})};
  const fair::Nurbs_curve_2<K> r = bezier_pieces_nurbs<K>(rational, true, "rational loop");
  EXPECT_TRUE(r.is_closed());
  expect_nurbs_is_pieces(r, rational, "rational loop, end weights != 1, product 1");
  std::vector<R> twisted = rational;  // product 2 * 1/2 * 2 = 2
  twisted[2] = R({P(4, 0), P(3, -2), P(0, 0)}, {FT(3), FT(1), FT(6)});
  EXPECT_NO_THROW(bezier_pieces_nurbs<K>(twisted, false, "who"));
  const std::string w = message_of([&] { bezier_pieces_nurbs<K>(twisted, true, "who"); });
  EXPECT_NE(w.find("who: a closed loop of rational pieces whose end-weight ratios w_p / w_0 multiply to 2, not 1"), std::string::npos) << w;
}

}  // namespace
