// Tests of the discrete optimal-curve functional (issue 11 §1; include/fair/internal/optimal/):
// the true-curvature discretisations against closed forms, scale and rigid-motion invariance (eq. 5),
// the exact gradient against central differences and against the paper's own gradient formula of
// Sec. 2.3.2 (corrected by the factor 2), the exact Hessian against differences of the gradient and
// its band, corners and open ends against the split polygon, the banded/cyclic Cholesky against a
// dense solve, the normal-offset reduction against differences of F(c + delta n), and typed errors.

#include <fair/internal/optimal/functional.h>
#include <fair/internal/optimal/reduced_system.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {
// Named: test_optimal is one unity translation unit (test/CMakeLists.txt), and this using-directive
// must not reach the other sources' unnamed namespace.
namespace functional_tests {

using namespace fair::internal::optimal;
using fair::Curvature_discretisation;
using fair_test::pi;
const Curvature_discretisation all_discretisations[3] = {Curvature_discretisation::REGULARISED, Curvature_discretisation::CIRCUMCIRCLE,
                                                         Curvature_discretisation::TURNING_ANGLE};

::testing::AssertionResult near_rel(double x, double y, double rel, double scale = 0) {
  const double tol = rel * std::max({std::fabs(x), std::fabs(y), scale});
  if (std::fabs(x - y) <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << x << " vs " << y << " differ by " << std::fabs(x - y) << " > " << tol;
}

std::vector<Vec2> regular_polygon(std::size_t n, double r, double cx = 0, double cy = 0) {
  std::vector<Vec2> c(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * pi * static_cast<double>(i) / static_cast<double>(n);
    c[i] = Vec2{{cx + r * std::cos(t), cy + r * std::sin(t)}};
  }
  return c;
}

/// Seeded random polygon: a walk with edge lengths in [0.5, 1.5] and turns in [-max_turn, max_turn]
/// (closed: a perturbed circle, turns of both signs when the perturbation is large).
std::vector<Vec2> random_polygon(std::mt19937& rng, std::size_t n, bool closed, double max_turn = 1.0) {
  std::vector<Vec2> c(n);
  if (closed) {
    std::uniform_real_distribution<double> u(-0.25, 0.25);
    for (std::size_t i = 0; i < n; ++i) {
      const double t = 2 * pi * (static_cast<double>(i) + u(rng)) / static_cast<double>(n);
      const double r = 2 + u(rng);
      c[i] = Vec2{{r * std::cos(t), r * std::sin(t)}};
    }
    return c;
  }
  std::uniform_real_distribution<double> len(0.5, 1.5), turn(-max_turn, max_turn);
  double x = 0, y = 0, a = 0;
  for (std::size_t i = 0; i < n; ++i) {
    c[i] = Vec2{{x, y}};
    a += turn(rng);
    const double l = len(rng);
    x += l * std::cos(a);
    y += l * std::sin(a);
  }
  return c;
}

double polygon_length(const std::vector<Vec2>& c, bool closed) {
  double L = 0;
  const std::size_t e = closed ? c.size() : c.size() - 1;
  for (std::size_t i = 0; i < e; ++i) L += std::hypot(c[(i + 1) % c.size()][0] - c[i][0], c[(i + 1) % c.size()][1] - c[i][1]);
  return L;
}

/// A functional with every term switched on (or only the given derivative order), weights varying
/// per edge and vertex.
Functional make_functional(const std::vector<Vec2>& c, bool closed, int only_k = -1, double alpha = 2,
                           Curvature_discretisation d = Curvature_discretisation::REGULARISED) {
  Functional f;
  f.closed = closed;
  f.reference_length = polygon_length(c, closed);
  f.discretisation = d;
  const std::size_t n = c.size(), e = closed ? n : n - 1;
  f.length_weight.resize(e);
  f.curvature_weight.resize(n);
  for (std::size_t i = 0; i < e; ++i) f.length_weight[i] = only_k < 0 ? 0.5 + 0.1 * static_cast<double>(i % 3) : 0;
  for (std::size_t i = 0; i < n; ++i)
    f.curvature_weight[i] = (only_k < 0 || only_k == 0) ? 1 + 0.2 * static_cast<double>(i % 4) : 0;
  f.curvature_exponent = alpha;
  for (int k = 1; k <= 4; ++k) {
    f.derivative_weight[k] = (only_k < 0 || only_k == k) ? 1e-3 * k : 0;
    f.derivative_exponent[k] = alpha;
  }
  return f;
}

double max_abs(const std::vector<Vec2>& g) {
  double m = 0;
  for (const Vec2& v : g) m = std::max({m, std::fabs(v[0]), std::fabs(v[1])});
  return m;
}

// --- Discrete curvature ------------------------------------------------------------------------

// On a regular n-gon of circumradius r: phi = 2 pi/n, l = s = 2 r sin(pi/n). The true-curvature
// discretisations give phi/(s cos(phi/2.1)), phi/s and 2 sin(phi)/|c_{j+1} - c_{j-1}| = 1/r; all tend
// to 1/r (the paper's eq. 6/9 give half of that: doc/optimal_curves.md).
TEST(OptimalCurvature, RegularPolygonClosedFormsAndTrueCurvatureLimit) {
  const double r = 2.5;
  for (std::size_t n : {5u, 12u, 100u, 2000u}) {
    const std::vector<Vec2> c = regular_polygon(n, r, 1.0, -3.0);
    const double phi = 2 * pi / static_cast<double>(n), s = 2 * r * std::sin(pi / static_cast<double>(n));
    const double expected[3] = {phi / (s * std::cos(phi / 2.1)), 1 / r, phi / s};
    for (int d = 0; d < 3; ++d) {
      Functional f = make_functional(c, true, 0, 2, all_discretisations[d]);
      const std::vector<double> kappa = discrete_curvatures(f, c);
      for (std::size_t j = 0; j < n; ++j) EXPECT_TRUE(near_rel(kappa[j], expected[d], 1e-13 * static_cast<double>(n))) << "n " << n << " d " << d;
      // O(1/n^2) convergence to 1/r: |kappa r - 1| <= 2 phi^2 for REGULARISED and TURNING_ANGLE
      // (phi/(2 sin(phi/2)) = 1 + phi^2/24 + ..., 1/cos(phi/2.1) = 1 + phi^2/8.82 + ...).
      EXPECT_LE(std::fabs(kappa[0] * r - 1), 0.2 * phi * phi + 1e-12) << "n " << n << " d " << d;
      // Clockwise traversal: the same magnitude, negative sign.
      std::vector<Vec2> cw(c.rbegin(), c.rend());
      EXPECT_TRUE(near_rel(discrete_curvatures(f, cw)[3], -expected[d], 1e-13 * static_cast<double>(n)));
    }
  }
}

TEST(OptimalCurvature, EndsAndCornersHaveZeroCurvature) {
  std::mt19937 rng(11);
  const std::vector<Vec2> c = random_polygon(rng, 8, false);
  Functional f = make_functional(c, false);
  f.zero_curvature.assign(8, 0);
  f.zero_curvature[4] = 1;
  const std::vector<double> kappa = discrete_curvatures(f, c);
  EXPECT_EQ(kappa[0], 0.0);
  EXPECT_EQ(kappa[7], 0.0);
  EXPECT_EQ(kappa[4], 0.0);
  for (int j : {1, 2, 3, 5, 6}) EXPECT_NE(kappa[j], 0.0);
}

// Eq. 9 stays finite up to a full reversal phi = pi: |phi/cos(phi/2.1)| <= pi/cos(pi/2.1) = 42.04
// (the paper's "21.1" is half of it, at s = 1).
TEST(OptimalCurvature, RegularisedIsFiniteAtReversal) {
  const std::vector<Vec2> c = {{{0, 0}}, {{1, 0}}, {{0, 0}}};
  Functional f = make_functional(c, false, 0);
  const double kappa = discrete_curvatures(f, c)[1];
  EXPECT_TRUE(std::isfinite(kappa));
  EXPECT_NEAR(std::fabs(kappa), pi / std::cos(pi / 2.1), 1e-12);
  EXPECT_LT(std::fabs(kappa), 42.05);
  std::vector<Vec2> g;
  Block_banded_hessian h;
  EXPECT_TRUE(std::isfinite(energy_gradient_hessian(f, c, g, h)));
  f.discretisation = Curvature_discretisation::CIRCUMCIRCLE;  // 2 sin(phi)/|c_2 - c_0| = 0/0
  EXPECT_THROW(energy(f, c), fair::Invalid_input_error);
}

// --- The functional: closed form, invariances ---------------------------------------------------

// Regular n-gon, beta = 1, beta_0 = 1, alpha = 2: F = n l + n s (kappa L0)^2, and it tends to the
// continuous 2 pi r (1 + L0^2/r^2).
TEST(OptimalFunctional, RegularPolygonEnergyClosedForm) {
  const double r = 1.5;
  for (std::size_t n : {6u, 50u, 1000u}) {
    const std::vector<Vec2> c = regular_polygon(n, r);
    Functional f;
    f.closed = true;
    f.reference_length = 3;
    f.length_weight.assign(n, 1);
    f.curvature_weight.assign(n, 1);
    const double phi = 2 * pi / static_cast<double>(n), l = 2 * r * std::sin(pi / static_cast<double>(n));
    const double kappa = phi / (l * std::cos(phi / 2.1));
    const double nn = static_cast<double>(n);
    EXPECT_TRUE(near_rel(energy(f, c), nn * l + nn * l * kappa * kappa * 9, 1e-12));
    if (n == 1000) {
      EXPECT_TRUE(near_rel(energy(f, c), 2 * pi * r * (1 + 9 / (r * r)), 1e-5));
    }
  }
}

// Eq. 5: F(q c) = q F(c) when L0 scales with the curve; translations and rotations leave F unchanged.
TEST(OptimalFunctional, ScaleAndRigidMotionInvariance) {
  std::mt19937 rng(2026);
  for (int trial = 0; trial < 20; ++trial) {
    const bool closed = trial % 2 == 1;
    const std::vector<Vec2> c = random_polygon(rng, 9 + trial % 5, closed);
    for (int d = 0; d < 3; ++d) {
      const double alpha = 1 + 0.5 * (trial % 4);
      Functional f = make_functional(c, closed, -1, alpha, all_discretisations[d]);
      const double e = energy(f, c);
      const double q = 0.37 + trial;
      std::vector<Vec2> s = c, m = c;
      const double angle = 0.3 * trial, co = std::cos(angle), si = std::sin(angle);
      for (std::size_t i = 0; i < c.size(); ++i) {
        s[i] = Vec2{{q * c[i][0], q * c[i][1]}};
        m[i] = Vec2{{co * c[i][0] - si * c[i][1] + 5.0, si * c[i][0] + co * c[i][1] - 7.0}};
      }
      Functional fs = f;
      fs.reference_length = q * f.reference_length;
      EXPECT_TRUE(near_rel(energy(fs, s), q * e, 1e-11)) << "trial " << trial << " d " << d;
      EXPECT_TRUE(near_rel(energy(f, m), e, 1e-10)) << "trial " << trial << " d " << d;
    }
  }
}

// A corner (zero_curvature) splits the functional: F(open c with corner at j) = F(c_0..c_j) +
// F(c_j..c_{n-1}); a closed polygon with a corner at j is the open polygon c_j, ..., c_{j-1}, c_j.
TEST(OptimalFunctional, CornerSplitsIntoOpenPieces) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 6; ++trial) {
    const std::size_t n = 14, j = 6;
    const std::vector<Vec2> c = random_polygon(rng, n, false);
    const double alpha = trial % 2 ? 2.0 : 3.0;
    Functional f = make_functional(c, false, -1, alpha);
    f.zero_curvature.assign(n, 0);
    f.zero_curvature[j] = 1;
    auto piece = [&](std::size_t a, std::size_t b) {
      const std::vector<Vec2> p(c.begin() + static_cast<long>(a), c.begin() + static_cast<long>(b) + 1);
      Functional g = f;
      g.zero_curvature.clear();
      g.length_weight.assign(f.length_weight.begin() + static_cast<long>(a), f.length_weight.begin() + static_cast<long>(b));
      g.curvature_weight.assign(f.curvature_weight.begin() + static_cast<long>(a),
                                f.curvature_weight.begin() + static_cast<long>(b) + 1);
      return energy(g, p);
    };
    EXPECT_TRUE(near_rel(energy(f, c), piece(0, j) + piece(j, n - 1), 1e-12));

    const std::vector<Vec2> cc = random_polygon(rng, n, true);
    Functional fc = make_functional(cc, true, -1, alpha);
    fc.zero_curvature.assign(n, 0);
    fc.zero_curvature[j] = 1;
    std::vector<Vec2> open;
    Functional fo = fc;
    fo.closed = false;
    fo.zero_curvature.clear();
    fo.length_weight.clear();
    fo.curvature_weight.clear();
    for (std::size_t i = 0; i <= n; ++i) {
      open.push_back(cc[(j + i) % n]);
      fo.curvature_weight.push_back(fc.curvature_weight[(j + i) % n]);
      if (i < n) fo.length_weight.push_back(fc.length_weight[(j + i) % n]);
    }
    EXPECT_TRUE(near_rel(energy(fc, cc), energy(fo, open), 1e-12));
  }
}

