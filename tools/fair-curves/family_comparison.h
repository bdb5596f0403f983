// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Every family of the library on the same points (issue 25 §4): the kappa-curve (w = 1 and
// automatic weights), the Cardinal spline at its optimum (eq. 18; Catmull-Rom where it has none),
// the classic C2 spline (chordal; natural or periodic), Catmull-Rom (centripetal), the csr-spline
// and the optimal curve at its defaults, each through its public API with default options but
// open / closed. Per method, the shape figures a designer reads (doc/real_data.md, "Every family
// on the same data"):
//  - extent ratio: diagonal of the curve's bounding box (65 samples a piece) over the points';
//  - arc length over the polygon's (closed: with its closing edge);
//  - E L: bending energy int kappa^2 ds times the length, scale free (1 / length^2 * length^2);
//    4 pi^2 for a circle;
//  - certified inflections and curvature extrema (fair/Fairness_metrics.h) per input point;
//  - certified self-intersections (internal/metrics/self_intersections.h);
//  - the outcome: the family's status, or the typed error that refused the points.
// Shared by the gallery's first section (demo_families.cpp) and test/test_real_data_families.cpp.

#ifndef FAIR_CURVES_FAMILY_COMPARISON_H
#define FAIR_CURVES_FAMILY_COMPARISON_H

#include <fair/Cardinal_spline_2.h>
#include <fair/Catmull_rom_2.h>
#include <fair/Csr_spline_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Curve_sampling.h>
#include <fair/Errors.h>
#include <fair/Fairness_metrics.h>
#include <fair/Kappa_curve_2.h>
#include <fair/Optimal_curve_2.h>
#include <fair/internal/metrics/self_intersections.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace fair_curves {

/// The methods of the comparison, in the order of the table.
inline const std::vector<std::string>& family_methods() {
  static const std::vector<std::string> m = {"kappa w=1", "kappa auto", "cardinal", "c2 spline",
                                             "catmull-rom", "csr", "optimal"};
  return m;
}

/// One method on one point set.
struct Family_row {
  std::string method;
  bool solved = false;      ///< a curve was made (whatever its status)
  std::string outcome;      ///< the status, or "rejected: <message>" (typed Invalid_input_error)
  double extent_ratio = 0, length_ratio = 0, bending_EL = 0;
  std::size_t inflections = 0, extrema = 0;
  double inflections_per_point = 0, extrema_per_point = 0;
  bool features_certified = true;
  fair::internal::metrics::Self_intersection_report self_intersections;
  double seconds = 0;       ///< wall time of the solve and the figures
};

/// Bounding-box diagonal of points given as (x, y) doubles.
inline double diagonal(const std::vector<double>& x, const std::vector<double>& y) {
  const auto [x0, x1] = std::minmax_element(x.begin(), x.end());
  const auto [y0, y1] = std::minmax_element(y.begin(), y.end());
  return std::hypot(*x1 - *x0, *y1 - *y0);
}

template <class Point>
double polygon_length(const std::vector<Point>& q, bool closed) {
  double L = 0;
  for (std::size_t i = 0; i + 1 < q.size() + (closed ? 1 : 0); ++i) {
    const Point &a = q[i], &b = q[(i + 1) % q.size()];
    L += std::hypot(CGAL::to_double(b.x()) - CGAL::to_double(a.x()), CGAL::to_double(b.y()) - CGAL::to_double(a.y()));
  }
  return L;
}

/// The figures of one curve (pieces) through `q`.
template <class Piece, class Point>
void measure_family_curve(const std::vector<Piece>& pieces, const std::vector<Point>& q, bool closed, Family_row& r) {
  std::vector<double> x, y, cx, cy;
  for (const Point& p : q) x.push_back(CGAL::to_double(p.x())), y.push_back(CGAL::to_double(p.y()));
  const fair::Sampled_curve s = fair::sample_curve(pieces, 64);
  for (const fair::Curve_sample& c : s.samples) cx.push_back(c.x), cy.push_back(c.y);
  r.extent_ratio = diagonal(cx, cy) / diagonal(x, y);
  const double L = fair::arc_length(pieces).value;
  r.length_ratio = L / polygon_length(q, closed);
  try {
    r.bending_EL = fair::bending_energy(pieces).value * L;
  } catch (const fair::Error&) {
    r.bending_EL = std::numeric_limits<double>::infinity(); // a singular point: curvature unbounded
  }
  const fair::Feature_report in = fair::inflections(pieces), ex = fair::curvature_extrema(pieces);
  r.inflections = in.count();
  r.extrema = ex.count();
  r.features_certified = in.certified && ex.certified;
  r.inflections_per_point = double(r.inflections) / double(q.size());
  r.extrema_per_point = double(r.extrema) / double(q.size());
  r.self_intersections = fair::internal::metrics::self_intersections(pieces, closed);
}

