// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The uniform cubic B-spline of a control polygon as cubic Bezier pieces (shared by
// Cubic_bspline_2 and Cubic_quasi_interpolant_2).

#ifndef FAIR_INTERNAL_CLASSIC_BSPLINE_H
#define FAIR_INTERNAL_CLASSIC_BSPLINE_H

#include <fair/Bezier_2.h>
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

} // namespace classic
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_CLASSIC_BSPLINE_H
