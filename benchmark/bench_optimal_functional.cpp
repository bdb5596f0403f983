// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Benchmarks of the discrete optimal-curve functional (include/fair/internal/optimal/functional.h):
// one Newton step's linear algebra on n vertices, n = 10^3, 10^4, 10^5 —
//   energy_gradient_hessian (exact, dual numbers), the solver's reduction to normal offsets (reduced_system.h; every 10th
//   vertex fixed, the interpolation points), and the banded Cholesky solve (with the diagonal shift that makes it
//   positive definite, found once before the timing: 0, or 1e-8 max|diag| doubled),
// for half-bandwidth w = 2 (beta + beta_0 kappa^2) and w = 6 (plus beta_4 kappa''''^2), closed curves
// (the cyclic solve). Separately: energy alone, energy and gradient, and the solve alone.
// Run with --benchmark_repetitions=9 --benchmark_report_aggregates_only=true for medians.

#include <fair/internal/optimal/functional.h>
#include <fair/internal/optimal/reduced_system.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace fair::internal::optimal;

std::vector<Vec2> wobbly_circle(std::size_t n) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  std::vector<Vec2> c(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * 3.14159265358979323846 * static_cast<double>(i) / static_cast<double>(n);
    const double r = 1 + 0.1 * std::sin(5 * t) + 1e-3 * u(rng);
    c[i] = Vec2{{r * std::cos(t), r * std::sin(t)}};
  }
  return c;
}

Functional functional(std::size_t n, std::size_t w) {
  Functional f;
  f.closed = true;
  f.reference_length = 2 * 3.14159265358979323846;
  f.length_weight.assign(n, 1.0);
  f.curvature_weight.assign(n, 0.05);
  if (w == 6) f.derivative_weight[4] = 1e-9;
  return f;
}

struct Step {
  std::vector<Vec2> c, gradient, normals;
  Vertex_roles roles;
  Functional f;
  Block_banded_hessian hessian;
  std::vector<double> rg;
  Banded_symmetric rh;
  explicit Step(std::size_t n, std::size_t w) : c(wobbly_circle(n)), f(functional(n, w)) {
    normals = vertex_normals(c, true);
    roles.role.assign(n, Vertex_role::FREE);
    for (std::size_t i = 0; i < n; i += 10) roles.role[i] = Vertex_role::FIXED;
  }
  /// The reduced gradient and Hessian (the solver's reduction: unknowns, then the band).
  void reduce() {
    const Reduced_unknowns u = reduced_unknowns(c, normals, roles, true);
    reduced_system(gradient, hessian, true, u, rg, rh);
  }
  /// The smallest diagonal shift of the form 0 or 1e-8 max|diag| 2^m that makes the reduced Hessian
  /// positive definite (the optimiser's fallback), and the number of attempts it took.
  std::size_t find_shift(double& shift) {
    double diag = 0;
    for (std::size_t a = 0; a < rh.size(); ++a) diag = std::max(diag, std::fabs(rh.at(a, a)));
    shift = 0;
    for (std::size_t attempt = 0; attempt < 60; ++attempt) {
      Banded_symmetric m = rh;
      m.add_to_diagonal(shift);
      std::vector<double> x = rg;
      if (solve_banded_positive_definite(m, x)) return attempt;
      shift = shift == 0 ? 1e-8 * diag : 2 * shift;
    }
    return 60;
  }
};

void newton_step(benchmark::State& state) {
  Step s(static_cast<std::size_t>(state.range(0)), static_cast<std::size_t>(state.range(1)));
  energy_gradient_hessian(s.f, s.c, s.gradient, s.hessian);
  s.reduce();
  double shift = 0;
  const std::size_t attempts = s.find_shift(shift);  // outside the timing: the optimiser's business
  bool solved = false;
  for (auto _ : state) {
    benchmark::DoNotOptimize(energy_gradient_hessian(s.f, s.c, s.gradient, s.hessian));
    s.reduce();
    s.rh.add_to_diagonal(shift);
    solved = solve_banded_positive_definite(s.rh, s.rg);
    benchmark::DoNotOptimize(s.rg.data());
  }
  state.counters["shift_attempts"] = static_cast<double>(attempts);
  state.counters["solved"] = solved ? 1 : 0;
}

void hessian_only(benchmark::State& state) {
  Step s(static_cast<std::size_t>(state.range(0)), static_cast<std::size_t>(state.range(1)));
  for (auto _ : state) benchmark::DoNotOptimize(energy_gradient_hessian(s.f, s.c, s.gradient, s.hessian));
}

void gradient_only(benchmark::State& state) {
  Step s(static_cast<std::size_t>(state.range(0)), static_cast<std::size_t>(state.range(1)));
  for (auto _ : state) benchmark::DoNotOptimize(energy_and_gradient(s.f, s.c, s.gradient));
}

void energy_only(benchmark::State& state) {
  Step s(static_cast<std::size_t>(state.range(0)), static_cast<std::size_t>(state.range(1)));
  for (auto _ : state) benchmark::DoNotOptimize(energy(s.f, s.c));
}

void solve_only(benchmark::State& state) {
  Step s(static_cast<std::size_t>(state.range(0)), static_cast<std::size_t>(state.range(1)));
  energy_gradient_hessian(s.f, s.c, s.gradient, s.hessian);
  s.reduce();
  double shift = 0;
  s.find_shift(shift);  // positive definite, so that the timing is one full factorisation + solve
  s.rh.add_to_diagonal(shift);
  bool solved = false;
  for (auto _ : state) {
    std::vector<double> x = s.rg;
    solved = solve_banded_positive_definite(s.rh, x);
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["solved"] = solved ? 1 : 0;
}

void sizes(benchmark::internal::Benchmark* b) {
  for (long w : {2, 6})
    for (long n : {1000, 10000, 100000}) b->Args({n, w});
  b->Unit(benchmark::kMillisecond);
}

BENCHMARK(newton_step)->Apply(sizes);
BENCHMARK(hessian_only)->Apply(sizes);
BENCHMARK(gradient_only)->Apply(sizes);
BENCHMARK(energy_only)->Apply(sizes);
BENCHMARK(solve_only)->Apply(sizes);

}  // namespace
