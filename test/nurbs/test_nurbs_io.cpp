// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The "bspline" member of the curve JSON: fair::io::nurbs_to_json writes a Nurbs_curve_2,
// fair::io::read_nurbs reads it back -- exactly in Simple_cartesian<Gmpq> (values that are not
// doubles travel as "p/q"), open and closed, polynomial and rational -- and every malformed member
// is a Parse_error at the line of the offending value: wrong knot count, decreasing knots,
// weights <= 0, NaN, a missing member, a knot of too high multiplicity.

#include "test_support.h"

#include <fair/Nurbs_curve_2.h>
#include <fair/io/read_curve.h>
#include <fair/io/read_nurbs.h>
#include <fair/io/write_json.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

typedef fair_test::SC_gmpq Kq;
typedef fair_test::SC_double Kd;

template <class K>
fair::Nurbs_curve_2<K> rational_open() {
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  // degree 2, a double interior knot, a weight 1/3 (not a double)
  return fair::Nurbs_curve_2<K>(2, {FT(0), FT(0), FT(0), FT(1) / 3, FT(1) / 3, FT(1), FT(1), FT(1)},
                                {P(0, 0), P(1, 2), P(FT(3) / 2, FT(5) / 7), P(2, -1), P(4, 0)},
                                {FT(1), FT(1) / 3, FT(1), FT(2), FT(1)});
}

template <class K>
fair::Nurbs_curve_2<K> closed_cubic() {
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  // periodic, N = 4 control points, period 4 with knot intervals 1, 1/3, 2/3, 2
  const std::vector<FT> period{FT(0), FT(1), FT(4) / 3, FT(2), FT(4)};
  std::vector<FT> u(4 + 6 + 1);
  for (std::size_t k = 0; k <= 4; ++k) u[3 + k] = period[k];
  for (std::size_t k = 0; k < 3; ++k) u[k] = u[k + 4] - FT(4);
  for (std::size_t k = 8; k < u.size(); ++k) u[k] = u[k - 4] + FT(4);
  std::vector<P> d{P(0, 0), P(2, FT(1) / 5), P(3, 2), P(FT(1) / 3, 3)};
  for (std::size_t k = 0; k < 3; ++k) d.push_back(d[k]);
  return fair::Nurbs_curve_2<K>(3, u, d, {}, true);
}

template <class K>
void expect_same_curve(const fair::Nurbs_curve_2<K>& a, const fair::Nurbs_curve_2<K>& b) {
  EXPECT_EQ(a.degree(), b.degree());
  EXPECT_EQ(a.is_closed(), b.is_closed());
  EXPECT_EQ(a.is_rational(), b.is_rational());
  EXPECT_EQ(a.knots(), b.knots());
  EXPECT_EQ(a.control_points(), b.control_points());
  EXPECT_EQ(a.weights(), b.weights());
}

TEST(Nurbs_json, RoundTripIsExactInGmpq) {
  for (const fair::Nurbs_curve_2<Kq>& c : {rational_open<Kq>(), closed_cubic<Kq>()}) {
    const nlohmann::json j = fair::io::nurbs_to_json(c);
    EXPECT_EQ(j["degree"], c.degree());
    EXPECT_EQ(j["closed"], c.is_closed());
    EXPECT_EQ(j["knots"].size(), c.knots().size());
    EXPECT_EQ(j.contains("weights"), c.is_rational());
    const nlohmann::json doc{{"format", "fair-curve"}, {"bspline", j}};
    expect_same_curve(fair::io::parse_nurbs_json<Kq>(doc.dump(2), "doc.json"), c);
  }
  const nlohmann::json j = fair::io::nurbs_to_json(rational_open<Kq>());
  EXPECT_EQ(j["knots"][3], "1/3");
  EXPECT_EQ(j["weights"][1], "1/3");
  EXPECT_EQ(j["control_points"][2][1], "5/7");
  EXPECT_EQ(j["control_points"][2][0], 1.5);  // a double stays a JSON number
  // the closed curve: no weights, the periodic knots written out
  const nlohmann::json k = fair::io::nurbs_to_json(closed_cubic<Kq>());
  EXPECT_FALSE(k.contains("weights"));
  EXPECT_EQ(k["knots"].size(), 11u);
  EXPECT_EQ(k["knots"][0], -3.0);  // u_0 = u_4 - T = 1 - 4
  EXPECT_EQ(k["knots"][1], "-8/3");  // u_1 = u_5 - T = 4/3 - 4
}

