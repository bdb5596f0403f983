// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Kappa_curve_2<Kernel>: rational kappa-curves (Yan, Schiller, Schaefer, "Circle
// reproduction with interpolatory curves at local maximal curvature points"; equation numbers
// refer to that paper). One rational quadratic piece c_i (fair::Rational_quadratic_bezier_2) per
// interpolated point Q_i, such that
//   - Q_i = c_i(t_i) for some t_i in (0,1)                                  (eqs. 2, 8)
//   - Q_i is a critical point of the curvature of c_i                       (eq. 7; a maximum of
//     |kappa| whenever w_i >= 1, and in practice for the clamped automatic weights)
//   - consecutive pieces share their end point (1-lambda_i) P_{i-1,1} + lambda_i P_{i,1}, which
//     makes the curve C0 and G1 by construction                            (eq. 9)
//   - |kappa| is continuous at every join (kappa itself except at inflections) (eqs. 5, 10)
// Weights: all 1 (the polynomial kappa-curves of Yan et al. 2017), fixed per point, or the
// clamped minimum-eccentricity weights of eq. 16 (tension mu_i, clamp default 1/2), which
// reproduce circles (Sec. 4.4, Sec. 8). Options: Kappa_curve_options.h; what a solve reached:
// Kappa_curve_report.h; exact certification (certify(), certify_pieces()): include
// Kappa_certificate.h.
// Open curves (Sec. 6): the first and last points are the fixed end points; the interior
// points get one piece each. Closed curves: one piece per point, treated cyclically.
//
// Numerics (internal/kappa/solver.h, problem_setup.h): the data are translated and scaled to
// the box [-1,1]^2, the initial guess is Algorithm 1 of the paper, and the square system of
// eqs. 7, 10, 18 (and 16) is solved by Newton's method with a direct O(n) block LU
// (Levenberg-Marquardt as the fallback), O(n) per iteration.

#ifndef FAIR_KAPPA_CURVE_2_H
#define FAIR_KAPPA_CURVE_2_H

#include <fair/Errors.h>
#include <fair/Kappa_curve_options.h>
#include <fair/Kappa_curve_report.h>
#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/internal/kappa/input_checks.h>
#include <fair/internal/kappa/pieces.h>
#include <fair/internal/kappa/problem_setup.h>
#include <fair/internal/kappa/solver.h>
#include <fair/internal/nurbs/assembly.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace fair {

/// A kappa-curve through given points, solved on construction and re-solved (warm-started from
/// the current solution) by move_point() and set_points().
///
/// Exactness per kernel: the solve runs in double on the normalised data whatever the kernel;
/// the pieces are then built in the kernel (P_j rounded to it, the joins E_j formed from the
/// P_j in its arithmetic): C0 and G1 by construction, exactly so in an exact kernel.
/// Accuracy: report().residual, the max norm of dimensionless residuals (distances in units of
/// the half size of the bounding box, eq. 7 divided by A + C, relative |kappa| mismatch); with
/// unit or fixed weights it usually reaches options().tolerance (default 1e-12).
/// Outcome: report().status, INTERIOR (every property of the paper), ON_JOINS (the listed
/// report().points_on_joins lie on joins, the rest holds) or UNSOLVED (residual above the
/// tolerance, or report().points_at_minima); see Kappa_curve_status and doc/kappa_curves.md.
/// certify() and certify_pieces() (Kappa_certificate.h) certify the result, exactly or by
/// certified bounds.
/// Complexity: O(n) per iteration of the solver (a few Newton iterations from a cold start on
/// typical data); after move_point() first O(1) per iteration on the pieces near the point.
template <class K>
class Kappa_curve_2 {
public:
  typedef K Kernel;
  typedef Kappa_curve_options Options;
  typedef Kappa_curve_report Report;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Rational_quadratic_bezier_2<K> Piece;

  /// Solves the kappa-curve through `points` (at least 3).
  /// \throws Invalid_input_error for too few points, NaN/inf coordinates, coincident
  /// consecutive points, all points collinear, bad weights/tension/clamp, or a solution with a
  /// degenerate (straight) piece; Precondition_error for a negative or non-finite tolerance;
  /// Solve_error carrying the Kappa_curve_report if the outcome is Kappa_curve_status::UNSOLVED
  /// and options.throw_on_failure is set (never for INTERIOR or ON_JOINS; see report().status).
  explicit Kappa_curve_2(std::vector<Point_2> points, const Kappa_curve_options& options = {})
    : q_(std::move(points)), opt_(options) {
    solve(false, no_point);
  }

  /// Moves input point i to p and solves again, starting from the current solution (a local
  /// warm start around point i, then a global one, then a cold start if needed; the better of
  /// warm and cold is kept, report().warm_started says which).
  /// \throws Precondition_error if i >= points().size(); otherwise as the constructor, and then
  /// the curve is unchanged (strong guarantee).
  void move_point(std::size_t i, const Point_2& p) {
    internal::require(i < q_.size(), "Kappa_curve_2::move_point: index ", i, " >= number of points ", q_.size());
    const std::vector<Point_2> backup = q_;
    q_[i] = p;
    try {
      solve(true, i);
    } catch (...) {
      q_ = backup;
      throw;
    }
  }

  /// Replaces all points and solves again: warm-started from the current solution when the
  /// count is the same, a cold solve otherwise. \throws as the constructor, and then the curve
  /// is unchanged (strong guarantee, as move_point).
  void set_points(std::vector<Point_2> points) {
    const bool warm = points.size() == q_.size();
    q_.swap(points);  // points now holds the previous input
    try {
      solve(warm, no_point);
    } catch (...) {
      q_.swap(points);
      throw;
    }
  }

