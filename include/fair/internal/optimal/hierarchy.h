// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The hierarchical, adaptive optimiser of Gumhold's Sec. 2.3 (doc/optimal_curves.md,
// "Hierarchy"): start from the input polygon (with the constrained edges split, constraints.h),
// solve the level (solver.h), split the edges (new vertex by the four-point rule, see subdivide) where
//   max(eps(l_j, phi_j), eps(l_j, phi_{j+1})) > eps_max,   eps(l, phi) = (l/2) tan(|phi|/4)
// (the sagitta of the circle tangent to the vertex bisector through the chord of length l: with
// central angle phi, r = l / (2 sin(phi/2)) and eps = r (1 - cos(phi/2)) = (l/2) tan(phi/4) by the
// half-angle identity (1 - cos x)/sin x = tan(x/2); the paper's printed
// l (1 - cos(phi/2)) / (2 sin(phi/2)) is the same expression), eps_max = one pixel = extent / rho
// of the current polygon (rotation_invariant_extent), warm start, until no edge is split (the target
// resolution) or a cap (max_levels, max_vertices) stops it. Interpolation points stay fixed.

#ifndef FAIR_INTERNAL_OPTIMAL_HIERARCHY_H
#define FAIR_INTERNAL_OPTIMAL_HIERARCHY_H

#include <fair/Errors.h>
#include <fair/Optimal_curve_options.h>
#include <fair/Optimal_curve_report.h>
#include <fair/internal/optimal/constraints.h>
#include <fair/internal/optimal/extent.h>
#include <fair/internal/optimal/fair_reference.h>
#include <fair/internal/optimal/functional.h>
#include <fair/internal/optimal/input_checks.h>
#include <fair/internal/optimal/lambda.h>
#include <fair/internal/optimal/solver.h>
#include <fair/internal/spline/smoothing_runs.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

struct Solve_result {
  std::vector<Vec2> polygon;
  std::vector<std::size_t> interpolation_indices;
  std::vector<double> curvatures;
  Optimal_curve_report report{Status::CAPPED, 0, 0, 0, {}};
  std::vector<double> eta;  // per segment, when the lambda design ran (eq. 11)
  bool eta_reference_guarded = false;  // lambda = 1 diverged: eta from the lambda = 0.99 curve
  bool eta_from_spline = false;  // the lambda = 1 (0.99) curve was not fair: eta from the C2 spline (fair_reference.h)
};

/// The turning angle phi_j at every vertex (0 at open ends).
inline std::vector<double> turning_angles(const std::vector<Vec2>& c, bool closed) {
  const std::size_t n = c.size();
  std::vector<double> phi(n, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    if (!closed && (j == 0 || j + 1 == n)) continue;
    const Vec2 a = vec::sub(c[j], c[(j + n - 1) % n]), b = vec::sub(c[(j + 1) % n], c[j]);
    phi[j] = std::atan2(vec::cross(a, b), vec::dot(a, b));
  }
  return phi;
}

/// eps(l, phi) = (l/2) tan(|phi|/4): the largest distance of the edge from the circle arc it
/// approximates (file comment).
inline double edge_error(double l, double phi) { return 0.5 * l * std::tan(0.25 * std::abs(phi)); }

/// The curvature-profile refinement of subdivide (issue 25 §3): an edge whose end curvatures differ
/// by more than this factor is split while its sagitta exceeds eps_max / curvature_resolution_floor.
constexpr double curvature_resolution_ratio = 2, curvature_resolution_floor = 8;

