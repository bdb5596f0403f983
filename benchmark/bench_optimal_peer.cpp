// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Issue 11 §5/§6: the OCCT batten side by side with fair::Optimal_curve_2 (the free-length
// elastica between two points with clamped tangents, angles 0.5 and 0.5 to the chord), and the
// CAD output: fit_cubic_spline / fit_quintic_spline through 10^3 .. 10^5 vertices (O(n)).
// BM_occt_batten is built only when OCCT is found (bench_optimal_peer.cmake).

#include <fair/Optimal_curve_2.h>
#include <fair/Polygon_spline_fit.h>

#include <CGAL/Simple_cartesian.h>

#ifdef FAIR_HAVE_OCCT
// after CGAL: OCCT's macro `Handle` breaks CGAL's headers
#include <FairCurve_AnalysisCode.hxx>
#include <FairCurve_Batten.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <gp_Pnt2d.hxx>
#endif

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> K;

const double batten_angle = 0.5;

#ifdef FAIR_HAVE_OCCT
void BM_occt_batten(benchmark::State& state) {
  for (auto _ : state) {
    FairCurve_Batten batten(gp_Pnt2d(0, 0), gp_Pnt2d(1, 0), 0.01);
    batten.SetFreeSliding(Standard_True);
    batten.SetAngle1(batten_angle);
    batten.SetAngle2(batten_angle);
    FairCurve_AnalysisCode code;
    benchmark::DoNotOptimize(batten.Compute(code, 200, 1e-9));
    benchmark::DoNotOptimize(batten.Curve());
  }
}
BENCHMARK(BM_occt_batten)->Unit(benchmark::kMillisecond);
#endif

// The same batten: beta = 0, beta_0 = 1, the tangents (cos a, +-sin a), rho = 500 and 1000.
void BM_optimal_batten(benchmark::State& state) {
  fair::Optimal_curve_options o;
  o.lambda = -1;  // the raw weights of eq. 5
  o.length_weight = 0;
  o.curvature_weight = 1;
  o.resolution = static_cast<double>(state.range(0));
  fair::Point_constraint c0, c1;
  c0.index = 0;
  c0.kind = fair::Point_constraint_kind::TANGENT;
  c0.direction = {{std::cos(batten_angle), std::sin(batten_angle)}};
  c1 = c0;
  c1.index = 1;
  c1.direction = {{std::cos(batten_angle), -std::sin(batten_angle)}};
  o.constraints = {c0, c1};
  const std::vector<K::Point_2> p{K::Point_2(0, 0), K::Point_2(1, 0)};
  for (auto _ : state) {
    const fair::Optimal_curve_2<K> curve(p, o);
    benchmark::DoNotOptimize(curve.polygon().data());
  }
}
BENCHMARK(BM_optimal_batten)->Arg(500)->Arg(1000)->Unit(benchmark::kMillisecond);

std::vector<K::Point_2> ellipse_polygon(std::size_t n) {
  std::vector<K::Point_2> p;
  const double two_pi = 2 * std::acos(-1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i) / static_cast<double>(n);
    const double t = two_pi * (x + 0.4 / two_pi * std::sin(two_pi * x));
    p.push_back(K::Point_2(2 * std::cos(t), 0.7 * std::sin(t)));
  }
  return p;
}

void BM_fit_cubic_closed(benchmark::State& state) {
  const std::vector<K::Point_2> p = ellipse_polygon(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(fair::fit_cubic_spline<K>(p, true).max_distance);
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_fit_cubic_closed)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_fit_quintic_closed(benchmark::State& state) {
  const std::vector<K::Point_2> p = ellipse_polygon(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(fair::fit_quintic_spline<K>(p, true).max_distance);
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_fit_quintic_closed)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

} // namespace
