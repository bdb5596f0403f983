// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Cubic_spline_2: its pieces against an independent Cox-de Boor evaluation of the NURBS
// form, eqs. 1-3 of Karciauskas & Peters literally (beta_i, e_i, ẽ_i, x_i), C2 at every join
// (exactly in the exact kernels), the eq. 3 round trip, Boehm knot insertion, closed splines,
// rational splines (an exact circle), the NURBS form and the JSON member, and bad input.

#include "test_support.h"

#include <fair/Cubic_bspline_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Cubic_quasi_interpolant_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/io/write_json.h>

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

using fair_test::q;
using fair_test::same;

template <class K>
class Cubic_spline : public ::testing::Test {};
TYPED_TEST_SUITE(Cubic_spline, fair_test::All_kernels);

// Random strictly increasing breakpoints k/4 with gaps 1/4 .. 3 (exact in every kernel).
template <class K>
std::vector<typename K::FT> random_breakpoints(std::mt19937& rng, std::size_t m) {
  std::uniform_int_distribution<int> gap(1, 12);
  std::vector<typename K::FT> t{q<K>(-3, 2)};
  for (std::size_t i = 0; i < m; ++i) t.push_back(t.back() + q<K>(gap(rng), 4));
  return t;
}

template <class K>
std::vector<typename K::FT> random_weights(std::mt19937& rng, std::size_t n) {
  std::uniform_int_distribution<int> w(1, 9);
  std::vector<typename K::FT> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(q<K>(w(rng), 4));
  return out;
}

// Cox-de Boor recursion on a full knot vector U for a NURBS curve of degree 3: the reference
// evaluation, written independently of the Bezier construction of the library.
template <class K>
typename K::Point_2 de_boor_reference(const std::vector<typename K::FT>& U, const std::vector<typename K::Point_2>& P,
                                      const std::vector<typename K::FT>& W, const typename K::FT& t) {
  typedef typename K::FT FT;
  const std::size_t n = P.size();
  std::size_t span = 3;
  while (span + 1 < n && !(t < U[span + 1])) ++span; // U[span] <= t < U[span+1], last span closed
  std::vector<FT> N(U.size() - 1, FT(0));
  N[span] = FT(1);
  for (std::size_t p = 1; p <= 3; ++p)
    for (std::size_t i = 0; i + p + 1 < U.size(); ++i) {
      FT a(0), b(0);
      if (U[i + p] != U[i]) a = (t - U[i]) / (U[i + p] - U[i]) * N[i];
      if (U[i + p + 1] != U[i + 1]) b = (U[i + p + 1] - t) / (U[i + p + 1] - U[i + 1]) * N[i + 1];
      N[i] = a + b;
    }
  FT x(0), y(0), w(0);
  for (std::size_t i = 0; i < n; ++i) {
    x += N[i] * W[i] * P[i].x();
    y += N[i] * W[i] * P[i].y();
    w += N[i] * W[i];
  }
  return typename K::Point_2(x / w, y / w);
}

// Parameters to probe: every breakpoint and three interior rationals per interval.
template <class K>
std::vector<typename K::FT> probes(const std::vector<typename K::FT>& t) {
  std::vector<typename K::FT> out;
  for (std::size_t i = 0; i + 1 < t.size(); ++i)
    for (int k = 0; k < 4; ++k) out.push_back(t[i] + (t[i + 1] - t[i]) * q<K>(2 * k + (k == 0 ? 0 : 1), 9));
  out.push_back(t.back());
  return out;
}

template <class K>
fair::Cubic_spline_2<K> random_spline(std::mt19937& rng, std::size_t m, bool closed, bool rational) {
  const auto t = random_breakpoints<K>(rng, m);
  const auto d = fair_test::random_points<K>(rng, closed ? m : m + 3);
  if (!rational) return fair::Cubic_spline_2<K>(t, d, closed);
  return fair::Cubic_spline_2<K>(t, d, random_weights<K>(rng, d.size()), closed);
}