/// Splits the edges whose error exceeds eps_max at their midpoints (or, with `forced`, exactly the
/// edges marked there: the spline-resolution pass of run_hierarchy); updates the interpolation
/// indices and the constraint vertices. Returns the number of edges split.
inline std::size_t subdivide(const Level_problem& p, std::vector<Vec2>& c, double eps_max,
                             std::vector<std::size_t>& interpolation, std::vector<Placed_constraint>& placed,
                             const std::vector<unsigned char>* forced = nullptr) {
  const bool closed = p.f.closed;
  const std::size_t n = c.size(), edges = closed ? n : n - 1;
  // New vertices by the four-point rule (Dyn, Levin, Gregory; weights -1, 9, 9, -1 over 16)
  // instead of the paper's edge midpoints: a midpoint on a straight edge has kappa = 0 and doubles
  // its neighbours' kappa, which doubles int kappa^2 after every subdivision (and makes kappa^(k)
  // ~ h^-k): Newton then needs 15-40 step-capped iterations at 1e4 vertices instead of 2-5. The
  // four-point polygon is within O(h^4) of a smooth curve: the warm start is nearly converged.
  // Plain midpoints next to corners (their neighbours stay on the rays) and at open ends (no
  // fourth point). (The paper found other placements "less stable" with CG; with Newton and the
  // step cap of line_search.h the four-point start is the more stable one, measured on the tests.)
  const std::vector<unsigned char>& zero = p.f.zero_curvature;
  // (With no curvature term at all, e.g. lambda = 0, the minimiser is the input polygon: plain
  // midpoints keep it exactly.)
  bool four_point = false;
  for (double b0 : p.f.curvature_weight) four_point = four_point || b0 > 0;
  for (int k = 1; k <= 4; ++k) four_point = four_point || p.f.derivative_weight[k] > 0;
  // Turning angles with the ghosts of clamped ends (the turn from the end tangent counts).
  const std::vector<double> phi = p.ghosts() ? p.strip(turning_angles(p.extend(c), closed), n) : turning_angles(c, closed);
  std::vector<unsigned char> split(edges, 0);
  std::size_t count = 0;
  std::vector<double> length(edges);
  for (std::size_t j = 0; j < edges; ++j) length[j] = vec::norm(vec::sub(c[(j + 1) % n], c[j]));
  // The discrete curvature |phi_v| / (mean length of the edges at v) (0 at open ends).
  auto curvature_at = [&](std::size_t v) {
    const double a = closed || v > 0 ? length[(v + edges - 1) % edges] : 0, b = closed || v < edges ? length[v % edges] : 0;
    return a + b > 0 ? 2 * std::abs(phi[v]) / (a + b) : 0.0;
  };
  const double ratio = curvature_resolution_ratio, below = curvature_resolution_floor;
  // Only with a curvature term (beta_0 > 0: the lambda design and the raw weights with a curvature
  // weight): the derivative energies alone make kappa smooth by themselves, and their Newton levels
  // (k = 4: condition ~ n^10) gain nothing from the extra vertices.
  bool curvature_term = false;
  for (double b0 : p.f.curvature_weight) curvature_term = curvature_term || b0 > 0;
  for (std::size_t j = 0; j < edges && !forced; ++j) {
    const double l = length[j];
    const double e = std::max(edge_error(l, phi[j]), edge_error(l, phi[(j + 1) % n]));
    bool resolve = e > eps_max;
    // The curvature profile resolved too (issue 25 §3): at lambda < 1 the curvature of the
    // minimiser peaks at the input points and decays over L0 / sqrt(q) (a fraction of an edge at
    // q ~ 10^4), which the sagitta test above accepts; the spline through such a polygon must make
    // the spike with a C2 cubic and rings (two inflections around every point). An edge whose
    // end curvatures differ by more than `ratio` is split while its sagitta is above eps_max / below.
    if (!resolve && curvature_term && e > eps_max / below) {
      const double k0 = curvature_at(j), k1 = curvature_at((j + 1) % n);
      resolve = std::max(k0, k1) > ratio * std::min(k0, k1);
    }
    if (resolve) { split[j] = 1; ++count; }
  }
  if (forced)
    for (std::size_t j = 0; j < edges; ++j)
      if ((*forced)[j]) { split[j] = 1; ++count; }
  if (count == 0) return 0;
  std::vector<Vec2> d;
  d.reserve(n + count);
  std::vector<std::size_t> index(n);
  for (std::size_t j = 0; j < n; ++j) {
    index[j] = d.size();
    d.push_back(c[j]);
    if (j < edges && split[j]) {
      const Vec2& q = c[(j + 1) % n];
      Vec2 mid = {{0.5 * (c[j][0] + q[0]), 0.5 * (c[j][1] + q[1])}};
      if (four_point && (closed || (j >= 1 && j + 2 < n))) {
        const std::size_t a = (j + n - 1) % n, b = (j + 2) % n;
        bool corner = false;
        for (std::size_t v : {a, j, (j + 1) % n, b}) corner = corner || (!zero.empty() && zero[v]);
        if (!corner)
          for (int k = 0; k < 2; ++k) mid[k] = (9 * (c[j][k] + q[k]) - (c[a][k] + c[b][k])) / 16;
      }
      d.push_back(mid);
    }
  }
  for (std::size_t& i : interpolation) i = index[i];
  for (Placed_constraint& p : placed) p.vertex = index[p.vertex];
  c.swap(d);
  return count;
}

