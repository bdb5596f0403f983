// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Constraints of Gumhold's optimal curves (Sec. 3.1) as roles of the polygon vertices, and the
// initial polygon that satisfies them (doc/optimal_curves.md, "Constraints"):
//  - an interpolation point is FIXED;
//  - CORNER at point i: kappa_i = 0 (natural boundary, Sec. 3.1) and its two polygon neighbours
//    FIXED on the rays c_i - r t_in and c_i + r t_out (Fig. 5a). After a subdivision the new
//    neighbours (edge midpoints, so on the rays again) are fixed and the old ones freed (Fig. 5b):
//    the tangents hold exactly at every level; the curve is pinned to a point at distance h (the
//    current neighbour edge) on the ray, which moves the curve by O(h^2), the discretisation order.
//    (Letting the neighbours slide on the rays instead fails on coarse levels: an end neighbour
//    slides into the end point, where an open curve has no curvature term, and the level degenerates.)
//  - TANGENT/NORMAL (or a one-sided CORNER) at an open end: a clamped end, a fixed ghost vertex on
//    the tangent behind the end gives the end its curvature term (level_problem.h, Level_problem).
//  - TANGENT/NORMAL at an interior point j: a TIE. Both neighbours move along their normals with
//    offsets tied by the linearised constraint "the bisector of the unit edge directions keeps
//    its angle" (one unknown for the two), and after every step both are rotated about c_j so that
//    the constraint holds exactly again (the rotation of Fig. 5c; it changes nothing to first
//    order, so Newton keeps its local convergence).
// The initial polygon splits each edge incident to a constrained point at a third of its length
// from that point, on the constrained direction (Sec. 3.1: "all edges incident to a single or
// double normal constraint were split").

#ifndef FAIR_INTERNAL_OPTIMAL_CONSTRAINTS_H
#define FAIR_INTERNAL_OPTIMAL_CONSTRAINTS_H

#include <fair/Errors.h>
#include <fair/Optimal_curve_options.h>
#include <fair/internal/optimal/functional.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {


enum class Vertex_role : unsigned char { FREE, FIXED };

/// Roles of the vertices of one level polygon.
struct Vertex_roles {
  std::vector<Vertex_role> role;   // per vertex
  std::vector<unsigned char> zero_curvature;  // per vertex (corner points)
  struct Tie { std::size_t centre; Vec2 tangent; };  // tangent: unit direction of travel at centre
  std::vector<Tie> ties;
  bool ghost_front = false, ghost_back = false;  // clamped open ends
  Vec2 front_tangent{{1, 0}}, back_tangent{{1, 0}};
};


/// A constraint in polygon terms: tangent(s) at polygon vertex `vertex` (the point itself).
struct Placed_constraint {
  std::size_t vertex;
  bool corner;
  Vec2 in, out;  // unit tangents (equal unless corner)
};

/// Checks the constraints against the points (typed errors naming the value), converts NORMAL to
/// TANGENT (t = (n_y, -n_x), the inverse of n = (-t_y, t_x)), normalises.
inline std::vector<Placed_constraint> check_constraints(const std::vector<Point_constraint>& constraints,
                                                        const std::vector<Vec2>& points, bool closed) {
  const char* fn = "fair::Optimal_curve_2";
  const std::size_t m = points.size();
  std::vector<Placed_constraint> out;
  std::vector<unsigned char> seen(m, 0);
  for (const Point_constraint& c : constraints) {
    if (c.index >= m)
      throw Invalid_input_error(message(fn, ": constraint at point ", c.index, " is out of range (", m, " points)"));
    if (seen[c.index]) throw Invalid_input_error(message(fn, ": two constraints at point ", c.index));
    seen[c.index] = 1;
    const bool corner = c.kind == Point_constraint_kind::CORNER;
    Vec2 d = c.direction, o = corner ? c.outgoing : c.direction;
    if (c.kind == Point_constraint_kind::NORMAL) { d = {{c.direction[1], -c.direction[0]}}; o = d; }
    if (!std::isfinite(d[0]) || !std::isfinite(d[1]) || !std::isfinite(o[0]) || !std::isfinite(o[1]) ||
        vec::norm(d) == 0 || vec::norm(o) == 0)
      throw Invalid_input_error(message(fn, ": constraint at point ", c.index, " has a zero or non-finite direction (",
                                        c.direction[0], ", ", c.direction[1], ")",
                                        corner ? message(" / (", c.outgoing[0], ", ", c.outgoing[1], ")") : std::string()));
    d = vec::unit(d);
    o = vec::unit(o);
    const bool interior = closed || (c.index > 0 && c.index + 1 < m);
    if (interior && !corner) {
      // Three collinear points p_{i-1}, p_i, p_{i+1} with p_i between them and the tangent across
      // the line: the curve would have to turn by pi/2 and back within the segment: reject, as
      // the issue asks ("a normal on a collinear triple that cannot be met").
      const Vec2 a = vec::sub(points[c.index], points[(c.index + m - 1) % m]);
      const Vec2 b = vec::sub(points[(c.index + 1) % m], points[c.index]);
      const double scale = vec::norm(a) * vec::norm(b);
      if (std::abs(vec::cross(a, b)) <= 1e-12 * scale && vec::dot(a, b) > 0 && std::abs(vec::dot(d, vec::unit(a))) <= 1e-12)
        throw Invalid_input_error(message(fn, ": the tangent constraint (", d[0], ", ", d[1], ") at point ", c.index,
                                          " is perpendicular to the line of the collinear points ", (c.index + m - 1) % m,
                                          ", ", c.index, ", ", (c.index + 1) % m, ": it cannot be met"));
    }
    if (interior && !corner) {
      // A tangent exactly against an incident chord: the initial split point (initial_polygon) lies
      // on that chord behind the point, the polygon folds back by pi there and the neighbour has no
      // normal to move along.
      const Vec2 a = vec::sub(points[c.index], points[(c.index + m - 1) % m]);
      const Vec2 b = vec::sub(points[(c.index + 1) % m], points[c.index]);
      const bool back_a = vec::dot(d, a) < 0 && std::abs(vec::cross(d, a)) <= 1e-12 * vec::norm(a);
      const bool back_b = vec::dot(d, b) < 0 && std::abs(vec::cross(d, b)) <= 1e-12 * vec::norm(b);
      if (back_a || back_b)
        throw Invalid_input_error(message(fn, ": the tangent constraint (", d[0], ", ", d[1], ") at point ", c.index,
                                          " points back along the chord (", back_a ? a[0] : b[0], ", ", back_a ? a[1] : b[1],
                                          ") ", back_a ? "from the previous" : "to the next", " point: the solver's start polygon folds back there (a limitation of the start, not of the design; "
                                          "tilting the tangent by 1e-11 is enough)"));
    }
    out.push_back({c.index, corner, d, o});
  }
  return out;
}

