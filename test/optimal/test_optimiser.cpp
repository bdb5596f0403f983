// Tests of the optimal-curve optimiser (issue 11 §2, §3, §5; include/fair/Optimal_curve_2.h and
// include/fair/internal/optimal/{solver,hierarchy,constraints,lambda}.h): the oracles of §5 (the
// circle with error O(h^2), the rectangular elastica, the Euler-Lagrange residual on the borderline
// elastica, the clothoid), structure (collinear -> segment, lambda = 0 -> polygon, rigid motions and
// scaling, reversal, symmetry), constraints (normal held exactly at every level, corners), the
// lambda design, divergence, the derivative energies, CG against Newton, and typed errors.

#include <fair/Kappa_curve_report.h>
#include <fair/Optimal_curve_2.h>
#include <fair/internal/common/polygon_crossings.h>

#include "test_support.h"
// The real data sets of test/data/real (read only: no glyph outlines here, so no FreeType).
#ifndef FAIR_NO_FREETYPE
#define FAIR_NO_FREETYPE
#endif
#include "kappa_real/data_sets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using fair::Optimal_curve_2;
using fair::Optimal_curve_options;
using fair::Optimal_curve_status;
using fair::Point_constraint;
using fair::Point_constraint_kind;
typedef fair_test::SC_double K;
typedef K::Point_2 P;
using fair_test::pi;

// The raw weights of eq. 5 (lambda = -1): the oracles below are stated for them. The defaults are
// the lambda design at fair::default_optimal_lambda (issue 25 §1; test_real_data.cpp).
Optimal_curve_options raw_weights() {
  Optimal_curve_options o{};
  o.lambda = -1;
  return o;
}

double polygon_length(const std::vector<P>& c, bool closed) {
  double s = 0;
  const std::size_t e = closed ? c.size() : c.size() - 1;
  for (std::size_t j = 0; j < e; ++j) s += std::sqrt(CGAL::squared_distance(c[j], c[(j + 1) % c.size()]));
  return s;
}

double max_edge(const std::vector<P>& c, bool closed) {
  double h = 0;
  const std::size_t e = closed ? c.size() : c.size() - 1;
  for (std::size_t j = 0; j < e; ++j) h = std::max(h, std::sqrt(CGAL::squared_distance(c[j], c[(j + 1) % c.size()])));
  return h;
}

Point_constraint tangent(std::size_t i, double x, double y, Point_constraint_kind kind = Point_constraint_kind::TANGENT) {
  Point_constraint c;
  c.index = i;
  c.kind = kind;
  c.direction = {{x, y}};
  return c;
}

// Distance of q from the segment ab.
double segment_distance(const P& q, const P& a, const P& b) {
  return std::sqrt(CGAL::squared_distance(q, K::Segment_2(a, b)));
}

// Points on the circle of radius r about (cx, cy), unevenly spaced.
std::vector<P> circle_points(double r, double cx, double cy) {
  const double angles[5] = {0.3, 1.4, 2.9, 4.0, 5.1};
  std::vector<P> p;
  for (double a : angles) p.push_back(P(cx + r * std::cos(a), cy + r * std::sin(a)));
  return p;
}

const std::vector<P> wave = {P(0, 0), P(1, 2), P(3, 2.5), P(4, 0), P(6, 1)};

// ---------------------------------------------------------------------------------------------
// Kernels: the interpolation points of the polygon are the input points, exactly.

template <class Kernel>
class OptimiserKernels : public ::testing::Test {};
TYPED_TEST_SUITE(OptimiserKernels, fair_test::All_kernels);

