// Tests of the classic approximants and subdivision: Cubic_bspline_2 (data as control points),
// Cubic_quasi_interpolant_2 ((-1,8,-1)/6) and Four_point_subdivision_2 (Dyn-Levin-Gregory and
// the relaxed variant).

#include <fair/Cubic_bspline_2.h>
#include <fair/Cubic_quasi_interpolant_2.h>
#include <fair/Four_point_subdivision_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <vector>

namespace {

using namespace fair_test;

// The options the tests build most often (doc/concepts.md: closed is an option of every family).
fair::Cubic_bspline_options bspline_options(bool closed,
                                            fair::Cubic_bspline_ends ends = fair::Cubic_bspline_ends::INTERPOLATE_END_POINTS) {
  fair::Cubic_bspline_options o;
  o.closed = closed;
  o.ends = ends;
  return o;
}
fair::Cubic_quasi_interpolant_options quasi_options(bool closed) {
  fair::Cubic_quasi_interpolant_options o;
  o.closed = closed;
  return o;
}
fair::Four_point_subdivision_options four_point_options(
    bool closed, fair::Four_point_variant variant = fair::Four_point_variant::INTERPOLATORY) {
  fair::Four_point_subdivision_options o;
  o.closed = closed;
  o.variant = variant;
  return o;
}

// C2 at every join of a sequence of pieces on uniform knots (all pieces have h = 1).
template <class K, class Piece>
void check_c2_joins(const std::vector<Piece>& pieces, bool closed) {
  typedef typename K::FT FT;
  const std::size_t joins = closed ? pieces.size() : pieces.size() - 1;
  for (std::size_t i = 0; i < joins; ++i) {
    const Piece& a = pieces[i];
    const Piece& b = pieces[(i + 1) % pieces.size()];
    EXPECT_TRUE(same<K>(a.point(FT(1)), b.point(FT(0)), 1e-11)) << "C0";
    EXPECT_TRUE(same<K>(a.derivative(FT(1)), b.derivative(FT(0)), 1e-11)) << "C1";
    EXPECT_TRUE(same<K>(a.second_derivative(FT(1)), b.second_derivative(FT(0)), 1e-11)) << "C2";
  }
}

// The fourth difference p_{i-2} - 4 p_{i-1} + 6 p_i - 4 p_{i+1} + p_{i+2} (indices mod n).
template <class K>
typename K::Vector_2 fourth_difference(const std::vector<typename K::Point_2>& p, std::size_t i) {
  const std::size_t n = p.size();
  const auto& a = p[(i + n - 2) % n];
  const auto& b = p[(i + n - 1) % n];
  const auto& c = p[i];
  const auto& d = p[(i + 1) % n];
  const auto& e = p[(i + 2) % n];
  return typename K::Vector_2(a.x() - 4 * b.x() + 6 * c.x() - 4 * d.x() + e.x(),
                              a.y() - 4 * b.y() + 6 * c.y() - 4 * d.y() + e.y());
}

template <class K>
class Classic_approximants : public ::testing::Test {};
TYPED_TEST_SUITE(Classic_approximants, All_kernels);

// ---------------------------------------------------------------------------------------------
// Cubic_bspline_2

TYPED_TEST(Classic_approximants, BsplineKnotValuesContinuityAndEnds) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  std::mt19937 rng(11);
  const int trials = is_exact<K>() ? 3 : 30;
  for (int trial = 0; trial < trials; ++trial) {
    const std::size_t n = 4 + static_cast<std::size_t>(trial % 7);
    const auto p = random_points<K>(rng, n);
    // Closed: n pieces, piece i starts at the knot value (p_{i-1} + 4 p_i + p_{i+1})/6.
    fair::Cubic_bspline_2<K> closed(p, bspline_options(true));
    EXPECT_TRUE(closed.is_closed());
    ASSERT_EQ(closed.pieces().size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      const P& a = p[(i + n - 1) % n];
      const P& c = p[(i + 1) % n];
      EXPECT_TRUE(same<K>(closed.pieces()[i].point(FT(0)), P((a.x() + 4 * p[i].x() + c.x()) / 6, (a.y() + 4 * p[i].y() + c.y()) / 6), 1e-11)) << "knot value";
    }
    check_c2_joins<K>(closed.pieces(), true);
    // Open with end points: starts at p_0 with zero second derivative, n - 1 pieces.
    fair::Cubic_bspline_2<K> open(p);
    ASSERT_EQ(open.pieces().size(), n - 1);
    EXPECT_TRUE(same<K>(open.pieces().front().point(FT(0)), p.front(), 1e-11)) << "start";
    EXPECT_TRUE(same<K>(open.pieces().back().point(FT(1)), p.back(), 1e-11)) << "end";
    EXPECT_TRUE(same<K>(open.pieces().front().derivative(FT(0)), p[1] - p[0], 1e-11)) << "start tangent";
    EXPECT_TRUE(same<K>(open.pieces().front().second_derivative(FT(0)), typename K::Vector_2(0, 0), 1e-11)) << "start c''";
    EXPECT_TRUE(same<K>(open.pieces().back().second_derivative(FT(1)), typename K::Vector_2(0, 0), 1e-11)) << "end c''";
    check_c2_joins<K>(open.pieces(), false);
    // Trimmed: n - 3 pieces, from (p0 + 4 p1 + p2)/6.
    fair::Cubic_bspline_2<K> trimmed(p, bspline_options(false, fair::Cubic_bspline_ends::TRIMMED));
    ASSERT_EQ(trimmed.pieces().size(), n - 3);
    EXPECT_TRUE(same<K>(trimmed.pieces()[0].point(FT(0)), P((p[0].x() + 4 * p[1].x() + p[2].x()) / 6, (p[0].y() + 4 * p[1].y() + p[2].y()) / 6), 1e-11)) << "trimmed start";
    check_c2_joins<K>(trimmed.pieces(), false);
  }
}

