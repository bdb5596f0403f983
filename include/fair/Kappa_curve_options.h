// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The options of fair::Kappa_curve_2 (Kappa_curve_2.h): open or closed, how the weights of the
// pieces are chosen, and the caps and tolerance of the solve. Equation numbers refer to Yan,
// Schiller, Schaefer, "Circle reproduction with interpolatory curves at local maximal curvature
// points".

#ifndef FAIR_KAPPA_CURVE_OPTIONS_H
#define FAIR_KAPPA_CURVE_OPTIONS_H

#include <cstddef>
#include <vector>

namespace fair {

/// How the weights w_i of the middle control points are chosen.
enum class Kappa_weights {
  UNIT,      ///< w_i = 1: the polynomial kappa-curves (parabolic pieces)
  FIXED,     ///< w_i given per input point (Kappa_curve_options::fixed_weights)
  AUTOMATIC  ///< clamped minimum-eccentricity weights of eq. 16 (reproduce circles)
};

/// The options of a Kappa_curve_2. Checked by its constructor (Invalid_input_error for bad
/// weights, tension or clamp; Precondition_error for a negative or non-finite tolerance).
struct Kappa_curve_options {
  bool closed = false;
  Kappa_weights weights = Kappa_weights::UNIT;
  /// FIXED: one weight > 0 per input point (the entries of the two end points of an open curve
  /// are ignored).
  std::vector<double> fixed_weights;
  /// AUTOMATIC: tension mu_i > 0 per input point (eq. 16); empty means all 1.
  std::vector<double> tension;
  /// AUTOMATIC: lower clamp of eq. 16 (paper: 1/2, pieces of at most 120 degrees of a circle).
  double weight_clamp = 0.5;
  /// Cap on the alternating passes (Sec. 5.1; the paper uses 60): two before Newton's method,
  /// the rest (stopping once the residual is below 1e-3) only if Newton's method fails.
  std::size_t refinement_passes = 60;
  /// Cap on the iterations (Jacobians) of Newton's method and Levenberg-Marquardt together.
  /// With AUTOMATIC weights, the continuation from w = 1 that runs when no kappa-curve was found
  /// (doc/kappa_curves.md) has one more cap of the same size: at most 2 x max_iterations in all.
  std::size_t max_iterations = 200;
  /// Stop when the max-norm residual (dimensionless, see Kappa_curve_report) is at most this.
  double tolerance = 1e-12;
  /// Throw fair::Solve_error carrying the Kappa_curve_report instead of returning an UNSOLVED
  /// curve (Kappa_curve_status; never for INTERIOR or ON_JOINS; doc/concepts.md).
  bool throw_on_failure = false;
};

} // namespace fair

#endif // FAIR_KAPPA_CURVE_OPTIONS_H
