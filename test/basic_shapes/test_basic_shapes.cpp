// Tests of fair/Basic_shape_design.h and fair/io/read_design.h: the shapes as splines (exact),
// the merge of Fig. 9 (agree / averaged / edge, open and closed), the exact reproduction of every
// shape on its interior [u_2, u_{m-2}] (the knot decision of doc/basic_shapes.md), C^2 of the
// merged and of the edited spline, and every error of the design file.

#include "test_support.h"

#include <fair/Basic_shape_design.h>
#include <fair/Parametric_curve_2.h>
#include <fair/Spline_convexity.h>
#include <fair/io/read_design.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using fair_test::q;
using fair_test::same;

template <class K>
class Shapes : public ::testing::Test {};
TYPED_TEST_SUITE(Shapes, fair_test::All_kernels);

template <class K>
class Shapes_float : public ::testing::Test {};
TYPED_TEST_SUITE(Shapes_float, fair_test::Floating_kernels);

// The circle arc of issue 10 with rational tan(alpha/4): w = 3/5, P0 = (1,0), P1 = (1,4/3),
// P2 = (-7/25,24/25) (cos alpha = -7/25), and the same arc rotated by alpha, which starts where the
// first ends: both exactly rational.
template <class K>
fair::Rational_quadratic_bezier_2<K> arc1() {
  typedef typename K::Point_2 P;
  return fair::Rational_quadratic_bezier_2<K>(P(1, 0), P(1, q<K>(4, 3)), P(q<K>(-7, 25), q<K>(24, 25)), q<K>(3, 5));
}
template <class K>
fair::Rational_quadratic_bezier_2<K> arc2() {
  typedef typename K::Point_2 P;
  return fair::Rational_quadratic_bezier_2<K>(P(q<K>(-7, 25), q<K>(24, 25)), P(q<K>(-39, 25), q<K>(44, 75)),
                                              P(q<K>(-527, 625), q<K>(-336, 625)), q<K>(3, 5));
}

template <class K>
std::vector<typename K::FT> marks(std::initializer_list<std::pair<int, int>> fractions) {
  std::vector<typename K::FT> out;
  for (const auto& f : fractions) out.push_back(q<K>(f.first, f.second));
  return out;
}

// C^2 at every interior breakpoint (every breakpoint of a closed spline), from the pieces in their
// local parameters: equal points, p_{i+1}'(0) h_i = p_i'(1) h_{i+1}, p_{i+1}''(0) h_i^2 = p_i''(1) h_{i+1}^2.
template <class K>
void expect_c2(const fair::Cubic_spline_2<K>& s, double rel) {
  typedef typename K::FT FT;
  const std::size_t m = s.number_of_pieces();
  const auto& t = s.breakpoints();
  const std::size_t joins = s.is_closed() ? m : m - 1;
  for (std::size_t i = 0; i < joins; ++i) {
    const std::size_t j = (i + 1) % m;
    const FT hi = t[i + 1] - t[i], hj = t[j + 1] - t[j];
    const auto a = s.piece(i), b = s.piece(j);
    EXPECT_TRUE(same<K>(a.point(FT(1)), b.point(FT(0)), rel)) << "C0 at breakpoint " << i + 1;
    EXPECT_TRUE(same<K>(a.derivative(FT(1)) * hj, b.derivative(FT(0)) * hi, rel)) << "C1 at breakpoint " << i + 1;
    EXPECT_TRUE(same<K>(a.second_derivative(FT(1)) * (hj * hj), b.second_derivative(FT(0)) * (hi * hi), rel))
        << "C2 at breakpoint " << i + 1;
  }
}

// The same rational piece: equal control points, proportional weights.
template <class K>
::testing::AssertionResult same_piece(const fair::Rational_bezier_2<K>& a, const fair::Rational_bezier_2<K>& b,
                                      double rel) {
  if (a.degree() != b.degree()) return ::testing::AssertionFailure() << "degrees differ";
  for (std::size_t k = 0; k <= a.degree(); ++k) {
    ::testing::AssertionResult p = same<K>(a.control_point(k), b.control_point(k), rel);
    if (!p) return p << " (control point " << k << ")";
    ::testing::AssertionResult w = same<K>(a.weight(k) * b.weight(0), b.weight(k) * a.weight(0), rel);
    if (!w) return w << " (weight " << k << ")";
  }
  return ::testing::AssertionSuccess();
}

