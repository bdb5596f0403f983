// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Tests of the Newton machinery of the kappa-curve solver (include/fair/internal/): the block
// LU of internal/kappa/block_lu.h against a dense pivoted solve, the structured Jacobian of
// internal/kappa/jacobian.h against automatic differentiation over all 16 unknowns of a window, and
// the Newton phase of internal/kappa/solver.h against Levenberg-Marquardt.

#include <fair/internal/kappa/solver.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace {

using namespace fair::internal::kappa;
using fair::Kappa_solve_report;
using fair::Kappa_solver_state;
using fair::Kappa_weights;

// ------------------------------------------------------------------ block LU

/// Random block matrix of the kappa structure (row i: column blocks i-2..i+1), the diagonal
/// blocks shifted by `shift` * I; filled into both the block LU and a dense pivoted LU.
void random_system(std::mt19937& g, std::size_t n, bool cyclic, double shift, Block_band_lu& lu, Banded_lu& dense) {
  std::uniform_real_distribution<double> U(-1, 1);
  const std::size_t N = 4 * n;
  lu.reset(n, cyclic);
  dense.reset(N, N - 1, N - 1);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 4; ++k) {
      long c = static_cast<long>(i) - 2 + k;
      if (cyclic) c = ((c % static_cast<long>(n)) + static_cast<long>(n)) % static_cast<long>(n);
      else if (c < 0 || c >= static_cast<long>(n)) continue;
      Block4& b = lu.block(i, k);
      for (int r = 0; r < 4; ++r)
        for (int q = 0; q < 4; ++q) {
          const double v = U(g) + (k == 2 && r == q ? shift : 0.0);
          b[4 * r + q] = v;
          dense.add(4 * i + static_cast<std::size_t>(r), 4 * static_cast<std::size_t>(c) + static_cast<std::size_t>(q), v);
        }
    }
}

TEST(KappaBlockLu, AgreesWithDensePivotedSolve) {
  std::mt19937 g(7);
  std::uniform_real_distribution<double> U(-1, 1);
  for (const bool cyclic : {false, true})
    for (std::size_t n : {1, 2, 3, 4, 5, 6, 7, 9, 16, 61}) {
      for (int rep = 0; rep < 5; ++rep) {
        Block_band_lu lu;
        Banded_lu dense;
        random_system(g, n, cyclic, 6.0, lu, dense);
        std::vector<double> x(4 * n);
        for (double& v : x) v = U(g);
        std::vector<double> y = x;
        ASSERT_TRUE(lu.factor()) << "n " << n << " cyclic " << cyclic;
        ASSERT_TRUE(dense.factor());
        lu.solve(x.data());
        dense.solve(y.data());
        for (std::size_t k = 0; k < x.size(); ++k)
          EXPECT_NEAR(x[k], y[k], 1e-12 * (1 + std::abs(y[k]))) << "n " << n << " cyclic " << cyclic << " k " << k;
      }
    }
}

// The fused sweep (assembly, factorisation and forward substitution in one pass) gives the
// same solution as factor() + solve(); long cyclic systems exercise the truncated Woodbury
// spikes (they die out after a few dozen block rows here) against the dense solve.
TEST(KappaBlockLu, FusedSweepAndTruncatedSpikesAgreeWithDenseSolve) {
  std::mt19937 g(9);
  std::uniform_real_distribution<double> U(-1, 1);
  for (const bool cyclic : {false, true})
    for (std::size_t n : {3, 6, 40, 500}) {
      Block_band_lu lu, fused;
      Banded_lu dense;
      random_system(g, n, cyclic, 6.0, lu, dense);
      fused.resize(n, cyclic);
      std::vector<double> b(4 * n);
      for (double& v : b) v = U(g);
      std::vector<double> x = b, y = b, z = b;
      auto fill = [&](std::size_t i, Block4* row) {
        for (int k = 0; k < 4; ++k) row[k] = lu.block(i, k);
      };
      ASSERT_TRUE(fused.factor_rows(fill, z.data()));
      fused.finish_solve(z.data());
      ASSERT_TRUE(lu.factor());
      ASSERT_TRUE(dense.factor());
      lu.solve(x.data());
      dense.solve(y.data());
      for (std::size_t k = 0; k < x.size(); ++k) {
        EXPECT_NEAR(x[k], y[k], 1e-12 * (1 + std::abs(y[k]))) << "n " << n << " cyclic " << cyclic << " k " << k;
        EXPECT_EQ(z[k], x[k]) << "n " << n << " cyclic " << cyclic << " k " << k;
      }
    }
}