TYPED_TEST(OptimiserKernels, InterpolationPointsAreTheInputPoints) {
  typedef typename TypeParam::Point_2 Point;
  const std::vector<Point> p = {Point(0, 0), Point(1, 2), Point(3, 2.5), Point(4, 0)};
  Optimal_curve_options o = raw_weights();
  o.resolution = 100;
  const Optimal_curve_2<TypeParam> c(p, o);
  ASSERT_EQ(c.interpolation_indices().size(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_TRUE(fair_test::same<TypeParam>(c.polygon()[c.interpolation_indices()[i]], p[i]));
  EXPECT_EQ(c.report().status, Optimal_curve_status::CONVERGED);
  EXPECT_EQ(c.curvatures().size(), c.polygon().size());
  // The contract's accessors (doc/concepts.md): points() the input, the pieces those of spline(),
  // one cubic per polygon edge, from the first input point to the last.
  EXPECT_EQ(c.points(), p);
  EXPECT_FALSE(c.is_closed());
  EXPECT_EQ(c.status(), c.report().status);
  ASSERT_EQ(c.number_of_pieces(), c.polygon().size() - 1);
  ASSERT_EQ(c.pieces().size(), c.number_of_pieces());
  EXPECT_EQ(c.spline().splines.size(), 1u);
  EXPECT_EQ(c.spline().splines[0].number_of_pieces(), c.number_of_pieces());
  // Through the input points to rounding (the fit runs in double, Polygon_spline_fit.h), in every
  // kernel; the other vertices within the smoothing tolerance (the smoothing spline, issue 25 §3).
  const auto distance = [](const Point& a, const Point& b) {
    return std::hypot(CGAL::to_double(a.x()) - CGAL::to_double(b.x()), CGAL::to_double(a.y()) - CGAL::to_double(b.y()));
  };
  std::vector<bool> input(c.polygon().size(), false);
  for (std::size_t i : c.interpolation_indices()) input[i] = true;
  EXPECT_GT(c.spline_smoothing().tolerance, 0);
  // When even the interpolant of every vertex is farther than the tolerance, that is the spline.
  const double tolerance = c.spline_smoothing().tolerance_met ? c.spline_smoothing().tolerance : 1e-13;
  for (std::size_t j = 0; j < c.number_of_pieces(); ++j) {
    EXPECT_EQ(c.pieces()[j].degree(), 3u);
    EXPECT_LE(distance(c.pieces()[j].source(), c.polygon()[j]), input[j] ? 1e-13 : tolerance * (1 + 1e-9)) << j;
    EXPECT_LE(distance(c.pieces()[j].target(), c.polygon()[j + 1]), input[j + 1] ? 1e-13 : tolerance * (1 + 1e-9)) << j;
    if (j > 0) {
      EXPECT_LE(distance(c.pieces()[j].source(), c.pieces()[j - 1].target()), 1e-13) << j;
    }
  }
  if (c.spline_smoothing().tolerance_met) {
    EXPECT_LE(c.spline().max_distance, tolerance * (1 + 1e-9));
  }
}

// ---------------------------------------------------------------------------------------------
// §5 oracles.

// Closed curve through points on a circle of radius R, F = int beta + beta0 |kappa L0|^2: the
// circle of radius sqrt(beta0/beta) L0 is the global minimiser (F >= 4 pi sqrt(beta beta0) L0 by
// Fenchel and Cauchy-Schwarz). beta0/beta = R^2/L0^2 puts it through the points.
struct Circle_run {
  double error, h, energy;
};
Circle_run solve_on_circle(const std::vector<P>& p, double R, double cx, double cy, double rho) {
  Optimal_curve_options o = raw_weights();
  o.closed = true;
  o.resolution = rho;
  const double L0 = polygon_length(p, true);
  o.curvature_weight = R * R / (L0 * L0);
  const Optimal_curve_2<K> c(p, o);
  EXPECT_EQ(c.report().status, Optimal_curve_status::CONVERGED);
  Circle_run r{0, max_edge(c.polygon(), true), c.energy()};
  for (const P& q : c.polygon()) r.error = std::max(r.error, std::abs(std::hypot(q.x() - cx, q.y() - cy) - R));
  return r;
}

TEST(OptimiserOracle, CircleThroughPointsOnACircleWithErrorOrderTwo) {
  const double R = 2, cx = 1, cy = -2;
  std::vector<P> p;
  for (int i = 0; i < 6; ++i) p.push_back(P(cx + R * std::cos(0.3 + pi * i / 3), cy + R * std::sin(0.3 + pi * i / 3)));
  const Circle_run coarse = solve_on_circle(p, R, cx, cy, 200), fine = solve_on_circle(p, R, cx, cy, 800);
  for (const Circle_run& r : {coarse, fine}) {
    // F -> 4 pi beta R (the circle: beta 2 pi R + beta0 L0^2 2 pi / R) from above, O(h^2).
    EXPECT_GT(r.energy, 4 * pi * R * (1 - 1e-12));
    EXPECT_LT(r.energy, 4 * pi * R * (1 + 0.1 * r.h * r.h));
    EXPECT_LT(r.error, 1e-3 * r.h * r.h);  // measured error / h^2 = 3.6e-4, 2.9e-4 (9.8e-5, 2.0e-5)
  }
  EXPECT_LT(fine.h, 0.6 * coarse.h);
  const double order = std::log(coarse.error / fine.error) / std::log(coarse.h / fine.h);
  EXPECT_GT(order, 1.8);
  EXPECT_LT(order, 2.5);
}

// Unevenly spaced points: the adaptive subdivision leaves edges of lengths h and 2h side by side,
// where the error is largest; it is O(h^2) with a larger constant once asymptotic: measured
// 2.1e-3, 9.0e-4, 2.5e-4 at h = 0.56, 0.28, 0.14 (rho = 200, 800, 3200; error/h^2 ~ 0.012).
TEST(OptimiserOracle, CircleThroughUnevenPointsConvergesWithOrderTwo) {
  const double R = 2, cx = 1, cy = -2;
  const std::vector<P> p = circle_points(R, cx, cy);
  const Circle_run coarse = solve_on_circle(p, R, cx, cy, 800), fine = solve_on_circle(p, R, cx, cy, 3200);
  const double order = std::log(coarse.error / fine.error) / std::log(coarse.h / fine.h);
  EXPECT_GT(order, 1.7);
  EXPECT_LT(fine.error, 0.03 * fine.h * fine.h);
  EXPECT_GT(fine.energy, 4 * pi * R * (1 - 1e-12));
  EXPECT_LT(fine.energy, coarse.energy);
}

// Rectangular elastica (beta = 0, tangents clamped, free length): from the inflection at (0,0)
// with tangent (1,0) to the vertical tangent at (1, y1): y1 = B(3/4,1/2)/4, L = varpi/2,
// int kappa^2 ds = 2.396280469471184, E L = pi. F = L0^2 int kappa^2 (eq. 5, alpha0 = 2).
TEST(OptimiserOracle, RectangularElastica) {
  const double y1 = 0.599070117367796, length = 1.311028777146060, bending = 2.396280469471184;
  const std::vector<P> p = {P(0, 0), P(1, y1)};
  const double L0 = std::hypot(1, y1);
  double e_error[2], l_error[2];
  const double rho[2] = {2000, 8000};
  for (int t = 0; t < 2; ++t) {
    Optimal_curve_options o = raw_weights();
    o.length_weight = 0;
    o.curvature_weight = 1;
    o.resolution = rho[t];
    o.constraints = {tangent(0, 1, 0), tangent(1, 0, 1)};
    const Optimal_curve_2<K> c(p, o);
    ASSERT_EQ(c.report().status, Optimal_curve_status::CONVERGED);
    const double e = c.energy() / (L0 * L0), l = polygon_length(c.polygon(), false);
    e_error[t] = std::abs(e - bending) / bending;
    l_error[t] = std::abs(l - length) / length;
    EXPECT_NEAR(e * l, pi, 20 * (e_error[t] + l_error[t]) * pi);
  }
  // Measured: relative errors 5.2e-4 / 1.5e-4 (E, L) at rho = 2000 (29 vertices), 1.7e-5 / 9.3e-5
  // at 8000 (55 vertices); E L = 3.14194 at 8000.
  EXPECT_LT(e_error[1], 3e-4);
  EXPECT_LT(l_error[1], 1e-4);
  EXPECT_LT(e_error[1], 0.5 * e_error[0]);
  EXPECT_LT(l_error[1], 0.7 * l_error[0]);
}

// Euler-Lagrange: kappa'' + kappa^3/2 - (beta/(2 beta0)) kappa = 0 for int beta + beta0 kappa^2.
// The borderline elastica x = 2 tanh s - s, y = -2 sech s (kappa = 2 sech s) is critical for
// beta/beta0 = 2; clamped at s = -S, S with the point at s = 0 in between.
TEST(OptimiserOracle, BorderlineElasticaAndItsEulerLagrangeResidual) {
  auto point = [](double s) { return P(2 * std::tanh(s) - s, -2 / std::cosh(s)); };
  auto direction = [](double s) {
    return std::array<double, 2>{{2 / (std::cosh(s) * std::cosh(s)) - 1, 2 * std::tanh(s) / std::cosh(s)}};
  };
  const double S = 1.2;
  const std::vector<P> p = {point(-S), point(0), point(S)};
  Optimal_curve_options o = raw_weights();
  o.resolution = 2000;
  const double L0 = polygon_length(p, false);
  o.length_weight = 1;
  o.curvature_weight = 0.5 / (L0 * L0);  // beta0/beta = 1/2 in the unscaled functional
  Point_constraint a = tangent(0, 0, 0), b = tangent(2, 0, 0);
  a.direction = direction(-S);
  b.direction = direction(S);
  o.constraints = {a, b};
  const Optimal_curve_2<K> c(p, o);
  ASSERT_EQ(c.report().status, Optimal_curve_status::CONVERGED);
  const std::vector<P>& q = c.polygon();
  // Distance of every vertex from the analytic curve (dense sampling + local refinement).
  double distance = 0;
  for (const P& v : q) {
    double best = std::numeric_limits<double>::infinity(), sbest = 0;
    for (int k = 0; k <= 2400; ++k) {
      const double s = -S + 2 * S * k / 2400.0, d = CGAL::squared_distance(v, point(s));
      if (d < best) { best = d; sbest = s; }
    }
    for (int k = -100; k <= 100; ++k) best = std::min(best, CGAL::squared_distance(v, point(sbest + k * 1e-5)));
    distance = std::max(distance, std::sqrt(best));
  }
  EXPECT_LT(distance, 2e-4);  // measured 5.3e-5 (65 vertices at rho = 2000)
  // The residual by finite differences along s on the discrete kappa, away from the three points.
  const std::vector<double> kappa = c.curvatures();
  double residual = 0;
  const std::size_t mid = c.interpolation_indices()[1];
  for (std::size_t j = 3; j + 3 < q.size(); ++j) {
    if (j + 2 >= mid && j <= mid + 2) continue;
    const double hm = std::sqrt(CGAL::squared_distance(q[j - 1], q[j])), hp = std::sqrt(CGAL::squared_distance(q[j], q[j + 1]));
    const double k2 = 2 * (hm * (kappa[j + 1] - kappa[j]) - hp * (kappa[j] - kappa[j - 1])) / (hm * hp * (hm + hp));
    residual = std::max(residual, std::abs(k2 + 0.5 * kappa[j] * kappa[j] * kappa[j] - kappa[j]));
  }
  // Scale: kappa^3/2 up to 4 on this arc. Measured max residual 0.039 (discretisation O(h^2)
  // plus the O(h^2)/h^2 noise of a second difference of an O(h^2)-accurate kappa).
  EXPECT_LT(residual, 0.1);
  EXPECT_NEAR(kappa[mid], 2.0, 5e-3);  // kappa(0) = 2 sech 0
}

// The clothoid kappa = a s is critical for int beta + beta1 kappa'^2 exactly when beta = beta1 a^2:
// on the polygon sampled from a clothoid the discrete reduced gradient (normal offsets) at the
// interior vertices vanishes to O(h^2) for beta = beta1 a^2 and not for another beta.
TEST(OptimiserOracle, ClothoidIsCriticalExactlyWhenBetaIsBeta1TimesASquared) {
  using namespace fair::internal::optimal;
  const double a = 1.5, s0 = 0.2, s1 = 1.4;
  auto sample = [&](std::size_t n) {  // midpoint-rule integration of the Fresnel integrals
    std::vector<Vec2> c;
    double x = 0, y = 0, s = 0;
    const int sub = 200;
    const double ds = (s1 - s0) / static_cast<double>(n - 1) / sub;
    for (int k = 0; k < 20000; ++k) {  // from 0 to s0
      const double t = (k + 0.5) * s0 / 20000;
      x += std::cos(0.5 * a * t * t) * s0 / 20000;
      y += std::sin(0.5 * a * t * t) * s0 / 20000;
    }
    s = s0;
    for (std::size_t j = 0; j < n; ++j) {
      c.push_back({{x, y}});
      for (int k = 0; k < sub && j + 1 < n; ++k) {
        const double t = s + (k + 0.5) * ds;
        x += std::cos(0.5 * a * t * t) * ds;
        y += std::sin(0.5 * a * t * t) * ds;
      }
      s += sub * ds;
    }
    return c;
  };
  auto residual = [&](const std::vector<Vec2>& c, double beta) {
    Functional f;
    f.reference_length = 1;
    f.length_weight.assign(c.size() - 1, beta);
    f.curvature_weight.assign(c.size(), 0);
    f.derivative_weight[1] = 1;
    std::vector<Vec2> g;
    energy_and_gradient(f, c, g);
    const std::vector<Vec2> n = vertex_normals(c, false);
    double r = 0;
    for (std::size_t j = 6; j + 6 < c.size(); ++j) r = std::max(r, std::abs(g[j][0] * n[j][0] + g[j][1] * n[j][1]));
    return r;
  };
  const std::vector<Vec2> coarse = sample(41), fine = sample(81);
  const double h = (s1 - s0) / 40;
  // The gradient of each term alone at a vertex is ~ beta kappa h (length) ~ 3 h here.
  const double critical_coarse = residual(coarse, a * a), critical_fine = residual(fine, a * a);
  const double wrong = residual(coarse, 2 * a * a);
  EXPECT_LT(critical_coarse, 0.05 * wrong);
  // Measured 3.8e-4 (h = 0.03), 1.2e-4 (h = 0.015): order 1.7; the wrong beta gives 0.12.
  EXPECT_LT(critical_fine, 0.45 * critical_coarse);
  EXPECT_GT(wrong, 0.5 * a * a * a * h);             // (beta - beta1 a^2) kappa h with kappa >= a s0
}

// ---------------------------------------------------------------------------------------------
// Structure.

TEST(OptimiserStructure, CollinearPointsGiveTheSegment) {
  const std::vector<P> p = {P(0, 0), P(1, 0.5), P(3, 1.5), P(4, 2)};
  const Optimal_curve_2<K> c(p);
  for (const P& q : c.polygon()) EXPECT_LT(segment_distance(q, p.front(), p.back()), 1e-14);
}

TEST(OptimiserStructure, LambdaZeroGivesTheInputPolygon) {
  Optimal_curve_options o = raw_weights();
  o.lambda = 0;
  const Optimal_curve_2<K> c(wave, o);
  EXPECT_EQ(c.report().status, Optimal_curve_status::CONVERGED);
  const std::vector<std::size_t>& idx = c.interpolation_indices();
  for (std::size_t i = 0; i + 1 < wave.size(); ++i)
    for (std::size_t j = idx[i]; j <= idx[i + 1]; ++j) EXPECT_LT(segment_distance(c.polygon()[j], wave[i], wave[i + 1]), 1e-12);
  EXPECT_NEAR(polygon_length(c.polygon(), false), polygon_length(wave, false), 1e-12);
}

TEST(OptimiserStructure, RigidMotionsAndScalingCommuteWithTheSolve) {
  const double angle = 0.7, scale = 3.5, tx = -4, ty = 9;
  auto map = [&](const P& q) {
    return P(scale * (std::cos(angle) * q.x() - std::sin(angle) * q.y()) + tx,
             scale * (std::sin(angle) * q.x() + std::cos(angle) * q.y()) + ty);
  };
  std::vector<P> moved;
  for (const P& q : wave) moved.push_back(map(q));
  Optimal_curve_options o = raw_weights();
  o.tolerance = 1e-14;
  o.constraints = {tangent(1, 1, 0.2)};
  Optimal_curve_options om = o;
  const double t0 = std::cos(angle) * 1 - std::sin(angle) * 0.2, t1 = std::sin(angle) * 1 + std::cos(angle) * 0.2;
  om.constraints = {tangent(1, t0, t1)};
  const Optimal_curve_2<K> c(wave, o), d(moved, om);
  ASSERT_EQ(c.polygon().size(), d.polygon().size());
  for (std::size_t j = 0; j < c.polygon().size(); ++j)
    EXPECT_LT(std::sqrt(CGAL::squared_distance(map(c.polygon()[j]), d.polygon()[j])), 1e-7 * scale);
  EXPECT_NEAR(d.energy(), scale * c.energy(), 1e-8 * d.energy());  // F(q c) = q F(c)
}

TEST(OptimiserStructure, ReversalGivesTheSameCurve) {
  std::vector<P> r(wave.rbegin(), wave.rend());
  Optimal_curve_options o = raw_weights();
  o.tolerance = 1e-14;  // solve to the rounding floor: positions to ~1e-8
  const Optimal_curve_2<K> c(wave, o), d(r, o);
  ASSERT_EQ(c.polygon().size(), d.polygon().size());
  const std::size_t n = c.polygon().size();
  for (std::size_t j = 0; j < n; ++j) EXPECT_LT(std::sqrt(CGAL::squared_distance(c.polygon()[j], d.polygon()[n - 1 - j])), 1e-7);
  EXPECT_NEAR(c.energy(), d.energy(), 1e-9 * c.energy());
}

TEST(OptimiserStructure, SymmetricDataGiveASymmetricCurve) {
  const std::vector<P> p = {P(-3, 0), P(-1, 2), P(0, 1), P(1, 2), P(3, 0)};  // mirror x -> -x
  Optimal_curve_options o = raw_weights();
  o.tolerance = 1e-14;
  const Optimal_curve_2<K> c(p, o);
  const std::size_t n = c.polygon().size();
  for (std::size_t j = 0; j < n; ++j) {
    const P& a = c.polygon()[j];
    const P& b = c.polygon()[n - 1 - j];
    EXPECT_NEAR(a.x(), -b.x(), 1e-7);
    EXPECT_NEAR(a.y(), b.y(), 1e-7);
  }
}

// ---------------------------------------------------------------------------------------------
// Constraints (Sec. 3.1).

// The unit bisector direction of the polygon at vertex j (the tangent the constraint fixes).
K::Vector_2 bisector(const std::vector<P>& q, std::size_t j) {
  K::Vector_2 u = q[j] - q[j - 1], w = q[j + 1] - q[j];
  u = u / std::sqrt(u.squared_length());
  w = w / std::sqrt(w.squared_length());
  const K::Vector_2 t = u + w;
  return t / std::sqrt(t.squared_length());
}

TEST(OptimiserConstraints, SingleNormalHoldsExactlyOnEveryLevel) {
  const std::vector<P> p = {P(0, 0), P(1, 1), P(2, 0), P(3, 1)};
  Optimal_curve_options o = raw_weights();
  Point_constraint n = tangent(1, -1, 1, Point_constraint_kind::NORMAL);  // left normal (-1,1): tangent (1,1)
  o.constraints = {n};
  const Optimal_curve_2<K> full(p, o);
  ASSERT_EQ(full.report().status, Optimal_curve_status::CONVERGED);
  const std::size_t levels = full.report().levels.size();
  ASSERT_GE(levels, 4u);
  bool converged_below = false;
  for (std::size_t l = 1; l <= levels; ++l) {
    o.max_levels = l;
    const Optimal_curve_2<K> c(p, o);
    const K::Vector_2 t = bisector(c.polygon(), c.interpolation_indices()[1]);
    EXPECT_LT(std::abs(t.x() - t.y()), 1e-12) << "level " << l;  // parallel to (1, 1)
    EXPECT_GT(t.x(), 0);
    // The level cap counts only when another level would be needed (reviewer finding 7), and not
    // for the levels the spline-resolution pass adds (hierarchy.h, review of issue 25 §3, M1):
    // CAPPED below some count of levels, CONVERGED from it on, CAPPED at one level.
    if (c.report().status == Optimal_curve_status::CONVERGED) converged_below = true;
    else {
      EXPECT_FALSE(converged_below) << "level " << l;
      EXPECT_EQ(c.report().status, Optimal_curve_status::CAPPED) << "level " << l;
    }
    if (l == 1) {
      EXPECT_EQ(c.report().status, Optimal_curve_status::CAPPED);
    }
    if (l == levels) {
      EXPECT_EQ(c.report().status, Optimal_curve_status::CONVERGED);
    }
  }
}

// An interior tangent swept over -90..90 degrees at each interior point of the wave (reviewer
// finding 2: 29 of 39 converged, 4 DIVERGING by a collapsing edge, before the re-anchoring, the
// tie's exact Hessian and the CAPPED label for a collapse). A finite minimiser exists (beta > 0
// bounds the length), so none may be DIVERGING; the tangent holds.
TEST(OptimiserConstraints, InteriorTangentSweepConvergesAndNeverDiverges) {
  std::size_t converged = 0, total = 0;
  for (std::size_t i = 1; i <= 3; ++i)
    for (int deg = -90; deg <= 90; deg += 15) {
      Optimal_curve_options o = raw_weights();
      const double a = deg * pi / 180;
      o.constraints = {tangent(i, std::cos(a), std::sin(a))};
      const Optimal_curve_2<K> c(wave, o);
      ++total;
      EXPECT_NE(c.report().status, Optimal_curve_status::DIVERGING) << "point " << i << " at " << deg << " deg";
      if (c.report().status != Optimal_curve_status::CONVERGED) continue;
      ++converged;
      const K::Vector_2 t = bisector(c.polygon(), c.interpolation_indices()[i]);
      EXPECT_LT(std::abs(t.x() * std::sin(a) - t.y() * std::cos(a)), 1e-9 * std::sqrt(t.squared_length())) << i << " " << deg;
      EXPECT_GT(t.x() * std::cos(a) + t.y() * std::sin(a), 0) << i << " " << deg;
    }
  EXPECT_GE(converged, total - 1);  // measured: 38 of 39 (point 1 at -75 deg: CAPPED)
}

// Scale invariance and translations far beyond the old window (reviewer finding 9: 1e+-100 threw,
// a translation by 1e12 ended CAPPED): the solve runs on normalised points.
TEST(OptimiserStructure, HugeTinyAndFarAwayInputGiveTheSameCurve) {
  const Optimal_curve_2<K> c(wave);
  ASSERT_EQ(c.report().status, Optimal_curve_status::CONVERGED);
  for (double q : {1e-150, 1e150}) {
    std::vector<P> w;
    for (const P& v : wave) w.push_back(P(q * v.x(), q * v.y()));
    const Optimal_curve_2<K> d(w);
    EXPECT_EQ(d.report().status, Optimal_curve_status::CONVERGED) << q;
    ASSERT_EQ(d.polygon().size(), c.polygon().size()) << q;
    EXPECT_NEAR(d.energy() / q, c.energy(), 1e-9 * c.energy()) << q;
    for (std::size_t j = 0; j < c.polygon().size(); ++j) {
      EXPECT_NEAR(d.polygon()[j].x() / q, c.polygon()[j].x(), 1e-9) << q << " " << j;
      EXPECT_NEAR(d.polygon()[j].y() / q, c.polygon()[j].y(), 1e-9) << q << " " << j;
    }
  }
  std::vector<P> far;
  for (const P& v : wave) far.push_back(P(v.x() + 1e12, v.y() - 1e12));
  const Optimal_curve_2<K> e(far);
  EXPECT_EQ(e.report().status, Optimal_curve_status::CONVERGED);
  ASSERT_EQ(e.polygon().size(), c.polygon().size());
  EXPECT_NEAR(e.energy(), c.energy(), 1e-6 * c.energy());
  for (std::size_t j = 0; j < c.polygon().size(); ++j) EXPECT_NEAR(e.polygon()[j].x() - 1e12, c.polygon()[j].x(), 1e-3) << j;
}

// The interpolation points are the user's points in an exact kernel too (reviewer finding 10).
TEST(OptimiserStructure, ExactKernelPointsAreReproducedExactly) {
  typedef fair_test::EPECK E;
  const std::vector<E::Point_2> p = {E::Point_2(0, 0), E::Point_2(E::FT(1) / 3, E::FT(5) / 7), E::Point_2(2, E::FT(1) / 3),
                                     E::Point_2(3, 1)};
  const Optimal_curve_2<E> c(p);
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_TRUE(c.polygon()[c.interpolation_indices()[i]] == p[i]) << i;
}

TEST(OptimiserConstraints, CornerKeepsBothTangentsAndZeroCurvature) {
  const std::vector<P> p = {P(0, 0), P(1, 1), P(2, 0), P(1, -1)};
  Optimal_curve_options o = raw_weights();
  o.closed = true;
  Point_constraint corner = tangent(1, 1, 0, Point_constraint_kind::CORNER);
  corner.outgoing = {{0, -1}};
  o.constraints = {corner};
  const Optimal_curve_2<K> c(p, o);
  ASSERT_EQ(c.report().status, Optimal_curve_status::CONVERGED);
  const std::size_t j = c.interpolation_indices()[1];
  const std::vector<P>& q = c.polygon();
  const K::Vector_2 in = q[j] - q[j - 1], out = q[j + 1] - q[j];
  EXPECT_LT(std::abs(in.y()), 1e-15);
  EXPECT_GT(in.x(), 0);
  EXPECT_LT(std::abs(out.x()), 1e-15);
  EXPECT_LT(out.y(), 0);
  EXPECT_EQ(c.curvatures()[j], 0.0);
}

// A closed curve through three collinear points with F = int kappa^2 (lambda = 1): a stadium
// whose flat side holds the points has int kappa^2 = 2 pi / r for any radius r: no finite
// minimiser, the curve inflates; reported as DIVERGING, not as converged or capped.
TEST(OptimiserConstraints, PureBendingThroughCollinearPointsDiverges) {
  Optimal_curve_options o = raw_weights();
  o.closed = true;
  o.length_weight = 0;
  const Optimal_curve_2<K> c({P(0, 0), P(1, 0), P(2, 0)}, o);
  EXPECT_EQ(c.report().status, Optimal_curve_status::DIVERGING);
  EXPECT_EQ(c.status(), Optimal_curve_status::DIVERGING);
  EXPECT_EQ(c.report().levels.back().status, Optimal_curve_status::DIVERGING);
  for (const P& q : c.polygon()) EXPECT_TRUE(std::isfinite(q.x()) && std::isfinite(q.y()));
  // The failure policy (doc/concepts.md): the same solve with throw_on_failure throws Solve_error
  // carrying the report the curve has without it.
  o.throw_on_failure = true;
  try {
    const Optimal_curve_2<K> thrown({P(0, 0), P(1, 0), P(2, 0)}, o);
    FAIL() << "a DIVERGING solve with throw_on_failure did not throw";
  } catch (const fair::Solve_error& e) {
    ASSERT_NE(e.report<fair::Optimal_curve_report>(), nullptr);
    EXPECT_EQ(*e.report<fair::Optimal_curve_report>(), c.report()) << *e.report<fair::Optimal_curve_report>();
    EXPECT_NE(std::string(e.what()).find("diverging"), std::string::npos) << e.what();
  }
}

// A level cap ends CAPPED: reported, or with throw_on_failure thrown with the same report; a
// CONVERGED solve never throws.
TEST(OptimiserConstraints, CappedSolveIsReportedOrThrown) {
  Optimal_curve_options o = raw_weights();
  o.max_levels = 1;
  const Optimal_curve_2<K> c(wave, o);
  ASSERT_EQ(c.status(), Optimal_curve_status::CAPPED);
  ASSERT_EQ(c.report().levels.size(), 1u);
  EXPECT_EQ(c.number_of_pieces(), c.polygon().size() - 1);  // a capped curve still has its spline
  std::ostringstream text;
  text << c.report();
  EXPECT_EQ(text.str().rfind("Optimal_curve_report{capped, energy ", 0), 0u) << text.str();
  EXPECT_NE(text.str().find("1 level, last level{vertices " + std::to_string(c.report().levels[0].vertices)),
            std::string::npos)
      << text.str();
  o.throw_on_failure = true;
  try {
    const Optimal_curve_2<K> thrown(wave, o);
    FAIL() << "a CAPPED solve with throw_on_failure did not throw";
  } catch (const fair::Solve_error& e) {
    ASSERT_NE(e.report<fair::Optimal_curve_report>(), nullptr);
    EXPECT_EQ(*e.report<fair::Optimal_curve_report>(), c.report());
    EXPECT_EQ(e.report<fair::Kappa_curve_report>(), nullptr);
  }
  o.max_levels = 30;
  const Optimal_curve_2<K> converged(wave, o);  // throw_on_failure set: no throw when CONVERGED
  EXPECT_EQ(converged.status(), Optimal_curve_status::CONVERGED);
  EXPECT_NE(converged.report(), c.report());
}

// spline() is the program's spline: fit_smoothing_spline_runs(polygon(), closed, interpolation_indices(),
// corner_vertices(), spline_smoothing().tolerance), one C2 run between corners; pieces() its cubic pieces.
TEST(OptimiserConstraints, SplineIsTheFitOfThePolygonBetweenCorners) {
  for (const bool closed : {false, true}) {
    Optimal_curve_options o = raw_weights();
    o.closed = closed;
    o.resolution = 100;
    Point_constraint corner = tangent(2, 1, 0, Point_constraint_kind::CORNER);
    corner.outgoing = {{0, -1}};
    o.constraints = {corner};
    const Optimal_curve_2<K> c(wave, o);
    ASSERT_EQ(c.status(), Optimal_curve_status::CONVERGED) << closed;
    EXPECT_EQ(c.is_closed(), closed);
    const fair::Polygon_spline_runs<K> fit =
        fair::fit_smoothing_spline_runs<K>(c.polygon(), closed, c.interpolation_indices(), c.corner_vertices(),
                                           c.spline_smoothing().tolerance)
            .runs;
    ASSERT_EQ(c.spline().splines.size(), fit.splines.size());
    EXPECT_EQ(c.spline().splines.size(), closed ? 1u : 2u);  // closed: one run from the corner around
    EXPECT_EQ(c.spline().first_vertex, fit.first_vertex);
    EXPECT_EQ(c.spline().max_distance, fit.max_distance);
    const std::size_t edges = closed ? c.polygon().size() : c.polygon().size() - 1;
    ASSERT_EQ(c.number_of_pieces(), edges);
    std::size_t j = 0;
    for (const fair::Cubic_spline_2<K>& run : fit.splines)
      for (const fair::Bezier_2<K>& piece : run.polynomial_pieces()) {
        ASSERT_LT(j, c.pieces().size());
        EXPECT_EQ(c.pieces()[j].control_points(), piece.control_points()) << j;
        ++j;
      }
    EXPECT_EQ(j, edges);
  }
}

// ---------------------------------------------------------------------------------------------
// The lambda design (eqs. 10-12, Sec. 3.2).

TEST(OptimiserLambda, FamilyHasMonotoneLength) {
  double previous = 0;
  for (int i = 0; i <= 10; ++i) {
    Optimal_curve_options o = raw_weights();
    o.lambda = 0.1 * i;
    o.resolution = 200;
    const Optimal_curve_2<K> c(wave, o);
    ASSERT_EQ(c.report().status, Optimal_curve_status::CONVERGED) << "lambda " << o.lambda;
    const double l = polygon_length(c.polygon(), false);
    EXPECT_GT(l, previous) << "lambda " << o.lambda;
    previous = l;
  }
}

// q held fixed (lambda_length_scale, Fig. 6a): eq. 10 is then beta = q (1 - lambda), beta0 =
// lambda, which is the plain weighted functional; and a larger q pulls the curve towards the
// polygon (shorter), monotonically.
TEST(OptimiserLambda, FixedQIsThePlainWeightedFunctional) {
  Optimal_curve_options fixed = raw_weights();
  fixed.lambda = 0.25;
  fixed.lambda_length_scale = 400;
  fixed.resolution = 200;
  Optimal_curve_options plain = raw_weights();
  plain.length_weight = 400 * 0.75;
  plain.curvature_weight = 0.25;
  plain.resolution = 200;
  const Optimal_curve_2<K> a(wave, fixed), b(wave, plain);
  ASSERT_EQ(a.report().status, Optimal_curve_status::CONVERGED);
  ASSERT_EQ(a.polygon().size(), b.polygon().size());
  for (std::size_t i = 0; i < a.polygon().size(); ++i)
    EXPECT_LT(std::sqrt(CGAL::squared_distance(a.polygon()[i], b.polygon()[i])), 1e-12);
  double previous = std::numeric_limits<double>::infinity();
  for (double q : {4.0, 40.0, 400.0, 4000.0}) {
    Optimal_curve_options o = fixed;
    o.lambda = 0.5;
    o.lambda_length_scale = q;
    const Optimal_curve_2<K> c(wave, o);
    ASSERT_EQ(c.report().status, Optimal_curve_status::CONVERGED) << "q " << q;
    const double l = polygon_length(c.polygon(), false);
    EXPECT_LT(l, previous) << "q " << q;
    previous = l;
  }
}

TEST(OptimiserLambda, LocalLambdaChangesOnlyNearbySegments) {
  const std::vector<P> p = {P(0, 0), P(1, 1.5), P(2, 0), P(3, 1.5), P(4, 0), P(5, 1.5), P(6, 0), P(7, 1.5)};
  Optimal_curve_options o = raw_weights();
  o.segment_lambda.assign(p.size() - 1, 0.5);
  o.resolution = 200;
  const Optimal_curve_2<K> base(p, o);
  o.segment_lambda[0] = 1;  // drag the first segment towards c_simp(1)
  const Optimal_curve_2<K> local(p, o);
  // Largest deviation of the changed curve from the base, per segment (by distance to the base polygon).
  auto deviation = [&](std::size_t segment) {
    double d = 0;
    const std::size_t a = local.interpolation_indices()[segment], b = local.interpolation_indices()[segment + 1];
    for (std::size_t j = a; j <= b; ++j) {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k + 1 < base.polygon().size(); ++k)
        best = std::min(best, segment_distance(local.polygon()[j], base.polygon()[k], base.polygon()[k + 1]));
      d = std::max(d, best);
    }
    return d;
  };
  const double near = deviation(0), far = deviation(5);
  EXPECT_GT(near, 1e-2);
  EXPECT_LT(far, 0.05 * near);
}

// ---------------------------------------------------------------------------------------------
// k-th derivative energies (Sec. 3.3) and the CG comparison.

// int beta + beta1 |kappa' L0^2|^2 with beta = 0.03 L0^4 (the beta >~ 0.03 beta1 L0^4):
// the discrete kappa' of the int kappa^2 curve jumps at the interpolation points (its EL equation
// is second order in kappa: the point forces make kappa' jump), that of the kappa' curve does not
// (fourth order: kappa' is continuous). Measured: the slope difference across a point over the
// largest neighbouring slope difference, min 6.6 for k = 0, max 1.2 for k = 1 (rho = 1000).
TEST(OptimiserDerivative, FirstDerivativeEnergyMakesKappaPrimeContinuous) {
  const double L0 = polygon_length(wave, false);
  auto jumps = [&](const Optimal_curve_2<K>& c, double& lo, double& hi) {
    const std::vector<double> k = c.curvatures();
    const std::vector<P>& q = c.polygon();
    auto slope = [&](std::size_t j) { return (k[j + 1] - k[j]) / std::sqrt(CGAL::squared_distance(q[j], q[j + 1])); };
    lo = std::numeric_limits<double>::infinity();
    hi = 0;
    for (std::size_t i = 1; i + 1 < wave.size(); ++i) {
      const std::size_t v = c.interpolation_indices()[i];
      const double across = std::abs(slope(v) - slope(v - 1));
      const double beside = std::max(std::abs(slope(v - 1) - slope(v - 2)), std::abs(slope(v + 1) - slope(v)));
      lo = std::min(lo, across / beside);
      hi = std::max(hi, across / beside);
    }
  };
  Optimal_curve_options o0 = raw_weights();
  o0.resolution = 1000;
  const Optimal_curve_2<K> c0(wave, o0);
  Optimal_curve_options o1 = o0;
  o1.length_weight = 0.03 * std::pow(L0, 4);
  o1.curvature_weight = 0;
  o1.derivative_weight[1] = 1;
  const Optimal_curve_2<K> c1(wave, o1);
  ASSERT_EQ(c0.report().status, Optimal_curve_status::CONVERGED);
  ASSERT_EQ(c1.report().status, Optimal_curve_status::CONVERGED);
  double lo0, hi0, lo1, hi1;
  jumps(c0, lo0, hi0);
  jumps(c1, lo1, hi1);
  EXPECT_GT(lo0, 4);
  EXPECT_LT(hi1, 2.5);
}

// k = 2, 3, 4 with the length term scaled like the k = 1 rule, beta = 0.03 L0^(2k+2) (eq. 5 weighs
// |kappa^(k) L0^(k+1)|^2 = L0^(2k+2) kappa^(k)^2): every level converges (with beta = 0.03 L0^4
// the k >= 2 solves end on the iteration cap with growing gradients, measured).
TEST(OptimiserDerivative, HigherDerivativeEnergiesConvergeWithScaledLengthTerm) {
  const double L0 = polygon_length(wave, false);
  for (int k = 2; k <= 4; ++k) {
    Optimal_curve_options o = raw_weights();
    o.resolution = 200;
    o.length_weight = 0.03 * std::pow(L0, 2 * k + 2);
    o.curvature_weight = 0;
    o.derivative_weight[k] = 1;
    const Optimal_curve_2<K> c(wave, o);
    EXPECT_EQ(c.report().status, Optimal_curve_status::CONVERGED) << "k = " << k;
    for (const auto& level : c.report().levels) EXPECT_LE(level.iterations, 80u) << "k = " << k;
  }
}

TEST(OptimiserSolver, ConjugateGradientReachesNoLowerEnergyAndNeedsMoreSteps) {
  Optimal_curve_options o = raw_weights();
  o.resolution = 200;
  const Optimal_curve_2<K> newton(wave, o);
  o.solver = fair::Optimal_curve_solver::CONJUGATE_GRADIENT;
  o.max_iterations_per_level = 20;  // the paper's 10-20 steps per level
  const Optimal_curve_2<K> cg(wave, o);
  EXPECT_EQ(newton.report().status, Optimal_curve_status::CONVERGED);
  EXPECT_GE(cg.energy(), newton.energy() * (1 - 1e-9));
  EXPECT_GT(cg.report().iterations, newton.report().iterations);
  for (const auto& level : newton.report().levels) EXPECT_LE(level.iterations, 12u);
  // The whole solve's gradient norm is that of the final polygon (the last level), and Newton's
  // is far below CG's after 20 steps per level.
  EXPECT_EQ(newton.report().gradient_norm, newton.report().levels.back().gradient_norm);
  EXPECT_EQ(cg.report().gradient_norm, cg.report().levels.back().gradient_norm);
  EXPECT_LT(newton.report().gradient_norm, cg.report().gradient_norm);
}

// ---------------------------------------------------------------------------------------------
// Bad input: typed errors naming the value.

template <class E>
void expect_error(const std::vector<P>& p, const Optimal_curve_options& o, const char* needle) {
  try {
    Optimal_curve_2<K> c(p, o);
    ADD_FAILURE() << "no error, expected one containing '" << needle << "'";
  } catch (const E& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(OptimiserErrors, BadPointsAndOptions) {
  Optimal_curve_options o = raw_weights();
  expect_error<fair::Invalid_input_error>({P(0, 0)}, o, "at least 2");
  o.closed = true;
  expect_error<fair::Invalid_input_error>({P(0, 0), P(1, 0)}, o, "at least 3");
  o.closed = false;
  expect_error<fair::Invalid_input_error>({P(0, 0), P(1, 0), P(1, 0)}, o, "coincide");
  expect_error<fair::Invalid_input_error>({P(0, 0), P(std::nan(""), 0)}, o, "non-finite");
  Optimal_curve_options b = o;
  b.lambda = 1.5;
  expect_error<fair::Precondition_error>(wave, b, "lambda = 1.5");
  b = o;
  b.length_weight = -1;
  expect_error<fair::Precondition_error>(wave, b, "length_weight (beta) = -1");
  b = o;
  b.length_weight = 0;
  b.curvature_weight = 0;
  expect_error<fair::Precondition_error>(wave, b, "every weight is zero");
  b = o;
  b.segment_lambda = {0.5, 0.5};
  expect_error<fair::Precondition_error>(wave, b, "segment_lambda has 2");
  b = o;
  b.lambda_length_scale = -1;
  expect_error<fair::Precondition_error>(wave, b, "lambda_length_scale (q) = -1");
  b = o;
  b.resolution = 0;
  expect_error<fair::Precondition_error>(wave, b, "resolution = 0");
  b = o;
  b.max_vertices = 0;  // reviewer finding 11: ended CAPPED
  expect_error<fair::Precondition_error>(wave, b, "max_vertices = 0");
}

TEST(OptimiserErrors, BadConstraints) {
  Optimal_curve_options o = raw_weights();
  o.constraints = {tangent(7, 1, 0)};
  expect_error<fair::Invalid_input_error>(wave, o, "point 7 is out of range");
  o.constraints = {tangent(1, 0, 0)};
  expect_error<fair::Invalid_input_error>(wave, o, "zero or non-finite direction");
  o.constraints = {tangent(1, 1, 0), tangent(1, 0, 1)};
  expect_error<fair::Invalid_input_error>(wave, o, "two constraints at point 1");
  // A normal along the line of three collinear points (the tangent across it) cannot be met.
  o.constraints = {tangent(1, 1, 0, Point_constraint_kind::NORMAL)};
  expect_error<fair::Invalid_input_error>({P(0, 0), P(1, 0), P(2, 0)}, o, "cannot be met");
  // A tangent back along a chord (reviewer finding 3: was an Internal_error from the tie setup).
  o.constraints = {tangent(1, -1, 0)};
  expect_error<fair::Invalid_input_error>({P(0, 0), P(1, 0), P(2, 0)}, o, "folds back");
}

// ---- Real data (issue 11, "converge on data nobody here wrote") ----
// Feather icons (MIT, Copyright (c) 2014-2017 Cole Bemis) and the Quick, Draw! "angel" strokes
// (CC BY 4.0, Google, Inc.): sources and licences in test/data/real/SOURCES.md. Hand-drawn strokes
// double back (hairpins); before the re-anchoring of solver.h 15 of the 246 sets ended DIVERGING or
// CAPPED at lambda = 0.5 (the fixed lines of motion crowded vertices together).

std::vector<kappa_real::Point_set> real_sets() {
  std::vector<kappa_real::Point_set> s = kappa_real::feather_polylines(FAIR_TEST_DATA_DIR "/real/feather_polylines.txt");
  const std::vector<kappa_real::Point_set> q = kappa_real::quickdraw_strokes(FAIR_TEST_DATA_DIR "/real/quickdraw_angel.json");
  s.insert(s.end(), q.begin(), q.end());
  return s;
}

// Every set converges at lambda = 0.5 and 0.9 since the fair reference of issue 25 §2 (two strokes
// whose lambda curve used to balloon and creep on the step cap at 0.5 / 0.9 converge now).

// The largest distance of a vertex of a from the polygon b (one side of the Hausdorff distance).
double polygon_distance(const std::vector<fair::internal::optimal::Vec2>& a,
                        const std::vector<fair::internal::optimal::Vec2>& b, bool closed) {
  double d = 0;
  for (const fair::internal::optimal::Vec2& v : a) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < (closed ? b.size() : b.size() - 1); ++j)
      nearest = std::min(nearest, segment_distance(P(v[0], v[1]), P(b[j][0], b[j][1]),
                                                   P(b[(j + 1) % b.size()][0], b[(j + 1) % b.size()][1])));
    d = std::max(d, nearest);
  }
  return d;
}

// Solves one set and checks it: the polygon interpolates the input exactly and is finite, and, as an
// independent check of the minimiser, the reversed points give the same curve (reversed) with the same
// energy (the solve is not symmetric in its order of work; measured on all 246 sets at lambda = 0.5:
// energies within 1e-11 relative; the vertices may sit elsewhere along the curve, 0.6 % of the extent
// on the activity icon at lambda = 0.9, so the curves are compared).
Optimal_curve_status check_real_set(const kappa_real::Point_set& s, double lambda) {
  namespace io = fair::internal::optimal;
  std::vector<io::Vec2> p;
  for (const kappa_real::Xy& q : s.points) p.push_back({{q.x, q.y}});
  std::vector<io::Vec2> reversed(p.rbegin(), p.rend());
  if (s.closed) std::rotate(reversed.begin(), reversed.end() - 1, reversed.end());  // starts at p_0 again
  Optimal_curve_options o = raw_weights();
  o.closed = s.closed;
  o.lambda = lambda;
  const io::Solve_result r = io::solve_optimal_curve(p, o), b = io::solve_optimal_curve(reversed, o);
  const std::string what = s.data_set + " " + s.name + " lambda " + std::to_string(lambda);
  const std::size_t m = p.size();
  EXPECT_EQ(r.interpolation_indices.size(), m) << what;
  for (std::size_t i = 0; i < m; ++i) {
    EXPECT_EQ(r.polygon[r.interpolation_indices[i]][0], p[i][0]) << what << " point " << i;
    EXPECT_EQ(r.polygon[r.interpolation_indices[i]][1], p[i][1]) << what << " point " << i;
  }
  for (const io::Vec2& v : r.polygon) EXPECT_TRUE(std::isfinite(v[0]) && std::isfinite(v[1])) << what;
  EXPECT_TRUE(std::isfinite(r.report.energy)) << what;
  EXPECT_EQ(b.report.status, r.report.status) << what;
  EXPECT_NEAR(b.report.energy, r.report.energy, 1e-8 * r.report.energy) << what;
  // The curves, not the vertices: two solves may place the vertices differently along the same curve.
  // Data symmetric under the half turn about their centre (p_i + p_{m-1-i} constant: the activity
  // icon) make the reversed problem the half-turned one: it has the mirror pair of minimisers, and
  // rounding may pick either, so the half-turned curve is accepted as well.
  const double tolerance = 1e-4 * io::polygon_extent(p);
  const double d = std::max(polygon_distance(r.polygon, b.polygon, s.closed), polygon_distance(b.polygon, r.polygon, s.closed));
  bool half_turn = !s.closed;
  for (std::size_t i = 0; i < m && half_turn; ++i)
    half_turn = p[i][0] + p[m - 1 - i][0] == p[0][0] + p[m - 1][0] && p[i][1] + p[m - 1 - i][1] == p[0][1] + p[m - 1][1];
  if (half_turn && !(d < tolerance)) {
    std::vector<io::Vec2> turned = r.polygon;
    for (io::Vec2& v : turned) v = {{p[0][0] + p[m - 1][0] - v[0], p[0][1] + p[m - 1][1] - v[1]}};
    EXPECT_LT(std::max(polygon_distance(turned, b.polygon, false), polygon_distance(b.polygon, turned, false)), tolerance) << what;
  } else {
    EXPECT_LT(d, tolerance) << what;
  }
  return r.report.status;
}

TEST(OptimiserRealData, FeatherAndQuickDrawSubsetConverges) {
  const std::vector<kappa_real::Point_set> sets = real_sets();
  ASSERT_EQ(sets.size(), 246u);
  std::size_t checked = 0;
  for (std::size_t k = 0; k < sets.size(); k += 6) {
    EXPECT_EQ(check_real_set(sets[k], 0.5), Optimal_curve_status::CONVERGED) << sets[k].name;
    ++checked;
  }
  EXPECT_GE(checked, 40u);
}

TEST(OptimiserRealData, StressEveryFeatherAndQuickDrawSetConverges) {
  const std::vector<kappa_real::Point_set> sets = real_sets();
  ASSERT_EQ(sets.size(), 246u);
  for (double lambda : {0.5, 0.9})
    for (std::size_t index = 0; index < sets.size(); index += fair_test::real_data_stride) {
      const kappa_real::Point_set& s = sets[index];
      const Optimal_curve_status status = check_real_set(s, lambda);
      EXPECT_EQ(status, Optimal_curve_status::CONVERGED)
          << s.data_set << " " << s.name << " lambda " << lambda;
    }
}

} // namespace

