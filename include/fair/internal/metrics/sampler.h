// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The one curvature sampler of the library, behind fair::sample_curve (Curve_sampling.h) and
// fair::curvature_profile (Fairness_metrics.h): every piece is evaluated through its Piece_jet
// (internal/metrics/pieces.h) at samples_per_piece + 1 uniform parameters; the arc length is the
// adaptive Gauss-Kronrod quadrature of |c'(t)| on every sampling interval (quadrature.h), the
// curvature the scale-safe one of internal/common/curvature.h. At a singular sample (c' = 0) the
// caller chooses: throw, or take the one-sided limit a little inside the piece.
// Included by Curve_sampling.h after its types (Curve_sample, Sampled_curve).

#ifndef FAIR_INTERNAL_METRICS_SAMPLER_H
#define FAIR_INTERNAL_METRICS_SAMPLER_H

#include <fair/Errors.h>
#include <fair/Quadrature.h>
#include <fair/internal/metrics/pieces.h>
#include <fair/internal/metrics/quadrature.h>

#include <cmath>
#include <cstddef>
#include <iterator>

namespace fair {
namespace internal {
namespace metrics {

/// int_a^b |c'(t)| dt on one piece by adaptive_integral.
template <class Piece>
double arc_length_between(const Piece_jet<Piece>& jet, double a, double b, const Quadrature_options& options,
                          const char* what) {
  return adaptive_integral([&](double t) { return jet(t, 1).speed(); }, a, b, options, what).value;
}

/// What the sampler does at a sample where c' = 0 (the normal and the curvature are undefined).
enum class At_singular_sample {
  THROW,          ///< Precondition_error
  ONE_SIDED_LIMIT ///< the values a little inside the piece (singular_sample_offsets)
};

/// How far inside the piece the one-sided limit at a singular sample is taken, tried in order:
/// the smallest offset at which c' is nonzero in double, so that the limit is accurate.
constexpr double singular_sample_offsets[] = {1e-9, 1e-7, 1e-5};

/// Sets the unit normal and the curvature of `c` from the jet `j`; false where c' = 0 (or a value
/// is not finite) and they are undefined.
inline bool set_normal_and_curvature(const Jet& j, Curve_sample& c) {
  const double v = j.speed();
  const double kappa = j.curvature();
  if (!(v > 0) || !std::isfinite(v) || !std::isfinite(kappa)) return false;
  c.nx = -j.y1 / v;
  c.ny = j.x1 / v;
  c.curvature = kappa;
  return true;
}

/// The sampled curve of `pieces` (a range of pieces joined end to start), arc lengths to the
/// accuracy of `options`. \throws Precondition_error when samples_per_piece is 0, a point or the
/// arc length is not finite, or at a singular sample (for ONE_SIDED_LIMIT: only when the piece is
/// singular at every offset too).
template <class PieceRange>
Sampled_curve sample_pieces(const PieceRange& pieces, std::size_t samples_per_piece, const Quadrature_options& options,
                            At_singular_sample at_singular, const char* what) {
  require(samples_per_piece > 0, what, ": samples_per_piece must be > 0");
  typedef typename std::iterator_traits<decltype(std::begin(pieces))>::value_type Piece;
  Sampled_curve out;
  double s = 0;
  std::size_t index = 0;
  const double n = static_cast<double>(samples_per_piece);
  for (const Piece& piece : pieces) {
    out.piece_start.push_back(s);
    const Piece_jet<Piece> jet(piece);
    double previous_t = 0;
    for (std::size_t k = 0; k <= samples_per_piece; ++k) {
      Curve_sample c;
      c.piece = index;
      c.t = k == samples_per_piece ? 1.0 : static_cast<double>(k) / n;
      if (k > 0) s += arc_length_between(jet, previous_t, c.t, options, what);
      previous_t = c.t;
      const Jet j = jet(c.t, 2);
      c.x = j.x;
      c.y = j.y;
      c.arc_length = s;
      if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(s))
        throw Precondition_error(message(what, ": piece ", index, " at t = ", c.t, " gives the non-finite point (", c.x,
                                         ", ", c.y, ") or arc length ", s));
      if (!set_normal_and_curvature(j, c)) {
        require(at_singular == At_singular_sample::ONE_SIDED_LIMIT, what, ": singular point (c' = 0) on piece ", index,
                " at t = ", c.t);
        bool found = false;
        for (double offset : singular_sample_offsets) {
          found = set_normal_and_curvature(jet(c.t < 0.5 ? c.t + offset : c.t - offset, 2), c);
          if (found) break;
        }
        require(found, what, ": piece ", index, " is singular at t = ", c.t,
                " (c'(t) = 0 or undefined curvature, also nearby)");
      }
      out.samples.push_back(c);
    }
    ++index;
  }
  out.piece_start.push_back(s);
  return out;
}

} // namespace metrics
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_METRICS_SAMPLER_H
