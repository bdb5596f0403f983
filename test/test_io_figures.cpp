// Tests of fair::sample_curve (arc length and curvature against closed forms), the SVG figure
// writers (finite output inside the view box, scale invariance, huge and tiny coordinates) and
// the HTML gallery.

#include <fair/Bezier_2.h>
#include <fair/Curve_sampling.h>
#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/io/svg.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include "test_support.h"

// The demo page of fair-curves (a program header, tested here with the figures it shows).
#include "../tools/fair-curves/gallery.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace fair_test;

// Arc length of y = x^2 from 0 to x: (x sqrt(1 + 4x^2))/2 + asinh(2x)/4.
double parabola_length(double x) { return 0.5 * x * std::sqrt(1 + 4 * x * x) + 0.25 * std::asinh(2 * x); }

// The parabola y = x^2, x in [-1, 1], as the quadratic Bezier (-1,1), (0,-1), (1,1):
// x(t) = 2t - 1, y(t) = (2t - 1)^2.
template <class K>
fair::Bezier_2<K> unit_parabola(double scale = 1) {
  typedef typename K::Point_2 P;
  return fair::Bezier_2<K>(std::vector<P>{P(-scale, scale), P(0, -scale), P(scale, scale)});
}

template <class K>
class SamplingKernels : public ::testing::Test {};
TYPED_TEST_SUITE(SamplingKernels, All_kernels);

TYPED_TEST(SamplingKernels, ParabolaArcLengthCurvatureAndNormalsMatchClosedForms) {
  typedef TypeParam K;
  const std::vector<fair::Bezier_2<K>> curve = {unit_parabola<K>()};
  const fair::Sampled_curve s = fair::sample_curve(curve, 32);
  ASSERT_EQ(s.samples.size(), 33u);
  ASSERT_EQ(s.number_of_pieces(), 1u);
  const double total = 2 * parabola_length(1);  // sqrt(5) + asinh(2)/2
  EXPECT_NEAR(s.length(), total, 1e-13 * total);
  for (const fair::Curve_sample& c : s.samples) {
    const double x = 2 * c.t - 1;
    EXPECT_NEAR(c.x, x, 1e-15);
    EXPECT_NEAR(c.y, x * x, 1e-15);
    EXPECT_NEAR(c.arc_length, parabola_length(x) + parabola_length(1), 1e-13 * total) << c.t;
    // kappa(x) = 2 / (1 + 4x^2)^(3/2), positive: the curve turns left.
    EXPECT_NEAR(c.curvature, 2 / std::pow(1 + 4 * x * x, 1.5), 1e-14) << c.t;
    // Unit normal = unit tangent (1, 2x)/sqrt(1+4x^2) turned by +90 degrees.
    const double v = std::sqrt(1 + 4 * x * x);
    EXPECT_NEAR(c.nx, -2 * x / v, 1e-15);
    EXPECT_NEAR(c.ny, 1 / v, 1e-15);
    EXPECT_EQ(c.piece, 0u);
  }
}

TEST(Sampling, CircleArcAsRationalQuadraticHasLengthRThetaAndCurvatureOneOverR) {
  typedef SC_double K;
  typedef K::Point_2 P;
  // A circular arc of radius R and angle theta: P1 at the intersection of the end tangents,
  // w = cos(theta/2). Its speed is not a polynomial, so this exercises the quadrature.
  for (double theta : {0.1, pi / 2, 2.0, 2.8}) {
    const double R = 3.5;
    const fair::Rational_quadratic_bezier_2<K> arc(P(R, 0), P(R, R * std::tan(theta / 2)),
                                                   P(R * std::cos(theta), R * std::sin(theta)),
                                                   std::cos(theta / 2));
    const std::vector<fair::Rational_quadratic_bezier_2<K>> curve = {arc};
    const fair::Sampled_curve s = fair::sample_curve(curve, 16);
    EXPECT_NEAR(s.length(), R * theta, 1e-13 * R * theta) << theta;
    EXPECT_NEAR(fair::piece_arc_length(arc, 0, 1), R * theta, 1e-13 * R * theta);
    for (const fair::Curve_sample& c : s.samples) {
      EXPECT_NEAR(c.curvature, 1 / R, 1e-13) << theta << " " << c.t;
      // On a circle the arc length is R times the polar angle, and the normal points to the centre.
      EXPECT_NEAR(c.arc_length, R * std::atan2(c.y, c.x), 1e-12 * R) << theta << " " << c.t;
      EXPECT_NEAR(c.nx, -c.x / R, 1e-13);
      EXPECT_NEAR(c.ny, -c.y / R, 1e-13);
    }
  }
}