// Every part of every shape is reproduced on the pieces its span declares exact.
template <class K>
void expect_reproduced(const fair::Basic_shape_design_2<K>& d, const std::vector<fair::Basic_shape_2<K>>& shapes,
                       double rel) {
  for (const fair::Shape_span& span : d.spans) {
    const auto& part = shapes[span.shape].parts()[span.part];
    EXPECT_EQ(span.end_piece - span.first_piece, part.number_of_pieces());
    for (std::size_t k = span.first_exact; k < span.end_exact; ++k)
      EXPECT_TRUE(same_piece<K>(d.spline.piece(k), part.piece(k - span.first_piece), rel))
          << "shape " << span.shape << " part " << span.part << " piece " << k - span.first_piece;
  }
}

TYPED_TEST(Shapes, SegmentHasLinearPrecision) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  const P a(1, 2), b(5, -2);
  const auto s = fair::Basic_shape_2<K>::segment(a, b, marks<K>({{1, 5}, {1, 2}, {3, 4}}));
  ASSERT_EQ(s.parts().size(), 1u);
  const auto& sp = s.parts()[0];
  EXPECT_EQ(sp.number_of_pieces(), 4u);
  EXPECT_EQ(sp.number_of_control_points(), 7u);
  EXPECT_TRUE(same<K>(sp.control_points().front(), a));
  EXPECT_TRUE(same<K>(sp.control_points().back(), b));
  for (const auto& t : marks<K>({{0, 1}, {1, 7}, {1, 5}, {2, 3}, {9, 10}, {1, 1}}))
    EXPECT_TRUE(same<K>(sp.point(t), a + (b - a) * t));
}

TYPED_TEST(Shapes, ConicShapeIsTheConicExactly) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const auto c = arc1<K>();
  const auto s = fair::Basic_shape_2<K>::conic(c, marks<K>({{1, 4}, {1, 2}, {2, 3}}));
  const auto& sp = s.parts()[0];
  EXPECT_TRUE(sp.is_rational());
  EXPECT_EQ(sp.number_of_pieces(), 4u);
  for (const auto& u : marks<K>({{0, 1}, {1, 8}, {1, 4}, {3, 7}, {2, 3}, {1, 1}})) {
    const auto p = sp.point(u);
    EXPECT_TRUE(same<K>(p, c.point(u)));
    EXPECT_TRUE(same<K>(p.x() * p.x() + p.y() * p.y(), FT(1)));  // on the unit circle, exactly
  }
}

// The four kinds of shapes in one open design: two agreeing arcs, an edge to a segment, an
// averaged join to a polynomial cubic. The merged spline reproduces every shape on its exact
// pieces (the proof of the knot decision), the betas around every join are 1, and it is C^2.
template <class K>
std::vector<fair::Basic_shape_2<K>> four_shapes() {
  typedef typename K::Point_2 P;
  typedef fair::Basic_shape_2<K> S;
  const auto m6 = marks<K>({{1, 8}, {1, 4}, {3, 8}, {1, 2}, {5, 8}, {3, 4}, {7, 8}});
  std::vector<S> shapes;
  shapes.push_back(S::conic(arc1<K>(), m6));
  shapes.push_back(S::conic(arc2<K>(), marks<K>({{1, 10}, {1, 5}, {2, 5}, {3, 5}, {4, 5}, {9, 10}})));
  shapes.push_back(S::segment(P(-1, -1), P(1, -1), marks<K>({{1, 6}, {1, 3}, {1, 2}, {2, 3}, {5, 6}})));
  const P start(1 + q<K>(1, 1 << 30), -1);  // 2^-30 from the segment's end: averaged at tolerance 1e-6
  shapes.push_back(S::cubic(fair::Rational_bezier_2<K>({start, P(2, -1), P(3, 0), P(3, 2)}), m6));
  return shapes;
}

