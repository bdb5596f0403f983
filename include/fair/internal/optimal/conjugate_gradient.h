// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The paper's CONJUGATE_GRADIENT step of a level of the optimal-curve solver (for comparison with
// Newton's method): Polak-Ribiere+ on the reduced unknowns, the step length found by at most ten
// Newton-Raphson steps on F(sigma) (the paper's line search); the Armijo search of line_search.h
// guards the result.

#ifndef FAIR_INTERNAL_OPTIMAL_CONJUGATE_GRADIENT_H
#define FAIR_INTERNAL_OPTIMAL_CONJUGATE_GRADIENT_H

#include <fair/Errors.h>
#include <fair/internal/optimal/level_problem.h>
#include <fair/internal/optimal/reduced_system.h>
#include <fair/internal/optimal/vec2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

/// Newton-Raphson steps of the CG line search (the paper: "a maximum of ten").
constexpr int cg_line_search_steps = 10;

/// The previous reduced gradient and direction of the Polak-Ribiere+ recurrence.
struct Conjugate_gradient_state {
  std::vector<double> previous_g, direction;
};

/// The conjugate-gradient step x (direction times its Newton-Raphson step length) of the iterate
/// `at`; returns its predicted decrease -g^T x.
inline double conjugate_gradient_step(const Level_iterate& at, Conjugate_gradient_state& cg, std::vector<double>& x) {
  const std::vector<double>& rg = at.gradient;
  const std::vector<Vec2>& c = at.polygon;
  const Reduced_unknowns& u = at.unknowns;
  std::vector<double>& previous_g = cg.previous_g;
  std::vector<double>& direction = cg.direction;
  // Polak-Ribiere+ direction (restart when the number of unknowns changed or it is not descent).
  double beta = 0;
  if (previous_g.size() == rg.size() && direction.size() == rg.size()) {
    double num = 0;
    for (std::size_t k = 0; k < rg.size(); ++k) num += rg[k] * (rg[k] - previous_g[k]);
    beta = std::max(0.0, num / dot_product(previous_g, previous_g));
  } else {
    direction.assign(rg.size(), 0);
  }
  for (std::size_t k = 0; k < rg.size(); ++k) direction[k] = -rg[k] + beta * direction[k];
  if (dot_product(direction, rg) >= 0)
    for (std::size_t k = 0; k < rg.size(); ++k) direction[k] = -rg[k];
  previous_g = rg;
  // Newton-Raphson on phi(sigma) = F(c + sigma d): phi'(0) = g.d, phi''(0) = d^T H d; later
  // steps use the secant of phi' (the gradient at the trial point).
  const double d1 = dot_product(rg, direction), d2 = reduced_form(at.hessian, direction);
  double sigma = d2 > 0 ? -d1 / d2 : 1.0;
  double sigma_prev = 0, slope_prev = d1;
  for (int r = 1; r < cg_line_search_steps && std::isfinite(sigma); ++r) {
    const std::vector<Vec2> trial = displaced(c, u, direction, sigma, at.roles);
    std::vector<Vec2> gt;
    double slope;
    try {
      problem_energy_and_gradient(at.problem, trial, gt);
      slope = 0;
      for (std::size_t a = 0; a < c.size(); ++a)
        if (u.var[a] >= 0) slope += direction[u.var[a]] * vec::dot(u.dir[a], gt[a]);
    } catch (const Invalid_input_error&) { break; }
    if (!std::isfinite(slope) || std::abs(slope) <= 1e-3 * std::abs(d1)) break;
    const double curvature = (slope - slope_prev) / (sigma - sigma_prev);
    if (!(curvature > 0)) break;
    sigma_prev = sigma; slope_prev = slope;
    sigma -= slope / curvature;
  }
  if (!(std::isfinite(sigma) && sigma > 0)) sigma = 1.0;
  for (std::size_t k = 0; k < rg.size(); ++k) direction[k] *= sigma;
  x = direction;
  return -dot_product(rg, x);
}

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_CONJUGATE_GRADIENT_H
