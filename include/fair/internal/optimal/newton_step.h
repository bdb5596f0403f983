// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The Newton step of a level of the optimal-curve solver (doc/optimal_curves.md, "Level solve"):
// solve (H + mu I) d = -g on the reduced system with mu = 0, else mu from 1e-10 max|H_kk| up by x10
// until the banded Cholesky succeeds (capped); the level has converged when the Newton decrement
// g^T d / 2 (the predicted decrease) is <= tolerance |F| without a large shift.

#ifndef FAIR_INTERNAL_OPTIMAL_NEWTON_STEP_H
#define FAIR_INTERNAL_OPTIMAL_NEWTON_STEP_H

#include <fair/internal/optimal/hessian.h>
#include <fair/internal/optimal/level_outcome.h>
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

/// Most diagonal shifts tried before giving up on a Newton step (mu grows x10 from 1e-10 max|H_kk|:
/// 30 tries reach 1e20 max|H_kk|, far beyond any Hessian of a finite polygon).
constexpr int max_shifts = 30;

/// Solves (rh + mu I) x = rhs with the smallest shift mu of the ladder that makes it positive
/// definite; false if none does. `shift` returns mu relative to the smallest |rh_kk| (0 if unshifted).
inline bool shifted_solve(const Banded_symmetric& rh, std::vector<double>& x, double& shift) {
  double diag = 0, smallest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < x.size(); ++k) {
    diag = std::max(diag, std::abs(rh.at(k, k)));
    smallest = std::min(smallest, std::abs(rh.at(k, k)));
  }
  if (!(diag > 0)) diag = 1;
  const std::vector<double> rhs = x;
  double mu = 0;
  for (int s = 0; s <= max_shifts; ++s) {
    Banded_symmetric a = rh;
    if (mu > 0) a.add_to_diagonal(mu);
    x = rhs;
    if (solve_banded_positive_definite(a, x)) {
      shift = mu == 0 ? 0.0 : smallest > 0 ? mu / smallest : std::numeric_limits<double>::infinity();
      return true;
    }
    mu = mu == 0 ? 1e-10 * diag : 10 * mu;
  }
  return false;
}

/// A Newton decrement computed with a shift larger than this fraction of the smallest diagonal entry
/// of the reduced Hessian does not certify convergence (the shift, relative to the largest entry,
/// can swamp the soft unknowns: the step and the decrement become negligible far from a minimiser).
constexpr double converged_shift = 1e-6;

/// The Newton step x of the iterate `at` of iteration `it`, and its decrement -g^T x. Returns true
/// when the level ends here, with out.status: CAPPED when no shift of the ladder makes the reduced
/// Hessian positive definite; CONVERGED when the predicted decrease is within the tolerance (the
/// last, tiny step is then still taken when it does not raise F beyond rounding: it is free,
/// already solved, and squares the remaining error; c and out follow it).
inline bool newton_step(const Level_iterate& at, double tolerance, std::size_t it, std::vector<double>& x,
                        double& decrement, std::vector<Vec2>& c, Level_outcome& out) {
  const std::vector<double>& rg = at.gradient;
  x.assign(rg.size(), 0);
  for (std::size_t k = 0; k < rg.size(); ++k) x[k] = -rg[k];
  double shift = 0;
  if (!shifted_solve(at.hessian, x, shift)) {
    out.status = Status::CAPPED;
    return true;
  }
  decrement = -dot_product(rg, x);
  if (!(0.5 * decrement <= tolerance * at.scale && shift <= converged_shift)) return false;
  const std::vector<Vec2> last = displaced(at.polygon, at.unknowns, x, 1.0, at.roles);
  const double el = energy_or_infinity(at.problem, last);
  if (el <= at.energy + 1e-14 * at.scale) {
    c = last;
    out.energy = el;
    out.iterations = it + 1;
  }
  out.status = Status::CONVERGED;
  return true;
}

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_NEWTON_STEP_H