TYPED_TEST(Shapes, MergedSplineReproducesEveryShapeInside) {
  typedef TypeParam K;
  const auto shapes = four_shapes<K>();
  fair::Basic_shape_design_options o;
  o.merge_tolerance = 1e-6;
  const auto d = fair::basic_shape_design(shapes, o);
  ASSERT_EQ(d.joins.size(), 3u);
  EXPECT_EQ(d.joins[0].kind, fair::Shape_join_kind::AGREE);
  EXPECT_EQ(d.joins[1].kind, fair::Shape_join_kind::EDGE);
  EXPECT_EQ(d.joins[2].kind, fair::Shape_join_kind::AVERAGED);
  EXPECT_NEAR(d.joins[1].distance, std::hypot(1 - 527.0 / 625, 1 - 336.0 / 625), 1e-12);
  EXPECT_NEAR(d.joins[2].distance, std::ldexp(1.0, -30), 1e-20);
  EXPECT_FALSE(d.spline.is_closed());
  EXPECT_TRUE(d.spline.is_rational());
  // Control points: every part's own (m + 3 each) minus the merged end points, plus the edge.
  std::size_t total = 0;
  for (const auto& s : shapes) total += s.parts()[0].number_of_control_points();
  EXPECT_EQ(d.spline.number_of_control_points(), total - 2);  // agree and averaged joins: one point less each
  EXPECT_TRUE(same<K>(d.spline.control_points().front(), shapes.front().source()));
  EXPECT_TRUE(same<K>(d.spline.control_points().back(), shapes.back().target()));
  // The averaged join is the midpoint of the two end points.
  EXPECT_TRUE(same<K>(d.spline.control_points()[d.joins[2].control_point],
                      CGAL::midpoint(shapes[2].target(), shapes[3].source())));
  // The first shape is kept from its clamped start, the last to its clamped end.
  EXPECT_EQ(d.spans.front().first_exact, 0u);
  EXPECT_EQ(d.spans.back().end_exact, d.spline.number_of_pieces());
  for (const auto& span : d.spans) EXPECT_GT(span.end_exact, span.first_exact);
  expect_reproduced(d, shapes, 1e-12);
  // beta = 1 at every new breakpoint and at the shape ends next to it.
  for (const auto& j : d.joins) {
    const std::size_t b = j.control_point - 1;  // open: control point b + 1 belongs to breakpoint b
    const std::size_t last = b + (j.kind == fair::Shape_join_kind::EDGE ? 2 : 1);
    for (std::size_t i = b - 1; i <= last; ++i) EXPECT_TRUE(same<K>(d.spline.beta(i), typename K::FT(1))) << i;
  }
  expect_c2(d.spline, 1e-10);
  // The same shapes with tolerance 0: the nearly equal points become an edge.
  const auto d0 = fair::basic_shape_design(shapes, fair::Basic_shape_design_options{false, 0.0});
  EXPECT_EQ(d0.joins[2].kind, fair::Shape_join_kind::EDGE);
  EXPECT_EQ(d0.spline.number_of_control_points(), d.spline.number_of_control_points() + 1);
  expect_reproduced(d0, shapes, 1e-12);
}

TYPED_TEST(Shapes, EditedControlPointsKeepC2) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  const auto shapes = four_shapes<K>();
  const auto d = fair::basic_shape_design(shapes, fair::Basic_shape_design_options{false, 1e-6});
  // The designer moves the join points and a control point inside the first arc.
  auto edited = d.spline;
  for (const auto& j : d.joins) {
    const P p = edited.control_points()[j.control_point];
    edited = edited.with_control_point(j.control_point, P(p.x() + q<K>(1, 3), p.y() - q<K>(1, 7)));
  }
  edited = edited.with_control_point(4, P(q<K>(3, 2), q<K>(1, 2)));
  EXPECT_EQ(edited.breakpoints(), d.spline.breakpoints());
  expect_c2(edited, 1e-10);
  // Moving one control point changes at most four pieces (local control): the rest is kept.
  const std::size_t i = d.joins[0].control_point;
  const auto one = d.spline.with_control_point(i, P(0, 0));
  std::size_t changed = 0;
  for (std::size_t k = 0; k < d.spline.number_of_pieces(); ++k)
    if (!same_piece<K>(one.piece(k), d.spline.piece(k), 1e-13)) ++changed;
  EXPECT_LE(changed, 4u);
  EXPECT_GE(changed, 1u);
}

