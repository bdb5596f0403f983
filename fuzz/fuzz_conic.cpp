// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fuzz target (issue 29): what `fair-curves conic` reports about one conic piece
// (fair::Rational_quadratic_bezier_2, tools/fair-curves/conic_report.h): type, eccentricity,
// end curvatures (eq. 5), constant curvature, the certified curvature extrema and the curvature
// there, plus its implicit form and the eq.-15 weight. Three decoded points (fuzz_common.h
// numbers: grid, scaled, special, raw) and a decoded weight. Oracle (doc/fuzzing.md): typed
// errors only, every reported number finite, extrema intervals inside [0, 1] and ordered.

#include "fuzz_common.h"

#include <fair/Rational_quadratic_bezier_2.h>

#include <CGAL/Simple_cartesian.h>

namespace {
// Named inside the unnamed namespace: fuzz_replay is one unity translation unit of every target
// (fuzz/CMakeLists.txt), whose file-local names must not clash.
namespace conic_target {

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 Point_2;
using fair_fuzz::require_finite;

template <class F>
void typed(F&& f) {
  try {
    f();
  } catch (const fair::Internal_error&) {
    throw;
  } catch (const fair::Error&) {
  }
}

} // namespace conic_target
} // namespace

extern "C" int FAIR_FUZZ_ENTRY(conic)(const std::uint8_t* data, std::size_t size) {
  using namespace conic_target;
  fair_fuzz::Fuzz_input in(data, size);
  const std::uint8_t head = in.byte();
  Point_2 p[3];
  for (Point_2& q : p) {
    // Mostly small integers and their near-collinear nudges; sometimes any decoded number.
    if (head & 1) {
      const double x = in.number(), y = in.number();
      q = Point_2(x, y);
    } else {
      const double s = (head & 2) ? in.scale() : 1.0;
      const double x = static_cast<std::int8_t>(in.byte()) * s, y = static_cast<std::int8_t>(in.byte()) * s;
      q = Point_2(x, y);
    }
  }
  if (head & 4) p[1] = Point_2(p[1].x(), std::nextafter(p[1].y(), 1e308) + in.number() * 1e-9);
  const double w = (head & 8) ? in.number() : (in.byte() + 1) / 64.0;
  if (std::getenv("FAIR_FUZZ_VERBOSE"))
    std::fprintf(stderr, "P0 = (%.17g, %.17g), P1 = (%.17g, %.17g), P2 = (%.17g, %.17g), w = %.17g\n", p[0].x(), p[0].y(),
                 p[1].x(), p[1].y(), p[2].x(), p[2].y(), w);
  return fair_fuzz::run_guarded([&] {
    const fair::Rational_quadratic_bezier_2<K> piece(p[0], p[1], p[2], w);
    (void)fair::to_string(piece.conic_type());
    typed([&] { require_finite(piece.eccentricity(), "eccentricity"); });
    typed([&] { require_finite(piece.curvature_at_source(), "curvature at source"); });
    typed([&] { require_finite(piece.curvature_at_target(), "curvature at target"); });
    typed([&] { (void)piece.has_constant_curvature(); });
    typed([&] { require_finite(piece.minimum_eccentricity_weight(), "eq. 15 weight"); });
    typed([&] {
      for (const fair::Curvature_extremum& x : piece.curvature_extrema()) {
        require_finite(x.t, "extremum t");
        if (!(x.t_lower <= x.t_upper) || x.t_lower < 0 || x.t_upper > 1)
          fair_fuzz::fuzz_fail("extremum interval outside [0, 1] or reversed");
        typed([&] { require_finite(piece.curvature(x.t), "curvature at an extremum"); });
      }
    });
    typed([&] { fair_fuzz::check_piece(piece); });
  });
}