TEST(Sampling, PiecesAreJoinedAndCusplessSingularitiesFallBack) {
  typedef SC_double K;
  typedef K::Point_2 P;
  // The parabola split at t = 1/4: two pieces, lengths F(-1/2) - F(-1) and F(1) - F(-1/2).
  const auto halves = unit_parabola<K>().split(0.25);
  const std::vector<fair::Bezier_2<K>> curve = {halves.first, halves.second};
  const fair::Sampled_curve s = fair::sample_curve(curve, 8);
  ASSERT_EQ(s.samples.size(), 18u);
  ASSERT_EQ(s.piece_start.size(), 3u);
  EXPECT_NEAR(s.piece_start[1], parabola_length(1) - parabola_length(0.5), 1e-13);
  EXPECT_NEAR(s.length(), 2 * parabola_length(1), 1e-13);
  EXPECT_EQ(s.samples[8].piece, 0u);
  EXPECT_EQ(s.samples[9].piece, 1u);
  EXPECT_EQ(s.samples[8].arc_length, s.samples[9].arc_length);  // the join, seen twice

  // A cubic with a cusp at t = 1/2 (c'(1/2) = 0): the sample there takes the one-sided limit,
  // everything stays finite, and the length is symmetric and matches a fine chord sum.
  const fair::Bezier_2<K> cusp(P(0, 0), P(1, 1), P(0, 1), P(1, 0));
  const std::vector<fair::Bezier_2<K>> c2 = {cusp};
  const fair::Sampled_curve sc = fair::sample_curve(c2, 64);
  for (const fair::Curve_sample& c : sc.samples) {
    EXPECT_TRUE(std::isfinite(c.curvature) && std::isfinite(c.nx) && std::isfinite(c.ny));
    EXPECT_NEAR(std::hypot(c.nx, c.ny), 1.0, 1e-12);
  }
  const double left = fair::piece_arc_length(cusp, 0, 0.5), right = fair::piece_arc_length(cusp, 0.5, 1);
  EXPECT_NEAR(left, right, 1e-12);
  double chords = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const P a = cusp.point(double(i) / n), b = cusp.point(double(i + 1) / n);
    chords += std::hypot(b.x() - a.x(), b.y() - a.y());
  }
  EXPECT_NEAR(sc.length(), chords, 1e-8 * chords);

  EXPECT_THROW(fair::sample_curve(c2, 0), fair::Precondition_error);
  // A piece that is a single point is singular everywhere.
  const std::vector<fair::Bezier_2<K>> dot = {fair::Bezier_2<K>(std::vector<P>{P(1, 1), P(1, 1), P(1, 1)})};
  EXPECT_THROW(fair::sample_curve(dot, 4), fair::Precondition_error);
}

// ------------------------------------------------------------------ SVG

struct Svg_numbers {
  double width = 0, height = 0;
  std::vector<double> xs, ys;  // every drawn x and y coordinate
};

// Collects the view box and every coordinate of the drawing elements.
Svg_numbers svg_numbers(const std::string& svg) {
  Svg_numbers out;
  std::smatch m;
  const std::regex viewbox("viewBox=\"0 0 ([0-9.]+) ([0-9.]+)\"");
  EXPECT_TRUE(std::regex_search(svg, m, viewbox));
  out.width = std::stod(m[1]);
  out.height = std::stod(m[2]);
  const std::regex points("points=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), points); it != std::sregex_iterator(); ++it) {
    std::istringstream in((*it)[1].str());
    std::string pair;
    while (in >> pair) {
      const std::size_t comma = pair.find(',');
      out.xs.push_back(std::stod(pair.substr(0, comma)));
      out.ys.push_back(std::stod(pair.substr(comma + 1)));
    }
  }
  // the comb's teeth: one path per comb and kind, "M x,y L x,y ..."
  const std::regex path_d(" d=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path_d); it != std::sregex_iterator(); ++it) {
    std::string d = (*it)[1].str();
    std::replace(d.begin(), d.end(), 'M', ' ');
    std::replace(d.begin(), d.end(), 'L', ' ');
    std::istringstream in(d);
    std::string pair;
    while (in >> pair) {
      const std::size_t comma = pair.find(',');
      out.xs.push_back(std::stod(pair.substr(0, comma)));
      out.ys.push_back(std::stod(pair.substr(comma + 1)));
    }
  }
  const std::regex attr("\\b(cx|x|x1|x2|cy|y|y1|y2)=\"(-?[0-9.]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), attr); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1].str();
    (name[0] == 'x' || name == "cx" ? out.xs : out.ys).push_back(std::stod((*it)[2].str()));
  }
  return out;
}