TYPED_TEST(Shapes, ClosedDesignIsPeriodicAndReproducesTheShapes) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef fair::Basic_shape_2<K> S;
  std::vector<S> shapes;
  shapes.push_back(S::conic(arc1<K>(), marks<K>({{1, 6}, {1, 3}, {1, 2}, {2, 3}, {5, 6}})));
  shapes.push_back(S::conic(arc2<K>(), marks<K>({{1, 6}, {1, 3}, {1, 2}, {2, 3}, {5, 6}})));
  // Back to the start of the first arc: the closing join agrees too.
  shapes.push_back(S::segment(P(q<K>(-527, 625), q<K>(-336, 625)), P(1, 0), marks<K>({{1, 4}, {1, 2}, {3, 4}})));
  const auto d = fair::basic_shape_design(shapes, fair::Basic_shape_design_options{true, 0.0});
  EXPECT_TRUE(d.spline.is_closed());
  ASSERT_EQ(d.joins.size(), 3u);
  for (const auto& j : d.joins) EXPECT_EQ(j.kind, fair::Shape_join_kind::AGREE);
  EXPECT_EQ(d.joins[2].before, 2u);
  EXPECT_EQ(d.joins[2].after, 0u);
  // Closed: every part's control points d_1..d_{m+1} and one per join.
  std::size_t total = 0;
  for (const auto& s : shapes) total += s.parts()[0].number_of_control_points() - 2;
  EXPECT_EQ(d.spline.number_of_control_points(), total + 3);
  for (const auto& span : d.spans) {
    EXPECT_EQ(span.first_exact, span.first_piece + 2);
    EXPECT_EQ(span.end_exact + 2, span.end_piece);
  }
  expect_reproduced(d, shapes, 1e-12);
  expect_c2(d.spline, 1e-10);
  // Proposition 1: the joint control polygon is convex, so the curve is locally convex -- decided
  // exactly in an exact kernel (in double the segment's collinear control points are rounded off
  // their line, and the verdict is about the rounded points).
  if (fair_test::is_exact<K>()) {
    const auto convexity = fair::spline_convexity(d.spline);
    EXPECT_TRUE(convexity.polygon_convex);
    EXPECT_TRUE(convexity.curve_locally_convex);
    EXPECT_EQ(convexity.curve_orientation, CGAL::LEFT_TURN);
  }
  // Points of the merged curve on the arcs' exact pieces are on the unit circle.
  typedef typename K::FT FT;
  for (std::size_t k = d.spans[0].first_exact; k < d.spans[1].end_exact; ++k) {
    if (k >= d.spans[0].end_exact && k < d.spans[1].first_exact) continue;
    const P p = d.spline.piece(k).point(q<K>(1, 3));
    EXPECT_TRUE(same<K>(p.x() * p.x() + p.y() * p.y(), FT(1))) << k;
  }
}

TYPED_TEST(Shapes, RationalWeightsAreRescaledAcrossJoins) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  typedef fair::Basic_shape_2<K> S;
  // A rational cubic with end weights 2 and 3 between two conics whose end weights are 1.
  const fair::Rational_bezier_2<K> cubic({P(q<K>(-527, 625), q<K>(-336, 625)), P(0, -2), P(2, -1), P(3, 0)},
                                         {FT(2), FT(5), FT(1), FT(3)});
  const auto m5 = marks<K>({{1, 6}, {1, 3}, {1, 2}, {2, 3}, {5, 6}});
  std::vector<S> shapes;
  shapes.push_back(S::conic(arc2<K>(), m5));
  shapes.push_back(S::cubic(cubic, m5));
  shapes.push_back(S::conic(fair::Rational_quadratic_bezier_2<K>(P(3, 0), P(4, 1), P(3, 2), q<K>(7, 4)), m5));
  const auto d = fair::basic_shape_design(shapes);
  const auto& w = d.spline.weights();
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& j = d.joins[k];
    EXPECT_EQ(j.kind, fair::Shape_join_kind::AGREE);
    const auto& before = shapes[k].parts()[0].weights();
    const auto& after = shapes[k + 1].parts()[0].weights();
    const std::size_t c = j.control_point;
    // Each side keeps its own weight ratios: the join weight is the scaled end weight of both.
    EXPECT_TRUE(same<K>(w[c] * before[before.size() - 2], w[c - 1] * before.back()));
    EXPECT_TRUE(same<K>(w[c + 1] * after.front(), w[c] * after[1]));
  }
  expect_reproduced(d, shapes, 1e-12);
  expect_c2(d.spline, 1e-10);
}

