// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of fair::Rational_quadratic_bezier_2:
// the curvature extrema of eq. 4 (ellipse arcs of Fig. 1, classification by sampling).

#include "support.h"

namespace {

// ------------------------------------------------------------------ ellipses, Fig. 1
TYPED_TEST(Rational_quadratic_test, EllipseArcsHaveZeroOneOrTwoExtrema) {
  typedef TypeParam K;
  // Arcs of x^2/4 + y^2 = 1 (the unit-circle arcs scaled by 2 in x); |kappa| is maximal at
  // (+-2, 0) and minimal at (0, +-1). The angle alpha of the circle runs with t.
  struct Case {
    Half_angle b0, b2;
    std::vector<int> kinds;
  };
  const Case cases[] = {{Hm7, H7, {MAX}},        // alpha in [-32.5, 32.5] deg
                        {H8, H15, {MIN}},        // alpha in [56.1, 123.9] deg
                        {Hm7, H4, {MAX, MIN}},   // alpha in [-32.5, 106.3] deg
                        {H7, H3, {}}};           // alpha in [32.5, 73.7] deg
  for (const Case& cs : cases) {
    const fair::Rational_quadratic_bezier_2<K> c = circle_arc<K>(cs.b0, cs.b2, 2);
    EXPECT_EQ(c.conic_type(), fair::Conic_type::ELLIPSE);
    EXPECT_LT(CGAL::to_double(c.conic_discriminant()), 0.0);
    EXPECT_NEAR(c.eccentricity(), std::sqrt(3.0) / 2, 1e-14);
    EXPECT_FALSE(c.has_constant_curvature());
    const std::vector<fair::Curvature_extremum> e = c.curvature_extrema();
    EXPECT_EQ(kinds_of(e), cs.kinds);
    for (const fair::Curvature_extremum& x : e) {
      const typename K::Point_2 p = c.point(typename K::FT(x.t));
      if (x.kind == fair::Curvature_extremum_kind::MAXIMUM) EXPECT_NEAR(CGAL::to_double(p.y()), 0.0, 1e-12);
      else EXPECT_NEAR(CGAL::to_double(p.x()), 0.0, 1e-12);
      EXPECT_TRUE(dbl(x.t_lower) - 1e-15 <= x.t && x.t <= dbl(x.t_upper) + 1e-15);
    }
  }
}

// Classification of random pieces checked by sampling |kappa| in double around each extremum,
// and the Sec. 3.1 bounds: at most 2 critical points for an ellipse, 1 for w >= 1.
TYPED_TEST(Rational_quadratic_test, ExtremaClassificationMatchesSampling) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::mt19937_64 rng(314159);
  std::uniform_real_distribution<double> u(-1.0, 1.0), lw(-2.0, 1.5);
  int tested = 0, classified = 0, two = 0;
  while (tested < (is_exact<K>() ? 60 : 300)) {
    const typename K::Point_2 p0(u(rng), u(rng)), p1(u(rng), u(rng)), p2(u(rng), u(rng));
    if (std::fabs(CGAL::to_double(CGAL::area(p0, p1, p2))) < 1e-2) continue;
    ++tested;
    const double wd = std::pow(2.0, lw(rng));
    const fair::Rational_quadratic_bezier_2<K> c(p0, p1, p2, FT(wd));
    const std::vector<fair::Curvature_extremum> e = c.curvature_extrema();
    EXPECT_LE(e.size(), wd < 1 ? 2u : 1u);
    if (e.size() == 2) {
      ++two;
      EXPECT_NE(e[0].kind, e[1].kind); // one maximum and one minimum
    }
    for (std::size_t i = 0; i < e.size(); ++i) {
      const double t = e[i].t;
      double gap = std::min(t, 1 - t);
      if (i > 0) gap = std::min(gap, t - e[i - 1].t);
      if (i + 1 < e.size()) gap = std::min(gap, e[i + 1].t - t);
      const double d = std::min(1e-2, gap / 2);
      const double k0 = std::fabs(c.curvature(t)), ka = std::fabs(c.curvature(t - d)), kb = std::fabs(c.curvature(t + d));
      if (std::fabs(ka - k0) < 1e-9 * k0 || std::fabs(kb - k0) < 1e-9 * k0) continue; // too flat to sample
      ++classified;
      if (e[i].kind == fair::Curvature_extremum_kind::MAXIMUM) {
        EXPECT_LT(ka, k0) << c;
        EXPECT_LT(kb, k0) << c;
      } else {
        EXPECT_EQ(e[i].kind, fair::Curvature_extremum_kind::MINIMUM);
        EXPECT_GT(ka, k0) << c;
        EXPECT_GT(kb, k0) << c;
      }
    }
    // Between the extrema |kappa| is monotone: sampled increments have the sign predicted by
    // the kinds (checked on a coarse grid away from the extrema).
    for (int j = 0; j < 40; ++j) {
      const double a = j / 40.0, b = (j + 1) / 40.0;
      bool near = false;
      for (const fair::Curvature_extremum& x : e) near = near || (x.t > a - 0.02 && x.t < b + 0.02);
      if (near) continue;
      int rising = 0; // |kappa| rises on (a,b) iff the next extremum to the right is a maximum
      for (const fair::Curvature_extremum& x : e) {
        if (x.t > b) { rising = x.kind == fair::Curvature_extremum_kind::MAXIMUM ? 1 : -1; break; }
      }
      if (rising == 0 && !e.empty()) rising = e.back().kind == fair::Curvature_extremum_kind::MAXIMUM ? -1 : 1;
      const double ka = std::fabs(c.curvature(a)), kb = std::fabs(c.curvature(b));
      if (rising == 0 || std::fabs(kb - ka) < 1e-9 * ka) continue;
      EXPECT_EQ(kb > ka ? 1 : -1, rising) << c << " on [" << a << ", " << b << "]";
    }
  }
  EXPECT_GT(classified, tested / 3);
  EXPECT_GT(two, 0);
}

} // namespace
