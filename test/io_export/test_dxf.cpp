// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::io::write_dxf (include/fair/io/write_dxf.h): the structure of the drawing (sections in
// order, unique handles below $HANDSEED, owners, the SPLINE groups of every case); every case in
// EPECK and Simple_cartesian<Gmpq> (each number the nearest double of its exact value, decided
// exactly; dyadic curves byte for byte the double kernel's); the error for a value that is not
// finite as a double. Every case is also
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
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
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

// ---------------------------------------------------------------- exact kernels
// Every case of nurbs_cases.h (every family, and the direct NURBS) is also built in EPECK and
// Simple_cartesian<Gmpq>, once per kernel. (This test once stopped with no output: building the
// families in EPECK crashed in finish_c0 of internal/nurbs/assembly.h, which formatted
// to_double(d.w.back()) of an emptied weight vector for its error message even when the check
// held; fixed there. Each case is now its own test, so a crash names the case under ctest, and
// check_dxf.py reports a generator killed by a signal.)
template <class KK>
const std::vector<fair_test::Nurbs_case<KK>>& cases_in() {
  static const std::vector<fair_test::Nurbs_case<KK>> cases = fair_test::nurbs_cases<KK>();
  return cases;
}

template <class KK>
const fair::Nurbs_curve_2<KK>& case_named(const std::string& name) {
  for (const auto& c : cases_in<KK>())
    if (c.name == name) return c.curve;
  throw std::runtime_error("no case " + name);
}

std::vector<std::string> case_names() {
  std::vector<std::string> names;
  for (const auto& c : fair_test::nurbs_cases<K>()) names.push_back(c.name);
  return names;
}

CGAL::Gmpq exact_value(const CGAL::Gmpq& x) { return x; }
CGAL::Gmpq exact_value(const fair_test::EPECK::FT& x) {
  CGAL::Gmpq q;
  mpq_set(q.mpq(), x.exact().get_mpq_t());
  return q;
}

/// The written text of a number is the double nearest to the exact value x: no neighbour of it
/// is closer (decided in exact rational arithmetic, independently of the writer).
template <class FT>
void expect_nearest(const std::string& text, const FT& value) {
  const CGAL::Gmpq x = exact_value(value);
  const double d = std::strtod(text.c_str(), nullptr);
  const CGAL::Gmpq e = CGAL::abs(CGAL::Gmpq(d) - x);
  for (double n : {std::nextafter(d, HUGE_VAL), std::nextafter(d, -HUGE_VAL)})
    EXPECT_LE(e, CGAL::abs(CGAL::Gmpq(n) - x)) << text << " is not the nearest double of " << x;
  EXPECT_EQ(text, text17(d)) << "17 significant digits";
}

/// The drawing of the case `name` in the exact kernel KK: a valid structure; every knot, weight
/// and coordinate the nearest double of its exact value; and the same curve as the double
/// kernel's case (control points within 1e-9 of the extent: the families' exact and floating
/// constructions agree).
template <class KK>
void check_exact_case(const std::string& name) {
  const fair::Nurbs_curve_2<KK>& c = case_named<KK>(name);
  const fair::Nurbs_curve_2<K>& d = case_named<K>(name);
  const std::vector<Tag> tags = tags_of(fair::io::dxf_text(std::vector<fair::Nurbs_curve_2<KK>>{c}));
  check_structure(tags);
  std::size_t at = 0;
  while (at < tags.size() && !(tags[at].code == 0 && tags[at].value == "SPLINE")) ++at;
  ASSERT_LT(at, tags.size());
  std::map<int, std::vector<std::string>> g;
  for (std::size_t i = at + 1; i < tags.size() && tags[i].code != 0; ++i) g[tags[i].code].push_back(tags[i].value);
  EXPECT_EQ(g[70], std::vector<std::string>{std::to_string(8 + (c.is_rational() ? 4 : 0) + (c.is_closed() ? 3 : 0))});
  EXPECT_EQ(g[71], std::vector<std::string>{std::to_string(c.degree())});
  ASSERT_EQ(g[40].size(), c.knots().size());
  for (std::size_t i = 0; i < g[40].size(); ++i) expect_nearest(g[40][i], c.knots()[i]);
  ASSERT_EQ(g[41].size(), c.is_rational() ? c.weights().size() : 0u);
  for (std::size_t i = 0; i < g[41].size(); ++i) expect_nearest(g[41][i], c.weights()[i]);
  ASSERT_EQ(g[10].size(), c.control_points().size());
  ASSERT_EQ(g[20].size(), c.control_points().size());
  ASSERT_EQ(c.control_points().size(), d.control_points().size());
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for (const auto& p : d.control_points()) {
    lo[0] = std::min(lo[0], p.x()), hi[0] = std::max(hi[0], p.x());
    lo[1] = std::min(lo[1], p.y()), hi[1] = std::max(hi[1], p.y());
  }
  const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  for (std::size_t i = 0; i < g[10].size(); ++i) {
    expect_nearest(g[10][i], c.control_points()[i].x());
    expect_nearest(g[20][i], c.control_points()[i].y());
    EXPECT_NEAR(std::strtod(g[10][i].c_str(), nullptr), d.control_points()[i].x(), 1e-9 * extent) << i;
    EXPECT_NEAR(std::strtod(g[20][i].c_str(), nullptr), d.control_points()[i].y(), 1e-9 * extent) << i;
  }
}