// Linear data are reproduced; quadratic data q(i) give q(u) + q''/6 (a constant shift).
TYPED_TEST(Classic_approximants, BsplineReproducesLinesAndShiftsQuadratics) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  std::vector<P> line, quad;
  auto q = [](const FT& u) { return P(u * u / 2 - u, 3 * u * u + 1); };  // q'' = (1, 6)
  for (int i = 0; i <= 6; ++i) {
    line.push_back(P(FT(3 * i - 2), FT(1) - FT(i) / 4));
    quad.push_back(q(FT(i)));
  }
  fair::Cubic_bspline_2<K> bl(line);
  for (std::size_t i = 0; i < bl.pieces().size(); ++i) {
    const FT u = FT(static_cast<int>(i)) + FT(1) / 3;
    EXPECT_TRUE(same<K>(bl.pieces()[i].point(FT(1) / 3), P(3 * u - 2, FT(1) - u / 4), 1e-11)) << "line";
  }
  fair::Cubic_bspline_2<K> bq(quad, bspline_options(false, fair::Cubic_bspline_ends::TRIMMED));
  for (std::size_t i = 0; i < bq.pieces().size(); ++i) {
    const FT u = FT(static_cast<int>(i) + 1) + FT(2) / 5;  // trimmed piece i spans [i+1, i+2]
    EXPECT_TRUE(same<K>(bq.pieces()[i].point(FT(2) / 5), q(u) + typename K::Vector_2(FT(1) / 6, 1), 1e-11)) << "quadratic";
  }
}

// ---------------------------------------------------------------------------------------------
// Cubic_quasi_interpolant_2

