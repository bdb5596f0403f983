// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The plane vector of the optimal-curve solver, fitter and functional (all in double: the
// solver's side of the data flow), with the few operations they share.

#ifndef FAIR_INTERNAL_OPTIMAL_VEC2_H
#define FAIR_INTERNAL_OPTIMAL_VEC2_H

#include <array>
#include <cmath>

namespace fair {
namespace internal {
namespace optimal {

typedef std::array<double, 2> Vec2;

namespace vec {
inline double cross(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }
inline double dot(const Vec2& a, const Vec2& b) { return a[0] * b[0] + a[1] * b[1]; }
inline double norm(const Vec2& a) { return std::hypot(a[0], a[1]); }
inline Vec2 sub(const Vec2& a, const Vec2& b) { return {{a[0] - b[0], a[1] - b[1]}}; }
inline Vec2 unit(const Vec2& a) { const double l = norm(a); return {{a[0] / l, a[1] / l}}; }
} // namespace vec

} // namespace optimal
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_OPTIMAL_VEC2_H
