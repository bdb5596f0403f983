// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Unique_root: the result of fair::certified_unique_root (Bernstein_root_isolation.h), the
// fast certified root of a double Bernstein polynomial with exactly one sign change.

#ifndef FAIR_UNIQUE_ROOT_H
#define FAIR_UNIQUE_ROOT_H

namespace fair {

/// Result of certified_unique_root.
struct Unique_root {
  enum Status {
    UNIQUE_ROOT, ///< exactly one distinct root in [0,1]; it lies in [lower, upper]
    NO_ROOT,     ///< certainly no root in [0,1]
    UNDECIDED    ///< the coefficients do not prove 0 or 1 roots: use Bernstein_root_isolation
  };
  Status status = UNDECIDED;
  double root = 0;   ///< for UNIQUE_ROOT: a point of [lower, upper]
  double lower = 0;  ///< certified bracket (lower == upper == root when the root is exact)
  double upper = 0;
  int sign_variations = 0;          ///< of the coefficient sequence, zeros skipped
  bool used_exact_fallback = false; ///< whether some sign needed exact Gmpq evaluation
};

} // namespace fair

#endif // FAIR_UNIQUE_ROOT_H
