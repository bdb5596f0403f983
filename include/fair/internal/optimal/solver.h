// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The level optimiser of Gumhold's optimal curves (Sec. 2.3.2, replaced by Newton as issue 11
// asks; doc/optimal_curves.md, "Level solve"): solve_level minimises the functional of one level
// (level_problem.h) over the reduced unknowns (reduced_system.h: offsets along the vertex normals
// and tie rotations). Each iteration takes a Newton step (newton_step.h; the paper's
// CONJUGATE_GRADIENT step on request, conjugate_gradient.h), an Armijo line search capped by the
// geometry (line_search.h), and re-anchors the lines of motion when the vertices crowd
// (reanchoring.h); level_outcome.h says how a level ends.

#ifndef FAIR_INTERNAL_OPTIMAL_SOLVER_H
#define FAIR_INTERNAL_OPTIMAL_SOLVER_H

#include <fair/Optimal_curve_report.h>
#include <fair/internal/optimal/conjugate_gradient.h>
#include <fair/internal/optimal/constraints.h>
#include <fair/internal/optimal/functional.h>
#include <fair/internal/optimal/hessian.h>
#include <fair/internal/optimal/level_outcome.h>
#include <fair/internal/optimal/level_problem.h>
#include <fair/internal/optimal/line_search.h>
#include <fair/internal/optimal/newton_step.h>
#include <fair/internal/optimal/reanchoring.h>
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

struct Level_settings {
  bool conjugate_gradient = false;
  std::size_t max_iterations = 100;
  double tolerance = 1e-10;
  double max_extent = std::numeric_limits<double>::infinity();  // divergence cap
  bool fixed_normals = true;  // lines of motion fixed for the whole level (see solve_level)
};

/// Minimises F over the free unknowns of `c` (in place).
inline Level_outcome solve_level(const Level_problem& p, const Vertex_roles& roles, const Level_settings& s,
                                 std::vector<Vec2>& c) {
  const bool closed = p.f.closed;
  Level_outcome out;
  std::vector<Vec2> g, normals, trial;
  Block_banded_hessian h;
  Banded_symmetric rh;
  std::vector<double> rg, x;
  Conjugate_gradient_state cg;
  const double start_extent = polygon_extent(c);
  double half_way_extent = 0;  // the extent after half the iteration cap (runaway test)
  Anchoring anchoring(c, closed);
  bool reanchored = false;
  for (std::size_t it = 0;; ++it) {
    const double e = problem_energy_gradient_hessian(p, c, g, h);
    out.energy = e;
    // The lines of motion: normals of the level's start polygon (s.fixed_normals) or of the
    // current polygon (recomputed after every step, the paper's choice).
    if (it == 0 || !s.fixed_normals || reanchored) normals = vertex_normals(c, closed);
    reanchored = false;
    const Reduced_unknowns u = reduced_unknowns(c, normals, roles, closed);
    reduced_system(g, h, closed, u, rg, rh);
    if (!s.conjugate_gradient) add_tie_curvature(c, g, u, roles, rh);
    out.gradient_norm = euclidean_norm(rg);
    out.iterations = it;
    const double scale = std::max(std::abs(e), std::numeric_limits<double>::min());
    if (u.count == 0 || out.gradient_norm == 0) { out.status = Status::CONVERGED; return out; }
    if (it == s.max_iterations / 2) half_way_extent = polygon_extent(c);
    if (it >= s.max_iterations) {
      out.status = capped_status(c, start_extent, half_way_extent);
      return out;
    }
    const Level_iterate at{p, roles, c, u, rg, rh, e, scale};
    double decrement;  // predicted decrease of a full step
    if (!s.conjugate_gradient) {
      if (newton_step(at, s.tolerance, it, x, decrement, c, out)) return out;
    } else {
      decrement = conjugate_gradient_step(at, cg, x);
    }
    double et;
    if (!armijo_search(at, x, decrement, trial, et)) {
      out.status = 0.5 * decrement <= rounding_floor * scale ? Status::CONVERGED : Status::CAPPED;
      return out;
    }
    if (geometry_stop(trial, closed, roles, s.max_extent, out.status)) {
      c = trial;
      out.energy = et;
      out.iterations = it + 1;
      return out;
    }
    c = trial;
    if (anchoring.reanchor(c, closed, roles)) {
      reanchored = true;
      continue;
    }
    if (s.conjugate_gradient && e - et <= s.tolerance * scale) {
      out.energy = et;
      out.iterations = it + 1;
      out.status = Status::CONVERGED;
      return out;
    }
  }
}

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_SOLVER_H