// --- Gradient --------------------------------------------------------------------------------

// Central differences of the energy, every term on its own and all together, open and closed,
// several exponents and the three discretisations.
TEST(OptimalFunctional, GradientMatchesCentralDifferences) {
  std::mt19937 rng(7);
  int checked = 0;
  for (int closed = 0; closed < 2; ++closed)
    for (int k = -1; k <= 4; ++k)
      for (double alpha : {1.5, 2.0, 3.0})
        for (int d = 0; d < 3; ++d) {
          const std::vector<Vec2> c = random_polygon(rng, 11, closed != 0, 0.8);
          const Functional f = make_functional(c, closed != 0, k, alpha, all_discretisations[d]);
          std::vector<Vec2> g;
          const double e = energy_and_gradient(f, c, g);
          EXPECT_TRUE(near_rel(e, energy(f, c), 1e-14));
          const double scale = max_abs(g);
          ASSERT_GT(scale, 0);
          for (std::size_t i = 0; i < c.size(); ++i)
            for (int r = 0; r < 2; ++r) {
              const double h = 1e-6;
              std::vector<Vec2> p = c, m = c;
              p[i][r] += h;
              m[i][r] -= h;
              const double fd = (energy(f, p) - energy(f, m)) / (2 * h);
              EXPECT_TRUE(near_rel(g[i][r], fd, 1e-6, scale)) << "closed " << closed << " k " << k << " alpha " << alpha
                                                              << " d " << d << " vertex " << i;
              ++checked;
            }
        }
  EXPECT_EQ(checked, 2 * 6 * 3 * 3 * 22);
}

