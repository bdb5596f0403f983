// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The linear algebra of the kappa-curve solver (internal/linear_algebra/): the block band LU of
// Newton's method, the pivoted band LU of its fallback and of the alternating passes, the banded
// Cholesky of Levenberg-Marquardt, the zig-zag order of closed curves; named in namespace kappa.

#ifndef FAIR_INTERNAL_KAPPA_BANDED_H
#define FAIR_INTERNAL_KAPPA_BANDED_H

#include <fair/internal/linear_algebra/banded_cholesky.h>
#include <fair/internal/linear_algebra/banded_lu.h>
#include <fair/internal/linear_algebra/block_band_lu.h>
#include <fair/internal/linear_algebra/cyclic_order.h>

namespace fair {
namespace internal {
namespace kappa {

using linear_algebra::Banded_cholesky;
using linear_algebra::Banded_lu;
using linear_algebra::Block4;
using linear_algebra::Block_band_lu;
using linear_algebra::cyclic_position;

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_BANDED_H
