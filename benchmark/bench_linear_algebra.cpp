// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The hand-written solvers of internal/linear_algebra/ against Eigen's sparse direct solvers on
// the systems the library actually solves (doc/linear_algebra.md), in the same run, at about
// 10^3, 10^4 and 10^5 unknowns:
//  - kappa_newton: the Jacobian of the kappa-curve system (4 unknowns per block, block rows
//    coupling blocks i-2..i+1; closed: cyclic, open: clipped) at the start of Newton's method
//    (random star, initial guess and two alternating passes, as the cold solve runs it).
//    Hand: Block_band_lu (block LU, Woodbury correction for the wrap-around), assembly fused with
//    the factorisation as newton() runs it (factor_rows + finish_solve). Eigen: SparseLU
//    (COLAMD ordering) with the pattern analysed once outside the timing (it is fixed across
//    the Newton iterations): values copied in, factorize(), solve().
//  - kappa_lm: Levenberg-Marquardt's damped normal equations J^T J + mu D (SPD, half bandwidth
//    15 open / 31 closed in zig-zag order). Hand: Banded_cholesky (storage copied in, factor,
//    solve, as levenberg_marquardt() does per damping attempt). Eigen: SimplicialLDLT (AMD, and
//    natural ordering = the band) and SimplicialLLT, pattern analysed once.
//  - optimal_newton: the reduced Hessian of the optimal-curve solver (closed wobbly circle, every
//    10th vertex fixed, half bandwidth w = 2 and w = 6 in unknowns, cyclic), shifted to be SPD as
//    the solver shifts it. Hand: solve_banded_positive_definite (folding order, banded Cholesky).
//    Eigen: SimplicialLDLT (AMD) with the pattern analysed once.
// Every case checks its solution (relative residual) once before the timing.
// Run: ./bench_linear_algebra --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include <fair/internal/kappa/levenberg_marquardt.h>
#include <fair/internal/kappa/refinement.h>
#include <fair/internal/optimal/functional.h>
#include <fair/internal/optimal/newton_step.h>
#include <fair/internal/optimal/reduced_system.h>

#include <benchmark/benchmark.h>

#ifdef FAIR_HAVE_EIGEN
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

namespace kappa = fair::internal::kappa;
namespace optimal = fair::internal::optimal;
namespace la = fair::internal::linear_algebra;

// ------------------------------------------------------------------ the kappa systems

/// A random star (every point a corner, alternately convex and concave) of n blocks; closed, or
/// open with its first and last points fixed (n + 2 points).
kappa::Problem star_problem(std::size_t n, bool closed) {
  std::mt19937 g(7);
  std::uniform_real_distribution<double> U(0, 1);
  const std::size_t m = closed ? n : n + 2;
  std::vector<double> x(m), y(m);
  for (std::size_t i = 0; i < m; ++i) {
    const double a = 2 * M_PI * (static_cast<double>(i) + 0.2 * (U(g) - 0.5)) / static_cast<double>(closed ? m : m + 1);
    const double r = 1 + 0.05 * (i % 2 ? 1 : -1) * (0.5 + U(g));
    x[i] = r * std::cos(a);
    y[i] = r * std::sin(a);
  }
  kappa::Problem pb;
  pb.closed = closed;
  pb.n = n;
  const std::size_t first = closed ? 0 : 1;
  pb.qx.assign(x.begin() + first, x.begin() + first + n);
  pb.qy.assign(y.begin() + first, y.begin() + first + n);
  if (!closed) { pb.sx = x[0]; pb.sy = y[0]; pb.ex = x[m - 1]; pb.ey = y[m - 1]; }
  pb.mode = fair::Kappa_weights::UNIT;
  return pb;
}

/// The Newton start of the cold solve: initial guess and two alternating passes.
fair::Kappa_solver_state newton_start(const kappa::Problem& pb) {
  fair::Kappa_solver_state st;
  kappa::initial_guess(pb, st);
  fair::Kappa_curve_report res;
  kappa::refine(pb, st, 2, 1e-3, res);
  return st;
}

