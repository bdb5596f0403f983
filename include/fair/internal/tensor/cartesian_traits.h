// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The scalar coordinates of a CGAL Point_3 or Vector_3 of a kernel K, as the
// Tensor_coefficient_traits specialisations of Tensor_product_spline.h see them: the surface maps
// (eqs. 2, 3, 11 of Karciauskas & Peters) are linear and act on each coordinate separately
// (internal/tensor/net.h), so a coefficient is nothing but its three coordinates in K::FT.

#ifndef FAIR_INTERNAL_TENSOR_CARTESIAN_TRAITS_H
#define FAIR_INTERNAL_TENSOR_CARTESIAN_TRAITS_H

#include <array>
#include <cstddef>

namespace fair {
namespace internal {
namespace tensor {

/// The coordinates of a CGAL Point_3 or Vector_3 (V) of kernel K.
template <class V, class K>
struct Cartesian_3_traits {
  typedef V Coefficient;
  typedef typename K::FT FT;
  static constexpr std::size_t dimension = 3;
  static FT coordinate(const Coefficient& p, std::size_t i) { return p[static_cast<int>(i)]; }
  static Coefficient make(const std::array<FT, 3>& x) { return Coefficient(x[0], x[1], x[2]); }
};

} // namespace tensor
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_TENSOR_CARTESIAN_TRAITS_H
