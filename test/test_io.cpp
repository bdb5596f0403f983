// Tests of fair/io: reading point files (CSV, JSON), number files (tensions, lambdas, constraints)
// and curve JSON, the exact line of every parse error, the JSON/CSV writers (round trips, exact
// rationals, refusal to write non-finite numbers, the one curve JSON, the reports) and the enum
// spellings.

#include <fair/Bezier_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/Rational_bezier_2.h>
#include <fair/io/enum_names.h>
#include <fair/io/parsing.h>
#include <fair/io/read_constraints.h>
#include <fair/io/read_curve.h>
#include <fair/io/read_numbers.h>
#include <fair/io/read_points.h>
#include <fair/io/write_json.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace fair_test;

const std::string data_dir = std::string(FAIR_TEST_DATA_DIR) + "/io/";

// Expects `f` to throw Parse_error at `line`, naming `file`; returns the message.
template <class F>
std::string expect_parse_error(F f, const std::string& file, std::size_t line) {
  try {
    f();
  } catch (const fair::Parse_error& e) {
    EXPECT_EQ(e.file(), file) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    const std::string prefix = line ? file + ":" + std::to_string(line) + ": " : file + ": ";
    EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "multi-line message: " << e.what();
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected Parse_error at " << file << ":" << line << ", got " << e.what();
    return std::string();
  }
  ADD_FAILURE() << "expected Parse_error at " << file << ":" << line << ", nothing thrown";
  return std::string();
}

// A malformed text and the line its Parse_error must name (0: the whole file).
struct Parse_case {
  const char* text;
  std::size_t line;
};

// ------------------------------------------------------------------ number parsing

TEST(IoNumbers, DecimalsRoundTripEveryDouble) {
  // Seeded random doubles over the whole exponent range: the 17-digit text reads back to
  // the same double (correct rounding), as does the shortest text nlohmann writes.
  std::mt19937_64 rng(20260101);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-300, 300);
  for (int i = 0; i < 2000; ++i) {
    const double v = std::ldexp(mantissa(rng), exponent(rng));
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    EXPECT_EQ(fair::io::parse_decimal(buffer, "f", 1, "x"), v) << buffer;
    const std::string shortest = nlohmann::json(v).dump();
    EXPECT_EQ(fair::io::parse_decimal(shortest, "f", 1, "x"), v) << shortest;
  }
  // Halfway cases and subnormals are rounded correctly.
  EXPECT_EQ(fair::io::parse_decimal("0.1", "f", 1, "x"), 0.1);
  EXPECT_EQ(fair::io::parse_decimal("9007199254740993", "f", 1, "x"), 9007199254740992.0);
  EXPECT_EQ(fair::io::parse_decimal("4.9406564584124654e-324", "f", 1, "x"),
            std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(fair::io::parse_decimal("+.5", "f", 1, "x"), 0.5);
  EXPECT_EQ(fair::io::parse_decimal("-7.", "f", 1, "x"), -7.0);
  EXPECT_EQ(fair::io::parse_decimal("1.7976931348623157e308", "f", 1, "x"),
            std::numeric_limits<double>::max());
}

TEST(IoNumbers, RejectsEveryMalformedNumberWithItsReason) {
  struct Case {
    const char* text;
    const char* reason;
  };
  const Case cases[] = {{"nan", "NaN"},           {"-NaN", "NaN"},
                        {"inf", "infinite"},      {"+Infinity", "infinite"},
                        {"0x1p3", "hexadecimal"}, {"1e999", "overflows"},
                        {"-1e400", "overflows"},  {"1e-999", "underflows"},
                        {"", "empty"},            {"abc", "not a number"},
                        {"1.2.3", "trailing"},    {"--1", "not a number"},
                        {"1e", "trailing"},       {"e5", "not a number"},
                        {".", "not a number"},    {"1 2", "trailing"},
                        {"1,5", "trailing"},      {"12abc", "trailing"}};
  for (const Case& c : cases) {
    const std::string msg = expect_parse_error(
        [&] { fair::io::parse_decimal(c.text, "n.csv", 9, "x coordinate"); }, "n.csv", 9);
    EXPECT_NE(msg.find(c.reason), std::string::npos) << c.text << " -> " << msg;
  }
}

// Oracle of correct rounding: |v - q| <= |w - q| for both neighbours w of v (exact in Gmpq).
static void expect_nearest_double(double v, const CGAL::Gmpq& q) {
  ASSERT_TRUE(std::isfinite(v));
  const CGAL::Gmpq d = CGAL::abs(CGAL::Gmpq(v) - q);
  for (const double w : {std::nextafter(v, -INFINITY), std::nextafter(v, INFINITY)})
    if (std::isfinite(w)) { EXPECT_LE(d, CGAL::abs(CGAL::Gmpq(w) - q)) << v; }
}

TEST(IoNumbers, RationalsBeyondTheDoubleRangeAreReadExactlyThenRounded) {
  // Issue 29 #11: 10^310 / (3 10^310) is 1/3, although p and q overflow double.
  const std::string zeros(310, '0');
  const auto third = fair::io::parse_number("1" + zeros + "/3" + zeros, "f", 1, "x");
  EXPECT_EQ(third.value, 1.0 / 3.0);
  EXPECT_EQ(fair::io::to_ft<CGAL::Gmpq>(third), CGAL::Gmpq(1, 3));
  // Subnormal quotients are finite numbers, rounded like the decimal of the same value.
  const auto tiny = fair::io::parse_number("1/1" + std::string(320, '0'), "f", 1, "x");
  EXPECT_EQ(tiny.value, fair::io::parse_decimal("1e-320", "f", 1, "x"));
  EXPECT_EQ(fair::io::parse_decimal("1e-320", "f", 1, "x"), 1e-320);
  // Quotients beyond the range: overflow and underflow named.
  const std::string m1 = expect_parse_error([] { fair::io::parse_number("1" + std::string(400, '0') + "/3", "f", 2, "x"); }, "f", 2);
  EXPECT_NE(m1.find("overflows double"), std::string::npos) << m1;
  const std::string m2 = expect_parse_error([] { fair::io::parse_number("1/1" + std::string(400, '0'), "f", 2, "x"); }, "f", 2);
  EXPECT_NE(m2.find("underflows to zero"), std::string::npos) << m2;
  // Largest double and the rounding boundary above it (DBL_MAX + half an ulp rounds to inf).
  const CGAL::Gmpq max(std::numeric_limits<double>::max());
  std::ostringstream at_max;
  at_max << max;
  EXPECT_EQ(fair::io::parse_number(at_max.str(), "f", 1, "x").value, std::numeric_limits<double>::max());
  // Seeded random property: 1..60-digit p and q, ties included (q a power of two), correctly rounded.
  std::mt19937_64 rng(29);
  for (int trial = 0; trial < 300; ++trial) {
    auto digits = [&](int n) {
      std::string d(1, char('1' + rng() % 9));
      for (int k = 1; k < n; ++k) d += char('0' + rng() % 10);
      return d;
    };
    const std::string p = digits(1 + int(rng() % 60)), q = trial % 10 == 0 ? "4" : digits(1 + int(rng() % 60));
    const auto n = fair::io::parse_number("-" + p + "/" + q, "f", 1, "x");
    expect_nearest_double(n.value, -CGAL::Gmpq(p + "/" + q));
  }
  // A cap on the digits of one rational (fair::io::max_rational_digits).
  expect_parse_error([] { fair::io::parse_number(std::string(fair::io::max_rational_digits + 1, '7') + "/3", "f", 3, "x"); },
                     "f", 3);
}

