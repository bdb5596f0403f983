// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::io::write_dxf (include/fair/io/write_dxf.h): the structure of the drawing (sections in
// order, unique handles below $HANDSEED, owners, the SPLINE groups of every case), the exact
// kernels' drawing, the error for a value that is not finite as a double. Every case is also
// written, with the library's own points c(u) (Nurbs_curve_2::point), to the directory named by
// FAIR_DXF_CASES_DIR, where test/io_export/check_dxf.py (ctest dxf_ezdxf) has ezdxf read,
// audit and evaluate them.

#include "nurbs_cases.h"
#include "test_support.h"

#include <fair/io/write_dxf.h>

#include <CGAL/Gmpq.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef fair_test::SC_double K;

struct Tag {
  int code;
  std::string value;
};

std::vector<Tag> tags_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<Tag> tags;
  std::string code, value;
  while (std::getline(in, code) && std::getline(in, value)) tags.push_back({std::stoi(code), value});
  return tags;
}

/// The 17-digit text of a double, as the writer prints it.
std::string text17(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v == 0 ? 0.0 : v);  // the writer prints no "-0"
  return b;
}

// Structure shared by every drawing: sections in order, handles unique and below $HANDSEED,
// every owner (330) a handle of the drawing or 0, EOF last.
void check_structure(const std::vector<Tag>& tags) {
  std::vector<std::string> sections;
  std::set<unsigned long> handles;
  std::vector<unsigned long> owners;
  unsigned long seed = 0;
  for (std::size_t i = 0; i < tags.size(); ++i) {
    const Tag& t = tags[i];
    if (t.code == 2 && i > 0 && tags[i - 1].value == "SECTION") sections.push_back(t.value);
    if (t.code == 9 && t.value == "$HANDSEED") seed = std::stoul(tags[i + 1].value, nullptr, 16);
    if ((t.code == 5 || t.code == 105) && sections.size() > 1) {  // (in HEADER, 5 is $HANDSEED's value)
      EXPECT_TRUE(handles.insert(std::stoul(t.value, nullptr, 16)).second) << t.value;
    }
    if (t.code == 330 || t.code == 350) owners.push_back(std::stoul(t.value, nullptr, 16));
  }
  EXPECT_EQ(sections, (std::vector<std::string>{"HEADER", "CLASSES", "TABLES", "BLOCKS", "ENTITIES", "OBJECTS"}));
  ASSERT_FALSE(handles.empty());
  EXPECT_GT(seed, *handles.rbegin());
  for (unsigned long o : owners) EXPECT_TRUE(o == 0 || handles.count(o)) << std::hex << o;
  EXPECT_EQ(tags.back().code, 0);
  EXPECT_EQ(tags.back().value, "EOF");
  EXPECT_EQ(tags[2].value, "$ACADVER");
  EXPECT_EQ(tags[3].value, "AC1015");
}

// The SPLINE groups of curve c: flags, degree, counts, the full knot vector, the weights when
// rational, the control points, every number with 17 significant digits.
void check_spline(const std::vector<Tag>& tags, const fair::Nurbs_curve_2<K>& c) {
  std::size_t at = 0;
  while (at < tags.size() && !(tags[at].code == 0 && tags[at].value == "SPLINE")) ++at;
  ASSERT_LT(at, tags.size());
  std::map<int, std::vector<std::string>> g;
  for (std::size_t i = at + 1; i < tags.size() && tags[i].code != 0; ++i) g[tags[i].code].push_back(tags[i].value);
  const int flags = 8 + (c.is_rational() ? 4 : 0) + (c.is_closed() ? 3 : 0);
  EXPECT_EQ(g[70], std::vector<std::string>{std::to_string(flags)});
  EXPECT_EQ(g[71], std::vector<std::string>{std::to_string(c.degree())});
  EXPECT_EQ(g[72], std::vector<std::string>{std::to_string(c.knots().size())});
  EXPECT_EQ(g[73], std::vector<std::string>{std::to_string(c.control_points().size())});
  EXPECT_EQ(g[74], std::vector<std::string>{"0"});
  ASSERT_EQ(g[40].size(), c.knots().size());
  for (std::size_t i = 0; i < c.knots().size(); ++i) EXPECT_EQ(std::strtod(g[40][i].c_str(), nullptr), c.knots()[i]);
  ASSERT_EQ(g[41].size(), c.is_rational() ? c.weights().size() : 0u);
  for (std::size_t i = 0; i < g[41].size(); ++i) EXPECT_EQ(std::strtod(g[41][i].c_str(), nullptr), c.weights()[i]);
  ASSERT_EQ(g[10].size(), c.control_points().size());
  for (std::size_t i = 0; i < g[10].size(); ++i) {
    EXPECT_EQ(g[10][i], text17(c.control_points()[i].x()));
    EXPECT_EQ(g[20][i], text17(c.control_points()[i].y()));
    EXPECT_EQ(g[30][i], "0");
  }
}