TYPED_TEST(Cubic_spline, PiecesAgreeWithCoxDeBoorOnTheNurbsForm) {
  typedef TypeParam K;
  std::mt19937 rng(11);
  for (int trial = 0; trial < 12; ++trial) {
    const bool closed = trial % 2 == 1, rational = trial % 4 >= 2;
    const std::size_t m = closed ? 3 + trial % 5 : 1 + trial % 6;
    const fair::Cubic_spline_2<K> s = random_spline<K>(rng, m, closed, rational);
    const auto U = s.knot_vector();
    const auto P = s.knot_vector_control_points();
    const auto W = s.knot_vector_weights();
    ASSERT_EQ(U.size(), P.size() + 4);
    ASSERT_EQ(W.size(), P.size());
    for (const auto& t : probes<K>(s.breakpoints())) {
      const auto ref = de_boor_reference<K>(U, P, W, t);
      EXPECT_TRUE(same<K>(s.point(t), ref, 1e-11)) << "trial " << trial << " t = " << CGAL::to_double(t);
      // the piece of t, evaluated at the local parameter, is the same point
      std::size_t i = 0;
      while (i + 1 < s.number_of_pieces() && !(t < s.breakpoints()[i + 1])) ++i;
      const auto& b = s.breakpoints();
      EXPECT_TRUE(same<K>(s.piece(i).point((t - b[i]) / (b[i + 1] - b[i])), ref, 1e-11));
    }
  }
}

TYPED_TEST(Cubic_spline, OpenSplineIsClampedAtItsEndControlPoints) {
  typedef TypeParam K;
  std::mt19937 rng(5);
  for (std::size_t m = 1; m <= 5; ++m) {
    const fair::Cubic_spline_2<K> s = random_spline<K>(rng, m, false, m % 2 == 0);
    const auto& d = s.control_points();
    const auto first = s.piece(0), last = s.piece(m - 1);
    EXPECT_TRUE(same<K>(first.control_point(0), d[0]));
    EXPECT_TRUE(same<K>(first.control_point(1), d[1]));
    EXPECT_TRUE(same<K>(last.control_point(2), d[m + 1]));
    EXPECT_TRUE(same<K>(last.control_point(3), d[m + 2]));
    EXPECT_TRUE(same<K>(s.point(s.breakpoints().front()), d.front()));
    EXPECT_TRUE(same<K>(s.point(s.breakpoints().back()), d.back()));
  }
}

// eqs. 1-2 as printed, with beta_i = h_i / h_{i-1}: interior pieces of an open spline and every
// piece of a closed one (the library multiplies them out; here they are used literally).
TYPED_TEST(Cubic_spline, InteriorPiecesFollowEquationTwoLiterally) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  std::mt19937 rng(7);
  for (int closed = 0; closed < 2; ++closed) {
    const std::size_t m = 7;
    const fair::Cubic_spline_2<K> s = random_spline<K>(rng, m, closed == 1, false);
    const std::size_t first = closed ? 0 : 2, last = closed ? m : m - 2; // pieces whose 4 neighbours are interior
    // the paper's c_i: d_{i+1} open, d_{i mod m} closed (i >= -1)
    auto c = [&](long i) -> P {
      return closed ? s.control_points()[static_cast<std::size_t>((i + static_cast<long>(m)) % static_cast<long>(m))]
                    : s.control_points()[static_cast<std::size_t>(i + 1)];
    };
    auto beta = [&](std::size_t i) -> FT { return s.beta(i % m); };
    auto mix = [](const FT& a, const P& x, const P& y) { return P((1 - a) * x.x() + a * y.x(), (1 - a) * x.y() + a * y.y()); };
    for (long i = static_cast<long>(first); i < static_cast<long>(last); ++i) {
      const std::size_t u = static_cast<std::size_t>(i);
      const FT bi = beta(u), bn = beta(u + 1), bp = beta(u + m - 1);
      const FT e = FT(1) / (1 + bi + bi * bn), et = bi * bn / (1 + bi + bi * bn);
      const P b1 = mix(e, c(i), c(i + 1)), b2 = mix(1 - et, c(i), c(i + 1));
      const auto piece = s.piece(u % m);
      EXPECT_TRUE(same<K>(piece.control_point(1), b1));
      EXPECT_TRUE(same<K>(piece.control_point(2), b2));
      // b_0^i = (1 - x_i) b_2^{i-1} + x_i b_1^i, x_i = 1 / (1 + beta_i)
      const FT etp = bp * bi / (1 + bp + bp * bi);
      const P b2_prev = mix(1 - etp, c(i - 1), c(i));
      const FT x = FT(1) / (1 + bi);
      EXPECT_TRUE(same<K>(piece.control_point(0), mix(x, b2_prev, b1)));
    }
  }
}

