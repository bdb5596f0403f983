// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Small helpers shared by Bernstein_polynomial and the root isolation: binomial tables in any
// number type, and sign-variation counting that copes with the uncertain signs of
// CGAL::Interval_nt.

#ifndef FAIR_INTERNAL_BERNSTEIN_SIGN_H
#define FAIR_INTERNAL_BERNSTEIN_SIGN_H

#include <fair/Errors.h>

#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace bernstein {

/// Rows 0..n of Pascal's triangle in NT, built by additions only (exact for exact NT, and for
/// double as long as the entries stay below 2^53, i.e. n <= 55).
template <class NT>
std::vector<std::vector<NT>> binomial_table(std::size_t n) {
  std::vector<std::vector<NT>> C(n + 1);
  for (std::size_t i = 0; i <= n; ++i) {
    C[i].assign(i + 1, NT(1));
    for (std::size_t k = 1; k < i; ++k) C[i][k] = C[i - 1][k - 1] + C[i - 1][k];
  }
  return C;
}

/// The range [min, max] of the possible signs (-1, 0, +1) of a CGAL sign result.
inline std::pair<int, int> sign_range(CGAL::Sign s) { return std::make_pair(int(s), int(s)); }
inline std::pair<int, int> sign_range(const CGAL::Uncertain<CGAL::Sign>& s) {
  return std::make_pair(int(s.inf()), int(s.sup()));
}
template <class NT>
std::pair<int, int> sign_range_of(const NT& x) {
  return sign_range(CGAL::sign(x));
}

/// Sign variation bounds of the sequence [first, last), zero coefficients skipped.
/// `upper` is computed by a dynamic programme over the last nonzero sign (none, -, +).
/// `Count` is fair::Sign_variation_count (members `lower`, `upper`): a template parameter, so
/// that its one declaration stays in Bernstein_polynomial.h, which includes this file.
template <class Count, class Iterator>
Count sign_variation_bounds(Iterator first, Iterator last) {
  Count out;
  int last_certain = 0;        // last certainly nonzero sign, for the lower bound
  const int NONE = -1000000;   // "unreachable" state marker
  int best_none = 0, best_minus = NONE, best_plus = NONE; // max variations ending in each state
  for (Iterator it = first; it != last; ++it) {
    const std::pair<int, int> r = sign_range_of(*it);
    if (r.first == r.second) { // certain sign
      if (r.first != 0) {
        if (last_certain != 0 && last_certain != r.first) ++out.lower;
        last_certain = r.first;
      }
    }
    // Upper bound: the coefficient may be any sign in [r.first, r.second].
    int nn = best_none, nm = best_minus, np = best_plus;
    if (r.first <= 0 && r.second >= 0) { /* zero possible: states unchanged */ }
    else { nn = NONE; nm = NONE; np = NONE; }
    if (r.first < 0) { // may be negative
      const int v = std::max({best_none, best_minus, best_plus == NONE ? NONE : best_plus + 1});
      nm = std::max(nm, v);
    }
    if (r.second > 0) { // may be positive
      const int v = std::max({best_none, best_plus, best_minus == NONE ? NONE : best_minus + 1});
      np = std::max(np, v);
    }
    best_none = nn; best_minus = nm; best_plus = np;
  }
  out.upper = std::max({best_none, best_minus, best_plus});
  return out;
}

} // namespace bernstein
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_BERNSTEIN_SIGN_H
