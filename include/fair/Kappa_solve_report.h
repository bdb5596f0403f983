// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// What the solve of a fair::Kappa_curve_2 did and reached (Kappa_solve_report) and where it
// ended (Kappa_solver_state): both filled by the solver itself (internal/kappa/solver.h).
// Equation numbers refer to Yan, Schiller, Schaefer, "Circle reproduction with interpolatory
// curves at local maximal curvature points".

#ifndef FAIR_KAPPA_SOLVE_REPORT_H
#define FAIR_KAPPA_SOLVE_REPORT_H

#include <cstddef>
#include <ostream>
#include <vector>

namespace fair {

/// What a solve did and reached. Residuals are dimensionless: distances in units of the half
/// size of the bounding box of the points, eq. 7 divided by A_i + C_i, relative |kappa|
/// mismatch (Kappa_curve_2.h).
struct Kappa_solve_report {
  bool converged = false;
  bool warm_started = false;           ///< the solution came from the previous one (not a cold start)
  std::size_t refinement_passes = 0;   ///< alternating passes of Sec. 5.1
  std::size_t iterations = 0;          ///< Jacobians evaluated (Newton and Levenberg-Marquardt)
  double residual = 0;                 ///< max of the four below
  double interpolation_residual = 0;   ///< max |c_i(t_i) - Q_i| / (half size of the bounding box)
  double curvature_residual = 0;       ///< max |eq. 7| / (A_i + C_i)
  double g2_residual = 0;              ///< max | |k1|-|k2| | / (|k1|+|k2|) at joins
  double weight_residual = 0;          ///< max |w_i - w~_i| (AUTOMATIC; 0 when converged)
  /// Energy terms: sums of squares of the same residuals (E_G2 ~ eq. 11, E_c ~ eq. 12,
  /// E_w = eq. 13, plus the interpolation constraint eq. 18 as an energy).
  double energy_interpolation = 0, energy_curvature = 0, energy_g2 = 0, energy_weight = 0;
  /// Number of t_i or lambda_i within 1e-4 of 0 or 1: the data have no (well-separated) interior solution
  /// there (an interpolated point lands on a join); such a solve is never "converged".
  std::size_t bounds_active = 0;
  /// The input points whose t_i or lambda_i is there (indices into points()): each lies on a
  /// join, not at a curvature maximum (see doc/kappa_existence.md). Empty when converged.
  std::vector<std::size_t> boundary_points;
  double energy() const { return energy_interpolation + energy_curvature + energy_g2 + energy_weight; }

  friend std::ostream& operator<<(std::ostream& out, const Kappa_solve_report& r) {
    out << "Kappa_solve_report{converged " << r.converged << ", warm " << r.warm_started << ", passes "
        << r.refinement_passes << ", iterations " << r.iterations << ", residual " << r.residual << " (interpolation "
        << r.interpolation_residual << ", eq.7 " << r.curvature_residual << ", |kappa| " << r.g2_residual << ", weight "
        << r.weight_residual << "), bounds active " << r.bounds_active;
    if (!r.boundary_points.empty()) {
      out << " (points on a join:";
      for (const std::size_t i : r.boundary_points) out << ' ' << i;
      out << ')';
    }
    return out << ", energy " << r.energy() << "}";
  }
};

/// The unknowns of a kappa-curve solve, one entry per piece j (per block of the system): what
/// a Kappa_curve_2 keeps to warm-start the next solve, and the exact parameters fair::certify()
/// rebuilds the curve from. Offsets are in the solver's normalised coordinates:
/// x_original = center + Kappa_curve_2::normalisation_scale() * x_normalised.
struct Kappa_solver_state {
  std::vector<double> dx, dy;  ///< d_j = P_j - Q_j, the middle control point relative to its point (normalised)
  std::vector<double> lambda;  ///< lambda_j of eq. 9 (the join at the start of piece j; unused for piece 0 of an open curve)
  std::vector<double> t;       ///< t_j with c_j(t_j) = Q_j
  std::vector<double> w;       ///< the weight w_j, as last computed

  /// n pieces of the neutral start: offsets 0, lambda_j = t_j = 1/2, w_j = 1.
  void resize(std::size_t n) {
    dx.assign(n, 0.0); dy.assign(n, 0.0); lambda.assign(n, 0.5); t.assign(n, 0.5); w.assign(n, 1.0);
  }
};

} // namespace fair

#endif // FAIR_KAPPA_SOLVE_REPORT_H