// C2 at every join in the global parameter: g'(0) = beta f'(1), g''(0) = beta^2 f''(1) (eq. 1).
TYPED_TEST(Cubic_spline, JoinsAreC2WithTheirBetas) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::mt19937 rng(3);
  for (int trial = 0; trial < 8; ++trial) {
    const bool closed = trial % 2 == 1, rational = trial >= 4;
    const std::size_t m = 4 + trial;
    const fair::Cubic_spline_2<K> s = random_spline<K>(rng, m, closed, rational);
    for (std::size_t i = closed ? 0 : 1; i < m; ++i) {
      const auto f = s.piece((i + m - 1) % m), g = s.piece(i);
      const FT beta = s.beta(i);
      EXPECT_TRUE(same<K>(g.point(FT(0)), f.point(FT(1)), 1e-11));
      EXPECT_TRUE(same<K>(g.derivative(FT(0)), f.derivative(FT(1)) * beta, 1e-10));
      EXPECT_TRUE(same<K>(g.second_derivative(FT(0)), f.second_derivative(FT(1)) * (beta * beta), 1e-9));
    }
  }
}

TYPED_TEST(Cubic_spline, DerivativesAreThoseOfThePiecesScaledByTheIntervals) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::mt19937 rng(13);
  const fair::Cubic_spline_2<K> s = random_spline<K>(rng, 5, false, true);
  const auto& t = s.breakpoints();
  for (std::size_t i = 0; i < 5; ++i) {
    const FT h = t[i + 1] - t[i], u = q<K>(2, 7);
    const auto p = s.piece(i);
    EXPECT_TRUE(same<K>(s.derivative(t[i] + u * h), p.derivative(u) / h, 1e-11));
    EXPECT_TRUE(same<K>(s.second_derivative(t[i] + u * h), p.second_derivative(u) / (h * h), 1e-10));
  }
}

TYPED_TEST(Cubic_spline, FromBezierPiecesIsTheInverseOfPieces) {
  typedef TypeParam K;
  std::mt19937 rng(17);
  for (int trial = 0; trial < 6; ++trial) {
    const bool closed = trial % 2 == 1;
    const std::size_t m = closed ? 3 + trial : 1 + trial;
    const fair::Cubic_spline_2<K> s = random_spline<K>(rng, m, closed, false);
    const auto back = fair::Cubic_spline_2<K>::from_bezier_pieces(s.breakpoints(), s.polynomial_pieces(), closed);
    ASSERT_EQ(back.number_of_control_points(), s.number_of_control_points());
    for (std::size_t i = 0; i < s.number_of_control_points(); ++i)
      EXPECT_TRUE(same<K>(back.control_points()[i], s.control_points()[i], 1e-10)) << "trial " << trial << " i " << i;
    const fair::Cubic_spline_2<K> r = random_spline<K>(rng, m, closed, true);
    const auto rback = fair::Cubic_spline_2<K>::from_rational_bezier_pieces(r.breakpoints(), r.pieces(), closed);
    for (std::size_t i = 0; i < r.number_of_control_points(); ++i) {
      EXPECT_TRUE(same<K>(rback.control_points()[i], r.control_points()[i], 1e-10));
      EXPECT_TRUE(same<K>(rback.weights()[i], r.weights()[i], 1e-10));
    }
  }
}

