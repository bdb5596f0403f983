// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of the alternating passes of Section 5.1 (Yan, Schiller, Schaefer; internal/kappa/refinement.h)
// in double: the eq. 7 root against a long-double bisection, eq. 18 against a dense solve with complete pivoting
// (open and closed, diagonally dominant and not), one refinement pass against a
// straightforward reference written here from the paper's formulas in absolute coordinates,
// and circle reproduction (the paper's main property) by the passes alone.

#include <fair/internal/kappa/refinement.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace kp = fair::internal::kappa;

const double eps = std::numeric_limits<double>::epsilon();

// ------------------------------------------------------------------ references

long double eq7_ld(long double A, long double B, long double C, long double w, long double t) {
  const long double u = 1 - t;
  return -w * A * u * u * u * u - (A + B) * u * u * u * t + (B + C) * u * t * t * t + w * C * t * t * t * t;
}

// Root of eq. 7 by bisection in long double (f(0) < 0 < f(1)), to the long double resolution.
long double eq7_bisection(double A, double B, double C, double w) {
  long double lo = 0, hi = 1;
  for (int k = 0; k < 200 && hi - lo > 0; ++k) {
    const long double mid = (lo + hi) / 2;
    if (mid <= lo || mid >= hi) break;
    const long double f = eq7_ld(A, B, C, w, mid);
    if (f == 0) return mid;
    if (f < 0) lo = mid; else hi = mid;
  }
  return (lo + hi) / 2;
}

// Bound on the error of a double root: a few eps plus the rounding error of the double
// evaluation of f (a small multiple of eps times the sum of |terms|) divided by |f'|.
double eq7_root_tolerance(double A, double B, double C, double w, double t) {
  const double u = 1 - t;
  const double terms = std::abs(w * A) * u * u * u * u + std::abs(A + B) * u * u * u * t +
                       std::abs(B + C) * u * t * t * t + std::abs(w * C) * t * t * t * t;
  const double df = 4 * w * A * u * u * u - (A + B) * (u * u * u - 3 * u * u * t) +
                    (B + C) * (3 * u * t * t - t * t * t) + 4 * w * C * t * t * t;
  return 16 * eps + 32 * eps * (terms + eps * (std::abs(A) + std::abs(B) + std::abs(C))) / std::abs(df);
}

struct Pt {
  double x, y;
};
Pt operator+(Pt a, Pt b) { return {a.x + b.x, a.y + b.y}; }
Pt operator-(Pt a, Pt b) { return {a.x - b.x, a.y - b.y}; }
Pt operator*(double s, Pt a) { return {s * a.x, s * a.y}; }
double dot(Pt a, Pt b) { return a.x * b.x + a.y * b.y; }
double cross(Pt a, Pt b) { return a.x * b.y - a.y * b.x; }

Pt Q(const kp::Problem& pb, std::size_t i) { return {pb.qx[i], pb.qy[i]}; }
Pt P(const kp::Problem& pb, const fair::Kappa_solver_state& st, std::size_t i) { return {pb.qx[i] + st.dx[i], pb.qy[i] + st.dy[i]}; }
std::size_t prev(const kp::Problem& pb, std::size_t i) { return i == 0 ? pb.n - 1 : i - 1; }
std::size_t next(const kp::Problem& pb, std::size_t i) { return i + 1 == pb.n ? 0 : i + 1; }

/// A dense row-major matrix, for the oracles below.
struct Dense {
  std::size_t rows = 0, cols = 0;
  std::vector<double> a;
  Dense() = default;
  Dense(std::size_t r, std::size_t c) : rows(r), cols(c), a(r * c, 0.0) {}
  double& operator()(std::size_t i, std::size_t j) { return a[i * cols + j]; }
  double operator()(std::size_t i, std::size_t j) const { return a[i * cols + j]; }
};

