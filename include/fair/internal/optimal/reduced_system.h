// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The reduced Newton system of a level of the optimal-curve solver (doc/optimal_curves.md, "Level
// solve"). Unknowns: one scalar per free vertex (its offset along the vertex normal n_j, fixed for
// the level unless it is re-anchored, see reanchoring.h) and one per TIE (the two neighbours of a
// single tangent/normal constraint, see constraints.h). Every unknown u_k moves its vertices as
// c_a += u_k v_a, so the reduced gradient is sum_a v_a . g_a and the reduced Hessian
// sum_{a,b} v_a^T H_ab v_b (exact second derivative of u -> F(c + sum u_k v_k), a linear map), plus
// at a tie the curvature term g . R'' of its restoring rotation (add_tie_curvature).
// Unknowns are numbered in vertex order. The reduced system of a closed curve stays CYCLIC even
// though the interpolation points are fixed: kappa_j of a fixed vertex j still couples c_{j-1} and
// c_{j+1} (and the kappa^(k) terms couple up to w vertices across it), so eliminating a fixed vertex
// cuts the ring only where w consecutive vertices are fixed, which never happens here; the banded
// Cholesky of linear_algebra/symmetric_band.h handles the cyclic band in O(n w^2) (folding order).

#ifndef FAIR_INTERNAL_OPTIMAL_REDUCED_SYSTEM_H
#define FAIR_INTERNAL_OPTIMAL_REDUCED_SYSTEM_H

#include <fair/Errors.h>
#include <fair/internal/optimal/constraints.h>
#include <fair/internal/optimal/hessian.h>
#include <fair/internal/optimal/level_problem.h>
#include <fair/internal/optimal/vec2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

/// The unknowns of one step: vertex a moves by u_{var[a]} dir[a] (var[a] = -1: fixed).
struct Reduced_unknowns {
  std::vector<long> var;
  std::vector<Vec2> dir;
  std::size_t count = 0;
  bool cyclic = false;
};

inline Reduced_unknowns reduced_unknowns(const std::vector<Vec2>& c, const std::vector<Vec2>& normals,
                                         const Vertex_roles& roles, bool closed) {
  const std::size_t n = c.size();
  Reduced_unknowns u;
  u.var.assign(n, -1);
  u.dir.assign(n, Vec2{{0, 0}});
  std::vector<long> tie_of(n, -1);  // tie index of a tied neighbour
  for (std::size_t t = 0; t < roles.ties.size(); ++t) {
    const std::size_t j = roles.ties[t].centre;
    const std::size_t a = (j + n - 1) % n, b = (j + 1) % n;
    FAIR_ASSERT(roles.role[a] == Vertex_role::FREE && roles.role[b] == Vertex_role::FREE);
    tie_of[a] = tie_of[b] = static_cast<long>(t);
    // Linearised constraint (see constraints.h): the bisector angle changes by
    // (A delta_b + B delta_a)/2 with A = (u+ x n_b)/l+, B = -(u- x n_a)/l-.
    const Vec2 dm = vec::sub(c[j], c[a]), dp = vec::sub(c[b], c[j]);
    const double lm = vec::norm(dm), lp = vec::norm(dp);
    const double A = vec::cross(dp, normals[b]) / (lp * lp), B = -vec::cross(dm, normals[a]) / (lm * lm);
    const double N = std::hypot(A, B);
    FAIR_ASSERT_MSG(N > 0, "tie at vertex ", j);
    u.dir[b] = {{normals[b][0] * B / N, normals[b][1] * B / N}};
    u.dir[a] = {{-normals[a][0] * A / N, -normals[a][1] * A / N}};
  }
  u.cyclic = closed;
  std::vector<long> tie_var(roles.ties.size(), -1);
  for (std::size_t v = 0; v < n; ++v) {
    if (roles.role[v] == Vertex_role::FIXED) continue;
    if (tie_of[v] >= 0) {
      long& k = tie_var[tie_of[v]];
      if (k < 0) k = static_cast<long>(u.count++);
      u.var[v] = k;
    } else {
      u.var[v] = static_cast<long>(u.count++);
      u.dir[v] = normals[v];
    }
  }
  return u;
}

