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
// reproduce circles (Sec. 4.4, Sec. 8).
// Open curves (Sec. 6): the first and last points are the fixed end points; the interior
// points get one piece each. Closed curves: one piece per point, treated cyclically.
//
// Numerics: see include/fair/internal/kappa/solver.h. The data are translated and scaled to the
// box [-1,1]^2 before solving (so 1e+150 and 1e-150 coordinates behave like unit ones), the
// initial guess is Algorithm 1 of the paper, and the square system of eqs. 7, 10, 18 (and 16)
// is solved by Newton's method with a direct O(n) block LU (Levenberg-Marquardt as the fallback),
// O(n) per iteration. With unit or fixed
// weights the residual usually reaches 1e-12 (max norm of dimensionless residuals: distances in
// units of the half-size of the bounding box, eq. 7 divided by A+C, relative |kappa| mismatch);
// a solve that stops earlier is reported in report() (converged == false) -- and throws
// fair::Non_convergence_error when Kappa_curve_options::throw_on_non_convergence is set.
// In a floating kernel the pieces carry the rounding of the solve; fair::certify() (below)
// rebuilds the curve exactly from its rational lambda_i, t_i, w_i and certifies it (global exact
// fraction-free solve, O(n M(n)) bit operations per curve); fair::certify_pieces() certifies the returned pieces themselves in O(n) (their
// joins are formed from the rounded P_{i,1} in the kernel: exactly G1 in an exact kernel).

#ifndef FAIR_KAPPA_CURVE_2_H
#define FAIR_KAPPA_CURVE_2_H

#include <fair/Errors.h>
#include <fair/Kappa_certificate.h>
#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/internal/common/input_checks.h>
#include <fair/internal/kappa/certify.h>
#include <fair/internal/kappa/solver.h>
#include <fair/internal/common/exact_conversion.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <ostream>
#include <utility>
#include <vector>

namespace fair {

/// How the weights w_i of the middle control points are chosen.
enum class Kappa_weights {
  UNIT,      ///< w_i = 1: the polynomial kappa-curves (parabolic pieces)
  FIXED,     ///< w_i given per input point (Kappa_curve_options::fixed_weights)
  AUTOMATIC  ///< clamped minimum-eccentricity weights of eq. 16 (reproduce circles)
};

struct Kappa_curve_options {
  bool closed = false;
  Kappa_weights weights = Kappa_weights::UNIT;
  /// FIXED: one weight > 0 per input point (the entries of the two end points of an open curve
  /// are ignored).
  std::vector<double> fixed_weights;
  /// AUTOMATIC: tension mu_i > 0 per input point (eq. 16); empty means all 1.
  std::vector<double> tension;
  /// AUTOMATIC: lower clamp of eq. 16 (paper: 1/2, pieces of at most 120 degrees of a circle).
  double weight_clamp = 0.5;
  /// Cap on the alternating passes (Sec. 5.1; the paper uses 60): two before Newton's method,
  /// the rest (stopping once the residual is below 1e-3) only if Newton's method fails.
  std::size_t refinement_passes = 60;
  /// Cap on the iterations (Jacobians) of Newton's method and Levenberg-Marquardt together.
  std::size_t max_iterations = 200;
  /// Stop when the max-norm residual is at most this.
  double tolerance = 1e-12;
  /// Throw fair::Non_convergence_error instead of returning a non-converged curve.
  bool throw_on_non_convergence = false;
};

/// What a solve did and reached. Residuals are dimensionless (see the file comment).
struct Kappa_solve_report {
  bool converged = false;
  bool warm_started = false;
  std::size_t refinement_passes = 0;
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

template <class K>
class Kappa_curve_2 {
public:
  typedef K Kernel;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Rational_quadratic_bezier_2<K> Piece;

  /// Solves the kappa-curve through `points` (at least 3).
  /// \throws Invalid_input_error for too few points, NaN/inf coordinates, coincident
  /// consecutive points, all points collinear, bad weights/tension, or a solution with a
  /// degenerate (straight) piece; Non_convergence_error if requested in the options.
  explicit Kappa_curve_2(std::vector<Point_2> points, Kappa_curve_options options = Kappa_curve_options())
    : q_(std::move(points)), opt_(std::move(options)) {
    solve(false);
  }

  /// Moves input point i and solves again, starting from the current solution (warm start).
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

  /// Replaces all points (same count: warm start; otherwise a cold solve).
  void set_points(std::vector<Point_2> points) {
    const bool warm = points.size() == q_.size();
    q_ = std::move(points);
    solve(warm);
  }

