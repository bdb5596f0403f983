// Tests of Parametric_curve_spline.h: eq. 7 (local derivatives) against an independent quintic
// Hermite construction, eqs. 8 + 3 against the closed form of the control points, cubic
// precision (exact in exact kernels), the ends, the hybrid's C2 joins (exact in exact kernels),
// convergence orders O(h^6) / O(h^4) on spiral, involute and clothoid, the paper's Sec. 5
// figures, and the typed errors.

#include <fair/Parametric_curve_spline.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

using fair_test::pi;
using fair_test::same;

// A polynomial cubic f(u) = sum_k a_k u^k as a ParametricCurve_2 (dyadic coefficients: its jets
// at dyadic u are exact doubles), with its value also in any FT.
struct Cubic_curve {
  double ax[4], ay[4], u0, u1;
  double parameter_begin() const { return u0; }
  double parameter_end() const { return u1; }
  fair::Curve_jet_2 jet(double u) const {
    auto v = [u](const double* a) { return a[0] + u * (a[1] + u * (a[2] + u * a[3])); };
    auto d = [u](const double* a) { return a[1] + u * (2 * a[2] + 3 * u * a[3]); };
    auto dd = [u](const double* a) { return 2 * a[2] + 6 * u * a[3]; };
    return fair::Curve_jet_2{v(ax), v(ay), d(ax), d(ay), dd(ax), dd(ay)};
  }
  template <class FT>
  std::pair<FT, FT> value(const FT& u) const {
    auto v = [&u](const double* a) { return FT(a[0]) + u * (FT(a[1]) + u * (FT(a[2]) + u * FT(a[3]))); };
    return std::make_pair(v(ax), v(ay));
  }
};
const Cubic_curve test_cubic{{0.5, 2, -1.25, 0.375}, {-1, 0.75, 1.5, -0.625}, -1, 3};
const std::vector<double> cubic_marks{-1, -0.5, -0.375, 0.25, 1, 1.125, 2, 3}; // non-uniform, dyadic

template <class K>
class Parametric_spline_exact : public ::testing::Test {};
TYPED_TEST_SUITE(Parametric_spline_exact, fair_test::All_kernels);

TYPED_TEST(Parametric_spline_exact, CubicPrecisionOfQuinticsAndSpline) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const std::vector<fair::Bezier_2<K>> q = fair::quintic_pieces<K>(test_cubic, cubic_marks);
  const fair::Cubic_spline_2<K> s = fair::parametric_curve_spline<K>(test_cubic, cubic_marks);
  ASSERT_EQ(q.size(), cubic_marks.size() - 1);
  ASSERT_EQ(s.number_of_pieces(), cubic_marks.size() - 1);
  for (std::size_t i = 0; i + 1 < cubic_marks.size(); ++i) {
    const FT a(cubic_marks[i]), h = FT(cubic_marks[i + 1]) - a;
    for (int k = 0; k <= 8; ++k) {
      const FT t = fair_test::q<K>(k, 8), u = a + t * h;
      const std::pair<FT, FT> f = test_cubic.value(u);
      const typename K::Point_2 p(f.first, f.second);
      EXPECT_TRUE(same<K>(q[i].point(t), p)) << "quintic " << i << " at t = " << k << "/8";
      EXPECT_TRUE(same<K>(s.point(u), p)) << "spline at u = " << CGAL::to_double(u);
    }
  }
  // the spline's control polygon is the B-spline form of the cubic: eq. 3 of Cubic_spline_2 on
  // the cubic's own pieces (an independent construction) gives the same control points
  std::vector<fair::Bezier_2<K>> pieces;
  for (const fair::Bezier_2<K>& p : s.polynomial_pieces()) pieces.push_back(p);
  const fair::Cubic_spline_2<K> r = fair::Cubic_spline_2<K>::from_bezier_pieces(s.breakpoints(), pieces);
  for (std::size_t i = 0; i < s.number_of_control_points(); ++i)
    EXPECT_TRUE(same<K>(r.control_points()[i], s.control_points()[i])) << "control point " << i;
}