// Independent construction: the paper's analytic gradient of Sec. 2.3.2 for kappa_j (with the true
// curvature kappa = f(phi)/s, i.e. its formula without the 2 in the denominator), chained by hand
// into F = sum beta0 (kappa L0)^2 s_j + beta l_j.
TEST(OptimalFunctional, GradientMatchesPaperFormula) {
  std::mt19937 rng(99);
  for (int trial = 0; trial < 10; ++trial) {
    const bool closed = trial % 2 == 1;
    const std::vector<Vec2> c = random_polygon(rng, 10, closed, 1.2);
    Functional f = make_functional(c, closed, 0);
    const std::size_t n = c.size(), edges = closed ? n : n - 1;
    for (std::size_t e = 0; e < edges; ++e) f.length_weight[e] = 0.3;
    std::vector<Vec2> g;
    energy_and_gradient(f, c, g);
    std::vector<Vec2> paper(n, Vec2{{0, 0}});
    auto star = [](Vec2 v) { return Vec2{{v[1], -v[0]}}; };  // the paper's * (right normal)
    auto add = [&](std::size_t v, double s, Vec2 d) {
      paper[v][0] += s * d[0];
      paper[v][1] += s * d[1];
    };
    for (std::size_t e = 0; e < edges; ++e) {
      const Vec2 a = c[e], b = c[(e + 1) % n];
      const double l = std::hypot(b[0] - a[0], b[1] - a[1]);
      const Vec2 t{{(b[0] - a[0]) / l, (b[1] - a[1]) / l}};
      add(e, -0.3, t);
      add((e + 1) % n, 0.3, t);
    }
    const double L0 = f.reference_length;
    for (std::size_t j = closed ? 0 : 1; j < (closed ? n : n - 1); ++j) {
      const std::size_t im = (j + n - 1) % n, ip = (j + 1) % n;
      const Vec2 d0{{c[j][0] - c[im][0], c[j][1] - c[im][1]}}, d1{{c[ip][0] - c[j][0], c[ip][1] - c[j][1]}};
      const double l0 = std::hypot(d0[0], d0[1]), l1 = std::hypot(d1[0], d1[1]), s = 0.5 * (l0 + l1);
      const double X = d0[0] * d1[0] + d0[1] * d1[1];
      const Vec2 d1s = star(d1), d0s = star(d0);
      const double Y = d0[0] * d1s[0] + d0[1] * d1s[1];
      const double phi = std::atan2(Y, X), rho = phi / 2.1, fphi = phi / std::cos(rho);
      const double kappa = fphi / s;
      const double factor = 1 / std::cos(rho) + fphi * std::tan(rho) / 2.1;
      // dX/dc, dY/dc, 2 ds/dc for c_{j-1}, c_j, c_{j+1} (Sec. 2.3.2).
      const Vec2 dX[3] = {{{-d1[0], -d1[1]}}, {{d1[0] - d0[0], d1[1] - d0[1]}}, {{d0[0], d0[1]}}};
      const Vec2 dY[3] = {{{-d1s[0], -d1s[1]}}, {{d0s[0] + d1s[0], d0s[1] + d1s[1]}}, {{-d0s[0], -d0s[1]}}};
      const Vec2 t0{{d0[0] / l0, d0[1] / l0}}, t1{{d1[0] / l1, d1[1] / l1}};
      const Vec2 ds2[3] = {{{-t0[0], -t0[1]}}, {{t0[0] - t1[0], t0[1] - t1[1]}}, {{t1[0], t1[1]}}};
      const std::size_t v[3] = {im, j, ip};
      const double beta0 = f.curvature_weight[j];
      for (int m = 0; m < 3; ++m)
        for (int r = 0; r < 2; ++r) {
          const double dkappa = factor * (X * dY[m][r] - Y * dX[m][r]) / (s * (X * X + Y * Y)) - kappa / s * 0.5 * ds2[m][r];
          // d/dc [beta0 L0^2 kappa^2 s] = beta0 L0^2 (2 kappa s dkappa + kappa^2 ds)
          paper[v[m]][r] += beta0 * L0 * L0 * (2 * kappa * s * dkappa + kappa * kappa * 0.5 * ds2[m][r]);
        }
    }
    const double scale = max_abs(g);
    for (std::size_t i = 0; i < n; ++i)
      for (int r = 0; r < 2; ++r) EXPECT_TRUE(near_rel(g[i][r], paper[i][r], 1e-12, scale)) << "trial " << trial << " i " << i;
  }
}

