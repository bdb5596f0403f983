// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The merge of Fig. 9 (Karciauskas-Peters, Sec. 6): the control polygons of the parts of all
// shapes become one control polygon, their knot sequences one knot sequence.
//
// Notation: part p is an open clamped spline with breakpoints u_0 < ... < u_m (intervals
// h_j = u_{j+1} - u_j) and control points d_0 .. d_{m+2}: d_0 and d_{m+2} its end points,
// d_{j+1} the control point of u_j (j = 0..m). In the merged spline every d_1..d_{m+1} of every
// part keeps its breakpoint, affinely mapped (u -> sigma_p u + shift_p); a join contributes one
// control point (agree / averaged) or two (edge) with a breakpoint each.
//
// Knots (the paper's "beta := 1"): sigma_1 = 1 and sigma_{p+1} = sigma_p h^p_{m-1} / h^{p+1}_0,
// so that the last interval of part p equals the first of part p+1; every interval created at
// the join gets that length h. The betas at the two shape ends and at the join points are then
// all 1. A piece of part p on [u_j, u_{j+1}] depends on the knots u_{j-2}..u_{j+3} and on the
// control points d_j..d_{j+3}; for 2 <= j <= m-3 those are the part's own (knot u_0 keeps its
// value, only its multiplicity changes, and no piece with j >= 2 sees the multiplicity), so
// these pieces are reproduced exactly. At the clamped ends of an open design nothing changes:
// the first part's pieces from j = 0 and the last part's up to j = m-1 are kept too.
//
// Weights: the homogeneous control points of part p are scaled by lambda_p (the same rational
// curve), lambda_1 = 1, lambda_{p+1} = lambda_p w^p_end / w^{p+1}_start, so the two end weights
// at every join agree. An averaged point is the Cartesian midpoint with that common weight.
// The closing join of a closed design cannot be matched both ways in general (the chains of
// sigma and lambda do not close): its intervals are the two neighbouring end intervals (beta = 1
// at both shape ends, beta = h^1_0 sigma_1 / (h^n_{m-1} sigma_n) at the join point) and its weight
// the mean of the two end weights; an edge there gets the mean interval.

#ifndef FAIR_INTERNAL_BASIC_SHAPES_MERGE_H
#define FAIR_INTERNAL_BASIC_SHAPES_MERGE_H

#include <fair/Basic_shape_design.h>
#include <fair/Errors.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Kernel/global_functions_2.h>
#include <CGAL/squared_distance_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace basic_shapes {

template <class K>
struct Merge_state {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  std::vector<Point_2> points;
  std::vector<FT> weights;
  std::vector<FT> intervals;  // intervals[i]: from the breakpoint of points[i] (closed) / points[i+1] (open) on
};

/// The corners (xmin, ymin), (xmax, ymax) of the bounding box of all control points of all parts (exact).
template <class K>
std::pair<typename K::Point_2, typename K::Point_2> design_box(const std::vector<const Cubic_spline_2<K>*>& parts) {
  typedef typename K::FT FT;
  const auto& p0 = parts.front()->control_points().front();
  FT xmin = p0.x(), xmax = p0.x(), ymin = p0.y(), ymax = p0.y();
  for (const auto* s : parts)
    for (const auto& p : s->control_points()) {
      if (p.x() < xmin) xmin = p.x();
      if (p.x() > xmax) xmax = p.x();
      if (p.y() < ymin) ymin = p.y();
      if (p.y() > ymax) ymax = p.y();
    }
  return {typename K::Point_2(xmin, ymin), typename K::Point_2(xmax, ymax)};
}

/// Squared diagonal of the bounding box of all control points of all parts (exact).
template <class K>
typename K::FT squared_design_size(const std::vector<const Cubic_spline_2<K>*>& parts) {
  const auto box = design_box(parts);
  return CGAL::squared_distance(box.first, box.second);
}