/// X = M^{-1} B by Gaussian elimination with complete pivoting: the dense oracle, independent of
/// the tridiagonal, bordered and banded solves under test (and of any library code).
Dense solve_complete_pivoting(Dense M, Dense B) {
  const std::size_t n = M.rows, m = B.cols;
  std::vector<std::size_t> column(n);
  for (std::size_t k = 0; k < n; ++k) column[k] = k;
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k, q = k;
    for (std::size_t i = k; i < n; ++i)
      for (std::size_t j = k; j < n; ++j)
        if (std::abs(M(i, j)) > std::abs(M(p, q))) { p = i; q = j; }
    for (std::size_t j = 0; j < n; ++j) std::swap(M(k, j), M(p, j));
    for (std::size_t c = 0; c < m; ++c) std::swap(B(k, c), B(p, c));
    for (std::size_t i = 0; i < n; ++i) std::swap(M(i, k), M(i, q));
    std::swap(column[k], column[q]);
    for (std::size_t i = k + 1; i < n; ++i) {
      const double f = M(i, k) / M(k, k);
      if (f == 0.0) continue;
      for (std::size_t j = k; j < n; ++j) M(i, j) -= f * M(k, j);
      for (std::size_t c = 0; c < m; ++c) B(i, c) -= f * B(k, c);
    }
  }
  Dense Y(n, m), X(n, m);
  for (std::size_t k = n; k-- > 0;)
    for (std::size_t c = 0; c < m; ++c) {
      double s = B(k, c);
      for (std::size_t j = k + 1; j < n; ++j) s -= M(k, j) * Y(j, c);
      Y(k, c) = s / M(k, k);
    }
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t c = 0; c < m; ++c) X(column[k], c) = Y(k, c);
  return X;
}

// Eq. 18 assembled densely in the unknowns P_i (absolute coordinates) straight from the paper:
// (1-t)^2 (P_{i,0} - Q_i) + 2(1-t)t w (P_i - Q_i) + t^2 (P_{i,2} - Q_i) = 0 with eq. 9 joins
// P_{i,0} = (1-l_i) P_{i-1} + l_i P_i, P_{i,2} = (1-l_{i+1}) P_i + l_{i+1} P_{i+1} (open ends: the
// fixed end points): M P = rhs.
void dense_eq18_system(const kp::Problem& pb, const fair::Kappa_solver_state& st, Dense& M, Dense& rhs) {
  const std::size_t n = pb.n;
  M = Dense(n, n);
  rhs = Dense(n, 2);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = st.t[i], u = 1 - t, c0 = u * u, c1 = 2 * u * t * st.w[i], c2 = t * t;
    const Pt q = Q(pb, i);
    rhs(i, 0) += (c0 + c1 + c2) * q.x;
    rhs(i, 1) += (c0 + c1 + c2) * q.y;
    M(i, i) += c1;
    if (pb.has_start(i)) {
      M(i, prev(pb, i)) += c0 * (1 - st.lambda[i]);
      M(i, i) += c0 * st.lambda[i];
    } else {
      rhs(i, 0) -= c0 * pb.sx;
      rhs(i, 1) -= c0 * pb.sy;
    }
    if (pb.has_end(i)) {
      M(i, i) += c2 * (1 - st.lambda[next(pb, i)]);
      M(i, next(pb, i)) += c2 * st.lambda[next(pb, i)];
    } else {
      rhs(i, 0) -= c2 * pb.ex;
      rhs(i, 1) -= c2 * pb.ey;
    }
  }
}

// Solved by complete pivoting (solve_complete_pivoting); returns d = P - Q.
void dense_eq18(const kp::Problem& pb, const fair::Kappa_solver_state& st, std::vector<double>& dx, std::vector<double>& dy) {
  Dense M, rhs;
  dense_eq18_system(pb, st, M, rhs);
  const Dense X = solve_complete_pivoting(M, rhs);
  dx.resize(pb.n);
  dy.resize(pb.n);
  for (std::size_t i = 0; i < pb.n; ++i) {
    dx[i] = X(i, 0) - pb.qx[i];
    dy[i] = X(i, 1) - pb.qy[i];
  }
}

