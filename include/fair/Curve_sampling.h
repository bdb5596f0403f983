// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::sample_curve: a double-precision polyline of any curve made of CurvePiece_2 pieces
// (doc/contributing.md), with the differential quantities plotting and fairness reports need:
// per sample the point, the unit normal, the signed curvature, the arc length from the start
// of the curve, the piece index and the piece parameter.
//
// Accuracy. Points, normals and curvatures are evaluated in double from the piece's jet (the
// Bernstein form converted to double once, or the piece's own point / derivative /
// second_derivative for other pieces: its fair::Piece_kind, fair/Curve_traits.h), the curvature by the scale-safe
// formula of internal/common/curvature.h (no overflow or underflow for coordinates near
// 1e+-300). The same sampler gives fair::curvature_profile. Arc length is integrated, not
// accumulated from chords: on each sampling interval the speed |c'(t)| is integrated by the
// library's adaptive Gauss-Kronrod quadrature (fair/Quadrature.h) to 1e-13 of the interval's
// length (arc_length_options()), so for a regular piece the arc length is accurate to about
// 1e-13 relative. Where c'(t) = 0 (a
// cusp, or a degenerate end of a piece) |c'| has a kink, which the adaptive bisection resolves.
// At such a sample the normal and the curvature are the one-sided limits, taken at t moved by
// 1e-9 (then 1e-7, 1e-5) towards the inside of the piece; if the piece is singular there too,
// Precondition_error.

#ifndef FAIR_CURVE_SAMPLING_H
#define FAIR_CURVE_SAMPLING_H

#include <fair/Curve_traits.h>
#include <fair/Errors.h>
#include <fair/Quadrature.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {

/// One sample of a curve, in double precision.
struct Curve_sample {
  double x = 0, y = 0;     ///< the point c(t)
  double nx = 0, ny = 0;   ///< unit normal: the unit tangent turned by +90 degrees
  double curvature = 0;    ///< signed curvature (positive when turning left)
  double arc_length = 0;   ///< arc length from the start of the curve
  std::size_t piece = 0;   ///< index of the piece in the curve
  double t = 0;            ///< parameter in the piece, in [0,1]
};

/// A sampled curve. Each piece contributes samples_per_piece + 1 samples, both of its ends
/// included, so a join appears twice (once as the end of a piece, once as the start of the
/// next one) and a jump of curvature across it is visible.
struct Sampled_curve {
  std::vector<Curve_sample> samples;
  /// Arc length at the start of each piece, followed by the total length (size = pieces + 1).
  std::vector<double> piece_start;

  double length() const { return piece_start.empty() ? 0.0 : piece_start.back(); }
  std::size_t number_of_pieces() const { return piece_start.empty() ? 0 : piece_start.size() - 1; }
};

} // namespace fair

// The implementation needs the types above.
#include <fair/internal/metrics/sampler.h>

namespace fair {

/// The quadrature options of the sampler's arc lengths: 1e-13 relative to the length of each
/// interval (the accuracy the plots and the gallery's length figures rely on), no absolute floor
/// so that the accuracy does not depend on the scale of the curve.
inline Quadrature_options arc_length_options() {
  Quadrature_options o;
  o.relative_tolerance = 1e-13;
  o.absolute_tolerance = 0;
  o.initial_subintervals = 1;
  return o;
}

/// Arc length of one piece between parameters 0 <= a <= b <= 1: the adaptive Gauss-Kronrod
/// quadrature of |c'(t)| (fair/Quadrature.h) to the accuracy of `options`.
/// \throws Precondition_error unless a <= b are finite, or if |c'| is not finite on [a, b];
/// Non_convergence_error when options.max_subintervals does not reach the accuracy.
template <class Piece>
double piece_arc_length(const Piece& piece, double a = 0.0, double b = 1.0,
                        const Quadrature_options& options = arc_length_options()) {
  internal::require(a <= b && std::isfinite(a) && std::isfinite(b),
                    "piece_arc_length: need finite a <= b, got a = ", a, ", b = ", b);
  const internal::metrics::Piece_jet<Piece> jet(piece);
  return internal::metrics::arc_length_between(jet, a, b, options, "piece_arc_length");
}

/// The default number of sampling intervals per piece: a smooth plot and comb of a fair piece.
constexpr std::size_t default_samples_per_piece = 64;

/// Samples every piece of `pieces` (a range of CurvePiece_2 pieces, joined end to start) at
/// samples_per_piece + 1 uniformly spaced parameters. Throws Precondition_error when
/// samples_per_piece is 0, or when a piece gives a non-finite point or is singular over a
/// neighbourhood of a sample.
template <class PieceRange>
Sampled_curve sample_curve(const PieceRange& pieces, std::size_t samples_per_piece = default_samples_per_piece) {
  return internal::metrics::sample_pieces(pieces, samples_per_piece, arc_length_options(),
                                          internal::metrics::At_singular_sample::ONE_SIDED_LIMIT, "sample_curve");
}

} // namespace fair

#endif // FAIR_CURVE_SAMPLING_H