/// The initial polygon (the input points with the constrained edges split, see the file comment),
/// the polygon index of every input point, and the constraints placed on the polygon.
inline std::vector<Vec2> initial_polygon(const std::vector<Vec2>& points, bool closed,
                                         std::vector<Placed_constraint>& placed,
                                         std::vector<std::size_t>& interpolation) {
  const std::size_t m = points.size();
  std::vector<int> at(m, -1);
  for (std::size_t k = 0; k < placed.size(); ++k) at[placed[k].vertex] = static_cast<int>(k);
  std::vector<Vec2> c;
  interpolation.assign(m, 0);
  const std::size_t edges = closed ? m : m - 1;
  for (std::size_t i = 0; i < m; ++i) {
    interpolation[i] = c.size();
    c.push_back(points[i]);
    if (i >= edges) break;
    const Vec2& p = points[i];
    const Vec2& q = points[(i + 1) % m];
    const double l = vec::norm(vec::sub(q, p));
    const bool inner_i = closed || i > 0, inner_next = closed || i + 2 < m;  // open ends are not split
    if (at[i] >= 0 && inner_i) {
      const Vec2& t = placed[at[i]].out;
      c.push_back({{p[0] + t[0] * l / 3, p[1] + t[1] * l / 3}});
    }
    const int j = at[(i + 1) % m];
    if (j >= 0 && inner_next) {
      const Vec2& t = placed[j].in;
      c.push_back({{q[0] - t[0] * l / 3, q[1] - t[1] * l / 3}});
    }
  }
  for (std::size_t k = 0; k < placed.size(); ++k) placed[k].vertex = interpolation[placed[k].vertex];
  return c;
}

/// Roles of the vertices of the polygon `c` whose interpolation points are at `interpolation`.
inline Vertex_roles vertex_roles(std::size_t n, bool closed, const std::vector<std::size_t>& interpolation,
                                 const std::vector<Placed_constraint>& placed) {
  Vertex_roles r;
  r.role.assign(n, Vertex_role::FREE);
  r.zero_curvature.assign(n, 0);
  for (std::size_t v : interpolation) r.role[v] = Vertex_role::FIXED;
  for (const Placed_constraint& p : placed) {
    const std::size_t v = p.vertex;
    const bool first = !closed && v == 0, last = !closed && v + 1 == n;
    if (first) {
      r.ghost_front = true;
      r.front_tangent = p.out;
    } else if (last) {
      r.ghost_back = true;
      r.back_tangent = p.in;
    } else if (p.corner) {
      r.zero_curvature[v] = 1;
      r.role[(v + 1) % n] = Vertex_role::FIXED;
      r.role[(v + n - 1) % n] = Vertex_role::FIXED;
    } else {
      r.ties.push_back({v, p.in});
    }
  }
  return r;
}

/// Rotates the two neighbours of every tie about its centre so that the bisector of the unit
/// edge directions is the constrained tangent again (exact up to rounding).
inline void restore_ties(const Vertex_roles& r, std::vector<Vec2>& c) {
  const std::size_t n = c.size();
  for (const Vertex_roles::Tie& t : r.ties) {
    const std::size_t j = t.centre, a = (j + n - 1) % n, b = (j + 1) % n;
    const Vec2 u = vec::unit(vec::sub(c[j], c[a])), w = vec::unit(vec::sub(c[b], c[j]));
    const Vec2 bis = {{u[0] + w[0], u[1] + w[1]}};
    if (vec::norm(bis) == 0) continue;  // a cusp: no bisector; the energy rejects such steps
    const double angle = std::atan2(vec::cross(bis, t.tangent), vec::dot(bis, t.tangent));
    const double cs = std::cos(angle), sn = std::sin(angle);
    for (std::size_t k : {a, b}) {
      const Vec2 d = vec::sub(c[k], c[j]);
      c[k] = {{c[j][0] + cs * d[0] - sn * d[1], c[j][1] + sn * d[0] + cs * d[1]}};
    }
  }
}

} // namespace optimal
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_OPTIMAL_CONSTRAINTS_H
