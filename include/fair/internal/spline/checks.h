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
}

/// Breakpoints as above, m + 3 (open) or m (closed) finite control points, as many finite
/// positive weights.
template <class K>
void check_spline_data(const std::vector<typename K::FT>& t, const std::vector<typename K::Point_2>& d,
                       const std::vector<typename K::FT>& w, bool closed) {
  check_breakpoints(t, closed, "Cubic_spline_2");
  const std::size_t m = t.size() - 1, expected = closed ? m : m + 3;
  require(d.size() == expected, "fair::Cubic_spline_2: ", m, " pieces ", closed ? "(closed)" : "(open)", " need ",
          expected, " control points, got ", d.size());
  require(w.size() == d.size(), "fair::Cubic_spline_2: ", w.size(), " weights for ", d.size(), " control points");
  for (std::size_t i = 0; i < d.size(); ++i) {
    const double x = CGAL::to_double(d[i].x()), y = CGAL::to_double(d[i].y()), wi = CGAL::to_double(w[i]);
    require(std::isfinite(x) && std::isfinite(y), "fair::Cubic_spline_2: control point ", i, " = (", x, ", ", y,
            ") is not finite");
    require(std::isfinite(wi) && w[i] > typename K::FT(0), "fair::Cubic_spline_2: weight ", i, " = ", wi,
            " is not finite and > 0");
  }
}

/// Throws Invalid_input_error unless the spline `form` reproduces the homogeneous Bezier points
/// `b` (in Euclidean coordinates): exactly in an exact number type, else to
/// c2_relative_tolerance of the extent of the pieces' control points.
template <class K>
void check_reproduces(const Bspline_form<typename K::FT>& form,
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
    const std::array<Homogeneous_point<FT>, 4> r = form.bezier_points(static_cast<long>(i));
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
