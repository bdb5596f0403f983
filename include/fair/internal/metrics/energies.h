// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The integral metrics of Fairness_metrics.h (arc length, bending energy, curvature variation
// energy): the adaptive quadrature of a function of the piece's jet over every piece.

#ifndef FAIR_INTERNAL_METRICS_ENERGIES_H
#define FAIR_INTERNAL_METRICS_ENERGIES_H

#include <fair/internal/metrics/pieces.h>
#include <fair/internal/metrics/quadrature.h>

#include <vector>

namespace fair {
namespace internal {
namespace metrics {

/// Sum over the pieces of int_0^1 f(jet(t)) dt, each by adaptive_integral with the options `o`.
template <class Piece, class F>
Quadrature_estimate integrate_over_curve(const std::vector<Piece>& curve, F f, const Quadrature_options& o,
                                         const char* what) {
  check_curve(curve, what);
  Quadrature_estimate total;
  for (const Piece& piece : curve) {
    Piece_jet<Piece> jet(piece);
    total += adaptive_integral([&](double t) { return f(jet(t)); }, 0.0, 1.0, o, what);
  }
  return total;
}

} // namespace metrics
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_METRICS_ENERGIES_H
