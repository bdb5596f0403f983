// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::io::svg_path (include/fair/io/write_svg_path.h): polynomial pieces of degree <= 3 are
// their own L/Q/C commands (the d text parsed back gives the control points bit for bit);
// rational pieces and higher degrees are cubics within the certified bound (B): checked against
// the curve evaluated by Nurbs_curve_2::point at 257 parameters of every cubic, for every case
// of nurbs_cases.h and three tolerances; the bound shrinks ~16x per halving (O(h^4)).

#include "nurbs_cases.h"
#include "test_support.h"

#include <fair/io/write_svg_path.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef fair_test::SC_double K;

/// The commands of a d text: (letter, numbers).
std::vector<std::pair<char, std::vector<double>>> parse_d(const std::string& d) {
  std::istringstream in(d);
  std::vector<std::pair<char, std::vector<double>>> out;
  std::string word;
  while (in >> word) {
    if (std::isalpha(static_cast<unsigned char>(word[0]))) out.push_back({word[0], {}});
    else out.back().second.push_back(std::strtod(word.c_str(), nullptr));
  }
  return out;
}

std::array<double, 2> bezier_point(const fair::io::Svg_path_segment& s, double t) {
  std::array<std::array<double, 2>, 4> b = s.points;
  for (int r = 1; r <= s.degree; ++r)
    for (int k = 0; k + r <= s.degree; ++k)
      for (int c = 0; c < 2; ++c) b[k][c] = (1 - t) * b[k][c] + t * b[k + 1][c];
  return b[0];
}

/// The largest distance, over 257 parameters per command, between the command and the curve at
/// the same parameter (Nurbs_curve_2::point: the knot-vector evaluation, not the pieces the
/// writer used); checks it against each command's bound.
double check_against_curve(const fair::Nurbs_curve_2<K>& c, const fair::io::Svg_path& path, double extent) {
  const std::vector<double> b = c.breakpoints();
  double worst = 0;
  for (const auto& s : path.segments) {
    double here = 0;
    for (int k = 0; k <= 256; ++k) {
      const double sp = k / 256.0;
      const double t = s.t0 + sp * (s.t1 - s.t0);
      const double u = std::min(b[s.piece] + t * (b[s.piece + 1] - b[s.piece]), b.back());
      const auto p = c.point(u);
      const auto q = bezier_point(s, sp);
      here = std::max(here, std::hypot(p.x() - q[0], p.y() - q[1]));
    }
    // evaluation rounding of both sides: a few ulps of the extent
    EXPECT_LE(here, s.error_bound + 1e-14 * extent) << "piece " << s.piece << " [" << s.t0 << ", " << s.t1 << "]";
    worst = std::max(worst, here);
  }
  return worst;
}

TEST(Svg_path, polynomial_pieces_of_degree_at_most_3_are_exact_commands) {
  for (const auto& c : fair_test::nurbs_cases<K>()) {
    if (c.curve.is_rational() || c.curve.degree() > 3) continue;
    SCOPED_TRACE(c.name);
    const fair::io::Svg_path path = fair::io::svg_path(c.curve);
    EXPECT_TRUE(path.is_exact());
    ASSERT_EQ(path.segments.size(), c.curve.number_of_pieces());
    const auto commands = parse_d(path.d);
    ASSERT_EQ(commands.size(), c.curve.number_of_pieces() + 1 + (c.curve.is_closed() ? 1 : 0));
    const char letter = " LQC"[c.curve.degree()];
    const auto& first = c.curve.pieces().front().control_point(0);
    EXPECT_EQ(commands[0].first, 'M');
    EXPECT_EQ(commands[0].second, (std::vector<double>{first.x(), first.y()}));
    for (std::size_t j = 0; j < c.curve.number_of_pieces(); ++j) {
      const auto& piece = c.curve.pieces()[j];
      std::vector<double> expected;
      for (std::size_t i = 1; i <= piece.degree(); ++i) {
        expected.push_back(piece.control_point(i).x());
        expected.push_back(piece.control_point(i).y());
      }
      EXPECT_EQ(commands[j + 1].first, letter);
      EXPECT_EQ(commands[j + 1].second, expected) << "piece " << j;  // bit for bit (%.17g)
    }
    if (c.curve.is_closed()) {
      EXPECT_EQ(commands.back().first, 'Z');
    }
  }
}