inline double polygon_length(const std::vector<Vec2>& c, bool closed) {
  const std::size_t n = c.size(), e = closed ? n : n - 1;
  double s = 0;
  for (std::size_t j = 0; j < e; ++j) s += vec::norm(vec::sub(c[(j + 1) % n], c[j]));
  return s;
}

inline Status worse(Status a, Status b) {
  if (a == Status::DIVERGING || b == Status::DIVERGING) return Status::DIVERGING;
  if (a == Status::CAPPED || b == Status::CAPPED) return Status::CAPPED;
  return Status::CONVERGED;
}

/// The spline-resolution pass of run_hierarchy splits where the C2 interpolant is beyond this
/// fraction of the smoothing fit's tolerance (a margin for the rounding between the two).
constexpr double spline_resolution_margin = 0.99;

/// The hierarchy with per-edge beta and per-vertex beta0 given by `weights(c, interpolation,
/// edge_beta, vertex_beta0)` (re-evaluated on every level). `spline_resolution` (the polygon that
/// Optimal_curve_2 delivers, not the lambda = 1 reference of eq. 11): once the sagitta test splits
/// no edge, the edges on which the C2 interpolant lies farther than optimal_spline_distance_fraction
/// * eps_max from the polygon are split too (internal/spline/smoothing_runs.h), until none is.
template <class Weights>
Solve_result run_hierarchy(const std::vector<Vec2>& points, const Optimal_curve_options& o, Weights weights,
                           bool spline_resolution = true) {
  Solve_result r;
  std::vector<Placed_constraint> placed = check_constraints(o.constraints, points, o.closed);
  std::vector<Vec2> c = initial_polygon(points, o.closed, placed, r.interpolation_indices);
  Level_problem p;
  Functional& f = p.f;
  f.closed = o.closed;
  f.reference_length = polygon_length(points, o.closed);
  f.curvature_exponent = o.curvature_exponent;
  f.derivative_weight = o.derivative_weight;
  f.derivative_exponent = o.derivative_exponent;
  f.derivative_weight[0] = 0;
  f.discretisation = o.discretisation;
  Level_settings s;
  s.conjugate_gradient = o.solver == Optimal_curve_solver::CONJUGATE_GRADIENT;
  s.max_iterations = o.max_iterations_per_level;
  s.tolerance = o.tolerance;
  s.max_extent = divergence_extent_factor * polygon_extent(points);
  bool derivative = false;
  for (int k = 1; k <= 4; ++k) derivative = derivative || o.derivative_weight[k] > 0;
  Status overall = Status::CONVERGED;
  // The spline-resolution pass may refine the polygon, never lower the outcome (review of issue
  // 25 §3, M1): once it has forced a level, a level that does not converge (that one or a later
  // one, refined further by the sagitta test) sends the solve back to the state before the first
  // forced level, and the caps do not count after it; the smoothing fit then reports
  // tolerance_met = false where its interpolant is still beyond the tolerance.
  struct Kept {
    Solve_result r;
    std::vector<Vec2> c;
    std::vector<Placed_constraint> placed;
    Level_problem p;
    Status overall;
  };
  std::unique_ptr<Kept> kept;  // the state before the first level the spline pass forced
  for (std::size_t level = 0;; ++level) {
    const Vertex_roles roles = vertex_roles(c.size(), o.closed, r.interpolation_indices, placed);
    p.f.zero_curvature = roles.zero_curvature;
    weights(c, r.interpolation_indices, p.f.length_weight, p.f.curvature_weight);
    p.ghost_front = roles.ghost_front;
    p.ghost_back = roles.ghost_back;
    p.front_tangent = roles.front_tangent;
    p.back_tangent = roles.back_tangent;
    p.prepare();
    std::size_t iterations = 0;
    if (derivative && level == 0) {
      // Continuation (Sec. 3.3): the k = 0 solution first, then the k-th derivative energy.
      Level_problem p0 = p;
      p0.f.derivative_weight = {{0, 0, 0, 0, 0}};
      p0.prepare();
      iterations += solve_level(p0, roles, s, c).iterations;
    }
    Level_outcome out = solve_level(p, roles, s, c);
    out.iterations += iterations;
    r.report.levels.push_back({c.size(), out.iterations, out.energy, out.gradient_norm, out.status});
    r.report.iterations += out.iterations;
    r.report.energy = out.energy;
    r.report.gradient_norm = out.gradient_norm;
    overall = worse(overall, out.status);
    if (kept && out.status != Status::CONVERGED) {
      const std::size_t spent = r.report.iterations;
      r = std::move(kept->r);
      c = std::move(kept->c);
      placed = std::move(kept->placed);
      p = std::move(kept->p);
      overall = kept->overall;
      r.report.iterations = spent;  // the work done stays reported
      break;
    }
    if (out.status == Status::DIVERGING) break;
    // A Newton level that hit its iteration cap makes the solve CAPPED whatever follows; refining
    // it further only multiplies the work (issue 29 #19: 100 random points with a kappa' term took
    // 10.6 s through capped levels of thousands of vertices). Stop there (the paper's CG, kept for
    // comparison, runs its levels to the end).
    if (out.status == Status::CAPPED && !s.conjugate_gradient) break;
    std::vector<Vec2> d = c;
    std::vector<std::size_t> interpolation = r.interpolation_indices;
    std::vector<Placed_constraint> moved = placed;
    const double eps_max = rotation_invariant_extent(c) / o.resolution;
    std::size_t split = subdivide(p, d, eps_max, interpolation, moved);
    bool forced = false;
    if (split == 0 && spline_resolution) {  // the spline's resolution (smoothing_runs.h)
      std::vector<std::size_t> corners;
      for (const Placed_constraint& q : placed)
        if (q.corner) corners.push_back(q.vertex);
      // (a margin of 1 % under the fit's tolerance: Optimal_curve_2 measures it on the polygon mapped
      // back to the user's coordinates, which rounding moves by far less)
      const std::vector<unsigned char> beyond = spline::interpolant_beyond_edges(
          c, o.closed, corners, spline_resolution_margin * optimal_spline_distance_fraction * eps_max);
      split = subdivide(p, d, eps_max, interpolation, moved, &beyond);
      forced = split > 0;
    }
    if (split == 0) break;  // the target resolution is reached
    // The level cap counts only when another level is needed (and not for the spline pass).
    if (level + 1 >= o.max_levels || d.size() > o.max_vertices) {
      if (!forced && !kept) overall = worse(overall, Status::CAPPED);
      break;
    }
    if (forced && !kept) kept.reset(new Kept{r, c, placed, p, overall});
    c.swap(d);
    r.interpolation_indices.swap(interpolation);
    placed.swap(moved);
    restore_ties(vertex_roles(c.size(), o.closed, r.interpolation_indices, placed), c);
  }
  r.report.status = overall;
  r.polygon = c;
  r.curvatures = problem_curvatures(p, c);
  return r;
}

