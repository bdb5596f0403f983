// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fuzz target (issue 29): the curve-file reader (fair/io/read_curve.h) and the fairness metrics
// of `fair-curves metrics`, with --hausdorff and --circle. The first byte holds options (the
// Hausdorff tolerance exponent, a circle from the decoder), then the text: a curve JSON, or two
// separated by a byte 0x01 (the second is the --hausdorff curve; without it the first is
// compared with itself). Read in Simple_cartesian<Gmpq> as the command does. Oracle
// (doc/fuzzing.md): typed errors only; every figure finite (energies, curvature range, feature
// parameters and points, profile samples, the circle deviation, the Hausdorff bounds with
// lower <= upper and upper - lower <= tolerance when converged).

#include "fuzz_common.h"

#include <fair/Fairness_metrics.h>
#include <fair/io/read_curve.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <string>

namespace {
// Named inside the unnamed namespace: fuzz_replay is one unity translation unit of every target
// (fuzz/CMakeLists.txt), whose file-local names must not clash.
namespace metrics_target {

typedef CGAL::Simple_cartesian<CGAL::Gmpq> K;
using fair_fuzz::require_finite;

template <class Piece>
void check_features(const fair::Feature_report& r) {
  for (const fair::Curve_feature& f : r.features) {
    require_finite(f.t, "feature t");
    require_finite(f.x, "feature x");
    require_finite(f.y, "feature y");
    require_finite(f.curvature, "feature curvature");
  }
}

template <class A, class B>
void guarded(A&& body, B&&) {
  try {
    body();
  } catch (const fair::Internal_error&) {
    throw;
  } catch (const fair::Error&) {
  }
}

template <class Piece, class Other>
void metrics(const std::vector<Piece>& curve, const std::vector<Other>& other, double tolerance, double cx, double cy,
             double r) {
  guarded([&] {
    const fair::Fairness_report f = fair::fairness_report(curve);
    require_finite(f.length.value, "arc length");
    require_finite(f.bending.value, "bending energy");
    require_finite(f.curvature_variation.value, "curvature variation");
    require_finite(f.min_curvature, "min curvature");
    require_finite(f.max_curvature, "max curvature");
  }, 0);
  guarded([&] { check_features<Piece>(fair::inflections(curve)); }, 0);
  guarded([&] { check_features<Piece>(fair::curvature_extrema(curve)); }, 0);
  guarded([&] {
    for (const fair::Curvature_sample& s : fair::curvature_profile(curve, 8)) {
      require_finite(s.arc_length, "profile arc length");
      require_finite(s.curvature, "profile curvature");
    }
  }, 0);
  guarded([&] {
    const fair::Circle_deviation d = fair::max_circle_deviation(curve, typename Piece::Point_2(cx, cy), r);
    require_finite(d.max_deviation, "circle deviation");
  }, 0);
  guarded([&] {
    const fair::Hausdorff_bounds h = fair::hausdorff_distance_bounds(curve, other, tolerance);
    require_finite(h.lower, "Hausdorff lower bound");
    require_finite(h.upper, "Hausdorff upper bound");
    if (!(h.lower <= h.upper)) fair_fuzz::fuzz_fail("Hausdorff bounds out of order");
    if (h.converged && h.upper - h.lower > tolerance * (1 + 1e-9) + 1e-300)
      fair_fuzz::fuzz_fail("Hausdorff bounds converged but wider than the tolerance");
  }, 0);
}

bool read(const std::string& text, fair::io::Curve_file<K>& out) {
  return fair_fuzz::parsed_or_refused([&] { out = fair::io::parse_curve_json<K>(text, "fuzz.json"); });
}

} // namespace metrics_target
} // namespace

extern "C" int FAIR_FUZZ_ENTRY(metrics)(const std::uint8_t* data, std::size_t size) {
  using namespace metrics_target;
  if (size < 4) return 0;
  // Options: tolerance 10^-(b mod 13), circle center and radius from small integers.
  const double tolerance = std::pow(10.0, -double(data[0] % 13));
  const double cx = static_cast<std::int8_t>(data[1]), cy = static_cast<std::int8_t>(data[2]);
  const double r = data[3] & 127;
  const std::string all(reinterpret_cast<const char*>(data) + 4, size - 4);
  const std::size_t sep = all.find('\x01');
  const std::string first = all.substr(0, sep), second = sep == std::string::npos ? first : all.substr(sep + 1);
  return fair_fuzz::run_guarded([&] {
    fair::io::Curve_file<K> a, b;
    if (!read(first, a) || !read(second, b)) return;
    for (const auto& p : a.pieces)
      for (const auto& c : p.control_points()) fair_fuzz::require_finite_point(c, "control point read");
    if (a.rational) {
      if (b.rational) metrics(a.pieces, b.pieces, tolerance, cx, cy, r);
      else metrics(a.pieces, b.polynomial_pieces(), tolerance, cx, cy, r);
    } else {
      if (b.rational) metrics(a.polynomial_pieces(), b.pieces, tolerance, cx, cy, r);
      else metrics(a.polynomial_pieces(), b.polynomial_pieces(), tolerance, cx, cy, r);
    }
  });
}
