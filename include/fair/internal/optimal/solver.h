// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The level optimiser of Gumhold's optimal curves (Sec. 2.3.2, replaced by Newton as issue 11
// asks; doc/optimal_curves.md, "Level solve"). Unknowns: one scalar per free vertex (its
// offset along the vertex normal n_j, fixed for the level unless it is re-anchored, see solve_level) and one per TIE
// (the two neighbours of a single tangent/normal constraint, see constraints.h). Every unknown u_k moves its vertices as
// c_a += u_k v_a, so the reduced gradient is sum_a v_a . g_a and the reduced Hessian
// sum_{a,b} v_a^T H_ab v_b (exact second derivative of u -> F(c + sum u_k v_k), a linear map), plus
// at a tie the curvature term g . R'' of its restoring rotation (add_tie_curvature).
// Unknowns are numbered in vertex order. The reduced system of a closed curve stays CYCLIC even
// though the interpolation points are fixed: kappa_j of a fixed vertex j still couples c_{j-1} and
// c_{j+1} (and the kappa^(k) terms couple up to w vertices across it), so eliminating a fixed vertex
// cuts the ring only where w consecutive vertices are fixed, which never happens here; the banded
// Cholesky of functional.h/banded.h handles the cyclic band in O(n w^2) (folding order).
//
// Newton: solve (H + mu I) d = -g with mu = 0, else mu from 1e-10 max|H_kk| up by x10 until the
// banded Cholesky succeeds (capped); stop when the Newton decrement g^T d / 2 (the predicted
// decrease) is <= tolerance |F|; Armijo backtracking (c1 = 1e-4, halving, capped).
// CONJUGATE_GRADIENT: Polak-Ribiere+ on the same unknowns, the step found by at most ten
// Newton-Raphson steps on F(sigma) (the paper's line search), Armijo-guarded.

#ifndef FAIR_INTERNAL_OPTIMAL_SOLVER_H
#define FAIR_INTERNAL_OPTIMAL_SOLVER_H

#include <fair/Errors.h>
#include <fair/Optimal_curve_options.h>
#include <fair/Optimal_curve_report.h>
#include <fair/internal/optimal/constraints.h>
#include <fair/internal/optimal/functional.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

typedef fair::Optimal_curve_status Status;

/// Most diagonal shifts tried before giving up on a Newton step (mu grows x10 from 1e-10 max|H_kk|:
/// 30 tries reach 1e20 max|H_kk|, far beyond any Hessian of a finite polygon).
constexpr int max_shifts = 30;
/// Most halvings of the Armijo line search (2^-60 ~ 1e-18: below rounding of any step).
constexpr int max_backtracks = 60;
/// Armijo sufficient-decrease constant.
constexpr double armijo_c1 = 1e-4;
/// A polygon whose bounding-box extent exceeds this multiple of the input's is diverging.
constexpr double divergence_extent_factor = 1e3;
/// An edge (with a free end) shorter than this fraction of the extent is degenerate: the level stops CAPPED.
constexpr double degenerate_edge_fraction = 1e-12;
/// When no Armijo step decreases F any more, the level counts as converged if the predicted
/// decrease is below this fraction of |F| (the rounding floor of F's evaluation at large n).
constexpr double rounding_floor = 1e-8;
/// Largest move of a vertex in one step, as a fraction of its shorter incident edge.
constexpr double max_step_fraction = 0.5;
/// A level ending on its iteration cap with its extent grown by this factor since its start, and
/// by still_growing since half its iterations, is DIVERGING (else CAPPED).
constexpr double runaway_growth = 4;
constexpr double still_growing = 1.5;
/// Re-anchoring (see solve_level): an edge shorter than this fraction of its length at the last
/// anchor means the fixed lines of motion have crowded its vertices together.
constexpr double anchor_shrink = 0.5;
/// Most re-anchorings of one level.
constexpr int max_reanchors = 50;
/// Newton-Raphson steps of the CG line search (the paper: "a maximum of ten").
constexpr int cg_line_search_steps = 10;

