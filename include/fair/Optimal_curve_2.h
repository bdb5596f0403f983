// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Gumhold's optimal curves (issue 11; S. Gumhold, "Designing optimal curves in 2D", Sec. 2.3-3.3):
// the interpolating polygon that minimises the scale-invariant functional of eq. 5,
//   F(c) = int beta + beta_0 |kappa L0|^alpha_0 + sum_k beta_k |kappa^(k) L0^(k+1)|^alpha_k ds,
// with TRUE curvature (the paper's eq. 9 is half of it, doc/optimal_curves.md), computed by a
// hierarchical, adaptive Newton method on the normal offsets of the free vertices
// (doc/optimal_curves.md). Points -> solver on doubles -> polygon in the user's kernel -> the C2
// cubic smoothing spline with a knot at every polygon vertex, through the input points exactly and
// within 0.9 of the polygon's resolution of the other vertices (fair::fit_smoothing_spline_runs: C2
// between CORNER constraints, G0 at them; issue 25 §3), whose cubic Bezier pieces are pieces().

#ifndef FAIR_OPTIMAL_CURVE_2_H
#define FAIR_OPTIMAL_CURVE_2_H

#include <fair/Bezier_2.h>
#include <fair/Errors.h>
#include <fair/Optimal_curve_options.h>
#include <fair/Optimal_curve_report.h>
#include <fair/Polygon_spline_fit.h>
#include <fair/internal/optimal/hierarchy.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace fair {

// fair::optimal_spline_distance_fraction (0.9 of the resolution): internal/spline/smoothing_runs.h,
// shared with the hierarchy, which refines the polygon until the spline can keep it.

/// The optimal curve through `points` (closed: no repeated last point): the optimal polygon and
/// the C2 cubic smoothing spline of it through the points (pieces(), spline()).
/// Errors: Invalid_input_error for too few points (< 2 open, < 3 closed), non-finite or
/// coincident consecutive points (or closer than 2^-40 of the data's chord length: the spline
/// fits of the polygon fail a few ulps of the length, and this keeps a margin of about 2^13;
/// internal::optimal::resolved_edge_fraction), constraints out of range / with a zero direction / that cannot
/// be met, data at an extent whose energy or curvatures overflow double (near 1e308 or 1e-308:
/// the message names the value at unit extent and the extent); Precondition_error for options outside their domain (negative or non-finite weights,
/// all of beta, beta_0, beta_k zero, lambda outside [0, 1], exponents < 1, resolution <= 0).
/// A solve that diverges or hits a cap does not throw unless options.throw_on_failure is set
/// (then Solve_error carrying the report): report().status says so.
/// Complexity: O(n w^2) per Newton step (banded Hessian, w = max k + 2), n = finest vertices;
/// the spline O(n).
template <class K>
class Optimal_curve_2 {
public:
  typedef K Kernel;
  typedef Optimal_curve_options Options;
  typedef Optimal_curve_report Report;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  /// The cubic Bezier pieces of spline(), one per polygon edge.
  typedef Bezier_2<K> Piece;
  /// The C2 cubic spline runs of the polygon (one run without CORNER constraints).
  typedef Polygon_spline_runs<K> Spline;

  /// Solves for the optimal polygon through `points`, then fits spline() through it.
  /// \throws as the class comment says.
  explicit Optimal_curve_2(const std::vector<Point_2>& points, const Optimal_curve_options& options = {})
    : points_(points), options_(options) {
    std::vector<internal::optimal::Vec2> p;
    p.reserve(points.size());
    for (const Point_2& q : points) p.push_back({{CGAL::to_double(q.x()), CGAL::to_double(q.y())}});
    internal::optimal::Solve_result r = internal::optimal::solve_optimal_curve(p, options);
    if (options.throw_on_failure && r.report.status != Optimal_curve_status::CONVERGED)
      throw Solve_error(internal::message("Optimal_curve_2: the solve is ", r.report.status, " (", r.report, ")"),
                        r.report);
    polygon_.reserve(r.polygon.size());
    for (const internal::optimal::Vec2& v : r.polygon) polygon_.push_back(Point_2(FT(v[0]), FT(v[1])));
    interpolation_indices_ = r.interpolation_indices;
    // The interpolation points are the user's points exactly (also in an exact kernel, where the
    // round trip through double would change them).
    for (std::size_t i = 0; i < points.size(); ++i) polygon_[interpolation_indices_[i]] = points[i];
    curvatures_ = std::move(r.curvatures);
    report_ = std::move(r.report);
    try {
      fit_spline();
    } catch (const Invalid_input_error&) {
      // A failed solve may stop on a collapsed free edge (solver.h: CAPPED below 1e-12 of the
      // extent) that the mapping back (hierarchy.h) rounds to a zero chord, which the fit refuses.
      // Without throw_on_failure a failed solve does not throw (doc/concepts.md): the curve keeps
      // its polygon, without spline() and pieces(); status() says why.
      if (report_.status == Optimal_curve_status::CONVERGED) throw;
      spline_ = Spline{{}, {}, 0.0};
      pieces_.clear();
      return;
    }
  }

