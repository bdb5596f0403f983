// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fuzz target: the classic interpolants and approximants -- Cubic_interpolating_spline_2
// (natural, clamped, periodic; every knot spacing), Catmull_rom_2 (open, closed, given
// auxiliary points), Cubic_bspline_2 (both ends, closed), Cubic_quasi_interpolant_2 and
// Four_point_subdivision_2 (interpolatory with decoded tension, relaxed with decoded gamma) --
// on decoded point sets (fuzz_common.h). Oracle: every piece, knot, derivative, spline and
// refined point finite; typed errors only (doc/fuzzing.md).

#include "fuzz_common.h"

#include <fair/Catmull_rom_2.h>
#include <fair/Cubic_bspline_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Cubic_quasi_interpolant_2.h>
#include <fair/Four_point_subdivision_2.h>

#include <CGAL/Simple_cartesian.h>

namespace {
// Named inside the unnamed namespace: fuzz_replay is one unity translation unit of every target
// (fuzz/CMakeLists.txt), whose file-local names must not clash.
namespace classic_target {

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 Point_2;
typedef K::Vector_2 Vector_2;
using fair_fuzz::require_finite;

template <class Curve>
void check_knots_and_derivatives(const Curve& c) {
  for (const double u : c.knots()) require_finite(u, "knot");
  for (const Vector_2& m : c.derivatives()) fair_fuzz::require_finite_vector(m, "knot derivative");
}

void check_spline(const fair::Cubic_spline_2<K>& s) {
  for (const double t : s.breakpoints()) require_finite(t, "breakpoint");
  for (const Point_2& d : s.control_points()) fair_fuzz::require_finite_point(d, "spline control point");
  const std::pair<double, double> dom = s.domain();
  for (const double f : {0.0, 0.3, 1.0}) {
    const double t = dom.first + f * (dom.second - dom.first);
    if (!(t >= dom.first && t <= dom.second)) continue;  // rounding at the ends of a huge domain
    fair_fuzz::require_finite_point(s.point(t), "spline point");
  }
}

} // namespace classic_target
} // namespace

extern "C" int FAIR_FUZZ_ENTRY(classic)(const std::uint8_t* data, std::size_t size) {
  using namespace classic_target;
  fair_fuzz::Fuzz_input in(data, size);
  const std::uint8_t head = in.byte();
  const std::size_t method = head % 5;
  const bool closed = head & 8;
  const std::uint8_t variant = in.byte();
  const fair::Knot_spacing spacing = static_cast<fair::Knot_spacing>(variant % 3);
  std::vector<Point_2> p = in.kernel_points<Point_2>();
  const double a = in.number(), b = in.number(), c = in.number(), d = in.number();
  const std::size_t rounds = in.choice(5);
  return fair_fuzz::run_guarded([&] {
    switch (method) {
      case 0: {
        const std::size_t end = (variant >> 2) % 4;  // natural, clamped, periodic, not-a-knot
        if (end == 1) {
          const fair::Cubic_interpolating_spline_2<K> s(
              p, Vector_2(a, b), Vector_2(c, d), fair::Cubic_interpolating_spline_options{false, fair::Spline_end_condition::CLAMPED, spacing});
          fair_fuzz::check_pieces(s.pieces());
          check_knots_and_derivatives(s);
          check_spline(s.spline());
        } else {
          fair::Cubic_interpolating_spline_options o;  // periodic: closed
          o.closed = end == 2;
          o.end_condition = end == 3 ? fair::Spline_end_condition::NOT_A_KNOT : fair::Spline_end_condition::NATURAL;
          o.knot_spacing = spacing;
          const fair::Cubic_interpolating_spline_2<K> s(p, o);
          fair_fuzz::check_pieces(s.pieces());
          check_knots_and_derivatives(s);
          check_spline(s.spline());
        }
        break;
      }
      case 1: {
        if (variant & 4) {
          const fair::Catmull_rom_2<K> s(p, Point_2(a, b), Point_2(c, d), fair::Catmull_rom_options{false, spacing});
          fair_fuzz::check_pieces(s.pieces());
          check_knots_and_derivatives(s);
        } else {
          const fair::Catmull_rom_2<K> s(p, fair::Catmull_rom_options{closed, spacing});
          fair_fuzz::check_pieces(s.pieces());
          check_knots_and_derivatives(s);
        }
        break;
      }
      case 2: {
        const fair::Cubic_bspline_2<K> s(
            p, fair::Cubic_bspline_options{closed, (variant & 4) ? fair::Cubic_bspline_ends::TRIMMED
                                                                 : fair::Cubic_bspline_ends::INTERPOLATE_END_POINTS});
        fair_fuzz::check_pieces(s.pieces());
        check_spline(s.spline());
        for (const Point_2& q : s.control_polygon()) fair_fuzz::require_finite_point(q, "control polygon");
        break;
      }
      case 3: {
        const fair::Cubic_quasi_interpolant_2<K> s(p, fair::Cubic_quasi_interpolant_options{closed});
        fair_fuzz::check_pieces(s.pieces());
        check_spline(s.spline());
        for (const Point_2& q : s.control_polygon()) fair_fuzz::require_finite_point(q, "control polygon");
        break;
      }
      default: {
        fair::Four_point_subdivision_options o;
        o.closed = closed;
        o.rounds = rounds;  // the pieces are the polyline after these rounds
        if (variant & 4) {
          o.variant = fair::Four_point_variant::RELAXED;
          o.relaxation = (variant & 8) ? a : -3.0 / 128.0;
        } else {
          o.tension = (variant & 8) ? a : 1.0 / 16.0;
        }
        const fair::Four_point_subdivision_2<K> s(p, o);
        for (const Point_2& q : s.polyline()) fair_fuzz::require_finite_point(q, "refined point");
        fair_fuzz::check_pieces(s.pieces());
        break;
      }
    }
  });
}
