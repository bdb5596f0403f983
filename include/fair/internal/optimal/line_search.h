// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The line search of a level of the optimal-curve solver: Armijo backtracking (c1 = 1e-4,
// halving, capped) from the longest step that moves no vertex by more than max_step_fraction of its
// shorter incident edge (a trust region in the geometry: a full Newton step far from the minimiser
// must not throw vertices across the curve, which makes loops and cusps that the level then
// "converges" in; near the minimiser steps are tiny and the cap is inactive, so the quadratic
// convergence is kept).

#ifndef FAIR_INTERNAL_OPTIMAL_LINE_SEARCH_H
#define FAIR_INTERNAL_OPTIMAL_LINE_SEARCH_H

#include <fair/internal/optimal/level_problem.h>
#include <fair/internal/optimal/reduced_system.h>
#include <fair/internal/optimal/vec2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

/// Most halvings of the Armijo line search (2^-60 ~ 1e-18: below rounding of any step).
constexpr int max_backtracks = 60;
/// Armijo sufficient-decrease constant.
constexpr double armijo_c1 = 1e-4;
/// When no Armijo step decreases F any more, the level counts as converged if the predicted
/// decrease is below this fraction of |F| (the rounding floor of F's evaluation at large n).
constexpr double rounding_floor = 1e-8;
/// Largest move of a vertex in one step, as a fraction of its shorter incident edge.
constexpr double max_step_fraction = 0.5;

/// The largest t <= 1 (or more) with |t x_k v_a| <= max_step_fraction * min(l_{a-1}, l_a) at
/// every moved vertex a.
inline double step_cap(const std::vector<Vec2>& c, bool closed, const Reduced_unknowns& u, const std::vector<double>& x) {
  const std::size_t n = c.size();
  double cap = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < n; ++a) {
    if (u.var[a] < 0) continue;
    double l = std::numeric_limits<double>::infinity();
    if (closed || a > 0) l = std::min(l, vec::norm(vec::sub(c[a], c[(a + n - 1) % n])));
    if (closed || a + 1 < n) l = std::min(l, vec::norm(vec::sub(c[(a + 1) % n], c[a])));
    const double move = std::abs(x[u.var[a]]) * vec::norm(u.dir[a]);
    if (move > 0) cap = std::min(cap, max_step_fraction * l / move);
  }
  return cap;
}

/// The Armijo search along the step x of the iterate `at` (predicted decrease `decrement`): the
/// accepted polygon `trial` and its energy `et`; false when no step of the ladder decreases F
/// enough (the caller then judges the decrement against rounding_floor).
inline bool armijo_search(const Level_iterate& at, const std::vector<double>& x, double decrement,
                          std::vector<Vec2>& trial, double& et) {
  double t = std::min(1.0, step_cap(at.polygon, at.problem.f.closed, at.unknowns, x));
  et = std::numeric_limits<double>::infinity();
  int b = 0;
  for (; b <= max_backtracks; ++b, t *= 0.5) {
    trial = displaced(at.polygon, at.unknowns, x, t, at.roles);
    et = energy_or_infinity(at.problem, trial);
    if (et <= at.energy - armijo_c1 * t * decrement) break;
  }
  return b <= max_backtracks;
}

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_LINE_SEARCH_H