struct Level_settings {
  bool conjugate_gradient = false;
  std::size_t max_iterations = 100;
  double tolerance = 1e-10;
  double max_extent = std::numeric_limits<double>::infinity();  // divergence cap
  bool fixed_normals = true;  // lines of motion fixed for the whole level (see solve_level)
};

struct Level_outcome {
  std::size_t iterations = 0;
  double energy = 0, gradient_norm = 0;
  Status status = Status::CAPPED;
};

/// Distance of the ghost vertex behind a clamped open end, as a fraction of L0 (see Level_problem):
/// small enough that its half-edge adds a negligible 1e-6 L0 / l_end to the end's arc element, large
/// enough that the ghost edge direction is exact to ~1e-10 for data of extent ~ L0.
constexpr double ghost_fraction = 1e-6;

/// The functional of one level, with the clamped open ends of constraints.h: a tangent t at an
/// open end p_0 adds a FIXED ghost vertex p_0 - eps t (eps = ghost_fraction L0) before it (after
/// it at the last end), its edge weighted 0 and the ghost itself without curvature. The end vertex
/// then carries the curvature term phi_0 / (s_0 cos(phi_0/2.1)) with phi_0 the angle between t and
/// the first edge and s_0 = (eps + l_0)/2 ~ l_0/2: a consistent discretisation of kappa at a clamped
/// end (for a smooth curve phi_0 = kappa l_0/2 + O(l_0^2)), where fixing the end's neighbour on
/// the tangent (as for corners) would force kappa = 0 on the first edge and cost O(h) in F. The
/// derivative terms whose stencil reaches the ghost are absent (it has no curvature), so the tiny
/// ghost edge never enters a difference quotient.
struct Level_problem {
  Functional f;  // on the level polygon (n vertices)
  bool ghost_front = false, ghost_back = false;
  Vec2 front_tangent{{1, 0}}, back_tangent{{1, 0}};
  Functional augmented;  // f on the polygon with the ghosts (prepare())

  bool ghosts() const { return ghost_front || ghost_back; }
  /// Builds `augmented` from f (call after setting f's weights).
  void prepare() {
    if (!ghosts()) return;
    augmented = f;
    const double zero = 0;
    if (ghost_front) {
      augmented.length_weight.insert(augmented.length_weight.begin(), zero);
      augmented.curvature_weight.insert(augmented.curvature_weight.begin(), zero);
      if (!augmented.zero_curvature.empty()) augmented.zero_curvature.insert(augmented.zero_curvature.begin(), 0);
    }
    if (ghost_back) {
      augmented.length_weight.push_back(zero);
      augmented.curvature_weight.push_back(zero);
      if (!augmented.zero_curvature.empty()) augmented.zero_curvature.push_back(0);
    }
  }
  std::size_t offset() const { return ghost_front ? 1 : 0; }
  std::vector<Vec2> extend(const std::vector<Vec2>& c) const {
    if (!ghosts()) return c;
    const double e = ghost_fraction * f.reference_length;
    std::vector<Vec2> d;
    d.reserve(c.size() + 2);
    if (ghost_front) d.push_back({{c.front()[0] - e * front_tangent[0], c.front()[1] - e * front_tangent[1]}});
    d.insert(d.end(), c.begin(), c.end());
    if (ghost_back) d.push_back({{c.back()[0] + e * back_tangent[0], c.back()[1] + e * back_tangent[1]}});
    return d;
  }
  std::vector<double> strip(const std::vector<double>& v, std::size_t n) const {
    return std::vector<double>(v.begin() + offset(), v.begin() + offset() + n);
  }
};