TYPED_TEST(Parametric_spline_exact, CubicPrecisionOnSeededRandomCubicsAndMarks) {
  // dyadic coefficients k/8 and marks k/64: the jets are exact doubles, so in an exact kernel
  // the spline must be the cubic exactly, at every dyadic parameter
  typedef TypeParam K;
  typedef typename K::FT FT;
  std::mt19937 rng(1201);
  std::uniform_int_distribution<int> coefficient(-16, 16), gap(1, 48), count(1, 9);
  for (int trial = 0; trial < 6; ++trial) {
    Cubic_curve f{{}, {}, 0, 0};
    for (int k = 0; k < 4; ++k) f.ax[k] = coefficient(rng) / 8.0, f.ay[k] = coefficient(rng) / 8.0;
    f.ax[1] = 3; // a generic cubic; regularity at the marks is not needed for cubic precision
    std::vector<double> u{-1.0};
    const int m = count(rng);
    for (int i = 0; i < m; ++i) u.push_back(u.back() + gap(rng) / 64.0);
    f.u0 = u.front(), f.u1 = u.back();
    fair::Parametric_spline_options o;
    o.require_regular = false;
    const fair::Cubic_spline_2<K> s = fair::parametric_curve_spline<K>(f, u, o);
    for (int k = 0; k <= 16; ++k) {
      const FT v = FT(u.front()) + (FT(u.back()) - FT(u.front())) * fair_test::q<K>(k, 16);
      const std::pair<FT, FT> p = f.value(v);
      EXPECT_TRUE(same<K>(s.point(v), typename K::Point_2(p.first, p.second), 1e-13)) << "trial " << trial << " k " << k;
    }
  }
}

TYPED_TEST(Parametric_spline_exact, ControlPointsAreTheBlossomOfTheTwoJet) {
  // eqs. 8 and 3 with local derivatives amount to c_i = f + (h_i - h_{i-1})/3 f' - h_{i-1} h_i/6 f''
  // (doc/parametric_curves.md), and the ends to f(u_0), f(u_0) + h_0/3 f'(u_0) and mirrored.
  typedef TypeParam K;
  typedef typename K::FT FT;
  const fair::Archimedean_spiral_2 f(0.0, 0.5 / pi, 0.5, 9.0);
  const std::vector<double> u{0.5, 0.75, 1.5, 2.0, 4.0, 4.5, 7.0, 9.0};
  const fair::Cubic_spline_2<K> s = fair::parametric_curve_spline<K>(f, u);
  const std::vector<typename K::Point_2>& d = s.control_points();
  ASSERT_EQ(d.size(), u.size() + 2);
  auto jet = [&](std::size_t i, FT& x, FT& y, FT& dx, FT& dy, FT& ddx, FT& ddy) {
    const fair::Curve_jet_2 j = f.jet(u[i]);
    x = FT(j.x), y = FT(j.y), dx = FT(j.dx), dy = FT(j.dy), ddx = FT(j.ddx), ddy = FT(j.ddy);
  };
  FT x, y, dx, dy, ddx, ddy;
  const std::size_t m = u.size() - 1;
  for (std::size_t i = 1; i < m; ++i) {
    jet(i, x, y, dx, dy, ddx, ddy);
    const FT hl = FT(u[i]) - FT(u[i - 1]), hr = FT(u[i + 1]) - FT(u[i]);
    const FT a = (hr - hl) / FT(3), b = hl * hr / FT(6);
    EXPECT_TRUE(same<K>(d[i + 1], typename K::Point_2(x + a * dx - b * ddx, y + a * dy - b * ddy), 1e-14)) << i;
  }
  jet(0, x, y, dx, dy, ddx, ddy);
  const FT h0 = FT(u[1]) - FT(u[0]), hm = FT(u[m]) - FT(u[m - 1]);
  EXPECT_TRUE(same<K>(d[0], typename K::Point_2(x, y)));
  EXPECT_TRUE(same<K>(d[1], typename K::Point_2(x + h0 / FT(3) * dx, y + h0 / FT(3) * dy), 1e-14));
  EXPECT_TRUE(same<K>(s.point(FT(u[0])), typename K::Point_2(x, y)));
  jet(m, x, y, dx, dy, ddx, ddy);
  EXPECT_TRUE(same<K>(d[m + 2], typename K::Point_2(x, y)));
  EXPECT_TRUE(same<K>(d[m + 1], typename K::Point_2(x - hm / FT(3) * dx, y - hm / FT(3) * dy), 1e-14));
  EXPECT_TRUE(same<K>(s.point(FT(u[m])), typename K::Point_2(x, y)));
}

