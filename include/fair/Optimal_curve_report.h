// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The outcome of a fair::Optimal_curve_2 solve (Optimal_curve_status) and what the solve did
// (Optimal_curve_report): filled by the solver (internal/optimal/hierarchy.h).

#ifndef FAIR_OPTIMAL_CURVE_REPORT_H
#define FAIR_OPTIMAL_CURVE_REPORT_H

#include <cstddef>
#include <ostream>
#include <vector>

namespace fair {

/// CONVERGED: the Newton decrement (with a negligible shift) fell below the tolerance on every
/// level and the target resolution was reached; DIVERGING: the curve runs away (its extent grows
/// beyond a cap: the functional has no finite minimiser for these data); CAPPED: an iteration,
/// level or vertex cap was hit first, or the solver failed (an edge collapsed, no descent step). JSON spelling: "converged", "diverging", "capped".
enum class Optimal_curve_status { CONVERGED, DIVERGING, CAPPED };

/// One level of the hierarchy: its vertices, solver iterations, final energy, the Euclidean
/// norm of the reduced gradient (dF/d offsets; on a CONVERGED level: at the start of the final
/// Newton step, which is then still taken and squares it) and its outcome.
struct Optimal_curve_level {
  std::size_t vertices = 0, iterations = 0;
  double energy = 0, gradient_norm = 0;
  Optimal_curve_status status = Optimal_curve_status::CAPPED;
  friend bool operator==(const Optimal_curve_level& a, const Optimal_curve_level& b) {
    return a.vertices == b.vertices && a.iterations == b.iterations && a.energy == b.energy &&
           a.gradient_norm == b.gradient_norm && a.status == b.status;
  }
  friend bool operator!=(const Optimal_curve_level& a, const Optimal_curve_level& b) { return !(a == b); }
};
/// The whole solve: outcome (the worst of the levels, or CAPPED if a level/vertex cap stopped the
/// hierarchy before the target resolution), final energy, total iterations, the reduced gradient
/// norm of the last level (as in Optimal_curve_level), per-level records.
struct Optimal_curve_report {
  Optimal_curve_status status = Optimal_curve_status::CAPPED;
  double energy = 0;
  std::size_t iterations = 0;
  double gradient_norm = 0;
  std::vector<Optimal_curve_level> levels;
  /// How far the curve swings out of its data (issue 25 §2; internal/optimal/shape_check.h): the
  /// largest distance of a polygon vertex from the centroid of the input points over the largest
  /// distance of an input point from it (>= 1; a balloon 4 times the data's size: ~4). JSON
  /// "extent_ratio".
  double extent_ratio = 1;
  /// Certified self-intersections (pairs of non-adjacent edges that meet, exact predicates on the
  /// double coordinates) of the optimal polygon (JSON "self_intersections") and of the input
  /// polygon (JSON "input_self_intersections"): a curve with more crossings than its input makes
  /// loops the data do not force.
  std::size_t self_intersections = 0, input_self_intersections = 0;
  /// Member by member (the report a Solve_error carries equals the curve's report()).
  friend bool operator==(const Optimal_curve_report& a, const Optimal_curve_report& b) {
    return a.status == b.status && a.energy == b.energy && a.iterations == b.iterations &&
           a.gradient_norm == b.gradient_norm && a.levels == b.levels && a.extent_ratio == b.extent_ratio &&
           a.self_intersections == b.self_intersections && a.input_self_intersections == b.input_self_intersections;
  }
  friend bool operator!=(const Optimal_curve_report& a, const Optimal_curve_report& b) { return !(a == b); }
};

/// "converged", "diverging" or "capped".
inline const char* to_string(Optimal_curve_status s) {
  switch (s) {
    case Optimal_curve_status::CONVERGED: return "converged";
    case Optimal_curve_status::DIVERGING: return "diverging";
    case Optimal_curve_status::CAPPED: break;
  }
  return "capped";
}
inline std::ostream& operator<<(std::ostream& out, Optimal_curve_status s) { return out << to_string(s); }

/// "level{vertices 96, iterations 4, energy 12.5, gradient 1e-09, converged}".
inline std::ostream& operator<<(std::ostream& out, const Optimal_curve_level& l) {
  return out << "level{vertices " << l.vertices << ", iterations " << l.iterations << ", energy " << l.energy
             << ", gradient " << l.gradient_norm << ", " << l.status << "}";
}

/// One line: "Optimal_curve_report{converged, energy 12.5, iterations 31, gradient 1e-09,
/// 6 levels, last level{...}, extent ratio 1.02, self-intersections 0 (input 0)}".
inline std::ostream& operator<<(std::ostream& out, const Optimal_curve_report& r) {
  out << "Optimal_curve_report{" << r.status << ", energy " << r.energy << ", iterations " << r.iterations
      << ", gradient " << r.gradient_norm << ", " << r.levels.size() << (r.levels.size() == 1 ? " level" : " levels");
  if (!r.levels.empty()) out << ", last " << r.levels.back();
  return out << ", extent ratio " << r.extent_ratio << ", self-intersections " << r.self_intersections << " (input "
             << r.input_self_intersections << ")}";
}

} // namespace fair

#endif // FAIR_OPTIMAL_CURVE_REPORT_H