inline double problem_energy(const Level_problem& p, const std::vector<Vec2>& c) {
  return p.ghosts() ? energy(p.augmented, p.extend(c)) : energy(p.f, c);
}
inline double problem_energy_and_gradient(const Level_problem& p, const std::vector<Vec2>& c, std::vector<Vec2>& g) {
  if (!p.ghosts()) return energy_and_gradient(p.f, c, g);
  std::vector<Vec2> ga;
  const double e = energy_and_gradient(p.augmented, p.extend(c), ga);
  g.assign(ga.begin() + p.offset(), ga.begin() + p.offset() + c.size());
  return e;
}
inline double problem_energy_gradient_hessian(const Level_problem& p, const std::vector<Vec2>& c, std::vector<Vec2>& g,
                                              Block_banded_hessian& h) {
  if (!p.ghosts()) return energy_gradient_hessian(p.f, c, g, h);
  std::vector<Vec2> ga;
  Block_banded_hessian ha;
  const double e = energy_gradient_hessian(p.augmented, p.extend(c), ga, ha);
  const std::size_t n = c.size(), o = p.offset(), w = ha.half_bandwidth();
  g.assign(ga.begin() + o, ga.begin() + o + n);
  h.reset(n, w, false);  // ghosts only on open curves
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n && j <= i + w; ++j)
      for (int r = 0; r < 2; ++r)
        for (int q = 0; q < 2; ++q) h.at(i, j, r, q) = ha.at(i + o, j + o, r, q);
  return e;
}
/// The discrete curvature at every vertex of the level polygon (clamped ends: their kappa).
inline std::vector<double> problem_curvatures(const Level_problem& p, const std::vector<Vec2>& c) {
  return p.ghosts() ? p.strip(discrete_curvatures(p.augmented, p.extend(c)), c.size()) : discrete_curvatures(p.f, c);
}

inline double polygon_extent(const std::vector<Vec2>& c) {
  double x0 = c[0][0], x1 = x0, y0 = c[0][1], y1 = y0;
  for (const Vec2& p : c) {
    x0 = std::min(x0, p[0]); x1 = std::max(x1, p[0]);
    y0 = std::min(y0, p[1]); y1 = std::max(y1, p[1]);
  }
  return std::max(x1 - x0, y1 - y0);
}

/// The shortest edge with at least one free end (edges between two fixed vertices do not move).
inline double free_min_edge(const std::vector<Vec2>& c, bool closed, const Vertex_roles& roles) {
  const std::size_t n = c.size(), e = closed ? n : n - 1;
  double m = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < e; ++j)
    if (roles.role[j] == Vertex_role::FREE || roles.role[(j + 1) % n] == Vertex_role::FREE)
      m = std::min(m, vec::norm(vec::sub(c[(j + 1) % n], c[j])));
  return m;
}

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

/// F at c, +infinity where the functional rejects the polygon (its Invalid_input_error: coincident
/// vertices after a step, overflow); any other error (an Internal_error) propagates.
inline double energy_or_infinity(const Level_problem& p, const std::vector<Vec2>& c) {
  try {
    const double e = problem_energy(p, c);
    return std::isfinite(e) ? e : std::numeric_limits<double>::infinity();
  } catch (const Invalid_input_error&) {
    return std::numeric_limits<double>::infinity();
  }
}

/// Solves (rh + mu I) x = rhs with the smallest shift mu of the ladder that makes it positive
/// definite; false if none does. `shift` returns mu relative to the smallest |rh_kk| (0 if unshifted).
inline bool shifted_solve(const Banded_symmetric& rh, std::vector<double>& x, double& shift) {
  double diag = 0, smallest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < x.size(); ++k) {
    diag = std::max(diag, std::abs(rh.at(k, k)));
    smallest = std::min(smallest, std::abs(rh.at(k, k)));
  }
  if (!(diag > 0)) diag = 1;
  const std::vector<double> rhs = x;
  double mu = 0;
  for (int s = 0; s <= max_shifts; ++s) {
    Banded_symmetric a = rh;
    if (mu > 0) a.add_to_diagonal(mu);
    x = rhs;
    if (solve_banded_positive_definite(a, x)) {
      shift = mu == 0 ? 0.0 : smallest > 0 ? mu / smallest : std::numeric_limits<double>::infinity();
      return true;
    }
    mu = mu == 0 ? 1e-10 * diag : 10 * mu;
  }
  return false;
}

/// A Newton decrement computed with a shift larger than this fraction of the smallest diagonal entry
/// of the reduced Hessian does not certify convergence (the shift, relative to the largest entry,
/// can swamp the soft unknowns: the step and the decrement become negligible far from a minimiser).
constexpr double converged_shift = 1e-6;

