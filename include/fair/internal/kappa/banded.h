// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The banded solvers of the kappa-curve solver: internal/common/banded.h (Banded_lu,
// Banded_cholesky, the zig-zag order cyclic_position), under the names the solver uses.

#ifndef FAIR_INTERNAL_KAPPA_BANDED_H
#define FAIR_INTERNAL_KAPPA_BANDED_H

#include <fair/internal/common/banded.h>

namespace fair {
namespace internal {
namespace kappa {

using common::Banded_cholesky;
using common::Banded_lu;
using common::cyclic_position;

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_BANDED_H
