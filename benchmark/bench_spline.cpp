// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Benchmarks of fair::Cubic_spline_2 (include/fair/Cubic_spline_2.h):
//  - evaluation throughput of Cubic_spline_2::point(t) (binary search + the piece's four Bezier
//    points by eq. 2 + homogeneous de Casteljau) against evaluating the stored Bezier pieces of
//    the classic C2 interpolant (Cubic_interpolating_spline_2, the same curve: its spline());
//  - all pieces of a spline of 10^5 pieces (pieces(), eq. 2), polynomial and rational;
//  - Boehm insertion of one knot into 10^5 pieces (the O(m) copy);
//  - the exact (EPECK) evaluation;
//  - fit_cubic_spline of a closed polygon of 10^5 vertices (the optimal curves' CAD output: the
//    periodic chordal interpolant, its Cubic_spline_2 and the measured distance to the polygon).
// Run with --benchmark_repetitions=9 --benchmark_report_aggregates_only=true for medians.

#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/Polygon_spline_fit.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <benchmark/benchmark.h>

#include "bench_inputs.h"

#include <cmath>
#include <random>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> Kd;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;

template <class K>
std::vector<typename K::Point_2> walk(std::size_t n, unsigned seed) { return fair_bench::random_walk<K>(n, seed); }

constexpr std::size_t evaluations = 1 << 16;

std::vector<double> random_parameters(double t0, double t1, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(t0, t1);
  std::vector<double> t(evaluations);
  for (double& x : t) x = u(rng);
  return t;
}

void BM_spline_point(benchmark::State& state) {
  const fair::Cubic_interpolating_spline_2<Kd> c(walk<Kd>(static_cast<std::size_t>(state.range(0)), 1),
                                                 fair::Cubic_interpolating_spline_options{false, fair::Spline_end_condition::NATURAL, fair::Knot_spacing::CHORDAL});
  const fair::Cubic_spline_2<Kd>& s = c.spline();
  const std::vector<double> t = random_parameters(s.domain().first, s.domain().second, 2);
  for (auto _ : state)
    for (double x : t) benchmark::DoNotOptimize(s.point(x));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * evaluations));
}
BENCHMARK(BM_spline_point)->Arg(1000)->Arg(100000);

// The classic interpolant's stored pieces: the same binary search, then Bezier_2::point.
void BM_classic_pieces_point(benchmark::State& state) {
  const fair::Cubic_interpolating_spline_2<Kd> c(walk<Kd>(static_cast<std::size_t>(state.range(0)), 1),
                                                 fair::Cubic_interpolating_spline_options{false, fair::Spline_end_condition::NATURAL, fair::Knot_spacing::CHORDAL});
  const std::vector<double>& u = c.knots();
  const std::vector<double> t = random_parameters(u.front(), u.back(), 2);
  for (auto _ : state)
    for (double x : t) {
      std::size_t i = static_cast<std::size_t>(std::upper_bound(u.begin(), u.end(), x) - u.begin());
      i = std::min(i == 0 ? 0 : i - 1, c.number_of_pieces() - 1);
      benchmark::DoNotOptimize(c.pieces()[i].point((x - u[i]) / (u[i + 1] - u[i])));
    }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * evaluations));
}
BENCHMARK(BM_classic_pieces_point)->Arg(1000)->Arg(100000);

void BM_spline_pieces(benchmark::State& state) {
  const std::size_t n = 100000;
  const fair::Cubic_interpolating_spline_2<Kd> c(walk<Kd>(n, 3), fair::Cubic_interpolating_spline_options{false, fair::Spline_end_condition::NATURAL, fair::Knot_spacing::CHORDAL});
  const fair::Cubic_spline_2<Kd>& s = c.spline();
  const bool rational = state.range(0) == 1;
  std::vector<double> w(s.number_of_control_points());
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = 1.0 + 0.5 * std::sin(0.1 * static_cast<double>(i));
  const fair::Cubic_spline_2<Kd> r(s.breakpoints(), s.control_points(), w);
  for (auto _ : state) {
    if (rational) benchmark::DoNotOptimize(r.pieces());
    else benchmark::DoNotOptimize(s.polynomial_pieces());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * s.number_of_pieces()));
}
BENCHMARK(BM_spline_pieces)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_spline_knot_insertion(benchmark::State& state) {
  const fair::Cubic_interpolating_spline_2<Kd> c(walk<Kd>(100000, 4), fair::Cubic_interpolating_spline_options{false, fair::Spline_end_condition::NATURAL, fair::Knot_spacing::UNIFORM});
  const fair::Cubic_spline_2<Kd>& s = c.spline();
  for (auto _ : state) benchmark::DoNotOptimize(s.with_knot_inserted(50000.5));
}
BENCHMARK(BM_spline_knot_insertion)->Unit(benchmark::kMillisecond);

void BM_spline_point_epeck(benchmark::State& state) {
  const fair::Cubic_interpolating_spline_2<Epeck> c(walk<Epeck>(1000, 5), fair::Cubic_interpolating_spline_options{false, fair::Spline_end_condition::NATURAL, fair::Knot_spacing::UNIFORM});
  const fair::Cubic_spline_2<Epeck>& s = c.spline();
  std::vector<Epeck::FT> t;
  for (int k = 0; k < 1000; ++k) t.push_back(Epeck::FT(k * 999) / Epeck::FT(1000));
  for (auto _ : state)
    for (const auto& x : t) {
      const auto p = s.point(x);
      benchmark::DoNotOptimize(p.x().exact());
    }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * t.size()));
}
BENCHMARK(BM_spline_point_epeck)->Unit(benchmark::kMillisecond);

void BM_fit_cubic_spline_closed(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const std::vector<Kd::Point_2> p = fair_bench::wobbly_circle<Kd>(n);  // closed
  for (auto _ : state) benchmark::DoNotOptimize(fair::fit_cubic_spline<Kd>(p, true).max_distance);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * n));
}
BENCHMARK(BM_fit_cubic_spline_closed)->Arg(100000)->Unit(benchmark::kMillisecond);

} // namespace