// Weak diagonal blocks (no diagonal dominance at all): without pivoting across blocks the
// factorisation is not backward stable to machine precision, but every accepted solve must have
// a small backward error |A x - b| / (|A| |x| + |b|) (measured worst: 5e-8).
TEST(KappaBlockLu, NonDominantSystemsHaveSmallBackwardError) {
  std::mt19937 g(8);
  std::uniform_real_distribution<double> U(-1, 1);
  int accepted = 0;
  for (int rep = 0; rep < 400; ++rep) {
    const std::size_t n = 6 + static_cast<std::size_t>(rep % 30), N = 4 * n;
    const bool cyclic = rep % 2 == 0;
    Block_band_lu lu;
    lu.reset(n, cyclic);
    std::vector<double> A(N * N, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 4; ++k) {
        long c = static_cast<long>(i) - 2 + k;
        if (cyclic) c = ((c % static_cast<long>(n)) + static_cast<long>(n)) % static_cast<long>(n);
        else if (c < 0 || c >= static_cast<long>(n)) continue;
        for (int r = 0; r < 4; ++r)
          for (int q = 0; q < 4; ++q) {
            const double v = U(g);
            lu.block(i, k)[4 * r + q] = v;
            A[(4 * i + static_cast<std::size_t>(r)) * N + 4 * static_cast<std::size_t>(c) + static_cast<std::size_t>(q)] += v;
          }
      }
    std::vector<double> b(N);
    for (double& v : b) v = U(g);
    std::vector<double> x = b;
    if (!lu.factor()) continue;
    lu.solve(x.data());
    ++accepted;
    double norm_a = 0, norm_x = 0, norm_b = 0, residual = 0;
    for (std::size_t r = 0; r < N; ++r) {
      double ax = 0, row = 0;
      for (std::size_t c = 0; c < N; ++c) {
        ax += A[r * N + c] * x[c];
        row += std::abs(A[r * N + c]);
      }
      residual = std::max(residual, std::abs(ax - b[r]));
      norm_a = std::max(norm_a, row);
      norm_b = std::max(norm_b, std::abs(b[r]));
      norm_x = std::max(norm_x, std::abs(x[r]));
    }
    EXPECT_LE(residual / (norm_a * norm_x + norm_b), 1e-6) << "n " << n << " cyclic " << cyclic;
  }
  EXPECT_GE(accepted, 390);
}

// A well-conditioned cyclic matrix whose cut matrix B is not: A = I + 2 S (S the cyclic block
// shift; eigenvalues 1 + 2 omega, |.| >= 1) but B^{-1} grows like 2^n. The Woodbury correction
// would cancel ~n log10(2) digits: accepted and accurate while that is below 8 digits, refused
// beyond (the caller then uses a pivoted method) -- never a silently wrong solve.
TEST(KappaBlockLu, IllConditionedCutIsRefused) {
  for (const std::size_t n : {std::size_t(20), std::size_t(60)}) {
    Block_band_lu lu;
    Banded_lu dense;
    lu.reset(n, true);
    dense.reset(4 * n, 4 * n - 1, 4 * n - 1);
    for (std::size_t i = 0; i < n; ++i)
      for (int r = 0; r < 4; ++r) {
        lu.block(i, 2)[5 * r] = 1.0;
        lu.block(i, 1)[5 * r] = 2.0;  // column block i - 1 (cyclic)
        dense.add(4 * i + static_cast<std::size_t>(r), 4 * i + static_cast<std::size_t>(r), 1.0);
        dense.add(4 * i + static_cast<std::size_t>(r), 4 * ((i + n - 1) % n) + static_cast<std::size_t>(r), 2.0);
      }
    std::vector<double> x(4 * n), y;
    for (std::size_t k = 0; k < x.size(); ++k) x[k] = std::cos(static_cast<double>(k));
    y = x;
    ASSERT_TRUE(dense.factor());
    dense.solve(y.data());
    if (n == 20) {
      ASSERT_TRUE(lu.factor());
      lu.solve(x.data());
      for (std::size_t k = 0; k < x.size(); ++k) EXPECT_NEAR(x[k], y[k], 1e-8) << k;
    } else {
      EXPECT_FALSE(lu.factor());
    }
  }
}