inline double dot_product(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t k = 0; k < a.size(); ++k) s += a[k] * b[k];
  return s;
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

/// The largest t <= 1 (or more) with |t x_k v_a| <= max_step_fraction * min(l_{a-1}, l_a) at
/// every moved vertex a.
inline double step_cap(const std::vector<Vec2>& c, bool closed, const Reduced_unknowns& u, const std::vector<double>& x) {
  const std::size_t n = c.size();
  double cap = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < n; ++a) {
    if (u.var[a] < 0) continue;
    double l = std::numeric_limits<double>::infinity();
    if (closed || a > 0) l = std::min(l, vec::norm(vec::sub(c[a], c[(a + n - 1) % n])));
    if (closed || a + 1 < n) l = std::min(l, vec::norm(vec::sub(c[(a + 1) % n], c[a])));
    const double move = std::abs(x[u.var[a]]) * vec::norm(u.dir[a]);
    if (move > 0) cap = std::min(cap, max_step_fraction * l / move);
  }
  return cap;
}

inline std::vector<double> edge_lengths(const std::vector<Vec2>& c, bool closed) {
  const std::size_t n = c.size(), e = closed ? n : n - 1;
  std::vector<double> l(e);
  for (std::size_t j = 0; j < e; ++j) l[j] = vec::norm(vec::sub(c[(j + 1) % n], c[j]));
  return l;
}

/// True if some edge of `c` is shorter than anchor_shrink times its length `anchor[j]` at the last anchor.
inline bool crowded(const std::vector<Vec2>& c, bool closed, const std::vector<double>& anchor) {
  const std::vector<double> l = edge_lengths(c, closed);
  for (std::size_t j = 0; j < l.size(); ++j)
    if (l[j] < anchor_shrink * anchor[j]) return true;
  return false;
}

/// Slides the free vertices of every chain between two consecutive FIXED vertices along the current
/// polygon (linear interpolation in arc length) so that the chain's edges have the length fractions
/// `fractions` had (the level's start: the adaptive spacing the subdivision chose), then restores the
/// ties. A tangential move: the polygon's shape is kept up to O(h^2) chord errors.
inline void redistribute(std::vector<Vec2>& c, bool closed, const std::vector<double>& fractions, const Vertex_roles& roles) {
  const std::size_t n = c.size(), edges = closed ? n : n - 1;
  std::size_t first = n;
  for (std::size_t v = 0; v < n && first == n; ++v)
    if (roles.role[v] == Vertex_role::FIXED) first = v;
  if (first == n) return;
  const std::vector<Vec2> old = c;
  std::size_t a = first;
  for (std::size_t done = 0; done < edges;) {
    std::size_t m = 1;  // edges of the chain a -> a + m
    while (roles.role[(a + m) % n] != Vertex_role::FIXED && done + m < edges) ++m;
    if (m > 1) {
      double total = 0, target = 0;
      for (std::size_t k = 0; k < m; ++k) { total += vec::norm(vec::sub(old[(a + k + 1) % n], old[(a + k) % n])); target += fractions[(a + k) % n]; }
      double along = 0, walked = 0;
      std::size_t e = 0;  // current old edge of the chain
      for (std::size_t k = 1; k < m; ++k) {
        along += fractions[(a + k - 1) % n] / target * total;
        for (;;) {
          const double l = vec::norm(vec::sub(old[(a + e + 1) % n], old[(a + e) % n]));
          if (walked + l >= along || e + 1 == m) {
            const double t = l > 0 ? std::min(1.0, std::max(0.0, (along - walked) / l)) : 0.0;
            const Vec2& p = old[(a + e) % n];
            const Vec2& q = old[(a + e + 1) % n];
            c[(a + k) % n] = {{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])}};
            break;
          }
          walked += l;
          ++e;
        }
      }
    }
    done += m;
    a = (a + m) % n;
  }
  restore_ties(roles, c);
}