TYPED_TEST(Parametric_spline_exact, HybridIsC2AtEveryJoin) {
  typedef TypeParam K;
  typedef typename K::FT FT;
  const fair::Circle_involute_2 f(0.5, 0.5, 8.0);
  for (const std::vector<double>& u : {std::vector<double>{0.5, 1, 2, 2.5, 3, 4.5, 5, 6.25, 7, 8},
                                       std::vector<double>{0.5, 1.5, 2, 4, 8}}) {
    const std::vector<fair::Bezier_2<K>> c = fair::parametric_curve_hybrid<K>(f, u);
    const std::vector<fair::Bezier_2<K>> q = fair::quintic_pieces<K>(f, u);
    ASSERT_EQ(c.size(), u.size() - 1);
    for (std::size_t i = 2; i + 2 < c.size(); ++i) EXPECT_EQ(c[i].control_points(), q[i].control_points()) << i;
    for (std::size_t i = 1; i < c.size(); ++i) {
      const FT hl = FT(u[i]) - FT(u[i - 1]), hr = FT(u[i + 1]) - FT(u[i]);
      EXPECT_TRUE(same<K>(c[i - 1].point(FT(1)), c[i].point(FT(0)))) << i;
      // d/du = (1/h) d/dt on each piece
      EXPECT_TRUE(same<K>(c[i - 1].derivative(FT(1)) / hl, c[i].derivative(FT(0)) / hr, 1e-13)) << i;
      EXPECT_TRUE(same<K>(c[i - 1].second_derivative(FT(1)) / (hl * hl), c[i].second_derivative(FT(0)) / (hr * hr), 1e-12))
          << i;
    }
  }
}

TEST(QuinticPieces, Eq7ReadLiterallyDoesNotReproduceCubics) {
  // eq. 7 with the global f', f'' (no h_i) on pieces of length h != 1: the piece's tangent is
  // f'/h times too long in the local parameter, so it leaves the cubic.
  typedef fair_test::SC_double K;
  const double a = 0.25, b = 1.0, h = b - a;
  const fair::Curve_jet_2 j0 = test_cubic.jet(a), j1 = test_cubic.jet(b);
  const std::vector<K::Point_2> literal{K::Point_2(j0.x, j0.y), K::Point_2(j0.x + j0.dx / 5, j0.y + j0.dy / 5),
                                        K::Point_2(j0.x + 0.4 * j0.dx + j0.ddx / 20, j0.y + 0.4 * j0.dy + j0.ddy / 20),
                                        K::Point_2(j1.x - 0.4 * j1.dx + j1.ddx / 20, j1.y - 0.4 * j1.dy + j1.ddy / 20),
                                        K::Point_2(j1.x - j1.dx / 5, j1.y - j1.dy / 5), K::Point_2(j1.x, j1.y)};
  const std::pair<double, double> mid = test_cubic.value(a + 0.5 * h);
  const K::Point_2 p = fair::Bezier_2<K>(literal).point(0.5);
  EXPECT_GT(std::hypot(p.x() - mid.first, p.y() - mid.second), 1e-2);
  const K::Point_2 r = fair::quintic_pieces<K>(test_cubic, {a, b})[0].point(0.5);
  EXPECT_NEAR(std::hypot(r.x() - mid.first, r.y() - mid.second), 0.0, 1e-15);
}

// Quintic Hermite basis on [0,1]: value, first and second derivative at 0 and at 1.
double hermite(int k, double t) {
  const double t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t;
  switch (k) {
    case 0: return 1 - 10 * t3 + 15 * t4 - 6 * t5;
    case 1: return t - 6 * t3 + 8 * t4 - 3 * t5;
    case 2: return 0.5 * (t2 - 3 * t3 + 3 * t4 - t5);
    case 3: return 0.5 * (t3 - 2 * t4 + t5);
    case 4: return -4 * t3 + 7 * t4 - 3 * t5;
    default: return 10 * t3 - 15 * t4 + 6 * t5;
  }
}

TEST(QuinticPieces, AgreeWithTheQuinticHermiteInterpolant) {
  typedef fair_test::SC_double K;
  const fair::Clothoid_2 f(0.2, 1.3, -1.0, 2.0, 1.5, 0.5, 0.5, 0.3);
  const std::vector<double> u{-1.0, -0.6, 0.1, 0.3, 1.2, 2.0};
  const std::vector<fair::Bezier_2<K>> q = fair::quintic_pieces<K>(f, u);
  for (std::size_t i = 0; i + 1 < u.size(); ++i) {
    const fair::Curve_jet_2 a = f.jet(u[i]), b = f.jet(u[i + 1]);
    const double h = u[i + 1] - u[i];
    for (int k = 0; k <= 10; ++k) {
      const double t = k / 10.0;
      const double x = hermite(0, t) * a.x + hermite(1, t) * h * a.dx + hermite(2, t) * h * h * a.ddx +
                       hermite(3, t) * h * h * b.ddx + hermite(4, t) * h * b.dx + hermite(5, t) * b.x;
      const double y = hermite(0, t) * a.y + hermite(1, t) * h * a.dy + hermite(2, t) * h * h * a.ddy +
                       hermite(3, t) * h * h * b.ddy + hermite(4, t) * h * b.dy + hermite(5, t) * b.y;
      EXPECT_TRUE(same<K>(q[i].point(t), K::Point_2(x, y), 1e-14)) << i << " " << t;
    }
    // the end 2-jets in the global parameter are f's
    EXPECT_TRUE(same<K>(q[i].derivative(0.0) / h, K::Vector_2(a.dx, a.dy), 1e-13));
    EXPECT_TRUE(same<K>(q[i].second_derivative(1.0) / (h * h), K::Vector_2(b.ddx, b.ddy), 1e-12));
  }
}