/// The lambda design and the hierarchy on points already normalised (defined below); `delivered`:
/// the polygon Optimal_curve_2 returns (false for the lambda = 1 reference: no spline resolution).
inline Solve_result solve_normalised(const std::vector<Vec2>& points, const Optimal_curve_options& o,
                                     bool delivered = true);

/// The whole solve of Optimal_curve_2 (checks, the lambda design, the hierarchy), on the points
/// translated by their centroid and divided by a power of two near their extent (reviewer finding 9:
/// without it the scale invariance F(q c) = q F(c) held only in a window, |q| in 1e-30..1e30, and a
/// translation by 1e12 ended CAPPED), mapped back after: the polygon (with the input points written
/// back exactly at the interpolation indices), curvatures (x 1/scale) and energies (x scale; the
/// reduced gradients are invariant: F and the offsets scale alike).
inline Solve_result solve_optimal_curve(const std::vector<Vec2>& points, const Optimal_curve_options& o) {
  check_solve_input(points, o);
  double cx = 0, cy = 0;
  for (const Vec2& p : points) { cx += p[0] / static_cast<double>(points.size()); cy += p[1] / static_cast<double>(points.size()); }
  const Vec2 centroid = refined_centroid(points, {{cx, cy}});  // accurate far from the origin too
  cx = centroid[0];
  cy = centroid[1];
  double r = 0;
  for (const Vec2& p : points) r = std::max(r, std::max(std::abs(p[0] - cx), std::abs(p[1] - cy)));
  // What a designer must know about the shape (issue 25 §2, shape_check.h), on the polygon returned.
  auto with_shape = [&](Solve_result res) {
    res.report.extent_ratio = extent_ratio(res.polygon, points);
    res.report.self_intersections = count_self_intersections(res.polygon, o.closed);
    res.report.input_self_intersections = count_self_intersections(points, o.closed);
    return res;
  };
  // Points farther than the double range from their centroid (e.g. at +-1.7e308): no curve
  // through them has a representable extent, and the unnormalised solve would fail later with a
  // message about an internal quantity (review R20).
  if (!std::isfinite(r))
    throw Invalid_input_error(message("Optimal_curve_2: the points' extent overflows double (a coordinate differs from ",
                                      "the centroid (", cx, ", ", cy, ") by more than ", std::numeric_limits<double>::max(),
                                      "); scale the points down"));
  if (!(r > 0)) return with_shape(solve_normalised(points, o));
  const double scale = std::ldexp(1.0, std::ilogb(r));  // exact: a power of two
  std::vector<Vec2> q(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) q[i] = {{(points[i][0] - cx) / scale, (points[i][1] - cy) / scale}};
  for (std::size_t i = 0; i + 1 < q.size() || (o.closed && i < q.size()); ++i) {
    const Vec2& a = q[i];
    const Vec2& b = q[(i + 1) % q.size()];
    if (a[0] == b[0] && a[1] == b[1]) return with_shape(solve_normalised(points, o));  // distinct only before rounding: solve as given
  }
  Solve_result res = solve_normalised(q, o);
  for (std::size_t i = 0; i < res.polygon.size(); ++i) {
    const Vec2 u = res.polygon[i];
    res.polygon[i] = {{u[0] * scale + cx, u[1] * scale + cy}};
    // Points at the edge of the double range (e.g. y near -1.8e308): the curve between them can
    // bulge beyond it (fuzz finding optimal/regress-curve-beyond-the-double-range: an infinite
    // vertex then reached the exact self-intersection count, and GMP aborted on it).
    if (!std::isfinite(res.polygon[i][0]) || !std::isfinite(res.polygon[i][1]))
      throw Invalid_input_error(message("Optimal_curve_2: the curve leaves the double range (its vertex ", i,
                                        ", at (", u[0], ", ", u[1], ") in units of ", scale, " from the centroid (", cx,
                                        ", ", cy, "), overflows); move the points towards the origin"));
  }
  for (std::size_t i = 0; i < points.size(); ++i) res.polygon[res.interpolation_indices[i]] = points[i];
  // Mapped back, vertices can round onto each other where the extent is a few ulps of the
  // coordinates (points far from the origin; review R20b): refused by name, rather than by the
  // spline fit naming two polygon vertices the user never gave.
  for (std::size_t i = 0; i + 1 < res.polygon.size() || (o.closed && i < res.polygon.size()); ++i) {
    const Vec2& a = res.polygon[i];
    const Vec2& b = res.polygon[(i + 1) % res.polygon.size()];
    if (a[0] == b[0] && a[1] == b[1]) {
      double magnitude = 0;
      for (const Vec2& p : points) magnitude = std::max(magnitude, std::max(std::abs(p[0]), std::abs(p[1])));
      throw Invalid_input_error(message("Optimal_curve_2: the points' extent ", r, " is only ",
                                        r / (magnitude * std::numeric_limits<double>::epsilon()),
                                        " ulps of their coordinates (up to ", magnitude,
                                        "), too few to place the curve's vertices; translate the points towards the origin"));
    }
  }
  // kappa(q c) = kappa(c) / q: at an extent near the bottom of the double range the curvature of a
  // tight turn can exceed it (fuzz finding optimal/regress-curvature-overflow: points at 1e-298
  // with two of them 4e-309 apart).
  double largest_curvature = 0;
  for (const double k : res.curvatures) largest_curvature = std::max(largest_curvature, std::abs(k));
  if (std::isfinite(largest_curvature) && !std::isfinite(largest_curvature / scale))
    throw Invalid_input_error(message("Optimal_curve_2: the curvature of the curve (up to ", largest_curvature,
                                      " at unit extent) overflows double at the points' extent ", r,
                                      "; scale the points up"));
  for (double& k : res.curvatures) k /= scale;
  // F(q c) = q F(c): at an extent near the top of the double range the energy itself can exceed
  // it (fuzz finding optimal/open-energy-inf: points at 1e302 with a kappa'' term), or only the
  // energy of a coarser level, which is higher than the final one (review R20).
  double largest_energy = res.report.energy;
  for (const Optimal_curve_level& l : res.report.levels) largest_energy = std::max(largest_energy, l.energy);
  if (std::isfinite(largest_energy) && !std::isfinite(largest_energy * scale))
    throw Invalid_input_error(message("Optimal_curve_2: the energy of the curve (", largest_energy, " at unit extent",
                                      largest_energy > res.report.energy ? ", on a coarser level" : "",
                                      ") overflows double at the points' extent ", r, "; scale the points down"));
  res.report.energy *= scale;
  for (Optimal_curve_level& l : res.report.levels) l.energy *= scale;
  return with_shape(std::move(res));
}

