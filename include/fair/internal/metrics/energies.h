// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The integral metrics of Fairness_metrics.h (arc length, bending energy, curvature variation
// energy): the adaptive quadrature of a function of the piece's jet over every piece.

#ifndef FAIR_INTERNAL_METRICS_ENERGIES_H
#define FAIR_INTERNAL_METRICS_ENERGIES_H

#include <fair/internal/metrics/pieces.h>
#include <fair/internal/metrics/quadrature.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace metrics {

/// Whether an integrand needs the curvature (undefined where c' = 0) or only the speed.
enum class Integrand_domain { ANY_POINT, REGULAR_POINTS };

/// Sum over the pieces of int_0^1 f(jet(t)) dt, each by adaptive_integral with the options `o`.
/// \throws Precondition_error for REGULAR_POINTS at a node where c' = 0.
template <class Piece, class F>
Quadrature_estimate integrate_over_curve(const std::vector<Piece>& curve, F f, Integrand_domain domain,
                                         const Quadrature_options& o, const char* what) {
  check_curve(curve, what);
  Quadrature_estimate total;
  for (std::size_t i = 0; i < curve.size(); ++i) {
    Piece_jet<Piece> jet(curve[i]);
    total += adaptive_integral(
        [&](double t) {
          const Jet j = jet(t);
          require(domain == Integrand_domain::ANY_POINT || j.speed() > 0, what, ": singular point (c' = 0) on piece ",
                  i, " at t = ", t, ", where the curvature is undefined");
          return f(j);
        },
        0.0, 1.0, o, what);
  }
  // Finite pieces can still have an integral beyond double (kappa ~ 1e300 on a tiny piece, its
  // square overflows): a typed refusal rather than inf or NaN.
  if (!std::isfinite(total.value) || !std::isfinite(total.error_bound))
    throw Invalid_input_error(message(what, ": the integral is ", total.value, " (error bound ", total.error_bound,
                                      ") in double: the integrand overflows for this curve's scale"));
  return total;
}

/// int |c'| dt over every piece (defined at singular points too).
template <class Piece>
Quadrature_estimate arc_length(const std::vector<Piece>& curve, const Quadrature_options& o) {
  return integrate_over_curve(curve, [](const Jet& j) { return j.speed(); }, Integrand_domain::ANY_POINT, o,
                              "arc_length");
}

/// int kappa^2 |c'| dt over every piece.
template <class Piece>
Quadrature_estimate bending_energy(const std::vector<Piece>& curve, const Quadrature_options& o) {
  auto f = [](const Jet& j) {
    const double k = j.curvature();
    return k * k * j.speed();
  };
  return integrate_over_curve(curve, f, Integrand_domain::REGULAR_POINTS, o, "bending_energy");
}

/// int (dkappa/dt)^2 / |c'| dt (per_arc_length: = int (dkappa/ds)^2 ds) or int (dkappa/dt)^2 dt
/// over every piece.
template <class Piece>
Quadrature_estimate curvature_variation_energy(const std::vector<Piece>& curve, bool per_arc_length,
                                               const Quadrature_options& o) {
  auto f = [per_arc_length](const Jet& j) {
    const double k = j.curvature_derivative();
    return per_arc_length ? k * k / j.speed() : k * k;
  };
  return integrate_over_curve(curve, f, Integrand_domain::REGULAR_POINTS, o, "curvature_variation_energy");
}

} // namespace metrics
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_METRICS_ENERGIES_H