TEST(KappaBlockLu, SingularPivotBlockIsReported) {
  Block_band_lu lu;
  lu.reset(8, false);
  for (std::size_t i = 0; i < 8; ++i)
    for (int r = 0; r < 4; ++r) lu.block(i, 2)[5 * r] = 1.0;
  lu.block(3, 2)[15] = 0.0;  // a zero row in the diagonal block of row 3: singular
  EXPECT_FALSE(lu.factor());
  Block4 a{}, inv;
  a[0] = a[5] = a[10] = 1.0;
  a[15] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(invert_block(a, inv));
}

// ------------------------------------------------------------------ Jacobian

Problem random_problem(std::mt19937& g, std::size_t n, bool closed, Kappa_weights mode, double clamp) {
  std::uniform_real_distribution<double> U(0, 1);
  Problem pb;
  pb.closed = closed;
  pb.n = n;
  pb.mode = mode;
  pb.clamp = clamp;
  for (std::size_t i = 0; i < n; ++i) {
    pb.qx.push_back(2 * U(g) - 1);
    pb.qy.push_back(2 * U(g) - 1);
    pb.weight.push_back(0.5 + U(g));
    pb.tension.push_back(0.5 + U(g));
  }
  pb.sx = -1.5; pb.sy = 0.2; pb.ex = 1.4; pb.ey = -0.3;
  return pb;
}

Kappa_solver_state random_state(std::mt19937& g, std::size_t n) {
  std::uniform_real_distribution<double> U(0, 1);
  Kappa_solver_state st;
  st.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    st.dx[i] = U(g) - 0.5;
    st.dy[i] = U(g) - 0.5;
    st.lambda[i] = 0.1 + 0.8 * U(g);
    st.t[i] = 0.1 + 0.8 * U(g);
  }
  return st;
}

/// Compares block_jacobian with a differentiation over all 16 window unknowns.
void expect_jacobian_matches(const Problem& pb, const Kappa_solver_state& st, const char* what) {
  Jacobian_workspace ws;
  for (std::size_t i = 0; i < pb.n; ++i) {
    double r[4], J[4][16];
    block_jacobian(pb, st, i, ws, r, J);
    Window<Dual<16>> win;
    build_window(pb, st, i, win);
    Dual<16> ref[4];
    block_residuals(pb, st, i, win, ref);
    for (int e = 0; e < 4; ++e) {
      EXPECT_NEAR(r[e], ref[e].v, 1e-14 * (1 + std::abs(ref[e].v))) << what << " block " << i << " residual " << e;
      for (int c = 0; c < 16; ++c) {
        if (!win.valid[c / 4]) {
          EXPECT_EQ(J[e][c], 0.0);
          continue;
        }
        EXPECT_NEAR(J[e][c], ref[e].d[c], 1e-12 * (1 + std::abs(ref[e].d[c])))
            << what << " block " << i << " d r" << e << " / d unknown " << c % 4 << " of window block " << c / 4;
      }
    }
  }
}

TEST(KappaJacobian, MatchesFullAutomaticDifferentiation) {
  std::mt19937 g(11);
  for (int trial = 0; trial < 300; ++trial) {
    const bool closed = trial % 2 == 0;
    const std::size_t n = (closed ? 3 : 2) + static_cast<std::size_t>(trial % 9);
    const Kappa_weights mode = static_cast<Kappa_weights>((trial / 2) % 3);
    // clamp 0.9: the clamp of eq. 16 is often active; 0.05: rarely.
    const Problem pb = random_problem(g, n, closed, mode, trial % 4 < 2 ? 0.9 : 0.05);
    const Kappa_solver_state st = random_state(g, n);
    expect_jacobian_matches(pb, st, "random");
  }
}