/// Minimises F over the free unknowns of `c` (in place).
inline Level_outcome solve_level(const Level_problem& p, const Vertex_roles& roles, const Level_settings& s,
                                 std::vector<Vec2>& c) {
  const Functional& f = p.f;
  Level_outcome out;
  std::vector<Vec2> g;
  Block_banded_hessian h;
  Banded_symmetric rh;
  std::vector<double> rg, x, previous_g, direction;
  std::vector<Vec2> normals;
  const double inf = std::numeric_limits<double>::infinity();
  const double start_extent = polygon_extent(c);
  const std::vector<double> fractions = edge_lengths(c, f.closed);
  std::vector<double> anchor = fractions;
  double half_way_extent = 0;  // the extent after half the iteration cap (runaway test)
  int reanchors = 0;
  bool reanchored = false;
  for (std::size_t it = 0;; ++it) {
    const double e = problem_energy_gradient_hessian(p, c, g, h);
    out.energy = e;
    // The lines of motion: normals of the level's start polygon (s.fixed_normals) or of the
    // current polygon (recomputed after every step, the paper's choice).
    if (it == 0 || !s.fixed_normals || reanchored) normals = vertex_normals(c, f.closed);
    reanchored = false;
    const Reduced_unknowns u = reduced_unknowns(c, normals, roles, f.closed);
    reduced_system(g, h, f.closed, u, rg, rh);
    if (!s.conjugate_gradient) add_tie_curvature(c, g, u, roles, rh);
    out.gradient_norm = std::sqrt(dot_product(rg, rg));
    out.iterations = it;
    const double scale = std::max(std::abs(e), std::numeric_limits<double>::min());
    if (u.count == 0 || out.gradient_norm == 0) { out.status = Status::CONVERGED; return out; }
    if (it == s.max_iterations / 2) half_way_extent = polygon_extent(c);
    if (it >= s.max_iterations) {
      // A level that ends on the cap with its extent grown many times, and still growing over
      // the second half of its iterations, is running away; one that grew and then settled
      // (a nearly collinear start bulging out to its minimiser) is only CAPPED.
      const double extent = polygon_extent(c);
      const bool runaway = extent > runaway_growth * start_extent && extent > still_growing * half_way_extent;
      out.status = runaway ? Status::DIVERGING : Status::CAPPED;
      return out;
    }
    double decrement;  // predicted decrease of a full step
    if (!s.conjugate_gradient) {
      x.assign(rg.size(), 0);
      for (std::size_t k = 0; k < rg.size(); ++k) x[k] = -rg[k];
      double shift = 0;
      if (!shifted_solve(rh, x, shift)) { out.status = Status::CAPPED; return out; }
      decrement = -dot_product(rg, x);
      if (0.5 * decrement <= s.tolerance * scale && shift <= converged_shift) {
        // Converged: still take this last (tiny) Newton step when it does not raise F beyond
        // rounding: it is free (already solved) and squares the remaining error.
        const std::vector<Vec2> last = displaced(c, u, x, 1.0, roles);
        const double el = energy_or_infinity(p, last);
        if (el <= e + 1e-14 * scale) { c = last; out.energy = el; out.iterations = it + 1; }
        out.status = Status::CONVERGED;
        return out;
      }
    } else {
      // Polak-Ribiere+ direction (restart when the number of unknowns changed or it is not descent).
      double beta = 0;
      if (previous_g.size() == rg.size() && direction.size() == rg.size()) {
        double num = 0;
        for (std::size_t k = 0; k < rg.size(); ++k) num += rg[k] * (rg[k] - previous_g[k]);
        beta = std::max(0.0, num / dot_product(previous_g, previous_g));
      } else {
        direction.assign(rg.size(), 0);
      }
      for (std::size_t k = 0; k < rg.size(); ++k) direction[k] = -rg[k] + beta * direction[k];
      if (dot_product(direction, rg) >= 0)
        for (std::size_t k = 0; k < rg.size(); ++k) direction[k] = -rg[k];
      previous_g = rg;
      // Newton-Raphson on phi(sigma) = F(c + sigma d): phi'(0) = g.d, phi''(0) = d^T H d; later
      // steps use the secant of phi' (the gradient at the trial point).
      const double d1 = dot_product(rg, direction), d2 = reduced_form(rh, direction);
      double sigma = d2 > 0 ? -d1 / d2 : 1.0;
      double sigma_prev = 0, slope_prev = d1;
      for (int r = 1; r < cg_line_search_steps && std::isfinite(sigma); ++r) {
        const std::vector<Vec2> trial = displaced(c, u, direction, sigma, roles);
        std::vector<Vec2> gt;
        double slope;
        try {
          problem_energy_and_gradient(p, trial, gt);
          slope = 0;
          for (std::size_t a = 0; a < c.size(); ++a)
            if (u.var[a] >= 0) slope += direction[u.var[a]] * vec::dot(u.dir[a], gt[a]);
        } catch (const Invalid_input_error&) { break; }
        if (!std::isfinite(slope) || std::abs(slope) <= 1e-3 * std::abs(d1)) break;
        const double curvature = (slope - slope_prev) / (sigma - sigma_prev);
        if (!(curvature > 0)) break;
        sigma_prev = sigma; slope_prev = slope;
        sigma -= slope / curvature;
      }
      if (!(std::isfinite(sigma) && sigma > 0)) sigma = 1.0;
      for (std::size_t k = 0; k < rg.size(); ++k) direction[k] *= sigma;
      x = direction;
      decrement = -dot_product(rg, x);
    }
    // Armijo backtracking from the longest step that moves no vertex by more than
    // max_step_fraction of its shorter incident edge (a trust region in the geometry: a full
    // Newton step far from the minimiser must not throw vertices across the curve, which makes
    // loops and cusps that the level then "converges" in; near the minimiser steps are tiny and
    // the cap is inactive, so the quadratic convergence is kept).
    double t = std::min(1.0, step_cap(c, f.closed, u, x)), et = inf;
    std::vector<Vec2> trial;
    int b = 0;
    for (; b <= max_backtracks; ++b, t *= 0.5) {
      trial = displaced(c, u, x, t, roles);
      et = energy_or_infinity(p, trial);
      if (et <= e - armijo_c1 * t * decrement) break;
    }
    if (b > max_backtracks) {
      out.status = 0.5 * decrement <= rounding_floor * scale ? Status::CONVERGED : Status::CAPPED;
      return out;
    }
    // DIVERGING only when the curve runs away (its extent beyond the cap: no finite minimiser); an
    // edge with a free end that degenerates is a solver failure on a problem that may well have a
    // minimiser (with beta > 0 the length is bounded by F/beta): CAPPED.
    const double extent = polygon_extent(trial);
    const bool runaway = extent > s.max_extent, collapsed = free_min_edge(trial, f.closed, roles) < degenerate_edge_fraction * extent;
    if (runaway || collapsed) {
      c = trial;
      out.energy = et;
      out.iterations = it + 1;
      out.status = runaway ? Status::DIVERGING : Status::CAPPED;
      return out;
    }
    c = trial;
    // Re-anchoring. The lines of motion are fixed for the level (Newton then minimises one fixed
    // function), but where the curve moves towards its centres of curvature by more than the local
    // radius of the start polygon, the fixed normals of neighbouring vertices converge and the
    // vertices crowd together on them: the restricted minimiser has a collapsing edge (the level
    // creeps, step-capped, towards it, and the collapse looked like a degenerating curve). Seen on
    // hand-drawn strokes that double back. Then the free vertices are slid back along the current
    // polygon to the level's spacing and the normals recomputed: a new fixed function, from which
    // Newton continues (capped: max_reanchors).
    if (reanchors < max_reanchors && crowded(c, f.closed, anchor)) {
      redistribute(c, f.closed, fractions, roles);
      anchor = edge_lengths(c, f.closed);
      ++reanchors;
      reanchored = true;
      continue;
    }
    if (s.conjugate_gradient && e - et <= s.tolerance * scale) {
      out.energy = et;
      out.iterations = it + 1;
      out.status = Status::CONVERGED;
      return out;
    }
  }
}

} // namespace optimal
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_OPTIMAL_SOLVER_H