// Hand value: data (0,0), (1,0), (2,1), (3,0), (4,0). The fourth difference at index 2 is
// p0 - 4 p1 + 6 p2 - 4 p3 + p4 = (0 - 4 + 12 - 12 + 4, 6) = (0, 6), so the curve passes at
// knot 2 through p2 - (0,6)/36 = (2, 5/6): it does not interpolate p2.
TYPED_TEST(Classic_approximants, QuasiInterpolantByHandDoesNotInterpolate) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  const std::vector<P> p = {P(0, 0), P(1, 0), P(2, 1), P(3, 0), P(4, 0)};
  fair::Cubic_quasi_interpolant_2<K> q(p);
  ASSERT_EQ(q.pieces().size(), 4u);
  EXPECT_TRUE(same<K>(q.pieces()[2].point(FT(0)), P(2, FT(5) / 6), 1e-11)) << "knot 2";
  EXPECT_TRUE(same<K>(q.pieces()[1].point(FT(1)), P(2, FT(5) / 6), 1e-11)) << "knot 2 from the left";
  // The end points and their neighbours are interpolated (end cubic extrapolation).
  EXPECT_TRUE(same<K>(q.pieces()[0].point(FT(0)), p[0], 1e-11)) << "p0";
  EXPECT_TRUE(same<K>(q.pieces()[1].point(FT(0)), p[1], 1e-11)) << "p1";
  EXPECT_TRUE(same<K>(q.pieces()[3].point(FT(0)), p[3], 1e-11)) << "p3";
  EXPECT_TRUE(same<K>(q.pieces()[3].point(FT(1)), p[4], 1e-11)) << "p4";
  check_c2_joins<K>(q.pieces(), false);
}

TYPED_TEST(Classic_approximants, QuasiInterpolantReproducesCubicsUpToTheEnds) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  auto q = [](const FT& u) { return P(u * u * u / 3 - 2 * u, FT(5) - u * u + u * u * u / 7); };
  std::vector<P> p;
  for (int i = 0; i <= 7; ++i) p.push_back(q(FT(i)));
  fair::Cubic_quasi_interpolant_2<K> c(p);
  ASSERT_EQ(c.pieces().size(), 7u);
  for (std::size_t i = 0; i < c.pieces().size(); ++i)
    for (int k = 0; k <= 4; ++k)
      EXPECT_TRUE(same<K>(c.pieces()[i].point(FT(k) / 4), q(FT(static_cast<int>(i)) + FT(k) / 4), 1e-11)) << "cubic";
  // Exactly four points: the data define one cubic, which is reproduced, so all four are hit.
  std::vector<P> four(p.begin(), p.begin() + 4);
  fair::Cubic_quasi_interpolant_2<K> c4(four);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_TRUE(same<K>(c4.pieces()[i].point(FT(1) / 2), q(FT(static_cast<int>(i)) + FT(1) / 2), 1e-11)) << "4 points";
}

TYPED_TEST(Classic_approximants, QuasiInterpolantKnotValuesOnRandomClosedData) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::mt19937 rng(12);
  const int trials = is_exact<K>() ? 3 : 30;
  for (int trial = 0; trial < trials; ++trial) {
    const std::size_t n = 3 + static_cast<std::size_t>(trial % 8);
    const auto p = random_points<K>(rng, n);
    fair::Cubic_quasi_interpolant_2<K> c(p, quasi_options(true));
    EXPECT_TRUE(c.is_closed() && c.options().closed);
    ASSERT_EQ(c.pieces().size(), n);
    for (std::size_t i = 0; i < n; ++i)
      EXPECT_TRUE(same<K>(c.pieces()[i].point(FT(0)), p[i] - fourth_difference<K>(p, i) / FT(36), 1e-11)) << "p_i - D4/36";
    check_c2_joins<K>(c.pieces(), true);
    if (n >= 4) {
      fair::Cubic_quasi_interpolant_2<K> o(p);
      check_c2_joins<K>(o.pieces(), false);
      EXPECT_TRUE(same<K>(o.pieces().front().point(FT(0)), p.front(), 1e-11)) << "open start";
      EXPECT_TRUE(same<K>(o.pieces().back().point(FT(1)), p.back(), 1e-11)) << "open end";
    }
  }
}