// Straight control polygons (cross products 0, |kappa| = 0 on one side of a join) and the
// end blocks of open curves.
TEST(KappaJacobian, DegenerateJoinsAndOpenEnds) {
  for (const Kappa_weights mode : {Kappa_weights::UNIT, Kappa_weights::AUTOMATIC}) {
    Problem pb;
    pb.closed = false;
    pb.n = 5;
    pb.mode = mode;
    pb.tension.assign(5, 1.0);
    for (int i = 0; i < 5; ++i) {
      pb.qx.push_back(i);
      pb.qy.push_back(i == 3 ? 0.5 : 0.0);
    }
    pb.sx = -1; pb.sy = 0; pb.ex = 5; pb.ey = 0;
    Kappa_solver_state st;
    st.resize(5);
    st.lambda[2] = 0.3;
    st.t[1] = 0.7;
    expect_jacobian_matches(pb, st, "collinear");
  }
}

// ------------------------------------------------------------------ Newton

Problem star(std::size_t n, unsigned seed, Kappa_weights mode) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> U(0, 1);
  Problem pb;
  pb.closed = true;
  pb.n = n;
  pb.mode = mode;
  pb.tension.assign(n, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * M_PI * (static_cast<double>(i) + 0.2 * (U(g) - 0.5)) / static_cast<double>(n);
    const double r = 1 + 0.05 * (i % 2 ? 1 : -1) * (0.5 + U(g));
    pb.qx.push_back(r * std::cos(a));
    pb.qy.push_back(r * std::sin(a));
  }
  return pb;
}

// From the same start, Newton's method and Levenberg-Marquardt reach the same root; Newton in
// few iterations (quadratic convergence). (With few points -- large turning angles -- or
// automatic weights on small sets, two passes can leave the start outside Newton's basin;
// solve() then falls back to more passes and Levenberg-Marquardt, as test_kappa.cpp exercises.)
TEST(KappaNewton, ReachesTheLevenbergMarquardtRootQuickly) {
  const std::pair<Kappa_weights, std::size_t> cases[] = {{Kappa_weights::UNIT, 24}, {Kappa_weights::UNIT, 50},
                                                         {Kappa_weights::UNIT, 400}, {Kappa_weights::AUTOMATIC, 100},
                                                         {Kappa_weights::AUTOMATIC, 400}};
  for (const auto& mode_and_size : cases) {
      const Kappa_weights mode = mode_and_size.first;
      const std::size_t n = mode_and_size.second;
      const Problem pb = star(n, static_cast<unsigned>(n) + 1, mode);
      Kappa_solver_state a;
      initial_guess(pb, a);
      Kappa_solve_report passes;
      refine(pb, a, 2, 1e-3, passes);
      Kappa_solver_state b = a;
      Solve_settings s;
      Kappa_solve_report ra, rb;
      const double fa = newton(pb, a, s, ra, 30);
      const double fb = levenberg_marquardt(pb, b, s, rb, 200);
      ASSERT_LE(fa, 1e-12) << "n " << n;
      ASSERT_LE(fb, 1e-12) << "n " << n;
      EXPECT_LE(ra.iterations, 6u) << "n " << n;
      for (std::size_t i = 0; i < n; ++i) {
        EXPECT_NEAR(a.dx[i], b.dx[i], 1e-10);
        EXPECT_NEAR(a.dy[i], b.dy[i], 1e-10);
        EXPECT_NEAR(a.lambda[i], b.lambda[i], 1e-10);
        EXPECT_NEAR(a.t[i], b.t[i], 1e-10);
      }
    }
}

// The cold solve takes the fast path (two passes, then Newton) on regular data and reports it.
TEST(KappaNewton, ColdSolveUsesTheFastPath) {
  const Problem pb = star(1000, 3, Kappa_weights::UNIT);
  Kappa_solver_state st;
  const Kappa_solve_report res = solve(pb, st, Solve_settings{});
  EXPECT_TRUE(res.converged);
  EXPECT_LE(res.refinement_passes, 2u);
  EXPECT_LE(res.iterations, 6u);
  EXPECT_LE(res.residual, 1e-12);
}