// End control points of piece i (eq. 9; open ends: the fixed end points).
Pt piece_start(const kp::Problem& pb, const fair::Kappa_solver_state& st, std::size_t i) {
  if (!pb.has_start(i)) return {pb.sx, pb.sy};
  const double l = st.lambda[i];
  return (1 - l) * P(pb, st, prev(pb, i)) + l * P(pb, st, i);
}
Pt piece_end(const kp::Problem& pb, const fair::Kappa_solver_state& st, std::size_t i) {
  if (!pb.has_end(i)) return {pb.ex, pb.ey};
  const double l = st.lambda[next(pb, i)];
  return (1 - l) * P(pb, st, i) + l * P(pb, st, next(pb, i));
}

// One pass of Algorithm 1 (lines 7-10), written straightforwardly from the paper.
void reference_pass(const kp::Problem& pb, fair::Kappa_solver_state& st) {
  const std::size_t n = pb.n;
  std::vector<double> w(n), t(n), lambda = st.lambda;
  for (std::size_t i = 0; i < n; ++i) {
    const Pt p0 = piece_start(pb, st, i), p1 = P(pb, st, i), p2 = piece_end(pb, st, i);
    // Weight: 1, fixed, or eqs. 15-16 (clamped minimum-eccentricity weight).
    w[i] = 1;
    if (pb.mode == fair::Kappa_weights::FIXED) w[i] = pb.weight[i];
    if (pb.mode == fair::Kappa_weights::AUTOMATIC) {
      const double what = std::sqrt(dot(p2 - p0, p2 - p0) / (2 * (dot(p0 - p1, p0 - p1) + dot(p2 - p1, p2 - p1))));
      w[i] = std::max(pb.tension[i] * what, pb.clamp);
    }
    // t: the root of eq. 7 for E0 = P_{i,0} - Q_i, E2 = P_{i,2} - Q_i, clamped.
    const Pt E0 = p0 - Q(pb, i), E2 = p2 - Q(pb, i);
    const double A = dot(E0, E0), B = dot(E0, E2), C = dot(E2, E2);
    const double r = (A > 0 && C > 0) ? static_cast<double>(eq7_bisection(A, B, C, w[i])) : st.t[i];
    t[i] = std::min(std::max(r, 1e-6), 1 - 1e-6);
  }
  // lambda: eq. 10, |kappa_{i-1}(1)| = |kappa_i(0)| with the end curvatures of eq. 5:
  // (1-l_{i-1}) |(P_{i-1} - P_{i-2}) x (P_i - P_{i-1})| / (w_{i-1}^2 l^2)
  //   = l_{i+1} |(P_i - P_{i-1}) x (P_{i+1} - P_i)| / (w_i^2 (1-l)^2).
  for (std::size_t i = 0; i < n; ++i) {
    if (!pb.has_start(i)) continue;
    const std::size_t im = prev(pb, i);
    const Pt pm = P(pb, st, im), pi = P(pb, st, i);
    const Pt before = pb.has_start(im) ? (1 - st.lambda[im]) * (pm - P(pb, st, prev(pb, im))) : pm - Pt{pb.sx, pb.sy};
    const Pt after = pb.has_end(i) ? st.lambda[next(pb, i)] * (P(pb, st, next(pb, i)) - pi) : Pt{pb.ex, pb.ey} - pi;
    const double a = std::sqrt(std::abs(cross(before, pi - pm))) / w[im];
    const double b = std::sqrt(std::abs(cross(pi - pm, after))) / w[i];
    if (a + b > 0) lambda[i] = std::min(std::max(a / (a + b), 1e-3), 1 - 1e-3);
  }
  st.w = w;
  st.t = t;
  st.lambda = lambda;
  dense_eq18(pb, st, st.dx, st.dy);
}

// ------------------------------------------------------------------ data