namespace {

// The lambda design's pieces (Sec. 3.2, eq. 12 times 4): phi_4 is the C4 smoothstep, i.e. its
// derivative is 630 x^4 (1 - x)^4 (checked by central differences against that closed form, an
// independent construction), so the blended lambda(s) and eta(s) are C4 across the segment middles
// and the points; q(eta) = 4 * 10^(3.5 eta + 0.08).
TEST(OptimiserLambdaDesign, Phi4BlendAndScale) {
  using fair::internal::optimal::blended;
  using fair::internal::optimal::lambda_scale;
  using fair::internal::optimal::phi4;
  EXPECT_EQ(phi4(0), 0);
  EXPECT_EQ(phi4(1), 1);
  EXPECT_NEAR(phi4(0.5), 0.5, 1e-15);
  const double h = 1e-5;
  for (int k = 1; k < 20; ++k) {
    const double x = k / 20.0;
    const double slope = (phi4(x + h) - phi4(x - h)) / (2 * h);
    EXPECT_NEAR(slope, 630 * std::pow(x * (1 - x), 4), 1e-7) << "x = " << x;
    // Horner with coefficients up to 540 in double: rounding up to ~9 * 540 eps ~ 1e-12
    EXPECT_NEAR(phi4(x) + phi4(1 - x), 1, 1e-12) << "symmetry, x = " << x;
  }
  const std::vector<double> v{0.2, 0.9, 0.5, 0.0};
  for (bool closed : {false, true}) {
    const std::size_t segments = v.size();
    for (std::size_t i = 0; i < segments; ++i) {
      EXPECT_NEAR(blended(v, closed, i, 0.5), v[i], 1e-15) << "the segment's own value at its middle";
      if (i + 1 < segments || closed) {
        const std::size_t j = (i + 1) % segments;
        EXPECT_NEAR(blended(v, closed, i, 1), blended(v, closed, j, 0), 1e-15) << "continuous at point " << j;
        EXPECT_NEAR(blended(v, closed, i, 1), 0.5 * (v[i] + v[j]), 1e-15) << "the averaged value at the point";
      }
    }
    if (!closed) {
      EXPECT_NEAR(blended(v, false, 0, 0), v[0], 1e-15) << "an open end keeps its segment's value";
      EXPECT_NEAR(blended(v, false, 3, 1), v[3], 1e-15);
    }
  }
  EXPECT_NEAR(lambda_scale(0), 4 * std::pow(10.0, 0.08), 1e-12);
  EXPECT_NEAR(lambda_scale(1) / lambda_scale(0), std::pow(10.0, 3.5), 1e-9);
}

} // namespace