TYPED_TEST(Classic_approximants, BsplineAndQuasiInterpolantRejectBadInput) {
  typedef TypeParam K;
  typedef typename K::Point_2 P;
  typedef fair::Cubic_bspline_2<K> B;
  typedef fair::Cubic_quasi_interpolant_2<K> Q;
  EXPECT_THROW(B({P(0, 0)}), fair::Invalid_input_error);
  EXPECT_THROW(B({P(0, 0), P(1, 0), P(2, 2)}, bspline_options(false, fair::Cubic_bspline_ends::TRIMMED)), fair::Invalid_input_error);
  EXPECT_THROW(B({P(0, 0), P(1, 0)}, bspline_options(true)), fair::Invalid_input_error);
  EXPECT_THROW(B({P(0, 0), P(1, 0), P(1, 0)}), fair::Invalid_input_error);
  EXPECT_THROW(Q({P(0, 0), P(1, 0), P(2, 2)}), fair::Invalid_input_error);
  EXPECT_THROW(Q({P(0, 0), P(1, 0), P(2, 2), P(0, 0)}, quasi_options(true)), fair::Invalid_input_error);
  EXPECT_THROW(Q({P(0, 0), P(1, 0), P(2, 2), P(2, 2), P(3, 3)}), fair::Invalid_input_error);
  if (!is_exact<K>()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(B({P(0, 0), P(nan, 0), P(2, 2)}), fair::Invalid_input_error);
    EXPECT_THROW(Q({P(0, 0), P(1, 0), P(2, inf), P(3, 3)}), fair::Invalid_input_error);
    // Finite data whose extrapolation overflows double.
    EXPECT_THROW(Q({P(0, 0), P(1e308, 0), P(-1e308, 0), P(1e308, 1)}), fair::Invalid_input_error);
    EXPECT_THROW(B({P(-1.5e308, 0), P(1.5e308, 0)}), fair::Invalid_input_error);
  }
}

// ---------------------------------------------------------------------------------------------
// Four_point_subdivision_2

// Hand values, data (0,0), (1,0), (2,1), (3,0), (4,0), one round.
// DLG: the point on edge (p1, p2) is 9/16 (p1 + p2) - 1/16 (p0 + p3) = (27/16 - 3/16, 9/16)
//      = (3/2, 9/16), at index 3; p2 stays at index 4.
// Relaxed (gamma = -3/128): p2 moves to p2 + gamma D4 = (2, 1 - 18/128) = (2, 55/64).
TYPED_TEST(Classic_approximants, FourPointByHand) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  const std::vector<P> p = {P(0, 0), P(1, 0), P(2, 1), P(3, 0), P(4, 0)};
  fair::Four_point_subdivision_2<K> dlg(p);
  const auto r = dlg.refine(1);
  ASSERT_EQ(r.size(), 9u);
  EXPECT_TRUE(same<K>(r[3], P(FT(3) / 2, FT(9) / 16), 1e-11)) << "DLG edge point";
  EXPECT_TRUE(same<K>(r[4], p[2], 1e-11)) << "DLG keeps p2";
  fair::Four_point_subdivision_2<K> rel(p, four_point_options(false, fair::Four_point_variant::RELAXED));
  const auto s = rel.refine(1);
  ASSERT_EQ(s.size(), 9u);
  EXPECT_TRUE(same<K>(s[3], P(FT(3) / 2, FT(9) / 16), 1e-11)) << "relaxed edge point";
  EXPECT_TRUE(same<K>(s[4], P(2, FT(55) / 64), 1e-11)) << "relaxed vertex";
  // The end points and their neighbours do not move (end cubic extrapolation: D4 = 0 there).
  EXPECT_TRUE(same<K>(s[0], p[0], 1e-11)) << "relaxed p0";
  EXPECT_TRUE(same<K>(s[2], p[1], 1e-11)) << "relaxed p1";
  EXPECT_TRUE(dlg.refine(0) == p);
}

