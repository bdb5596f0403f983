// Helpers shared by the test executables: the four kernels of the typed tests, exact/approximate
// comparison of numbers and points, and seeded random data. Header-only, test code only.

#ifndef FAIR_TEST_SUPPORT_H
#define FAIR_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <type_traits>
#include <vector>

namespace fair_test {

// The kernels of the typed tests: floating point (plain and with exact predicates) and exact
// (lazy exact and plain rational).
typedef CGAL::Simple_cartesian<double> SC_double;
typedef CGAL::Exact_predicates_inexact_constructions_kernel EPICK;
typedef CGAL::Exact_predicates_exact_constructions_kernel EPECK;
typedef CGAL::Simple_cartesian<CGAL::Gmpq> SC_gmpq;
typedef ::testing::Types<SC_double, EPICK, EPECK, SC_gmpq> All_kernels;

// True for the kernels whose number type is exact (EPECK, SC_gmpq).
template <class K>
constexpr bool is_exact() {
  return CGAL::Algebraic_structure_traits<typename K::FT>::Is_exact::value &&
         !std::is_floating_point<typename K::FT>::value;
}

// a == b exactly in an exact kernel, to a relative 1e-11 otherwise.
template <class K>
void expect_equal(const typename K::FT& a, const typename K::FT& b, const char* what) {
  if (is_exact<K>()) {
    EXPECT_TRUE(a == b) << what << ": " << CGAL::to_double(a) << " != " << CGAL::to_double(b);
  } else {
    const double x = CGAL::to_double(a), y = CGAL::to_double(b);
    EXPECT_NEAR(x, y, 1e-11 * (1 + std::max(std::fabs(x), std::fabs(y)))) << what;
  }
}

// expect_equal on both coordinates of two points (or vectors).
template <class K, class P>
void expect_equal_xy(const P& a, const P& b, const char* what) {
  expect_equal<K>(a.x(), b.x(), what);
  expect_equal<K>(a.y(), b.y(), what);
}

// Points (or vectors) equal exactly in an exact kernel, and in a floating-point kernel each
// coordinate to tol * (1 + |coordinate of a|).
template <class K, class T>
void expect_same(const T& a, const T& b, double tol = 1e-12) {
  if (is_exact<K>()) {
    EXPECT_TRUE(a == b) << a << " vs " << b;
  } else {
    EXPECT_NEAR(CGAL::to_double(a.x()), CGAL::to_double(b.x()), tol * (1 + std::fabs(CGAL::to_double(a.x()))));
    EXPECT_NEAR(CGAL::to_double(a.y()), CGAL::to_double(b.y()), tol * (1 + std::fabs(CGAL::to_double(a.y()))));
  }
}

// n random points with coordinates k/8, |k| <= 800: exactly representable in double, so every
// kernel sees the same data. Consecutive points are distinct, and so are the last and the first.
template <class K>
std::vector<typename K::Point_2> random_points(std::mt19937& rng, std::size_t n) {
  std::uniform_int_distribution<int> d(-800, 800);
  std::vector<typename K::Point_2> p;
  while (p.size() < n) {
    typename K::Point_2 q(typename K::FT(d(rng)) / 8, typename K::FT(d(rng)) / 8);
    if (!p.empty() && (q == p.back() || (p.size() + 1 == n && q == p.front()))) continue;
    p.push_back(q);
  }
  return p;
}

// The FT value n/d (exact in exact kernels).
template <class K>
typename K::FT q(int n, int d = 1) {
  return typename K::FT(n) / typename K::FT(d);
}

// a == b exactly in an exact kernel, |a - b| <= rel (1 + |b|) in a floating kernel.
template <class K>
::testing::AssertionResult same(const typename K::FT& a, const typename K::FT& b, double rel = 1e-13) {
  const double x = CGAL::to_double(a), y = CGAL::to_double(b);
  if (is_exact<K>()) {
    if (a == b) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << x << " != " << y << " (exact)";
  }
  if (std::fabs(x - y) <= rel * (1.0 + std::fabs(y))) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << x << " vs " << y << " differ by " << std::fabs(x - y);
}

} // namespace fair_test

#endif // FAIR_TEST_SUPPORT_H