// Closed (or open: first and last point fixed) star-shaped polygon, alternately convex and
// concave corners, n interpolated points.
kp::Problem star(std::size_t n, bool closed, fair::Kappa_weights mode, unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> U(0, 1);
  const std::size_t m = closed ? n : n + 2;
  std::vector<double> x(m), y(m);
  for (std::size_t i = 0; i < m; ++i) {
    const double a = (closed ? 2 * M_PI : 3.0) * (i + 0.3 * (U(g) - 0.5)) / m;
    const double r = 1 + 0.2 * (i % 2 ? 1 : -1) * (0.5 + U(g));
    x[i] = r * std::cos(a);
    y[i] = r * std::sin(a);
  }
  kp::Problem pb;
  pb.closed = closed;
  pb.n = n;
  pb.mode = mode;
  const std::size_t first = closed ? 0 : 1;
  pb.qx.assign(x.begin() + first, x.begin() + first + n);
  pb.qy.assign(y.begin() + first, y.begin() + first + n);
  if (!closed) { pb.sx = x[0]; pb.sy = y[0]; pb.ex = x[m - 1]; pb.ey = y[m - 1]; }
  pb.weight.resize(n);
  pb.tension.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    pb.weight[i] = 0.5 + U(g);
    pb.tension[i] = 0.8 + 0.4 * U(g);
  }
  return pb;
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// ------------------------------------------------------------------ eq. 7

TEST(KappaRefinement, Eq7RootAgreesWithLongDoubleBisection) {
  std::mt19937 g(7);
  std::uniform_real_distribution<double> U(-1, 1), W(0.05, 5), L(-12, 2);
  int checked = 0;
  for (int k = 0; k < 4000; ++k) {
    // End points E0, E2 relative to Q of a piece, of independent random lengths (10^L).
    const double s0 = std::pow(10.0, L(g)), s2 = std::pow(10.0, L(g));
    const double e0x = s0 * U(g), e0y = s0 * U(g), e2x = s2 * U(g), e2y = s2 * U(g);
    const double A = e0x * e0x + e0y * e0y, B = e0x * e2x + e0y * e2y, C = e2x * e2x + e2y * e2y;
    const double w = (k % 3 == 0) ? 1.0 : W(g);
    if (!(A > 0 && C > 0)) continue;
    const long double ref = eq7_bisection(A, B, C, w);
    // Starts: near the root (as in late passes), anywhere, at the clamps, NaN.
    const double starts[] = {static_cast<double>(ref) + 1e-9, 0.5 * (U(g) + 1), 1e-6, 1 - 1e-6,
                             std::numeric_limits<double>::quiet_NaN()};
    for (double start : starts) {
      const double t = kp::eq7_root(A, B, C, w, start);
      ASSERT_GT(t, 0.0);
      ASSERT_LT(t, 1.0);
      const double tol = eq7_root_tolerance(A, B, C, w, static_cast<double>(ref));
      EXPECT_LE(std::abs(static_cast<long double>(t) - ref), tol)
          << "A=" << A << " B=" << B << " C=" << C << " w=" << w << " start=" << start;
      ++checked;
    }
  }
  EXPECT_GT(checked, 15000);
}

TEST(KappaRefinement, Eq7RootSymmetricAndExtremeCases) {
  // A == C: f(1/2) = (C - A)(w + 1)/16 = 0, the root is 1/2 exactly (up to the stopping rule).
  for (double w : {0.1, 1.0, 7.0})
    for (double B : {-0.99, 0.0, 0.5})
      EXPECT_NEAR(kp::eq7_root(1.0, B, 1.0, w, 0.2), 0.5, 4 * eps) << "w=" << w << " B=" << B;
  // A tiny: the start point nearly at Q, the root near 0; C tiny: near 1.
  for (double a : {1e-8, 1e-16, 1e-30}) {
    const double t0 = kp::eq7_root(a, 0.0, 1.0, 1.0, 0.5);
    const double t1 = kp::eq7_root(1.0, 0.0, a, 1.0, 0.5);
    EXPECT_NEAR(t0, static_cast<double>(eq7_bisection(a, 0.0, 1.0, 1.0)), 16 * eps);
    EXPECT_NEAR(t1, static_cast<double>(eq7_bisection(1.0, 0.0, a, 1.0)), 16 * eps);
    EXPECT_GT(t0, 0.0);
    EXPECT_LT(t1, 1.0);
  }
  // Starting outside (0,1) or from NaN still finds the root.
  const double ref = static_cast<double>(eq7_bisection(2.0, -0.5, 1.0, 0.7));
  for (double start : {-3.0, 0.0, 1.0, 42.0, std::numeric_limits<double>::infinity(),
                       std::numeric_limits<double>::quiet_NaN()})
    EXPECT_NEAR(kp::eq7_root(2.0, -0.5, 1.0, 0.7, start), ref, 8 * eps) << start;
}