/// The block rows of the Jacobian (4 blocks of 4x4 per block row, zero where the structure has
/// none), and the right-hand side -r.
struct Kappa_jacobian {
  kappa::Problem pb;
  std::vector<la::Block4> rows;
  std::vector<double> rhs;
  Kappa_jacobian(std::size_t n, bool closed) : pb(star_problem(n, closed)) {
    const fair::Kappa_solver_state st = newton_start(pb);
    rows.assign(4 * n, la::Block4{});
    rhs.assign(4 * n, 0.0);
    kappa::Jacobian_workspace ws;
    for (std::size_t i = 0; i < n; ++i) {
      double r[4], J[4][16];
      kappa::block_jacobian(pb, st, i, ws, r, J);
      for (int k = 0; k < 4; ++k) {
        if (!ws.values.valid[k]) continue;
        for (int e = 0; e < 4; ++e)
          for (int c = 0; c < 4; ++c) rows[4 * i + k][4 * e + c] = J[e][4 * k + c];
      }
      for (int e = 0; e < 4; ++e) rhs[4 * i + e] = -r[e];
    }
  }
  /// Column block of slot k of block row i, or -1.
  long column_block(std::size_t i, int k) const {
    long b = static_cast<long>(i) - 2 + k;
    const long n = static_cast<long>(pb.n);
    if (pb.closed) return (b % n + n) % n;
    return b >= 0 && b < n ? b : -1;
  }
  /// max |A x - b| / (max|A| max|x| + max|b|).
  double relative_residual(const std::vector<double>& x) const {
    std::vector<double> ax(rhs.size(), 0.0);
    double na = 0, nx = 0, nb = 0;
    for (std::size_t i = 0; i < pb.n; ++i)
      for (int k = 0; k < 4; ++k) {
        const long c = column_block(i, k);
        if (c < 0) continue;
        for (int e = 0; e < 4; ++e)
          for (int q = 0; q < 4; ++q) {
            const double v = rows[4 * i + k][4 * e + q];
            ax[4 * i + e] += v * x[4 * c + q];
            na = std::max(na, std::abs(v));
          }
      }
    double r = 0;
    for (std::size_t k = 0; k < rhs.size(); ++k) {
      r = std::max(r, std::abs(ax[k] - rhs[k]));
      nx = std::max(nx, std::abs(x[k]));
      nb = std::max(nb, std::abs(rhs[k]));
    }
    return r / (na * nx + nb);
  }
};

/// Blocks for 10^3, 10^4, 10^5 unknowns.
std::size_t kappa_blocks(long unknowns) { return static_cast<std::size_t>(unknowns / 4); }

void kappa_newton_hand(benchmark::State& state) {
  const Kappa_jacobian sys(kappa_blocks(state.range(0)), state.range(1) != 0);
  la::Block_band_lu lu;
  std::vector<double> x;
  auto run = [&]() {
    lu.resize(sys.pb.n, sys.pb.closed);
    x = sys.rhs;
    const bool ok = lu.factor_rows([&](std::size_t i, la::Block4* row) { std::copy_n(&sys.rows[4 * i], 4, row); }, x.data());
    if (!ok) throw std::runtime_error("block LU refused the kappa Jacobian");
    lu.finish_solve(x.data());
  };
  run();
  state.counters["residual"] = sys.relative_residual(x);
  for (auto _ : state) {
    run();
    benchmark::DoNotOptimize(x.data());
  }
}

/// max |A x - b| / (max|A| max|x| + max|b|) of a sparse system (the same measure as above).
template <class Matrix>
double sparse_relative_residual(const Matrix& A, const std::vector<double>& x, const std::vector<double>& b) {
  std::vector<double> ax(b.size(), 0.0);
  double na = 0, nx = 0, nb = 0, r = 0;
  for (int c = 0; c < A.outerSize(); ++c)
    for (typename Matrix::InnerIterator it(A, c); it; ++it) {
      ax[static_cast<std::size_t>(it.row())] += it.value() * x[static_cast<std::size_t>(it.col())];
      na = std::max(na, std::abs(it.value()));
    }
  for (std::size_t k = 0; k < b.size(); ++k) {
    r = std::max(r, std::abs(ax[k] - b[k]));
    nx = std::max(nx, std::abs(x[k]));
    nb = std::max(nb, std::abs(b[k]));
  }
  return r / (na * nx + nb);
}

