// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Mathematical constants of the library, once: std::numbers is C++20 and M_PI is POSIX, not C++.

#ifndef FAIR_INTERNAL_COMMON_CONSTANTS_H
#define FAIR_INTERNAL_COMMON_CONSTANTS_H

namespace fair {
namespace internal {
namespace common {

constexpr double pi = 3.14159265358979323846;  ///< the double nearest to pi
constexpr double two_pi = 2 * pi;              ///< exact: doubling is exact in binary
constexpr double half_pi = pi / 2;             ///< exact: halving is exact in binary

}  // namespace common
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_COMMON_CONSTANTS_H