// Both variants reproduce cubics: q(i) -> q(j / 2^k), up to the ends of open polylines.
TYPED_TEST(Classic_approximants, FourPointReproducesCubics) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  auto q = [](const FT& u) { return P(u * u * u - 3 * u, FT(2) - u * u * u / 4 + u * u); };
  std::vector<P> p;
  for (int i = 0; i <= 5; ++i) p.push_back(q(FT(i)));
  const std::size_t rounds = is_exact<K>() ? 3 : 5;
  const FT step = FT(1) / FT(1 << rounds);
  for (auto v : {fair::Four_point_variant::INTERPOLATORY, fair::Four_point_variant::RELAXED}) {
    fair::Four_point_subdivision_2<K> s(p, four_point_options(false, v));
    const auto r = s.refine(rounds);
    ASSERT_EQ(r.size(), s.size_after(rounds));
    ASSERT_EQ(r.size(), 5u * (1u << rounds) + 1);
    for (std::size_t j = 0; j < r.size(); ++j)
      EXPECT_TRUE(same<K>(r[j], q(FT(static_cast<int>(j)) * step), 1e-11)) << "cubic";
  }
}

TYPED_TEST(Classic_approximants, FourPointInterpolatesRandomData) {
  typedef TypeParam K;
  std::mt19937 rng(13);
  const int trials = is_exact<K>() ? 2 : 20;
  const std::size_t rounds = is_exact<K>() ? 2 : 4;
  for (int trial = 0; trial < trials; ++trial) {
    const std::size_t n = 4 + static_cast<std::size_t>(trial % 6);
    const auto p = random_points<K>(rng, n);
    for (bool closed : {false, true}) {
      fair::Four_point_subdivision_options o = four_point_options(closed);
      o.tension = 0.1;
      o.rounds = rounds;
      fair::Four_point_subdivision_2<K> s(p, o);
      const auto r = s.refine(rounds);
      ASSERT_EQ(r.size(), closed ? n << rounds : ((n - 1) << rounds) + 1);
      for (std::size_t i = 0; i < n; ++i) EXPECT_TRUE(r[i << rounds] == p[i]) << "interpolates p_" << i;
      // The contract's pieces: the segments of refine(options().rounds), closing when closed.
      EXPECT_TRUE(s.polyline() == r);
      ASSERT_EQ(s.number_of_pieces(), closed ? r.size() : r.size() - 1);
      for (std::size_t j = 0; j < s.number_of_pieces(); ++j) {
        ASSERT_EQ(s.pieces()[j].degree(), 1u);
        EXPECT_TRUE(s.pieces()[j].source() == r[j] && s.pieces()[j].target() == r[(j + 1) % r.size()]) << j;
      }
    }
  }
}

TYPED_TEST(Classic_approximants, FourPointRejectsBadInput) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  typedef fair::Four_point_subdivision_2<K> S;
  const std::vector<P> ok = {P(0, 0), P(1, 0), P(2, 1), P(3, 0)};
  EXPECT_THROW(S({P(0, 0), P(1, 0), P(2, 1)}), fair::Invalid_input_error);
  EXPECT_THROW(S({P(0, 0), P(1, 0)}, four_point_options(true)), fair::Invalid_input_error);
  EXPECT_THROW(S({P(0, 0), P(1, 0), P(1, 0), P(3, 0)}), fair::Invalid_input_error);
  fair::Four_point_subdivision_options o = four_point_options(false);
  o.tension = 0;
  EXPECT_THROW(S(ok, o), fair::Precondition_error);
  o.tension = 0.2;
  EXPECT_THROW(S(ok, o), fair::Precondition_error);
  o = four_point_options(false, fair::Four_point_variant::RELAXED);
  o.relaxation = 0.1;
  EXPECT_THROW(S(ok, o), fair::Precondition_error);
  o.relaxation = -0.125;
  EXPECT_THROW(S(ok, o), fair::Precondition_error);
  o.relaxation = -3.0 / 128;
  o.tension = 0.1;  // the relaxed scheme is derived for w = 1/16 only
  EXPECT_THROW(S(ok, o), fair::Precondition_error);
  o = four_point_options(false);
  o.rounds = S::max_rounds + 1;
  EXPECT_THROW(S(ok, o), fair::Precondition_error);
  EXPECT_TRUE(S(ok, four_point_options(false, fair::Four_point_variant::RELAXED)).relaxation() == FT(-3) / FT(128));
  const S s(ok);
  EXPECT_THROW(s.refine(S::max_rounds + 1), fair::Precondition_error);
  EXPECT_THROW(s.round({P(0, 0), P(1, 0), P(2, 1)}), fair::Precondition_error);
  std::vector<P> many;
  for (int i = 0; i < 1000; ++i) many.push_back(P(i, i % 7));
  EXPECT_THROW(S(many).refine(15), fair::Precondition_error);  // 999 * 2^15 + 1 > 2^24 points
  if (!is_exact<K>()) {
    EXPECT_THROW(S({P(0, 0), P(1, 0), P(2, std::nan("")), P(3, 0)}), fair::Invalid_input_error);
    EXPECT_THROW(S({P(0, 0), P(1, 0), P(2, 1), P(std::numeric_limits<double>::infinity(), 0)}),
                 fair::Invalid_input_error);
  }
}

