// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The certified roots in [0,1] of an exact Bernstein polynomial together with its exact sign on
// every gap between them (Bernstein_root_isolation, then an exact rational probe inside each
// gap). Shared by the certified curvature features (internal/metrics/features.h) and the
// Proposition-1 certificate (internal/exact_conversion/convexity.h).

#ifndef FAIR_INTERNAL_BERNSTEIN_SIGNED_ROOTS_H
#define FAIR_INTERNAL_BERNSTEIN_SIGNED_ROOTS_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Bernstein_root_isolation.h>
#include <fair/Errors.h>

#include <CGAL/Gmpq.h>
#include <CGAL/number_utils.h>

#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace bernstein {

/// Exact sign of a Gmpq polynomial at x.
inline int exact_sign_at(const Bernstein_polynomial<CGAL::Gmpq>& p, const CGAL::Gmpq& x) {
  return CGAL::sign(p.evaluate(x));
}

/// The roots of p in [0,1] with the sign of p on each gap between consecutive roots (and before
/// the first / after the last). gaps[k] is the sign on the gap just before root k
/// (gaps.size() == roots + 1); an empty gap (root at 0 or at 1) has sign 0.
struct Signed_roots {
  std::vector<Isolating_interval> roots;
  std::vector<double> approximations;
  std::vector<int> gaps;
};

/// Cap on the refinements of the isolating intervals next to a gap while looking for a rational
/// that is not a root inside it: one refinement suffices unless the midpoint hits a root; the cap
/// only guards against a broken isolation (then Internal_error).
constexpr int max_gap_refinements = 200;

inline Signed_roots signed_roots(const Bernstein_polynomial<CGAL::Gmpq>& p) {
  Signed_roots out;
  Bernstein_root_isolation iso(p);
  const std::size_t k = iso.number_of_roots();
  for (std::size_t i = 0; i < k; ++i) out.approximations.push_back(iso.root_approximation(i));
  out.roots = iso.intervals();
  const CGAL::Gmpq zero(0), one(1);
  for (std::size_t g = 0; g <= k; ++g) {
    // Find an exact rational strictly inside the gap between root g-1 and root g.
    int sign = 0;
    bool empty = false;
    for (int attempt = 0; attempt < max_gap_refinements; ++attempt) {
      const std::vector<Isolating_interval>& R = iso.intervals();
      const bool has_prev = g > 0, has_next = g < k;
      empty = (has_prev && !has_next && R[g - 1].is_point() && R[g - 1].lower == one) ||  // empty gap at 1
              (!has_prev && has_next && R[g].is_point() && R[g].lower == zero);          // empty gap at 0
      if (empty) break;
      const CGAL::Gmpq left = has_prev ? R[g - 1].upper : zero;
      const CGAL::Gmpq right = has_next ? R[g].lower : one;
      sign = exact_sign_at(p, (left + right) / 2);
      if (sign != 0) break;
      // The midpoint is a root: it is the end of a neighbouring point interval (all roots are
      // isolated), so the other neighbour is not a point interval; shrink it.
      if (has_next && !R[g].is_point()) iso.refine(g, R[g].width() / 2);
      else if (has_prev && !R[g - 1].is_point()) iso.refine(g - 1, R[g - 1].width() / 2);
      else break;
    }
    // Between two consecutive isolated roots the polynomial has no root, so a nonzero sign exists.
    FAIR_ASSERT_MSG(empty || sign != 0, "signed_roots: no non-root found in gap ", g, " of ", k + 1);
    out.gaps.push_back(sign);
  }
  out.roots = iso.intervals();
  return out;
}

} // namespace bernstein
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_BERNSTEIN_SIGNED_ROOTS_H