#ifdef FAIR_HAVE_EIGEN
typedef Eigen::SparseMatrix<double, Eigen::ColMajor, int> Sparse;
typedef Eigen::Map<const Eigen::VectorXd> Const_vector_map;

void kappa_newton_eigen_sparse_lu(benchmark::State& state) {
  const Kappa_jacobian sys(kappa_blocks(state.range(0)), state.range(1) != 0);
  const int N = static_cast<int>(4 * sys.pb.n);
  std::vector<Eigen::Triplet<double>> triplets;
  for (std::size_t i = 0; i < sys.pb.n; ++i)
    for (int k = 0; k < 4; ++k) {
      const long c = sys.column_block(i, k);
      if (c < 0) continue;
      for (int e = 0; e < 4; ++e)
        for (int q = 0; q < 4; ++q)
          triplets.emplace_back(static_cast<int>(4 * i) + e, static_cast<int>(4 * c) + q, sys.rows[4 * i + k][4 * e + q]);
    }
  Sparse A(N, N);
  A.setFromTriplets(triplets.begin(), triplets.end());  // the full block pattern, zeros kept
  A.makeCompressed();
  const std::vector<double> values(A.valuePtr(), A.valuePtr() + A.nonZeros());
  Eigen::SparseLU<Sparse, Eigen::COLAMDOrdering<int>> lu;
  lu.analyzePattern(A);
  Eigen::VectorXd x;
  const Const_vector_map b(sys.rhs.data(), N);
  auto run = [&]() {
    std::copy(values.begin(), values.end(), A.valuePtr());  // the assembly of the iteration
    lu.factorize(A);
    if (lu.info() != Eigen::Success) throw std::runtime_error("SparseLU failed on the kappa Jacobian");
    x = lu.solve(b);
  };
  run();
  state.counters["residual"] = sparse_relative_residual(A, std::vector<double>(x.data(), x.data() + N), sys.rhs);
  for (auto _ : state) {
    run();
    benchmark::DoNotOptimize(x.data());
  }
}
#endif

/// Levenberg-Marquardt's damped normal equations at the Newton start (mu = 1e-8 of the largest
/// diagonal entry times Marquardt's scaling, as its first iteration), in the band order of the solver.
struct Kappa_normal_equations {
  kappa::Problem pb;
  la::Banded_cholesky chol;  // unfactored J^T J + mu D
  std::vector<double> g, storage;
  Kappa_normal_equations(std::size_t n, bool closed) : pb(star_problem(n, closed)) {
    const fair::Kappa_solver_state st = newton_start(pb);
    kappa::assemble_normal_equations(pb, st, chol, g, kappa::normal_bandwidth(pb));
    double maxdiag = 0;
    for (std::size_t k = 0; k < chol.size(); ++k) maxdiag = std::max(maxdiag, chol.diagonal(k));
    for (std::size_t k = 0; k < chol.size(); ++k)
      chol.add_diagonal(k, kappa::lm_initial_damping * std::max(chol.diagonal(k), kappa::lm_diagonal_floor * maxdiag));
    for (double& v : g) v = -v;
    storage = chol.storage();
  }
};

