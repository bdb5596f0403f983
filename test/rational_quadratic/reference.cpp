// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of fair::Rational_quadratic_bezier_2:
// agreement with an independent 256-bit CGAL::Gmpfr evaluation.

#include "support.h"

namespace {

// ------------------------------------------------------------------ 256-bit reference
// Independent evaluation with CGAL::Gmpfr at 256 bits from the quotient rule on
// X(t) = sum b_i w_i P_i, W(t) = sum b_i w_i (not the closed forms the class uses).
TYPED_TEST(Rational_quadratic_test, AgreesWithGmpfrReference) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  typedef CGAL::Gmpfr R;
  const auto old = R::set_default_precision(256);
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-10.0, 10.0), lw(-2.0, 2.0);
  int tested = 0;
  double worst = 0;
  while (tested < 300) {
    const double x[3] = {u(rng), u(rng), u(rng)}, y[3] = {u(rng), u(rng), u(rng)}, wd = std::pow(2.0, lw(rng));
    const double area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    if (std::fabs(area) < 1.0) continue; // keep the conditioning moderate
    ++tested;
    const fair::Rational_quadratic_bezier_2<K> c(typename K::Point_2(x[0], y[0]), typename K::Point_2(x[1], y[1]),
                                                 typename K::Point_2(x[2], y[2]), FT(wd));
    for (double td : {0.0, 0.125, 0.3, 0.5, 0.77, 1.0}) {
      const R t(td), s = R(1) - t, w(wd);
      const R b0 = s * s, b1 = R(2) * s * t * w, b2 = t * t;
      const R db0 = R(-2) * s, db1 = R(2) * w * (s - t), db2 = R(2) * t;
      const R d2b0(2), d2b1 = R(-4) * w, d2b2(2);
      const R W = b0 + b1 + b2, W1 = db0 + db1 + db2, W2 = d2b0 + d2b1 + d2b2;
      R cx[3], cy[3];
      for (int k = 0; k < 3; ++k) {
        const R bb[3] = {k == 0 ? b0 : (k == 1 ? db0 : d2b0), k == 0 ? b1 : (k == 1 ? db1 : d2b1),
                         k == 0 ? b2 : (k == 1 ? db2 : d2b2)};
        cx[k] = bb[0] * R(x[0]) + bb[1] * R(x[1]) + bb[2] * R(x[2]);
        cy[k] = bb[0] * R(y[0]) + bb[1] * R(y[1]) + bb[2] * R(y[2]);
      }
      const R px = cx[0] / W, py = cy[0] / W;
      const R dx = (cx[1] - W1 * px) / W, dy = (cy[1] - W1 * py) / W;
      const R ex = (cx[2] - R(2) * W1 * dx - W2 * px) / W, ey = (cy[2] - R(2) * W1 * dy - W2 * py) / W;
      const R n2 = dx * dx + dy * dy;
      const double kappa = CGAL::to_double((dx * ey - dy * ex) / (n2 * CGAL::sqrt(n2)));
      const typename K::Point_2 p = c.point(FT(td));
      const typename K::Vector_2 d = c.derivative(FT(td)), e = c.second_derivative(FT(td));
      const double dn = std::sqrt(CGAL::to_double(n2)), en = std::hypot(CGAL::to_double(ex), CGAL::to_double(ey));
      const double errs[] = {std::hypot(CGAL::to_double(p.x()) - CGAL::to_double(px), CGAL::to_double(p.y()) - CGAL::to_double(py)) / 10.0,
                             std::hypot(CGAL::to_double(d.x()) - CGAL::to_double(dx), CGAL::to_double(d.y()) - CGAL::to_double(dy)) / dn,
                             std::hypot(CGAL::to_double(e.x()) - CGAL::to_double(ex), CGAL::to_double(e.y()) - CGAL::to_double(ey)) / en,
                             std::fabs(c.curvature(td) - kappa) / std::fabs(kappa),
                             std::fabs(CGAL::to_double(c.squared_curvature(FT(td))) / (kappa * kappa) - 1)};
      for (double err : errs) {
        worst = std::max(worst, err);
        EXPECT_LT(err, 1e-13) << c << " t = " << td;
      }
    }
  }
  R::set_default_precision(old);
  ::testing::Test::RecordProperty("worst_relative_error", std::to_string(worst));
}

} // namespace