  /// The interpolated points, as given.
  const std::vector<Point_2>& points() const { return q_; }
  const Kappa_curve_options& options() const { return opt_; }
  bool is_closed() const { return opt_.closed; }
  /// The pieces in curve order: one per point of a closed curve, one per interior point of an
  /// open one (from points().front() to points().back()).
  const std::vector<Piece>& pieces() const { return pieces_; }
  std::size_t number_of_pieces() const { return pieces_.size(); }
  /// The curve in the exchange form (fair/Nurbs_curve_2.h; doc/nurbs.md, "Kappa_curve_2"): degree 2,
  /// piece j on [j, j + 1] (knots at the piece indices, each interior one of multiplicity 2: C0 in
  /// u, G1 and |kappa|-continuous by construction), control points P_{j,0}, P_{j,1}, ... with weights
  /// 1 at the joins and w_j between; rational unless every w_j is 1. Closed: the periodic form.
  /// point(j + t) is piece(j).point(t); exactly the pieces in an exact kernel. O(n).
  Nurbs_curve_2<K> nurbs() const {
    return internal::nurbs::bezier_pieces_nurbs<K>(pieces_, opt_.closed, "Kappa_curve_2::nurbs");
  }
  /// Piece j. \throws Precondition_error if j >= number_of_pieces().
  const Piece& piece(std::size_t j) const {
    internal::require(j < pieces_.size(), "Kappa_curve_2::piece: index ", j, " >= ", pieces_.size());
    return pieces_[j];
  }
  /// Index in points() of the point interpolated by piece j (j, or j+1 for an open curve).
  std::size_t point_index(std::size_t j) const { return opt_.closed ? j : j + 1; }
  /// t_j with c_j(t_j) = Q_{point_index(j)} (to the accuracy of the solve).
  /// \throws Precondition_error if j >= number_of_pieces() (also weight() and lambda()).
  double t(std::size_t j) const { check_piece(j, "t"); return st_.t[j]; }
  /// The weight w_j of piece j.
  double weight(std::size_t j) const { check_piece(j, "weight"); return st_.w[j]; }
  /// lambda_j of eq. 9 at the start of piece j (the join with piece j-1).
  /// \throws Precondition_error also for piece 0 of an open curve (its start is the fixed end point).
  double lambda(std::size_t j) const {
    check_piece(j, "lambda");
    internal::require(opt_.closed || j > 0, "Kappa_curve_2::lambda: piece 0 of an open curve has no join");
    return st_.lambda[j];
  }
  /// What the last solve did and reached.
  const Kappa_curve_report& report() const { return report_; }
  /// report().status: INTERIOR, ON_JOINS or UNSOLVED.
  Kappa_curve_status status() const { return report_.status; }

  /// The solver's unknowns at the solution (normalised offsets, lambda, t, w; one entry per
  /// piece): the exact parameters certify() rebuilds the curve from, and the start of the next
  /// warm solve. x_original = center + normalisation_scale() * x_normalised.
  const Kappa_solver_state& state() const { return st_; }
  /// The half size of the bounding box of points(), the unit of state()'s offsets and of the
  /// report's distances.
  double normalisation_scale() const { return normalisation_.scale; }

private:
  static constexpr std::size_t no_point = static_cast<std::size_t>(-1);

  void check_piece(std::size_t j, const char* fn) const {
    internal::require(j < pieces_.size(), "Kappa_curve_2::", fn, ": piece index ", j, " >= ", pieces_.size());
  }

  /// Solves for q_ and opt_ and commits the result only if nothing throws. `warm`: start from
  /// the current solution; `moved`: the only input point changed since the last solve (enables
  /// the local warm start), or no_point when unknown.
  void solve(bool warm, std::size_t moved) {
    namespace kp = internal::kappa;
    kp::check_curve_input<K>(q_, opt_);
    std::vector<double> x, y;
    const kp::Normalisation normalisation = kp::normalise(q_, x, y);
    const kp::Problem pb = kp::make_problem(x, y, opt_);
    const bool has_previous = warm && normalisation_.scale > 0;
    const Kappa_solver_state previous = has_previous ? kp::renormalised(st_, normalisation_, normalisation)
                                                     : Kappa_solver_state();
    Kappa_solver_state st;
    Kappa_curve_report report =
        kp::solve_with_warm_start(pb, has_previous ? &previous : nullptr, moved, kp::solve_settings(opt_), st);
    std::vector<Piece> pieces = kp::assemble_pieces<K>(pb, st, normalisation, q_);
    if (report.status == Kappa_curve_status::UNSOLVED && opt_.throw_on_failure)
      throw Solve_error(
          report.residual <= opt_.tolerance
              ? internal::message("Kappa_curve_2: unsolved: residual ", report.residual, " <= tolerance ",
                                  opt_.tolerance, " but points at a curvature minimum (", report, ")")
              : internal::message("Kappa_curve_2: unsolved after ", report.iterations, " iterations, residual ",
                                  report.residual, " > tolerance ", opt_.tolerance, " (", report, ")"),
          report);
    pieces_.swap(pieces);
    st_ = std::move(st);
    normalisation_ = normalisation;
    report_ = std::move(report);
  }

  std::vector<Point_2> q_;
  Kappa_curve_options opt_;
  std::vector<Piece> pieces_;
  Kappa_solver_state st_;
  internal::kappa::Normalisation normalisation_;
  Kappa_curve_report report_;
};

} // namespace fair

#endif // FAIR_KAPPA_CURVE_2_H
