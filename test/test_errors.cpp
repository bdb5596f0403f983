#include <fair/Errors.h>
#include <gtest/gtest.h>

#include "test_support.h"

#include <cmath>
#include <limits>
#include <string>

TEST(Errors, ParseErrorNamesFileAndLine) {
  fair::Parse_error e("points.csv", 7, "expected two numbers, got 'abc'");
  EXPECT_STREQ(e.what(), "points.csv:7: expected two numbers, got 'abc'");
  EXPECT_EQ(e.line(), 7u);
  EXPECT_EQ(e.file(), "points.csv");
  fair::Parse_error whole("missing.csv", 0, "cannot open file");
  EXPECT_STREQ(whole.what(), "missing.csv: cannot open file");
}

TEST(Errors, RequireThrowsPreconditionErrorWithValues) {
  EXPECT_NO_THROW(fair::internal::require(true, "never"));
  try {
    fair::internal::require(false, "weight must be > 0, got w = ", -0.5);
    FAIL() << "require(false) did not throw";
  } catch (const fair::Precondition_error& e) {
    EXPECT_STREQ(e.what(), "weight must be > 0, got w = -0.5");
  }
}

TEST(Errors, HierarchyIsCatchableAsFairError) {
  EXPECT_THROW(throw fair::Parse_error("f", 1, "x"), fair::Invalid_input_error);
  EXPECT_THROW(throw fair::Non_convergence_error("no", 10, 1e-3), fair::Error);
  fair::Non_convergence_error n("no", 10, 1e-3);
  EXPECT_EQ(n.iterations(), 10u);
  EXPECT_DOUBLE_EQ(n.residual(), 1e-3);
}

// Solve_error carries the report of any family (std::any inside): the type it was given comes
// back by pointer, equal to the original; any other type gives nullptr.
TEST(Errors, SolveErrorCarriesItsReport) {
  struct Report_a {
    int status = 0;
    double energy = 0;
  };
  struct Report_b {
    int iterations = 0;
  };
  const Report_a a{2, 0.25};
  const fair::Solve_error e("solve failed", a);
  EXPECT_STREQ(e.what(), "solve failed");
  ASSERT_NE(e.report<Report_a>(), nullptr);
  EXPECT_EQ(e.report<Report_a>()->status, 2);
  EXPECT_EQ(e.report<Report_a>()->energy, 0.25);
  EXPECT_EQ(e.report<Report_b>(), nullptr);
  EXPECT_EQ(e.report<int>(), nullptr);
  // A copy (what a catch by value makes) carries its own equal report.
  const fair::Solve_error copy = e;
  ASSERT_NE(copy.report<Report_a>(), nullptr);
  EXPECT_NE(copy.report<Report_a>(), e.report<Report_a>());
  EXPECT_EQ(copy.report<Report_a>()->energy, 0.25);
  EXPECT_THROW(throw fair::Solve_error("x", a), fair::Error);
}

TEST(Errors, AssertThrowsInternalErrorNamingExpressionFileAndLine) {
  EXPECT_NO_THROW(FAIR_ASSERT(1 + 1 == 2));
  const int line = __LINE__ + 2;
  try {
    FAIR_ASSERT_MSG(2 + 2 == 5, "sum = ", 4);
    FAIL() << "FAIR_ASSERT_MSG(false) did not throw";
  } catch (const fair::Precondition_error&) {
    FAIL() << "a broken invariant must not look like a caller's mistake";
  } catch (const fair::Internal_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("2 + 2 == 5 does not hold: sum = 4"), std::string::npos) << what;
    EXPECT_NE(what.find("test_errors.cpp:" + std::to_string(line)), std::string::npos) << what;
    EXPECT_EQ(e.line(), line);
  }
  EXPECT_THROW(FAIR_ASSERT(false), fair::Error);
}

// The test helpers' own contract (test_support.h): the ULP comparison counts units in the last
// place of the larger magnitude, and the relative comparison is exact in an exact kernel.
TEST(TestSupport, SameUlpsCountsUnitsInTheLastPlace) {
  const double one = 1.0, next = std::nextafter(1.0, 2.0), next2 = std::nextafter(next, 2.0);
  EXPECT_TRUE(fair_test::same_ulps(one, one, 0));
  EXPECT_TRUE(fair_test::same_ulps(one, next, 1));
  EXPECT_FALSE(fair_test::same_ulps(one, next2, 1));
  EXPECT_TRUE(fair_test::same_ulps(one, next2, 2));
  EXPECT_FALSE(fair_test::same_ulps(1.0, std::numeric_limits<double>::quiet_NaN(), 1e9));
  EXPECT_TRUE(fair_test::same<fair_test::SC_double>(1.0, 1.0 + 1e-13, 1e-12));
  EXPECT_FALSE(fair_test::same<fair_test::SC_gmpq>(1.0, 1.0 + 1e-13, 1e-3));  // exact kernel: equality only
}