// Max over 16 samples per piece of |s(u) - f(u)| and of |kappa_s(u) - kappa_f(u)|.
struct Errors {
  double position = 0, curvature = 0;
};
template <class Curve>
double curvature_of(const Curve& f, double u) {
  const fair::Curve_jet_2 j = f.jet(u);
  return (j.dx * j.ddy - j.dy * j.ddx) / std::pow(std::hypot(j.dx, j.dy), 3);
}
template <class Curve>
Errors quintic_errors(const Curve& f, const std::vector<double>& u) {
  typedef fair_test::SC_double K;
  const std::vector<fair::Bezier_2<K>> q = fair::quintic_pieces<K>(f, u);
  Errors e;
  for (std::size_t i = 0; i < q.size(); ++i)
    for (int k = 0; k <= 16; ++k) {
      const double t = k / 16.0, v = u[i] + t * (u[i + 1] - u[i]);
      const fair::Curve_jet_2 j = f.jet(std::min(v, u[i + 1]));
      const K::Point_2 p = q[i].point(t);
      e.position = std::max(e.position, std::hypot(p.x() - j.x, p.y() - j.y));
      e.curvature = std::max(e.curvature, std::fabs(q[i].curvature(t) - curvature_of(f, std::min(v, u[i + 1]))));
    }
  return e;
}
template <class Curve>
Errors spline_errors(const Curve& f, const std::vector<double>& u) {
  typedef fair_test::SC_double K;
  const fair::Cubic_spline_2<K> s = fair::parametric_curve_spline<K>(f, u);
  Errors e;
  for (std::size_t i = 0; i + 1 < u.size(); ++i)
    for (int k = 0; k <= 16; ++k) {
      const double v = std::min(u[i] + k / 16.0 * (u[i + 1] - u[i]), u[i + 1]);
      const fair::Curve_jet_2 j = f.jet(v);
      const K::Point_2 p = s.point(v);
      e.position = std::max(e.position, std::hypot(p.x() - j.x, p.y() - j.y));
      e.curvature = std::max(e.curvature, std::fabs(s.curvature(v) - curvature_of(f, v)));
    }
  return e;
}
std::vector<double> uniform_marks(double a, double b, std::size_t m) {
  std::vector<double> u(m + 1);
  for (std::size_t i = 0; i <= m; ++i) u[i] = (i == m) ? b : a + (b - a) * double(i) / double(m);
  return u;
}

// log2 of successive error ratios over m = 16, 32, 64, 128 pieces must be near the order
// (measured table in doc/parametric_curves.md).
template <class Curve>
void expect_orders(const Curve& f, const char* name) {
  std::vector<Errors> q, s;
  for (std::size_t m : {16, 32, 64, 128}) {
    const std::vector<double> u = uniform_marks(f.parameter_begin(), f.parameter_end(), m);
    q.push_back(quintic_errors(f, u));
    s.push_back(spline_errors(f, u));
  }
  for (std::size_t k = 0; k + 1 < q.size(); ++k) {
    const double qp = std::log2(q[k].position / q[k + 1].position), sp = std::log2(s[k].position / s[k + 1].position);
    const double qk = std::log2(q[k].curvature / q[k + 1].curvature), sk = std::log2(s[k].curvature / s[k + 1].curvature);
    EXPECT_GT(qp, 5.6) << name << " quintic position, step " << k;
    EXPECT_LT(qp, 6.6) << name << " quintic position, step " << k;
    EXPECT_GT(sp, 3.6) << name << " spline position, step " << k;
    EXPECT_LT(sp, 4.6) << name << " spline position, step " << k;
    EXPECT_GT(qk, 3.6) << name << " quintic curvature, step " << k;
    EXPECT_LT(qk, 4.6) << name << " quintic curvature, step " << k;
    EXPECT_GT(sk, 1.5) << name << " spline curvature, step " << k;
    EXPECT_LT(sk, 2.8) << name << " spline curvature, step " << k;
  }
}