TEST(IoNumbers, Rationals) {
  const auto r = fair::io::parse_number("-9192/12241", "f", 1, "x");
  EXPECT_TRUE(r.rational);
  EXPECT_EQ(r.value, -9192.0 / 12241.0);
  const CGAL::Gmpq q = fair::io::to_ft<CGAL::Gmpq>(r);
  EXPECT_EQ(q, CGAL::Gmpq(-9192, 12241));
  // An exact FT gets the exact value even for digits beyond double precision.
  const auto big = fair::io::parse_number("123456789012345678901234567891/7", "f", 1, "x");
  const EPECK::FT e = fair::io::to_ft<EPECK::FT>(big);
  std::ostringstream exact;
  exact << e.exact();
  EXPECT_EQ(exact.str(), "123456789012345678901234567891/7");
  // The double of a rational is the correctly rounded exact quotient (issue 29: not p and q
  // rounded separately, then divided): no double is nearer to the exact value.
  expect_nearest_double(fair::io::to_ft<double>(big), CGAL::Gmpq("123456789012345678901234567891/7"));
  for (const char* bad : {"1/0", "1/-3", "1/", "/3", "1.5/2", "1/2/3", "a/b", "1/00"})
    expect_parse_error([&] { fair::io::parse_number(bad, "r", 4, "x"); }, "r", 4);
}

// ------------------------------------------------------------------ point files, per kernel

template <class K>
class IoKernels : public ::testing::Test {};
TYPED_TEST_SUITE(IoKernels, All_kernels);

TYPED_TEST(IoKernels, ReadsCsvWithHeaderCommentsBlankLinesCrlfAndRationals) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const std::string file = data_dir + "good.csv";
  const fair::io::Point_file<K> f = fair::io::read_point_file<K>(file);
  ASSERT_EQ(f.points.size(), 5u);
  EXPECT_EQ(f.lines, (std::vector<std::size_t>{3, 5, 6, 7, 8}));
  EXPECT_FALSE(f.closed_given);
  EXPECT_EQ(f.points[0], typename K::Point_2(0, 0));
  EXPECT_EQ(f.points[1], typename K::Point_2(1.5, 0.25));
  EXPECT_EQ(f.points[2], typename K::Point_2(3, 1));
  EXPECT_EQ(f.points[3], typename K::Point_2(-0.25, 4));
  // "9192/12241": exact in an exact kernel, the correctly rounded quotient otherwise.
  if (is_exact<K>())
    EXPECT_TRUE(f.points[4].x() * FT(12241) == FT(9192));
  else
    EXPECT_EQ(CGAL::to_double(f.points[4].x()), 9192.0 / 12241.0);
  EXPECT_EQ(fair::io::read_points<K>(file), f.points);
}

TYPED_TEST(IoKernels, ReadsJsonObjectAndBareArray) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const fair::io::Point_file<K> sq = fair::io::read_point_file<K>(data_dir + "good_closed.json");
  ASSERT_EQ(sq.points.size(), 4u);
  EXPECT_TRUE(sq.closed_given);
  EXPECT_TRUE(sq.closed);
  EXPECT_EQ(sq.points[2], typename K::Point_2(1, 1));
  EXPECT_EQ(sq.lines, (std::vector<std::size_t>{3, 3, 3, 3}));
  EXPECT_NO_THROW(fair::io::check_point_file(sq, 3, true, "test"));

  const fair::io::Point_file<K> bare = fair::io::read_point_file<K>(data_dir + "good_bare.json");
  ASSERT_EQ(bare.points.size(), 3u);
  EXPECT_FALSE(bare.closed_given);
  EXPECT_EQ(bare.points[0], typename K::Point_2(0.1, 0.2));  // through the nearest double
  if (is_exact<K>()) {
    EXPECT_TRUE(bare.points[1].x() * FT(3) == FT(1));
    EXPECT_TRUE(bare.points[1].y() * FT(7) == FT(-2));
  } else {
    EXPECT_EQ(CGAL::to_double(bare.points[1].x()), 1.0 / 3.0);
  }
  const fair::io::Point_file<K> spaces = fair::io::read_point_file<K>(data_dir + "good_spaces.txt");
  EXPECT_EQ(spaces.points.size(), 3u);
  EXPECT_EQ(spaces.points[2], typename K::Point_2(3, 5));
}