void kappa_lm_hand(benchmark::State& state) {
  Kappa_normal_equations sys(kappa_blocks(state.range(0)), state.range(1) != 0);
  std::vector<double> x;
  auto run = [&]() {
    sys.chol.storage() = sys.storage;
    if (!sys.chol.factor()) throw std::runtime_error("banded Cholesky refused J^T J + mu D");
    x = sys.g;
    sys.chol.solve(x.data());
  };
  run();
  for (auto _ : state) {
    run();
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["half_bandwidth"] = static_cast<double>(sys.chol.half_bandwidth());
}

#ifdef FAIR_HAVE_EIGEN
/// The band (lower triangle stored row-wise, half bandwidth h) as a full symmetric sparse matrix.
Sparse band_to_sparse(const std::vector<double>& band, std::size_t n, std::size_t h) {
  std::vector<Eigen::Triplet<double>> t;
  const std::size_t w = h + 1;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i > h ? i - h : 0; j <= i; ++j) {
      const double v = band[i * w + (j + h - i)];
      t.emplace_back(static_cast<int>(i), static_cast<int>(j), v);
      if (j != i) t.emplace_back(static_cast<int>(j), static_cast<int>(i), v);
    }
  Sparse A(static_cast<int>(n), static_cast<int>(n));
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

template <class Solver>
void kappa_lm_eigen(benchmark::State& state) {
  const Kappa_normal_equations sys(kappa_blocks(state.range(0)), state.range(1) != 0);
  Sparse A = band_to_sparse(sys.storage, sys.chol.size(), sys.chol.half_bandwidth());
  const std::vector<double> values(A.valuePtr(), A.valuePtr() + A.nonZeros());
  Solver solver;
  solver.analyzePattern(A);
  Eigen::VectorXd x;
  const Const_vector_map b(sys.g.data(), static_cast<int>(sys.g.size()));
  auto run = [&]() {
    std::copy(values.begin(), values.end(), A.valuePtr());
    solver.factorize(A);
    if (solver.info() != Eigen::Success) throw std::runtime_error("Eigen refused J^T J + mu D");
    x = solver.solve(b);
  };
  run();
  state.counters["residual"] = sparse_relative_residual(A, std::vector<double>(x.data(), x.data() + x.size()), sys.g);
  for (auto _ : state) {
    run();
    benchmark::DoNotOptimize(x.data());
  }
}
#endif

// ------------------------------------------------------------------ the optimal-curve system

/// The reduced Newton system of the optimal-curve solver on a closed wobbly circle of n vertices,
/// every 10th fixed, shifted by the smallest shift of the solver's ladder that makes it SPD.
struct Optimal_system {
  optimal::Banded_symmetric rh;
  std::vector<double> rhs;
  Optimal_system(std::size_t n, std::size_t w) {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    std::vector<optimal::Vec2> c(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double t = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
      const double r = 1 + 0.1 * std::sin(5 * t) + 1e-3 * u(rng);
      c[i] = optimal::Vec2{{r * std::cos(t), r * std::sin(t)}};
    }
    optimal::Functional f;
    f.closed = true;
    f.reference_length = 2 * M_PI;
    f.length_weight.assign(n, 1.0);
    f.curvature_weight.assign(n, 0.05);
    if (w == 6) f.derivative_weight[4] = 1e-9;
    std::vector<optimal::Vec2> g;
    optimal::Block_banded_hessian h;
    optimal::energy_gradient_hessian(f, c, g, h);
    optimal::Vertex_roles roles;
    roles.role.assign(n, optimal::Vertex_role::FREE);
    for (std::size_t i = 0; i < n; i += 10) roles.role[i] = optimal::Vertex_role::FIXED;
    const optimal::Reduced_unknowns unknowns = optimal::reduced_unknowns(c, optimal::vertex_normals(c, true), roles, true);
    optimal::reduced_system(g, h, true, unknowns, rhs, rh);
    for (double& v : rhs) v = -v;
    std::vector<double> x = rhs;
    double shift = 0;
    if (!optimal::shifted_solve(rh, x, shift)) throw std::runtime_error("no shift makes the reduced Hessian SPD");
    double diag = 0, smallest = INFINITY;
    for (std::size_t k = 0; k < rh.size(); ++k) {
      diag = std::max(diag, std::abs(rh.at(k, k)));
      smallest = std::min(smallest, std::abs(rh.at(k, k)));
    }
    if (shift > 0) rh.add_to_diagonal(shift * smallest);
  }
};

/// Vertices for about 10^3, 10^4, 10^5 unknowns (every 10th vertex fixed).
std::size_t optimal_vertices(long unknowns) { return static_cast<std::size_t>(unknowns + unknowns / 9); }

void optimal_newton_hand(benchmark::State& state) {
  const Optimal_system sys(optimal_vertices(state.range(0)), static_cast<std::size_t>(state.range(1)));
  std::vector<double> x;
  for (auto _ : state) {
    x = sys.rhs;
    if (!optimal::solve_banded_positive_definite(sys.rh, x)) throw std::runtime_error("banded Cholesky refused");
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["unknowns"] = static_cast<double>(sys.rhs.size());
  state.counters["half_bandwidth"] = static_cast<double>(sys.rh.half_bandwidth());
}

#ifdef FAIR_HAVE_EIGEN
template <class Solver>
void optimal_newton_eigen(benchmark::State& state) {
  const Optimal_system sys(optimal_vertices(state.range(0)), static_cast<std::size_t>(state.range(1)));
  const std::size_t m = sys.rh.size(), w = sys.rh.half_bandwidth();
  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t k = 0; k < m; ++k)
    for (std::size_t d = 0; d <= w && 2 * d <= m; ++d) {
      const std::size_t l = (k + d) % m;
      if (d > 0 && 2 * d == m && l < k) continue;  // the antipodal pair of an even ring once
      const double v = sys.rh.at(k, l);
      t.emplace_back(static_cast<int>(k), static_cast<int>(l), v);
      if (l != k) t.emplace_back(static_cast<int>(l), static_cast<int>(k), v);
    }
  Sparse A(static_cast<int>(m), static_cast<int>(m));
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  const std::vector<double> values(A.valuePtr(), A.valuePtr() + A.nonZeros());
  Solver solver;
  solver.analyzePattern(A);
  Eigen::VectorXd x;
  const Const_vector_map b(sys.rhs.data(), static_cast<int>(m));
  auto run = [&]() {
    std::copy(values.begin(), values.end(), A.valuePtr());
    solver.factorize(A);
    if (solver.info() != Eigen::Success) throw std::runtime_error("Eigen refused the reduced Hessian");
    x = solver.solve(b);
  };
  run();
  state.counters["residual"] = sparse_relative_residual(A, std::vector<double>(x.data(), x.data() + x.size()), sys.rhs);
  for (auto _ : state) {
    run();
    benchmark::DoNotOptimize(x.data());
  }
}
#endif

void kappa_sizes(benchmark::internal::Benchmark* b) {
  for (long closed : {1, 0})
    for (long unknowns : {1000, 10000, 100000}) b->Args({unknowns, closed});
  b->ArgNames({"unknowns", "closed"})->Unit(benchmark::kMicrosecond);
}
void optimal_sizes(benchmark::internal::Benchmark* b) {
  for (long w : {2, 6})
    for (long unknowns : {1000, 10000, 100000}) b->Args({unknowns, w});
  b->ArgNames({"unknowns", "w"})->Unit(benchmark::kMicrosecond);
}

BENCHMARK(kappa_newton_hand)->Apply(kappa_sizes);
BENCHMARK(kappa_lm_hand)->Apply(kappa_sizes);
BENCHMARK(optimal_newton_hand)->Apply(optimal_sizes);
#ifdef FAIR_HAVE_EIGEN
BENCHMARK(kappa_newton_eigen_sparse_lu)->Apply(kappa_sizes);
BENCHMARK_TEMPLATE(kappa_lm_eigen, Eigen::SimplicialLDLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int>>)->Apply(kappa_sizes);
BENCHMARK_TEMPLATE(kappa_lm_eigen, Eigen::SimplicialLDLT<Sparse, Eigen::Lower, Eigen::NaturalOrdering<int>>)->Apply(kappa_sizes);
BENCHMARK_TEMPLATE(kappa_lm_eigen, Eigen::SimplicialLLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int>>)->Apply(kappa_sizes);
BENCHMARK_TEMPLATE(optimal_newton_eigen, Eigen::SimplicialLDLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int>>)->Apply(optimal_sizes);
BENCHMARK_TEMPLATE(optimal_newton_eigen, Eigen::SimplicialLLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int>>)->Apply(optimal_sizes);
#endif

} // namespace
