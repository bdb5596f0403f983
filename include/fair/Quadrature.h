// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The options and the result of the library's adaptive quadrature (arc length, bending energy,
// curvature variation energy of Fairness_metrics.h; arc lengths of Curve_sampling.h).
// Method: globally adaptive Gauss-Kronrod 7/15 in double; the error of a subinterval is estimated
// by |K15 - G7|, conservative for smooth integrands but not a rigorous bound (a feature narrower
// than the initial subintervals can be missed). doc/fairness_metrics.md has the details.

#ifndef FAIR_QUADRATURE_H
#define FAIR_QUADRATURE_H

#include <cstddef>

namespace fair {

/// Accuracy goals and caps of the adaptive quadrature.
struct Quadrature_options {
  /// Stop when the summed error estimate is <= max(absolute_tolerance, relative_tolerance |value|).
  double relative_tolerance = 1e-10;
  double absolute_tolerance = 1e-14;
  /// Cap on the number of subintervals per integral (each costs 15 integrand evaluations).
  /// Reaching it throws Non_convergence_error.
  std::size_t max_subintervals = 20000;
  /// Initial uniform subdivision of each piece's parameter interval.
  std::size_t initial_subintervals = 4;
};

/// A quadrature result: the value, an error estimate and the cost.
struct Quadrature_estimate {
  double value = 0;
  double error_bound = 0;
  std::size_t evaluations = 0;
  std::size_t subintervals = 0;

  Quadrature_estimate& operator+=(const Quadrature_estimate& o) {
    value += o.value;
    error_bound += o.error_bound;
    evaluations += o.evaluations;
    subintervals += o.subintervals;
    return *this;
  }
};

} // namespace fair

#endif // FAIR_QUADRATURE_H
