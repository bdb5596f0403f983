// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The functional of one level of the optimal-curve hierarchy (hierarchy.h), with the ghost
// vertices of clamped open ends (Level_problem), and its energy, gradient, Hessian and curvatures
// on the level polygon.

#ifndef FAIR_INTERNAL_OPTIMAL_LEVEL_PROBLEM_H
#define FAIR_INTERNAL_OPTIMAL_LEVEL_PROBLEM_H

#include <fair/Errors.h>
#include <fair/internal/optimal/functional.h>
#include <fair/internal/optimal/hessian.h>
#include <fair/internal/optimal/vec2.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

/// Distance of the ghost vertex behind a clamped open end, as a fraction of L0 (see Level_problem):
/// small enough that its half-edge adds a negligible 1e-6 L0 / l_end to the end's arc element, large
/// enough that the ghost edge direction is exact to ~1e-10 for data of extent ~ L0.
constexpr double ghost_fraction = 1e-6;

/// The functional of one level, with the clamped open ends of constraints.h: a tangent t at an
/// open end p_0 adds a FIXED ghost vertex p_0 - eps t (eps = ghost_fraction L0) before it (after
/// it at the last end), its edge weighted 0 and the ghost itself without curvature. The end vertex
/// then carries the curvature term phi_0 / (s_0 cos(phi_0/2.1)) with phi_0 the angle between t and
/// the first edge and s_0 = (eps + l_0)/2 ~ l_0/2: a consistent discretisation of kappa at a clamped
/// end (for a smooth curve phi_0 = kappa l_0/2 + O(l_0^2)), where fixing the end's neighbour on
/// the tangent (as for corners) would force kappa = 0 on the first edge and cost O(h) in F. The
/// derivative terms whose stencil reaches the ghost are absent (it has no curvature), so the tiny
/// ghost edge never enters a difference quotient.
struct Level_problem {
  Functional f;  // on the level polygon (n vertices)
  bool ghost_front = false, ghost_back = false;
  Vec2 front_tangent{{1, 0}}, back_tangent{{1, 0}};
  Functional augmented;  // f on the polygon with the ghosts (prepare())

  bool ghosts() const { return ghost_front || ghost_back; }
  /// Builds `augmented` from f (call after setting f's weights).
  void prepare() {
    if (!ghosts()) return;
    augmented = f;
    const double zero = 0;
    if (ghost_front) {
      augmented.length_weight.insert(augmented.length_weight.begin(), zero);
      augmented.curvature_weight.insert(augmented.curvature_weight.begin(), zero);
      if (!augmented.zero_curvature.empty()) augmented.zero_curvature.insert(augmented.zero_curvature.begin(), 0);
    }
    if (ghost_back) {
      augmented.length_weight.push_back(zero);
      augmented.curvature_weight.push_back(zero);
      if (!augmented.zero_curvature.empty()) augmented.zero_curvature.push_back(0);
    }
  }
  std::size_t offset() const { return ghost_front ? 1 : 0; }
  std::vector<Vec2> extend(const std::vector<Vec2>& c) const {
    if (!ghosts()) return c;
    const double e = ghost_fraction * f.reference_length;
    std::vector<Vec2> d;
    d.reserve(c.size() + 2);
    if (ghost_front) d.push_back({{c.front()[0] - e * front_tangent[0], c.front()[1] - e * front_tangent[1]}});
    d.insert(d.end(), c.begin(), c.end());
    if (ghost_back) d.push_back({{c.back()[0] + e * back_tangent[0], c.back()[1] + e * back_tangent[1]}});
    return d;
  }
  std::vector<double> strip(const std::vector<double>& v, std::size_t n) const {
    return std::vector<double>(v.begin() + offset(), v.begin() + offset() + n);
  }
};

inline double problem_energy(const Level_problem& p, const std::vector<Vec2>& c) {
  return p.ghosts() ? energy(p.augmented, p.extend(c)) : energy(p.f, c);
}
inline double problem_energy_and_gradient(const Level_problem& p, const std::vector<Vec2>& c, std::vector<Vec2>& g) {
  if (!p.ghosts()) return energy_and_gradient(p.f, c, g);
  std::vector<Vec2> ga;
  const double e = energy_and_gradient(p.augmented, p.extend(c), ga);
  g.assign(ga.begin() + p.offset(), ga.begin() + p.offset() + c.size());
  return e;
}
inline double problem_energy_gradient_hessian(const Level_problem& p, const std::vector<Vec2>& c, std::vector<Vec2>& g,
                                              Block_banded_hessian& h) {
  if (!p.ghosts()) return energy_gradient_hessian(p.f, c, g, h);
  std::vector<Vec2> ga;
  Block_banded_hessian ha;
  const double e = energy_gradient_hessian(p.augmented, p.extend(c), ga, ha);
  const std::size_t n = c.size(), o = p.offset(), w = ha.half_bandwidth();
  g.assign(ga.begin() + o, ga.begin() + o + n);
  h.reset(n, w, false);  // ghosts only on open curves
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n && j <= i + w; ++j)
      for (int r = 0; r < 2; ++r)
        for (int q = 0; q < 2; ++q) h.at(i, j, r, q) = ha.at(i + o, j + o, r, q);
  return e;
}
/// The discrete curvature at every vertex of the level polygon (clamped ends: their kappa).
inline std::vector<double> problem_curvatures(const Level_problem& p, const std::vector<Vec2>& c) {
  return p.ghosts() ? p.strip(discrete_curvatures(p.augmented, p.extend(c)), c.size()) : discrete_curvatures(p.f, c);
}

/// F at c, +infinity where the functional rejects the polygon (its Invalid_input_error: coincident
/// vertices after a step, overflow); any other error (an Internal_error) propagates.
inline double energy_or_infinity(const Level_problem& p, const std::vector<Vec2>& c) {
  try {
    const double e = problem_energy(p, c);
    return std::isfinite(e) ? e : std::numeric_limits<double>::infinity();
  } catch (const Invalid_input_error&) {
    return std::numeric_limits<double>::infinity();
  }
}

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_LEVEL_PROBLEM_H
