// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Gumhold's optimal curves (issue 11; S. Gumhold, "Designing optimal curves in 2D", Sec. 2.3-3.3):
// the interpolating polygon that minimises the scale-invariant functional of eq. 5,
//   F(c) = int beta + beta_0 |kappa L0|^alpha_0 + sum_k beta_k |kappa^(k) L0^(k+1)|^alpha_k ds,
// with TRUE curvature (the paper's eq. 9 is half of it, doc/optimal_curves.md), computed by a
// hierarchical, adaptive Newton method on the normal offsets of the free vertices
// (doc/optimal_curves_solver.md). Points -> solver on doubles -> polygon in the user's kernel.

#ifndef FAIR_OPTIMAL_CURVE_2_H
#define FAIR_OPTIMAL_CURVE_2_H

#include <fair/internal/optimal/hierarchy.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <ostream>
#include <vector>

namespace fair {

/// The discrete curvature of the functional (doc/optimal_curves.md), all in TRUE curvature:
/// REGULARISED = eq. 9 x 2 (phi/(s cos(phi/2.1))), CIRCUMCIRCLE = kappa° of eq. 6 x 2,
/// TURNING_ANGLE = kappa^phi of eq. 6 x 2 (phi/s).
enum class Curvature_discretisation { REGULARISED, CIRCUMCIRCLE, TURNING_ANGLE };
/// NEWTON (the default: exact banded Hessian, converges in a few steps per level) or the paper's
/// CONJUGATE_GRADIENT (Polak-Ribiere with a Newton line search; for comparison only).
enum class Optimal_curve_solver { NEWTON, CONJUGATE_GRADIENT };
/// CONVERGED: the Newton decrement fell below the tolerance on every level and the target
/// resolution was reached; DIVERGING: the curve runs away (its extent grows beyond a cap or an
/// edge degenerates: the functional has no finite minimiser for these data); CAPPED: an
/// iteration, level or vertex cap was hit first. JSON spelling: "converged", "diverging", "capped".
enum class Optimal_curve_status { CONVERGED, DIVERGING, CAPPED };
/// TANGENT (direction of travel), NORMAL (its left normal) or CORNER (in- and outgoing tangents).
enum class Point_constraint_kind { TANGENT, NORMAL, CORNER };

/// A constraint at input point `index` (0-based). Directions may have any non-zero length.
struct Point_constraint {
  std::size_t index = 0;
  Point_constraint_kind kind = Point_constraint_kind::TANGENT;
  std::array<double, 2> direction{{1, 0}};  ///< TANGENT: direction of travel; NORMAL: its left normal
                                            ///< (-t_y, t_x); CORNER: the incoming tangent
  std::array<double, 2> outgoing{{1, 0}};   ///< CORNER only: the outgoing tangent
};

/// Options of the solve. Weights are those of eq. 5 (F = int beta + beta0 |kappa L0|^alpha0 + ...
/// ds, L0 = length of the input polygon): with alpha0 = 2 the minimiser of int beta + beta0 kappa^2
/// (unscaled) is obtained with curvature_weight/length_weight = (beta0/beta) / L0^2.
struct Optimal_curve_options {
  bool closed = false;
  double length_weight = 1;                               ///< beta (>= 0)
  double curvature_weight = 1;                            ///< beta_0 (>= 0)
  double curvature_exponent = 2;                          ///< alpha_0 (>= 1)
  std::array<double, 5> derivative_weight{{0, 0, 0, 0, 0}};    ///< beta_k, k = 1..4 (index 0 unused)
  std::array<double, 5> derivative_exponent{{2, 2, 2, 2, 2}};  ///< alpha_k (>= 1)
  /// eq. 10 if in [0, 1]: beta = q(eta)(1 - lambda), beta0 = lambda, q(eta) = 4*10^(3.5 eta + 0.08)
  /// per segment (eqs. 11-12 x 4), overriding length_weight and curvature_weight; -1 = off.
  double lambda = -1;
  /// per input segment lambda_i (eq. 10 locally, blended with phi_4 as in Sec. 3.2); empty = off.
  /// Size: points - 1 (open) or points (closed).
  std::vector<double> segment_lambda;
  std::vector<Point_constraint> constraints;
  double resolution = 500;                                ///< rho: pixels per bounding-box extent (> 0)
  Optimal_curve_solver solver = Optimal_curve_solver::NEWTON;
  Curvature_discretisation discretisation = Curvature_discretisation::REGULARISED;
  std::size_t max_levels = 30, max_iterations_per_level = 100, max_vertices = 1000000;
  /// Newton stops when half the Newton decrement g^T H^-1 g (the predicted decrease) is below
  /// tolerance * |F|; CG when the relative decrease of F per step is below it.
  double tolerance = 1e-10;
};

/// One level of the hierarchy: its vertices, solver iterations, final energy, the Euclidean
/// norm of the reduced gradient (dF/d offsets) and its outcome.
struct Optimal_curve_level {
  std::size_t vertices, iterations;
  double energy, gradient_norm;
  Optimal_curve_status status;
};
/// The whole solve: outcome (the worst of the levels, or CAPPED if a level/vertex cap stopped the
/// hierarchy before the target resolution), final energy, total iterations, per-level records.
struct Optimal_curve_report {
  Optimal_curve_status status;
  double energy;
  std::size_t iterations;
  std::vector<Optimal_curve_level> levels;
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

/// The optimal curve through `points` (closed: no repeated last point).
/// Errors: Invalid_input_error for too few points (< 2 open, < 3 closed), non-finite or
/// coincident consecutive points, constraints out of range / with a zero direction / that cannot
/// be met; Precondition_error for options outside their domain (negative or non-finite weights,
/// all of beta, beta_0, beta_k zero, lambda outside [0, 1], exponents < 1, resolution <= 0).
/// A solve that diverges or hits a cap does not throw: report().status says so.
/// Complexity: O(n w^2) per Newton step (banded Hessian, w = max k + 2), n = finest vertices.
template <class K>
class Optimal_curve_2 {
public:
  typedef K Kernel;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;

