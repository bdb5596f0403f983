// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The uniform cubic B-spline of a control polygon as cubic Bezier pieces (shared by
// Cubic_bspline_2 and Cubic_quasi_interpolant_2).

#ifndef FAIR_INTERNAL_CLASSIC_BSPLINE_H
#define FAIR_INTERNAL_CLASSIC_BSPLINE_H

#include <fair/Bezier_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/internal/classic/common.h>

#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace classic {

/// The Bezier pieces of the uniform cubic B-spline with control points d_0..d_{m-1}.
/// Open: m - 3 pieces, piece j uses d_j..d_{j+3} (needs m >= 4). Closed: m pieces, piece j uses
/// d_{j-1}, d_j, d_{j+1}, d_{j+2} (indices mod m, needs m >= 3), so that piece j starts at the
/// knot of d_j. Only +, -, * and / by 3 and 6: exact in an exact kernel.
template <class K>
std::vector<Bezier_2<K>> classic_uniform_bspline_pieces(const std::vector<typename K::Point_2>& d, bool closed) {
  std::vector<Bezier_2<K>> pieces;
  const std::size_t m = d.size();
  if (closed) {
    pieces.reserve(m);
    for (std::size_t j = 0; j < m; ++j)
      pieces.push_back(classic_bspline_segment<K>(d[(j + m - 1) % m], d[j], d[(j + 1) % m], d[(j + 2) % m]));
  } else {
    if (m < 4) return pieces;
    pieces.reserve(m - 3);
    for (std::size_t j = 0; j + 3 < m; ++j)
      pieces.push_back(classic_bspline_segment<K>(d[j], d[j + 1], d[j + 2], d[j + 3]));
  }
  return pieces;
}

/// The uniform cubic B-spline of d_0..d_{m-1} as a Cubic_spline_2 on the integer breakpoints
/// 0, 1, ...: closed, d itself is the periodic control polygon (d_j is the control point of
/// breakpoint j); open, the m - 3 pieces (which start at the knot of d_1, not at d_0) are
/// re-expressed in the clamped form by eq. 3 (exact). `method` names the caller in errors.
template <class K>
Cubic_spline_2<K> classic_uniform_spline(const std::vector<typename K::Point_2>& d, bool closed, const char* method) {
  typedef typename K::FT FT;
  const std::size_t pieces = closed ? d.size() : d.size() - 3;
  std::vector<FT> breakpoints;
  breakpoints.reserve(pieces + 1);
  for (std::size_t i = 0; i <= pieces; ++i) breakpoints.push_back(FT(static_cast<int>(i)));
  const std::vector<Bezier_2<K>> bezier = classic_uniform_bspline_pieces<K>(d, closed);
  classic_check_finite_pieces(bezier, method);
  if (closed) return Cubic_spline_2<K>(std::move(breakpoints), d, true);
  return Cubic_spline_2<K>::from_bezier_pieces(std::move(breakpoints), bezier, false);
}

} // namespace classic
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_CLASSIC_BSPLINE_H
