// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Certified roots of the conic piece (Yan, Schiller, Schaefer, rational kappa-curves):
//  - eq. 7 (the parameter of Q as curvature extremum, unique root certified by Appendix A) with
//    the double fast path (interval filter + exact fallback), through the generic kernel API
//    for Simple_cartesian<double>, EPECK and Simple_cartesian<Gmpq>, and, for comparison, the
//    generic certified_unique_root of Bernstein_root_isolation.h on the rounded double quartic;
//  - eq. 4 (curvature extrema of a piece): certified isolation + classification through the
//    double kernel and EPECK, and the isolation of the rounded double quartic alone.
// Every benchmark cycles over 4096 seeded random pieces; time per piece = time per iteration.
// Run with --benchmark_repetitions=9 --benchmark_report_aggregates_only=true for medians.

#include <fair/Bernstein_root_isolation.h>
#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/Rational_quadratic_interpolation.h>
#include <fair/internal/conic/interpolation.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

struct Raw {
  double x0, y0, qx, qy, x2, y2, w;
};

const std::vector<Raw>& inputs() {
  static const std::vector<Raw> data = [] {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-1.0, 1.0), lw(-1.5, 1.5);
    std::vector<Raw> v;
    while (v.size() < 4096) {
      Raw r{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), std::pow(2.0, lw(rng))};
      const double area = (r.qx - r.x0) * (r.y2 - r.y0) - (r.qy - r.y0) * (r.x2 - r.x0);
      if (std::fabs(area) < 1e-3) continue; // keep the rebuilt pieces non-degenerate
      v.push_back(r);
    }
    return v;
  }();
  return data;
}

void BM_eq7_double_interval_filter(benchmark::State& state) {
  const std::vector<Raw>& in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    const Raw& r = in[i++ & 4095];
    benchmark::DoNotOptimize(fair::internal::conic::rational_quadratic_extremum_parameter(r.x0, r.y0, r.qx, r.qy, r.x2, r.y2, r.w));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_eq7_double_interval_filter);

void BM_eq7_double_unique_root_of_rounded_quartic(benchmark::State& state) {
  const std::vector<Raw>& in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    const Raw& r = in[i++ & 4095];
    const double v0x = r.x0 - r.qx, v0y = r.y0 - r.qy, v2x = r.x2 - r.qx, v2y = r.y2 - r.qy;
    const double A = v0x * v0x + v0y * v0y, B = v0x * v2x + v0y * v2y, C = v2x * v2x + v2y * v2y;
    const double b[5] = {-r.w * A, -(A + B) / 4, 0.0, (B + C) / 4, r.w * C};
    benchmark::DoNotOptimize(fair::internal::bernstein::certified_unique_root<fair::Unique_root>(b, 5));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_eq7_double_unique_root_of_rounded_quartic);

template <class K>
void BM_eq7_kernel(benchmark::State& state) {
  const std::vector<Raw>& in = inputs();
  std::vector<std::array<typename K::Point_2, 3>> pts;
  std::vector<typename K::FT> ws;
  for (const Raw& r : in) {
    pts.push_back({{typename K::Point_2(r.x0, r.y0), typename K::Point_2(r.qx, r.qy), typename K::Point_2(r.x2, r.y2)}});
    ws.push_back(typename K::FT(r.w));
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & 4095;
    benchmark::DoNotOptimize(fair::curvature_extremum_parameter<K>(pts[k][0], pts[k][1], pts[k][2], ws[k]));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_eq7_kernel, CGAL::Simple_cartesian<double>);
BENCHMARK_TEMPLATE(BM_eq7_kernel, CGAL::Epeck);
BENCHMARK_TEMPLATE(BM_eq7_kernel, CGAL::Simple_cartesian<CGAL::Gmpq>);

// Pieces for eq. 4: P1 rebuilt by eq. 6 at t = 0.5 (so each piece has Q as a critical point).
template <class K>
std::vector<fair::Rational_quadratic_bezier_2<K>> pieces() {
  std::vector<fair::Rational_quadratic_bezier_2<K>> out;
  for (const Raw& r : inputs()) {
    double p1x, p1y;
    fair::internal::conic::rational_quadratic_middle_control_point(r.x0, r.y0, r.qx, r.qy, r.x2, r.y2, r.w, 0.37, p1x, p1y);
    out.emplace_back(typename K::Point_2(r.x0, r.y0), typename K::Point_2(p1x, p1y), typename K::Point_2(r.x2, r.y2),
                     typename K::FT(r.w));
  }
  return out;
}

template <class K>
void BM_eq4_extrema_kernel(benchmark::State& state) {
  const std::vector<fair::Rational_quadratic_bezier_2<K>> pc = pieces<K>();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(pc[i++ & 4095].curvature_extrema());
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_eq4_extrema_kernel, CGAL::Simple_cartesian<double>);
BENCHMARK_TEMPLATE(BM_eq4_extrema_kernel, CGAL::Epeck);

void BM_eq4_isolation_of_rounded_quartic(benchmark::State& state) {
  const std::vector<fair::Rational_quadratic_bezier_2<CGAL::Simple_cartesian<double>>> pc =
    pieces<CGAL::Simple_cartesian<double>>();
  std::size_t i = 0;
  for (auto _ : state) {
    const fair::Bernstein_root_isolation iso(pc[i++ & 4095].curvature_derivative_numerator());
    benchmark::DoNotOptimize(iso.number_of_roots());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_eq4_isolation_of_rounded_quartic);

} // namespace
