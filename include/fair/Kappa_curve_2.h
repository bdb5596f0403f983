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


/// The exact certificate of a kappa-curve, see certify().
struct Kappa_certificate {
  typedef CGAL::Simple_cartesian<CGAL::Gmpq> Exact_kernel;
  struct Piece {
    std::size_t point_index = 0;
    bool valid_piece = false;      ///< exact control points not collinear (a genuine conic arc)
    bool point_on_piece = false;   ///< Q_i == c_i(t_i) exactly
    /// Certified upper bound on |c_i(t_i) - Q_i| (0 when point_on_piece; infinity if not valid).
    double interpolation_error = std::numeric_limits<double>::infinity();
    std::size_t extrema = 0;       ///< certified curvature extrema in (0,1) (roots of eq. 4)
    std::size_t maxima = 0;        ///< of which maxima of |kappa|
    bool unique_maximum = false;   ///< exactly one root in (0,1) and it is a maximum
    double t = 0;                  ///< t_i (its exact value is this double)
    /// The certified extremum nearest to t_i: its kind, isolating interval (outward rounded)
    /// and an upper bound on |root - t_i| (infinity when the piece has no extremum). With
    /// w_i < 1 (automatic weights) Q_i can be a curvature minimum (Sec. 3.2): kind says so.
    bool has_extremum_at_t = false;
    Curvature_extremum_kind kind_at_t = Curvature_extremum_kind::MAXIMUM;
    double root_lower = 0, root_upper = 0;
    double root_distance = std::numeric_limits<double>::infinity();
  };
  struct Join {
    std::size_t piece = 0;         ///< the join at the start of this piece
    bool c0 = false;               ///< both pieces share the exact point
    bool g1 = false;               ///< P_{i-1}, E_i, P_i exactly collinear, E_i strictly between
    double kappa_mismatch_lower = 0, kappa_mismatch_upper = 0;  ///< (|k1|-|k2|)/(|k1|+|k2|) enclosure
  };
  std::vector<Piece> pieces;
  std::vector<Join> joins;
  std::vector<Rational_quadratic_bezier_2<Exact_kernel>> exact_pieces;

  bool all_points_on_pieces() const { for (const Piece& p : pieces) if (!p.point_on_piece) return false; return true; }
  bool all_unique_maxima() const { for (const Piece& p : pieces) if (!p.unique_maximum) return false; return true; }
  bool all_g1() const { for (const Join& j : joins) if (!(j.c0 && j.g1)) return false; return true; }
  /// Largest certified upper bound on |c_i(t_i) - Q_i| over the pieces.
  double max_interpolation_error() const {
    double m = 0;
    for (const Piece& p : pieces) m = std::max(m, p.interpolation_error);
    return m;
  }
  /// As valid(), but interpolation only up to `interpolation_tolerance` (absolute, in the
  /// curve's coordinates): the criterion for certify_pieces(), whose pieces pass through the
  /// Q_i up to the rounding of the solver's P_i.
  bool valid_within(double interpolation_tolerance, double kappa_tolerance = 1e-9, double t_tolerance = 1e-9) const {
    return max_interpolation_error() <= interpolation_tolerance && all_unique_maxima() && all_g1() &&
           max_kappa_mismatch() <= kappa_tolerance && max_root_distance() <= t_tolerance;
  }
  /// Largest |relative |kappa| mismatch| over the joins (certified upper bound).
  double max_kappa_mismatch() const {
    double m = 0;
    for (const Join& j : joins) m = std::max(m, std::max(std::abs(j.kappa_mismatch_lower), std::abs(j.kappa_mismatch_upper)));
    return m;
  }
  /// Largest distance from t_i to the nearest certified curvature extremum (infinity if a piece
  /// has none).
  double max_root_distance() const { double m = 0; for (const Piece& p : pieces) m = std::max(m, p.root_distance); return m; }
  /// Number of pieces whose Q_i is a certified curvature minimum rather than a maximum.
  std::size_t minima_at_points() const {
    std::size_t k = 0;
    for (const Piece& p : pieces) k += p.has_extremum_at_t && p.kind_at_t == Curvature_extremum_kind::MINIMUM;
    return k;
  }
  /// Everything exact holds and |kappa| matches within `kappa_tolerance` and each maximum lies
  /// within `t_tolerance` of t_i.
  bool valid(double kappa_tolerance = 1e-9, double t_tolerance = 1e-9) const {
    return all_points_on_pieces() && all_unique_maxima() && all_g1() && max_kappa_mismatch() <= kappa_tolerance &&
           max_root_distance() <= t_tolerance;
  }
  friend std::ostream& operator<<(std::ostream& out, const Kappa_certificate& c) {
    out << "Kappa_certificate{pieces " << c.pieces.size() << ", Q_i on pieces " << c.all_points_on_pieces()
        << ", unique maxima " << c.all_unique_maxima() << ", G1 " << c.all_g1() << ", max |kappa| mismatch <= "
        << c.max_kappa_mismatch() << ", max |root - t_i| <= " << c.max_root_distance() << "}";
    for (const Piece& p : c.pieces)
      if (!(p.point_on_piece && p.unique_maximum))
        out << "\n  piece for point " << p.point_index << ": valid " << p.valid_piece << ", on piece "
            << p.point_on_piece << ", extrema " << p.extrema << ", maxima " << p.maxima << ", nearest extremum "
            << (p.has_extremum_at_t ? to_string(p.kind_at_t) : "none") << " at distance <= " << p.root_distance;
    return out;
  }
};

