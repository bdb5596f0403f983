// Benchmarks of the Bernstein root isolation: general certified isolation of random degree-4 and
// degree-10 polynomials with double, point-interval and exact (Gmpq, EPECK FT) coefficients,
// and the fast certified unique-root path on eq. (7) of the kappa-curve paper.

#include <fair/Bernstein_root_isolation.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <benchmark/benchmark.h>

#include <array>
#include <random>
#include <vector>

namespace {

constexpr std::size_t pool = 256;

std::vector<std::vector<double>> random_coefficients(std::size_t degree, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1, 1);
  std::vector<std::vector<double>> out(pool, std::vector<double>(degree + 1));
  for (auto& b : out)
    for (double& x : b) x = d(rng);
  return out;
}

template <class NT>
void BM_isolate(benchmark::State& state) {
  const std::size_t degree = static_cast<std::size_t>(state.range(0));
  std::vector<fair::Bernstein_polynomial<NT>> polys;
  for (const auto& b : random_coefficients(degree, 42)) polys.emplace_back(std::vector<NT>(b.begin(), b.end()));
  std::size_t i = 0, roots = 0;
  for (auto _ : state) {
    const fair::Bernstein_root_isolation iso(polys[i++ % pool]);
    roots += iso.number_of_roots();
    benchmark::DoNotOptimize(roots);
  }
  state.counters["roots/poly"] = double(roots) / double(state.iterations());
}
BENCHMARK_TEMPLATE(BM_isolate, double)->Arg(4)->Arg(10);
BENCHMARK_TEMPLATE(BM_isolate, CGAL::Interval_nt<>)->Arg(4)->Arg(10);
BENCHMARK_TEMPLATE(BM_isolate, CGAL::Gmpq)->Arg(4)->Arg(10);
BENCHMARK_TEMPLATE(BM_isolate, CGAL::Epeck::FT)->Arg(4)->Arg(10);

// Isolation plus a one-ulp double approximation of every root.
void BM_isolate_and_approximate(benchmark::State& state) {
  const std::size_t degree = static_cast<std::size_t>(state.range(0));
  const auto coeffs = random_coefficients(degree, 43);
  std::size_t i = 0;
  for (auto _ : state) {
    fair::Bernstein_root_isolation iso(fair::Bernstein_polynomial<double>(coeffs[i++ % pool]));
    benchmark::DoNotOptimize(iso.root_approximations());
  }
}
BENCHMARK(BM_isolate_and_approximate)->Arg(4)->Arg(10);

// Eq. (7) of the kappa-curve paper: (-w A, -(A+B)/4, 0, (B+C)/4, w C), one sign change.
std::vector<std::array<double, 5>> kappa_equations() {
  std::mt19937 rng(44);
  std::uniform_real_distribution<double> area(1e-3, 10.0), weight(0.05, 20.0), mix(-1, 1);
  std::vector<std::array<double, 5>> out(pool);
  for (auto& b : out) {
    const double A = area(rng), C = area(rng), w = weight(rng), B = mix(rng) * std::min(A, C);
    b = {-w * A, -(A + B) / 4, 0.0, (B + C) / 4, w * C};
  }
  return out;
}

void BM_unique_root_kappa_array(benchmark::State& state) {
  const auto eqs = kappa_equations();
  std::size_t i = 0;
  for (auto _ : state) {
    const fair::Unique_root u = fair::certified_unique_root(eqs[i++ % pool]);
    benchmark::DoNotOptimize(u.root);
  }
}
BENCHMARK(BM_unique_root_kappa_array);

// The same with a one-ulp bracket (adjacent doubles: more exact evaluations near the root).
void BM_unique_root_kappa_array_one_ulp(benchmark::State& state) {
  const auto eqs = kappa_equations();
  std::size_t i = 0;
  for (auto _ : state) {
    const fair::Unique_root u = fair::certified_unique_root(eqs[i++ % pool], 1.0);
    benchmark::DoNotOptimize(u.root);
  }
}
BENCHMARK(BM_unique_root_kappa_array_one_ulp);

void BM_unique_root_kappa_polynomial(benchmark::State& state) {
  const auto eqs = kappa_equations();
  std::vector<fair::Bernstein_polynomial<double>> polys;
  for (const auto& b : eqs) polys.emplace_back(std::vector<double>(b.begin(), b.end()));
  std::size_t i = 0;
  for (auto _ : state) {
    const fair::Unique_root u = fair::certified_unique_root(polys[i++ % pool]);
    benchmark::DoNotOptimize(u.root);
  }
}
BENCHMARK(BM_unique_root_kappa_polynomial);

// The same equations through the general isolation, for comparison.
void BM_general_isolation_kappa(benchmark::State& state) {
  const auto eqs = kappa_equations();
  std::vector<fair::Bernstein_polynomial<double>> polys;
  for (const auto& b : eqs) polys.emplace_back(std::vector<double>(b.begin(), b.end()));
  std::size_t i = 0;
  for (auto _ : state) {
    fair::Bernstein_root_isolation iso(polys[i++ % pool]);
    benchmark::DoNotOptimize(iso.root_approximation(0));
  }
}
BENCHMARK(BM_general_isolation_kappa);

} // namespace
