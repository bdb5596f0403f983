// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// max_circle_deviation() of Fairness_metrics.h: the candidate parameters of max | |c(t) - C| - r |
// on one piece. For a Bernstein-form piece they are the piece ends and the certified roots of
// d/dt |c - C|^2, whose numerator is G = (B . B') W - |B|^2 W' with B = (X - Cx W, Y - Cy W) on the
// exact homogeneous form; a generic piece is sampled.

#ifndef FAIR_INTERNAL_METRICS_CIRCLE_DEVIATION_H
#define FAIR_INTERNAL_METRICS_CIRCLE_DEVIATION_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Bernstein_root_isolation.h>
#include <fair/internal/common/exact_conversion.h>
#include <fair/internal/metrics/features.h>
#include <fair/internal/metrics/pieces.h>

#include <CGAL/Gmpq.h>

#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace metrics {

/// Samples per piece of the uncertified candidates on generic pieces (a deviation peak narrower
/// than 1/4096 of the parameter range can be missed; they are not certified).
constexpr int generic_deviation_samples = 4096;

/// The parameters of `piece` where |c - center| may be extremal: 0, 1 and the interior critical
/// points. `certified` is cleared when they come from sampling (generic pieces).
template <class Piece>
std::vector<double> circle_deviation_candidates(const Piece& piece, const typename Piece::Point_2& center,
                                                Certification_budget& budget, bool& certified) {
  std::vector<double> ts{0.0, 1.0};
  if constexpr (is_bernstein_form(kind_of<Piece>)) {
    const Homogeneous_form h = homogeneous_exact(piece);
    if (!budget.allows(predicted_work(h, 3, 1))) {
      certified = false;  // G (degree 3 in the form) would exceed the caps (pieces.h)
      for (int k = 1; k < generic_deviation_samples; ++k) ts.push_back(double(k) / generic_deviation_samples);
      return ts;
    }
    const CGAL::Gmpq Cx = common::to_gmpq(center.x()), Cy = common::to_gmpq(center.y());
    const Bernstein_polynomial<CGAL::Gmpq> Bx = h.X - Cx * h.W, By = h.Y - Cy * h.W;
    const Bernstein_polynomial<CGAL::Gmpq> G =
        (Bx * Bx.derivative() + By * By.derivative()) * h.W - (Bx * Bx + By * By) * h.W.derivative();
    if (!G.is_zero() && !budget.take(polynomial_work(G))) {
      certified = false;
      for (int k = 1; k < generic_deviation_samples; ++k) ts.push_back(double(k) / generic_deviation_samples);
    } else if (!G.is_zero()) {
      Bernstein_root_isolation iso(G);
      for (std::size_t k = 0; k < iso.number_of_roots(); ++k) ts.push_back(iso.root_approximation(k));
    } // else |c - C| is constant on the piece: the ends suffice
  } else {
    certified = false;
    for (int k = 1; k < generic_deviation_samples; ++k) ts.push_back(double(k) / generic_deviation_samples);
  }
  return ts;
}

} // namespace metrics
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_METRICS_CIRCLE_DEVIATION_H
