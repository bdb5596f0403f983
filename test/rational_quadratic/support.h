// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Shared helpers of the tests of fair::Rational_quadratic_bezier_2 (test/rational_quadratic/,
// one executable test_rational_quadratic): exact conic arcs with rational data (circles,
// ellipses, parabolas, hyperbolas), an independent exact eq.-7 evaluation, and the typed
// fixture over the four kernels.

#ifndef FAIR_TEST_RATIONAL_QUADRATIC_SUPPORT_H
#define FAIR_TEST_RATIONAL_QUADRATIC_SUPPORT_H

#include <fair/Rational_quadratic_bezier_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace rational_quadratic_test {

// The typed fixture over the four kernels. It lives outside the unnamed namespace: its tests are
// spread over several translation units, and googletest wants one fixture class per suite.
template <class K>
class Rational_quadratic_test : public ::testing::Test {};

} // namespace rational_quadratic_test

namespace {

using fair_test::is_exact;
using fair_test::q;
using fair_test::same;

typedef CGAL::Simple_cartesian<CGAL::Gmpq> Kq;

template <class K>
typename K::Point_2 pt(int xn, int xd, int yn, int yd) {
  return typename K::Point_2(q<K>(xn, xd), q<K>(yn, yd));
}

inline double dbl(const CGAL::Gmpq& x) { return CGAL::to_double(x); }

// A half angle beta with rational cos and sin: cos = c/d, sin = s/d (Pythagorean triple).
struct Half_angle {
  int c, s, d;
};
const Half_angle H0{1, 0, 1};      //   0 deg
const Half_angle H7{24, 7, 25};    //  16.26 deg
const Half_angle Hm7{24, -7, 25};  // -16.26 deg
const Half_angle H8{15, 8, 17};    //  28.07 deg
const Half_angle H3{4, 3, 5};      //  36.87 deg
const Half_angle H4{3, 4, 5};      //  53.13 deg
const Half_angle H15{8, 15, 17};   //  61.93 deg

// The arc of the unit circle from angle 2 beta0 to 2 beta2 (rational points: cos 2b = c^2 - s^2,
// sin 2b = 2 c s), P1 = (U0 + U2) / (1 + U0.U2) (tangent intersection), w = cos(beta2 - beta0),
// rational. With x_scale = 2 the arc of the ellipse x^2/4 + y^2 = 1 (the standard-form weight
// is affinely invariant).
template <class K>
fair::Rational_quadratic_bezier_2<K> circle_arc(Half_angle b0, Half_angle b2, int x_scale = 1) {
  typedef typename K::FT FT;
  const FT c0 = q<K>(b0.c, b0.d), s0 = q<K>(b0.s, b0.d), c2 = q<K>(b2.c, b2.d), s2 = q<K>(b2.s, b2.d);
  const FT u0x = c0 * c0 - s0 * s0, u0y = FT(2) * c0 * s0, u2x = c2 * c2 - s2 * s2, u2y = FT(2) * c2 * s2;
  const FT den = FT(1) + u0x * u2x + u0y * u2y;
  const FT w = c0 * c2 + s0 * s2;
  const FT sx(x_scale);
  return fair::Rational_quadratic_bezier_2<K>(typename K::Point_2(sx * u0x, u0y),
                                              typename K::Point_2(sx * (u0x + u2x) / den, (u0y + u2y) / den),
                                              typename K::Point_2(sx * u2x, u2y), w);
}

// The arc of y = x^2 from x = a to x = b: P1 = ((a+b)/2, ab), w = 1.
template <class K>
fair::Rational_quadratic_bezier_2<K> parabola_arc(int a, int b) {
  return fair::Rational_quadratic_bezier_2<K>(pt<K>(a, 1, a * a, 1), pt<K>(a + b, 2, a * b, 1),
                                              pt<K>(b, 1, b * b, 1), q<K>(1));
}

// The arc of xy = 1 from (a, 1/a) to (b, 1/b), a = an/ad, b = bn/bd with ab a rational square:
// P1 = (2ab/(a+b), 2/(a+b)), w = (a+b) / (2 sqrt(ab)) (derived from the factorisation
// x = (a(1-t) + b k t)^2 / D, y = ((1-t) + k t)^2 / D).
template <class K>
fair::Rational_quadratic_bezier_2<K> hyperbola_arc(int an, int ad, int bn, int bd, int sqrt_ab_n, int sqrt_ab_d) {
  typedef typename K::FT FT;
  const FT a = q<K>(an, ad), b = q<K>(bn, bd), r = q<K>(sqrt_ab_n, sqrt_ab_d);
  return fair::Rational_quadratic_bezier_2<K>(typename K::Point_2(a, FT(1) / a),
                                              typename K::Point_2(FT(2) * a * b / (a + b), FT(2) / (a + b)),
                                              typename K::Point_2(b, FT(1) / b), (a + b) / (FT(2) * r));
}

inline std::vector<int> kinds_of(const std::vector<fair::Curvature_extremum>& e) {
  std::vector<int> out;
  for (const fair::Curvature_extremum& x : e) out.push_back(static_cast<int>(x.kind));
  return out;
}
const int MAX = static_cast<int>(fair::Curvature_extremum_kind::MAXIMUM);
const int MIN = static_cast<int>(fair::Curvature_extremum_kind::MINIMUM);

// Exact value of the eq.-7 quartic (Bernstein coefficients of eq. A.1), computed independently
// of the library from exact inputs.
inline CGAL::Gmpq eq7_value(const Kq::Point_2& p0, const Kq::Point_2& qq, const Kq::Point_2& p2, const CGAL::Gmpq& w,
                     const CGAL::Gmpq& t) {
  const Kq::Vector_2 v0 = p0 - qq, v2 = p2 - qq;
  const CGAL::Gmpq A = v0 * v0, B = v0 * v2, C = v2 * v2, s = CGAL::Gmpq(1) - t;
  return -w * A * s * s * s * s - (A + B) * s * s * s * t + (B + C) * s * t * t * t + w * C * t * t * t * t;
}

template <class K>
Kq::Point_2 to_q(const typename K::Point_2& p) {
  return Kq::Point_2(fair::internal::common::to_gmpq(p.x()), fair::internal::common::to_gmpq(p.y()));
}

using rational_quadratic_test::Rational_quadratic_test;
TYPED_TEST_SUITE(Rational_quadratic_test, fair_test::All_kernels);

} // namespace

#endif // FAIR_TEST_RATIONAL_QUADRATIC_SUPPORT_H
