// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Benchmarks of fair::Optimal_curve_2 (Gumhold's optimal curves, issue 11): the paper-like design
// input (8 points, two normal constraints, rho = 500) with Newton and with the paper's CG (20 steps
// per level); the whole hierarchy up to ~1e4 and ~1e5 vertices at the finest level (closed curve
// through 12 points, rho chosen for the vertex count; the counter "vertices" reports it).
// Run: ./bench_optimal --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include <fair/Optimal_curve_2.h>

#include <CGAL/Simple_cartesian.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 P;

const std::vector<P> design = {P(0, 0), P(1, 2), P(3, 2.5), P(4, 0.5), P(6, 1), P(7, 3), P(9, 2), P(10, 0)};

void paper_like(benchmark::State& state, fair::Optimal_curve_solver solver) {
  fair::Optimal_curve_options o;
  o.resolution = 500;
  o.solver = solver;
  if (solver == fair::Optimal_curve_solver::CONJUGATE_GRADIENT) o.max_iterations_per_level = 20;
  fair::Point_constraint a, b;
  a.index = 2;
  a.kind = fair::Point_constraint_kind::NORMAL;
  a.direction = {{0, 1}};
  b.index = 5;
  b.kind = fair::Point_constraint_kind::NORMAL;
  b.direction = {{-1, 0.3}};
  o.constraints = {a, b};
  std::size_t vertices = 0;
  for (auto _ : state) {
    const fair::Optimal_curve_2<K> c(design, o);
    vertices = c.polygon().size();
    benchmark::DoNotOptimize(c.energy());
  }
  state.counters["vertices"] = static_cast<double>(vertices);
}
BENCHMARK_CAPTURE(paper_like, newton, fair::Optimal_curve_solver::NEWTON)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(paper_like, cg_20_steps, fair::Optimal_curve_solver::CONJUGATE_GRADIENT)->Unit(benchmark::kMillisecond);

// Closed curve through 12 points of a wobbly ellipse, up to the resolution state.range(0) * 1e6.
void hierarchy(benchmark::State& state) {
  std::vector<P> p;
  for (int i = 0; i < 12; ++i) {
    const double t = 2 * M_PI * i / 12, r = 1 + 0.15 * std::cos(3 * t);
    p.push_back(P(2 * r * std::cos(t), r * std::sin(t)));
  }
  fair::Optimal_curve_options o;
  o.closed = true;
  o.resolution = static_cast<double>(state.range(0)) * 1e6;
  o.lambda = -1;  // the raw weights of eq. 5
  o.curvature_weight = 0.01;
  std::size_t vertices = 0, levels = 0;
  for (auto _ : state) {
    const fair::Optimal_curve_2<K> c(p, o);
    vertices = c.polygon().size();
    levels = c.report().levels.size();
    benchmark::DoNotOptimize(c.energy());
  }
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["levels"] = static_cast<double>(levels);
}
BENCHMARK(hierarchy)->Arg(40)->Arg(4000)->Unit(benchmark::kMillisecond);

} // namespace