/// Solves `method` (one of family_methods()) on q and measures it; a typed Invalid_input_error is
/// the outcome "rejected: ..." (other errors propagate: they are bugs for the tests to see).
template <class K>
Family_row solve_family(const std::string& method, const std::vector<typename K::Point_2>& q, bool closed) {
  Family_row r;
  r.method = method;
  try {
    if (method == "kappa w=1" || method == "kappa auto") {
      fair::Kappa_curve_options o;
      o.closed = closed;
      o.weights = method == "kappa w=1" ? fair::Kappa_weights::UNIT : fair::Kappa_weights::AUTOMATIC;
      const fair::Kappa_curve_2<K> c(q, o);
      r.outcome = fair::to_string(c.status());
      measure_family_curve(c.pieces(), q, closed, r);
    } else if (method == "cardinal") {
      fair::Cardinal_spline_options o;
      o.closed = closed;
      const fair::Cardinal_spline_2<K> c(q, o);
      r.outcome = fair::to_string(c.status());
      measure_family_curve(c.pieces(), q, closed, r);
    } else if (method == "c2 spline") {
      const fair::Cubic_interpolating_spline_2<K> c(
          q, fair::Cubic_interpolating_spline_options{closed, fair::Spline_end_condition::NATURAL, fair::Knot_spacing::CHORDAL});
      r.outcome = "interpolated";
      measure_family_curve(c.pieces(), q, closed, r);
    } else if (method == "catmull-rom") {
      const fair::Catmull_rom_2<K> c(q, fair::Catmull_rom_options{closed, fair::Knot_spacing::CENTRIPETAL});
      r.outcome = "interpolated";
      measure_family_curve(c.pieces(), q, closed, r);
    } else if (method == "csr") {
      fair::Csr_spline_options o;
      o.closed = closed;
      const fair::Csr_spline_2<K> c(q, o);
      r.outcome = "approximated";
      measure_family_curve(c.pieces(), q, closed, r);
    } else if (method == "optimal") {
      fair::Optimal_curve_options o; // the defaults, whatever they are: only open / closed set
      o.closed = closed;
      const fair::Optimal_curve_2<K> c(q, o);
      r.outcome = fair::to_string(c.report().status);
      measure_family_curve(c.pieces(), q, closed, r);
    } else {
      throw fair::Precondition_error("solve_family: unknown method " + method);
    }
    r.solved = true;
  } catch (const fair::Invalid_input_error& e) {
    r.solved = false;
    r.outcome = std::string("rejected: ") + e.what();
  }
  return r;
}

/// The pieces of `method` on q, for drawing (Bezier or rational pieces, as a sampled curve), with
/// the same options as solve_family; throws what the family throws.
template <class K>
fair::Sampled_curve sample_family(const std::string& method, const std::vector<typename K::Point_2>& q, bool closed,
                                  std::size_t samples_per_piece = 48) {
  if (method == "kappa w=1" || method == "kappa auto") {
    fair::Kappa_curve_options o;
    o.closed = closed;
    o.weights = method == "kappa w=1" ? fair::Kappa_weights::UNIT : fair::Kappa_weights::AUTOMATIC;
    return fair::sample_curve(fair::Kappa_curve_2<K>(q, o).pieces(), samples_per_piece);
  }
  if (method == "cardinal") {
    fair::Cardinal_spline_options o;
    o.closed = closed;
    return fair::sample_curve(fair::Cardinal_spline_2<K>(q, o).pieces(), samples_per_piece);
  }
  if (method == "c2 spline")
    return fair::sample_curve(fair::Cubic_interpolating_spline_2<K>(
                                  q, fair::Cubic_interpolating_spline_options{closed, fair::Spline_end_condition::NATURAL,
                                                                              fair::Knot_spacing::CHORDAL})
                                  .pieces(),
                              samples_per_piece);
  if (method == "catmull-rom")
    return fair::sample_curve(fair::Catmull_rom_2<K>(q, fair::Catmull_rom_options{closed, fair::Knot_spacing::CENTRIPETAL}).pieces(),
                              samples_per_piece);
  if (method == "csr") {
    fair::Csr_spline_options o;
    o.closed = closed;
    return fair::sample_curve(fair::Csr_spline_2<K>(q, o).pieces(), samples_per_piece);
  }
  fair::Optimal_curve_options o;
  o.closed = closed;
  return fair::sample_curve(fair::Optimal_curve_2<K>(q, o).pieces(), samples_per_piece);
}

/// A number with `digits` significant digits, for the table.
inline std::string family_number(double v, int digits = 3) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

} // namespace fair_curves

#endif // FAIR_CURVES_FAMILY_COMPARISON_H
