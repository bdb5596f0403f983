// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Benchmarks of fair::Kappa_curve_2 (rational kappa-curves): time to converge on closed
// random star-shaped point sets (every point a corner, alternately convex and concave: the
// data kappa-curves are made for) with unit and automatic weights; a warm re-solve after moving
// one point of a 1000-point curve (also one that changes which points are on joins); dense
// smooth closed curves with inflections (r(a) = 1 + amplitude sin(lobes a), jittered angles,
// with and without small noise: issue 9); exact certification (fair::certify).
// Run: ./bench_kappa --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include <fair/Kappa_certificate.h>
#include <fair/Kappa_curve_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 P;

std::vector<P> random_star(std::size_t n, unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<P> p;
  p.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * M_PI * (i + 0.2 * (U(g) - 0.5)) / n;
    const double r = 1 + 0.05 * (i % 2 ? 1 : -1) * (0.5 + U(g));
    p.push_back(P(r * std::cos(a), r * std::sin(a)));
  }
  return p;
}

// Dense smooth closed curve with 2 * lobes inflections: r(a) = 1 + amplitude sin(lobes a) at n
// angles jittered by up to +-jitter/2 of the spacing, radii perturbed by relative noise of up to
// +-noise/2 (seeded).
std::vector<P> dense_inflected(std::size_t n, int lobes, double amplitude, double jitter, double noise, unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<P> p;
  p.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * M_PI * (i + jitter * (U(g) - 0.5)) / n;
    const double r = (1 + amplitude * std::sin(lobes * a)) * (1 + noise * (U(g) - 0.5));
    p.push_back(P(r * std::cos(a), r * std::sin(a)));
  }
  return p;
}

void solve_points(benchmark::State& state, const std::vector<P>& points, fair::Kappa_weights weights) {
  fair::Kappa_curve_options o;
  o.closed = true;
  o.weights = weights;
  std::size_t iterations = 0, passes = 0, on_joins = 0, beyond = 0;
  double residual = 0;
  bool converged = true;  // INTERIOR or ON_JOINS (the box-constrained solution)
  for (auto _ : state) {
    const fair::Kappa_curve_2<K> curve(points, o);
    iterations = curve.report().iterations;
    passes = curve.report().refinement_passes;
    residual = curve.report().residual;
    on_joins = curve.report().points_on_joins.size();
    beyond = curve.report().points_beyond_density_limit.size();
    converged = converged && curve.report().status != fair::Kappa_curve_status::UNSOLVED;
    benchmark::DoNotOptimize(curve.pieces().data());
  }
  state.counters["jacobians"] = static_cast<double>(iterations);
  state.counters["passes"] = static_cast<double>(passes);
  state.counters["converged"] = converged ? 1 : 0;
  state.counters["residual"] = residual;
  state.counters["on_joins"] = static_cast<double>(on_joins);
  state.counters["beyond_limit"] = static_cast<double>(beyond);  // UNSOLVED: points beyond the density limit
  state.SetComplexityN(state.range(0));
}

void solve(benchmark::State& state, fair::Kappa_weights weights) {
  solve_points(state, random_star(static_cast<std::size_t>(state.range(0)), 1), weights);
}

void BM_kappa_closed_unit(benchmark::State& state) { solve(state, fair::Kappa_weights::UNIT); }
void BM_kappa_closed_automatic(benchmark::State& state) { solve(state, fair::Kappa_weights::AUTOMATIC); }
BENCHMARK(BM_kappa_closed_unit)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
// 10^5: as many iterations as the minimum time asks for (not one), so that its median, like the
// 10^4 one, is of solves in a warmed-up process: the first solve of a process pays the page
// faults of fresh memory (on this VM about half of it, doc/benchmarks.md).
BENCHMARK(BM_kappa_closed_unit)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_kappa_closed_automatic)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_kappa_closed_automatic)->Arg(100000)->Unit(benchmark::kMillisecond);

// Dense inflected closed curves (issue 9, Sec. 4). Args: n, lobes, amplitude in %, jitter in %
// of the spacing, noise in 1e-4 (relative radius), weights (0 unit, 1 automatic).
void BM_kappa_dense_inflected(benchmark::State& state) {
  const std::vector<P> points =
      dense_inflected(static_cast<std::size_t>(state.range(0)), static_cast<int>(state.range(1)), 0.01 * static_cast<double>(state.range(2)),
                      0.01 * static_cast<double>(state.range(3)), 1e-4 * static_cast<double>(state.range(4)), 3);
  solve_points(state, points, state.range(5) ? fair::Kappa_weights::AUTOMATIC : fair::Kappa_weights::UNIT);
}
BENCHMARK(BM_kappa_dense_inflected)
    ->Args({1000, 7, 30, 40, 0, 0})
    ->Args({1000, 3, 10, 40, 0, 0})
    ->Args({1000, 7, 30, 40, 10, 0})
    ->Args({1000, 7, 30, 40, 0, 1})
    ->Args({10000, 7, 30, 40, 0, 0})
    ->Args({10000, 7, 30, 40, 0, 1})
    ->Args({10000, 7, 30, 40, 10, 0})
    ->Args({10000, 7, 30, 40, 10, 1})
    ->Args({100000, 7, 30, 40, 0, 0})
    ->Args({100000, 7, 30, 40, 0, 1})
    ->Args({100000, 7, 30, 40, 10, 0})  // issue 24: dense noisy data at 10^5 too
    ->Args({100000, 7, 30, 40, 10, 1})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// Dense uniform samples of the ellipse (cos a, 0.95 sin a): no inflection, |kappa| varying by