  const std::vector<Point_2>& points() const { return q_; }
  const Kappa_curve_options& options() const { return opt_; }
  bool is_closed() const { return opt_.closed; }
  const std::vector<Piece>& pieces() const { return pieces_; }
  std::size_t number_of_pieces() const { return pieces_.size(); }
  const Piece& piece(std::size_t j) const {
    internal::require(j < pieces_.size(), "Kappa_curve_2::piece: index ", j, " >= ", pieces_.size());
    return pieces_[j];
  }
  /// Index in points() of the point interpolated by piece j (j, or j+1 for an open curve).
  std::size_t point_index(std::size_t j) const { return opt_.closed ? j : j + 1; }
  /// t_j with c_j(t_j) = Q_{point_index(j)} (to the accuracy of the solve).
  double t(std::size_t j) const { check_piece(j, "t"); return st_.t[j]; }
  /// The weight w_j of piece j.
  double weight(std::size_t j) const { check_piece(j, "weight"); return st_.w[j]; }
  /// lambda_j of eq. 9 at the start of piece j (the join with piece j-1).
  /// \throws Precondition_error for piece 0 of an open curve (its start is the fixed end point).
  double lambda(std::size_t j) const {
    check_piece(j, "lambda");
    internal::require(opt_.closed || j > 0, "Kappa_curve_2::lambda: piece 0 of an open curve has no join");
    return st_.lambda[j];
  }
  const Kappa_solve_report& report() const { return report_; }

  /// The internal state (normalised offsets, lambda, t, w) and the normalisation, for the
  /// certification and for tools. x_original = center + scale * x_normalised.
  const internal::kappa::State& state() const { return st_; }
  double normalisation_scale() const { return scale_; }

private:
  void check_piece(std::size_t j, const char* fn) const {
    internal::require(j < pieces_.size(), "Kappa_curve_2::", fn, ": piece index ", j, " >= ", pieces_.size());
  }

  void validate() const {
    const char* fn = "Kappa_curve_2";
    internal::common::check_interpolation_input(q_, 3, opt_.closed, fn);
    const std::size_t m = q_.size();
    if (opt_.weights == Kappa_weights::FIXED) {
      if (opt_.fixed_weights.size() != m)
        throw Invalid_input_error(internal::message(fn, ": FIXED weights need one weight per point (", m,
                                                    "), got ", opt_.fixed_weights.size()));
      for (std::size_t i = 0; i < m; ++i)
        if (!(std::isfinite(opt_.fixed_weights[i]) && opt_.fixed_weights[i] > 0))
          throw Invalid_input_error(internal::message(fn, ": weight ", i, " = ", opt_.fixed_weights[i],
                                                      " must be finite and > 0"));
    }
    if (opt_.weights == Kappa_weights::AUTOMATIC) {
      if (!opt_.tension.empty() && opt_.tension.size() != m)
        throw Invalid_input_error(internal::message(fn, ": tension needs one value per point (", m, "), got ",
                                                    opt_.tension.size()));
      for (std::size_t i = 0; i < opt_.tension.size(); ++i)
        if (!(std::isfinite(opt_.tension[i]) && opt_.tension[i] > 0))
          throw Invalid_input_error(internal::message(fn, ": tension ", i, " = ", opt_.tension[i],
                                                      " must be finite and > 0"));
      if (!(std::isfinite(opt_.weight_clamp) && opt_.weight_clamp > 0))
        throw Invalid_input_error(internal::message(fn, ": weight clamp ", opt_.weight_clamp,
                                                    " must be finite and > 0"));
    }
    internal::require(std::isfinite(opt_.tolerance) && opt_.tolerance >= 0, fn, ": tolerance ", opt_.tolerance,
                      " must be finite and >= 0");
    // All points collinear: every piece would be a segment, which is not a conic arc.
    std::size_t far = 1;
    double best = -1;
    const double x0 = CGAL::to_double(q_[0].x()), y0 = CGAL::to_double(q_[0].y());
    for (std::size_t i = 1; i < m; ++i) {
      const double d = std::abs(CGAL::to_double(q_[i].x()) - x0) + std::abs(CGAL::to_double(q_[i].y()) - y0);
      if (d > best) { best = d; far = i; }
    }
    bool collinear = true;
    const typename K::Orientation_2 orient = K().orientation_2_object();
    for (std::size_t i = 1; i < m && collinear; ++i)
      if (orient(q_[0], q_[far], q_[i]) != CGAL::COLLINEAR) collinear = false;
    if (collinear)
      throw Invalid_input_error(internal::message(
          fn, ": all ", m, " points are collinear (through (", x0, ", ", y0, ") and (", CGAL::to_double(q_[far].x()),
          ", ", CGAL::to_double(q_[far].y()), ")): a kappa-curve would consist of straight segments, which are not ",
          "conic pieces; use the polyline"));
  }