// Convergence on random closed data (double): with d_k = max |new edge point - edge midpoint| at
// round k, the scaled first differences 2^k Delta p^k move by 2^(k+1) d_k per round, so they
// converge (C1 limit) when d_k decays faster than 2^-k. For the DLG scheme (w = 1/16) d_k decays
// like 4^-k; for the relaxed scheme the scaled second differences 4^k Delta^2 p^k converge too
// (C2), while for DLG they do not.
struct Round_statistics {
  double first = 0;   // 2^(k+1) max |p^{k+1}_{2i+1} - (p^k_i + p^k_{i+1})/2|
  double second = 0;  // max |4^(k+1) D2 p^{k+1}_{2i} - 4^k D2 p^k_i|
};

template <class K>
std::vector<Round_statistics> round_statistics(const fair::Four_point_subdivision_2<K>& s, std::size_t rounds) {
  std::vector<Round_statistics> out;
  std::vector<typename K::Point_2> p = s.points();
  auto d2 = [](const std::vector<typename K::Point_2>& q, std::size_t i) {
    const std::size_t n = q.size();
    return (q[(i + n - 1) % n] - q[i]) + (q[(i + 1) % n] - q[i]);
  };
  double scale = 1;
  for (std::size_t k = 0; k < rounds; ++k) {
    const auto r = s.round(p);
    Round_statistics st;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto mid = CGAL::midpoint(p[i], p[(i + 1) % p.size()]);
      st.first = std::max(st.first, 2 * scale * std::sqrt(CGAL::to_double(CGAL::squared_distance(r[2 * i + 1], mid))));
      const auto e = d2(r, 2 * i) * (4 * scale * scale) - d2(p, i) * (scale * scale);
      st.second = std::max(st.second, std::sqrt(CGAL::to_double(e.squared_length())));
    }
    out.push_back(st);
    p = r;
    scale *= 2;
  }
  return out;
}

TEST(Classic_four_point, SuccessiveRoundsConvergeC1AndRelaxedC2) {
  std::mt19937 rng(2026);
  for (int trial = 0; trial < 20; ++trial) {
    const auto p = random_points<SC_double>(rng, 6 + static_cast<std::size_t>(trial % 10));
    const auto dlg = round_statistics(fair::Four_point_subdivision_2<SC_double>(p, four_point_options(true)), 12);
    const auto rel = round_statistics(
        fair::Four_point_subdivision_2<SC_double>(p, four_point_options(true, fair::Four_point_variant::RELAXED)), 12);
    for (std::size_t k = 3; k + 1 < dlg.size(); ++k) {
      // C1: the tangent estimates move less and less (geometric, ratio about 1/2).
      EXPECT_LT(dlg[k + 1].first, 0.75 * dlg[k].first) << "DLG round " << k << " trial " << trial;
      EXPECT_LT(rel[k + 1].first, 0.75 * rel[k].first) << "relaxed round " << k << " trial " << trial;
      // C2 of the relaxed scheme: the scaled second differences converge as well.
      EXPECT_LT(rel[k + 1].second, 0.75 * rel[k].second) << "relaxed round " << k << " trial " << trial;
    }
    EXPECT_LT(dlg.back().first, 0.05 * dlg[2].first);  // measured: about 0.011 (ratio ~0.6 per round)
    EXPECT_LT(rel.back().second, 1e-2 * rel[2].second);
    // DLG is not C2: its scaled second differences do not settle down.
    EXPECT_GT(dlg.back().second, 0.1 * dlg[2].second) << "trial " << trial;
  }
}