/// solve_optimal_curve after its checks and normalisation: the lambda design (eqs. 10-12) and the
/// hierarchy.
inline Solve_result solve_normalised(const std::vector<Vec2>& points, const Optimal_curve_options& o, bool delivered) {
  const bool lambda_design = o.lambda != -1 || !o.segment_lambda.empty();
  if (!lambda_design) {
    return run_hierarchy(points, o, [&](const std::vector<Vec2>& c, const std::vector<std::size_t>&,
                                        std::vector<double>& beta, std::vector<double>& beta0) {
      beta.assign(o.closed ? c.size() : c.size() - 1, o.length_weight);
      beta0.assign(c.size(), o.curvature_weight);
    }, delivered);
  }
  const std::size_t m = points.size(), segments = o.closed ? m : m - 1;
  std::vector<double> lambda = o.segment_lambda.empty() ? std::vector<double>(segments, o.lambda) : o.segment_lambda;
  if (o.lambda_length_scale > 0)  // q held fixed: no reference curve, no eta
    return run_hierarchy(points, o, [&](const std::vector<Vec2>& c, const std::vector<std::size_t>& interpolation,
                                        std::vector<double>& beta, std::vector<double>& beta0) {
      lambda_weights(c, o.closed, interpolation, lambda, std::vector<double>(), beta, beta0, o.lambda_length_scale);
    }, delivered);
  // The lambda = 1 reference curve (beta = 0, beta0 = 1) for eta of eq. 11; guarded by
  // lambda = 0.99 with q(0) when it has no finite minimiser (diverges).
  Optimal_curve_options ref = o;
  ref.lambda = -1;
  ref.segment_lambda.clear();
  ref.derivative_weight = {{0, 0, 0, 0, 0}};
  ref.length_weight = 0;
  ref.curvature_weight = 1;
  Solve_result reference = solve_normalised(points, ref, false);
  bool guarded = false;
  if (reference.report.status == Status::DIVERGING) {
    ref.length_weight = 0.01 * lambda_scale(0);
    ref.curvature_weight = 0.99;
    reference = solve_normalised(points, ref, false);
    guarded = true;
  }
  // eta from a fair reference only (fair_reference.h): the lambda = 1 curve when it is fair,
  // else the C2 spline through the points.
  const bool fair_reference = reference.report.status != Status::DIVERGING &&
                              is_fair_shape(reference.polygon, o.closed, points, count_self_intersections(points, o.closed));
  const std::vector<double> spline_lengths = fair_reference ? std::vector<double>() : spline_segment_lengths(points, o.closed);
  std::vector<double> eta(segments);
  for (std::size_t i = 0; i < segments; ++i) {
    double length = 0;
    if (fair_reference) {
      const std::size_t a = reference.interpolation_indices[i];
      const std::size_t b = i + 1 < m ? reference.interpolation_indices[i + 1] : reference.polygon.size();
      for (std::size_t v = a; v < b; ++v)
        length += vec::norm(vec::sub(reference.polygon[(v + 1) % reference.polygon.size()], reference.polygon[v]));
    } else {
      length = spline_lengths[i];
    }
    const double chord = vec::norm(vec::sub(points[(i + 1) % m], points[i]));
    eta[i] = std::min(1.0, chord / length);
  }
  Solve_result r = run_hierarchy(points, o, [&](const std::vector<Vec2>& c, const std::vector<std::size_t>& interpolation,
                                                std::vector<double>& beta, std::vector<double>& beta0) {
    lambda_weights(c, o.closed, interpolation, lambda, eta, beta, beta0);
  }, delivered);
  r.eta = eta;
  r.eta_reference_guarded = guarded;
  r.eta_from_spline = !fair_reference;
  // eta is only as good as the reference curve it was measured on: a reference that did not
  // converge (after the guard) makes the whole solve no better than it (reviewer finding 8).
  // A reference replaced by the spline (not fair) does not count.
  if (fair_reference) r.report.status = worse(r.report.status, reference.report.status);
  return r;
}

} // namespace optimal
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_OPTIMAL_HIERARCHY_H