namespace internal {
namespace kappa {

/// How certify_* decide: FILTERED runs the filters first -- eq4_filtered_extremum for the
/// curvature extrema (exact isolation only where it is undecided), the interval sign of the
/// control triangle's area, and the exact but cheap G1 identity E_j - P_{j-1} == lambda_j
/// (P_j - P_{j-1}) -- with the exact predicates as fallback; EXACT always runs the exact
/// predicates and Rational_quadratic_bezier_2::curvature_extrema (for tests of the filters).
enum class Certify_mode { FILTERED, EXACT };

/// The exact per-piece and per-join checks of certify() and certify_pieces() on exact pieces
/// (E_j, P_j, E_{j+1}, w_j) of the curve scaled by a positive factor rho (E has n+1 entries,
/// E[n] == E[0] for closed curves) with parameters t_j and scaled points Q_j = rho * Q_i. All
/// checks are invariant under the scaling; a nonzero interpolation distance is multiplied by
/// inverse_scale_upper >= 1/rho. Fills pieces and joins (joins only when every piece is valid);
/// `exact_pieces` is left to the caller. O(n) pieces of bounded work each, plus the arithmetic
/// on the given numbers (dyadic rationals in certify(): no big gcds).
inline void certify_scaled(bool closed, const std::vector<std::size_t>& point_index,
                           const std::vector<Kappa_certificate::Exact_kernel::Point_2>& E,
                           const std::vector<Kappa_certificate::Exact_kernel::Point_2>& P,
                           const std::vector<CGAL::Gmpq>& w, const std::vector<double>& tt,
                           const std::vector<Kappa_certificate::Exact_kernel::Point_2>& Qp,
                           double inverse_scale_upper, Certify_mode mode, Kappa_certificate& cert,
                           const std::vector<double>* lambda = nullptr) {
  typedef CGAL::Gmpq Q;
  typedef Kappa_certificate::Exact_kernel EK;
  typedef CGAL::Interval_nt<false> I;
  const std::size_t n = P.size();
  const EK::Orientation_2 orient;
  auto iv = [](const Q& q) { const std::pair<double, double> x = CGAL::to_interval(q); return I(x.first, x.second); };
  std::vector<I> ex(n + 1), ey(n + 1), px(n), py(n), wi(n);
  for (std::size_t j = 0; j <= n; ++j) { ex[j] = iv(E[j].x()); ey[j] = iv(E[j].y()); }
  for (std::size_t j = 0; j < n; ++j) { px[j] = iv(P[j].x()); py[j] = iv(P[j].y()); wi[j] = iv(w[j]); }
  cert.pieces.clear();
  cert.joins.clear();
  bool all_valid = true;
  for (std::size_t j = 0; j < n; ++j) {
    Kappa_certificate::Piece pc;
    pc.point_index = point_index[j];
    pc.t = tt[j];
    // Not collinear: decided by the interval determinant when its sign is certain, else exactly.
    int area_sign = 0;
    if (mode == Certify_mode::FILTERED) {
      CGAL::Protect_FPU_rounding<true> guard;
      const I det = (px[j] - ex[j]) * (ey[j + 1] - ey[j]) - (py[j] - ey[j]) * (ex[j + 1] - ex[j]);
      area_sign = det.inf() > 0 ? 1 : (det.sup() < 0 ? -1 : 0);
    }
    pc.valid_piece = w[j] > 0 && E[j] != E[j + 1] &&
                     (area_sign != 0 || orient(E[j], P[j], E[j + 1]) != CGAL::COLLINEAR);
    if (pc.valid_piece) {
      // c_j(t_j) == Q_j  <=>  (1-t)^2 E_j + 2 (1-t) t w P_j + t^2 E_{j+1} == W(t) Q_j  (eq. 1)
      const Q t(tt[j]), u = Q(1) - t, c0 = u * u, c1 = Q(2) * u * t * w[j], c2 = t * t, D = c0 + c1 + c2;
      const Q cx = c0 * E[j].x() + c1 * P[j].x() + c2 * E[j + 1].x();
      const Q cy = c0 * E[j].y() + c1 * P[j].y() + c2 * E[j + 1].y();
      pc.point_on_piece = cx == D * Qp[j].x() && cy == D * Qp[j].y();
      if (pc.point_on_piece) {
        pc.interpolation_error = 0;
      } else {  // certified upper bound of the distance: sqrt of an upper bound, rounded up
        const EK::Point_2 c(cx / D, cy / D);
        const double d2 = CGAL::to_interval(CGAL::squared_distance(c, Qp[j])).second;
        pc.interpolation_error = std::nextafter(std::nextafter(std::sqrt(d2), std::numeric_limits<double>::infinity()) *
                                                    inverse_scale_upper, std::numeric_limits<double>::infinity());
      }
      int fast = -1;
      if (mode == Certify_mode::FILTERED) {
        const I xy[6] = {ex[j], ey[j], px[j], py[j], ex[j + 1], ey[j + 1]};
        Curvature_extremum_kind kind = Curvature_extremum_kind::MAXIMUM;
        double lo = 0, hi = 0, dist = 0;
        fast = eq4_filtered_extremum(xy, wi[j], tt[j], kind, lo, hi, dist);
        if (fast == 1) {
          pc.extrema = 1;
          pc.maxima = kind == Curvature_extremum_kind::MAXIMUM ? 1 : 0;
          pc.has_extremum_at_t = true;
          pc.kind_at_t = kind;
          pc.root_lower = lo;
          pc.root_upper = hi;
          pc.root_distance = dist;
        }
      }
      if (fast == -1) {
        // Exact certified isolation (with its own interval fast path) on the exact piece.
        const Rational_quadratic_bezier_2<EK> piece(E[j], P[j], E[j + 1], w[j]);
        const std::vector<Curvature_extremum> ext = piece.curvature_extrema();
        pc.extrema = ext.size();
        for (const Curvature_extremum& x : ext) {
          if (x.kind == Curvature_extremum_kind::MAXIMUM) ++pc.maxima;
          const Q d = std::max(CGAL::abs(t - x.t_lower), CGAL::abs(x.t_upper - t));
          const double dd = CGAL::to_interval(d).second;
          if (dd < pc.root_distance) {
            pc.root_distance = dd;
            pc.has_extremum_at_t = true;
            pc.kind_at_t = x.kind;
            pc.root_lower = CGAL::to_interval(x.t_lower).first;
            pc.root_upper = CGAL::to_interval(x.t_upper).second;
          }
        }
      }
      pc.unique_maximum = pc.extrema == 1 && pc.maxima == 1 && pc.kind_at_t == Curvature_extremum_kind::MAXIMUM;
    } else {
      all_valid = false;
    }
    cert.pieces.push_back(pc);
  }
  if (!all_valid) {
    // Some piece is not a valid conic piece: nothing is certified at the joins (reported as not
    // G1, mismatch unknown), so that all_g1() and max_kappa_mismatch() cannot read as success.
    for (std::size_t j = (closed ? 0 : 1); j < n; ++j) {
      Kappa_certificate::Join jn;
      jn.piece = j;
      jn.c0 = jn.g1 = false;
      jn.kappa_mismatch_lower = -std::numeric_limits<double>::infinity();
      jn.kappa_mismatch_upper = std::numeric_limits<double>::infinity();
      cert.joins.push_back(jn);
    }
    return;
  }
  for (std::size_t j = (closed ? 0 : 1); j < n; ++j) {
    const std::size_t a = (j + n - 1) % n;
    Kappa_certificate::Join jn;
    jn.piece = j;
    jn.c0 = true;  // set by the caller from the exact pieces
    // G1: P_{a}, E_j, P_j collinear with E_j strictly between. Sufficient and cheap (no product
    // of two long numbers): E_j - P_a == lambda_j (P_j - P_a) exactly with 0 < lambda_j < 1 and
    // P_a != P_j; otherwise the exact orientation and order decide.
    bool g1 = false;
    if (mode == Certify_mode::FILTERED && lambda != nullptr && (*lambda)[j] > 0 && (*lambda)[j] < 1 && P[a] != P[j]) {
      const Q l((*lambda)[j]);
      g1 = E[j].x() - P[a].x() == l * (P[j].x() - P[a].x()) && E[j].y() - P[a].y() == l * (P[j].y() - P[a].y());
    }
    jn.g1 = g1 || (orient(P[a], E[j], P[j]) == CGAL::COLLINEAR &&
                   CGAL::collinear_are_strictly_ordered_along_line(P[a], E[j], P[j]));
    const I A[2] = {ex[a], ey[a]}, Pa[2] = {px[a], py[a]}, Ej[2] = {ex[j], ey[j]}, Pj[2] = {px[j], py[j]};
    const I B[2] = {ex[j + 1], ey[j + 1]};
    relative_mismatch_interval(A, Pa, Ej, Pj, B, wi[a], wi[j], jn.kappa_mismatch_lower, jn.kappa_mismatch_upper);
    cert.joins.push_back(jn);
  }
}

/// Builds cert.exact_pieces from the exact control points (E_j, P_j, E_{j+1}) and weights of the
/// valid pieces and records C0 at the joins on them (true by construction when neighbouring
/// pieces are built from the same E_j; a check of the assembled curve, not a proof of more).
inline void attach_exact_pieces(const std::vector<Kappa_certificate::Exact_kernel::Point_2>& E,
                                const std::vector<Kappa_certificate::Exact_kernel::Point_2>& P,
                                const std::vector<CGAL::Gmpq>& w, Kappa_certificate& cert) {
  const std::size_t n = P.size();
  for (std::size_t j = 0; j < n; ++j)
    if (cert.pieces[j].valid_piece) cert.exact_pieces.emplace_back(E[j], P[j], E[j + 1], w[j]);
  if (cert.exact_pieces.size() == n)
    for (Kappa_certificate::Join& jn : cert.joins)
      jn.c0 = cert.exact_pieces[(jn.piece + n - 1) % n].target() == cert.exact_pieces[jn.piece].source();
}

/// certify_scaled on unscaled pieces, plus exact_pieces built from them (and C0 recorded).
inline Kappa_certificate certify_exact(bool closed, const std::vector<std::size_t>& point_index,
                                       const std::vector<Kappa_certificate::Exact_kernel::Point_2>& E,
                                       const std::vector<Kappa_certificate::Exact_kernel::Point_2>& P,
                                       const std::vector<CGAL::Gmpq>& w, const std::vector<double>& tt,
                                       const std::vector<Kappa_certificate::Exact_kernel::Point_2>& Qp,
                                       Certify_mode mode = Certify_mode::FILTERED,
                                       const std::vector<double>* lambda = nullptr) {
  Kappa_certificate cert;
  certify_scaled(closed, point_index, E, P, w, tt, Qp, 1.0, mode, cert, lambda);
  attach_exact_pieces(E, P, w, cert);
  return cert;
}

/// The certificate of the exact curve defined by exact points (qx, qy) (and end points s, e of
/// an open curve) and the rational parameters lambda, t, w (doubles, exact): eq. 18 solved
/// exactly and fraction-free (exact_eq18_integer), checks on the dyadic scaled curve
/// (certify_scaled), exact_pieces in original coordinates. lambda[0] is ignored for open curves.
inline Kappa_certificate certify_parameters(bool closed, const std::vector<std::size_t>& point_index,
                                            const std::vector<CGAL::Gmpq>& qx, const std::vector<CGAL::Gmpq>& qy,
                                            const CGAL::Gmpq& sx, const CGAL::Gmpq& sy, const CGAL::Gmpq& ex,
                                            const CGAL::Gmpq& ey, const std::vector<double>& lambda_d,
                                            const std::vector<double>& t_d, const std::vector<double>& w_d,
                                            Certify_mode mode = Certify_mode::FILTERED) {
  typedef CGAL::Gmpq Q;
  typedef Kappa_certificate::Exact_kernel EK;
  typedef EK::Point_2 EP;
  const std::size_t n = qx.size();
  std::vector<Q> lam(n), t(n), w(n);
  for (std::size_t j = 0; j < n; ++j) {
    lam[j] = Q(closed || j > 0 ? lambda_d[j] : 0.5);
    t[j] = Q(t_d[j]);
    w[j] = Q(w_d[j]);
  }
  std::vector<Certify_int> Nx, Ny;
  Certify_int Delta;
  exact_eq18_integer(closed, qx, qy, sx, sy, ex, ey, lam, t, w, Nx, Ny, Delta);
  // Scaled curve rho * c, rho = Delta / 2^s in [1, 2): P~_j = N_j / 2^s (dyadic, canonical by
  // mpq_div_2exp), E~_j by eq. 9 from them, Q~ = rho Q.
  const mp_bitcnt_t s = mpz_sizeinbase(Delta.v, 2) - 1;
  auto dyadic = [s](const Certify_int& z) {
    mpq_t q;
    mpq_init(q);
    mpz_set(mpq_numref(q), z.v);
    mpq_div_2exp(q, q, s);
    Q r(q);
    mpq_clear(q);
    return r;
  };
  Q rho;
  {
    Certify_int one;
    mpz_set(one.v, Delta.v);
    rho = dyadic(one);
  }
  std::vector<EP> Ps(n), Es(n + 1), Qs(n);
  for (std::size_t j = 0; j < n; ++j) {
    Ps[j] = EP(dyadic(Nx[j]), dyadic(Ny[j]));
    Qs[j] = EP(rho * qx[j], rho * qy[j]);
  }
  for (std::size_t j = 0; j < n; ++j) {
    if (!closed && j == 0) { Es[0] = EP(rho * sx, rho * sy); continue; }
    const std::size_t a = (j + n - 1) % n;
    const Q ml = Q(1) - lam[j];
    Es[j] = EP(ml * Ps[a].x() + lam[j] * Ps[j].x(), ml * Ps[a].y() + lam[j] * Ps[j].y());
  }
  Es[n] = closed ? Es[0] : EP(rho * ex, rho * ey);
  Kappa_certificate cert;
  // rho >= 1, so 1 is an upper bound of 1/rho for the interpolation distance.
  certify_scaled(closed, point_index, Es, Ps, w, t_d, Qs, 1.0, mode, cert, &lambda_d);
  // exact_pieces in original coordinates, canonical Gmpq (canonical_fractions: one big gcd).
  // P_j = N_j / Delta, E_j = ((2^k - l) N_{j-1} + l N_j) / (2^k Delta) for lambda_j = l / 2^k.
  std::vector<Certify_int> Ex(n), Ey(n);
  std::vector<const Certify_int*> X;
  std::vector<mp_bitcnt_t> e;
  for (std::size_t j = 0; j < n; ++j) {
    X.push_back(&Nx[j]); X.push_back(&Ny[j]);
    e.push_back(0); e.push_back(0);
  }
  for (std::size_t j = (closed ? 0 : 1); j < n; ++j) {
    const std::size_t a = (j + n - 1) % n;
    const mpz_srcptr l = mpq_numref(lam[j].mpq()), den = mpq_denref(lam[j].mpq());  // den = 2^k
    const mp_bitcnt_t k = mpz_sizeinbase(den, 2) - 1;
    Certify_int ml;
    mpz_sub(ml.v, den, l);
    mpz_mul(Ex[j].v, ml.v, Nx[a].v);
    mpz_addmul(Ex[j].v, l, Nx[j].v);
    mpz_mul(Ey[j].v, ml.v, Ny[a].v);
    mpz_addmul(Ey[j].v, l, Ny[j].v);
    X.push_back(&Ex[j]); X.push_back(&Ey[j]);
    e.push_back(k); e.push_back(k);
  }
  const std::vector<Q> F = canonical_fractions(X, e, Delta);
  std::vector<EP> Po(n), Eo(n + 1);
  for (std::size_t j = 0; j < n; ++j) Po[j] = EP(F[2 * j], F[2 * j + 1]);
  if (!closed) Eo[0] = EP(sx, sy);
  for (std::size_t j = (closed ? 0 : 1), r = 2 * n; j < n; ++j, r += 2) Eo[j] = EP(F[r], F[r + 1]);
  Eo[n] = closed ? Eo[0] : EP(ex, ey);
  attach_exact_pieces(Eo, Po, w, cert);
  return cert;
}

/// The exact inputs of certify(curve) for certify_parameters.
template <class K>
Kappa_certificate certify_curve(const Kappa_curve_2<K>& curve, Certify_mode mode) {
  typedef CGAL::Gmpq Q;
  const internal::kappa::State& st = curve.state();
  const std::size_t n = curve.number_of_pieces(), m = curve.points().size();
  const bool closed = curve.is_closed();
  std::vector<Q> qx(n), qy(n);
  std::vector<std::size_t> index(n);
  for (std::size_t j = 0; j < n; ++j) {
    index[j] = curve.point_index(j);
    const auto& q = curve.points()[index[j]];
    qx[j] = internal::common::to_gmpq(q.x());
    qy[j] = internal::common::to_gmpq(q.y());
  }
  Q sx(0), sy(0), ex(0), ey(0);
  if (!closed) {
    sx = internal::common::to_gmpq(curve.points()[0].x()); sy = internal::common::to_gmpq(curve.points()[0].y());
    ex = internal::common::to_gmpq(curve.points()[m - 1].x()); ey = internal::common::to_gmpq(curve.points()[m - 1].y());
  }
  return certify_parameters(closed, index, qx, qy, sx, sy, ex, ey, st.lambda, st.t, st.w, mode);
}

} // namespace kappa
} // namespace internal

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
  typedef Kappa_certificate::Exact_kernel EK;
  typedef EK::Point_2 EP;
  const std::size_t n = curve.number_of_pieces();
  auto ex = [](const typename K::Point_2& p) { return EP(internal::common::to_gmpq(p.x()), internal::common::to_gmpq(p.y())); };
  std::vector<EP> E(n + 1), P(n), Qp(n);
  std::vector<CGAL::Gmpq> w(n);
  std::vector<double> t(n);
  std::vector<std::size_t> index(n);
  for (std::size_t j = 0; j < n; ++j) {
    const auto& pc = curve.piece(j);
    E[j] = ex(pc.control_point(0));
    P[j] = ex(pc.control_point(1));
    w[j] = internal::common::to_gmpq(pc.weight());
    t[j] = curve.t(j);
    index[j] = curve.point_index(j);
    Qp[j] = ex(curve.points()[index[j]]);
  }
  E[n] = ex(curve.piece(n - 1).control_point(2));
  return internal::kappa::certify_exact(curve.is_closed(), index, E, P, w, t, Qp,
                                        internal::kappa::Certify_mode::FILTERED, &curve.state().lambda);
}

} // namespace fair

#endif // FAIR_KAPPA_CURVE_2_H
