// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Benchmarks of the alternating passes of Section 5.1 (internal/kappa/refinement.h), the first
// phase of every cold fair::Kappa_curve_2 solve, on the closed random star-shaped data of
// bench_kappa.cpp (n interpolated points):
//  - one refinement pass (w, t, lambda, P) from the state after 5 passes (the state is restored
//    outside the timed region), unit and automatic weights, with a reused workspace;
//  - the initial guess (one eq. 18 solve, fresh state);
//  - initial guess + passes until max |r| <= 1e-3 (what solve() does before Levenberg-Marquardt),
//    residual evaluations included; counter `passes`.
// Run: ./bench_kappa_refinement --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include <fair/internal/kappa/refinement.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

namespace kp = fair::internal::kappa;

kp::Problem random_star(std::size_t n, unsigned seed, fair::Kappa_weights mode) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> U(0, 1);
  kp::Problem pb;
  pb.closed = true;
  pb.n = n;
  pb.mode = mode;
  pb.tension.assign(n, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * M_PI * (i + 0.2 * (U(g) - 0.5)) / n;
    const double r = 1 + 0.05 * (i % 2 ? 1 : -1) * (0.5 + U(g));
    pb.qx.push_back(r * std::cos(a));
    pb.qy.push_back(r * std::sin(a));
  }
  return pb;
}

void pass(benchmark::State& state, fair::Kappa_weights mode) {
  const kp::Problem pb = random_star(static_cast<std::size_t>(state.range(0)), 1, mode);
  kp::Refinement_workspace ws;
  fair::Kappa_solver_state s0;
  kp::initial_guess(pb, s0, ws);
  for (int k = 0; k < 5; ++k) kp::refinement_pass(pb, s0, ws);
  fair::Kappa_solver_state st = s0;
  for (auto _ : state) {
    state.PauseTiming();
    st.dx = s0.dx; st.dy = s0.dy; st.lambda = s0.lambda; st.t = s0.t; st.w = s0.w;  // no allocation
    state.ResumeTiming();
    kp::refinement_pass(pb, st, ws);
    benchmark::DoNotOptimize(st.dx.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_kappa_refinement_pass_unit(benchmark::State& state) { pass(state, fair::Kappa_weights::UNIT); }
void BM_kappa_refinement_pass_automatic(benchmark::State& state) { pass(state, fair::Kappa_weights::AUTOMATIC); }
BENCHMARK(BM_kappa_refinement_pass_unit)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_kappa_refinement_pass_automatic)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

void BM_kappa_initial_guess(benchmark::State& state) {
  const kp::Problem pb = random_star(static_cast<std::size_t>(state.range(0)), 1, fair::Kappa_weights::UNIT);
  for (auto _ : state) {
    fair::Kappa_solver_state st;
    kp::initial_guess(pb, st);
    benchmark::DoNotOptimize(st.dx.data());
  }
}
BENCHMARK(BM_kappa_initial_guess)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

void BM_kappa_refine_to_1e3(benchmark::State& state) {
  const kp::Problem pb = random_star(static_cast<std::size_t>(state.range(0)), 1, fair::Kappa_weights::UNIT);
  std::size_t passes = 0;
  for (auto _ : state) {
    fair::Kappa_solver_state st;
    fair::Kappa_curve_report res;
    kp::initial_guess(pb, st);
    benchmark::DoNotOptimize(kp::refine(pb, st, 60, 1e-3, res));
    passes = res.refinement_passes;
  }
  state.counters["passes"] = static_cast<double>(passes);
}
BENCHMARK(BM_kappa_refine_to_1e3)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

} // namespace
