// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Sign_variation_count: the result of fair::sign_variation_bounds (Bernstein_polynomial.h).

#ifndef FAIR_SIGN_VARIATION_COUNT_H
#define FAIR_SIGN_VARIATION_COUNT_H

#include <fair/Errors.h>

namespace fair {

/// Bounds on the number of sign variations of a coefficient sequence whose signs may be
/// uncertain (CGAL::Interval_nt). For exact and floating NT, lower == upper always.
/// An uncertain coefficient may take any sign (including 0), so `lower` counts it as zero and
/// `upper` lets it take whichever sign maximises the count.
struct Sign_variation_count {
  int lower = 0;
  int upper = 0;
  /// The count is known. It may be known even when some signs are not: (?) gives 0..0, while
  /// (+, ?) gives 0..1.
  bool certain() const { return lower == upper; }
  /// The count; \throws Precondition_error if it is not certain.
  int count() const {
    internal::require(certain(), "Sign_variation_count::count: the sign variation count is uncertain, between ",
                      lower, " and ", upper);
    return lower;
  }
};

} // namespace fair

#endif // FAIR_SIGN_VARIATION_COUNT_H
