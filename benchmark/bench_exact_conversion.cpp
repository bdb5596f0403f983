// Benchmarks of the exact conversion (Karciauskas-Peters Sec. 6): the circle conic
// (w = 3/5) converted with 10^2 .. 10^4 rational marks k/(n+1) in EPECK (target: 10^4 marks
// <= 1 s) and in Simple_cartesian<Gmpq> and double for comparison, and spline_convexity of the
// converted EPECK spline (polygon predicates + per-piece filtered curvature signs).

#include <fair/Exact_spline_conversion.h>
#include <fair/Spline_convexity.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <benchmark/benchmark.h>

#include <vector>

namespace {

template <class K>
fair::Rational_quadratic_bezier_2<K> circle() {
  typedef typename K::Point_2 P;
  typedef typename K::FT FT;
  return fair::Rational_quadratic_bezier_2<K>(P(1, 0), P(FT(1), FT(4) / FT(3)), P(FT(-7) / FT(25), FT(24) / FT(25)),
                                              FT(3) / FT(5));
}

template <class K>
std::vector<typename K::FT> marks(int n) {
  std::vector<typename K::FT> u;
  for (int k = 1; k <= n; ++k) u.push_back(typename K::FT(k) / typename K::FT(n + 1));
  return u;
}

template <class K>
void BM_exact_spline(benchmark::State& state) {
  const fair::Rational_quadratic_bezier_2<K> c = circle<K>();
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    // the marks are made inside the loop: a fresh EPECK DAG each time, as a caller would have
    const fair::Cubic_spline_2<K> s = fair::exact_spline(c, marks<K>(n));
    benchmark::DoNotOptimize(s.control_points().back());
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void BM_convexity_epeck(benchmark::State& state) {
  typedef CGAL::Exact_predicates_exact_constructions_kernel K;
  const fair::Cubic_spline_2<K> s = fair::exact_spline(circle<K>(), marks<K>(static_cast<int>(state.range(0))));
  for (auto _ : state) {
    const fair::Spline_convexity_report<K> r = fair::spline_convexity(s);
    benchmark::DoNotOptimize(r.curve_locally_convex);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

} // namespace

BENCHMARK_TEMPLATE(BM_exact_spline, CGAL::Exact_predicates_exact_constructions_kernel)
    ->Arg(100)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_exact_spline, CGAL::Simple_cartesian<CGAL::Gmpq>)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_exact_spline, CGAL::Simple_cartesian<double>)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_convexity_epeck)->Arg(1000)->Unit(benchmark::kMillisecond);