TYPED_TEST(Shapes, BadShapesAndOptionsAreTypedErrors) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef fair::Basic_shape_2<K> S;
  EXPECT_THROW(S::segment(P(1, 1), P(1, 1)), fair::Invalid_input_error);
  EXPECT_THROW(S::segment(P(0, 0), P(1, 1), marks<K>({{1, 2}, {1, 3}})), fair::Invalid_input_error);
  EXPECT_THROW(S::segment(P(0, 0), P(1, 1), marks<K>({{0, 1}})), fair::Invalid_input_error);
  EXPECT_THROW(S::conic(arc1<K>(), marks<K>({{1, 2}, {1, 1}})), fair::Invalid_input_error);
  EXPECT_THROW(S::circle_arc(P(0, 0), typename K::FT(0), 0.0, 1.0), fair::Invalid_input_error);
  EXPECT_THROW(S::circle_arc(P(0, 0), typename K::FT(1), 1.0, 1.0), fair::Invalid_input_error);
  EXPECT_THROW(S::circle_arc(P(0, 0), typename K::FT(1), 0.0, 7.0), fair::Invalid_input_error);
  EXPECT_THROW(S::circle_arc(P(0, 0), typename K::FT(1), 0.0, 1.0, {0.5, 1.5}), fair::Invalid_input_error);
  const fair::Rational_bezier_2<K> quartic({P(0, 0), P(1, 1), P(2, 0), P(3, 1), P(4, 0)});
  EXPECT_THROW(S::cubic(quartic), fair::Precondition_error);
  const std::vector<S> none;
  EXPECT_THROW(fair::basic_shape_design(none), fair::Precondition_error);
  const std::vector<S> one = {S::segment(P(0, 0), P(1, 0))};
  EXPECT_THROW(fair::basic_shape_design(one, fair::Basic_shape_design_options{false, -1.0}), fair::Precondition_error);
  EXPECT_THROW(fair::basic_shape_design(one, fair::Basic_shape_design_options{false, std::nan("")}),
               fair::Precondition_error);
  // A lone segment: open, it is itself (4 control points); closed on itself it has no interior.
  const auto d = fair::basic_shape_design(one);
  EXPECT_EQ(d.spline.number_of_control_points(), 4u);
  EXPECT_TRUE(d.joins.empty());
  const std::string what = fair_test::invalid_input_message([&] { fair::basic_shape_design(one, fair::Basic_shape_design_options{true}); });
  EXPECT_NE(what.find("lie on one line"), std::string::npos) << what;
  // There and back along one line, closed: also no interior. A triangle of segments is fine.
  const std::vector<S> back = {S::segment(P(0, 0), P(2, 0)), S::segment(P(2, 0), P(0, 0))};
  EXPECT_THROW(fair::basic_shape_design(back, fair::Basic_shape_design_options{true}), fair::Invalid_input_error);
  const std::vector<S> triangle = {S::segment(P(0, 0), P(2, 0)), S::segment(P(2, 0), P(1, 1)),
                                   S::segment(P(1, 1), P(0, 0))};
  EXPECT_NO_THROW(fair::basic_shape_design(triangle, fair::Basic_shape_design_options{true}));
}