  /// The input points, as given.
  const std::vector<Point_2>& points() const { return points_; }
  /// The optimal polygon (closed: no repeated vertex); its vertices at interpolation_indices()
  /// are the input points themselves (exactly, in every kernel).
  const std::vector<Point_2>& polygon() const { return polygon_; }
  /// The polygon index of each input point.
  const std::vector<std::size_t>& interpolation_indices() const { return interpolation_indices_; }
  /// The polygon vertices of the CORNER constraints (ascending): where the curve is only G0, so
  /// that spline() has one C2 run between consecutive corners (fit_smoothing_spline_runs).
  std::vector<std::size_t> corner_vertices() const {
    std::vector<std::size_t> v;
    for (const Point_constraint& c : options_.constraints)
      if (c.kind == Point_constraint_kind::CORNER) v.push_back(interpolation_indices_[c.index]);
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
  }
  /// The C2 cubic smoothing spline of the polygon (a knot at every vertex, chordal breakpoints; C2
  /// runs between the corners, G0 at them; spline().max_distance: its distance to the polygon):
  /// fit_smoothing_spline_runs(polygon(), is_closed(), interpolation_indices(), corner_vertices(),
  /// spline_smoothing().tolerance), the tolerance optimal_spline_distance_fraction times the
  /// polygon's resolution (rotation-invariant extent / rho). It passes through the input points
  /// exactly and smooths the ripples that interpolating every vertex of the adaptive polygon makes
  /// (doc/optimal_curves.md, "The smoothing spline"; fit_cubic_spline_runs interpolates every vertex).
  /// The hierarchy refines the polygon until the interpolant of every vertex is within that
  /// tolerance (internal/spline/smoothing_runs.h), so spline_smoothing().tolerance_met holds for a
  /// solve that reached its resolution. The C4 quintic of the same rule: fit_smoothing_quintic_runs.
  const Spline& spline() const { return spline_; }
  /// How spline() was smoothed (tolerance, per-run smoothing weight and bisection solves).
  const Spline_smoothing_report& spline_smoothing() const { return smoothing_; }
  /// The C4 quintic smoothing spline of the polygon under spline()'s rule: fit_smoothing_quintic_runs(
  /// polygon(), is_closed(), interpolation_indices(), corner_vertices(), spline_smoothing().tolerance)
  /// (doc/optimal_curves.md, "The quintic smoothing spline"). Computed on each call, O(n); what
  /// `fair-curves optimal` and the Python module deliver as "quintic" with a derivative term.
  Polygon_quintic_fit<K> quintic_spline() const {
    return fit_smoothing_quintic_runs<K>(polygon(), is_closed(), interpolation_indices(), corner_vertices(),
                                         smoothing_.tolerance)
        .fit;
  }
  /// The cubic pieces of spline(), run after run: one per polygon edge.
  const std::vector<Piece>& pieces() const { return pieces_; }
  std::size_t number_of_pieces() const { return pieces_.size(); }
  /// spline() in the exchange form (fair/Nurbs_curve_2.h; doc/nurbs.md, "Optimal_curve_2"):
  /// degree 3, the chordal breakpoints of the runs (each run's shifted to start where the previous
  /// one ends), single knots inside a run and knots of multiplicity 3 at the corners (C0); closed:
  /// the periodic form (seam at the first corner, or C2 without corners). Its pieces are pieces().
  /// \throws Precondition_error for a curve without pieces (a failed solve, see status()).
  Nurbs_curve_2<K> nurbs() const {
    internal::require(!pieces_.empty(), "Optimal_curve_2::nurbs: the curve has no spline (status ", report_.status, ")");
    return spline_.nurbs(options_.closed);
  }
  bool is_closed() const { return options_.closed; }
  const Optimal_curve_options& options() const { return options_; }
  const Optimal_curve_report& report() const { return report_; }
  /// report().status: CONVERGED, DIVERGING or CAPPED.
  Optimal_curve_status status() const { return report_.status; }
  /// The discrete true curvature per polygon vertex (the functional's discretisation; 0 at open ends).
  const std::vector<double>& curvatures() const { return curvatures_; }
  /// F of eq. 5 (discrete, Sec. 2.2.3) at the final polygon.
  double energy() const { return report_.energy; }

private:
  /// spline_, smoothing_ and pieces_: the smoothing spline, run by run between the corners.
  void fit_spline() {
    std::vector<internal::optimal::Vec2> v;
    v.reserve(polygon_.size());
    for (const Point_2& q : polygon_) v.push_back({{CGAL::to_double(q.x()), CGAL::to_double(q.y())}});
    const double tolerance =
        optimal_spline_distance_fraction * internal::optimal::rotation_invariant_extent(v) / options_.resolution;
    // Near the top of the double range (coordinates of about 1e308) the extent or the spline's
    // control-point combinations overflow; the fit then refuses its own arguments with a
    // Precondition_error, which here is about the user's data (review R20b): said so.
    auto too_large = [&](const std::string& why) {
      return Invalid_input_error(internal::message("fair::Optimal_curve_2: the smoothing spline of the optimal polygon ",
                                                   "cannot be represented at this extent (", why, "); scale the points down"));
    };
    if (!std::isfinite(tolerance)) throw too_large("its extent overflows double");
    Polygon_smoothing_fit<K> fit;
    try {
      fit = fit_smoothing_spline_runs<K>(polygon_, options_.closed, interpolation_indices_, corner_vertices(), tolerance);
    } catch (const Precondition_error& e) {
      throw too_large(e.what());
    }
    spline_ = std::move(fit.runs);
    smoothing_ = std::move(fit.report);
    pieces_.clear();
    for (const Cubic_spline_2<K>& run : spline_.splines) {
      std::vector<Piece> q = run.polynomial_pieces();
      pieces_.insert(pieces_.end(), q.begin(), q.end());
    }
  }

  std::vector<Point_2> points_;
  Optimal_curve_options options_;
  std::vector<Point_2> polygon_;
  std::vector<std::size_t> interpolation_indices_;
  std::vector<double> curvatures_;
  Optimal_curve_report report_;
  Spline spline_{{}, {}, 0.0};
  Spline_smoothing_report smoothing_;
  std::vector<Piece> pieces_;
};

} // namespace fair

#endif // FAIR_OPTIMAL_CURVE_2_H
