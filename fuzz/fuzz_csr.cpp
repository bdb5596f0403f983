// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fuzz target: fair::Csr_spline_2 (open and closed; every knot spacing, both epsilon rules, a
// decoded relative epsilon; knots from the spacing or given parameters, increasing steps from
// the decoder or arbitrary numbers) on decoded samples (fuzz_common.h). Oracle: the spline,
// its pieces, discrete curvatures, epsilon and distances to the samples finite; typed errors
// only (doc/fuzzing.md).

#include "fuzz_common.h"

#include <fair/Csr_spline_2.h>

#include <CGAL/Simple_cartesian.h>

namespace {
// Named inside the unnamed namespace: fuzz_replay is one unity translation unit of every target
// (fuzz/CMakeLists.txt), whose file-local names must not clash.
namespace csr_target {

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 Point_2;
using fair_fuzz::require_finite;

void check_csr(const fair::Csr_spline_2<K>& s) {
  fair_fuzz::check_pieces(s.pieces());
  for (const double t : s.parameters()) require_finite(t, "parameter");
  for (const Point_2& c : s.spline().control_points()) fair_fuzz::require_finite_point(c, "control point");
  for (const double k : s.discrete_curvatures()) require_finite(k, "discrete curvature");
  require_finite(s.epsilon(), "epsilon");
  for (const double d : s.distances_to_samples()) require_finite(d, "distance to sample");
}

} // namespace csr_target
} // namespace

extern "C" int FAIR_FUZZ_ENTRY(csr)(const std::uint8_t* data, std::size_t size) {
  using namespace csr_target;
  fair_fuzz::Fuzz_input in(data, size);
  const std::uint8_t head = in.byte();
  const bool closed = head & 1;
  fair::Csr_spline_options opt;
  opt.knot_spacing = static_cast<fair::Knot_spacing>((head >> 1) % 3);
  opt.epsilon_rule = (head & 8) ? fair::Csr_epsilon_rule::ADD_TO_CURVATURES : fair::Csr_epsilon_rule::CASE_SPLIT;
  if (head & 16) opt.relative_epsilon = (head & 64) ? in.number() : in.byte() / 16.0;
  const bool given = head & 32;
  std::vector<Point_2> p = in.kernel_points<Point_2>();
  std::vector<double> t;
  if (given) {
    const std::size_t m = p.size() + (closed ? 1 : 0) + (in.byte() == 255 ? 1 : 0);
    double u = in.number();
    for (std::size_t i = 0; i < m; ++i) {
      t.push_back(u);
      const std::uint8_t b = in.byte();
      u = b < 200 ? u + (1 + b) * std::ldexp(1.0, static_cast<int>(b % 7) * 10 - 30) : in.number();
    }
  }
  opt.closed = closed;
  return fair_fuzz::run_guarded([&] {
    if (given)
      check_csr(fair::Csr_spline_2<K>(p, t, opt));
    else
      check_csr(fair::Csr_spline_2<K>(p, opt));
  });
}