TYPED_TEST(Cubic_spline, FromBezierPiecesRejectsPiecesThatAreNotC2) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  std::mt19937 rng(19);
  const fair::Cubic_spline_2<K> s = random_spline<K>(rng, 4, false, false);
  auto pieces = s.polynomial_pieces();
  // move an inner Bezier point of piece 2: the join with piece 1 is no longer C2
  std::vector<P> cp = pieces[2].control_points();
  cp[1] = P(cp[1].x() + q<K>(1, 8), cp[1].y());
  pieces[2] = fair::Bezier_2<K>(cp);
  EXPECT_THROW(fair::Cubic_spline_2<K>::from_bezier_pieces(s.breakpoints(), pieces), fair::Invalid_input_error);
  // the same pieces on other breakpoints (other betas) are not C2 either
  auto t = s.breakpoints();
  t[2] += q<K>(1, 3);
  EXPECT_THROW(fair::Cubic_spline_2<K>::from_bezier_pieces(t, s.polynomial_pieces()), fair::Invalid_input_error);
}

// Boehm: the curve is unchanged (exactly in an exact kernel), open and closed, polynomial and
// rational, also for a knot in the wrapping intervals of a closed spline.
TYPED_TEST(Cubic_spline, KnotInsertionKeepsTheCurve) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::mt19937 rng(23);
  for (int trial = 0; trial < 8; ++trial) {
    const bool closed = trial % 2 == 1, rational = trial % 4 >= 2;
    const std::size_t m = closed ? 3 + trial % 3 : 1 + trial % 3;
    fair::Cubic_spline_2<K> s = random_spline<K>(rng, m, closed, rational);
    const fair::Cubic_spline_2<K> original = s;
    for (std::size_t j = 0; j < m; ++j) { // one new knot in every original interval, first and last included
      const auto& t = original.breakpoints();
      const FT knot = t[j] + (t[j + 1] - t[j]) * q<K>(1 + static_cast<int>(j) % 3, 5);
      s = s.with_knot_inserted(knot);
    }
    ASSERT_EQ(s.number_of_pieces(), 2 * m);
    ASSERT_EQ(s.number_of_control_points(), original.number_of_control_points() + m);
    for (const auto& t : probes<K>(original.breakpoints()))
      EXPECT_TRUE(same<K>(s.point(t), original.point(t), 1e-11)) << "trial " << trial;
  }
}

// A rational spline of a circle: the quarter circle as a cubic (the conic (1, w, 1) with
// w = 1/sqrt(2) is irrational; take the rational parametrisation of the first quadrant,
// x = (1 - s^2)/(1 + s^2), y = 2 s/(1 + s^2), s in [0, 1], a rational quadratic with weights
// (1, 1, 2) elevated to a cubic): after knot insertion every point is exactly on the circle.
TYPED_TEST(Cubic_spline, RationalCircleStaysExactUnderKnotInsertion) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  // quadratic homogeneous Bezier points of (1 - s^2, 2s, 1 + s^2): (1,0,1), (1,1,1), (0,2,2)
  // elevated: b0 = (1,0,1), b1 = (1, 2/3, 1), b2 = (2/3, 4/3, 4/3), b3 = (0, 2, 2)
  const std::vector<P> cp{P(1, 0), P(1, q<K>(2, 3)), P(q<K>(1, 2), 1), P(0, 1)};
  const std::vector<FT> w{FT(1), FT(1), q<K>(4, 3), FT(2)};
  const fair::Rational_bezier_2<K> quarter(cp, w);
  auto s = fair::Cubic_spline_2<K>::from_rational_bezier_pieces({FT(0), FT(1)}, {quarter});
  for (int k : {1, 3, 4, 6}) s = s.with_knot_inserted(q<K>(k, 7));
  EXPECT_EQ(s.number_of_pieces(), 5u);
  EXPECT_TRUE(s.is_rational());
  for (const auto& t : probes<K>(s.breakpoints())) {
    const P p = s.point(t);
    EXPECT_TRUE(same<K>(p.x() * p.x() + p.y() * p.y(), FT(1), 1e-13));
    EXPECT_TRUE(same<K>(p, quarter.point(t), 1e-12));
  }
  // The curvature of the unit circle is 1 everywhere.
  EXPECT_NEAR(s.curvature(0.3), 1.0, 1e-12);
}

