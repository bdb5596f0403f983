// Helpers shared by the test executables: the four kernels of the typed tests, exact/approximate
// comparison of numbers and points, and seeded random data. Header-only, test code only.

#ifndef FAIR_TEST_SUPPORT_H
#define FAIR_TEST_SUPPORT_H

#include <fair/Errors.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace fair_test {

/// pi to double precision, for the tests' circles and angles (one definition: sources that share
/// a unity translation unit must not define it twice).
constexpr double pi = 3.14159265358979323846;

// The kernels of the typed tests: floating point (plain and with exact predicates) and exact
// (lazy exact and plain rational).
typedef CGAL::Simple_cartesian<double> SC_double;
typedef CGAL::Exact_predicates_inexact_constructions_kernel EPICK;
typedef CGAL::Exact_predicates_exact_constructions_kernel EPECK;
typedef CGAL::Simple_cartesian<CGAL::Gmpq> SC_gmpq;
#ifdef FAIR_TEST_KERNEL_SUBSET
// The sanitizer stage (`tools/bootstrap.sh sanitize`, FAIR_SANITIZE=ON) instantiates every typed
// test on one floating and one exact kernel. Memory errors and undefined behaviour belong to code
// paths, and the library's paths split by exactness: SC_double and EPICK share the double FT,
// EPECK and SC_gmpq the exact branch. The release stage runs the full matrix; this halves the
// sanitizer build, the longest part of CI.
typedef ::testing::Types<SC_double, EPECK> All_kernels;
typedef ::testing::Types<SC_double> Floating_kernels;
typedef ::testing::Types<EPECK> Exact_kernels;
#elif defined(FAIR_TEST_NO_EPICK)
// Release-stage suites whose code never reaches a kernel predicate (set per test executable in
// test/CMakeLists.txt): EPICK is SC_double there, instruction for instruction (see there).
typedef ::testing::Types<SC_double, EPECK, SC_gmpq> All_kernels;
typedef ::testing::Types<SC_double> Floating_kernels;
typedef ::testing::Types<EPECK, SC_gmpq> Exact_kernels;
#else
typedef ::testing::Types<SC_double, EPICK, EPECK, SC_gmpq> All_kernels;
typedef ::testing::Types<SC_double, EPICK> Floating_kernels;
typedef ::testing::Types<EPECK, SC_gmpq> Exact_kernels;
#endif

#ifdef FAIR_TEST_KERNEL_SUBSET
// The sanitizer stage runs every real_data_stride-th curve of the long real-data suites, with
// the same per-curve expectations; the release stage runs them all, and checks the statistics
// over the whole set (medians, maxima), which a subset cannot.
constexpr std::size_t real_data_stride = 3;
#else
constexpr std::size_t real_data_stride = 1;
#endif

// True for the kernels whose number type is exact (EPECK, SC_gmpq).
template <class K>
constexpr bool is_exact() {
  return CGAL::Algebraic_structure_traits<typename K::FT>::Is_exact::value &&
         !std::is_floating_point<typename K::FT>::value;
}

// The one comparison of the tests. same<K>(a, b, rel): a == b exactly in an exact kernel; in a
// floating-point kernel |a - b| <= rel (1 + max(|a|, |b|)) -- for numbers, and for points and
// vectors coordinate by coordinate. The tolerance is visible at every call site that needs
// another than the default.
inline ::testing::AssertionResult same_double(double x, double y, double rel) {
  if (std::fabs(x - y) <= rel * (1.0 + std::max(std::fabs(x), std::fabs(y)))) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << x << " vs " << y << " differ by " << std::fabs(x - y) << " (rel " << rel << ")";
}

// Numbers: any arguments convertible to FT (int, double, CGAL expression results).
template <class K>
::testing::AssertionResult same(const typename K::FT& a, const typename K::FT& b, double rel = 1e-12) {
  if (is_exact<K>()) {
    if (a == b) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << CGAL::to_double(a) << " != " << CGAL::to_double(b) << " (exact)";
  }
  return same_double(CGAL::to_double(a), CGAL::to_double(b), rel);
}

// Points and vectors: coordinate by coordinate.
template <class K, class T, class = std::enable_if_t<!std::is_convertible<T, typename K::FT>::value>>
::testing::AssertionResult same(const T& a, const T& b, double rel = 1e-12) {
  if (is_exact<K>()) {
    if (a == b) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << a << " != " << b << " (exact)";
  }
  ::testing::AssertionResult x = same_double(CGAL::to_double(a.x()), CGAL::to_double(b.x()), rel);
  if (!x) return x << " in x of " << a << " vs " << b;
  ::testing::AssertionResult y = same_double(CGAL::to_double(a.y()), CGAL::to_double(b.y()), rel);
  if (!y) return y << " in y of " << a << " vs " << b;
  return ::testing::AssertionSuccess();
}

// The ULP variant: two doubles at most `ulps` units in the last place apart (for results that
// must be correctly rounded or nearly so, where a relative tolerance would hide a lost bit).
inline ::testing::AssertionResult same_ulps(double a, double b, double ulps) {
  if (a == b) return ::testing::AssertionSuccess();
  if (!std::isfinite(a) || !std::isfinite(b)) return ::testing::AssertionFailure() << a << " vs " << b;
  const double ulp = std::nextafter(std::max(std::fabs(a), std::fabs(b)), HUGE_VAL) - std::max(std::fabs(a), std::fabs(b));
  if (std::fabs(a - b) <= ulps * ulp) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " vs " << b << " are " << std::fabs(a - b) / ulp << " ulps apart (max " << ulps << ")";
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

// The message of the fair::Invalid_input_error that f() throws ("no Invalid_input_error" if it
// throws none), for tests that check what a typed error names.
template <class F>
std::string invalid_input_message(F f) {
  try {
    f();
  } catch (const fair::Invalid_input_error& e) {
    return e.what();
  }
  return "no Invalid_input_error";
}

/// Dense Gaussian elimination with partial pivoting, for the small dense oracles of the tests
/// (e.g. the KKT systems of the smoothing splines, symmetric indefinite, n <= ~200): O(n^3).
inline std::vector<double> dense_solve(std::vector<std::vector<double>> a, std::vector<double> b) {
  const std::size_t n = b.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
    std::swap(a[c], a[p]);
    std::swap(b[c], b[p]);
    for (std::size_t r = c + 1; r < n; ++r) {
      const double f = a[r][c] / a[c][c];
      if (f == 0) continue;
      for (std::size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
      b[r] -= f * b[c];
    }
  }
  std::vector<double> x(n);
  for (std::size_t r = n; r-- > 0;) {
    double s = b[r];
    for (std::size_t k = r + 1; k < n; ++k) s -= a[r][k] * x[k];
    x[r] = s / a[r][r];
  }
  return x;
}

} // namespace fair_test

#endif // FAIR_TEST_SUPPORT_H
