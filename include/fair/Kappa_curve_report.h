// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// What the solve of a fair::Kappa_curve_2 did and reached (Kappa_curve_report) and where it
// ended (Kappa_solver_state): both filled by the solver itself (internal/kappa/solver.h).
// Equation numbers refer to Yan, Schiller, Schaefer, "Circle reproduction with interpolatory
// curves at local maximal curvature points".

#ifndef FAIR_KAPPA_CURVE_REPORT_H
#define FAIR_KAPPA_CURVE_REPORT_H

#include <cstddef>
#include <ostream>
#include <vector>

namespace fair {

/// The outcome of a kappa-curve solve (doc/kappa_curves.md, "Outcomes").
///  - INTERIOR: max residual <= tolerance, no t_i or lambda_i on a bound, and every input point
///    at a curvature MAXIMUM of its piece: every property of the paper holds.
///  - ON_JOINS: max residual <= tolerance (interpolating, C0, G1, |kappa|-continuous to the
///    tolerance), no point at a curvature minimum, but the points of points_on_joins lie on a
///    join (t or lambda at 0 or 1: the box-constrained solution of doc/kappa_existence.md), not
///    at an interior curvature maximum.
///  - UNSOLVED: otherwise: the residual stays above the tolerance (worst_points says where), or a
///    point lies at a curvature MINIMUM of its piece (points_at_minima; possible with weights
///    w_i < 1, paper Sec. 3.2), even when every equation holds; Kappa_curve_report::reason says
///    which (Kappa_curve_unsolved_reason).
enum class Kappa_curve_status { INTERIOR, ON_JOINS, UNSOLVED };

/// "interior", "on_joins" or "unsolved" (the spelling of the JSON of fair-curves kappa).
inline const char* to_string(Kappa_curve_status s) {
  switch (s) {
    case Kappa_curve_status::INTERIOR: return "interior";
    case Kappa_curve_status::ON_JOINS: return "on_joins";
    case Kappa_curve_status::UNSOLVED: break;
  }
  return "unsolved";
}
inline std::ostream& operator<<(std::ostream& out, Kappa_curve_status s) { return out << to_string(s); }

/// Why a solve ended UNSOLVED (Kappa_curve_report::reason; doc/kappa_curves.md, "Outcomes"):
///  - BEYOND_DENSITY_LIMIT: points_beyond_density_limit lists points where the data are denser
///    than interior kappa-curves allow (doc/kappa_existence.md, Sec. 7), and the solve did not
///    reach a root: such data are decided early (a bounded first attempt, no fallbacks; a
///    kappa-curve is a tool for sparse design points, dense samples want Csr_spline_2 or
///    Optimal_curve_2).
///  - POINTS_AT_MINIMA: the equations hold to the tolerance, but the points of points_at_minima
///    are at a curvature minimum of their piece (possible with weights < 1).
///  - NO_CONVERGENCE: the residual stays above the tolerance within the caps; worst_points says
///    where.
///  - NONE: the outcome is INTERIOR or ON_JOINS.
enum class Kappa_curve_unsolved_reason { NONE, BEYOND_DENSITY_LIMIT, POINTS_AT_MINIMA, NO_CONVERGENCE };

/// "none", "beyond_density_limit", "points_at_minima" or "no_convergence" (the spelling of the
/// JSON member "reason" of fair-curves kappa).
inline const char* to_string(Kappa_curve_unsolved_reason r) {
  switch (r) {
    case Kappa_curve_unsolved_reason::BEYOND_DENSITY_LIMIT: return "beyond_density_limit";
    case Kappa_curve_unsolved_reason::POINTS_AT_MINIMA: return "points_at_minima";
    case Kappa_curve_unsolved_reason::NO_CONVERGENCE: return "no_convergence";
    case Kappa_curve_unsolved_reason::NONE: break;
  }
  return "none";
}
inline std::ostream& operator<<(std::ostream& out, Kappa_curve_unsolved_reason r) { return out << to_string(r); }

/// An input point and the largest residual of its block (eq. 18 as distances, eq. 7, |kappa|
/// continuity at the join before it, eq. 16 with automatic weights): one of the worst points
/// of an UNSOLVED solve.
struct Kappa_point_residual {
  std::size_t point = 0;   ///< index into the input points
  double residual = 0;     ///< dimensionless, as Kappa_curve_report::residual
  friend bool operator==(const Kappa_point_residual& a, const Kappa_point_residual& b) {
    return a.point == b.point && a.residual == b.residual;
  }
};

/// What a solve did and reached. Residuals are dimensionless: distances in units of the half
/// size of the bounding box of the points, eq. 7 divided by A_i + C_i, relative |kappa|
/// mismatch (Kappa_curve_2.h).
struct Kappa_curve_report {
  /// Most worst_points an UNSOLVED report lists.
  static constexpr std::size_t worst_points_listed = 5;
  Kappa_curve_status status = Kappa_curve_status::UNSOLVED;  ///< the outcome (see Kappa_curve_status)
  /// Why the outcome is UNSOLVED (never NONE then); NONE for INTERIOR and ON_JOINS.
  Kappa_curve_unsolved_reason reason = Kappa_curve_unsolved_reason::NO_CONVERGENCE;
  bool warm_started = false;           ///< the solution came from the previous one (not a cold start)
  std::size_t refinement_passes = 0;   ///< alternating passes of Sec. 5.1
  std::size_t iterations = 0;          ///< Jacobians evaluated (Newton and Levenberg-Marquardt; <= 2 x max_iterations with AUTOMATIC weights)
  double residual = 0;                 ///< max of the four below
  double interpolation_residual = 0;   ///< max |c_i(t_i) - Q_i| / (half size of the bounding box)
  double curvature_residual = 0;       ///< max |eq. 7| / (A_i + C_i)
  double g2_residual = 0;              ///< max | |k1|-|k2| | / (|k1|+|k2|) at joins
  double weight_residual = 0;          ///< max |w_i - w~_i| (AUTOMATIC; 0 when the equations hold)
  /// AUTOMATIC: the weights of the curve are w_i = 1 + s (w~_i - 1) with s = weight_blend, w~_i
  /// those of eq. 16. 1 when eq. 16 holds; below 1 when the solve with eq. 16's weights found no
  /// kappa-curve and the continuation from the w = 1 kappa-curve ended at s (0: the w = 1
  /// kappa-curve itself); weight_residual then says how far eq. 16 is (doc/kappa_curves.md,
  /// "Automatic weights").
  double weight_blend = 1;
  /// Energy terms: sums of squares of the same residuals (E_G2 ~ eq. 11, E_c ~ eq. 12,
  /// E_w = eq. 13, plus the interpolation constraint eq. 18 as an energy).
  double energy_interpolation = 0, energy_curvature = 0, energy_g2 = 0, energy_weight = 0;
  /// Number of t_i or lambda_i within 1e-4 of 0 or 1: the data have no (well-separated) interior solution
  /// there (an interpolated point lands on a join); such a solve is never INTERIOR.
  std::size_t bounds_active = 0;
  /// The input points whose t_i or lambda_i is there (indices into points(), increasing): each
  /// lies on a join, not at a curvature maximum (see doc/kappa_existence.md). Empty when INTERIOR.
  std::vector<std::size_t> points_on_joins;
  /// The input points (increasing) that are not at the maximum of |kappa| of their piece: t_i
  /// inside (0, 1) at a curvature MINIMUM (the sign of the derivative of eq. 4's numerator at
  /// t_i, in double; fair::certify() decides it exactly; possible with weights < 1), or t_i on a
  /// join while |kappa| of the piece falls towards the join (the face multiplier) or is larger
  /// elsewhere on the piece (64 samples; a sample above is a witness). The outcome is then UNSOLVED.
  std::vector<std::size_t> points_at_minima;
  /// UNSOLVED: up to worst_points_listed input points with the largest residuals, worst first.
  /// Empty otherwise.
  std::vector<Kappa_point_residual> worst_points;
  /// UNSOLVED (any reason): the input points (increasing) where the data are denser than interior
  /// kappa-curves allow (doc/kappa_existence.md, Sec. 7): the |kappa| of a conic piece falls off
  /// quadratically from its maximum, so |kappa| continuity between points closer than about
  /// (2/3) |dkappa/ds| / kappa^3 puts the maximum of the point's piece outside the piece. Estimated
  /// from the data in O(n), to first order, only where the chords turn by at most 0.4 rad and |kappa|
  /// changes by at most 25 % to either neighbour (not near inflections or on straight runs), and only
  /// where the point's piece and its neighbours have weights <= 1 (there it is conservative). The likely
  /// cause of an UNSOLVED solve on dense samples of a smooth curve: such data need fewer points
  /// (kappa-curves are a tool for sparse design points) or a spline. Empty otherwise.
  std::vector<std::size_t> points_beyond_density_limit;
  double energy() const { return energy_interpolation + energy_curvature + energy_g2 + energy_weight; }

