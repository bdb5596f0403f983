// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The seeded inputs of the spline-core benchmarks, in one place so that bench_csr, bench_spline
// and the instruction counts of callgrind_spline_core.cpp measure the same data.

#ifndef FAIR_BENCH_INPUTS_H
#define FAIR_BENCH_INPUTS_H

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace fair_bench {

// n samples of a curve mixing arcs of different curvature (the csr-spline's use case): the
// spiral r = 1 + theta / 4 at roughly unit arc-length steps, with a little seeded jitter.
template <class K>
std::vector<typename K::Point_2> spiral_samples(std::size_t n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  std::vector<typename K::Point_2> p;
  p.reserve(n);
  double theta = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = 1 + theta / 4;
    p.emplace_back(r * std::cos(theta), r * std::sin(theta));
    theta += (0.5 + jitter(rng)) / r;
  }
  return p;
}

// A random walk with turning steps: distinct consecutive points, a curvy polyline.
template <class K>
std::vector<typename K::Point_2> random_walk(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> turn(-0.8, 0.8), step(0.5, 1.5);
  std::vector<typename K::Point_2> p;
  p.reserve(n);
  double x = 0, y = 0, h = 0;
  for (std::size_t i = 0; i < n; ++i) {
    p.emplace_back(x, y);
    h += turn(rng);
    const double s = step(rng);
    x += s * std::cos(h);
    y += s * std::sin(h);
  }
  return p;
}

// A closed polygon: n points on the wobbly circle r = 1 + 0.1 sin 7a (distinct consecutive vertices).
template <class K>
std::vector<typename K::Point_2> wobbly_circle(std::size_t n) {
  std::vector<typename K::Point_2> p;
  p.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    const double r = 1 + 0.1 * std::sin(7 * a);
    p.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return p;
}

}  // namespace fair_bench

#endif  // FAIR_BENCH_INPUTS_H