// The smoothness claims of Four_point_subdivision_2.h, re-derived in exact rational arithmetic:
// S_a is C^m if the scheme with symbol b(z) = 2^m a(z) / (1 + z)^(m+1) is contractive, i.e.
// max over residues r mod 2^L of sum_j |coefficient of z^(r + j 2^L) in b(z) b(z^2)...b(z^(2^(L-1)))|
// is < 1 for some L (Dyn 1992). The mask of a round is a(z) = sum_k a_k z^k with
//   a_{+-1} = 1/2 + w, a_{+-3} = -w (edge rule), a_0 = 1 + 6 gamma, a_{+-2} = -4 gamma,
//   a_{+-4} = gamma (vertex rule).
typedef CGAL::Gmpq Q;
typedef std::map<int, Q> Laurent;

Laurent divide_by_one_plus_z(const Laurent& a) {  // exact; fails the test if not divisible
  const int lo = a.begin()->first, hi = a.rbegin()->first;
  Laurent q;
  Q carry(0);
  for (int k = lo; k < hi; ++k) {
    const auto it = a.find(k);
    const Q c = (it == a.end() ? Q(0) : it->second) - carry;
    q[k] = c;
    carry = c;
  }
  const auto it = a.find(hi);
  EXPECT_EQ((it == a.end() ? Q(0) : it->second), carry) << "not divisible by (1 + z)";
  return q;
}

double contraction_norm(const Laurent& b, int L) {
  Laurent p;
  p[0] = Q(1);
  for (int l = 0; l < L; ++l) {
    Laurent r;
    for (const auto& x : p)
      for (const auto& y : b) r[x.first + y.first * (1 << l)] += x.second * y.second;
    p = r;
  }
  const int m = 1 << L;
  std::map<int, Q> sums;
  for (const auto& x : p) sums[((x.first % m) + m) % m] += CGAL::abs(x.second);
  Q worst(0);
  for (const auto& s : sums) worst = std::max(worst, s.second);
  return CGAL::to_double(worst / Q(m));  // (1/2)^L: the scheme is (1/2) S_{2b}
}

bool is_Cm(const Q& w, const Q& gamma, int m) {
  Laurent a;
  a[-4] = a[4] = gamma;
  a[-3] = a[3] = -w;
  a[-2] = a[2] = Q(-4) * gamma;
  a[-1] = a[1] = Q(1, 2) + w;
  a[0] = Q(1) + Q(6) * gamma;
  for (auto it = a.begin(); it != a.end();) it = (it->second == 0) ? a.erase(it) : std::next(it);
  Laurent b = a;
  for (int i = 0; i <= m; ++i) {
    b = divide_by_one_plus_z(b);
    for (auto& c : b) c.second *= Q(2);
  }
  for (int L = 1; L <= 8; ++L)
    if (contraction_norm(b, L) < 1) return true;
  return false;
}

TEST(Classic_four_point, DifferenceSchemeCertifiesTheStatedSmoothness) {
  const Q w(1, 16);
  EXPECT_TRUE(is_Cm(w, Q(0), 1));             // DLG 1987: C1 for w = 1/16
  EXPECT_FALSE(is_Cm(w, Q(0), 2));            // and the test cannot give C2 (DLG is not C2)
  EXPECT_TRUE(is_Cm(Q(1, 10), Q(0), 1));      // C1 inside (0, (sqrt 5 - 1)/8)
  for (const Q& g : {Q(-1, 16), Q(-1, 32), Q(-3, 128), Q(-1, 256)}) EXPECT_TRUE(is_Cm(w, g, 2)) << g;
  for (const Q& g : {Q(-3, 128), Q(-1, 32), Q(-9, 256)}) EXPECT_TRUE(is_Cm(w, g, 3)) << g;
}

} // namespace