// Fuzz finding optimal/regress-gradient-norm-overflow: a kappa'''' weight of 2.8e209 makes the
// reduced gradient's components about 1e160, finite, whose squares overflow: the reported norm was
// inf. It is now scaled by the largest component (reduced_system.h, euclidean_norm); checked here
// against the same norm in long double at 2^k scales, and on the finding itself.
TEST(OptimiserExtremes, GradientNormsOfHugeComponentsAreFinite) {
  using fair::internal::optimal::euclidean_norm;
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const int k : {-1070, -600, 0, 300, 1000, 1020}) {
    std::vector<double> v(7);
    for (double& a : v) a = std::ldexp(u(rng), k);
    long double s = 0;  // the oracle: the same norm at unit scale, in extended precision
    for (const double a : v) s += static_cast<long double>(std::ldexp(a, -k)) * std::ldexp(a, -k);
    const double expected = std::ldexp(static_cast<double>(std::sqrt(s)), k);
    EXPECT_NEAR(euclidean_norm(v) / expected, 1, 1e-15) << "2^" << k;
  }
  EXPECT_EQ(euclidean_norm({0, 0}), 0);
  Optimal_curve_options o;
  o.closed = true;
  o.solver = fair::Optimal_curve_solver::CONJUGATE_GRADIENT;
  o.discretisation = fair::Curvature_discretisation::TURNING_ANGLE;
  o.curvature_exponent = 2.671875;
  o.derivative_weight[4] = 2.8170090551184303e+209;
  o.resolution = 100;
  o.max_vertices = 4000;
  o.max_levels = 8;
  o.max_iterations_per_level = 40;
  const Optimal_curve_2<K> c({P(32, 5), P(0, 0), P(0, 3), P(32, 5), P(0.5, 0), P(1, 40)}, o);
  EXPECT_TRUE(std::isfinite(c.report().gradient_norm)) << c.report().gradient_norm;
  for (const fair::Optimal_curve_level& l : c.report().levels) EXPECT_TRUE(std::isfinite(l.gradient_norm));
  EXPECT_TRUE(std::isfinite(c.energy()));
}