// +-15 %. UNSOLVED from n = 50 on (doc/kappa_curves.md, "Dense smooth data", session 9): the
// time of a failing dense solve.
void BM_kappa_dense_ellipse(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  std::vector<P> points;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    points.push_back(P(std::cos(a), 0.95 * std::sin(a)));
  }
  solve_points(state, points, fair::Kappa_weights::UNIT);
}
BENCHMARK(BM_kappa_dense_ellipse)->Arg(48)->Arg(1000)->Arg(10000)->Iterations(1)->Unit(benchmark::kMillisecond);

// Warm re-solve: move one point of a converged 1000-point curve by 1 % and solve again from
// the previous solution (alternating back and forth so every iteration does real work).
void BM_kappa_warm_resolve_1000(benchmark::State& state) {
  std::vector<P> points = random_star(1000, 2);
  fair::Kappa_curve_options o;
  o.closed = true;
  fair::Kappa_curve_2<K> curve(points, o);
  const P a = points[500], b(a.x() * 1.01, a.y() * 1.01);
  bool flip = false, warm = true;
  for (auto _ : state) {
    curve.move_point(500, flip ? a : b);
    flip = !flip;
    warm = warm && curve.report().warm_started && (curve.report().status == fair::Kappa_curve_status::INTERIOR);
  }
  state.counters["warm_and_converged"] = warm ? 1 : 0;
}
BENCHMARK(BM_kappa_warm_resolve_1000)->Unit(benchmark::kMillisecond);

// Warm re-solve that changes which points are on joins: point 500 of the same curve alternates
// between its place (INTERIOR) and a place 0.2 beyond the chord of its neighbours (ON_JOINS).
void BM_kappa_warm_resolve_join_change_1000(benchmark::State& state) {
  std::vector<P> points = random_star(1000, 2);
  fair::Kappa_curve_options o;
  o.closed = true;
  fair::Kappa_curve_2<K> curve(points, o);
  const P a = points[500], m = CGAL::midpoint(points[499], points[501]);
  const P b = m + 0.2 * (m - a);
  bool flip = false, warm = true, changed = true;
  for (auto _ : state) {
    curve.move_point(500, flip ? a : b);
    flip = !flip;
    warm = warm && curve.report().warm_started;
    changed = changed && curve.report().status == (flip ? fair::Kappa_curve_status::ON_JOINS : fair::Kappa_curve_status::INTERIOR);
  }
  state.counters["warm"] = warm ? 1 : 0;
  state.counters["joins_changed"] = changed ? 1 : 0;
}
BENCHMARK(BM_kappa_warm_resolve_join_change_1000)->Unit(benchmark::kMillisecond);

// Exact certification of 10^4 pieces, as 500 closed curves of 20 pieces or 100 of 100 (the
// exact control points have ~200 n bits: O(n^2) bit operations per curve, see
// doc/kappa_curves.md). Arg 1: 0 = fair::certify (interval filter for eq. 4, exact fallback),
// 1 = forced exact eq.-4 isolation for every piece (internal::kappa::Certify_mode::EXACT).
void BM_kappa_certify_10000_pieces(benchmark::State& state) {
  const std::size_t per_curve = static_cast<std::size_t>(state.range(0));
  const bool exact = state.range(1) != 0;
  const std::size_t curves_count = 10000 / per_curve;
  std::vector<fair::Kappa_curve_2<K>> curves;
  fair::Kappa_curve_options o;
  o.closed = true;
  for (std::size_t c = 0; c < curves_count; ++c) curves.emplace_back(random_star(per_curve, 100 + c), o);
  std::size_t valid = 0;
  namespace kp = fair::internal::kappa;
  for (auto _ : state) {
    valid = 0;
    for (const auto& curve : curves)
      valid += (exact ? kp::certify_curve(curve, kp::Certify_mode::EXACT) : fair::certify(curve)).valid() ? 1 : 0;
  }
  state.counters["valid_curves"] = static_cast<double>(valid);
  state.counters["curves"] = static_cast<double>(curves_count);
}
BENCHMARK(BM_kappa_certify_10000_pieces)->Args({20, 0})->Args({100, 0})->Args({20, 1})->Iterations(1)->Unit(benchmark::kMillisecond);

// O(n) certification of the pieces actually returned (fair::certify_pieces): one closed EPECK
// curve of 10^4 pieces (its E_j exact from the rounded P_j), certified piece by piece.
void BM_kappa_certify_pieces_epeck(benchmark::State& state) {
  typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  std::vector<EK::Point_2> q;
  for (const P& p : random_star(n, 7)) q.push_back(EK::Point_2(p.x(), p.y()));
  fair::Kappa_curve_options o;
  o.closed = true;
  const fair::Kappa_curve_2<EK> curve(q, o);
  bool valid = false;
  for (auto _ : state) valid = fair::certify_pieces(curve).valid_within(1e-12);
  state.counters["valid"] = valid ? 1 : 0;
}
BENCHMARK(BM_kappa_certify_pieces_epeck)->Arg(10000)->Iterations(1)->Unit(benchmark::kMillisecond);

} // namespace