TYPED_TEST(IoKernels, EveryBadFileGivesParseErrorAtItsLine) {
  typedef TypeParam K;
  std::ifstream manifest(data_dir + "bad_inputs.txt");
  ASSERT_TRUE(manifest.good());
  std::string line;
  int cases = 0;
  while (std::getline(manifest, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream in(line);
    std::string name;
    std::size_t expected = 0;
    ASSERT_TRUE(static_cast<bool>(in >> name >> expected)) << line;
    const std::string file = data_dir + name;
    expect_parse_error(
        [&] {
          const fair::io::Point_file<K> f = fair::io::read_point_file<K>(file);
          fair::io::check_point_file(f, 2, false, "points");
        },
        file, expected);
    ++cases;
  }
  EXPECT_GE(cases, 25);
}

TYPED_TEST(IoKernels, JsonRoundTripIsExact) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1e6, 1e6);
  std::vector<Point_2> points;
  for (int i = 0; i < 50; ++i) points.push_back(Point_2(u(rng), std::ldexp(u(rng), -40)));
  if (is_exact<K>()) {
    // Values that are not doubles travel as exact "p/q" strings.
    points.push_back(Point_2(FT(1) / FT(3), FT(-22) / FT(7)));
  }
  const nlohmann::json j = fair::io::points_to_json(points, true);
  std::ostringstream text;
  fair::io::write_json(text, j);
  const fair::io::Point_file<K> back = fair::io::parse_points_json<K>(text.str(), "mem.json");
  EXPECT_TRUE(back.closed);
  ASSERT_EQ(back.points.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) EXPECT_TRUE(back.points[i] == points[i]) << i;

  std::ostringstream csv;
  std::vector<Point_2> doubles(points.begin(), points.begin() + 50);
  fair::io::write_points_csv(csv, doubles);
  const fair::io::Point_file<K> back_csv = fair::io::parse_points_csv<K>(csv.str(), "mem.csv");
  EXPECT_EQ(back_csv.points, doubles);
}

// ------------------------------------------------------------------ malformed text in memory

TEST(IoCsv, MalformedLinesInMemory) {
  typedef SC_double K;
  const Parse_case cases[] = {
      {"", 0},                          // empty
      {"\n\n  \n", 0},                  // blank only
      {"x,y\n", 0},                     // header only
      {"x,y,z\n1,2\n", 1},              // header with three columns
      {"1,2\n3\n", 2},                  // one field
      {"1,2\n3,4,\n", 2},               // trailing comma: an empty third field
      {"1,2\n,4\n", 2},                 // empty field
      {"1,2\n3;4\n", 2},                // wrong separator
      {"1,2\n3,4\n5,6 7\n", 3},         // trailing garbage
      {"1,2\n3 4 5\n", 2},              // three whitespace-separated fields
      {"1,2\nNaN,1\n", 2},              // NaN
      {"1,2\n1,-INF\n", 2},             // infinity
      {"1,2 # ok\n\n# c\n1e309,0\n", 4},// overflow after comments
      {"1,2\n\x01,3\n", 2},             // control byte
      {"x,1\n", 1},                     // not a header: one numeric field
      {"nan,inf\n", 1},                 // NaN spellings are not column names
  };
  for (const Parse_case& c : cases)
    expect_parse_error([&] { fair::io::parse_points_csv<K>(c.text, "m.csv"); }, "m.csv", c.line);
}

TEST(IoJson, MalformedJsonInMemory) {
  typedef SC_double K;
  const Parse_case cases[] = {
      {"", 0},
      {"  \n ", 0},
      {"{\n\"points\": [[0, 0]\n", 2},            // unterminated array (end of file on line 2)
      {"[[0,0],\n[1,1],\n]", 3},                  // trailing comma
      {"[[0,0],\n[1]]", 2},                       // one coordinate
      {"[[0,0],\n{\"x\": 1}]", 2},                // not a pair
      {"[[0,0],\n[1, true]]", 2},                 // boolean coordinate
      {"[[0,0],\n[1, null]]", 2},                 // null coordinate
      {"[[0,0],\n[1, \"1/0\"]]", 2},              // zero denominator
      {"[[0,0],\n[1, Infinity]]", 2},             // infinity
      {"[[0,0],\n[1, -0x10]]", 2},                // hexadecimal
      {"[[0,0],\n[1, 2]] x", 2},                  // trailing garbage
      {"{\"points\": 3}", 1},                     // points not an array
      {"3", 1},                                   // neither object nor array
      {"{\"points\": [[0,0]],\n\"closed\": 1}", 2},  // closed not a boolean
      {"{\"points\"\n [[0,0]]}", 2},              // missing ':'
      {"{\"a\": \"\x01\"}", 1},                   // control character in a string
      {"{\"a\": \"\\q\"}", 1},                    // bad escape
      {"[\"unterminated]", 1},
  };
  for (const Parse_case& c : cases)
    expect_parse_error([&] { fair::io::parse_points_json<K>(c.text, "m.json"); }, "m.json", c.line);
  // Deep nesting is refused, not a stack overflow.
  std::string deep(100000, '[');
  expect_parse_error([&] { fair::io::parse_points_json<K>(deep, "d.json"); }, "d.json", 1);
  // Escapes and unknown members are fine.
  const auto ok = fair::io::parse_points_json<K>(
      "{\"name\": \"a\\\"b\\u00e9\", \"points\": [[1, 2], [\"3\", \"4.5\"]], \"extra\": {\"k\": [null]}}", "ok");
  EXPECT_EQ(ok.points.size(), 2u);
  EXPECT_EQ(ok.points[1], K::Point_2(3, 4.5));
}

// Issue 29 #18: RFC 8259 strictly: number tokens, duplicate names, the byte-order mark.
TEST(IoJson, StrictRfc8259NumbersDuplicateKeysAndByteOrderMark) {
  typedef SC_double K;
  for (const char* bad : {"01", "-01", "1.", ".5", "+1", "-", "1e", "1.e3", "00"}) {
    const std::string text = std::string("[[0, 0],\n[1, ") + bad + "]]";
    const std::string m = expect_parse_error([&] { fair::io::parse_points_json<K>(text, "s.json"); }, "s.json", 2);
    EXPECT_TRUE(m.find("is not a JSON number") != std::string::npos || m.find("is not a number") != std::string::npos ||
                m.find("trailing garbage") != std::string::npos)
        << bad << ": " << m;
  }
  for (const char* good : {"0", "-0", "-0.5e-3", "1E+2", "12.25", "1e-320"}) {
    const auto f = fair::io::parse_points_json<K>(std::string("[[0, 0], [1, ") + good + "]]", "g.json");
    EXPECT_EQ(f.points[1].y(), fair::io::parse_decimal(good, "g", 1, "y")) << good;
  }
  // The looser grammar stays available inside strings.
  EXPECT_EQ(fair::io::parse_points_json<K>("[[0, 0], [\"+1\", \".5\"]]", "q.json").points[1], K::Point_2(1, 0.5));
  // Two "points": refused at the second, not the first used silently.
  const std::string dup = expect_parse_error(
      [] { fair::io::parse_points_json<K>("{\"points\": [[0, 0], [1, 1]],\n\"points\": [[5, 5], [6, 6]]}", "d.json"); },
      "d.json", 2);
  EXPECT_NE(dup.find("duplicate member \"points\""), std::string::npos) << dup;
  // Nested objects have their own names.
  EXPECT_EQ(fair::io::parse_json("{\"a\": {\"k\": 1}, \"b\": {\"k\": 2}}", "n.json").members.size(), 2u);
  // A byte-order mark, named: JSON, point CSV and number files.
  const std::string bom = "\xEF\xBB\xBF";
  for (const std::string& m :
       {expect_parse_error([&] { fair::io::parse_points_json<K>(bom + "[[0, 0], [1, 1]]", "b.json"); }, "b.json", 1),
        expect_parse_error([&] { fair::io::parse_points_csv<K>(bom + "0, 0\n1, 1\n", "b.csv"); }, "b.csv", 1),
        expect_parse_error([&] { fair::io::parse_tensions(bom + "1\n", "b.txt"); }, "b.txt", 1)})
    EXPECT_NE(m.find("byte-order mark"), std::string::npos) << m;
}

