// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The exact orientation of the control triangle of a conic piece, whatever the kernel and the
// scale: Simple_cartesian<double>'s own predicate underflows near 1e-300 and overflows near
// 1e300, and the exact determinant over Gmpq (Simple_cartesian<Gmpq>) costs a dozen gcds, so an
// interval filter on enclosures of the exact coordinates runs first in every kernel.

#ifndef FAIR_INTERNAL_CONIC_ORIENTATION_H
#define FAIR_INTERNAL_CONIC_ORIENTATION_H

#include <fair/Errors.h>
#include <fair/internal/common/exact_conversion.h>
#include <fair/internal/common/polygon_crossings.h>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <cmath>

namespace fair {
namespace internal {
namespace conic {

using common::exact_orientation_of_doubles;

/// Exact orientation of p0, p1, p2 in kernel K: exact_orientation_of_doubles for a floating
/// kernel; otherwise an interval filter on enclosures of the exact coordinates, then
/// K::Orientation_2 (EPECK filters on its own).
template <class K>
CGAL::Orientation control_triangle_orientation(const typename K::Point_2& p0, const typename K::Point_2& p1,
                                               const typename K::Point_2& p2) {
  if constexpr (common::Is_floating_nt<typename K::FT>::value) {
    return exact_orientation_of_doubles(CGAL::to_double(p0.x()), CGAL::to_double(p0.y()), CGAL::to_double(p1.x()),
                                        CGAL::to_double(p1.y()), CGAL::to_double(p2.x()), CGAL::to_double(p2.y()));
  } else {
    typedef CGAL::Interval_nt<false> I;
    CGAL::Orientation filtered = CGAL::COLLINEAR;
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const I x0(CGAL::to_interval(p0.x())), y0(CGAL::to_interval(p0.y())), x1(CGAL::to_interval(p1.x()));
      const I y1(CGAL::to_interval(p1.y())), x2(CGAL::to_interval(p2.x())), y2(CGAL::to_interval(p2.y()));
      const I d = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0);
      if (d.inf() > 0) filtered = CGAL::LEFT_TURN;
      else if (d.sup() < 0) filtered = CGAL::RIGHT_TURN;
    }
    return filtered != CGAL::COLLINEAR ? filtered : K().orientation_2_object()(p0, p1, p2);
  }
}

/// The orientation of a valid piece's control triangle (never COLLINEAR).
/// \throws Precondition_error if a coordinate or w is not finite, w <= 0, P0 == P2, or the
/// control points are collinear.
template <class K>
CGAL::Orientation checked_orientation(const typename K::Point_2& p0, const typename K::Point_2& p1,
                                      const typename K::Point_2& p2, const typename K::FT& w) {
  const char* fn = "Rational_quadratic_bezier_2";
  const typename K::Point_2* p[3] = {&p0, &p1, &p2};
  for (int i = 0; i < 3; ++i) {
    const double x = CGAL::to_double(p[i]->x()), y = CGAL::to_double(p[i]->y());
    require(std::isfinite(x) && std::isfinite(y), fn, ": control point P", i, " = (", x, ", ", y, ") is not finite");
  }
  const double wd = CGAL::to_double(w);
  require(std::isfinite(wd) && w > typename K::FT(0), fn, ": the weight must be finite and > 0, got w = ", wd);
  require(p0 != p2, fn, ": degenerate piece, P0 == P2 = (", CGAL::to_double(p0.x()), ", ", CGAL::to_double(p0.y()),
          ")");
  const CGAL::Orientation o = control_triangle_orientation<K>(p0, p1, p2);
  require(o != CGAL::COLLINEAR, fn, ": degenerate piece, collinear control points P0 = (", CGAL::to_double(p0.x()),
          ", ", CGAL::to_double(p0.y()), "), P1 = (", CGAL::to_double(p1.x()), ", ", CGAL::to_double(p1.y()),
          "), P2 = (", CGAL::to_double(p2.x()), ", ", CGAL::to_double(p2.y()), ")");
  return o;
}

} // namespace conic
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_CONIC_ORIENTATION_H