TEST(KappaRefinement, Eq7RootDegenerateReturnsFallback) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(kp::eq7_root(0.0, 0.0, 1.0, 1.0, 0.3), 0.3);  // E0 = Q
  EXPECT_EQ(kp::eq7_root(1.0, 0.0, 0.0, 1.0, 0.3), 0.3);  // E2 = Q
  EXPECT_EQ(kp::eq7_root(1.0, 0.0, 1.0, 0.0, 0.3), 0.3);  // w = 0
  EXPECT_EQ(kp::eq7_root(1.0, 0.0, 1.0, -1.0, 0.3), 0.3);
  EXPECT_EQ(kp::eq7_root(nan, 0.0, 1.0, 1.0, 0.3), 0.3);
  EXPECT_EQ(kp::eq7_root(1.0, 0.0, nan, 1.0, 0.3), 0.3);
  EXPECT_EQ(kp::eq7_root(1.0, 0.0, 1.0, nan, 0.3), 0.3);
  // eq7_value is the polynomial of eq. 7: -wA at 0, wC at 1, zero at the root.
  EXPECT_EQ(kp::eq7_value(2.0, 0.5, 3.0, 0.5, 0.0), -1.0);
  EXPECT_EQ(kp::eq7_value(2.0, 0.5, 3.0, 0.5, 1.0), 1.5);
  const double t = kp::eq7_root(2.0, 0.5, 3.0, 0.5, 0.5);
  EXPECT_LE(std::abs(kp::eq7_value(2.0, 0.5, 3.0, 0.5, t)), 64 * eps);
}

// ------------------------------------------------------------------ eq. 18

// Random diagonally dominant states (t, lambda near 1/2), arbitrary ones, and states far from
// dominance (t near 0 with small lambda, tiny weights: the banded-LU fallback; such systems
// can be arbitrarily ill-conditioned, so there only the backward error is checked), open and
// closed, n = 1..60.
TEST(KappaRefinement, Eq18AgreesWithDenseSolve) {
  std::mt19937 g(18);
  std::uniform_real_distribution<double> U(0, 1);
  kp::Refinement_workspace ws;  // reused across sizes on purpose
  for (bool closed : {true, false})
    for (std::size_t n : {1, 2, 3, 4, 5, 8, 33, 60})
      for (int kind = 0; kind < 3; ++kind) {
        kp::Problem pb = star(n, closed, fair::Kappa_weights::FIXED, static_cast<unsigned>(n * 10 + kind));
        fair::Kappa_solver_state st;
        st.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
          if (kind == 0) {  // near the initial guess
            st.t[i] = 0.3 + 0.4 * U(g); st.lambda[i] = 0.3 + 0.4 * U(g); st.w[i] = 0.5 + U(g);
          } else if (kind == 1) {  // anywhere
            st.t[i] = 0.02 + 0.96 * U(g); st.lambda[i] = 0.01 + 0.98 * U(g); st.w[i] = 0.05 + 3 * U(g);
          } else {  // rows far from diagonal dominance
            st.t[i] = 0.01 + 0.05 * U(g); st.lambda[i] = 0.05 + 0.1 * U(g); st.w[i] = 1e-3;
          }
          st.dx[i] = 7; st.dy[i] = -7;  // overwritten
        }
        const std::string what = "n=" + std::to_string(n) + (closed ? " closed" : " open") + " kind=" + std::to_string(kind);
        ASSERT_TRUE(kp::solve_eq18(pb, st, ws)) << what;
        // Backward error: |M P - rhs| <= c eps (|M| |P| + |rhs|) row by row.
        Dense M, rhs;
        dense_eq18_system(pb, st, M, rhs);
        for (std::size_t i = 0; i < n; ++i)
          for (int c = 0; c < 2; ++c) {
            double r = -rhs(i, c), mag = std::abs(rhs(i, c));
            for (std::size_t j = 0; j < n; ++j) {
              const double pj = c == 0 ? pb.qx[j] + st.dx[j] : pb.qy[j] + st.dy[j];
              r += M(i, j) * pj;
              mag += std::abs(M(i, j) * pj);
            }
            EXPECT_LE(std::abs(r), 64 * eps * mag) << what << " row " << i;
          }
        if (kind < 2) {  // well-conditioned: forward agreement with the dense solve
          std::vector<double> rx, ry;
          dense_eq18(pb, st, rx, ry);
          double scale = 1;
          for (std::size_t i = 0; i < n; ++i) scale = std::max({scale, std::abs(rx[i]), std::abs(ry[i])});
          EXPECT_LE(max_abs_diff(st.dx, rx), 1e-12 * scale) << what;
          EXPECT_LE(max_abs_diff(st.dy, ry), 1e-12 * scale) << what;
        }
        // The overload without a workspace gives the same numbers.
        fair::Kappa_solver_state st2 = st;
        st2.dx.assign(n, 0.0);
        st2.dy.assign(n, 0.0);
        ASSERT_TRUE(kp::solve_eq18(pb, st2));
        EXPECT_EQ(st2.dx, st.dx);
        EXPECT_EQ(st2.dy, st.dy);
      }
}

