// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Optimal curves a designer can use (issue 25 §1-3), on hand-drawn data: the strokes of the 20
// Quick, Draw! "angel" drawings (test/data/real/, CC BY 4.0, Google, Inc.; SOURCES.md), each
// subsampled to at most 15 points (every k-th point, the last kept: 3-15 points, as the issue's
// drawings), and Greenland of the Natural Earth coastlines (131 points, closed). At the defaults
// and at lambda = 0.5, per curve (expectations in real_data_expected.txt, written by this test
// with FAIR_WRITE_EXPECTED=<file>, measured with GCC 12 -O3):
//  - no balloon: extent_ratio <= 1.5 (report, shape_check.h); the certified self-intersections as
//    expected (none beyond the input's but on six strokes and Greenland: doc/optimal_curves.md);
//  - the spline (the smoothing spline of Optimal_curve_2::spline()) keeps the curve's shape: its
//    certified inflections and curvature extrema (Fairness_metrics.h) as expected, and over the set
//    the medians measured (inflections per input point 0.308 / 0.500, extrema 1.100 / 1.250 at the
//    defaults / lambda = 0.5; the targets: inflections
//    median <= 0.5, max <= 1.5; extrema median <= 1.5: all held at both settings);
//  - the spline within the polygon's resolution on every curve: the hierarchy refines the polygon
//    until the fit's tolerance (0.9 extent / rho) is met (tolerance_met), so max_distance <= 0.9
//    extent / rho (before: up to 1.21 on 7 strokes per setting).

#include <fair/Fairness_metrics.h>
#include <fair/Optimal_curve_2.h>

#ifndef FAIR_NO_FREETYPE
#define FAIR_NO_FREETYPE  // only the point sets, no glyphs
#endif
#include "kappa_real/data_sets.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef fair_test::SC_double K;
typedef K::Point_2 P;

/// Every k-th point, k the smallest step giving at most `cap` points; an open stroke keeps its last point.
std::vector<kappa_real::Xy> subsample(const std::vector<kappa_real::Xy>& p, bool closed, std::size_t cap) {
  if (p.size() <= cap) return p;
  const std::size_t step = (p.size() + cap - 1) / cap;
  std::vector<kappa_real::Xy> q;
  for (std::size_t i = 0; i < p.size(); i += step) q.push_back(p[i]);
  if (!closed && !(q.back() == p.back())) {
    if (q.size() >= cap) q.back() = p.back();
    else q.push_back(p.back());
  }
  return q;
}

struct Real_curve {
  std::string name;
  std::vector<P> points;
  bool closed = false;
};

std::vector<Real_curve> hand_drawn() {
  std::vector<Real_curve> out;
  for (const kappa_real::Point_set& s : kappa_real::quickdraw_strokes(FAIR_TEST_DATA_DIR "/real/quickdraw_angel.json")) {
    Real_curve c;
    c.name = "quickdraw " + s.name;
    c.closed = s.closed;
    for (const kappa_real::Xy& q : subsample(s.points, s.closed, 15)) c.points.push_back(P(q.x, q.y));
    if (c.points.size() >= 3) out.push_back(c);
  }
  for (const kappa_real::Point_set& s :
       kappa_real::geojson_lines(FAIR_TEST_DATA_DIR "/real/natural_earth_coastlines.ndjson", "coastlines"))
    if (s.points.size() == 131) {  // Greenland
      Real_curve c;
      c.name = "greenland";
      c.closed = s.closed;
      for (const kappa_real::Xy& q : s.points) c.points.push_back(P(q.x, q.y));
      out.push_back(c);
    }
  return out;
}

struct Measured {
  double extent_ratio = 0, distance = 0, resolution = 0;
  bool tolerance_met = true;  // the smoothing spline reached its distance (else: the interpolant of every vertex)
  std::size_t inflections = 0, extrema = 0, self_intersections = 0, input_self_intersections = 0;
  std::size_t polygon_sign_changes = 0;  // of the discrete curvature (zeros skipped): the polygon's inflections
  fair::Optimal_curve_status status = fair::Optimal_curve_status::CAPPED;
};

Measured measure(const Real_curve& c, double lambda) {
  fair::Optimal_curve_options o;
  o.closed = c.closed;
  if (lambda >= 0) o.lambda = lambda;
  const fair::Optimal_curve_2<K> curve(c.points, o);
  Measured m;
  m.status = curve.status();
  m.extent_ratio = curve.report().extent_ratio;
  m.self_intersections = curve.report().self_intersections;
  m.input_self_intersections = curve.report().input_self_intersections;
  std::vector<fair::internal::optimal::Vec2> v;
  for (const P& q : curve.polygon()) v.push_back({{q.x(), q.y()}});
  m.resolution = fair::internal::optimal::rotation_invariant_extent(v) / o.resolution;
  m.distance = curve.spline().max_distance;
  m.tolerance_met = curve.spline_smoothing().tolerance_met;
  double previous = 0;
  for (double k : curve.curvatures())
    if (k != 0) {
      m.polygon_sign_changes += previous * k < 0;
      previous = k;
    }
  m.inflections = fair::inflections(curve.pieces()).count();
  m.extrema = fair::curvature_extrema(curve.pieces()).count();
  return m;
}

std::string key(const std::string& name, const char* setting) { return name + " | " + setting; }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The lambdas measured: the defaults (-1: lambda left as constructed) and 0.5, with the medians over
// the strokes of inflections and curvature extrema per input point that they reach (the issue's
// targets: 0.5 and 1.5; doc/optimal_curves.md, "Defaults", for what is and is not reached).
struct Setting {
  const char* name;
  double lambda, inflections, extrema;
};
const std::vector<Setting> settings = {{"defaults", -1, 0.31, 1.10}, {"lambda 0.5", 0.5, 0.5, 1.25}};