TEST(ParametricCurveSpline, ConvergenceOrdersOnSpiralInvoluteClothoid) {
  expect_orders(fair::Archimedean_spiral_2(0.0, 0.5 / pi, pi, 6 * pi), "spiral");
  expect_orders(fair::Circle_involute_2(0.25, 0.5, 4 * pi), "involute");
  expect_orders(fair::Clothoid_2(0.0, pi, 0.0, 2.5), "clothoid");
}

TEST(ParametricCurveSpline, PaperClaimOnTheUnitArchimedeanSpiralAtAbout32Segments) {
  // Sec. 5: the quintics of a unit-sized Archimedean spiral deviate by < 1e-8 in position and
  // about 1e-5 in curvature; here r = theta / (4 pi), theta in [pi, 4 pi] (1.5 turns out to
  // radius 1), 36 uniform segments (32 give 1.6e-8 and 2.0e-5).
  const fair::Archimedean_spiral_2 f(0.0, 1 / (4 * pi), pi, 4 * pi);
  const std::vector<double> u = uniform_marks(pi, 4 * pi, 36);
  const Errors q = quintic_errors(f, u), s = spline_errors(f, u);
  EXPECT_LT(q.position, 1e-8);
  EXPECT_LT(q.curvature, 3e-5);
  EXPECT_GT(q.curvature, 3e-6);
  // the spline is not "twice the error of the quintic": it is orders of magnitude larger
  EXPECT_GT(s.position, 20 * q.position);
}

TEST(ParametricCurveSpline, LiteralHybridWithoutTransitionsIsNotC2) {
  // Replacing the spline's pieces on [u_2, u_{m-2}] by the quintics directly: the spline's second
  // derivative at u_2 differs from f''(u_2) (the spline does not interpolate 2-jets).
  typedef fair_test::SC_double K;
  const fair::Archimedean_spiral_2 f(0.0, 1 / (6 * pi), pi, 6 * pi);
  const std::vector<double> u = uniform_marks(pi, 6 * pi, 16);
  const fair::Cubic_spline_2<K> s = fair::parametric_curve_spline<K>(f, u);
  const fair::Curve_jet_2 j = f.jet(u[2]);
  const K::Vector_2 d2 = s.second_derivative(u[2]);
  EXPECT_GT(std::hypot(d2.x() - j.ddx, d2.y() - j.ddy), 1e-6 * std::hypot(j.ddx, j.ddy));
}

TEST(ParametricCurveSpline, OnePieceAndTypedErrors) {
  typedef fair_test::SC_double K;
  const fair::Parametric_circle_arc_2 arc(0, 0, 1, 0, pi / 2);
  const fair::Cubic_spline_2<K> s = fair::parametric_curve_spline<K>(arc, {0, pi / 2});
  EXPECT_EQ(s.number_of_pieces(), 1u);
  EXPECT_NEAR(std::hypot(s.point(pi / 4).x(), s.point(pi / 4).y()), 1.0, 2e-2); // the cubic Hermite arc
  EXPECT_TRUE(same<K>(s.point(pi / 2), K::Point_2(std::cos(pi / 2), 1.0)));
  auto message_of = [&](const std::vector<double>& u) -> std::string {
    try {
      fair::parametric_curve_spline<K>(arc, u);
    } catch (const fair::Invalid_input_error& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message_of({0.0}).find("at least 2 marks"), std::string::npos);
  EXPECT_NE(message_of({0.0, 0.5, 0.5, 1.0}).find("not strictly increasing"), std::string::npos);
  EXPECT_NE(message_of({0.0, 0.7, 0.5, 1.0}).find("and 2 = 0.5 are not"), std::string::npos);
  EXPECT_NE(message_of({0.0, 1.0, 2.0}).find("outside the curve's domain"), std::string::npos);
  EXPECT_NE(message_of({0.0, NAN}).find("outside"), std::string::npos);
  EXPECT_THROW(fair::parametric_curve_hybrid<K>(arc, {0, 0.2, 0.4, 0.6}), fair::Invalid_input_error);
  // a cusp at a mark: (u^2, u^3) at u = 0
  const Cubic_curve cusp{{0, 0, 1, 0}, {0, 0, 0, 1}, -1, 1};
  EXPECT_THROW(fair::parametric_curve_spline<K>(cusp, {-1, 0, 1}), fair::Invalid_input_error);
  fair::Parametric_spline_options o;
  o.require_regular = false;
  EXPECT_NO_THROW(fair::parametric_curve_spline<K>(cusp, {-1, 0, 1}, o));
}

} // namespace