// --- Hessian ---------------------------------------------------------------------------------

/// Differences of the exact gradient when coordinate r of vertex i moves by +-step and +-2 step:
/// h1 = g(+step) - g(-step), h2 = g(+2 step) - g(-2 step), and the five-point derivative (error
/// O(step^4); exponents like 1.5 make the third derivative large).
struct Gradient_differences {
  static constexpr double step = 1e-5;
  std::vector<Vec2> h1, h2;
  Gradient_differences(const Functional& f, const std::vector<Vec2>& c, std::size_t i, int r) {
    std::vector<Vec2> gp, gm, gp2, gm2;
    for (int m = 1; m <= 2; ++m) {
      std::vector<Vec2> p = c, q = c;
      p[i][r] += m * step;
      q[i][r] -= m * step;
      energy_and_gradient(f, p, m == 1 ? gp : gp2);
      energy_and_gradient(f, q, m == 1 ? gm : gm2);
    }
    h1 = h2 = gp;
    for (std::size_t j = 0; j < c.size(); ++j)
      for (int s = 0; s < 2; ++s) {
        h1[j][s] = gp[j][s] - gm[j][s];
        h2[j][s] = gp2[j][s] - gm2[j][s];
      }
  }
  double derivative(std::size_t j, int s) const { return (8 * h1[j][s] - h2[j][s]) / (12 * step); }
};

