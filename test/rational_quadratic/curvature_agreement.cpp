// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The conic piece keeps its own curvature formula (kappa = 4 w D W^3 / |V|^3 on the exactly
// computed area D, valid at scales where c' overflows), while the sampler and the metrics use the
// library's one scale-safe curvature of c' and c'' (internal/common/curvature.h). Both appear in
// one plot (the tool marks extrema with the piece's own value on a profile from the sampler), so
// they must agree wherever both are defined.

#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/internal/common/curvature.h>

#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <cmath>
#include <random>

TEST(Rational_quadratic_curvature, OwnFormulaAgreesWithTheSharedCurvatureOfTheDerivatives) {
  typedef CGAL::Simple_cartesian<double> K;
  typedef K::Point_2 P;
  std::mt19937 rng(20261201);
  std::uniform_real_distribution<double> coordinate(-10, 10), log_weight(-3, 3), parameter(0, 1);
  int compared = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const P p0(coordinate(rng), coordinate(rng)), p1(coordinate(rng), coordinate(rng)), p2(coordinate(rng), coordinate(rng));
    if (std::fabs(CGAL::to_double(CGAL::area(p0, p1, p2))) < 1e-3) continue;  // nearly flat: both ill-conditioned
    const fair::Rational_quadratic_bezier_2<K> c(p0, p1, p2, std::exp(log_weight(rng)));
    for (int k = 0; k < 5; ++k) {
      const double t = k == 0 ? 0.0 : (k == 4 ? 1.0 : parameter(rng));
      const K::Vector_2 d1 = c.derivative(t), d2 = c.second_derivative(t);
      const double shared = fair::internal::common::signed_curvature(d1.x(), d1.y(), d2.x(), d2.y());
      // The shared formula cancels in the cross product c' x c'' (relative error ~ eps |c'||c''| /
      // |c' x c''|); the piece's own formula does not. Compare to that conditioning.
      const double condition = std::hypot(d1.x(), d1.y()) * std::hypot(d2.x(), d2.y()) /
                               std::fabs(d1.x() * d2.y() - d1.y() * d2.x());
      EXPECT_TRUE(fair_test::same_double(c.curvature(t), shared, 1e-13 * condition)) << c << " t = " << t;
      ++compared;
    }
  }
  EXPECT_GT(compared, 5000);
}