class Dxf_exact_kernels : public ::testing::TestWithParam<std::string> {};

TEST_P(Dxf_exact_kernels, EPECK_writes_the_nearest_doubles_of_the_same_curve) {
  check_exact_case<fair_test::EPECK>(GetParam());
}

TEST_P(Dxf_exact_kernels, SC_gmpq_writes_the_nearest_doubles_of_the_same_curve) {
  check_exact_case<fair_test::SC_gmpq>(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Every_case, Dxf_exact_kernels, ::testing::ValuesIn(case_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// A curve with dyadic numbers (exact doubles): the exact kernels' drawing is the double
// kernel's, byte for byte.
TEST(Dxf_export, exact_kernels_write_dyadic_curves_byte_for_byte) {
  for (const std::string name : {"polyline_degree_1", "rational_cubic_closed"}) {
    SCOPED_TRACE(name);
    const std::string text = fair::io::dxf_text(std::vector<fair::Nurbs_curve_2<K>>{case_named<K>(name)});
    EXPECT_EQ(fair::io::dxf_text(std::vector<fair::Nurbs_curve_2<fair_test::EPECK>>{case_named<fair_test::EPECK>(name)}), text);
    EXPECT_EQ(fair::io::dxf_text(std::vector<fair::Nurbs_curve_2<fair_test::SC_gmpq>>{case_named<fair_test::SC_gmpq>(name)}), text);
  }
}

// Known nearest doubles: 1/10 -> 0.10000000000000001 (above 1/10; CGAL::to_double of a Gmpq
// truncates to 0.099999999999999992) and 1/3 -> 0.33333333333333331 (below 1/3; EPECK's
// CGAL::to_double gives 0.33333333333333337), as a knot, a weight and a coordinate.
template <class KK>
void check_known_nearest() {
  typedef typename KK::FT FT;
  typedef typename KK::Point_2 P;
  const FT tenth = FT(1) / FT(10), third = FT(1) / FT(3);
  const fair::Nurbs_curve_2<KK> c(2, {0, 0, 0, third, 1, 1, 1}, {P(0, 0), P(tenth, 1), P(2, third), P(3, 0)},
                                  {FT(1), third, tenth, FT(1)});
  const std::string text = fair::io::dxf_text(std::vector<fair::Nurbs_curve_2<KK>>{c});
  EXPECT_NE(text.find("\n40\n0.33333333333333331\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n41\n0.33333333333333331\n41\n0.10000000000000001\n"), std::string::npos);
  EXPECT_NE(text.find("\n10\n0.10000000000000001\n20\n1\n"), std::string::npos);
  EXPECT_NE(text.find("\n10\n2\n20\n0.33333333333333331\n"), std::string::npos);
}

TEST(Dxf_export, exact_kernels_round_to_the_nearest_double) {
  check_known_nearest<fair_test::SC_gmpq>();
  check_known_nearest<fair_test::EPECK>();
}

// A value whose nearest double is infinite is refused by name before anything is written.
// Nurbs_curve_2 refuses values whose CGAL::to_double is not finite; DBL_MAX + 2^970 + 2^969
// passes there (to_double truncates it to DBL_MAX = 2^1024 - 2^971) but lies beyond the midpoint
// DBL_MAX + 2^970 of DBL_MAX and 2^1024, so its nearest double is infinity.
TEST(Dxf_export, a_value_not_finite_as_a_double_is_a_precondition_error) {
  typedef fair_test::SC_gmpq Q;
  const CGAL::Gmpq huge = CGAL::Gmpq(std::numeric_limits<double>::max()) + CGAL::Gmpq(std::ldexp(1.0, 970)) +
                          CGAL::Gmpq(std::ldexp(1.0, 969));
  ASSERT_EQ(CGAL::to_double(huge), std::numeric_limits<double>::max());
  const fair::Nurbs_curve_2<Q> c(1, {0, 0, 1, 1}, {Q::Point_2(0, 0), Q::Point_2(1, huge)});
  std::ostringstream out;
  try {
    fair::io::write_dxf(out, c);
    ADD_FAILURE() << "no error";
  } catch (const fair::Precondition_error& e) {
    EXPECT_NE(std::string(e.what()).find("curve 0: control point y 1 is not finite"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(out.str().empty());
  // the same value as a knot of the second curve of a drawing
  const fair::Nurbs_curve_2<Q> ok(1, {0, 0, 1, 1}, {Q::Point_2(0, 0), Q::Point_2(1, 1)});
  const fair::Nurbs_curve_2<Q> far_knot(1, {0, 0, huge, huge}, {Q::Point_2(0, 0), Q::Point_2(1, 1)});
  try {
    fair::io::write_dxf(out, std::vector<fair::Nurbs_curve_2<Q>>{ok, far_knot});
    ADD_FAILURE() << "no error";
  } catch (const fair::Precondition_error& e) {
    EXPECT_NE(std::string(e.what()).find("curve 1: knot 2 is not finite"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(out.str().empty());
}

} // namespace