TYPED_TEST(Cubic_spline, ControlPointEditKeepsC2) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::mt19937 rng(29);
  const fair::Cubic_spline_2<K> s = random_spline<K>(rng, 6, false, false);
  const auto e = s.with_control_point(3, typename K::Point_2(q<K>(7, 3), q<K>(-1, 5)));
  for (std::size_t i = 1; i < 6; ++i) {
    const auto f = e.piece(i - 1), g = e.piece(i);
    EXPECT_TRUE(same<K>(g.derivative(FT(0)), f.derivative(FT(1)) * e.beta(i), 1e-10));
    EXPECT_TRUE(same<K>(g.second_derivative(FT(0)), f.second_derivative(FT(1)) * (e.beta(i) * e.beta(i)), 1e-9));
  }
  // local support: pieces 0 and 5 do not depend on control point 3 (basis on [t_0, t_4])
  EXPECT_TRUE(same<K>(e.piece(5).control_point(2), s.piece(5).control_point(2)));
}

// The classic cubic methods produce the library's spline: its pieces are theirs (exactly in an
// exact kernel), and the interpolating spline passes through the data at its knots.
template <class K, class Method>
void expect_spline_is_the_method(const Method& method, double rel) {
  const auto& s = method.spline();
  ASSERT_EQ(s.number_of_pieces(), method.number_of_pieces());
  EXPECT_FALSE(s.is_rational());
  const auto pieces = s.polynomial_pieces();
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t k = 0; k < 4; ++k)
      EXPECT_TRUE(same<K>(pieces[i].control_point(k), method.pieces()[i].control_point(k), rel)) << i << " " << k;
}

TYPED_TEST(Cubic_spline, ClassicCubicMethodsProduceIt) {
  typedef TypeParam K;
  std::mt19937 rng(37);
  for (int closed = 0; closed < 2; ++closed) {
    const auto p = fair_test::random_points<K>(rng, 9);
    fair::Cubic_interpolating_spline_options io;  // closed: periodic; open: natural
    io.closed = closed == 1;
    io.knot_spacing = fair::Knot_spacing::CHORDAL;
    const fair::Cubic_interpolating_spline_2<K> interpolant(p, io);
    expect_spline_is_the_method<K>(interpolant, 1e-12);
    for (std::size_t i = 0; i < p.size(); ++i)
      EXPECT_TRUE(same<K>(interpolant.spline().point(interpolant.knots()[i]), p[i], 1e-12));
    EXPECT_EQ(interpolant.spline().is_closed(), closed == 1);
    // the uniform methods' pieces come from their spline: compare them with the uniform
    // B-spline segment formula instead (Bezier points (d0 + 4 d1 + d2)/6, (2 d1 + d2)/3, ...)
    for (int method = 0; method < 3; ++method) {
      if (method == 2 && closed) continue;
      fair::Cubic_bspline_options bo;
      bo.closed = closed == 1;
      bo.ends = method == 2 ? fair::Cubic_bspline_ends::TRIMMED : fair::Cubic_bspline_ends::INTERPOLATE_END_POINTS;
      fair::Cubic_quasi_interpolant_options qo;
      qo.closed = closed == 1;
      const fair::Cubic_bspline_2<K> bs(p, bo);
      const fair::Cubic_quasi_interpolant_2<K> qi(p, qo);
      const auto& d = method == 1 ? qi.control_polygon() : bs.control_polygon();
      const auto& s = method == 1 ? qi.spline() : bs.spline();
      const std::size_t n = d.size(), pieces = closed ? n : n - 3;
      ASSERT_EQ(s.number_of_pieces(), pieces);
      for (std::size_t j = 0; j < pieces; ++j) {
        const auto& d0 = d[closed ? (j + n - 1) % n : j];
        const auto& d1 = d[closed ? j : j + 1];
        const auto& d2 = d[closed ? (j + 1) % n : j + 2];
        const auto& d3 = d[closed ? (j + 2) % n : j + 3];
        typedef typename K::FT FT;
        auto mix = [](const FT& a, const typename K::Point_2& x, const FT& b, const typename K::Point_2& y, const FT& c,
                      const typename K::Point_2& z) {
          return typename K::Point_2(a * x.x() + b * y.x() + c * z.x(), a * x.y() + b * y.y() + c * z.y());
        };
        const auto piece = s.polynomial_piece(j);
        EXPECT_TRUE(same<K>(piece.control_point(0), mix(q<K>(1, 6), d0, q<K>(4, 6), d1, q<K>(1, 6), d2), 1e-12));
        EXPECT_TRUE(same<K>(piece.control_point(1), mix(q<K>(2, 3), d1, q<K>(1, 3), d2, FT(0), d3), 1e-12));
        EXPECT_TRUE(same<K>(piece.control_point(2), mix(q<K>(1, 3), d1, q<K>(2, 3), d2, FT(0), d3), 1e-12));
        EXPECT_TRUE(same<K>(piece.control_point(3), mix(q<K>(1, 6), d1, q<K>(4, 6), d2, q<K>(1, 6), d3), 1e-12));
      }
      expect_spline_is_the_method<K>(bs, 0);
    }
  }
  // closed uniform B-spline: the data are the periodic control points themselves
  const auto p = fair_test::random_points<K>(rng, 5);
  fair::Cubic_bspline_options closed_options;
  closed_options.closed = true;
  const fair::Cubic_bspline_2<K> b(p, closed_options);
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_TRUE(same<K>(b.spline().control_points()[i], p[i]));
}