void expect_clean_svg(const std::string& svg) {
  std::string lower(svg);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  EXPECT_EQ(lower.find("nan"), std::string::npos);
  EXPECT_EQ(lower.find("inf"), std::string::npos);
  EXPECT_EQ(svg.rfind("<svg ", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  const Svg_numbers n = svg_numbers(svg);
  EXPECT_GT(n.xs.size(), 10u);
  for (double x : n.xs) EXPECT_TRUE(x >= 0 && x <= n.width) << x;
  // The figure's <g> is translated down by the title height: allow for it.
  for (double y : n.ys) EXPECT_TRUE(y >= 0 && y <= n.height) << y;
}

template <class K>
std::string parabola_figure(double scale, double shift_x = 0) {
  typedef typename K::Point_2 P;
  const std::vector<fair::Bezier_2<K>> curve = {fair::Bezier_2<K>(std::vector<P>{
      P(shift_x - scale, scale), P(shift_x, -scale), P(shift_x + scale, scale)})};
  const fair::Sampled_curve s = fair::sample_curve(curve, 24);
  fair::io::Svg_figure f;
  f.set_title("parabola <&>");
  f.add_control_polygons(curve);
  f.add_curve(s);
  f.add_curvature_comb(s);
  f.add_points(fair::io::to_xy(std::vector<P>{P(shift_x - scale, scale), P(shift_x + scale, scale)}));
  f.add_marks({fair::io::Svg_mark{shift_x, 0, "max"}});
  return f.str();
}

// fair::io::xml_escape (public since the gallery moved into the program, which uses it).
TEST(SvgText, XmlEscapeReplacesTheFiveSpecialCharacters) {
  EXPECT_EQ(fair::io::xml_escape("a<b & \"c\" > 'd'"), "a&lt;b &amp; &quot;c&quot; &gt; &#39;d&#39;");
  EXPECT_EQ(fair::io::xml_escape("plain"), "plain");
}

TEST(Svg, FigureIsFiniteInsideItsViewBoxAndEscaped) {
  const std::string svg = parabola_figure<SC_double>(1);
  expect_clean_svg(svg);
  EXPECT_NE(svg.find("parabola &lt;&amp;&gt;"), std::string::npos);
  EXPECT_EQ(svg.find("<&>"), std::string::npos);
  // The curve of 25 samples, the control polygon and one comb envelope as polylines; the 25
  // teeth as one path of 25 "M base L tip" (issue 29 #21: one element per comb, not per tooth),
  // none clipped (the parabola's curvature ranges over a factor 5.2, its 95th percentile is
  // within 1.1 of the largest).
  const std::regex polyline("<polyline"), path("<path "), move("M[0-9.]+,[0-9.]+L");
  EXPECT_EQ(std::distance(std::sregex_iterator(svg.begin(), svg.end(), polyline), std::sregex_iterator()), 1 + 1 + 1);
  EXPECT_EQ(std::distance(std::sregex_iterator(svg.begin(), svg.end(), path), std::sregex_iterator()), 1);
  EXPECT_EQ(std::distance(std::sregex_iterator(svg.begin(), svg.end(), move), std::sregex_iterator()), 25);
  // No clipped tooth and no mark of one (the red of the "max" mark is the marks' own colour).
  EXPECT_EQ(svg.find("stroke=\"#c0392b\" stroke-width=\"0.6\""), std::string::npos);
  EXPECT_EQ(svg.find("r=\"1.6\" fill=\"#c0392b\""), std::string::npos);
}

TEST(Svg, ScaleInvariantAndRobustToHugeAndTinyCoordinates) {
  // Scaling by a power of two is exact in binary floating point, and the view normalises by
  // the extent: the figure must be identical, down to the last digit.
  const std::string unit = parabola_figure<SC_double>(1);
  EXPECT_EQ(parabola_figure<SC_double>(std::ldexp(1.0, 900)), unit);
  EXPECT_EQ(parabola_figure<SC_double>(std::ldexp(1.0, -900)), unit);
  // Near the ends of the double range and far from the origin it still fits and stays finite.
  expect_clean_svg(parabola_figure<SC_double>(1e300));
  expect_clean_svg(parabola_figure<SC_double>(1e-300));
  expect_clean_svg(parabola_figure<SC_double>(1e-10, 1e8));
  expect_clean_svg(parabola_figure<EPECK>(1e-5, 3));
}

TEST(Svg, RefusesNonFiniteInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  fair::io::Svg_figure f;
  EXPECT_THROW(f.add_marks({fair::io::Svg_mark{nan, 0, "x"}}), fair::Precondition_error);
  EXPECT_THROW(f.add_points({fair::io::Xy{0, std::numeric_limits<double>::infinity()}}), fair::Precondition_error);
  fair::Sampled_curve s;
  s.samples.resize(3);
  s.samples[1].curvature = nan;
  s.piece_start = {0, 1};
  EXPECT_THROW(f.add_curvature_comb(s), fair::Precondition_error);
  EXPECT_THROW(fair::io::curvature_plot_svg(s), fair::Precondition_error);
  // A single point and an empty figure still give a valid picture.
  fair::io::Svg_figure one;
  one.add_points({fair::io::Xy{5, 5}});
  EXPECT_EQ(one.str().find("nan"), std::string::npos);
  EXPECT_NE(fair::io::Svg_figure().str().find("</svg>"), std::string::npos);
}

TEST(Svg, CombScaleIsChosenFromThe95thPercentileOfCurvature) {
  typedef SC_double K;
  const std::vector<fair::Bezier_2<K>> curve = {unit_parabola<K>()};
  const fair::Sampled_curve s = fair::sample_curve(curve, 16);
  // Bounding box [-1,1] x [0,1]: diagonal sqrt(5). The reference curvature is the 95th
  // percentile of |kappa| over the 17 samples, the sample of rank floor(0.95 * 16) = 15 of the
  // sorted magnitudes (an independent sort, not nth_element), drawn as 0.1 of the diagonal.
  std::vector<double> k;
  for (const fair::Curve_sample& x : s.samples) k.push_back(std::abs(x.curvature));
  std::sort(k.begin(), k.end());
  ASSERT_LT(k[15], k[16]);  // below the maximum 2 at the vertex
  fair::io::Svg_figure f;
  EXPECT_NEAR(f.add_curvature_comb(s), 0.1 * std::sqrt(5.0) / k[15], 1e-15);
  EXPECT_EQ(f.add_curvature_comb(s, 0.25), 0.25);  // an explicit scale is kept
  const std::vector<fair::Bezier_2<K>> line = {
      fair::Bezier_2<K>(std::vector<K::Point_2>{K::Point_2(0, 0), K::Point_2(1, 1)})};
  EXPECT_EQ(f.add_curvature_comb(fair::sample_curve(line, 4)), 0.0);  // straight: no comb
}

// Issue 25 §5: one curvature spike among 99 samples of curvature 1 does not shrink the comb; its
// tooth is clipped at twice the reference length and marked (red path, red dot at the tip).
TEST(Svg, CombClipsAndMarksTheTeethOfCurvatureSpikes) {
  fair::Sampled_curve s;
  for (int i = 0; i <= 100; ++i) {
    fair::Curve_sample x;
    x.x = i, x.y = 0, x.nx = 0, x.ny = 1, x.t = i / 100.0, x.arc_length = i;
    x.curvature = i == 50 ? -1000 : 1;
    s.samples.push_back(x);
  }
  s.piece_start = {0, 100};
  fair::io::Svg_figure f;
  // Diagonal 100 (the samples' box is the segment [0,100] x {0}): the tooth of kappa = 1 is 10 long.
  const double scale = f.add_curvature_comb(s);
  EXPECT_NEAR(scale, 10.0, 1e-12);
  EXPECT_EQ(f.clipped_teeth(), 1u);
  const std::string svg = f.str();
  expect_clean_svg(svg);
  const std::regex red_path("<path fill=\"none\" stroke=\"#c0392b\""), red_dot("<circle[^>]*fill=\"#c0392b\"");
  EXPECT_EQ(std::distance(std::sregex_iterator(svg.begin(), svg.end(), red_path), std::sregex_iterator()), 1);
  EXPECT_EQ(std::distance(std::sregex_iterator(svg.begin(), svg.end(), red_dot), std::sregex_iterator()), 1);
  // The figure's box holds the clipped tip at y = +20 (kappa < 0: the tooth points along +n) and
  // the other tips at y = -10, not the unclipped 10000: the curve fills the picture's width, and
  // its height is the aspect ratio of a 100 x 30 box, at least 0.35 of the width.
  const Svg_numbers n = svg_numbers(svg);
  EXPECT_NEAR(n.height, std::round(720 * 0.35), 1);
  // An explicit scale clips too: kappa = 1 at scale 25 is 25 long, beyond 2 * 10 = 20: all clipped.
  fair::io::Svg_figure g;
  EXPECT_EQ(g.add_curvature_comb(s, 25.0), 25.0);
  EXPECT_EQ(g.clipped_teeth(), 101u);
}

TEST(Svg, CurvaturePlotHasOnePolylinePerPieceAndJoinMarks) {
  typedef SC_double K;
  const auto halves = unit_parabola<K>().split(0.3);
  const auto quarters = halves.second.split(0.5);
  const std::vector<fair::Bezier_2<K>> curve = {halves.first, quarters.first, quarters.second};
  const fair::Sampled_curve s = fair::sample_curve(curve, 16);
  const double vertex_s = fair::io::arc_length_at(s, 1, (0.5 - 0.3) / 0.35);
  EXPECT_NEAR(vertex_s, parabola_length(1), 1e-3);  // the vertex is at half the length
  const std::string svg = fair::io::curvature_plot_svg(s, {fair::io::Plot_mark{vertex_s, 2.0, "max 2"}});
  expect_clean_svg(svg);
  const std::regex polyline("<polyline"), dashed("stroke-dasharray=\"3 3\"");
  EXPECT_EQ(std::distance(std::sregex_iterator(svg.begin(), svg.end(), polyline), std::sregex_iterator()), 3);
  EXPECT_EQ(std::distance(std::sregex_iterator(svg.begin(), svg.end(), dashed), std::sregex_iterator()), 2);
  EXPECT_NE(svg.find(">max 2<"), std::string::npos);
  // A straight line (kappa = 0) and tiny curvatures still produce a finite plot.
  const std::vector<fair::Bezier_2<K>> line = {
      fair::Bezier_2<K>(std::vector<K::Point_2>{K::Point_2(0, 0), K::Point_2(1, 1)})};
  expect_clean_svg(fair::io::curvature_plot_svg(fair::sample_curve(line, 4)));
  const std::vector<fair::Bezier_2<K>> big = {unit_parabola<K>(1e300)};
  expect_clean_svg(fair::io::curvature_plot_svg(fair::sample_curve(big, 8)));
}

// ------------------------------------------------------------------ gallery

TEST(Gallery, WritesIndexWithSectionsFiguresAndTables) {
  fair_curves::Gallery g("Test <gallery>", "intro & more");
  g.add_section("First", "one");
  const std::string svg = parabola_figure<SC_double>(1);
  g.add_case({"parabola", "caption <b>", {{"curve", svg}, {"curvature plot", svg}}, {{"length", "2.96"}}, {}});
  g.add_case({"again", "", {{"curve", svg}}, {}, {}});
  g.add_section("Second");
  g.add_case({"third", "c", {{"curve", svg}}, {{"a", "1"}, {"b", "2"}}, {}});
  EXPECT_EQ(g.case_count(), 3u);
  EXPECT_EQ(g.section_count(), 2u);
  const std::string html = g.html(false);
  const std::regex figure("<figure class=\"case\""), img("<img src=\"figures/"), row("<tr><td>");
  EXPECT_EQ(std::distance(std::sregex_iterator(html.begin(), html.end(), figure), std::sregex_iterator()), 3);
  EXPECT_EQ(std::distance(std::sregex_iterator(html.begin(), html.end(), img), std::sregex_iterator()), 4);
  EXPECT_EQ(std::distance(std::sregex_iterator(html.begin(), html.end(), row), std::sregex_iterator()), 3);
  EXPECT_NE(html.find("caption &lt;b&gt;"), std::string::npos);
  EXPECT_NE(html.find("Test &lt;gallery&gt;"), std::string::npos);
  const std::string inlined = g.html(true);
  EXPECT_EQ(inlined.find("<img"), std::string::npos);
  const std::regex svg_tag("<svg ");
  EXPECT_EQ(std::distance(std::sregex_iterator(inlined.begin(), inlined.end(), svg_tag), std::sregex_iterator()), 4);

  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "fair_test_gallery";
  std::filesystem::remove_all(dir);
  g.write(dir.string());
  EXPECT_TRUE(std::filesystem::exists(dir / "index.html"));
  for (const std::string& name : g.image_file_names()) {
    EXPECT_TRUE(std::filesystem::exists(dir / "figures" / name)) << name;
    EXPECT_NE(html.find("figures/" + name), std::string::npos) << name;
  }
  EXPECT_EQ(g.image_file_names()[1], "case-1-2-curvature-plot.svg");
  std::filesystem::remove_all(dir);
  EXPECT_THROW(g.write("/proc/fair-cannot-write-here"), fair::Error);
}

} // namespace