TEST(KappaRefinement, Eq18NonFiniteDataFailsAndKeepsState) {
  for (bool closed : {true, false}) {
    kp::Problem pb = star(12, closed, fair::Kappa_weights::UNIT, 3);
    fair::Kappa_solver_state st;
    st.resize(pb.n);
    st.dx.assign(pb.n, 0.25);
    st.t[5] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(kp::solve_eq18(pb, st));
    for (std::size_t i = 0; i < pb.n; ++i) EXPECT_EQ(st.dx[i], 0.25);
    st.t[5] = 0.5;
    pb.qx[3] = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(kp::solve_eq18(pb, st));
    for (std::size_t i = 0; i < pb.n; ++i) EXPECT_EQ(st.dx[i], 0.25);
  }
}

// ------------------------------------------------------------------ passes

TEST(KappaRefinement, PassAgreesWithReferenceImplementation) {
  kp::Refinement_workspace ws;
  for (bool closed : {true, false})
    for (fair::Kappa_weights mode : {fair::Kappa_weights::UNIT, fair::Kappa_weights::FIXED, fair::Kappa_weights::AUTOMATIC})
      for (std::size_t n : {3, 4, 7, 40}) {
        const kp::Problem pb = star(n, closed, mode, static_cast<unsigned>(n + 100 * static_cast<int>(mode)));
        fair::Kappa_solver_state st;
        kp::initial_guess(pb, st, ws);
        fair::Kappa_solver_state ref;
        ref.resize(n);
        if (mode == fair::Kappa_weights::FIXED) ref.w = pb.weight;
        dense_eq18(pb, ref, ref.dx, ref.dy);
        EXPECT_LE(max_abs_diff(st.dx, ref.dx), 1e-13) << "initial guess, n=" << n;
        EXPECT_LE(max_abs_diff(st.dy, ref.dy), 1e-13) << "initial guess, n=" << n;
        // Several passes, each from the same state for both implementations.
        for (int pass = 0; pass < 6; ++pass) {
          ref = st;
          kp::refinement_pass(pb, st, ws);
          reference_pass(pb, ref);
          const char* what = closed ? "closed" : "open";
          EXPECT_LE(max_abs_diff(st.t, ref.t), 1e-13) << what << " n=" << n << " pass " << pass;
          EXPECT_LE(max_abs_diff(st.w, ref.w), 1e-13) << what << " n=" << n << " pass " << pass;
          EXPECT_LE(max_abs_diff(st.lambda, ref.lambda), 1e-13) << what << " n=" << n << " pass " << pass;
          EXPECT_LE(max_abs_diff(st.dx, ref.dx), 1e-13) << what << " n=" << n << " pass " << pass;
          EXPECT_LE(max_abs_diff(st.dy, ref.dy), 1e-13) << what << " n=" << n << " pass " << pass;
          for (std::size_t i = 0; i < n; ++i) {
            ASSERT_TRUE(st.t[i] >= 1e-6 && st.t[i] <= 1 - 1e-6);
            if (pb.has_start(i)) ASSERT_TRUE(st.lambda[i] >= 1e-3 && st.lambda[i] <= 1 - 1e-3);
            else ASSERT_EQ(st.lambda[i], 0.5);  // first block of an open curve: no join
          }
        }
      }
}