// Equal weights other than 1: the same polynomial curve, also after knot insertion.
TYPED_TEST(Cubic_spline, EqualWeightsAreThePolynomialSpline) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  const std::vector<P> d{P(0, 0), P(1, 2), P(3, 2), P(4, 0)};
  const fair::Cubic_spline_2<K> s({FT(0), FT(1)}, d, std::vector<FT>(4, FT(2)));
  EXPECT_FALSE(s.is_rational());
  EXPECT_TRUE(same<K>(s.weights()[2], FT(1)));
  const auto r = s.with_knot_inserted(q<K>(1, 2));
  for (int k = 0; k <= 8; ++k) EXPECT_TRUE(same<K>(r.point(q<K>(k, 8)), fair::Bezier_2<K>(d).point(q<K>(k, 8))));
}

// Strongly non-uniform chordal knots (intervals of 1e-8 next to 1): eq. 3 in its
// better-conditioned form keeps the classic interpolant's spline within rounding of its pieces.
TYPED_TEST(Cubic_spline, ClassicInterpolantOnVeryNonUniformKnots) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  for (double e : {1e-6, 1e-8, 1e-10}) {
    const std::vector<P> p{P(0, 0), P(1, 0), P(1 + e, e), P(2, 1), P(3, 0), P(4, 1)};
    fair::Cubic_interpolating_spline_options chordal;
    chordal.knot_spacing = fair::Knot_spacing::CHORDAL;
    const fair::Cubic_interpolating_spline_2<K> c(p, chordal);
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_TRUE(same<K>(c.spline().point(c.knots()[i]), p[i], 1e-12)) << e;
  }
}

