// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::sample_curve: a double-precision polyline of any curve made of CurvePiece_2 pieces
// (doc/contributing.md), with the differential quantities plotting and fairness reports need:
// per sample the point, the unit normal, the signed curvature, the arc length from the start
// of the curve, the piece index and the piece parameter.
//
// Accuracy. Points, normals and curvatures are the piece's own values rounded to double (where
// a piece's curvature() throws or overflows -- e.g. |c'|^2 beyond the double range for
// coordinates near 1e300 -- the curvature is recomputed from c' and c'' with a scaling that
// avoids overflow and underflow). Arc
// length is integrated, not accumulated from chords: on each sampling interval the speed
// |c'(t)| is integrated by adaptive 7-point Gauss-Legendre quadrature (exact for polynomial
// integrands up to degree 13; the interval is bisected until the one-level and two-level
// results agree to 1e-13 of the piece's scale). For a regular piece the arc length is then
// accurate to about 1e-12 relative. Degenerate cases: where c'(t) = 0 (a cusp, or a degenerate
// end of a piece) |c'| has a kink; bisection stops at depth 40 and the last estimate is kept,
// which still leaves an error far below the sampling resolution. At such a sample the normal
// and the curvature are the one-sided limits, taken at t moved by 1e-9 (then 1e-7, 1e-5)
// towards the inside of the piece; if the piece is singular there too, Precondition_error.

#ifndef FAIR_CURVE_SAMPLING_H
#define FAIR_CURVE_SAMPLING_H

#include <fair/Errors.h>
#include <fair/internal/metrics/sampler.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstddef>
#include <iterator>
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


/// Arc length of one piece between parameters a <= b, by adaptive Gauss-Legendre quadrature
/// of |c'(t)| (accuracy: see the top of this file).
template <class Piece>
double piece_arc_length(const Piece& piece, double a = 0.0, double b = 1.0) {
  internal::require(a <= b && std::isfinite(a) && std::isfinite(b),
                    "piece_arc_length: need finite a <= b, got a = ", a, ", b = ", b);
  const double scale = internal::metrics::control_polygon_length(piece);
  const double whole = internal::metrics::gauss_legendre_7(piece, a, b);
  const double length = internal::metrics::adaptive_length(piece, a, b, whole, 1e-13 * scale * (b - a), 0);
  if (!std::isfinite(length))
    throw Precondition_error(internal::message("piece_arc_length: non-finite length on [", a, ", ",
                                               b, "]"));
  return length;
}

/// Samples every piece of `pieces` (a range of CurvePiece_2 pieces, joined end to start) at
/// samples_per_piece + 1 uniformly spaced parameters. Throws Precondition_error when
/// samples_per_piece is 0, or when a piece gives a non-finite point or is singular over a
/// neighbourhood of a sample.
template <class PieceRange>
Sampled_curve sample_curve(const PieceRange& pieces, std::size_t samples_per_piece = 64) {
  internal::require(samples_per_piece > 0, "sample_curve: samples_per_piece must be > 0");
  typedef typename std::iterator_traits<decltype(std::begin(pieces))>::value_type Piece;
  typedef typename Piece::FT FT;
  Sampled_curve out;
  double s = 0;
  std::size_t index = 0;
  const double n = static_cast<double>(samples_per_piece);
  for (const Piece& piece : pieces) {
    out.piece_start.push_back(s);
    const double scale = internal::metrics::control_polygon_length(piece);
    double previous_t = 0;
    for (std::size_t k = 0; k <= samples_per_piece; ++k) {
      Curve_sample c;
      c.piece = index;
      c.t = k == samples_per_piece ? 1.0 : static_cast<double>(k) / n;
      if (k > 0) {
        const double whole = internal::metrics::gauss_legendre_7(piece, previous_t, c.t);
        s += internal::metrics::adaptive_length(piece, previous_t, c.t, whole, 1e-13 * scale / n, 0);
      }
      previous_t = c.t;
      const auto p = piece.point(FT(c.t));
      c.x = CGAL::to_double(p.x());
      c.y = CGAL::to_double(p.y());
      if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(s))
        throw Precondition_error(internal::message("sample_curve: piece ", index, " at t = ", c.t,
                                                   " gives the non-finite point (", c.x, ", ", c.y,
                                                   ") or arc length ", s));
      internal::metrics::normal_and_curvature(piece, index, c.t, c.nx, c.ny, c.curvature);
      c.arc_length = s;
      out.samples.push_back(c);
    }
    ++index;
  }
  out.piece_start.push_back(s);
  return out;
}

} // namespace fair

#endif // FAIR_CURVE_SAMPLING_H