  Optimal_curve_2(const std::vector<Point_2>& points, const Optimal_curve_options& options = Optimal_curve_options())
    : options_(options) {
    std::vector<internal::optimal::Vec2> p;
    p.reserve(points.size());
    for (const Point_2& q : points) p.push_back({{CGAL::to_double(q.x()), CGAL::to_double(q.y())}});
    internal::optimal::Solve_result r = internal::optimal::solve_optimal_curve(p, to_internal(options));
    polygon_.reserve(r.polygon.size());
    for (const internal::optimal::Vec2& v : r.polygon) polygon_.push_back(Point_2(FT(v[0]), FT(v[1])));
    interpolation_indices_ = r.interpolation_indices;
    curvatures_ = r.curvatures;
    report_.status = static_cast<Optimal_curve_status>(r.status);
    report_.energy = r.energy;
    report_.iterations = r.iterations;
    for (const internal::optimal::Level_record& l : r.levels)
      report_.levels.push_back({l.vertices, l.iterations, l.energy, l.gradient_norm,
                                static_cast<Optimal_curve_status>(l.status)});
  }

  /// The optimal polygon (closed: no repeated vertex); its vertices at interpolation_indices()
  /// are the input points (converted to double and back: exact for double input).
  const std::vector<Point_2>& polygon() const { return polygon_; }
  /// The polygon index of each input point.
  const std::vector<std::size_t>& interpolation_indices() const { return interpolation_indices_; }
  const Optimal_curve_report& report() const { return report_; }
  /// The discrete true curvature per polygon vertex (the functional's discretisation; 0 at open ends).
  std::vector<double> curvatures() const { return curvatures_; }
  /// F of eq. 5 (discrete, Sec. 2.2.3) at the final polygon.
  double energy() const { return report_.energy; }
  const Optimal_curve_options& options() const { return options_; }

private:
  static internal::optimal::Solve_options to_internal(const Optimal_curve_options& o) {
    internal::optimal::Solve_options s;
    s.closed = o.closed;
    s.length_weight = o.length_weight;
    s.curvature_weight = o.curvature_weight;
    s.curvature_exponent = o.curvature_exponent;
    s.derivative_weight = o.derivative_weight;
    s.derivative_exponent = o.derivative_exponent;
    s.lambda = o.lambda;
    s.segment_lambda = o.segment_lambda;
    for (const Point_constraint& c : o.constraints)
      s.constraints.push_back({c.index, static_cast<internal::optimal::Constraint_kind>(c.kind), c.direction, c.outgoing});
    s.resolution = o.resolution;
    s.conjugate_gradient = o.solver == Optimal_curve_solver::CONJUGATE_GRADIENT;
    s.discretisation = static_cast<internal::optimal::Discretisation>(o.discretisation);
    s.max_levels = o.max_levels;
    s.max_iterations_per_level = o.max_iterations_per_level;
    s.max_vertices = o.max_vertices;
    s.tolerance = o.tolerance;
    return s;
  }

  Optimal_curve_options options_;
  std::vector<Point_2> polygon_;
  std::vector<std::size_t> interpolation_indices_;
  std::vector<double> curvatures_;
  Optimal_curve_report report_;
};

} // namespace fair

#endif // FAIR_OPTIMAL_CURVE_2_H