// The exact Hessian against central differences of the exact gradient; entries outside the band of
// half_bandwidth() are exactly zero (the gradient at a vertex farther than w does not change at all).
TEST(OptimalFunctional, HessianMatchesDifferencesOfGradientAndBand) {
  std::mt19937 rng(17);
  for (int closed = 0; closed < 2; ++closed)
    for (int k = -1; k <= 4; ++k)
      for (double alpha : {1.5, 2.0, 3.0}) {
        const Curvature_discretisation d = all_discretisations[(k + 3) % 3];
        const std::size_t n = 13 + static_cast<std::size_t>(k + 1);
        const std::vector<Vec2> c = random_polygon(rng, n, closed != 0, 0.8);
        const Functional f = make_functional(c, closed != 0, k, alpha, d);
        std::vector<Vec2> g;
        Block_banded_hessian h;
        const double e = energy_gradient_hessian(f, c, g, h);
        EXPECT_TRUE(near_rel(e, energy(f, c), 1e-14));
        const std::size_t w = f.half_bandwidth();
        EXPECT_EQ(h.half_bandwidth(), w);
        EXPECT_EQ(w, k >= 1 ? static_cast<std::size_t>(k) + 2 : k == 0 ? 2u : 6u);
        EXPECT_EQ(h.cyclic(), closed != 0);
        double scale = 0;
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t j = 0; j < n; ++j)
            if (h.in_band(i, j))
              for (int r = 0; r < 2; ++r)
                for (int s = 0; s < 2; ++s) {
                  scale = std::max(scale, std::fabs(h.at(i, j, r, s)));
                  EXPECT_EQ(h.at(i, j, r, s), h.at(j, i, s, r));  // one stored entry
                }
        for (std::size_t i = 0; i < n; ++i)
          for (int r = 0; r < 2; ++r) {
            const Gradient_differences d(f, c, i, r);
            for (std::size_t j = 0; j < n; ++j)
              for (int s = 0; s < 2; ++s) {
                if (h.in_band(i, j)) {
                  EXPECT_TRUE(near_rel(h.at(i, j, r, s), d.derivative(j, s), 1e-6, scale))
                      << "closed " << closed << " k " << k << " alpha " << alpha << " (" << i << "," << j << ")";
                } else {
                  EXPECT_EQ(d.h1[j][s], 0.0) << "coupling beyond the band: " << i << ", " << j;
                  EXPECT_EQ(d.h2[j][s], 0.0) << "coupling beyond the band: " << i << ", " << j;
                }
              }
          }
      }
}

// Closed polygons shorter than the stencils (n <= 2w + 1: the window wraps onto itself, the Hessian is
// stored dense): the exact Hessian still matches differences of the gradient.
TEST(OptimalFunctional, HessianOfTinyClosedPolygons) {
  std::mt19937 rng(31);
  for (std::size_t n : {3u, 4u, 5u, 7u, 13u}) {
    const std::vector<Vec2> c = random_polygon(rng, n, true);
    const Functional f = make_functional(c, true, -1, 2.0);
    std::vector<Vec2> g;
    Block_banded_hessian h;
    energy_gradient_hessian(f, c, g, h);
    double scale = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (int r = 0; r < 2; ++r) scale = std::max(scale, std::fabs(h.at(i, i, r, r)));
    for (std::size_t i = 0; i < n; ++i)
      for (int r = 0; r < 2; ++r) {
        const Gradient_differences d(f, c, i, r);
        for (std::size_t j = 0; j < n; ++j)
          for (int s = 0; s < 2; ++s) {
            ASSERT_TRUE(h.in_band(i, j));  // n <= 13 = 2w + 1: every pair
            EXPECT_TRUE(near_rel(h.at(i, j, r, s), d.derivative(j, s), 1e-6, scale)) << "n " << n << " (" << i << "," << j << ")";
          }
      }
  }
}

// A collinear polygon with exponents < 2: kappa = 0 everywhere, |x|^a at 0 gives a zero gradient and
// a finite Hessian (no NaN).
TEST(OptimalFunctional, StraightPolygonWithSmallExponentIsFinite) {
  std::vector<Vec2> c;
  for (int i = 0; i < 12; ++i) c.push_back(Vec2{{0.5 * i, 0.25 * i}});
  for (double alpha : {1.0, 1.5}) {
    Functional f = make_functional(c, false, -1, alpha);
    std::vector<Vec2> g;
    Block_banded_hessian h;
    const double e = energy_gradient_hessian(f, c, g, h);
    EXPECT_TRUE(std::isfinite(e));
    for (std::size_t i = 0; i < c.size(); ++i)
      for (std::size_t j = 0; j < c.size(); ++j) {
        if (!h.in_band(i, j)) continue;
        for (int r = 0; r < 2; ++r)
          for (int s = 0; s < 2; ++s) EXPECT_TRUE(std::isfinite(h.at(i, j, r, s)));
      }
    // Only the length term is left: the energy is its weighted length.
    double length = 0;
    for (std::size_t i = 0; i + 1 < c.size(); ++i) length += f.length_weight[i] * std::hypot(0.5, 0.25);
    EXPECT_TRUE(near_rel(e, length, 1e-14));
  }
}

// --- Normals and the normal-offset system ------------------------------------------------------