TEST(Nurbs_json, DoublesReadBackBitForBit) {
  const fair::Nurbs_curve_2<Kd> c = rational_open<Kd>();
  const nlohmann::json doc{{"bspline", fair::io::nurbs_to_json(c)}};
  expect_same_curve(fair::io::parse_nurbs_json<Kd>(doc.dump(), "d.json"), c);
  // and a double file read in Gmpq is the exact value of the doubles
  const fair::Nurbs_curve_2<Kq> e = fair::io::parse_nurbs_json<Kq>(doc.dump(), "d.json");
  EXPECT_EQ(e.weights()[1], Kq::FT(CGAL::to_double(c.weights()[1])));
}

// The text of a curve JSON whose "bspline" has `member` replaced by `value` (raw JSON text).
std::string with_member(const std::string& member, const std::string& value) {
  nlohmann::json b = fair::io::nurbs_to_json(rational_open<Kd>());
  std::string text = "{\n\"bspline\": {\n";
  bool first = true;
  for (auto it = b.begin(); it != b.end(); ++it) {
    if (it.key() == member) continue;
    text += std::string(first ? "" : ",\n") + "\"" + it.key() + "\": " + it.value().dump();
    first = false;
  }
  if (!value.empty()) text += ",\n\"" + member + "\":\n" + value;
  return text + "\n}\n}\n";
}

void expect_parse_error(const std::string& text, std::size_t line, const std::string& words) {
  try {
    fair::io::parse_nurbs_json<Kq>(text, "c.json");
    ADD_FAILURE() << "no error for " << text;
  } catch (const fair::Parse_error& e) {
    EXPECT_EQ(e.file(), "c.json");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what() << " (expected: " << words << ")";
  }
}

TEST(Nurbs_json, MalformedMembersAreParseErrorsAtTheirLine) {
  // the replaced member's value is written on line 8 (after "{", "\"bspline\": {", four members and
  // its key): an error about a value is reported at the value's line
  expect_parse_error(with_member("knots", "[0, 0, 0, 0.5, 1, 1, 1]"), 8, "7 knots for 5 control points of degree 2");
  expect_parse_error(with_member("knots", "[0, 0, 0, 0.5, 0.25, 1, 1, 1]"), 8, "knot 4 = 0.25 is smaller than knot 3");
  expect_parse_error(with_member("weights", "[1, 0, 1, 1, 1]"), 8, "weight 1 = 0 must be > 0");
  expect_parse_error(with_member("weights", "[1, -2, 1, 1, 1]"), 8, "must be > 0");
  expect_parse_error(with_member("weights", "[1, 1, 1]"), 8, "3 weights for 5 control points");
  expect_parse_error(with_member("weights", "[1, \"NaN\", 1, 1, 1]"), 8, "weight 1");
  expect_parse_error(with_member("knots", "[0, 0, 0, \"nan\", 0.5, 1, 1, 1]"), 8, "knot 3");
  expect_parse_error(with_member("control_points", "[[0, 0], [1, 1e999], [2, 0], [3, 1], [4, 0]]"), 8,
                     "'1e999' is too large");
  expect_parse_error(with_member("control_points", "[[0, 0], [1], [2, 0], [3, 1], [4, 0]]"), 8, "[x, y] pair");
  expect_parse_error(with_member("degree", "0"), 8, "\"degree\" must be an integer >= 1");
  expect_parse_error(with_member("degree", "2.5"), 8, "\"degree\" must be an integer >= 1");
  expect_parse_error(with_member("closed", "\"yes\""), 8, "\"closed\" must be true or false");
  expect_parse_error(with_member("knots", ""), 2, "has no \"knots\"");
  expect_parse_error(with_member("control_points", "[]"), 8, "\"control_points\" must be a nonempty array");
  // what only the class knows, reported at the line of the member: a knot of multiplicity 4 > p + 1
  expect_parse_error(with_member("knots", "[0, 0, 0, 0, 1, 1, 1, 1]"), 2, "multiplicity 4");
  // a closed curve that does not repeat its first p control points
  expect_parse_error(with_member("closed", "true"), 2, "closed curve");
  expect_parse_error("{\"pieces\": []}", 1, "no \"bspline\" member");
  expect_parse_error("[1, 2]", 1, "expected a curve JSON");
  expect_parse_error("{\"bspline\": [1]}", 1, "\"bspline\" must be an object");
}

TEST(Nurbs_json, ReadNurbsOnAParsedMember) {
  // read_nurbs on the member of a document parsed once (what a command reading a curve file does)
  const nlohmann::json doc{{"pieces", nlohmann::json::array()}, {"bspline", fair::io::nurbs_to_json(closed_cubic<Kq>())}};
  const fair::io::Json_value root = fair::io::parse_json(doc.dump(1), "f.json");
  expect_same_curve(fair::io::read_nurbs<Kq>(*root.find("bspline"), "f.json"), closed_cubic<Kq>());
}

}  // namespace
