// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Validation of Cubic_spline_2 data and the C2 check of from_bezier_pieces.

#ifndef FAIR_INTERNAL_SPLINE_CHECKS_H
#define FAIR_INTERNAL_SPLINE_CHECKS_H

#include <fair/Errors.h>
#include <fair/internal/spline/bspline_form.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace fair {
namespace internal {
namespace spline {

/// In double, from_bezier_pieces accepts pieces whose Bezier points the rebuilt spline
/// reproduces to this fraction of the control polygon's extent: far above the ~1e-15 rounding
/// of eqs. 2-3, far below any visible break of C2.
constexpr double c2_relative_tolerance = 1e-9;

template <class FT>
bool is_exact_number() {
  typedef typename CGAL::Algebraic_structure_traits<FT>::Is_exact Is_exact;
  return Is_exact::value && !std::is_floating_point<FT>::value;
}

/// eq. 2 adds up to three intervals (and a closed spline's extension adds a period), and
/// combines up to four control points: values below double's maximum divided by this factor
/// cannot overflow there.
constexpr double overflow_headroom = 16;

/// Breakpoints: enough of them (2 open, 4 closed), finite, strictly increasing.
template <class FT>
void check_breakpoints(const std::vector<FT>& t, bool closed, const char* fn) {
  const std::size_t minimum = closed ? 4 : 2;
  require(t.size() >= minimum, "fair::Cubic_spline_2::", fn, ": needs at least ", minimum, " breakpoints (",
          closed ? "3 pieces closed" : "1 piece open", "), got ", t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double ti = CGAL::to_double(t[i]);
    require(std::isfinite(ti), "fair::Cubic_spline_2::", fn, ": breakpoint ", i, " = ", ti, " is not finite");
    if (i > 0)
      require(t[i - 1] < t[i], "fair::Cubic_spline_2::", fn, ": breakpoints ", i - 1, " and ", i, " are not increasing (",
              CGAL::to_double(t[i - 1]), ", ", ti, ")");
  }
  const double extent = std::max(std::abs(CGAL::to_double(t.front())), std::abs(CGAL::to_double(t.back())));
  require(std::isfinite(overflow_headroom * extent), "fair::Cubic_spline_2::", fn, ": breakpoints up to ", extent,
          " are too large (sums of intervals would overflow double)");
}

/// Breakpoints as above, m + 3 (open) or m (closed) finite control points and, when `w` is not
/// null (a rational spline), as many finite positive weights. One pass over the control points.
/// Returns the largest max(|x|, |y|) max(1, w) of a control point (for check_finite_pieces).
template <class K>
double check_spline_data(const std::vector<typename K::FT>& t, const std::vector<typename K::Point_2>& d,
                       const std::vector<typename K::FT>* w, bool closed) {
  check_breakpoints(t, closed, "Cubic_spline_2");
  const std::size_t m = t.size() - 1, expected = closed ? m : m + 3;
  require(d.size() == expected, "fair::Cubic_spline_2: ", m, " pieces ", closed ? "(closed)" : "(open)", " need ",
          expected, " control points, got ", d.size());
  require(w == nullptr || w->size() == d.size(), "fair::Cubic_spline_2: ", w ? w->size() : 0, " weights for ",
          d.size(), " control points");
  // (|x| or |y|) * max(1, w) * headroom finite; for w = 1 that is max(|x|, |y|) below DBL_MAX / headroom.
  const double limit = std::numeric_limits<double>::max() / overflow_headroom;
  double bound = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const double x = CGAL::to_double(d[i].x()), y = CGAL::to_double(d[i].y());
    const double wi = w ? CGAL::to_double((*w)[i]) : 1.0;
    const double a = std::max(std::abs(x), std::abs(y)), scale = std::max(1.0, wi);
    // false for a NaN or infinite coordinate or weight: the checks below say which
    const bool small = std::abs(x) * scale <= limit && std::abs(y) * scale <= limit;
    bound = std::max(bound, a * scale);
    if (!small)
      require(std::isfinite(x) && std::isfinite(y), "fair::Cubic_spline_2: control point ", i, " = (", x, ", ", y,
              ") is not finite");
    if (w)
      require(std::isfinite(wi) && (*w)[i] > typename K::FT(0), "fair::Cubic_spline_2: weight ", i, " = ", wi,
              " is not finite and > 0");
    if (!small) {
      require(std::isfinite(overflow_headroom * a * scale), "fair::Cubic_spline_2: control point ", i,
              " = (", x, ", ", y, ") with weight ", wi,
              " is too large (combinations of control points would overflow double)");
    }
  }
  return bound;
}

/// Throws Invalid_input_error unless the spline whose homogeneous Bezier points of piece i are
/// `bezier_points(i)` reproduces the homogeneous Bezier points `b` (in Euclidean coordinates):
/// exactly in an exact number type, else to c2_relative_tolerance of the extent of the pieces'
/// control points.
template <class K, class Bezier_points>
void check_reproduces(const Bezier_points& bezier_points,
                      const std::vector<std::array<Homogeneous_point<typename K::FT>, 4>>& b, const char* fn) {
  typedef typename K::FT FT;
  const bool exact = is_exact_number<FT>();
  double extent = 0;
  if (!exact)
    for (const auto& piece : b)
      for (const auto& p : piece)
        extent = std::max({extent, std::abs(CGAL::to_double(p.x / p.w)), std::abs(CGAL::to_double(p.y / p.w))});
  const double tolerance = c2_relative_tolerance * std::max(extent, 1e-300);
  for (std::size_t i = 0; i < b.size(); ++i) {
    const std::array<Homogeneous_point<FT>, 4> r = bezier_points(static_cast<long>(i));
    for (std::size_t k = 0; k < 4; ++k) {
      const FT rx = r[k].x / r[k].w, ry = r[k].y / r[k].w, bx = b[i][k].x / b[i][k].w, by = b[i][k].y / b[i][k].w;
      const FT rw = r[k].w / b[i][k].w; // the homogeneous points must agree up to the weight too
      const bool same = exact ? (rx == bx && ry == by && rw == FT(1))
                              : (std::abs(CGAL::to_double(rx - bx)) <= tolerance &&
                                 std::abs(CGAL::to_double(ry - by)) <= tolerance &&
                                 std::abs(CGAL::to_double(rw) - 1.0) <= c2_relative_tolerance);
      if (!same)
        throw Invalid_input_error(message("fair::Cubic_spline_2::", fn, ": the pieces are not C2 for these breakpoints: ",
                                          "Bezier point ", k, " of piece ", i, " is (", CGAL::to_double(bx), ", ",
                                          CGAL::to_double(by), "), the spline through the pieces' control points gives (",
                                          CGAL::to_double(rx), ", ", CGAL::to_double(ry), ")"));
    }
  }
}

} // namespace spline
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_SPLINE_CHECKS_H
