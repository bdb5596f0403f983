// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Benchmarks of the Cardinal splines (include/fair/Cardinal_spline_2.h):
//  - the optimum of eqs. 18-20 for 10^6 points in double (target <= 20 ms) and for 10^5 points in
//    EPECK with the exact values forced (target <= 2 s);
//  - evaluation throughput of the uniform Catmull-Rom curve (alpha = 1/2) against
//    boost::math::catmull_rom with uniform knots (its alpha = 0), the same curve: Boost's open
//    curve wraps around (p_{-1} = p_n, p_{n+1} = p_0), so ours uses those auxiliary points. The
//    largest difference between the two evaluations is reported as the counter max_diff.
// Run with --benchmark_repetitions=9 --benchmark_report_aggregates_only=true for medians.

#include <fair/Cardinal_spline_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <benchmark/benchmark.h>

#include "bench_inputs.h"
#include <boost/math/interpolators/catmull_rom.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> Kd;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;

// bench_inputs.h's random walk, as the coordinate pairs Boost's catmull_rom takes.
std::vector<std::array<double, 2>> walk(std::size_t n, unsigned seed) {
  std::vector<std::array<double, 2>> w;
  w.reserve(n);
  for (const Kd::Point_2& q : fair_bench::random_walk<Kd>(n, seed)) w.push_back({q.x(), q.y()});
  return w;
}

template <class K>
std::vector<typename K::Point_2> points_of(const std::vector<std::array<double, 2>>& w) {
  std::vector<typename K::Point_2> p;
  p.reserve(w.size());
  for (const auto& a : w) p.emplace_back(a[0], a[1]);
  return p;
}

void BM_optimum_double(benchmark::State& state) {
  const auto p = points_of<Kd>(walk(std::size_t(state.range(0)), 1));
  for (auto _ : state) {
    const auto o = fair::optimal_cardinal_parameters(p);
    benchmark::DoNotOptimize(o.alpha);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_optimum_double)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_optimum_epeck_exact(benchmark::State& state) {
  const auto p = points_of<Epeck>(walk(std::size_t(state.range(0)), 2));
  for (auto _ : state) {
    const auto o = fair::optimal_cardinal_parameters(p);
    // Force the exact values of everything returned.
    benchmark::DoNotOptimize(CGAL::exact(o.alpha));
    benchmark::DoNotOptimize(CGAL::exact(o.aux_start.x()));
    benchmark::DoNotOptimize(CGAL::exact(o.aux_end.y()));
    benchmark::DoNotOptimize(CGAL::exact(o.energy));
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_optimum_epeck_exact)->Arg(100000)->Unit(benchmark::kMillisecond);

// Evaluation: the same 10^5 parameters in [0, n] on a closed-around curve of n = 1000 points.
const std::size_t kPoints = 1000, kEvaluations = 100000;

std::vector<double> parameters(double max) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, max);
  std::vector<double> s(kEvaluations);
  for (double& x : s) x = u(rng);
  return s;
}

fair::Cardinal_spline_2<Kd> fair_catmull_rom(const std::vector<std::array<double, 2>>& w) {
  const auto p = points_of<Kd>(w);
  return fair::Cardinal_spline_2<Kd>(p, 0.5, p.back(), p.front());  // alpha = 1/2, given auxiliary points
}

void BM_eval_fair_catmull_rom(benchmark::State& state) {
  const auto w = walk(kPoints, 4);
  const auto c = fair_catmull_rom(w);
  const auto s = parameters(double(kPoints - 1));
  // Sanity: the same curve as Boost's.
  boost::math::catmull_rom<std::array<double, 2>> b(std::vector<std::array<double, 2>>(w), false, 0.0);
  double diff = 0;
  for (std::size_t k = 0; k < 1000; ++k) {
    const auto q = c.point(s[k]);
    const auto r = b(s[k]);
    diff = std::max(diff, std::max(std::fabs(q.x() - r[0]), std::fabs(q.y() - r[1])));
  }
  for (auto _ : state) {
    double acc = 0;
    for (double u : s) {
      const Kd::Point_2 q = c.point(u);
      acc += q.x() + q.y();
    }
    benchmark::DoNotOptimize(acc);
  }
  state.counters["max_diff"] = diff;
  state.SetItemsProcessed(state.iterations() * std::int64_t(kEvaluations));
}
BENCHMARK(BM_eval_fair_catmull_rom)->Unit(benchmark::kMicrosecond);

void BM_eval_boost_catmull_rom(benchmark::State& state) {
  const auto w = walk(kPoints, 4);
  boost::math::catmull_rom<std::array<double, 2>> b(std::vector<std::array<double, 2>>(w), false, 0.0);
  const auto s = parameters(double(kPoints - 1));
  for (auto _ : state) {
    double acc = 0;
    for (double u : s) {
      const auto q = b(u);
      acc += q[0] + q[1];
    }
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(kEvaluations));
}
BENCHMARK(BM_eval_boost_catmull_rom)->Unit(benchmark::kMicrosecond);

} // namespace
