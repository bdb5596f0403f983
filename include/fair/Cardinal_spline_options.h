// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The options of fair::Cardinal_spline_2 (Cardinal_spline_2.h; J. Li, "Curvature variation
// minimizing Cardinal spline curves", eq. numbers refer to it; doc/cardinal_splines.md).

#ifndef FAIR_CARDINAL_SPLINE_OPTIONS_H
#define FAIR_CARDINAL_SPLINE_OPTIONS_H

#include <optional>

namespace fair {

/// How a Cardinal_spline_2 is built (doc/concepts.md).
struct Cardinal_spline_options {
  /// Closed: one segment per point, indices mod N, no auxiliary points.
  bool closed = false;
  /// The parameter alpha = (1 - tension)/2 > 0 of eqs. 1-2 (converted exactly to the kernel's FT).
  /// Without it the constructor computes Li's alpha* (eq. 18) and, open, the auxiliary points
  /// optimal for it (eqs. 19-20); with it the auxiliary points optimal for this alpha (eqs. 16-17).
  std::optional<double> alpha;
  /// Throw fair::Solve_error carrying the Cardinal_spline_report when eq. 18 has no positive
  /// optimum (status NO_OPTIMUM); otherwise such a curve is the Catmull-Rom spline (alpha = 1/2).
  bool throw_on_failure = false;
};

} // namespace fair

#endif // FAIR_CARDINAL_SPLINE_OPTIONS_H
