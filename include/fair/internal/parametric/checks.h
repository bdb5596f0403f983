// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The argument checks shared by the ParametricCurve_2 models of Parametric_curve_2.h: a finite
// parameter interval with begin < end, a parameter inside it, a finite constructor argument.
// Each throws Precondition_error naming the model and the offending value (the concept's
// promise: never a NaN for a parameter outside the domain).

#ifndef FAIR_INTERNAL_PARAMETRIC_CHECKS_H
#define FAIR_INTERNAL_PARAMETRIC_CHECKS_H

#include <fair/Errors.h>

#include <cmath>

namespace fair {
namespace internal {
namespace parametric {

/// [u0, u1] is a finite interval with u0 < u1.
inline void check_domain(const char* what, double u0, double u1) {
  require(std::isfinite(u0) && std::isfinite(u1) && u0 < u1, what, ": the parameter interval [", u0, ", ", u1,
          "] is not a finite interval with begin < end");
}

/// u is finite and in [u0, u1] (the domain of `what`::jet).
inline void check_parameter(const char* what, double u, double u0, double u1) {
  require(std::isfinite(u) && u0 <= u && u <= u1, what, "::jet: u = ", u, " is outside [", u0, ", ", u1, "]");
}

/// The argument `name` of `what` is finite.
inline void check_finite(const char* what, const char* name, double v) {
  require(std::isfinite(v), what, ": ", name, " = ", v, " is not finite");
}

} // namespace parametric
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_PARAMETRIC_CHECKS_H