TEST(Dxf_export, every_case_has_its_spline_and_a_valid_structure) {
  const char* dir = std::getenv("FAIR_DXF_CASES_DIR");
  const auto cases = fair_test::nurbs_cases<K>();
  std::vector<fair::Nurbs_curve_2<K>> all;
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string text = fair::io::dxf_text(std::vector<fair::Nurbs_curve_2<K>>{c.curve});
    const std::vector<Tag> tags = tags_of(text);
    check_structure(tags);
    check_spline(tags, c.curve);
    all.push_back(c.curve);
    if (!dir) continue;
    // The case for check_dxf.py: the drawing, and the library's points at 64 parameters per
    // knot span (the spans' ends included): "u x y" with 17 digits.
    std::ofstream(std::string(dir) + "/" + c.name + ".dxf") << text;
    std::ofstream samples(std::string(dir) + "/" + c.name + ".samples");
    const std::vector<double> b = c.curve.breakpoints();
    for (std::size_t j = 0; j + 1 < b.size(); ++j)
      for (int k = 0; k <= 64; ++k) {
        const double u = k == 64 ? b[j + 1] : b[j] + (b[j + 1] - b[j]) * k / 64.0;
        const auto p = c.curve.point(u);
        samples << text17(u) << ' ' << text17(p.x()) << ' ' << text17(p.y()) << '\n';
      }
  }
  // all curves in one drawing: one SPLINE each, handles still unique
  const std::vector<Tag> tags = tags_of(fair::io::dxf_text(all));
  check_structure(tags);
  std::size_t splines = 0;
  for (const Tag& t : tags) splines += t.code == 0 && t.value == "SPLINE";
  EXPECT_EQ(splines, cases.size());
  if (dir) std::ofstream(std::string(dir) + "/all.dxf") << fair::io::dxf_text(all);
}

// In an exact kernel each number is its nearest double: the drawing of a curve with dyadic
// numbers (exact doubles) is the double kernel's, byte for byte.
TEST(Dxf_export, exact_kernels_write_the_nearest_doubles) {
  // (the direct NURBS only: the families' solvers in an exact kernel are not this test's subject)
  std::vector<fair_test::Nurbs_case<K>> d;
  std::vector<fair_test::Nurbs_case<fair_test::EPECK>> e;
  std::vector<fair_test::Nurbs_case<fair_test::SC_gmpq>> q;
  fair_test::add_direct_cases(d);
  fair_test::add_direct_cases(e);
  fair_test::add_direct_cases(q);
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (d[i].name != "polyline_degree_1" && d[i].name != "rational_cubic_closed") continue;
    SCOPED_TRACE(d[i].name);
    EXPECT_EQ(fair::io::dxf_text(std::vector<fair::Nurbs_curve_2<fair_test::EPECK>>{e[i].curve}),
              fair::io::dxf_text(std::vector<fair::Nurbs_curve_2<K>>{d[i].curve}));
    EXPECT_EQ(fair::io::dxf_text(std::vector<fair::Nurbs_curve_2<fair_test::SC_gmpq>>{q[i].curve}),
              fair::io::dxf_text(std::vector<fair::Nurbs_curve_2<K>>{d[i].curve}));
  }
  // 1/3 as a knot: its nearest double, 17 digits
  typedef fair_test::SC_gmpq Q;
  const fair::Nurbs_curve_2<Q> c(1, {0, 0, CGAL::Gmpq(1, 3), 1, 1}, {Q::Point_2(0, 0), Q::Point_2(1, 1), Q::Point_2(2, 0)});
  EXPECT_NE(fair::io::dxf_text(std::vector<fair::Nurbs_curve_2<Q>>{c}).find("\n40\n0.33333333333333331\n"), std::string::npos);
}

} // namespace