/// The exact Hessian of u -> F(R(c + u v)) where R restores the ties (constraints.h) has, besides
/// v^T H v, the term g . d^2R/du^2 at every tie unknown: the neighbours move on the circles of the
/// rotation (Fig. 5c), not on the lines v. Without it Newton converges only linearly on designs with
/// interior tangent/normal constraints (up to 71 iterations per level were measured). d^2R/du^2 by a
/// central second difference of R (R depends only on the tie's own three vertices, so there are no
/// cross terms), step 1e-4 of the shorter neighbour edge: truncation ~1e-8, rounding ~1e-8 relative.
inline void add_tie_curvature(const std::vector<Vec2>& c, const std::vector<Vec2>& g, const Reduced_unknowns& u,
                              const Vertex_roles& roles, Banded_symmetric& rh) {
  const std::size_t n = c.size();
  for (const Vertex_roles::Tie& t : roles.ties) {
    const std::size_t j = t.centre, a = (j + n - 1) % n, b = (j + 1) % n;
    const long k = u.var[a];
    if (k < 0) continue;
    const double l = std::min(vec::norm(vec::sub(c[j], c[a])), vec::norm(vec::sub(c[b], c[j])));
    const double move = std::max(vec::norm(u.dir[a]), vec::norm(u.dir[b]));
    if (!(l > 0 && move > 0)) continue;
    const double step = 1e-4 * l / move;
    // Differenced in a frame centred on the tie: in absolute coordinates the rounding of
    // plus + minus - 2c grows like eps |c| / l (wrong signs for short edges far from the origin).
    std::vector<Vec2> local = c;
    for (Vec2& q : local) q = vec::sub(q, c[j]);
    std::vector<Vec2> plus = local, minus = local;
    for (std::size_t v : {a, b})
      for (int r = 0; r < 2; ++r) {
        plus[v][r] += step * u.dir[v][r];
        minus[v][r] -= step * u.dir[v][r];
      }
    Vertex_roles one = roles;
    one.ties.assign(1, t);
    restore_ties(one, plus);
    restore_ties(one, minus);
    double term = 0;
    for (std::size_t v : {a, b})
      for (int r = 0; r < 2; ++r) term += g[v][r] * (plus[v][r] + minus[v][r] - 2 * local[v][r]) / (step * step);
    rh.at(static_cast<std::size_t>(k), static_cast<std::size_t>(k)) += term;
  }
}

/// Index distance of two unknowns in the reduced system.
inline std::size_t unknown_distance(const Reduced_unknowns& u, long k, long l) {
  const std::size_t d = static_cast<std::size_t>(k > l ? k - l : l - k);
  return u.cyclic ? std::min(d, u.count - d) : d;
}

/// Calls f(a, b) for every ordered pair of vertices within the Hessian's band (each pair once).
template <class Fn>
void for_band_pairs(std::size_t n, std::size_t w, bool closed, Fn f) {
  for (std::size_t a = 0; a < n; ++a) {
    if (!closed || 2 * w + 1 >= n) {
      const std::size_t lo = closed ? 0 : (a > w ? a - w : 0), hi = closed ? n - 1 : std::min(n - 1, a + w);
      for (std::size_t b = lo; b <= hi; ++b) f(a, b);
    } else {
      for (std::size_t d = 0; d <= 2 * w; ++d) f(a, (a + n - w + d) % n);
    }
  }
}