/// |p - q| in double without overflow or underflow in the intermediate squares (halved
/// coordinates, then hypot); +inf only when the distance itself exceeds the double range.
template <class Point_2>
double double_distance(const Point_2& p, const Point_2& q) {
  const double dx = 0.5 * CGAL::to_double(p.x()) - 0.5 * CGAL::to_double(q.x());
  const double dy = 0.5 * CGAL::to_double(p.y()) - 0.5 * CGAL::to_double(q.y());
  return 2 * std::hypot(dx, dy);
}

/// The diagonal of the bounding box of all control points, in double (double_distance).
template <class K>
double design_diagonal(const std::vector<const Cubic_spline_2<K>*>& parts) {
  const auto box = design_box(parts);
  return double_distance(box.first, box.second);
}

/// Where a merged breakpoint comes from: the part and the breakpoint index inside it (for a
/// part of a segment or cubic shape, breakpoint k is its k-th mark; 0 and m are its ends).
struct Breakpoint_origin {
  std::size_t part = 0, index = 0;
  bool join = false;  ///< a breakpoint created at a join (edge) rather than a part's own
};

} // namespace basic_shapes
} // namespace internal

template <class K>
Basic_shape_design_2<K> basic_shape_design(const std::vector<Basic_shape_2<K>>& shapes,
                                           const Basic_shape_design_options& options) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  const char* fn = "fair::basic_shape_design";
  internal::require(!shapes.empty(), fn, ": needs at least one shape");
  internal::require(std::isfinite(options.merge_tolerance) && options.merge_tolerance >= 0, fn,
                    ": the merge tolerance ", options.merge_tolerance, " must be finite and >= 0");
  // The parts in order, with the shape each belongs to.
  std::vector<const Cubic_spline_2<K>*> parts;
  std::vector<std::size_t> owner, part_index;
  for (std::size_t s = 0; s < shapes.size(); ++s)
    for (std::size_t k = 0; k < shapes[s].parts().size(); ++k) {
      parts.push_back(&shapes[s].parts()[k]);
      owner.push_back(s);
      part_index.push_back(k);
      internal::require(!parts.back()->is_closed(), fn, ": part ", k, " of shape ", s, " is closed");
    }
  const std::size_t n = parts.size();
  const bool closed = options.closed;
  // The merge distance in double, robustly (issue 29 #15: the squared diagonal overflowed to inf
  // and inf * 0 printed "distance -nan"); a design whose extent is beyond the double range has no
  // finite distances to report and is refused.
  const double diagonal = internal::basic_shapes::design_diagonal<K>(parts);
  if (!std::isfinite(diagonal))
    throw Invalid_input_error(internal::message(fn, ": the bounding box of the shapes' control points is wider than "
                                                "the double range (its diagonal overflows)"));
  const double merge_distance = options.merge_tolerance == 0 ? 0.0 : options.merge_tolerance * diagonal;
  if (!std::isfinite(merge_distance))
    throw Invalid_input_error(internal::message(fn, ": the merge distance, merge tolerance ", options.merge_tolerance,
                                                " times the design's diagonal ", diagonal, ", overflows double precision"));
  typedef typename CGAL::Algebraic_structure_traits<FT>::Is_exact Is_exact;
  constexpr bool exact_ft = Is_exact::value && !std::is_floating_point<FT>::value;
  const FT size2 = exact_ft ? internal::basic_shapes::squared_design_size<K>(parts) : FT(0);
  const FT tol(options.merge_tolerance);
  const FT threshold2 = tol * tol * size2;

  // sigma (knot scale) and lambda (weight scale) of every part.
  std::vector<FT> sigma(n, FT(1)), lambda(n, FT(1));
  auto first_h = [&](std::size_t p) { const auto& t = parts[p]->breakpoints(); return t[1] - t[0]; };
  auto last_h = [&](std::size_t p) { const auto& t = parts[p]->breakpoints(); return t[t.size() - 1] - t[t.size() - 2]; };
  for (std::size_t p = 1; p < n; ++p) {
    sigma[p] = sigma[p - 1] * last_h(p - 1) / first_h(p);
    lambda[p] = lambda[p - 1] * parts[p - 1]->weights().back() / parts[p]->weights().front();
  }

  std::vector<Point_2> points;
  std::vector<FT> weights, intervals;  // intervals[i]: from the i-th breakpoint to the next
  std::vector<internal::basic_shapes::Breakpoint_origin> origin;  // of the breakpoint at the end of intervals[i]
  std::vector<Shape_join> joins;
  std::vector<Shape_span> spans;
  std::vector<std::size_t> first_break(n);  // breakpoint index of u_0 of every part
  std::size_t breaks = 0;                   // breakpoints so far
  if (!closed) {
    points.push_back(parts[0]->control_points().front());
    weights.push_back(lambda[0] * parts[0]->weights().front());
  }
  auto add_join = [&](std::size_t p, std::size_t q, bool wrap) {
    // The end of part p to the start of part q (q = 0 for the closing join).
    const Point_2& e = parts[p]->control_points().back();
    const Point_2& s = parts[q]->control_points().front();
    const FT we = lambda[p] * parts[p]->weights().back();
    const FT ws = lambda[q] * parts[q]->weights().front();
    const FT h_before = sigma[p] * last_h(p), h_after = sigma[q] * first_h(q);
    Shape_join j;
    j.before = owner[p];
    j.after = owner[q];
    j.inside = !wrap && owner[p] == owner[q];
    j.distance = internal::basic_shapes::double_distance(e, s);  // <= diagonal: finite
    j.control_point = points.size();
    // Exact kernels compare the exact squares; a floating one the distances (squares overflow).
    const bool near = exact_ft ? CGAL::squared_distance(e, s) <= threshold2 : j.distance <= merge_distance;
    if (e == s) j.kind = Shape_join_kind::AGREE;
    else if (j.inside || near) j.kind = Shape_join_kind::AVERAGED;
    else j.kind = Shape_join_kind::EDGE;
    // The weights agree by the lambda chain except at the closing join: their mean there.
    const FT wm = wrap ? (we + ws) / FT(2) : we;
    if (j.kind == Shape_join_kind::EDGE) {
      points.push_back(e);
      weights.push_back(we);
      points.push_back(s);
      weights.push_back(ws);
      intervals.push_back(h_before);
      intervals.push_back((h_before + h_after) / FT(2));
      intervals.push_back(h_after);
      origin.push_back({p, parts[p]->breakpoints().size() - 1, true});
      origin.push_back({q, 0, true});
      origin.push_back({q, 0, false});
      breaks += 2;
    } else {
      points.push_back(j.kind == Shape_join_kind::AGREE ? e : CGAL::midpoint(e, s));
      weights.push_back(wm);
      intervals.push_back(h_before);
      intervals.push_back(h_after);
      origin.push_back({p, parts[p]->breakpoints().size() - 1, true});
      origin.push_back({q, 0, false});
      breaks += 1;
    }
    joins.push_back(j);
  };
  for (std::size_t p = 0; p < n; ++p) {
    const auto& d = parts[p]->control_points();
    const auto& w = parts[p]->weights();
    const auto& t = parts[p]->breakpoints();
    const std::size_t m = t.size() - 1;
    first_break[p] = breaks;
    for (std::size_t k = 1; k + 1 < d.size(); ++k) {
      points.push_back(d[k]);
      weights.push_back(lambda[p] * w[k]);
    }
    for (std::size_t k = 0; k < m; ++k) {
      intervals.push_back(sigma[p] * (t[k + 1] - t[k]));
      origin.push_back({p, k + 1, false});
    }
    breaks += m + 1;
    if (p + 1 < n) add_join(p, p + 1, false);
    else if (closed) add_join(p, 0, true);
    Shape_span span;
    span.shape = owner[p];
    span.part = part_index[p];
    span.first_piece = first_break[p];
    span.end_piece = first_break[p] + m;
    const bool clamped_start = !closed && p == 0, clamped_end = !closed && p + 1 == n;
    span.first_exact = span.first_piece + (clamped_start ? 0 : 2);
    span.end_exact = clamped_end ? span.end_piece : (m >= 2 ? span.end_piece - 2 : span.first_piece);
    if (span.end_exact < span.first_exact) span.end_exact = span.first_exact;
    spans.push_back(span);
  }
  if (!closed) {
    points.push_back(parts[n - 1]->control_points().back());
    weights.push_back(lambda[n - 1] * parts[n - 1]->weights().back());
  }
  // Breakpoints from the intervals, starting at the first part's u_0.
  std::vector<FT> knots;
  knots.push_back(parts[0]->breakpoints().front());
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    knots.push_back(knots.back() + intervals[i]);
    // The chain sigma_{p+1} = sigma_p h^p_{m-1} / h^{p+1}_0 multiplies the ratios of end
    // intervals part after part: marks bunched at one end of many shapes make it decay (or grow)
    // geometrically, until in a floating FT a breakpoint no longer exceeds the previous one or
    // overflows (issue 29 #8). Said here with the shape and the mark that cause it.
    if (!(knots.back() > knots[knots.size() - 2]) || !std::isfinite(CGAL::to_double(knots.back()))) {
      const internal::basic_shapes::Breakpoint_origin& o = origin[i];
      const std::size_t p = o.part, s = owner[p];
      const std::size_t m = parts[p]->breakpoints().size() - 1;
      const std::string where =
          o.join ? internal::message("at the join of shape ", s, " (part ", part_index[p], ") with the next shape")
          : o.index == 0 || o.index == m
              ? internal::message("at the ", o.index == 0 ? "start" : "end", " of shape ", s, " (part ", part_index[p], ")")
              : internal::message("at mark ", o.index - 1, " of shape ", s, " (part ", part_index[p], ")");
      throw Invalid_input_error(internal::message(
          fn, ": the merged knots stop increasing in floating point ", where,
          ": each shape's knot intervals are scaled so that its first interval equals the previous shape's last one, "
          "and the ratios of the end intervals (marks bunched at one end) multiply to ", CGAL::to_double(sigma[p]),
          " by shape ", s, "; space the marks more evenly, or compute exactly (--exact, an exact kernel)"));
    }
  }
  FAIR_ASSERT_MSG(closed ? points.size() + 1 == knots.size() : points.size() == knots.size() + 2,
                  fn, ": ", points.size(), " control points for ", knots.size(), " breakpoints");
  // A closed design always has >= 3 control points (each part gives >= 2, the closing join >= 1),
  // but if all of them lie on one line the periodic curve runs there and back (e.g. one segment
  // closed on itself): no interior, a degenerate closed curve. Decided exactly in an exact kernel.
  if (closed) {
    std::size_t k = 1;
    while (k < points.size() && points[k] == points[0]) ++k;
    bool on_one_line = true;
    for (std::size_t i = k + 1; k < points.size() && i < points.size() && on_one_line; ++i)
      on_one_line = CGAL::collinear(points[0], points[k], points[i]);
    if (on_one_line)
      throw Invalid_input_error(internal::message(fn, ": the closed design's ", points.size(),
                                        " control points lie on one line (a curve there and back, no interior)"));
  }
  // All weights equal (polynomial shapes only): the constructor makes it a polynomial spline.
  Cubic_spline_2<K> spline(std::move(knots), std::move(points), std::move(weights), closed);
  Basic_shape_design_2<K> out{std::move(spline), std::move(joins), std::move(spans), 0.0};
  out.merge_distance = merge_distance;
  return out;
}

} // namespace fair

#endif // FAIR_INTERNAL_BASIC_SHAPES_MERGE_H
