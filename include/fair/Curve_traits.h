// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// What a piece type must provide to be measured (Fairness_metrics.h) and sampled
// (Curve_sampling.h), and how the library finds out. Every piece models CurvePiece_2
// (doc/contributing.md); beyond that a piece is looked at in one of three ways, its Piece_kind:
//
//  - POLYNOMIAL_BEZIER: fair::Bezier_2, c(t) = sum B_i^n(t) P_i. Needs control_points().
//  - RATIONAL_BEZIER: any piece with control_points() and weights() (same size, w_i > 0),
//    c(t) = sum B_i^n w_i P_i / sum B_i^n w_i: fair::Rational_bezier_2,
//    fair::Rational_quadratic_bezier_2 and user types. Only these two members are used, so a
//    struct holding control points and weights is enough.
//  - GENERIC: anything else, evaluated through point(), derivative() and second_derivative()
//    (third derivative by finite differences); its features are found by sampling, uncertified.
//
// The first two are the Bernstein-form kinds: evaluated in double from the control points
// converted once, and certified (exact root isolation on the homogeneous form). A piece may in
// addition certify its own curvature extrema (has_own_curvature_extrema, e.g. the conic piece):
// curvature_extrema() returning entries with t (double), t_lower, t_upper (exact rationals) and
// multiplicity; the metrics then take the interior extrema from it.
//
// The traits are detected from the members; a piece type may specialise fair::Piece_traits to
// state them itself.

#ifndef FAIR_CURVE_TRAITS_H
#define FAIR_CURVE_TRAITS_H

#include <fair/internal/common/piece_detection.h>

namespace fair {

/// How the metrics and the sampler evaluate a piece (see the file comment).
enum class Piece_kind {
  GENERIC,           ///< only the CurvePiece_2 concept; features sampled, not certified
  POLYNOMIAL_BEZIER, ///< fair::Bezier_2: control points, all weights 1
  RATIONAL_BEZIER    ///< control_points() and weights()
};

/// The capabilities of the piece type Piece that the metrics and the sampler rely on.
template <class Piece>
struct Piece_traits {
  /// How the piece is evaluated (see Piece_kind).
  static constexpr Piece_kind kind = internal::common::Is_bezier<Piece>::value ? Piece_kind::POLYNOMIAL_BEZIER
                                     : internal::common::Has_weights<Piece>::value ? Piece_kind::RATIONAL_BEZIER
                                                                                   : Piece_kind::GENERIC;
  /// True iff the piece certifies its own curvature extrema (curvature_extrema(), see above).
  static constexpr bool has_own_curvature_extrema = internal::common::Has_own_curvature_extrema<Piece>::value;
};

/// True for the kinds in Bernstein form (certified features).
constexpr bool is_bernstein_form(Piece_kind kind) { return kind != Piece_kind::GENERIC; }

} // namespace fair

#endif // FAIR_CURVE_TRAITS_H
