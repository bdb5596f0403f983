// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The certified unique root of a quartic in Bernstein form on [0,1] whose coefficients are known
// as interval ENCLOSURES of exact values, with an exact (Gmpq) sign fallback: what the curvature
// extrema of a conic piece (eq. 4 of Yan, Schiller, Schaefer, "Circle reproduction with
// interpolatory curves at local maximal curvature points", internal/conic/curvature_extrema.h)
// and the interpolation at a curvature extremum (eq. 7, internal/conic/interpolation.h) both
// need. Kept apart from both so that the piece (Rational_quadratic_bezier_2.h) does not depend
// on the interpolation (Rational_quadratic_interpolation.h), which builds pieces.
//
// Method: the one shared certified-bracket mechanism of the Bernstein internals,
// fair::internal::bernstein::tighten_double_bracket (internal/bernstein/unique_root.h):
// safeguarded Newton in double on the midpoints of the enclosures, started at the chord
// crossing, then a bracket grown by certified interval signs and shrunk by bisection to at most
// quartic_bracket_ulps ulps, with the exact fallback where the intervals cannot decide.
// Guarantee: since the enclosures contain the EXACT coefficients, f(t_lower) < 0 < f(t_upper)
// holds for the exact quartic, or t_lower == t_upper is its exact root.

#ifndef FAIR_INTERNAL_CONIC_QUARTIC_ROOT_H
#define FAIR_INTERNAL_CONIC_QUARTIC_ROOT_H

#include <fair/internal/bernstein/unique_root.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>

namespace fair {
namespace internal {
namespace conic {

typedef CGAL::Interval_nt<false> Rq_interval;

/// Width cap of the certified bracket, in ulps of its upper end: the interval-certified bracket
/// grown around Newton's iterate is usually that narrow already, so the exact fallback (Gmpq)
/// is rarely needed; 8 would trigger it on most inputs, whose enclosures are wider than point
/// intervals.
constexpr double quartic_bracket_ulps = 32;

/// A certified simple root of a quartic with f(0) < 0 < f(1).
struct Quartic_root {
  double t = 0.5;       ///< double estimate of the root, t_lower <= t <= t_upper
  double t_lower = 0;   ///< f(t_lower) < 0 exactly, or t_lower == t_upper == exact root
  double t_upper = 1;   ///< f(t_upper) > 0 exactly, or t_lower == t_upper == exact root
  int exact_evaluations = 0; ///< number of exact (Gmpq) sign evaluations the filter needed
};

/// f(t) exactly, de Casteljau on Gmpq coefficients.
inline CGAL::Sign quartic_sign_exact(const std::array<CGAL::Gmpq, 5>& b, double t) {
  const CGAL::Gmpq tt(t), s = CGAL::Gmpq(1) - tt;
  std::array<CGAL::Gmpq, 5> v = b;
  for (int r = 1; r <= 4; ++r)
    for (int i = 0; i + r <= 4; ++i) v[i] = s * v[i] + tt * v[i + 1];
  return CGAL::sign(v[0]);
}

/// Certified root of a quartic in Bernstein form on [0,1] that is known to have a unique simple
/// root in (0,1) with f(0) < 0 < f(1). `b` encloses the exact coefficients (intervals);
/// `exact_sign(t)` returns the exact sign of f at a double t. See the file comment.
/// Must be called in round-to-nearest mode (it protects the rounding mode itself).
template <class Exact_sign>
Quartic_root certified_unique_root_quartic(const Rq_interval* b, Exact_sign exact_sign) {
  Quartic_root out;
  double c[5];
  for (int i = 0; i < 5; ++i) {
    const double lo = b[i].inf(), hi = b[i].sup();
    c[i] = std::isfinite(lo) && std::isfinite(hi) ? lo + (hi - lo) / 2 : (std::isfinite(lo) ? lo : (std::isfinite(hi) ? hi : 0.0));
  }
  double start = c[0] / (c[0] - c[4]); // chord crossing (regula falsi start)
  if (!(start > 0.0 && start < 1.0)) start = 0.5;
  auto counted = [&](double t) {
    ++out.exact_evaluations;
    return int(exact_sign(t));
  };
  const bernstein::Double_bracket r =
    bernstein::tighten_double_bracket(b, c, 5, 0.0, 1.0, -1, start, counted, quartic_bracket_ulps);
  out.t = r.root;
  out.t_lower = r.lower;
  out.t_upper = r.upper;
  return out;
}

} // namespace conic
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_CONIC_QUARTIC_ROOT_H