// Fuzz finding optimal/regress-curvature-overflow: a closed curve at an extent of 1e-298 whose
// turn between two points 4e-309 apart has a curvature of about 1e11 at unit extent, 1e309 at its
// own. kappa(q c) = kappa(c) / q, so no double holds it: refused by name, not returned as inf.
TEST(OptimiserErrors, CurvaturesThatOverflowAtTheDataExtentAreRefused) {
  Optimal_curve_options o;
  o.closed = true;
  o.resolution = 20;
  const std::vector<P> p = {P(3.7241683106728043e-309, -9.1423200528744508e-311), P(4.5e-299, -8.6000000000000006e-299),
                            P(3.7241683106728043e-309, -9.1423200528744508e-311), P(0, 0)};
  expect_error<fair::Invalid_input_error>(p, o, "overflows double at the points' extent");
  // The same shape scaled up by 2^600 (exact: a power of two) solves, and its curvatures are the
  // refused ones scaled down by 2^600: finite, with the largest far beyond 1e300 / 2^600.
  std::vector<P> up;
  for (const P& q : p) up.push_back(P(std::ldexp(q.x(), 600), std::ldexp(q.y(), 600)));
  const Optimal_curve_2<K> c(up, o);
  double largest = 0;
  for (const double k : c.curvatures()) {
    ASSERT_TRUE(std::isfinite(k));
    largest = std::max(largest, std::abs(k));
  }
  EXPECT_GT(std::ldexp(largest, 600), std::numeric_limits<double>::max() / 1e10) << "at 2^-600 of this extent it overflows";
}

