// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Options of fair::Optimal_curve_2 (Gumhold's optimal curves, issue 11; see
// Optimal_curve_2.h and doc/optimal_curves.md). Separate from the class so that the solver
// (internal/optimal/hierarchy.h) reads these options directly.

#ifndef FAIR_OPTIMAL_CURVE_OPTIONS_H
#define FAIR_OPTIMAL_CURVE_OPTIONS_H

#include <array>
#include <cstddef>
#include <vector>

namespace fair {

/// The discrete curvature of the functional (doc/optimal_curves.md), all in TRUE curvature:
/// REGULARISED = eq. 9 x 2 (phi/(s cos(phi/2.1))), CIRCUMCIRCLE = kappa° of eq. 6 x 2,
/// TURNING_ANGLE = kappa^phi of eq. 6 x 2 (phi/s).
enum class Curvature_discretisation { REGULARISED, CIRCUMCIRCLE, TURNING_ANGLE };
/// NEWTON (the default: exact banded Hessian, converges in a few steps per level) or the paper's
/// CONJUGATE_GRADIENT (Polak-Ribiere with a Newton line search; for comparison only).
enum class Optimal_curve_solver { NEWTON, CONJUGATE_GRADIENT };
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

/// The lambda of the defaults (issue 25 §1): the paper's design of eq. 10 with q(eta) of eqs.
/// 11-12 at this lambda, chosen on hand-drawn data (doc/optimal_curves.md, "Defaults").
constexpr double default_optimal_lambda = 0.7;

/// The largest resolution (issue 29 #3). The vertex count of the hierarchy grows as sqrt(rho)
/// (hierarchy.h: an edge of sagitta extent / rho on a curvature kappa is ~ sqrt(8 extent /
/// (rho kappa)) long): on a five-point arch, 92 000 vertices at 10^10 (about 3 s), 917 020 and
/// 179 s, 3.6 GB at 10^12. A pixel of 10^-10 of the extent is far beyond any display or
/// machining tolerance (and near the rounding of the turning angles); a larger resolution is a
/// Precondition_error (the program: a usage error). max_vertices bounds what is left.
constexpr double max_optimal_resolution = 1e10;

/// Options of the solve. By default the lambda design of eq. 10 at default_optimal_lambda: a
/// fair curve close to the data. The raw weights of eq. 5 (F = int beta + beta0 |kappa L0|^alpha0
/// + ... ds, L0 = length of the input polygon) are used when lambda = -1 (and no segment_lambda):
/// with alpha0 = 2 the minimiser of int beta + beta0 kappa^2 (unscaled) is obtained with
/// curvature_weight/length_weight = (beta0/beta) / L0^2. (Their minimiser at beta = beta0 = 1 has
/// the natural radius L0, the input polygon's length: balloons several times the data's size.)
struct Optimal_curve_options {
  bool closed = false;
  double length_weight = 1;                               ///< beta (>= 0; used when lambda = -1)
  double curvature_weight = 1;                            ///< beta_0 (>= 0; used when lambda = -1)
  double curvature_exponent = 2;                          ///< alpha_0 (>= 1)
  std::array<double, 5> derivative_weight{{0, 0, 0, 0, 0}};    ///< beta_k, k = 1..4 (index 0 unused)
  std::array<double, 5> derivative_exponent{{2, 2, 2, 2, 2}};  ///< alpha_k (>= 1)
  /// eq. 10 if in [0, 1]: beta = q(eta)(1 - lambda), beta0 = lambda, q(eta) = 4*10^(3.5 eta + 0.08)
  /// per segment (eqs. 11-12 x 4), overriding length_weight and curvature_weight; -1 = off (the
  /// raw weights). Default: default_optimal_lambda.
  double lambda = default_optimal_lambda;
  /// per input segment lambda_i (eq. 10 locally, blended with phi_4 as in Sec. 3.2); empty = off.
  /// Size: points - 1 (open) or points (closed). Takes precedence over `lambda`.
  std::vector<double> segment_lambda;
  /// The q of eq. 10 held fixed (> 0, this library's true-curvature convention: the paper's
  /// q = 100 of Fig. 6a is 400 here) instead of q(eta) of eqs. 11-12 (0 = q(eta); then the
  /// lambda = 1 reference curve is solved first to measure eta). Finite and >= 0.
  double lambda_length_scale = 0;
  std::vector<Point_constraint> constraints;
  double resolution = 500;  ///< rho in (0, max_optimal_resolution]: pixels per extent (twice the largest distance from the centroid, doc)
  Optimal_curve_solver solver = Optimal_curve_solver::NEWTON;
  Curvature_discretisation discretisation = Curvature_discretisation::REGULARISED;
  std::size_t max_levels = 30, max_iterations_per_level = 100, max_vertices = 200000;
  /// Newton stops when half the Newton decrement g^T H^-1 g (the predicted decrease) is below
  /// tolerance * |F|; CG when the relative decrease of F per step is below it.
  double tolerance = 1e-10;
  /// Throw fair::Solve_error carrying the Optimal_curve_report when the solve ends DIVERGING or
  /// CAPPED (doc/concepts.md); otherwise such a curve is returned and report().status says it.
  bool throw_on_failure = false;
};

} // namespace fair

#endif // FAIR_OPTIMAL_CURVE_OPTIONS_H