TEST(OptimalRealData, HandDrawnCurvesAreFairAtTheDefaultsAndAtLambdaHalf) {
  const std::vector<Real_curve> curves = hand_drawn();
  ASSERT_EQ(curves.size(), 118u);  // 117 strokes of >= 3 points and Greenland
  const char* write = std::getenv("FAIR_WRITE_EXPECTED");
  std::map<std::string, std::vector<double>> expected;
  if (!write) {
    std::ifstream in(std::string(FAIR_TEST_DATA_DIR) + "/../optimal/real_data_expected.txt");
    ASSERT_TRUE(in.good()) << "test/optimal/real_data_expected.txt is missing";
    std::string line;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      const std::size_t bar = line.rfind(" | ");
      std::istringstream values(line.substr(bar + 3));
      std::vector<double> x;
      for (double d; values >> d;) x.push_back(d);
      expected[line.substr(0, bar)] = x;
    }
  }
  std::ofstream out;
  if (write) {
    out.open(write);
    out << "# test/optimal/test_real_data.cpp: per curve and setting: inflections, curvature extrema, extent_ratio,\n"
        << "# self_intersections, input_self_intersections (GCC 12 -O3)\n"
        << "# Rewritten (issue 25 §3, measured): the band steps of the smoothing fit moved the spline's inflections\n"
        << "# (101 curve-settings down, 60 up; sum 1104 -> 1007) and extrema (147 down, 16 up; 4147 -> 3141); the\n"
        << "# spline-resolution pass refined 12 polygons (extent_ratio within 0.4 %) and Greenland's (its loops\n"
        << "# cross more refined edges: 70 -> 76 and 36 -> 44 self-intersecting edge pairs).\n";
  }
  for (const auto& setting : settings) {
    std::vector<double> inflections, extrema, polygon_inflections;
    double worst_inflections = 0, worst_extrema = 0, worst_distance = 0;
    int beyond_resolution = 0, interpolants = 0;
    for (std::size_t index = 0; index < curves.size(); index += fair_test::real_data_stride) {
      const Real_curve& c = curves[index];
      const Measured m = measure(c, setting.lambda);
      const std::string what = key(c.name, setting.name);
      EXPECT_LE(m.extent_ratio, 1.5) << what;
      // Within the fit's tolerance, 0.9 of the polygon's resolution, on every curve (issue 25 §3:
      // <= 1; doc/optimal_curves.md, "Distance within the resolution").
      EXPECT_TRUE(m.tolerance_met) << what;
      EXPECT_LE(m.distance, fair::optimal_spline_distance_fraction * m.resolution * (1 + 1e-9)) << what;
      EXPECT_EQ(m.status, fair::Optimal_curve_status::CONVERGED) << what;
      const double n = static_cast<double>(c.points.size());
      if (c.name != "greenland") {
        inflections.push_back(static_cast<double>(m.inflections) / n);
        extrema.push_back(static_cast<double>(m.extrema) / n);
        polygon_inflections.push_back(static_cast<double>(m.polygon_sign_changes) / n);
        worst_inflections = std::max(worst_inflections, inflections.back());
        worst_extrema = std::max(worst_extrema, extrema.back());
        worst_distance = std::max(worst_distance, m.distance / m.resolution);
        beyond_resolution += m.distance > m.resolution;
        interpolants += !m.tolerance_met;
      }
      if (write) {
        out << what << " | " << m.inflections << " " << m.extrema << " " << m.extent_ratio << " " << m.self_intersections
            << " " << m.input_self_intersections << "\n";
        continue;
      }
      const auto e = expected.find(what);
      ASSERT_NE(e, expected.end()) << what << " has no expectation";
      ASSERT_EQ(e->second.size(), 5u) << what;
      EXPECT_EQ(static_cast<double>(m.inflections), e->second[0]) << what;
      EXPECT_EQ(static_cast<double>(m.extrema), e->second[1]) << what;
      EXPECT_NEAR(m.extent_ratio, e->second[2], 1e-4 * e->second[2]) << what;
      // Self-intersections the input polygon does not have: 0 on 111 of the 117 strokes, 1 on six
      // (near-touching hairpins), 70 on Greenland at the defaults (doc: "Not reached").
      EXPECT_EQ(static_cast<double>(m.self_intersections), e->second[3]) << what;
      EXPECT_EQ(static_cast<double>(m.input_self_intersections), e->second[4]) << what;
    }
    // The summary of doc/optimal_curves.md's table (per input point over the 117 strokes).
    std::printf("%s: inflections median %.3f max %.3f, extrema median %.3f max %.3f, distance / resolution max %.3f "
                "(%d strokes beyond 1; %d kept the interpolant of every vertex); polygon's discrete curvature sign "
                "changes per point median %.3f max %.3f\n",
                setting.name, median(inflections), worst_inflections, median(extrema), worst_extrema, worst_distance,
                beyond_resolution, interpolants, median(polygon_inflections),
                *std::max_element(polygon_inflections.begin(), polygon_inflections.end()));
    if (fair_test::real_data_stride != 1) continue;  // a subset (the sanitizer stage): no statistics of the set
    EXPECT_LE(median(inflections), setting.inflections) << setting.name;
    // the max (reached by the smoothing spline; measured 1.333 / 1.25: one 3-point stroke with
    // two roots of the curvature at its natural ends, doc/optimal_curves.md "How fragile the counts are")
    EXPECT_LE(worst_inflections, 1.5) << setting.name;
    EXPECT_LE(median(extrema), setting.extrema) << setting.name;
  }
}

}  // namespace