// settings.max_iterations caps the Jacobians of the whole solve (Newton and Levenberg-Marquardt,
// local warm-start stages included), cold and warm, converged or not.
TEST(KappaNewton, IterationCapHoldsForTheWholeSolve) {
  std::mt19937 g(21);
  std::uniform_real_distribution<double> U(0, 1);
  int warm_converged = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Problem pb = star(30 + static_cast<std::size_t>(trial), 100 + static_cast<unsigned>(trial), Kappa_weights::UNIT);
    pb.closed = trial % 2 == 0;
    pb.sx = 1.2; pb.sy = -0.3; pb.ex = 1.2; pb.ey = 0.3;
    Solve_settings tight;
    tight.max_iterations = 3;
    Kappa_solver_state cold;
    EXPECT_LE(solve(pb, cold, tight).iterations, 3u);
    Kappa_solver_state st;
    if (!solve(pb, st, Solve_settings{}).converged) continue;
    const std::size_t m = static_cast<std::size_t>(trial) % pb.n;  // a large move of one point
    pb.qx[m] *= 1.0 + 0.3 * (U(g) - 0.5);
    pb.qy[m] += 0.2 * (U(g) - 0.5);
    Solve_settings warm;
    warm.warm = true;
    warm.moved = m;
    warm.max_iterations = 25;
    const Kappa_solve_report r = solve(pb, st, warm);
    EXPECT_LE(r.iterations, 25u);
    warm_converged += r.converged ? 1 : 0;
  }
  EXPECT_GE(warm_converged, 25);
}

// A local (range) Newton solve only changes the unknowns of its range and zeroes their residuals.
TEST(KappaNewton, RangeSolveTouchesOnlyItsBlocks) {
  Problem pb = star(60, 5, Kappa_weights::UNIT);
  Kappa_solver_state st;
  ASSERT_TRUE(solve(pb, st, Solve_settings{}).converged);
  pb.qx[30] *= 1.01;
  Block_range range;
  range.all = false;
  range.first = 22;
  range.count = 17;
  Kappa_solver_state local = st;
  Kappa_solve_report res;
  const double f = newton(pb, local, Solve_settings{}, res, 30, range);
  EXPECT_LE(f, 1e-12);
  for (std::size_t i = 0; i < pb.n; ++i) {
    if (i >= 22 && i < 39) continue;
    EXPECT_EQ(local.dx[i], st.dx[i]);
    EXPECT_EQ(local.t[i], st.t[i]);
  }
  EXPECT_NE(local.dx[30], st.dx[30]);
}

// ------------------------------------------------------------------ warm/cold policy

// Input points and blocks: an open curve's end points belong to its end blocks.
TEST(KappaSolver, BlocksOfInputPoints) {
  Problem open;
  open.closed = false;
  open.n = 5;
  EXPECT_EQ(open.point_index(0), 1u);
  EXPECT_EQ(open.point_index(4), 5u);
  EXPECT_EQ(open.block_of_point(0), 0u);
  EXPECT_EQ(open.block_of_point(3), 2u);
  EXPECT_EQ(open.block_of_point(6), 4u);
  EXPECT_EQ(open.block_of_point(7), Problem::no_block);
  Problem closed;
  closed.closed = true;
  closed.n = 5;
  EXPECT_EQ(closed.point_index(4), 4u);
  EXPECT_EQ(closed.block_of_point(4), 4u);
  EXPECT_EQ(closed.block_of_point(5), Problem::no_block);
}

// The policy of Kappa_curve_2 (solve_with_warm_start): cold without a previous state (or with
// one of another size), warm and kept when the warm start converges.
TEST(KappaSolver, WarmStartPolicy) {
  Problem pb = star(60, 5, Kappa_weights::UNIT);
  Kappa_solver_state st;
  const Kappa_solve_report cold = solve_with_warm_start(pb, nullptr, 0, Solve_settings{}, st);
  ASSERT_TRUE(cold.converged);
  EXPECT_FALSE(cold.warm_started);
  const Kappa_solver_state previous = st;
  pb.qx[30] *= 1.01;
  Kappa_solver_state moved;
  const Kappa_solve_report warm = solve_with_warm_start(pb, &previous, 30, Solve_settings{}, moved);
  EXPECT_TRUE(warm.converged);
  EXPECT_TRUE(warm.warm_started);
  EXPECT_EQ(warm.refinement_passes, 0u);
  Kappa_solver_state other_size;
  other_size.resize(10);
  EXPECT_FALSE(solve_with_warm_start(pb, &other_size, 30, Solve_settings{}, moved).warm_started);
}

} // namespace