TEST(Cubic_spline_json, TheBsplineMemberIsTheNurbsForm) {
  typedef fair_test::SC_gmpq K;
  std::mt19937 rng(31);
  const auto s = random_spline<K>(rng, 4, true, true);
  const nlohmann::json j = fair::io::spline_curve_to_json(s);
  EXPECT_EQ(j["format"], "fair-curve");
  ASSERT_EQ(j["pieces"].size(), 4u);
  const auto& b = j["bspline"];
  EXPECT_EQ(b["degree"], 3);
  EXPECT_EQ(b["closed"], true);
  EXPECT_EQ(b["knots"].size(), b["control_points"].size() + 4);
  EXPECT_EQ(b["weights"].size(), b["control_points"].size());
  EXPECT_EQ(b["control_points"].size(), 4u + 3u);  // the periodic form: m + 3 (the last 3 repeat the first)
  EXPECT_EQ(b["control_points"][4], b["control_points"][0]);
  // exact rationals that are not doubles are written as "p/q"
  const auto third = fair::Cubic_spline_2<K>({K::FT(0), K::FT(1) / 3}, fair_test::random_points<K>(rng, 4));
  EXPECT_EQ(fair::io::nurbs_to_json(third.nurbs())["knots"][4], "1/3");
}

TEST(Cubic_spline_errors, BadDataIsRejectedWithAMessage) {
  typedef fair_test::SC_double K;
  typedef K::Point_2 P;
  const std::vector<P> four{P(0, 0), P(1, 0), P(2, 1), P(3, 0)};
  EXPECT_THROW(fair::Cubic_spline_2<K>({0.0}, four), fair::Precondition_error);           // too few breakpoints
  EXPECT_THROW(fair::Cubic_spline_2<K>({0.0, 0.0}, four), fair::Precondition_error);      // not increasing
  EXPECT_THROW(fair::Cubic_spline_2<K>({0.0, 1.0, 2.0}, four), fair::Precondition_error); // needs 5 points
  EXPECT_THROW(fair::Cubic_spline_2<K>({0.0, 1.0, 2.0}, four, true), fair::Precondition_error); // closed needs 3 pieces
  EXPECT_THROW(fair::Cubic_spline_2<K>({0.0, std::nan("")}, four), fair::Precondition_error);
  EXPECT_THROW(fair::Cubic_spline_2<K>({0.0, 1.0}, {P(0, 0), P(1, 0), P(HUGE_VAL, 1), P(3, 0)}), fair::Precondition_error);
  EXPECT_THROW(fair::Cubic_spline_2<K>({0.0, 1.0}, four, {1.0, 0.0, 1.0, 1.0}), fair::Precondition_error);
  EXPECT_THROW(fair::Cubic_spline_2<K>({0.0, 1.0}, four, {1.0, 1.0, 1.0}), fair::Precondition_error);
  const fair::Cubic_spline_2<K> s({0.0, 1.0}, four);
  EXPECT_THROW(s.point(1.5), fair::Precondition_error);
  EXPECT_THROW(s.with_knot_inserted(0.0), fair::Precondition_error);
  EXPECT_THROW(s.with_knot_inserted(2.0), fair::Precondition_error);
  EXPECT_THROW(s.beta(0), fair::Precondition_error);
  EXPECT_THROW(s.piece(1), fair::Precondition_error);
  const fair::Cubic_spline_2<K> r({0.0, 1.0}, four, {1.0, 2.0, 1.0, 1.0});
  EXPECT_THROW(r.polynomial_pieces(), fair::Precondition_error);
  // NaN parameters and sizes whose sums overflow double are refused, not turned into NaN
  EXPECT_THROW(s.point(std::nan("")), fair::Precondition_error);
  EXPECT_THROW(s.curvature(std::nan("")), fair::Precondition_error);
  EXPECT_THROW(fair::Cubic_spline_2<K>({0.0, 1e308, 1.7e308}, std::vector<P>(5, P(0, 0))), fair::Precondition_error);
  EXPECT_THROW(fair::Cubic_spline_2<K>({0.0, 1.0}, {P(0, 0), P(1e308, 0), P(-1e308, 1), P(3, 0)}),
               fair::Precondition_error);
  try {
    fair::Cubic_spline_2<K>({0.0, 1.0, 0.5, 2.0}, std::vector<P>(6, P(0, 0)));
    FAIL();
  } catch (const fair::Precondition_error& e) {
    EXPECT_NE(std::string(e.what()).find("breakpoints 1 and 2"), std::string::npos) << e.what();
  }
}

} // namespace