  /// Member by member (the report a Solve_error carries equals the curve's report()).
  friend bool operator==(const Kappa_curve_report& a, const Kappa_curve_report& b) {
    return a.status == b.status && a.reason == b.reason && a.warm_started == b.warm_started && a.refinement_passes == b.refinement_passes &&
           a.iterations == b.iterations && a.residual == b.residual &&
           a.interpolation_residual == b.interpolation_residual && a.curvature_residual == b.curvature_residual &&
           a.g2_residual == b.g2_residual && a.weight_residual == b.weight_residual && a.weight_blend == b.weight_blend &&
           a.energy_interpolation == b.energy_interpolation && a.energy_curvature == b.energy_curvature &&
           a.energy_g2 == b.energy_g2 && a.energy_weight == b.energy_weight && a.bounds_active == b.bounds_active &&
           a.points_on_joins == b.points_on_joins && a.points_at_minima == b.points_at_minima &&
           a.worst_points == b.worst_points && a.points_beyond_density_limit == b.points_beyond_density_limit;
  }
  friend bool operator!=(const Kappa_curve_report& a, const Kappa_curve_report& b) { return !(a == b); }

  friend std::ostream& operator<<(std::ostream& out, const Kappa_curve_report& r) {
    out << "Kappa_curve_report{" << r.status;
    if (r.reason != Kappa_curve_unsolved_reason::NONE) out << " (" << r.reason << ')';
    out << ", warm " << r.warm_started << ", passes "
        << r.refinement_passes << ", iterations " << r.iterations << ", residual " << r.residual << " (interpolation "
        << r.interpolation_residual << ", eq.7 " << r.curvature_residual << ", |kappa| " << r.g2_residual << ", weight "
        << r.weight_residual << "), bounds active " << r.bounds_active;
    if (r.weight_blend != 1) out << ", weights blended towards 1: s = " << r.weight_blend;
    if (!r.points_on_joins.empty()) {
      out << " (points on a join:";
      for (const std::size_t i : r.points_on_joins) out << ' ' << i;
      out << ')';
    }
    if (!r.points_at_minima.empty()) {
      out << ", points at a curvature minimum:";
      for (const std::size_t i : r.points_at_minima) out << ' ' << i;
    }
    if (!r.worst_points.empty()) {
      out << ", worst points:";
      for (const Kappa_point_residual& p : r.worst_points) out << ' ' << p.point << " (" << p.residual << ')';
    }
    if (!r.points_beyond_density_limit.empty())
      out << ", " << r.points_beyond_density_limit.size()
          << (r.points_beyond_density_limit.size() == 1 ? " point" : " points") << " beyond the density limit";
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

#endif // FAIR_KAPPA_CURVE_REPORT_H