// The public JSON reader of fair/io/parsing.h: kinds, lines, texts and members.
TEST(IoJson, ParseJsonKeepsKindsAndLines) {
  using fair::io::Json_value;
  const Json_value root = fair::io::parse_json(
      "{\"a\": [1.5,\n \"x\", true],\n \"b\": null,\n\n \"c\": {\"d\": \"2/3\"}}", "j.json");
  ASSERT_EQ(root.kind, Json_value::OBJECT);
  EXPECT_EQ(root.line, 1u);
  ASSERT_EQ(root.members.size(), 3u);
  const Json_value* a = root.find("a");
  ASSERT_NE(a, nullptr);
  ASSERT_EQ(a->kind, Json_value::ARRAY);
  ASSERT_EQ(a->items.size(), 3u);
  EXPECT_EQ(a->items[0].kind, Json_value::NUMBER);
  EXPECT_EQ(a->items[0].text, "1.5");
  EXPECT_EQ(a->items[1].kind, Json_value::STRING);
  EXPECT_EQ(a->items[1].line, 2u);
  EXPECT_EQ(a->items[2].kind, Json_value::BOOLEAN);
  EXPECT_TRUE(a->items[2].flag);
  EXPECT_EQ(root.find("b")->kind, Json_value::NULL_VALUE);
  EXPECT_EQ(root.find("b")->line, 3u);
  const Json_value* d = root.find("c")->find("d");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->line, 5u);
  EXPECT_EQ(fair::io::to_ft<CGAL::Gmpq>(fair::io::parse_number(d->text, "j.json", d->line, "d")), CGAL::Gmpq(2, 3));
  EXPECT_EQ(root.find("missing"), nullptr);
  EXPECT_STREQ(Json_value::kind_name(Json_value::OBJECT), "an object");
  expect_parse_error([&] { fair::io::parse_json("[1,\n2,\n nan]", "n.json"); }, "n.json", 3);
}

TEST(IoFiles, MissingFileAndDirectory) {
  const std::string missing = data_dir + "does_not_exist.csv";
  const std::string msg = expect_parse_error([&] { fair::io::read_points<SC_double>(missing); }, missing, 0);
  EXPECT_NE(msg.find("cannot open"), std::string::npos) << msg;
  expect_parse_error([&] { fair::io::read_points<SC_double>(data_dir); }, data_dir, 0);
  expect_parse_error([&] { fair::io::read_text_file(missing); }, missing, 0);
  EXPECT_NE(fair::io::read_text_file(data_dir + "good.csv").find("0,0"), std::string::npos);
}

TEST(IoFiles, CheckPointFileNamesTheLineOfARepeatedPoint) {
  typedef SC_double K;
  const auto f = fair::io::parse_points_csv<K>("# c\n0,0\n\n1,0\n1,1\n0,0\n", "c.csv");
  EXPECT_NO_THROW(fair::io::check_point_file(f, 4, false, "m"));
  // Closed: the last point (line 6) and the first (line 2) coincide; the error names line 2.
  const std::string msg = expect_parse_error([&] { fair::io::check_point_file(f, 3, true, "m"); }, "c.csv", 2);
  EXPECT_NE(msg.find("line 6"), std::string::npos) << msg;
  expect_parse_error([&] { fair::io::check_point_file(f, 5, false, "m"); }, "c.csv", 0);
}

// ------------------------------------------------------------------ writers

// A rational quadratic piece in standard form, only for the writer test (the library's
// Rational_quadratic_bezier_2 has its own tests).
struct Weighted_piece {
  typedef SC_double Kernel;
  typedef double FT;
  typedef Kernel::Point_2 Point_2;
  std::vector<Point_2> cps;
  double w;
  std::vector<Point_2> control_points() const { return cps; }
  double weight() const { return w; }
};

TEST(IoWriters, CurveJsonHasControlPointsWeightsAndExtras) {
  typedef SC_double K;
  typedef K::Point_2 P;
  std::vector<fair::Bezier_2<K>> curve = {fair::Bezier_2<K>(std::vector<P>{P(0, 0), P(1, 2), P(3, 2), P(4, 0)}),
                                          fair::Bezier_2<K>(std::vector<P>{P(4, 0), P(5, -2), P(7, 1)})};
  nlohmann::json extra = {{"method", "test"}, {"parameters", {{"alpha", 0.5}}}};
  const nlohmann::json j = fair::io::curve_to_json(curve, extra);
  EXPECT_EQ(j["format"], "fair-curve");
  ASSERT_EQ(j["pieces"].size(), 2u);
  EXPECT_EQ(j["pieces"][0]["degree"], 3);
  EXPECT_EQ(j["pieces"][1]["degree"], 2);
  EXPECT_EQ(j["pieces"][1]["control_points"][2], nlohmann::json::array({7.0, 1.0}));
  EXPECT_FALSE(j["pieces"][0].contains("weights"));
  EXPECT_EQ(j["method"], "test");
  EXPECT_EQ(j["parameters"]["alpha"], 0.5);
  EXPECT_THROW(fair::io::curve_to_json(curve, nlohmann::json{{"pieces", 1}}), fair::Precondition_error);
  EXPECT_THROW(fair::io::curve_to_json(curve, nlohmann::json::array()), fair::Precondition_error);

  std::vector<Weighted_piece> conic = {Weighted_piece{{P(1, 0), P(1, 1), P(0, 1)}, std::sqrt(0.5)}};
  const nlohmann::json c = fair::io::curve_to_json(conic);
  EXPECT_EQ(c["pieces"][0]["weights"], nlohmann::json::array({1, std::sqrt(0.5), 1}));
  // The written text reads back to the same double weight.
  const nlohmann::json again = nlohmann::json::parse(c.dump());
  EXPECT_EQ(again["pieces"][0]["weights"][1].get<double>(), std::sqrt(0.5));
}