  /// `moved`: index of the only input point changed since the last solve (enables the local
  /// warm start of internal::kappa::solve), or q_.size() or more when unknown.
  void solve(bool warm, std::size_t moved = static_cast<std::size_t>(-1)) {
    validate();
    const std::size_t m = q_.size();
    namespace kp = internal::kappa;
    // Normalise to [-1,1]^2 (halves first: no overflow near DBL_MAX).
    double xmin = CGAL::to_double(q_[0].x()), xmax = xmin, ymin = CGAL::to_double(q_[0].y()), ymax = ymin;
    std::vector<double> x(m), y(m);
    for (std::size_t i = 0; i < m; ++i) {
      x[i] = CGAL::to_double(q_[i].x());
      y[i] = CGAL::to_double(q_[i].y());
      xmin = std::min(xmin, x[i]); xmax = std::max(xmax, x[i]);
      ymin = std::min(ymin, y[i]); ymax = std::max(ymax, y[i]);
    }
    const double cx = 0.5 * xmin + 0.5 * xmax, cy = 0.5 * ymin + 0.5 * ymax;
    const double scale = std::max(0.5 * xmax - 0.5 * xmin, 0.5 * ymax - 0.5 * ymin);
    if (!(scale > 0) || !std::isfinite(scale))
      throw Invalid_input_error(internal::message("Kappa_curve_2: degenerate bounding box (half size ", scale, ")"));
    for (std::size_t i = 0; i < m; ++i) {
      x[i] = (x[i] - cx) / scale;
      y[i] = (y[i] - cy) / scale;
    }
    kp::Problem pb;
    pb.closed = opt_.closed;
    const std::size_t first = opt_.closed ? 0 : 1;
    pb.n = opt_.closed ? m : m - 2;
    pb.qx.assign(x.begin() + first, x.begin() + first + pb.n);
    pb.qy.assign(y.begin() + first, y.begin() + first + pb.n);
    if (!opt_.closed) { pb.sx = x[0]; pb.sy = y[0]; pb.ex = x[m - 1]; pb.ey = y[m - 1]; }
    pb.clamp = opt_.weight_clamp;
    switch (opt_.weights) {
      case Kappa_weights::UNIT: pb.mode = kp::Weight_mode::UNIT; break;
      case Kappa_weights::FIXED:
        pb.mode = kp::Weight_mode::FIXED;
        pb.weight.assign(opt_.fixed_weights.begin() + first, opt_.fixed_weights.begin() + first + pb.n);
        break;
      case Kappa_weights::AUTOMATIC:
        pb.mode = kp::Weight_mode::AUTOMATIC;
        if (opt_.tension.empty()) pb.tension.assign(pb.n, 1.0);
        else pb.tension.assign(opt_.tension.begin() + first, opt_.tension.begin() + first + pb.n);
        break;
    }
    kp::Solve_settings settings;
    settings.refinement_passes = opt_.refinement_passes;
    settings.max_iterations = opt_.max_iterations;
    settings.tolerance = opt_.tolerance;
    kp::State st;
    kp::Solve_result res;
    bool warm_used = false;
    if (warm && st_.t.size() == pb.n && scale_ > 0) {
      st = st_;
      const double f = scale_ / scale;  // offsets d_i are relative to Q_i: only the scale changes
      for (std::size_t i = 0; i < pb.n; ++i) { st.dx[i] *= f; st.dy[i] *= f; }
      settings.warm = true;
      if (moved < m) {  // block of input point `moved`; an open curve's end points belong to its end pieces
        settings.moved = opt_.closed ? moved : std::min(std::max<std::size_t>(moved, 1) - 1, pb.n - 1);
      }
      res = kp::solve(pb, st, settings);
      settings.moved = static_cast<std::size_t>(-1);
      warm_used = true;
      if (!res.converged) {  // fall back to a cold start, keep the better of the two
        kp::State cold;
        settings.warm = false;
        const kp::Solve_result res2 = kp::solve(pb, cold, settings);
        if (res2.residual < res.residual) { st = cold; res = res2; warm_used = false; }
      }
    } else {
      res = kp::solve(pb, st, settings);
    }
    std::vector<Piece> pieces;
    pieces.reserve(pb.n);
    auto to_point = [&](double px, double py) { return Point_2(FT(cx) + FT(scale) * FT(px), FT(cy) + FT(scale) * FT(py)); };
    // The middle control points P_j (rounded to the kernel), then the joins E_j of eq. 9
    // computed FROM them in the kernel's arithmetic: in an exact kernel the returned pieces are
    // exactly G1 (E_j on the segment P_{j-1} P_j), which certify_pieces() verifies piece by piece.
    std::vector<Point_2> Pm(pb.n), E(pb.n + 1);
    for (std::size_t j = 0; j < pb.n; ++j) Pm[j] = to_point(pb.qx[j] + st.dx[j], pb.qy[j] + st.dy[j]);
    for (std::size_t j = 0; j < pb.n; ++j) {
      if (!pb.has_start(j)) { E[j] = q_[0]; continue; }
      const Point_2& A = Pm[(j + pb.n - 1) % pb.n];
      const FT l(st.lambda[j]), ml = FT(1) - l;
      E[j] = Point_2(ml * A.x() + l * Pm[j].x(), ml * A.y() + l * Pm[j].y());
    }
    E[pb.n] = opt_.closed ? E[0] : q_[m - 1];
    for (std::size_t j = 0; j < pb.n; ++j) {
      const Point_2& P = Pm[j];
      const Point_2& A = E[j];
      const Point_2& B = E[j + 1];
      const double w = st.w[j];
      if (!(std::isfinite(w) && w > 0) || A == B || K().orientation_2_object()(A, P, B) == CGAL::COLLINEAR)
        throw Invalid_input_error(internal::message(
            "Kappa_curve_2: the piece through point ", point_index(j), " = (", CGAL::to_double(q_[point_index(j)].x()),
            ", ", CGAL::to_double(q_[point_index(j)].y()), ") degenerates to a straight segment (its control points are ",
            "collinear); the input is locally collinear"));
      pieces.emplace_back(A, P, B, FT(w));
    }
    Kappa_solve_report rep;
    rep.converged = res.converged;
    rep.warm_started = warm_used;
    rep.refinement_passes = res.refinement_passes;
    rep.iterations = res.iterations;
    rep.residual = res.residual;
    rep.interpolation_residual = res.interpolation_residual;
    rep.curvature_residual = res.curvature_residual;
    rep.g2_residual = res.g2_residual;
    rep.weight_residual = res.weight_residual;
    rep.energy_interpolation = res.energy_interpolation;
    rep.energy_curvature = res.energy_curvature;
    rep.energy_g2 = res.energy_g2;
    rep.energy_weight = res.energy_weight;
    rep.bounds_active = res.bounds_active;
    for (const std::size_t b : res.boundary_blocks) rep.boundary_points.push_back(point_index(b));
    if (!rep.converged && opt_.throw_on_non_convergence)
      throw Non_convergence_error(internal::message("Kappa_curve_2: no convergence after ", rep.iterations,
                                                    " iterations, residual ", rep.residual, " > tolerance ",
                                                    opt_.tolerance, " (", rep, ")"),
                                  rep.iterations, rep.residual);
    pieces_.swap(pieces);
    st_ = st;
    scale_ = scale;
    center_x_ = cx;
    center_y_ = cy;
    report_ = rep;
  }

