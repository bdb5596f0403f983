// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Gumhold's optimal curves (issue 11; S. Gumhold, "Designing optimal curves in 2D", Sec. 2.3-3.3):
// the interpolating polygon that minimises the scale-invariant functional of eq. 5,
//   F(c) = int beta + beta_0 |kappa L0|^alpha_0 + sum_k beta_k |kappa^(k) L0^(k+1)|^alpha_k ds,
// with TRUE curvature (the paper's eq. 9 is half of it, doc/optimal_curves.md), computed by a
// hierarchical, adaptive Newton method on the normal offsets of the free vertices
// (doc/optimal_curves.md). Points -> solver on doubles -> polygon in the user's kernel.

#ifndef FAIR_OPTIMAL_CURVE_2_H
#define FAIR_OPTIMAL_CURVE_2_H

#include <fair/Optimal_curve_options.h>
#include <fair/Optimal_curve_report.h>
#include <fair/internal/optimal/hierarchy.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace fair {

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
    internal::optimal::Solve_result r = internal::optimal::solve_optimal_curve(p, options);
    polygon_.reserve(r.polygon.size());
    for (const internal::optimal::Vec2& v : r.polygon) polygon_.push_back(Point_2(FT(v[0]), FT(v[1])));
    interpolation_indices_ = r.interpolation_indices;
    // The interpolation points are the user's points exactly (also in an exact kernel, where the
    // round trip through double would change them).
    for (std::size_t i = 0; i < points.size(); ++i) polygon_[interpolation_indices_[i]] = points[i];
    curvatures_ = r.curvatures;
    report_ = r.report;
  }

  /// The optimal polygon (closed: no repeated vertex); its vertices at interpolation_indices()
  /// are the input points themselves (exactly, in every kernel).
  const std::vector<Point_2>& polygon() const { return polygon_; }
  /// The polygon index of each input point.
  const std::vector<std::size_t>& interpolation_indices() const { return interpolation_indices_; }
  /// The polygon vertices of the CORNER constraints (ascending): where the curve is only G0, so
  /// that its spline is fit_cubic_spline_runs(polygon(), closed, corner_vertices()).
  std::vector<std::size_t> corner_vertices() const {
    std::vector<std::size_t> v;
    for (const Point_constraint& c : options_.constraints)
      if (c.kind == Point_constraint_kind::CORNER) v.push_back(interpolation_indices_[c.index]);
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
  }
  const Optimal_curve_report& report() const { return report_; }
  /// The discrete true curvature per polygon vertex (the functional's discretisation; 0 at open ends).
  std::vector<double> curvatures() const { return curvatures_; }
  /// F of eq. 5 (discrete, Sec. 2.2.3) at the final polygon.
  double energy() const { return report_.energy; }
  const Optimal_curve_options& options() const { return options_; }

private:
  Optimal_curve_options options_;
  std::vector<Point_2> polygon_;
  std::vector<std::size_t> interpolation_indices_;
  std::vector<double> curvatures_;
  Optimal_curve_report report_;
};

} // namespace fair

#endif // FAIR_OPTIMAL_CURVE_2_H