// Circle arcs from angles: split into sub-arcs of at most 180 degrees (circle_arc_split), on the
// circle to rounding, the marked angles at the knots.
TYPED_TEST(Shapes_float, CircleArcIsSplitAndOnTheCircle) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef fair::Basic_shape_2<K> S;
  const P c(2, -1);
  const double r = 3, a0 = 0.25, a1 = a0 + 5 * M_PI / 3;  // 300 degrees: 2 sub-arcs of 150
  const std::vector<double> m = {0.5, 1.0, 2.0, a0 + M_PI / 2 * 1.25, 3.0, 4.0, 5.0};
  const S arc = S::circle_arc(c, r, a0, a1, m);
  ASSERT_EQ(arc.parts().size(), 2u);
  std::size_t knots = 0;
  for (const auto& part : arc.parts()) {
    knots += part.number_of_pieces() - 1;
    for (const auto& piece : part.pieces())
      for (double t = 0; t <= 1; t += 0.125) {
        const P p = piece.point(t);
        EXPECT_NEAR(std::hypot(p.x() - 2, p.y() + 1), r, 1e-14);
        EXPECT_NEAR(std::fabs(piece.curvature(t)), 1 / r, 1e-12);
      }
    // The interior breakpoints are the marked points.
    for (std::size_t i = 1; i + 1 < part.breakpoints().size(); ++i) {
      const P p = part.point(part.breakpoints()[i]);
      const double a = std::atan2(p.y() + 1, p.x() - 2);
      bool found = false;
      for (double x : m) found = found || std::fabs(std::remainder(a - x, 2 * M_PI)) < 1e-13;
      EXPECT_TRUE(found) << a;
    }
  }
  EXPECT_EQ(knots, m.size());
  EXPECT_NEAR(arc.source().x(), 2 + 3 * std::cos(a0), 1e-15);
  EXPECT_NEAR(arc.target().y(), -1 + 3 * std::sin(a1), 1e-15);
  // Its sub-arcs are merged as agreeing, inside the shape, even with tolerance 0.
  const std::vector<S> shapes = {arc};
  const auto d = fair::basic_shape_design(shapes, fair::Basic_shape_design_options{false, 0.0});
  ASSERT_EQ(d.joins.size(), 1u);
  for (const auto& j : d.joins) {
    EXPECT_TRUE(j.inside);
    EXPECT_EQ(j.kind, fair::Shape_join_kind::AGREE);
  }
  expect_reproduced(d, shapes, 1e-14);
  expect_c2(d.spline, 1e-12);
  // A full circle, closed.
  const std::vector<S> circle = {S::circle_arc(c, r, 0.0, 2 * M_PI, {1.0, 2.0, 3.0, 4.0, 5.0, 6.0})};
  const auto dc = fair::basic_shape_design(circle, fair::Basic_shape_design_options{true, 1e-9});
  EXPECT_TRUE(dc.spline.is_closed());
  EXPECT_EQ(dc.joins.size(), 2u);
  EXPECT_EQ(circle[0].parts().size(), 2u);
  // A semicircle is one part (its cubic weights are 1, 1/3, 1/3, 1).
  EXPECT_EQ(S::circle_arc(c, r, 0.0, M_PI).parts().size(), 1u);
  EXPECT_NE(dc.joins.back().kind, fair::Shape_join_kind::EDGE);
  expect_c2(dc.spline, 1e-12);
}

// A parametric shape (Sec. 5): the spiral's spline is kept exactly on its interior when it is
// joined to a segment at its end (averaged: the end point is computed in double) and a conic.
TYPED_TEST(Shapes_float, ParametricShapeIsKeptInside) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef fair::Basic_shape_2<K> S;
  const fair::Archimedean_spiral_2 spiral(0.2, 0.15, 0.5, 2 * M_PI);
  std::vector<double> marks;
  for (int k = 0; k <= 12; ++k) marks.push_back(0.5 + (2 * M_PI - 0.5) * k / 12);
  const S shape = S::parametric(spiral, marks, "spiral");
  EXPECT_EQ(shape.kind(), "spiral");
  EXPECT_EQ(shape.parts()[0].number_of_pieces(), 12u);
  const fair::Curve_jet_2 e = spiral.jet(2 * M_PI);
  EXPECT_NEAR(shape.target().x(), e.x, 1e-15);
  EXPECT_NEAR(shape.target().y(), e.y, 1e-15);
  std::vector<S> shapes = {shape, S::segment(P(e.x, e.y), P(e.x + 0.5, e.y - 1), {0.25, 0.5, 0.75})};
  const auto d = fair::basic_shape_design(shapes);
  EXPECT_EQ(d.joins[0].kind, fair::Shape_join_kind::AGREE);
  expect_reproduced(d, shapes, 1e-14);
  expect_c2(d.spline, 1e-12);
  // On its interior the spline is within the O(h^4) error of the spiral (about 1e-4 here).
  for (std::size_t k = d.spans[0].first_exact; k < d.spans[0].end_exact; ++k) {
    const double u = marks[k] + 0.5 * (marks[k + 1] - marks[k]);
    const P p = d.spline.piece(k).point(0.5);
    EXPECT_LT(std::hypot(p.x() - spiral.jet(u).x, p.y() - spiral.jet(u).y), 1e-3) << k;
  }
}

// ------------------------------------------------------------------ the design file

template <class K>
fair::io::Design_file<K> parse(const std::string& text) {
  return fair::io::parse_design<K>(text, "design.json");
}