TEST(OptimalNormals, LeftUnitNormalsOfTravel) {
  const std::vector<Vec2> c = regular_polygon(16, 2.0, 1.0, 1.0);  // counter-clockwise
  const std::vector<Vec2> n = vertex_normals(c, true);
  for (std::size_t j = 0; j < c.size(); ++j) {
    // The left normal of counter-clockwise travel points to the centre.
    EXPECT_NEAR(n[j][0], -(c[j][0] - 1.0) / 2.0, 1e-14);
    EXPECT_NEAR(n[j][1], -(c[j][1] - 1.0) / 2.0, 1e-14);
  }
  const std::vector<Vec2> open = {{{0, 0}}, {{2, 0}}, {{2, 3}}};
  const std::vector<Vec2> no = vertex_normals(open, false);
  EXPECT_NEAR(no[0][0], 0, 1e-15);  // end: the edge's left normal
  EXPECT_NEAR(no[0][1], 1, 1e-15);
  EXPECT_NEAR(no[2][0], -1, 1e-15);
  EXPECT_NEAR(no[2][1], 0, 1e-15);
  EXPECT_NEAR(no[1][0], -std::sqrt(0.5), 1e-15);  // bisector of (1,0) and (0,1), rotated left
  EXPECT_NEAR(no[1][1], std::sqrt(0.5), 1e-15);
}

/// The solver's reduction to normal offsets (reduced_system.h) with the lines of motion `normals`,
/// no ties, and vertex j free iff free[j]: reduced index a <-> the a-th free vertex.
void normal_offset_reduction(const std::vector<Vec2>& c, bool closed, const std::vector<Vec2>& g,
                             const Block_banded_hessian& h, const std::vector<Vec2>& normals,
                             const std::vector<unsigned char>& free, std::vector<double>& rg, Banded_symmetric& rh) {
  Vertex_roles roles;
  roles.role.assign(c.size(), Vertex_role::FREE);
  for (std::size_t j = 0; j < c.size(); ++j)
    if (!free[j]) roles.role[j] = Vertex_role::FIXED;
  const Reduced_unknowns u = reduced_unknowns(c, normals, roles, closed);
  reduced_system(g, h, closed, u, rg, rh);
}

// The reduced gradient and Hessian are the derivatives of delta -> F(c + sum_a delta_a n_{f_a}) with
// fixed normals (the solver's reduction): checked by central differences in delta, with some
// vertices fixed; dropping them does not widen the band.
TEST(OptimalNormals, NormalOffsetSystemMatchesDifferences) {
  std::mt19937 rng(23);
  for (int closed = 0; closed < 2; ++closed)
    for (int k : {-1, 0, 2, 4}) {
      const std::size_t n = 15;
      const std::vector<Vec2> c = random_polygon(rng, n, closed != 0, 0.7);
      const Functional f = make_functional(c, closed != 0, k);
      const std::vector<Vec2> normals = vertex_normals(c, closed != 0);
      std::vector<unsigned char> free(n, 1);
      free[0] = free[5] = free[6] = 0;
      if (!closed) free[n - 1] = 0;
      std::vector<Vec2> g;
      Block_banded_hessian h;
      energy_gradient_hessian(f, c, g, h);
      std::vector<double> rg;
      Banded_symmetric rh;
      normal_offset_reduction(c, closed != 0, g, h, normals, free, rg, rh);
      std::vector<std::size_t> map;
      for (std::size_t j = 0; j < n; ++j)
        if (free[j]) map.push_back(j);
      ASSERT_EQ(rg.size(), map.size());
      ASSERT_EQ(rh.size(), map.size());
      EXPECT_EQ(rh.cyclic(), closed != 0);
      EXPECT_EQ(rh.half_bandwidth(), f.half_bandwidth());
      auto moved = [&](const std::vector<double>& delta) {
        std::vector<Vec2> p = c;
        for (std::size_t a = 0; a < map.size(); ++a)
          for (int r = 0; r < 2; ++r) p[map[a]][r] += delta[a] * normals[map[a]][r];
        return p;
      };
      double gscale = 0, hscale = 0;
      for (double v : rg) gscale = std::max(gscale, std::fabs(v));
      for (std::size_t a = 0; a < map.size(); ++a) hscale = std::max(hscale, std::fabs(rh.at(a, a)));
      const double step = 1e-6;
      for (std::size_t a = 0; a < map.size(); ++a) {
        std::vector<double> dp(map.size(), 0.0), dm(map.size(), 0.0);
        dp[a] = step;
        dm[a] = -step;
        const double fd = (energy(f, moved(dp)) - energy(f, moved(dm))) / (2 * step);
        EXPECT_TRUE(near_rel(rg[a], fd, 1e-6, gscale));
        std::vector<Vec2> gp, gm;
        energy_and_gradient(f, moved(dp), gp);
        energy_and_gradient(f, moved(dm), gm);
        for (std::size_t b = 0; b < map.size(); ++b) {
          const std::size_t j = map[b];
          const double fdh = ((gp[j][0] - gm[j][0]) * normals[j][0] + (gp[j][1] - gm[j][1]) * normals[j][1]) / (2 * step);
          if (rh.in_band(a, b)) {
            EXPECT_TRUE(near_rel(rh.at(a, b), fdh, 1e-6, hscale)) << "closed " << closed << " k " << k << " " << a << "," << b;
          } else {
            EXPECT_LE(std::fabs(fdh), 1e-9 * hscale) << "coupling beyond the reduced band " << a << "," << b;
          }
        }
      }
    }
}

// --- Banded solve ----------------------------------------------------------------------------