// Consecutive points closer than 2^-40 of the data's chord length (fuzz finding of session 19: two
// points 1 ulp apart made the final polygon's breakpoints equal): refused with both points named;
// just above the limit the curve is solved.
TEST(OptimiserErrors, PointsTooCloseToResolveAreRefusedByName) {
  Optimal_curve_options o;
  // The fuzz input: points at 1e-8 with the last two 7e-24 apart.
  expect_error<fair::Invalid_input_error>(
      {P(4.6972831674499663e-294, 0), P(2e-08, 3.0000000000000004e-08), P(-4.696323204354239e-261, -4.6963232011388926e-261),
       P(2e-08, 3.0000000000000004e-08), P(2e-08, 3.0000000000000011e-08)},
      o, "consecutive points 3 = (2e-08, 3.0000000000000004e-08) and 4 = (2e-08, 3.0000000000000011e-08)");
  const double length = 2 * std::sqrt(2.0);
  for (const double fraction : {0x1p-41, 0x1p-39}) {
    const std::vector<P> p = {P(0, 0), P(1, 1), P(2, 0), P(2 + fraction * length, fraction * length / 2)};
    if (fraction < fair::internal::optimal::resolved_edge_fraction) {
      expect_error<fair::Invalid_input_error>(p, o, "too close to be resolved reliably in double");
    } else {
      const Optimal_curve_2<K> c(p, o);
      EXPECT_EQ(c.report().status, fair::Optimal_curve_status::CONVERGED);
      EXPECT_FALSE(c.pieces().empty());
    }
  }
  // The same rule at the top of the double range, where the edges' differences and their sum
  // overflow (review R19: the check was skipped there): 2^-41 of the length is still refused.
  const double big = 0x1p1020;
  const double e = 0x1p-41 * 8 * std::sqrt(2.0);
  expect_error<fair::Invalid_input_error>({P(-4 * big, -4 * big), P(0, 4 * big), P(4 * big, -4 * big),
                                           P(4 * big, -4 * big + e * big)},
                                          o, "too close to be resolved reliably in double");
}

