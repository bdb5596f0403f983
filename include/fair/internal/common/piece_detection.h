// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Member detection behind fair::Piece_traits (Curve_traits.h): which of the optional members of a
// piece type exist. The traits users read or specialise are the public ones of Curve_traits.h.

#ifndef FAIR_INTERNAL_COMMON_PIECE_DETECTION_H
#define FAIR_INTERNAL_COMMON_PIECE_DETECTION_H

#include <type_traits>
#include <utility>

namespace fair {

template <class K>
class Bezier_2;

namespace internal {
namespace common {

template <class P, class = void>
struct Has_weights : std::false_type {};
template <class P>
struct Has_weights<P, std::void_t<decltype(std::declval<const P&>().weights()),
                                  decltype(std::declval<const P&>().control_points())>> : std::true_type {};

template <class P, class = void>
struct Has_own_curvature_extrema : std::false_type {};
template <class P>
struct Has_own_curvature_extrema<
    P, std::void_t<decltype(std::declval<const P&>().curvature_extrema().front().t_lower),
                   decltype(std::declval<const P&>().curvature_extrema().front().t_upper),
                   decltype(std::declval<const P&>().curvature_extrema().front().t),
                   decltype(std::declval<const P&>().curvature_extrema().front().multiplicity)>> : std::true_type {};

template <class P>
struct Is_bezier : std::false_type {};
template <class K>
struct Is_bezier<Bezier_2<K>> : std::true_type {};

} // namespace common
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_COMMON_PIECE_DETECTION_H
