// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Benchmarks of the csr-spline (include/fair/Csr_spline_2.h): the construction of the cubic C2
// spline (chordal knots, curvatures, the eq.-6 control points, the Cubic_spline_2 with its
// validation) from n samples
//  - in double for n = 10^3, 10^4, 10^5, 10^6 (growth; target <= 30 ms at 10^6: O(n), no solve);
//  - in EPECK for n = 10^4 (exact control points for the rounded chordal knots);
//  - in double, the same with uniform knots (no square roots for the knots);
//  - last, "warm": 10^6 in double after telling glibc to keep freed memory (mallopt), so that an
//    iteration reuses the previous one's pages instead of faulting in ~40 MB of fresh memory (the
//    result's knots, control points, weights and curvatures). Page faults cost ~13 us each on the
//    shared VM this was written on, i.e. ~130 ms per 40 MB: the cold runs measure mostly them.
// Run with --benchmark_repetitions=9 --benchmark_report_aggregates_only=true for medians.

#include <fair/Csr_spline_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <benchmark/benchmark.h>

#include "bench_inputs.h"
#include <malloc.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> Kd;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;

template <class K>
std::vector<typename K::Point_2> samples(std::size_t n) { return fair_bench::spiral_samples<K>(n); }

template <class K>
void construct(benchmark::State& state, fair::Knot_spacing spacing) {
  const auto q = samples<K>(std::size_t(state.range(0)));
  fair::Csr_spline_options o;
  o.knot_spacing = spacing;
  for (auto _ : state) {
    const fair::Csr_spline_2<K> s(q, o);
    benchmark::DoNotOptimize(s.spline().control_points().data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_csr_double_chordal(benchmark::State& state) { construct<Kd>(state, fair::Knot_spacing::CHORDAL); }
void BM_csr_double_uniform(benchmark::State& state) { construct<Kd>(state, fair::Knot_spacing::UNIFORM); }
void BM_csr_epeck_chordal(benchmark::State& state) { construct<Epeck>(state, fair::Knot_spacing::CHORDAL); }
void BM_csr_double_chordal_warm(benchmark::State& state) {
  mallopt(M_MMAP_THRESHOLD, 1 << 30);  // large blocks from the heap ...
  mallopt(M_TRIM_THRESHOLD, -1);       // ... which is never given back
  construct<Kd>(state, fair::Knot_spacing::CHORDAL);
}

BENCHMARK(BM_csr_double_chordal)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_csr_double_uniform)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_csr_epeck_chordal)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_csr_double_chordal_warm)->Arg(1000000)->Unit(benchmark::kMillisecond);  // last: mallopt stays

} // namespace