TEST(Svg_path, rational_and_high_degree_pieces_are_cubics_within_the_certified_bound) {
  std::size_t approximated = 0;
  for (const auto& c : fair_test::nurbs_cases<K>()) {
    if (!c.curve.is_rational() && c.curve.degree() <= 3) continue;
    SCOPED_TRACE(c.name);
    ++approximated;
    const double extent = fair::io::svg_path_extent(c.curve);
    std::size_t previous = 0;
    for (double relative : {1e-3, 1e-6, 1e-9}) {
      const double tolerance = relative * extent;
      const fair::io::Svg_path path = fair::io::svg_path(c.curve, tolerance);
      EXPECT_FALSE(path.is_exact());
      EXPECT_LE(path.error_bound, tolerance);
      const double measured = check_against_curve(c.curve, path, extent);
      // The bound is not vacuous: the measured distance is within a factor 40 of the largest
      // bound (16 of it is one halving too many, O(h^4)), unless the curve is met to rounding.
      EXPECT_TRUE(measured * 40 >= path.error_bound || path.error_bound < 1e-12 * extent)
          << "measured " << measured << " bound " << path.error_bound;
      // consecutive commands meet exactly (each starts where the previous ended)
      for (std::size_t k = 1; k < path.segments.size(); ++k)
        EXPECT_EQ(path.segments[k].points[0], path.segments[k - 1].points[path.segments[k - 1].degree]);
      // pieces that are exact stay exact; halvings grow as the tolerance shrinks, ~16^(1/4) x per decade... 
      EXPECT_GE(path.segments.size(), previous);
      previous = path.segments.size();
      // the d text is the segments: one C per approximated segment
      const auto commands = parse_d(path.d);
      EXPECT_EQ(commands.size(), path.segments.size() + 1 + (c.curve.is_closed() ? 1 : 0));
    }
  }
  EXPECT_GE(approximated, 5u);  // kappa auto open/closed, quintic, rational cubics
}

// A conic: the quarter of the unit circle (weights 1, sqrt(2)/2, 1). Every cubic stays on the
// circle to within its bound (|q| - 1 is at most the parametric distance), and the bound is tight.
TEST(Svg_path, quarter_circle_error_bound_and_halvings) {
  typedef K::Point_2 P;
  const fair::Nurbs_curve_2<K> c(2, {0, 0, 0, 1, 1, 1}, {P(1, 0), P(1, 1), P(0, 1)}, {1, std::sqrt(0.5), 1});
  const double extent = fair::io::svg_path_extent(c);
  std::vector<std::size_t> counts;
  for (double tol : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10}) {
    const fair::io::Svg_path path = fair::io::svg_path(c, tol);
    check_against_curve(c, path, extent);
    for (const auto& s : path.segments)
      for (int k = 0; k <= 64; ++k) {  // on the circle to within the bound
        const auto q = bezier_point(s, k / 64.0);
        EXPECT_LE(std::fabs(std::hypot(q[0], q[1]) - 1), s.error_bound + 1e-15);
      }
    counts.push_back(path.segments.size());
    // the bound is tight: measured 0.56-0.64 of it (1e-2: bound 5.4e-3, measured 3.1e-3)
    EXPECT_GE(check_against_curve(c, path, extent), 0.5 * path.error_bound) << tol;
  }
  // O(h^4): two decades of tolerance cost at most a factor 4 (16^(1/2)) more cubics, plus rounding up
  for (std::size_t i = 1; i < counts.size(); ++i) EXPECT_LE(counts[i], 4 * counts[i - 1] + 1) << i;
  // measured: 2, 8, 32, 64, 256 cubics for 1e-2 .. 1e-10
  EXPECT_EQ(counts, (std::vector<std::size_t>{2, 8, 32, 64, 256}));
}

// In an exact kernel each number of an exact command is the nearest double of the exact value:
// 1/10 -> 0.10000000000000001 (CGAL::to_double of a Gmpq truncates to 0.099999999999999992),
// 1/3 -> 0.33333333333333331 (EPECK's CGAL::to_double gives 0.33333333333333337).
template <class KK>
void check_exact_kernel_numbers() {
  typedef typename KK::FT FT;
  typedef typename KK::Point_2 P;
  const FT tenth = FT(1) / FT(10), third = FT(1) / FT(3);
  const fair::Nurbs_curve_2<KK> c(3, {0, 0, 0, 0, 1, 1, 1, 1}, {P(tenth, 0), P(1, third), P(2, tenth), P(3, 0)});
  const fair::io::Svg_path path = fair::io::svg_path(c);
  EXPECT_TRUE(path.is_exact());
  EXPECT_EQ(path.d, "M 0.10000000000000001 0 C 1 0.33333333333333331 2 0.10000000000000001 3 0");
}

TEST(Svg_path, exact_kernels_write_the_nearest_doubles) {
  check_exact_kernel_numbers<fair_test::SC_gmpq>();
  check_exact_kernel_numbers<fair_test::EPECK>();
}

TEST(Svg_path, bad_tolerances_are_precondition_errors) {
  typedef K::Point_2 P;
  const fair::Nurbs_curve_2<K> c(2, {0, 0, 0, 1, 1, 1}, {P(1, 0), P(1, 1), P(0, 1)}, {1, 2, 1});
  for (double tol : {0.0, -1.0, std::nan(""), HUGE_VAL, 1e-16})
    EXPECT_THROW(fair::io::svg_path(c, tol), fair::Precondition_error) << tol;
  EXPECT_NO_THROW(fair::io::svg_path(c, 1e-12));
}

} // namespace
