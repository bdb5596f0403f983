// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Noise-free figures of the spline core (issue 23 §4): each operation of the targets runs once
// between CALLGRIND_START_INSTRUMENTATION and CALLGRIND_STOP_INSTRUMENTATION, so that
//   valgrind --tool=callgrind --collect-atstart=no ./callgrind_spline_core <operation>
// counts the instructions of that operation alone (the data are built outside the window). The
// inputs are those of bench_csr, bench_spline and bench_cardinal. Not built by CMake (it needs
// valgrind's header only); compile it by hand against the include directory to compare, e.g.
//   g++ -O3 -DNDEBUG -frounding-math -I include benchmark/callgrind_spline_core.cpp -lgmp -lmpfr
// Operations: csr (10^6 samples, chordal), fit (fit_cubic_spline closed, 10^5 vertices),
// point3 / point5 (65536 point evaluations on 10^3 / 10^5 pieces), rational (pieces() of a
// rational spline of 10^5 pieces), alpha (Li's alpha*, 10^6 points).

#include <fair/Cardinal_spline_2.h>
#include <fair/Csr_spline_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/Polygon_spline_fit.h>

#include <CGAL/Simple_cartesian.h>

#include <valgrind/callgrind.h>

#include "bench_inputs.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> Kd;

std::vector<Kd::Point_2> spiral(std::size_t n) { return fair_bench::spiral_samples<Kd>(n); }
std::vector<Kd::Point_2> walk(std::size_t n, unsigned seed) { return fair_bench::random_walk<Kd>(n, seed); }
std::vector<Kd::Point_2> wobbly_circle(std::size_t n) { return fair_bench::wobbly_circle<Kd>(n); }




double sink = 0;

void point(std::size_t pieces) {
  const fair::Cubic_interpolating_spline_2<Kd> c(walk(pieces, 1), fair::Spline_end_condition::NATURAL,
                                                 fair::Knot_spacing::CHORDAL);
  const fair::Cubic_spline_2<Kd>& s = c.spline();
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(s.domain().first, s.domain().second);
  std::vector<double> t(1 << 16);
  for (double& x : t) x = u(rng);
  CALLGRIND_START_INSTRUMENTATION;
  for (double x : t) sink += s.point(x).x();
  CALLGRIND_STOP_INSTRUMENTATION;
}

} // namespace

int main(int argc, char** argv) {
  const char* op = argc > 1 ? argv[1] : "";
  if (!std::strcmp(op, "csr")) {
    const std::vector<Kd::Point_2> q = spiral(1000000);
    CALLGRIND_START_INSTRUMENTATION;
    const fair::Csr_spline_2<Kd> s(q);
    CALLGRIND_STOP_INSTRUMENTATION;
    sink += s.spline().control_points()[1].x();
  } else if (!std::strcmp(op, "fit")) {
    const std::vector<Kd::Point_2> p = wobbly_circle(100000);
    CALLGRIND_START_INSTRUMENTATION;
    sink += fair::fit_cubic_spline<Kd>(p, true).max_distance;
    CALLGRIND_STOP_INSTRUMENTATION;
  } else if (!std::strcmp(op, "point3")) {
    point(1000);
  } else if (!std::strcmp(op, "point5")) {
    point(100000);
  } else if (!std::strcmp(op, "rational")) {
    const fair::Cubic_interpolating_spline_2<Kd> c(walk(100000, 3), fair::Spline_end_condition::NATURAL,
                                                   fair::Knot_spacing::CHORDAL);
    const fair::Cubic_spline_2<Kd>& s = c.spline();
    std::vector<double> w(s.number_of_control_points());
    for (std::size_t i = 0; i < w.size(); ++i) w[i] = 1.0 + 0.5 * std::sin(0.1 * static_cast<double>(i));
    const fair::Cubic_spline_2<Kd> r(s.breakpoints(), s.control_points(), w);
    CALLGRIND_START_INSTRUMENTATION;
    sink += r.pieces().size();
    CALLGRIND_STOP_INSTRUMENTATION;
  } else if (!std::strcmp(op, "alpha")) {
    const std::vector<Kd::Point_2> p = walk(1000000, 1);
    CALLGRIND_START_INSTRUMENTATION;
    sink += fair::optimal_cardinal_parameters(p).alpha;
    CALLGRIND_STOP_INSTRUMENTATION;
  } else {
    std::fprintf(stderr, "usage: %s csr|fit|point3|point5|rational|alpha\n", argv[0]);
    return 1;
  }
  std::printf("%g\n", sink);
  return 0;
}