/// The reduced gradient and Hessian (see the file comment).
inline void reduced_system(const std::vector<Vec2>& g, const Block_banded_hessian& h, bool closed,
                           const Reduced_unknowns& u, std::vector<double>& rg, Banded_symmetric& rh) {
  const std::size_t n = g.size(), w = h.half_bandwidth();
  rg.assign(u.count, 0);
  for (std::size_t a = 0; a < n; ++a)
    if (u.var[a] >= 0) rg[u.var[a]] += vec::dot(u.dir[a], g[a]);
  auto block_form = [&](std::size_t a, std::size_t b) {
    double s = 0;
    for (int r = 0; r < 2; ++r)
      for (int q = 0; q < 2; ++q) s += u.dir[a][r] * h.at(a, b, r, q) * u.dir[b][q];
    return s;
  };
  std::size_t wr = 0;
  for_band_pairs(n, w, closed, [&](std::size_t a, std::size_t b) {
    if (u.var[a] >= 0 && u.var[b] >= 0) wr = std::max(wr, unknown_distance(u, u.var[a], u.var[b]));
  });
  if (u.count == 0) { rh.reset(0, 0, false); return; }
  // Accumulate in a private band (rows k, offsets -wr..wr) so that the storage convention of
  // Banded_symmetric (one or two triangles) does not matter.
  const std::size_t width = 2 * wr + 1;
  std::vector<double> band(u.count * width, 0.0);
  auto offset = [&](long k, long l) -> std::size_t {
    long d = l - k;
    if (u.cyclic) {
      const long m = static_cast<long>(u.count);
      if (d > static_cast<long>(wr)) d -= m;
      if (d < -static_cast<long>(wr)) d += m;
      if (2 * (-d) == m) d = -d;  // the antipodal pair of an even ring: one slot
    }
    return static_cast<std::size_t>(d + static_cast<long>(wr));
  };
  for_band_pairs(n, w, closed, [&](std::size_t a, std::size_t b) {
    if (u.var[a] >= 0 && u.var[b] >= 0) band[u.var[a] * width + offset(u.var[a], u.var[b])] += block_form(a, b);
  });
  rh.reset(u.count, wr, u.cyclic);
  for (std::size_t k = 0; k < u.count; ++k)
    for (std::size_t o = wr; o < width; ++o) {
      const long l = static_cast<long>(k) + static_cast<long>(o - wr);
      const std::size_t m = u.count;
      if (!u.cyclic && l >= static_cast<long>(m)) break;
      if (u.cyclic && o > wr && 2 * (o - wr) > m) break;  // each cyclic pair once
      const std::size_t ll = static_cast<std::size_t>(l) % m;
      if (u.cyclic && o > wr && 2 * (o - wr) == m && ll < k) continue;
      rh.at(k, ll) = band[k * width + o];
    }
}

/// c + t * (the displacement of the unknowns x), with the ties restored.
inline std::vector<Vec2> displaced(const std::vector<Vec2>& c, const Reduced_unknowns& u, const std::vector<double>& x,
                                   double t, const Vertex_roles& roles) {
  std::vector<Vec2> d = c;
  for (std::size_t a = 0; a < c.size(); ++a)
    if (u.var[a] >= 0) {
      const double s = t * x[u.var[a]];
      d[a][0] += s * u.dir[a][0];
      d[a][1] += s * u.dir[a][1];
    }
  restore_ties(roles, d);
  return d;
}

inline double dot_product(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t k = 0; k < a.size(); ++k) s += a[k] * b[k];
  return s;
}

/// The Euclidean norm of v, scaled by its largest magnitude so that it overflows only when the norm
/// itself does: sqrt(dot_product(v, v)) is inf once a component passes 1e154 (fuzz finding
/// optimal/regress-gradient-norm-overflow: a derivative weight of 3e209 gives reduced gradients
/// near 1e200). Relative error a few ulps (n additions of values <= 1).
inline double euclidean_norm(const std::vector<double>& v) {
  double largest = 0;
  for (const double a : v) largest = std::max(largest, std::abs(a));
  if (largest == 0 || !std::isfinite(largest)) return largest;
  double s = 0;
  for (const double a : v) s += (a / largest) * (a / largest);
  return largest * std::sqrt(s);
}

/// x^T RH x for the reduced banded matrix.
inline double reduced_form(const Banded_symmetric& rh, const std::vector<double>& x) {
  const std::size_t m = x.size(), w = rh.half_bandwidth();
  double s = 0;
  for (std::size_t k = 0; k < m; ++k) {
    s += rh.at(k, k) * x[k] * x[k];
    for (std::size_t d = 1; d <= w; ++d) {
      if (!rh.cyclic() && k + d >= m) break;
      if (rh.cyclic() && 2 * d > m) break;
      const std::size_t l = (k + d) % m;
      s += (2 * d == m ? 1.0 : 2.0) * rh.at(k, l) * x[k] * x[l];
    }
  }
  return s;
}

/// What a step of solve_level sees: the level's problem and constraints, the polygon, its reduced
/// unknowns, and F with its reduced gradient and Hessian there (scale: max(|F|, DBL_MIN), the
/// reference of the relative tests).
struct Level_iterate {
  const Level_problem& problem;
  const Vertex_roles& roles;
  const std::vector<Vec2>& polygon;
  const Reduced_unknowns& unknowns;
  const std::vector<double>& gradient;
  const Banded_symmetric& hessian;
  double energy, scale;
};

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_REDUCED_SYSTEM_H