// Review R20: the check stays exact where the extent is tiny next to the coordinates (edges of
// 2^-40 at y = 2^1000: measured in units of the largest coordinate they were subnormal and the
// check was skipped) and at a subnormal extent (d * 2^40 against the length: 2^-40 of a subnormal
// length underflows).
TEST(OptimiserErrors, PointsTooCloseAreRefusedAtEveryExtent) {
  Optimal_curve_options o;
  expect_error<fair::Invalid_input_error>({P(0, 0x1p1000), P(0x1p-40, 0x1p1000), P(0x1.0000000000001p-40, 0x1p1000)}, o,
                                          "too close to be resolved reliably in double");
  const double s = 0x1p-1025;  // subnormal; s * 2^-41 is still a double
  expect_error<fair::Invalid_input_error>({P(0, 0), P(s, 0), P(s, s), P(s, 1.5 * s), P(s + std::ldexp(s, -41), 1.5 * s)}, o,
                                          "too close to be resolved reliably in double");
  o.closed = true;
  expect_error<fair::Invalid_input_error>({P(0, 0), P(0x1p-40, 0), P(0x1.0000000001p-40, 0), P(0x1p-39, 0x1p-40)}, o,
                                          "too close to be resolved reliably in double");
}

// Review R20: data whose extent or whose coarse levels' energies leave the double range are
// refused by name, never answered with an inf in the report or a message about an internal value.
TEST(OptimiserErrors, ExtentsAndLevelEnergiesBeyondTheDoubleRange) {
  Optimal_curve_options o;
  expect_error<fair::Invalid_input_error>({P(1.7e308, 0), P(1.7e308, 1e308), P(-1.7e308, 0)}, o,
                                          "the points' extent overflows double");
  o.closed = true;
  try {
    const Optimal_curve_2<K> c({P(0, 0), P(1.8e304, 0), P(9e303, 1.8e303)}, o);
    for (const fair::Optimal_curve_level& l : c.report().levels) EXPECT_TRUE(std::isfinite(l.energy)) << l.energy;
    ADD_FAILURE() << "its first level's energy overflows: expected a refusal";
  } catch (const fair::Invalid_input_error& e) {
    EXPECT_NE(std::string(e.what()).find("on a coarser level"), std::string::npos) << e.what();
  }
  // Open, at 1e307 (was a Precondition_error "max_distance inf": the rho extent summed the raw
  // coordinates): the extent is finite now, and the energy of the first, coarsest level overflows.
  o.closed = false;
  expect_error<fair::Invalid_input_error>({P(0, 0), P(1e307, 0), P(5e306, 1e306)}, o, "on a coarser level");
  // Review R20b: at 9e307 the polygon is solved but its spline's extent overflows (was a
  // Precondition_error about max_distance, an argument the user never gave).
  o.length_weight = 0;
  o.lambda = -1;
  o.resolution = 20;
  for (const double x : {9e307, 1e308, 7e307})
    expect_error<fair::Invalid_input_error>({P(x, 0), P(0, 1e307), P(-x, 0)}, o, "scale the points down");
}