TYPED_TEST(Shapes, DesignFileReadsEveryShapeExactly) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  const std::string text = R"({
    "closed": false, "merge_tolerance": 1e-6,
    "shapes": [
      {"type": "conic", "control_points": [[1, 0], [1, "4/3"], ["-7/25", "24/25"]], "weight": "3/5",
       "marks": ["1/4", ["3/5", "4/5"], 0.75]},
      {"type": "segment", "from": ["-7/25", "24/25"], "to": [-2, 0], "marks": [0.25, ["-57/50", "12/25"]]},
      {"type": "cubic", "control_points": [[-2, 0], [-2, -1], [0, -2], [1, -2]], "weights": [1, 2, 2, 1],
       "marks": [0.5]},
      {"type": "arc", "center": [1, -1], "radius": 1, "start_angle": -1.5707963267948966, "end_angle": 0,
       "marks": [-0.5]}
    ]})";
  const auto f = parse<K>(text);
  EXPECT_FALSE(f.closed);
  EXPECT_EQ(f.merge_tolerance, 1e-6);
  ASSERT_EQ(f.shapes.size(), 4u);
  EXPECT_EQ(f.types[3], "arc");
  // The conic's parameter marks are exact; its point mark (3/5, 4/5) is at u = 1/2 (to rounding).
  const auto& conic = f.shapes[0].parts()[0];
  EXPECT_EQ(conic.number_of_pieces(), 4u);
  EXPECT_TRUE(same<K>(conic.breakpoints()[1], q<K>(1, 4)));
  EXPECT_TRUE(same<K>(f.marked_points[0][0], arc1<K>().point(q<K>(1, 4))));
  EXPECT_TRUE(same<K>(conic.breakpoints()[3], q<K>(3, 4)));
  EXPECT_NEAR(CGAL::to_double(conic.breakpoints()[2]), 0.5, 1e-15);
  EXPECT_TRUE(same<K>(conic.control_points().back(), P(q<K>(-7, 25), q<K>(24, 25))));
  // The segment's point mark (-57/50, 12/25) is its midpoint: u = 1/2 exactly.
  const auto& seg = f.shapes[1].parts()[0];
  EXPECT_TRUE(same<K>(seg.breakpoints()[2], q<K>(1, 2)));
  EXPECT_TRUE(same<K>(f.marked_points[1][1], P(q<K>(-57, 50), q<K>(12, 25))));
  const auto d = fair::basic_shape_design(f.shapes, f.options());
  EXPECT_EQ(d.joins.size(), 3u);
  expect_c2(d.spline, 1e-10);
  expect_reproduced(d, f.shapes, 1e-12);
}

TYPED_TEST(Shapes_float, DesignFileReadsParametricShapesAndCubicPointMarks) {
  typedef TypeParam K;
  const std::string text = R"({"closed": false, "shapes": [
      {"type": "spiral", "a": 0.2, "b": 0.15, "theta0": 0.5, "theta1": 6, "marks": [1, 2, 3, 4, 5]},
      {"type": "involute", "radius": 0.3, "t0": 0.5, "t1": 2, "center": [3, 0], "marks": [1, 1.5]},
      {"type": "clothoid", "kappa0": 0, "c": 1, "s0": 0, "s1": 1.5, "origin": [4, 1], "theta0": 1, "marks": [0.5, 1]},
      {"type": "cubic", "control_points": [[5, 2], [6, 3], [7, 1], [8, 2]], "marks": [0.25, [6.5, 2], 0.75]}]})";
  const auto f = parse<K>(text);
  ASSERT_EQ(f.shapes.size(), 4u);
  EXPECT_EQ(f.types[2], "clothoid");
  EXPECT_EQ(f.shapes[0].parts()[0].number_of_pieces(), 6u);
  EXPECT_EQ(f.shapes[1].parts()[0].number_of_pieces(), 3u);
  EXPECT_EQ(f.marked_points[0].size(), 5u);
  // (6.5, 2) is the polynomial cubic's point at u = 1/2: eq. 5 finds it.
  EXPECT_NEAR(CGAL::to_double(f.shapes[3].parts()[0].breakpoints()[2]), 0.5, 1e-12);
  const auto d = fair::basic_shape_design(f.shapes, f.options());
  EXPECT_EQ(d.joins.size(), 3u);
  for (const auto& j : d.joins) EXPECT_EQ(j.kind, fair::Shape_join_kind::EDGE);
  expect_c2(d.spline, 1e-12);
}

