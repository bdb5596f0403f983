// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Benchmarks of the parametric-curve spline (include/fair/Parametric_curve_spline.h) and of the
// marked-point parameters (include/fair/Marked_point_parameters.h):
//  - parametric_curve_spline of an Archimedean spiral with 10^3, 10^4 (and, in double, 10^5: linear) marks, in double and in
//    EPECK (O(m): one 2-jet per mark, eqs. 7, 8, 3 in FT);
//  - quintic_pieces of the same spiral with 10^4 marks;
//  - nearest_parameter (eq. 5) of points on a three-turn spiral (64 samples + safeguarded Newton),
//    and the closed forms circle_arc_parameter / conic_parameter for comparison.
// Run with --benchmark_repetitions=9 --benchmark_report_aggregates_only=true for medians.

#include <fair/Marked_point_parameters.h>
#include <fair/Parametric_curve_spline.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> Kd;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
const double pi = 3.14159265358979323846;

const fair::Archimedean_spiral_2 spiral(0.0, 1 / (6 * pi), pi, 6 * pi);

std::vector<double> marks(std::size_t m) {
  std::vector<double> u(m + 1);
  for (std::size_t i = 0; i <= m; ++i) u[i] = (i == m) ? 6 * pi : pi + 5 * pi * double(i) / double(m);
  return u;
}

template <class K>
void BM_spiral_spline(benchmark::State& state) {
  const std::vector<double> u = marks(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    fair::Cubic_spline_2<K> s = fair::parametric_curve_spline<K>(spiral, u);
    benchmark::DoNotOptimize(s);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK_TEMPLATE(BM_spiral_spline, Kd)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_spiral_spline, Epeck)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_spiral_quintics(benchmark::State& state) {
  const std::vector<double> u = marks(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    std::vector<fair::Bezier_2<Kd>> q = fair::quintic_pieces<Kd>(spiral, u);
    benchmark::DoNotOptimize(q);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_spiral_quintics)->Arg(10000)->Unit(benchmark::kMicrosecond);

void BM_nearest_parameter_spiral(benchmark::State& state) {
  std::vector<std::pair<double, double>> q;
  for (int k = 0; k < 100; ++k) {
    const fair::Curve_jet_2 j = spiral.jet(pi + 5 * pi * (k + 0.37) / 100);
    q.emplace_back(j.x, j.y);
  }
  for (auto _ : state)
    for (const auto& p : q) benchmark::DoNotOptimize(fair::nearest_parameter(spiral, p.first, p.second, pi, 6 * pi));
  state.SetItemsProcessed(state.iterations() * 100);
}
BENCHMARK(BM_nearest_parameter_spiral)->Unit(benchmark::kMicrosecond);

void BM_circle_arc_parameter(benchmark::State& state) {
  double a = 0.001, s = 0;
  for (auto _ : state) {
    s += fair::circle_arc_parameter(a, 2.0);
    a = (a > 1.9) ? 0.001 : a + 0.01;
  }
  benchmark::DoNotOptimize(s);
}
BENCHMARK(BM_circle_arc_parameter);

void BM_conic_parameter(benchmark::State& state) {
  const fair::Parametric_conic_arc_2 arc(-1, 0.5, 0.7, 2.0, 2.5, -0.3, 0.6);
  const fair::Curve_jet_2 j = arc.jet(0.3);
  for (auto _ : state) benchmark::DoNotOptimize(fair::conic_parameter(arc, j.x, j.y));
}
BENCHMARK(BM_conic_parameter);

} // namespace