using fair_test::dense_solve;  // the oracle

TEST(OptimalBanded, CholeskyMatchesDenseSolveOpenAndCyclic) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int cases = 0;
  for (int cyclic = 0; cyclic < 2; ++cyclic)
    for (std::size_t w : {1u, 2u, 3u, 6u, 12u})
      for (std::size_t n : {1u, 2u, 3u, 5u, 8u, 13u, 14u, 25u, 40u}) {
        if (cyclic && n < 3) continue;
        Banded_symmetric a;
        a.reset(n, w, cyclic != 0);
        std::vector<std::vector<double>> dense(n, std::vector<double>(n, 0.0));
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t j = i; j < n; ++j)
            if (a.in_band(i, j)) {
              const double v = i == j ? 0.0 : u(rng);
              a.at(i, j) = v;
              dense[i][j] = dense[j][i] = v;
            }
        // Diagonally dominant: SPD.
        for (std::size_t i = 0; i < n; ++i) {
          double row = 0;
          for (std::size_t j = 0; j < n; ++j) row += std::fabs(dense[i][j]);
          a.at(i, i) = dense[i][i] = row + 0.5 + std::fabs(u(rng));
        }
        std::vector<double> b(n);
        for (double& v : b) v = u(rng);
        const std::vector<double> expected = dense_solve(dense, b);
        std::vector<double> x = b;
        ASSERT_TRUE(solve_banded_positive_definite(a, x)) << "n " << n << " w " << w << " cyclic " << cyclic;
        for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(x[i], expected[i], 1e-12) << "n " << n << " w " << w;
        // Not positive definite: a negative pivot -> false, the right-hand side untouched.
        a.add_to_diagonal(-1e3);
        std::vector<double> y = b;
        EXPECT_FALSE(solve_banded_positive_definite(a, y));
        EXPECT_EQ(y, b);
        ++cases;
      }
  EXPECT_EQ(cases, 5 * 9 + 5 * 7);
}

// The entries of a cyclic band are stored once per unordered pair (at(i, j) and at(j, i) are the same
// double, also across the wrap), and storage is O(n w).
TEST(OptimalBanded, OneEntryPerPairAcrossTheWrap) {
  for (std::size_t n : {5u, 7u, 20u}) {
    Banded_symmetric a;
    a.reset(n, 2, true);
    Block_banded_hessian h;
    h.reset(n, 3, true);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        if (a.in_band(i, j)) {
          EXPECT_EQ(&a.at(i, j), &a.at(j, i));
        }
        if (i != j && h.in_band(i, j)) {
          EXPECT_EQ(&h.at(i, j, 0, 1), &h.at(j, i, 1, 0));
        }
      }
    EXPECT_TRUE(a.in_band(0, n - 1));
    EXPECT_TRUE(a.in_band(n - 2, 0));
  }
  // A large cyclic band is not stored dense: far pairs are outside it.
  Banded_symmetric big;
  big.reset(1000, 3, true);
  EXPECT_TRUE(big.in_band(0, 997));
  EXPECT_FALSE(big.in_band(0, 500));
  EXPECT_THROW(big.at(0, 500), fair::Internal_error);
  Banded_symmetric open;
  open.reset(10, 2, false);
  EXPECT_FALSE(open.in_band(0, 9));
  EXPECT_THROW(open.at(0, 9), fair::Internal_error);
}

// --- Conditioning (issue 11, "What is known") ------------------------------------------------------

/// y = A x over the band only.
void band_multiply(const Banded_symmetric& a, const std::vector<double>& x, std::vector<double>& y) {
  const std::size_t n = a.size(), w = a.half_bandwidth();
  y.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t d = 0; d <= std::min(w, n - 1); ++d) {
      const std::size_t j = a.cyclic() ? (i + d) % n : i + d;
      if (j >= n || !a.in_band(i, j)) continue;
      y[i] += a.at(i, j) * x[j];
      if (j != i) y[j] += a.at(i, j) * x[i];
    }
}

/// x <- apply(x / |x|) repeated; returns the last Rayleigh quotient x.apply(x) of a unit x (power
/// iteration for apply = A, inverse iteration for apply = A^-1).
template <class Apply>
double rayleigh_iteration(std::vector<double> x, int iterations, Apply apply) {
  double quotient = 0;
  for (int it = 0; it < iterations; ++it) {
    double norm = 0;
    for (double v : x) norm += v * v;
    norm = std::sqrt(norm);
    for (double& v : x) v /= norm;
    const std::vector<double> y = apply(x);
    quotient = 0;
    for (std::size_t i = 0; i < x.size(); ++i) quotient += x[i] * y[i];
    x = y;
  }
  return quotient;
}