  std::vector<Point_2> q_;
  Kappa_curve_options opt_;
  std::vector<Piece> pieces_;
  internal::kappa::State st_;
  double scale_ = 0, center_x_ = 0, center_y_ = 0;
  Kappa_solve_report report_;
};


/// Certifies `curve` exactly (see internal/kappa/certify.h): the exact curve defined by the
/// solver's rational lambda_i, t_i, w_i and the exact input points. Cost: O(n) products of
/// O(n)-bit numbers per curve (the exact control points have ~150 n bits); measured 0.07 ms per
/// piece for closed curves of 20 pieces and 0.54 ms for 100 (see doc/kappa_curves.md). The
/// parameters of a Kappa_curve_2 satisfy 0 < lambda_i, t_i < 1 and w_i > 0; outside that the
/// exact eq.-18 elimination can meet a zero pivot and throws (internal::kappa::certify_parameters).
template <class K>
Kappa_certificate certify(const Kappa_curve_2<K>& curve) {
  return internal::kappa::certify_curve(curve, internal::kappa::Certify_mode::FILTERED);
}

/// Certifies the pieces that `curve` returns, piece by piece in O(n): their exact control
/// points (in an exact kernel: P_j the solver's rounded P_{j,1}, E_j = (1 - lambda_j) P_{j-1} +
/// lambda_j P_j formed exactly, so C0 and G1 hold exactly by construction and are verified),
/// the parameters t_j, and the exact input points. What is certified, exactly or by outward
/// rounded intervals: C0 and G1 at every join; |c_j(t_j) - Q_j| <= interpolation_error (not 0:
/// the P_j carry the rounding of the solve, ~1e-16 relative); the number and kind of curvature
/// extrema of each piece and the distance of the nearest one to t_j; the relative |kappa|
/// mismatch at each join. Use Kappa_certificate::valid_within(). With a floating-point kernel
/// the pieces' E_j are rounded, and G1 generally fails exactly (as it is reported).
template <class K>
Kappa_certificate certify_pieces(const Kappa_curve_2<K>& curve) {
  return internal::kappa::certify_returned_pieces(curve);
}

} // namespace fair

#endif // FAIR_KAPPA_CURVE_2_H