TEST(IoWriters, NeverWriteNonFiniteNumbers) {
  typedef SC_double K;
  typedef K::Point_2 P;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(fair::io::points_to_json(std::vector<P>{P(0, 0), P(nan, 1)}), fair::Precondition_error);
  std::ostringstream out;
  EXPECT_THROW(fair::io::write_points_csv(out, std::vector<P>{P(inf, 0)}), fair::Precondition_error);
  EXPECT_TRUE(out.str().empty());
  std::vector<Weighted_piece> bad = {Weighted_piece{{P(1, 0), P(1, 1), P(0, 1)}, nan}};
  EXPECT_THROW(fair::io::curve_to_json(bad), fair::Precondition_error);
  nlohmann::json j = {{"a", {1.0, 2.0}}, {"b", {{"c", -inf}}}};
  try {
    fair::io::write_json(out, j);
    FAIL() << "wrote a non-finite number";
  } catch (const fair::Precondition_error& e) {
    EXPECT_NE(std::string(e.what()).find("$.b.c"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(out.str().empty());
  EXPECT_THROW(fair::io::write_json_file("/nonexistent-dir/x.json", nlohmann::json::object()), fair::Error);
}


TEST(IoWriters, NumberTextIsExact) {
  // Exact rationals: lowest terms, sign on the numerator, integers without "/1".
  EXPECT_EQ(fair::io::number_text(CGAL::Gmpq(18384, 24482)), "9192/12241"); // Li's alpha*, data set 1
  EXPECT_EQ(fair::io::number_text(CGAL::Gmpq(-6, 4)), "-3/2");
  EXPECT_EQ(fair::io::number_text(CGAL::Gmpq(12, 4)), "3");
  EXPECT_EQ(fair::io::number_text(CGAL::Gmpq(0)), "0");
  // EPECK's lazy number: the exact value, also after arithmetic (1/3 is not a double).
  typedef CGAL::Exact_predicates_exact_constructions_kernel::FT Lazy;
  EXPECT_EQ(fair::io::number_text(Lazy(1) / Lazy(3)), "1/3");
  EXPECT_EQ(fair::io::number_text(Lazy(9192) / Lazy(12241) * Lazy(2)), "18384/12241");
  // Doubles: 17 significant digits, which read back as the same double.
  for (double d : {0.1, -2.5, 1e-300, 123456789.125, 1.0 / 3.0}) {
    const std::string text = fair::io::number_text(d);
    EXPECT_EQ(std::stod(text), d) << text;
  }
  EXPECT_EQ(fair::io::number_text(-2.5), "-2.5");
  EXPECT_THROW(fair::io::number_text(std::numeric_limits<double>::quiet_NaN(), "alpha"), fair::Precondition_error);
  EXPECT_THROW(fair::io::number_text(std::numeric_limits<double>::infinity()), fair::Precondition_error);
}

// ------------------------------------------------------------------ number files

// Every number file reads the numbers of a point file: decimals, exact p/q, '+', ".5", blanks or
// commas, comments, CRLF; and refuses the same bad numbers at their line.
TEST(IoNumberFiles, TensionsAcceptTheGrammarOfPointFiles) {
  const std::vector<double> t =
      fair::io::parse_tensions("# mu per point\n1\n1/2   # half\r\n\n+.5\n3/4\n2e0\n", "t.txt", 5);
  EXPECT_EQ(t, (std::vector<double>{1, 0.5, 0.5, 0.75, 2}));
  EXPECT_EQ(fair::io::parse_tensions("7/3\n", "t.txt", 0), std::vector<double>{7.0 / 3.0});  // correctly rounded
  // Malformed, wrong count, NaN, inf, <= 0: Parse_error at the line (0: the whole file).
  const Parse_case bad[] = {{"1\nabc\n1\n", 2},    {"1\n1 2\n1\n", 2},   {"1\nnan\n1\n", 2},
                            {"1\n1\n-inf\n", 3},   {"1\n0\n1\n", 2},     {"1\n-1/2\n1\n", 2},
                            {"1\n1/0\n1\n", 2},    {"1\n0x10\n1\n", 2},  {"1\n1e999\n1\n", 2},
                            {"1\n1\n", 0},          {"1\n1\n1\n1\n", 0}, {"# nothing\n", 0},
                            {"1\n2,\n1\n", 2},     {"1\n1\x01\n1\n", 2}};
  for (const Parse_case& c : bad)
    expect_parse_error([&] { fair::io::parse_tensions(c.text, "t.txt", 3); }, "t.txt", c.line);
  EXPECT_NE(expect_parse_error([&] { fair::io::parse_tensions("1\nNaN\n1\n", "t.txt", 3); }, "t.txt", 2).find("NaN"),
            std::string::npos);
  EXPECT_NE(expect_parse_error([&] { fair::io::parse_tensions("1\n1\n", "t.txt", 3); }, "t.txt", 0)
                .find("3 lines, got 2"),
            std::string::npos);
  expect_parse_error([] { fair::io::read_tensions(data_dir + "no-such-tension-file.txt", 3); },
                     data_dir + "no-such-tension-file.txt", 0);
}

TEST(IoNumberFiles, SegmentLambdasInTheUnitIntervalOnePerSegment) {
  EXPECT_EQ(fair::io::parse_segment_lambdas("0\n 1/4 \n1\n", "l.txt", 3), (std::vector<double>{0, 0.25, 1}));
  const Parse_case bad[] = {{"0\n5/4\n1\n", 2}, {"0\n-1/4\n1\n", 2}, {"0\ninf\n1\n", 2},
                            {"0\nnan\n1\n", 2}, {"0\n0.5 0.5\n1\n", 2}, {"0\nhalf\n1\n", 2},
                            {"0\n1\n", 0},       {"0\n0\n0\n0\n", 0}};
  for (const Parse_case& c : bad)
    expect_parse_error([&] { fair::io::parse_segment_lambdas(c.text, "l.txt", 3); }, "l.txt", c.line);
}

TEST(IoNumberFiles, ConstraintsWithExactNumbersIndicesAndDuplicates) {
  using fair::Point_constraint_kind;
  const fair::io::Constraint_file t =
      fair::io::parse_constraints("# i tx ty\n0 1/2 1\n\n4, -3/4, +2\n", "t.txt", Point_constraint_kind::TANGENT, 5);
  ASSERT_EQ(t.constraints.size(), 2u);
  EXPECT_EQ(t.lines, (std::vector<std::size_t>{2, 4}));
  EXPECT_EQ(t.constraints[0].index, 0u);
  EXPECT_EQ(t.constraints[0].direction[0], 0.5);
  EXPECT_EQ(t.constraints[1].index, 4u);
  EXPECT_EQ(t.constraints[1].direction[0], -0.75);
  EXPECT_EQ(t.constraints[1].direction[1], 2.0);
  EXPECT_EQ(t.constraints[1].kind, Point_constraint_kind::TANGENT);
  const fair::io::Constraint_file c =
      fair::io::parse_constraints("2 1 0 0 1\n", "c.txt", Point_constraint_kind::CORNER, 5);
  ASSERT_EQ(c.constraints.size(), 1u);
  EXPECT_EQ(c.constraints[0].outgoing[1], 1.0);
  EXPECT_EQ(c.constraints[0].kind, Point_constraint_kind::CORNER);
  // An index is plain digits (issue 29 #17): numbers that equal an integer are not indices.
  EXPECT_EQ(fair::io::parse_constraints("4 1 0\n", "n.txt", Point_constraint_kind::NORMAL, 5).constraints[0].index, 4u);
  EXPECT_EQ(fair::io::parse_constraints("0 1 0\n", "n.txt", Point_constraint_kind::NORMAL, 5).constraints[0].index, 0u);
  for (const char* index : {"4/2", "1.0", "+1", "01", "1e0", "0x1p1", "-0"})
    expect_parse_error([&] { fair::io::parse_constraints(std::string(index) + " 1 0\n", "i.txt", Point_constraint_kind::NORMAL, 5); },
                       "i.txt", 1);
  // A subnormal direction component is a finite number.
  EXPECT_EQ(fair::io::parse_constraints("1 1 1e-320\n", "n.txt", Point_constraint_kind::TANGENT, 5).constraints[0].direction[1],
            1e-320);
  const Parse_case bad[] = {{"0 1 0\n1.5 1 0\n", 2}, {"0 1 0\n-1 1 0\n", 2},  {"0 1 0\n5 1 0\n", 2},
                            {"0 1 0\n1 0 0\n", 2},   {"0 1 0\n0 0 1\n", 2},   {"0 1 0\n1 nan 1\n", 2},
                            {"0 1 0\n1 1 inf\n", 2}, {"0 1 0\n1 1\n", 2},     {"0 1 0\n1 1 0 0\n", 2},
                            {"0 1 0\n1/2 1 0\n", 2}, {"0 1 0\n1 x 0\n", 2}};
  for (const Parse_case& b : bad)
    expect_parse_error([&] { fair::io::parse_constraints(b.text, "t.txt", Point_constraint_kind::TANGENT, 5); },
                       "t.txt", b.line);
  expect_parse_error([] { fair::io::parse_constraints("1 1 0 0 0\n", "c.txt", Point_constraint_kind::CORNER, 5); },
                     "c.txt", 1);  // zero outgoing tangent
  // One point constrained in two files: the second names the first.
  const fair::io::Constraint_file a = fair::io::parse_constraints("1 1 0\n", "a.txt", Point_constraint_kind::TANGENT, 5);
  const fair::io::Constraint_file b =
      fair::io::parse_constraints("3 0 1 1 0\n\n1 0 1 1 0\n", "b.txt", Point_constraint_kind::CORNER, 5);
  const std::string m = expect_parse_error([&] { fair::io::merge_constraint_files({a, b}); }, "b.txt", 3);
  EXPECT_NE(m.find("point 1 is already constrained (a.txt:1)"), std::string::npos) << m;
  EXPECT_EQ(fair::io::merge_constraint_files({a, c}).size(), 2u);
}

// ------------------------------------------------------------------ curve JSON

// curve_to_json writes what read_curve_json reads: exactly, "p/q" included, in an exact kernel.
TEST(IoCurveJson, RoundTripIsExactAndKeepsWeights) {
  typedef SC_gmpq K;
  typedef K::Point_2 P;
  typedef K::FT FT;
  const std::vector<P> points = {P(0, 0), P(FT(7, 3), 1)};
  std::vector<fair::Rational_bezier_2<K>> pieces = {
      fair::Rational_bezier_2<K>({P(0, 0), P(1, FT(1, 3)), P(FT(7, 3), 1)}, {FT(1), FT(2, 7), FT(1)}),
      fair::Rational_bezier_2<K>({P(FT(7, 3), 1), P(3, 2), P(4, 2), P(5, FT(-1, 10))}, {FT(1), FT(1), FT(3), FT(1)})};
  std::vector<nlohmann::json> per_piece = {{{"point", 1}, {"t", 0.25}}, {{"point", 2}, {"t", 0.75}}};
  const nlohmann::json j = fair::io::curve_to_json("test", true, points, pieces, {{"status", "fine"}}, per_piece);
  EXPECT_EQ(j["method"], "test");
  EXPECT_EQ(j["closed"], true);
  EXPECT_EQ(j["points"][1][0], "7/3");
  EXPECT_EQ(j["status"], "fine");
  EXPECT_EQ(j["pieces"][0]["degree"], 2);
  EXPECT_EQ(j["pieces"][0]["weights"][1], "2/7");
  EXPECT_EQ(j["pieces"][1]["point"], 2);
  EXPECT_EQ(j["pieces"][1]["t"], 0.75);
  const fair::io::Curve_file<K> f = fair::io::parse_curve_json<K>(j.dump(2), "c.json");
  EXPECT_EQ(f.method, "test");
  EXPECT_TRUE(f.closed);
  EXPECT_TRUE(f.rational);
  ASSERT_EQ(f.pieces.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(f.pieces[i].control_points(), pieces[i].control_points());
    EXPECT_EQ(f.pieces[i].weights(), pieces[i].weights());
  }
  // A polynomial curve (no "weights"): unit weights, not rational.
  std::vector<fair::Bezier_2<K>> cubic = {fair::Bezier_2<K>(std::vector<P>{P(0, 0), P(FT(1, 3), 1), P(2, 1), P(3, 0)})};
  const fair::io::Curve_file<K> g = fair::io::parse_curve_json<K>(fair::io::curve_to_json(cubic).dump(), "p.json");
  EXPECT_FALSE(g.rational);
  EXPECT_EQ(g.polynomial_pieces()[0].control_points(), cubic[0].control_points());
  // The writer refuses a piece extra per piece of another count, or one that redefines a member.
  EXPECT_THROW(fair::io::curve_to_json("test", false, points, pieces, nlohmann::json::object(),
                                       std::vector<nlohmann::json>{per_piece[0]}),
               fair::Precondition_error);
  EXPECT_THROW(fair::io::curve_to_json("test", false, points, pieces, nlohmann::json::object(),
                                       std::vector<nlohmann::json>{nlohmann::json{{"degree", 1}}, nlohmann::json{{"t", 1}}}),
               fair::Precondition_error);
  EXPECT_THROW(fair::io::curve_to_json("test", false, points, pieces, {{"method", "other"}}), fair::Precondition_error);
}

TEST(IoCurveJson, EveryMalformedCurveGivesParseErrorAtItsLine) {
  typedef SC_double K;
  const Parse_case bad[] = {
      {"x,y\n1,2\n", 1},                                           // a CSV
      {"[1, 2]", 1},                                                 // not an object
      {"{\"points\": [[0, 0]]}", 1},                                // no pieces
      {"{\n\"pieces\": []}", 2},                                    // empty
      {"{\"pieces\": [\n3]}", 2},                                   // a piece that is not an object
      {"{\"pieces\": [\n{\"degree\": 1}]}", 2},                     // no control points
      {"{\"pieces\": [{\"control_points\": [\n[0]]}]}", 2},          // not a pair
      {"{\"pieces\": [{\"control_points\": [[0, 0], [1,\n\"NaN\"]]}]}", 2},
      {"{\"pieces\": [{\"control_points\": [[0, 0], [1,\n\"1/0\"]]}]}", 2},
      {"{\"pieces\": [{\"control_points\": [[0, 0], [1, 1]],\n\"degree\": 2}]}", 2},
      {"{\"pieces\": [{\"control_points\": [[0, 0], [1, 1]],\n\"weights\": [1]}]}", 2},
      {"{\"pieces\": [{\"control_points\": [[0, 0], [1, 1]], \"weights\": [1,\n0]}]}", 2},
      {"{\"pieces\": [{\"control_points\": [[0, 0], [1, 1]], \"weights\": [1,\n\"-1/2\"]}]}", 2},
      {"{\"closed\":\n1, \"pieces\": [{\"control_points\": [[0, 0], [1, 1]]}]}", 2},
      {"", 0}};
  for (const Parse_case& c : bad) expect_parse_error([&] { fair::io::parse_curve_json<K>(c.text, "c.json"); }, "c.json", c.line);
  EXPECT_NE(expect_parse_error([] { fair::io::parse_curve_json<K>("x,y\n", "c.json"); }, "c.json", 1)
                .find("expected a curve JSON"),
            std::string::npos);
  expect_parse_error([] { fair::io::read_curve_json<K>(data_dir + "no-such-curve.json"); }, data_dir + "no-such-curve.json", 0);
}

// family_to_json writes what each family has, through the one writer of pieces: a curve with a
// report and a NURBS (nurbs(), as every family has) gets "status", "report" and
// "bspline" beside "method", "closed", "points" and "pieces".
struct Reporting_spline_curve {
  typedef SC_double K;
  fair::Cubic_spline_2<K> s;
  std::vector<K::Point_2> input;
  fair::Optimal_curve_report r;
  const std::vector<K::Point_2>& points() const { return input; }
  std::vector<fair::Bezier_2<K>> pieces() const { return s.polynomial_pieces(); }
  bool is_closed() const { return s.is_closed(); }
  const fair::Cubic_spline_2<K>& spline() const { return s; }
  fair::Nurbs_curve_2<K> nurbs() const { return s.nurbs(); }
  const fair::Optimal_curve_report& report() const { return r; }
};
struct Plain_curve {
  typedef SC_double K;
  std::vector<K::Point_2> input;
  std::vector<fair::Bezier_2<K>> p;
  const std::vector<K::Point_2>& points() const { return input; }
  const std::vector<fair::Bezier_2<K>>& pieces() const { return p; }
  bool is_closed() const { return false; }
};

TEST(IoCurveJson, FamilyToJsonWritesWhatTheFamilyHas) {
  typedef SC_double K;
  typedef K::Point_2 P;
  const std::vector<double> t = {0, 1, 3};
  const std::vector<P> d = {P(0, 0), P(1, 2), P(2, 2), P(3, 0), P(5, 1)};  // open: m + 3 control points
  Reporting_spline_curve c{fair::Cubic_spline_2<K>(t, d, false), {P(0, 0), P(5, 1)}, fair::Optimal_curve_report()};
  c.r.status = fair::Optimal_curve_status::CONVERGED;
  const nlohmann::json j = fair::io::family_to_json(c, "mock", {{"extra", 1}});
  EXPECT_EQ(j["method"], "mock");
  EXPECT_EQ(j["closed"], false);
  EXPECT_EQ(j["points"][1], nlohmann::json::array({5.0, 1.0}));
  EXPECT_EQ(j["status"], "converged");
  EXPECT_EQ(j["report"], fair::io::to_json(c.r));
  EXPECT_EQ(j["bspline"], fair::io::nurbs_to_json(c.s.nurbs()));
  EXPECT_EQ(j["extra"], 1);
  ASSERT_EQ(j["pieces"].size(), 2u);
  EXPECT_EQ(j["pieces"], fair::io::curve_to_json(c.pieces())["pieces"]);
  EXPECT_THROW(fair::io::family_to_json(c, "mock", {{"report", 1}}), fair::Precondition_error);
  const Plain_curve plain{{P(0, 0), P(1, 1)}, {fair::Bezier_2<K>(std::vector<P>{P(0, 0), P(1, 1)})}};
  const nlohmann::json k = fair::io::family_to_json(plain, "plain");
  EXPECT_FALSE(k.contains("status"));
  EXPECT_FALSE(k.contains("report"));
  EXPECT_FALSE(k.contains("bspline"));
  EXPECT_EQ(k["pieces"][0]["degree"], 1);
}

// ------------------------------------------------------------------ reports and spellings

TEST(IoReports, KappaAndOptimalReportsSerialiseEveryMember) {
  fair::Kappa_curve_report k;
  k.status = fair::Kappa_curve_status::ON_JOINS;
  k.iterations = 12;
  k.residual = 1e-13;
  k.energy_g2 = 0.25;
  k.energy_weight = 0.5;
  k.points_on_joins = {0, 7};
  k.worst_points = {fair::Kappa_point_residual{3, 0.125}};
  const nlohmann::json kj = fair::io::to_json(k);
  EXPECT_EQ(kj["status"], "on_joins");
  EXPECT_EQ(kj["iterations"], 12);
  EXPECT_EQ(kj["residuals"]["max"], 1e-13);
  EXPECT_EQ(kj["energy"]["total"], 0.75);
  EXPECT_EQ(kj["points_on_joins"], nlohmann::json::array({0, 7}));
  EXPECT_EQ(kj["worst_points"][0]["point"], 3);
  EXPECT_EQ(kj["worst_points"][0]["residual"], 0.125);
  EXPECT_TRUE(kj["points_at_minima"].is_array());
  fair::Optimal_curve_report o;
  o.status = fair::Optimal_curve_status::DIVERGING;
  o.energy = 2.5;
  o.levels = {fair::Optimal_curve_level{5, 3, 3.5, 1e-9, fair::Optimal_curve_status::CONVERGED},
              fair::Optimal_curve_level{9, 40, 2.5, 1e3, fair::Optimal_curve_status::DIVERGING}};
  const nlohmann::json oj = fair::io::to_json(o);
  EXPECT_EQ(oj["status"], "diverging");
  EXPECT_EQ(oj["energy"], 2.5);
  ASSERT_EQ(oj["levels"].size(), 2u);
  EXPECT_EQ(oj["levels"][0]["status"], "converged");
  EXPECT_EQ(oj["levels"][1]["vertices"], 9);
  // A default report is written too (every member initialised), and never with a NaN.
  std::ostringstream out;
  fair::io::write_json(out, fair::io::to_json(fair::Kappa_curve_report()));
  fair::io::write_json(out, fair::io::to_json(fair::Optimal_curve_report()));
  EXPECT_NE(out.str().find("\"unsolved\""), std::string::npos);
  EXPECT_NE(out.str().find("\"capped\""), std::string::npos);
  // Cardinal: exact numbers as "p/q" (alpha* of data set 1 of [Li]), doubles as numbers.
  fair::Cardinal_spline_report<SC_gmpq> c;
  c.status = fair::Cardinal_spline_status::OPTIMAL;
  c.alpha = CGAL::Gmpq(9192, 12241);
  c.aux_start = SC_gmpq::Point_2(CGAL::Gmpq(1, 3), 2);
  c.energy = CGAL::Gmpq(5, 2);
  const nlohmann::json cj = fair::io::to_json(c);
  EXPECT_EQ(cj["status"], "optimal");
  EXPECT_EQ(cj["alpha"], "9192/12241");
  EXPECT_EQ(cj["aux_start"], nlohmann::json::array({"1/3", 2.0}));
  EXPECT_EQ(cj["aux_end"], nlohmann::json::array({0.0, 0.0}));
  EXPECT_EQ(cj["energy"], 2.5);
  fair::Cardinal_spline_report<SC_double> d;
  EXPECT_EQ(fair::io::to_json(d)["status"], "no_optimum");
  EXPECT_EQ(fair::io::to_json(d)["alpha"], 0.5);
}

// Each spelling table reads back what it writes, agrees with the library's to_string where the
// library spells the enum, and refuses anything else with the list of spellings.
template <class Enum>
void expect_spellings_round_trip(std::size_t count) {
  const auto& table = fair::io::Enum_spellings<Enum>::table();
  EXPECT_EQ(table.size(), count);
  for (const auto& e : table) {
    EXPECT_EQ(fair::io::parse_spelling<Enum>(fair::io::spelling(e.first)), e.first);
    Enum v{};
    EXPECT_TRUE(fair::io::try_parse_spelling(std::string(e.second), v));
    EXPECT_EQ(v, e.first);
  }
  Enum v{};
  EXPECT_FALSE(fair::io::try_parse_spelling(std::string("no such spelling"), v));
  try {
    fair::io::parse_spelling<Enum>("Chordal ", "option");
    FAIL() << "accepted a wrong spelling";
  } catch (const fair::Invalid_input_error& e) {
    EXPECT_EQ(std::string(e.what()), "option: expected " + fair::io::spellings_list<Enum>() + ", got 'Chordal '");
  }
}

TEST(IoSpellings, EveryTableRoundTrips) {
  expect_spellings_round_trip<fair::Knot_spacing>(3);
  expect_spellings_round_trip<fair::Kappa_weights>(3);
  expect_spellings_round_trip<fair::Kappa_curve_status>(3);
  expect_spellings_round_trip<fair::Optimal_curve_solver>(2);
  expect_spellings_round_trip<fair::Curvature_discretisation>(3);
  expect_spellings_round_trip<fair::Point_constraint_kind>(3);
  expect_spellings_round_trip<fair::Optimal_curve_status>(3);
  expect_spellings_round_trip<fair::Cardinal_spline_status>(3);
  for (fair::Knot_spacing k : {fair::Knot_spacing::UNIFORM, fair::Knot_spacing::CENTRIPETAL, fair::Knot_spacing::CHORDAL})
    EXPECT_STREQ(fair::io::spelling(k), fair::to_string(k));
  for (fair::Kappa_curve_status k :
       {fair::Kappa_curve_status::INTERIOR, fair::Kappa_curve_status::ON_JOINS, fair::Kappa_curve_status::UNSOLVED})
    EXPECT_STREQ(fair::io::spelling(k), fair::to_string(k));
  EXPECT_EQ(fair::io::spellings_list<fair::Knot_spacing>(), "uniform, centripetal or chordal");
  EXPECT_EQ(fair::io::spellings_list<fair::Optimal_curve_solver>(), "newton or cg");
  EXPECT_THROW(fair::io::spelling(static_cast<fair::Knot_spacing>(17)), fair::Precondition_error);
}

} // namespace