/// Condition number of the reduced Hessian on the regular n-gon of radius 1 with 8 equally spaced fixed
/// vertices, F = sum l_j + beta_k |kappa^(k) L0^(k+1)|^2 (k = 0: beta_0 L0^2 = 1, so that the unit
/// circle is the continuous minimiser; k = 1: beta_1 = 1): the largest eigenvalue by power iteration
/// (Rayleigh quotient), the smallest by inverse iteration with the banded Cholesky.
double reduced_condition_number(std::size_t n, int k) {
  const std::vector<Vec2> c = regular_polygon(n, 1.0);
  Functional f;
  f.closed = true;
  f.reference_length = 2 * pi;
  f.length_weight.assign(n, 1.0);
  f.curvature_weight.assign(n, k == 0 ? 1 / (4 * pi * pi) : 0.0);
  if (k > 0) f.derivative_weight[k] = 1.0;
  std::vector<Vec2> g;
  Block_banded_hessian h;
  energy_gradient_hessian(f, c, g, h);
  std::vector<unsigned char> free(n, 1);
  for (std::size_t q = 0; q < 8; ++q) free[q * n / 8] = 0;
  std::vector<double> rg;
  Banded_symmetric r;
  normal_offset_reduction(c, true, g, h, vertex_normals(c, true), free, rg, r);
  const std::size_t m = r.size();
  std::vector<double> x(m), z(m);
  for (std::size_t i = 0; i < m; ++i) {
    x[i] = std::sin(0.37 * static_cast<double>(i)) + 1.1;
    z[i] = std::cos(0.11 * static_cast<double>(i)) + 1.2;
  }
  const double largest = rayleigh_iteration(x, 400, [&](const std::vector<double>& v) {
    std::vector<double> y;
    band_multiply(r, v, y);
    return y;
  });
  const double smallest = 1 / rayleigh_iteration(z, 40, [&](const std::vector<double>& v) {
    std::vector<double> w = v;
    EXPECT_TRUE(solve_banded_positive_definite(r, w)) << "n " << n << " k " << k;
    return w;
  });
  return largest / smallest;
}

// The measured law (doc/optimal_curves.md, "Conditioning"): cond ~ 4.6e-5 n^4 for the kappa term and
// ~ 2.9e-7 n^6 for the kappa' term in this setting (largest eigenvalue ~ n^(2k+3), smallest ~ 1/n):
// the growth exponent 2k + 4, asserted between n = 100 and n = 400.
TEST(OptimalConditioning, ReducedHessianGrowsLikeNToThe2kPlus4) {
  for (int k : {0, 1}) {
    const double c100 = reduced_condition_number(100, k), c400 = reduced_condition_number(400, k);
    const double exponent = std::log(c400 / c100) / std::log(4.0);
    EXPECT_NEAR(exponent, 2 * k + 4, 0.1) << "k " << k << ": cond(100) " << c100 << ", cond(400) " << c400;
  }
}

// --- Errors ------------------------------------------------------------------------------------

TEST(OptimalFunctional, TypedErrorsNameTheOffendingIndex) {
  std::mt19937 rng(1);
  const std::vector<Vec2> c = random_polygon(rng, 6, false);
  const Functional f = make_functional(c, false);
  auto message_of = [&](const Functional& g, const std::vector<Vec2>& p) -> std::string {
    try {
      energy(g, p);
    } catch (const fair::Error& e) {
      return e.what();
    }
    return "";
  };
  std::vector<Vec2> bad = c;
  bad[3][1] = std::nan("");
  EXPECT_THROW(energy(f, bad), fair::Invalid_input_error);
  EXPECT_NE(message_of(f, bad).find("vertex 3"), std::string::npos);
  bad = c;
  bad[4] = bad[3];
  EXPECT_THROW(energy(f, bad), fair::Invalid_input_error);
  EXPECT_NE(message_of(f, bad).find("3 and 4"), std::string::npos);
  std::vector<Vec2> g;
  EXPECT_THROW(energy_and_gradient(f, bad, g), fair::Invalid_input_error);
  EXPECT_THROW(vertex_normals(bad, false), fair::Invalid_input_error);
  EXPECT_THROW(energy(f, std::vector<Vec2>(1, Vec2{{0, 0}})), fair::Invalid_input_error);
  Functional h = f;
  h.length_weight[2] = -1;
  EXPECT_THROW(energy(h, c), fair::Precondition_error);
  EXPECT_NE(message_of(h, c).find("length_weight[2]"), std::string::npos);
  h = f;
  h.curvature_weight[1] = INFINITY;
  EXPECT_THROW(energy(h, c), fair::Precondition_error);
  h = f;
  h.derivative_weight[3] = std::nan("");
  EXPECT_THROW(energy(h, c), fair::Precondition_error);
  h = f;
  h.curvature_exponent = 0.5;
  EXPECT_THROW(energy(h, c), fair::Precondition_error);
  h = f;
  h.reference_length = 0;
  EXPECT_THROW(energy(h, c), fair::Precondition_error);
  h = f;
  h.curvature_weight.pop_back();
  EXPECT_THROW(energy(h, c), fair::Precondition_error);
  // Finite but overflowing: an edge of 1e-200 makes (kappa' L0^2)^2 ~ 1e400.
  bad = c;
  bad[2] = Vec2{{0, 0.3}};
  bad[3] = Vec2{{1e-200, 0.3}};
  EXPECT_THROW(energy(f, bad), fair::Invalid_input_error);
  EXPECT_NE(message_of(f, bad).find("shortest edge 2"), std::string::npos);
  Block_banded_hessian hb;
  EXPECT_THROW(energy_gradient_hessian(f, bad, g, hb), fair::Invalid_input_error);
  h = f;
  h.closed = true;  // length_weight has n - 1 entries, a closed polygon needs n
  EXPECT_THROW(energy(h, c), fair::Precondition_error);
}

}  // namespace functional_tests
}  // namespace