// Fuzz finding optimal/regress-curve-beyond-the-double-range: a closed curve through points at
// y near -DBL_MAX bulges below them, beyond the double range; an infinite vertex reached the exact
// self-intersection count and GMP aborted on it. Refused by name now, and the count itself refuses
// a non-finite vertex with a typed error.
TEST(OptimiserErrors, CurveBeyondTheDoubleRangeIsRefused) {
  Optimal_curve_options o;
  o.closed = true;
  o.resolution = 20;
  expect_error<fair::Invalid_input_error>(
      {P(8.8001147761549367e+223, -1.7976930348623157e+308), P(8.8001147761549367e+223, -1.7976931348623157e+308),
       P(3.2000000000000002e+301, -1.7976928148623157e+308), P(3.5989503653498832e+299, -1.7976931255323878e+308),
       P(3.2000000000000002e+301, -1.7976928148623157e+308)},
      o, "the curve leaves the double range");
  const std::vector<std::array<double, 2>> square = {{{0, 0}}, {{1, 0}}, {{1, std::numeric_limits<double>::infinity()}}, {{0, 1}}};
  EXPECT_THROW(fair::internal::common::polygon_crossings(square, true), fair::Invalid_input_error);
}

// Review R20b: points whose extent is a few ulps of their coordinates (far from the origin): the
// curve's vertices round onto each other when mapped back; refused by name, not by the spline fit
// naming two polygon vertices the user never gave.
TEST(OptimiserErrors, ExtentOfAFewUlpsIsRefusedByName) {
  Optimal_curve_options o;
  std::vector<P> p;
  for (const auto& q : std::vector<std::array<double, 2>>{{0, 0}, {10, 3}, {20, -2}, {30, 1}, {40, 5}})
    p.push_back(P(1e20 + 16384 * q[0], 1e20 + 16384 * q[1]));
  expect_error<fair::Invalid_input_error>(p, o, "translate the points towards the origin");
}

// Fuzz, session 20: points far from the origin against their spread (all at x = T, y spanning
// 300). The mean of the coordinates carried an error of n ulps of T, 1e29 at T = 2.6e45, which
// became the extent: the hierarchy did not subdivide and the spline's tolerance was 1e27. With the
// refined centroid the solve at T is the solve at 0 (the same subdivision, energies and curvatures
// to 1e-12).
TEST(OptimiserExtremes, FarFromTheOriginTheSolveIsTheSolveAtTheOrigin) {
  const double ys[] = {1, -128, 1, 13, 1, 104, 0, 196, 1, 30};
  for (const double t : {0x1p150, 2.586886443029552e+45, 1e20}) {
    Optimal_curve_options o;
    o.derivative_weight[1] = 2;
    std::vector<P> at_origin, far;
    for (const double y : ys) {
      at_origin.push_back(P(0, y));
      far.push_back(P(t, y));
    }
    const Optimal_curve_2<K> a(at_origin, o), b(far, o);
    EXPECT_EQ(a.report().status, b.report().status) << t;
    EXPECT_EQ(a.polygon().size(), b.polygon().size()) << t;
    // equal up to the rounding of the centroid (the origin's plain mean, T's refined one)
    EXPECT_NEAR(a.energy() / b.energy(), 1, 1e-12) << t;
    ASSERT_EQ(a.curvatures().size(), b.curvatures().size()) << t;
    for (std::size_t i = 0; i < a.curvatures().size(); ++i)
      EXPECT_NEAR(a.curvatures()[i], b.curvatures()[i], 1e-12 * std::abs(a.curvatures()[i]) + 1e-300) << t << " vertex " << i;
  }
}

// Review R20: the spline fits at a subnormal extent (1 / scale was inf: NaN points).
TEST(OptimiserExtremes, SubnormalExtentFitsWithoutNaN) {
  Optimal_curve_options o;
  o.lambda = -1;
  o.resolution = 50;
  const Optimal_curve_2<K> c({P(0, 0), P(1e-309, 1e-312), P(2e-309, 0)}, o);
  ASSERT_FALSE(c.pieces().empty());
  for (const auto& piece : c.pieces())
    for (std::size_t i = 0; i <= piece.degree(); ++i)
      EXPECT_TRUE(std::isfinite(piece.control_point(i).x()) && std::isfinite(piece.control_point(i).y()));
  for (const double k : c.curvatures()) EXPECT_FALSE(std::isnan(k));
}