TEST(KappaRefinement, WorkspaceReuseAndOverloadsGiveIdenticalResults) {
  kp::Refinement_workspace ws;
  for (std::size_t n : {50, 9, 120, 3}) {  // the workspace shrinks and grows
    const kp::Problem pb = star(n, n % 2 == 0, fair::Kappa_weights::AUTOMATIC, static_cast<unsigned>(n));
    fair::Kappa_solver_state a, b;
    kp::initial_guess(pb, a, ws);
    kp::initial_guess(pb, b);
    EXPECT_EQ(a.dx, b.dx);
    for (int pass = 0; pass < 4; ++pass) {
      kp::refinement_pass(pb, a, ws);
      kp::refinement_pass(pb, b);
    }
    EXPECT_EQ(a.dx, b.dx);
    EXPECT_EQ(a.dy, b.dy);
    EXPECT_EQ(a.t, b.t);
    EXPECT_EQ(a.lambda, b.lambda);
    EXPECT_EQ(a.w, b.w);
  }
}

// Circle reproduction (the paper's title property): for points equally spaced on a circle the
// passes alone reach the exact rational kappa-curve: every piece is the circular arc between
// the arc midpoints next to its point, so t = lambda = 1/2, w = cos(pi/n) (the weight of a
// circular arc of half angle pi/n) and P_i, the intersection of the tangents at the two
// joins, lies at distance R sec(pi/n) from the centre.
TEST(KappaRefinement, PassesReproduceTheCircle) {
  for (std::size_t n : {3, 5, 8, 13, 40}) {
    kp::Problem pb;
    pb.closed = true;
    pb.n = n;
    pb.mode = fair::Kappa_weights::AUTOMATIC;
    pb.tension.assign(n, 1.0);
    const double R = 3.5, cx = -2, cy = 7;
    for (std::size_t i = 0; i < n; ++i) {
      pb.qx.push_back(cx + R * std::cos(2 * M_PI * i / n + 0.3));
      pb.qy.push_back(cy + R * std::sin(2 * M_PI * i / n + 0.3));
    }
    fair::Kappa_solver_state st;
    kp::initial_guess(pb, st);
    fair::Kappa_curve_report res;
    const double fmax = kp::refine(pb, st, 20, 0.0, res);
    EXPECT_EQ(res.refinement_passes, 20u);
    EXPECT_LE(fmax, 1e-13) << n;
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_NEAR(st.t[i], 0.5, 1e-13);
      EXPECT_NEAR(st.lambda[i], 0.5, 1e-12);  // eq. 10 divides small cross products: less accurate
      EXPECT_NEAR(st.w[i], std::cos(M_PI / n), 1e-13);
      EXPECT_NEAR(std::hypot(pb.qx[i] + st.dx[i] - cx, pb.qy[i] + st.dy[i] - cy), R / std::cos(M_PI / n), 1e-12);
    }
  }
}

TEST(KappaRefinement, RefineStopsAtTheThresholdAndReducesTheResidual) {
  for (bool closed : {true, false}) {
    const kp::Problem pb = star(60, closed, fair::Kappa_weights::AUTOMATIC, 11);
    fair::Kappa_solver_state st;
    kp::initial_guess(pb, st);
    std::vector<double> F;
    const double f0 = kp::evaluate(pb, st, F);
    fair::Kappa_curve_report res;
    const double f1 = kp::refine(pb, st, 200, 1e-4, res);
    EXPECT_LT(f1, f0);
    EXPECT_LE(f1, 1e-4) << res.refinement_passes;
    EXPECT_GT(res.refinement_passes, 0u);
    EXPECT_EQ(f1, kp::evaluate(pb, st, F));
    // Already below the threshold: no pass.
    fair::Kappa_curve_report res2;
    kp::refine(pb, st, 200, 1e-4, res2);
    EXPECT_EQ(res2.refinement_passes, 0u);
  }
}

} // namespace