// Each error of the design file: a Parse_error naming the file, the line and the JSON path.
TYPED_TEST(Shapes_float, DesignFileErrorsNameFileLineAndPath) {
  typedef TypeParam K;
  struct Case {
    const char* shape;
    const char* expected;
  };
  const Case cases[] = {
      {R"({"type": "ellipse"})", "shapes[1].type: unknown shape type \"ellipse\""},
      {R"({"type": "segment", "from": [0, 0]})", "shapes[1]: missing member \"to\""},
      {R"({"type": "segment", "from": [0, 0], "to": [0, 0]})", "shapes[1]: fair::Basic_shape_2::segment: zero-length"},
      {R"({"type": "arc", "center": [0, 0], "radius": 0, "start_angle": 0, "end_angle": 1})", "radius 0 must be"},
      {R"({"type": "arc", "center": [0, 0], "radius": 1, "start_angle": 1, "end_angle": 1})", "degenerate arc"},
      {R"({"type": "arc", "center": [0, 0], "radius": 1, "start_angle": 0, "end_angle": 1, "marks": [0.5, 0.2]})",
       "strictly increasing"},
      {R"({"type": "arc", "center": [0, 0], "radius": 1, "start_angle": 0, "end_angle": 1, "marks": [2]})",
       "is not inside"},
      {R"({"type": "segment", "from": [0, 0], "to": [1, 0], "marks": [0.5, 0.5]})",
       "shapes[1].marks[1]: marks must be strictly increasing"},
      {R"({"type": "segment", "from": [0, 0], "to": [1, 0], "marks": [1.5]})", "shapes[1].marks[0]: the mark's parameter 1.5"},
      {R"({"type": "segment", "from": [0, 0], "to": [1, 0], "marks": [[0.5, 0.1]]})", "shapes[1].marks[0]: the marked point (0.5, 0.1"},
      {R"({"type": "conic", "control_points": [[1, 0], [1, 1], [0, 1]], "weight": 0.7, "marks": [[0.5, 0.5]]})",
       "shapes[1].marks[0]: conic_parameter: the point (0.5, 0.5) is at distance"},
      {R"({"type": "conic", "control_points": [[1, 0], [1, 1], [0, 1]], "weight": -1})", "shapes[1].weight: the weight -1 must be > 0"},
      {R"({"type": "cubic", "control_points": [[0, 0], [1, 1], [2, 1], [3, 0]], "weights": [1, 0, 1, 1]})",
       "shapes[1].weights[1]: the weight 0 must be > 0"},
      {R"({"type": "cubic", "control_points": [[0, 0], [1, 1], [2, 1]]})", "shapes[1].control_points: expected 4 entries"},
      {R"({"type": "segment", "from": [0, "1/0"], "to": [1, 0]})", "shapes[1].from[1]: the number '1/0' has a zero denominator"},
  };
  for (const Case& c : cases) {
    const std::string text = std::string("{\"shapes\": [{\"type\": \"segment\", \"from\": [5, 5], \"to\": [6, 5]},\n") +
                             c.shape + "]}";
    try {
      parse<K>(text);
      ADD_FAILURE() << "no error for " << c.shape;
    } catch (const fair::Parse_error& e) {
      EXPECT_EQ(e.file(), "design.json");
      EXPECT_EQ(e.line(), 2u) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what() << "\n  expected: " << c.expected;
    }
  }
  EXPECT_THROW(parse<K>("[1, 2]"), fair::Parse_error);
  // The parametric built-ins: their own checks (a cusp inside the involute's domain) and marks.
  const std::string involute = R"({"shapes": [{"type": "involute", "radius": 1, "t0": -1, "t1": 2}]})";
  EXPECT_THROW(parse<K>(involute), fair::Parse_error);
  const std::string spiral = R"({"shapes": [{"type": "spiral", "a": 0, "b": 1, "theta0": 1, "theta1": 2, "marks": [1.5, 2.5]}]})";
  try {
    parse<K>(spiral);
    ADD_FAILURE();
  } catch (const fair::Parse_error& e) {
    EXPECT_NE(std::string(e.what()).find("shapes[0].marks[1]: the mark 2.5 is not inside"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse<K>("{\"shapes\": []}"), fair::Parse_error);
  EXPECT_THROW(parse<K>("{\"closed\": 1, \"shapes\": [{\"type\": \"segment\", \"from\": [0, 0], \"to\": [1, 0]}]}"),
               fair::Parse_error);
  EXPECT_THROW(parse<K>("{\"merge_tolerance\": -1, \"shapes\": [{\"type\": \"segment\", \"from\": [0, 0], \"to\": [1, 0]}]}"),
               fair::Parse_error);
}

} // namespace
