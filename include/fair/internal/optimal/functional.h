// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Gumhold's optimality functional (eq. 5) discretised on a polygon as in Sec. 2.2.3, in the
// true-curvature convention of issue 11, with its exact gradient and banded Hessian
// (doc/optimal_curves.md: "The functional", "Discrete curvature (and the paper's factor 2)",
// "Derivatives and Hessian"). All arithmetic is double.
//
//   F = sum_edges l_j (beta_j + sum_{k odd} beta_k |kappa^(k)_j L0^(k+1)|^alpha_k)
//     + sum_vertices s_j (beta0_j |kappa_j L0|^alpha_0 + sum_{k even >= 2} beta_k |kappa^(k)_j L0^(k+1)|^alpha_k)
//   kappa^(k)_j = (kappa^(k-1)_{j+1} - kappa^(k-1)_j) / l_j     odd k, on edge j = c_j -> c_{j+1}
//   kappa^(k)_j = (kappa^(k-1)_j - kappa^(k-1)_{j-1}) / s_j     even k >= 2, at vertex j
//   l_j = |c_{j+1} - c_j|, s_j = (l_{j-1} + l_j)/2.
//
// Active vertices. kappa_j exists at an "active" vertex: every vertex of a closed polygon and the
// interior vertices of an open one, minus the vertices with zero_curvature[j] = 1 (corners, Sec. 3.1).
// At an inactive vertex kappa = 0 (natural boundary): it contributes no kappa term, and a derivative
// term kappa^(k) is present only where every kappa_i it is built from is active (its stencil does not
// reach over an end or a corner: the stencils become one-sided by dropping the terms that would cross).
//
// Evaluation. Each term is a function of a few "primitives": the curvatures kappa_i (each a function
// of 3 consecutive vertices, curvature.h) and the edge lengths l_e (2 vertices). The term is written
// once, templated on its scalar (term_value); its gradient and Hessian in the primitives come from
// the dual numbers of dual.h, the primitives' own gradients and Hessians likewise, and the chain rule
//   dT/dc = sum_p T_p dp/dc,   d2T/dc2 = sum_{p,q} T_pq (dp/dc)(dq/dc)^T + sum_p T_p d2p/dc2
// gives the exact local gradient and Hessian on the term's window of k + 3 consecutive vertices.
// Cost O(n) for the energy and gradient, O(n w^2) for the Hessian.

#ifndef FAIR_INTERNAL_OPTIMAL_FUNCTIONAL_H
#define FAIR_INTERNAL_OPTIMAL_FUNCTIONAL_H

#include <fair/Errors.h>
#include <fair/internal/optimal/banded.h>
#include <fair/internal/optimal/curvature.h>
#include <fair/internal/optimal/dual.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

typedef std::array<double, 2> Vec2;

/// Highest curvature derivative of eq. 5 the discretisation provides (the d <= 4).
constexpr int max_derivative_order = 4;

struct Functional {                    // eq. 5 discretised as in Sec. 2.2.3, TRUE curvature (issue 11)
  bool closed = false;
  double reference_length = 1;         // L0 (input polygon length), > 0
  std::vector<double> length_weight;   // beta per EDGE (edge j = c_j -> c_{j+1}); size = number of edges
  std::vector<double> curvature_weight;  // beta_0 per VERTEX; size = number of vertices
  double curvature_exponent = 2;       // alpha_0 >= 1 (|x|^a at 0 for a < 2: see abs_pow in dual.h)
  std::array<double, 5> derivative_weight{{0, 0, 0, 0, 0}};    // beta_k, k = 1..4 (index 0 ignored)
  std::array<double, 5> derivative_exponent{{2, 2, 2, 2, 2}};  // alpha_k >= 1 (index 0 ignored)
  Discretisation discretisation = Discretisation::REGULARISED;
  std::vector<unsigned char> zero_curvature;  // per vertex: 1 = kappa_j forced to 0 (corner), empty = none
  /// Half-bandwidth of the Hessian in vertices: 2 + max{k in 1..4 : beta_k > 0} (2 if none). A
  /// kappa^(k) term lives on k + 3 consecutive vertices (kappa on 3, the length term on 2), so the
  /// coupling reaches k + 2 vertices.
  std::size_t half_bandwidth() const {
    std::size_t w = 2;
    for (int k = 1; k <= max_derivative_order; ++k)
      if (derivative_weight[k] > 0) w = 2 + static_cast<std::size_t>(k);
    return w;
  }
};

namespace functional_detail {

/// Index ranges of the primitives of a kappa^(k) term at its site (vertex j for even k, edge j for odd
/// k), as offsets from j: curvatures kappa_{j+o}, o in [klo, khi]; edge lengths l_{j+o}, o in [llo, lhi].
/// The term's vertex window is [klo - 1, khi + 1] (k + 3 vertices).
struct Stencil {
  int klo, khi, llo, lhi;
};
constexpr Stencil stencils[5] = {{0, 0, -1, 0}, {0, 1, 0, 0}, {-1, 1, -1, 0}, {-1, 2, -1, 1}, {-2, 2, -2, 1}};
/// Number of primitives of the kappa^(k) term.
constexpr int primitive_count(int k) {
  return (stencils[k].khi - stencils[k].klo + 1) + (stencils[k].lhi - stencils[k].llo + 1);
}
constexpr int max_window = max_derivative_order + 3;  // vertices

/// kappa^(k) at offset o (vertex o for even k, edge o for odd k) from kap[o + 2], len[o + 2]
/// (the recursion of Sec. 2.2.3).
template <class T>
T derivative(int k, int o, const T* kap, const T* len) {
  if (k == 0) return kap[o + 2];
  if (k % 2 == 1) return (derivative(k - 1, o + 1, kap, len) - derivative(k - 1, o, kap, len)) / len[o + 2];
  const T s = 0.5 * (len[o + 1] + len[o + 2]);
  return (derivative(k - 1, o, kap, len) - derivative(k - 1, o - 1, kap, len)) / s;
}

/// beta |kappa^(k) L0^(k+1)|^alpha times l_j (odd k) or s_j (even k): one term of Sec. 2.2.3.
/// kap[o + 2] and len[o + 2] must be set on the stencil of k.
template <class T>
T term_value(int k, double beta, double alpha, double scale, const T* kap, const T* len) {
  const T measure = k % 2 == 1 ? len[2] : 0.5 * (len[1] + len[2]);
  return beta * abs_pow(derivative(k, 0, kap, len) * scale, alpha) * measure;
}

/// A primitive with its gradient and Hessian in its own coordinates (6 for kappa, 4 for l).
struct Primitive {
  double v = 0;
  double g[6] = {};
  double h[36] = {};
};

inline Primitive edge_length(const Vec2& a, const Vec2& b) {
  // l = |b - a|, t = (b - a)/l: dl/da = -t, dl/db = t; d2l = [P -P; -P P] with P = (I - t t^T)/l.
  Primitive p;
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  p.v = std::sqrt(dx * dx + dy * dy);
  const double t[2] = {dx / p.v, dy / p.v};
  for (int r = 0; r < 2; ++r) {
    p.g[r] = -t[r];
    p.g[2 + r] = t[r];
  }
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) {
      const double q = ((r == c ? 1.0 : 0.0) - t[r] * t[c]) / p.v;
      p.h[r * 4 + c] = q;
      p.h[(2 + r) * 4 + 2 + c] = q;
      p.h[r * 4 + 2 + c] = -q;
      p.h[(2 + r) * 4 + c] = -q;
    }
  return p;
}

inline Primitive vertex_curvature(Discretisation d, const Vec2& a, const Vec2& b, const Vec2& c) {
  typedef Dual<6> D;
  const D k = local_curvature(d, D::variable(0, a[0]), D::variable(1, a[1]), D::variable(2, b[0]),
                              D::variable(3, b[1]), D::variable(4, c[0]), D::variable(5, c[1]));
  Primitive p;
  p.v = k.v;
  for (int i = 0; i < 6; ++i) p.g[i] = k.g[i];
  for (int i = 0; i < 36; ++i) p.h[i] = k.h[i];
  return p;
}

/// The polygon's primitives and which vertices are active.
struct Geometry {
  std::size_t n = 0, edges = 0;
  bool closed = false;
  std::vector<unsigned char> active;
  std::vector<Primitive> kappa, length;  // kappa[j] only meaningful where active[j]
  std::size_t vertex(long j) const {  // offset index -> vertex (mod n when closed)
    const long m = static_cast<long>(n);
    return static_cast<std::size_t>(closed ? ((j % m) + m) % m : j);
  }
  bool kappa_active(long j) const {
    if (!closed && (j < 0 || j >= static_cast<long>(n))) return false;
    return active[vertex(j)] != 0;
  }
};

inline void check_input(const Functional& f, const std::vector<Vec2>& c, const char* method) {
  const std::size_t n = c.size();
  const std::size_t minimum = f.closed ? 3 : 2;
  if (n < minimum)
    throw Invalid_input_error(message(method, ": needs at least ", minimum, " vertices for a",
                                      f.closed ? " closed" : "n open", " polygon, got ", n));
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(c[i][0]) || !std::isfinite(c[i][1]))
      throw Invalid_input_error(message(method, ": vertex ", i, " = (", c[i][0], ", ", c[i][1],
                                        ") has a non-finite coordinate"));
  const std::size_t edges = f.closed ? n : n - 1;
  for (std::size_t i = 0; i < edges; ++i) {
    const std::size_t j = (i + 1) % n;
    if (c[i][0] == c[j][0] && c[i][1] == c[j][1])
      throw Invalid_input_error(message(method, ": consecutive vertices ", i, " and ", j, " coincide at (",
                                        c[i][0], ", ", c[i][1], ") (zero edge length)"));
  }
  require(std::isfinite(f.reference_length) && f.reference_length > 0, method,
          ": reference_length L0 must be finite and > 0, got ", f.reference_length);
  require(f.length_weight.size() == edges, method, ": length_weight has ", f.length_weight.size(),
          " entries, the polygon has ", edges, " edges");
  require(f.curvature_weight.size() == n, method, ": curvature_weight has ", f.curvature_weight.size(),
          " entries, the polygon has ", n, " vertices");
  require(f.zero_curvature.empty() || f.zero_curvature.size() == n, method, ": zero_curvature has ",
          f.zero_curvature.size(), " entries, the polygon has ", n, " vertices (or give none)");
  for (std::size_t i = 0; i < edges; ++i)
    require(std::isfinite(f.length_weight[i]) && f.length_weight[i] >= 0, method, ": length_weight[", i,
            "] = ", f.length_weight[i], " must be finite and >= 0");
  for (std::size_t i = 0; i < n; ++i)
    require(std::isfinite(f.curvature_weight[i]) && f.curvature_weight[i] >= 0, method, ": curvature_weight[",
            i, "] = ", f.curvature_weight[i], " must be finite and >= 0");
  require(std::isfinite(f.curvature_exponent) && f.curvature_exponent >= 1, method,
          ": curvature_exponent alpha_0 = ", f.curvature_exponent, " must be finite and >= 1");
  for (int k = 1; k <= max_derivative_order; ++k) {
    require(std::isfinite(f.derivative_weight[k]) && f.derivative_weight[k] >= 0, method,
            ": derivative_weight[", k, "] = ", f.derivative_weight[k], " must be finite and >= 0");
    require(std::isfinite(f.derivative_exponent[k]) && f.derivative_exponent[k] >= 1, method,
            ": derivative_exponent[", k, "] = ", f.derivative_exponent[k], " must be finite and >= 1");
  }
}

/// Active vertices and the primitives; `derivatives`: also their gradients and Hessians.
inline Geometry geometry(const Functional& f, const std::vector<Vec2>& c, bool derivatives, const char* method) {
  check_input(f, c, method);
  Geometry g;
  g.n = c.size();
  g.closed = f.closed;
  g.edges = f.closed ? g.n : g.n - 1;
  g.active.assign(g.n, 1);
  if (!f.closed) g.active[0] = g.active[g.n - 1] = 0;
  for (std::size_t i = 0; i < f.zero_curvature.size(); ++i)
    if (f.zero_curvature[i]) g.active[i] = 0;
  g.length.resize(g.edges);
  for (std::size_t e = 0; e < g.edges; ++e) {
    if (derivatives) {
      g.length[e] = edge_length(c[e], c[(e + 1) % g.n]);
    } else {
      const double dx = c[(e + 1) % g.n][0] - c[e][0], dy = c[(e + 1) % g.n][1] - c[e][1];
      g.length[e].v = std::sqrt(dx * dx + dy * dy);
    }
  }
  g.kappa.resize(g.n);
  for (std::size_t j = 0; j < g.n; ++j) {
    if (!g.active[j]) continue;
    const Vec2& a = c[(j + g.n - 1) % g.n];
    const Vec2& b = c[j];
    const Vec2& d = c[(j + 1) % g.n];
    if (f.discretisation == Discretisation::CIRCUMCIRCLE && a[0] == d[0] && a[1] == d[1])
      throw Invalid_input_error(message(method, ": vertices ", (j + g.n - 1) % g.n, " and ", (j + 1) % g.n,
                                        " around vertex ", j, " coincide at (", a[0], ", ", a[1],
                                        "): the circumcircle curvature is infinite"));
    if (derivatives) {
      g.kappa[j] = vertex_curvature(f.discretisation, a, b, d);
    } else {
      g.kappa[j].v = local_curvature(f.discretisation, a[0], a[1], b[0], b[1], d[0], d[1]);
    }
    if (!std::isfinite(g.kappa[j].v))
      throw Invalid_input_error(message(method, ": the curvature at vertex ", j, " = (", b[0], ", ", b[1],
                                        ") is not finite (", g.kappa[j].v, ")"));
  }
  return g;
}

/// Whether the kappa^(k) term at site j exists (every kappa of its stencil active; for an open polygon
/// the site must be a vertex/edge, which that implies).
inline bool term_present(const Geometry& g, int k, long j) {
  for (int o = stencils[k].klo; o <= stencils[k].khi; ++o)
    if (!g.kappa_active(j + o)) return false;
  return true;
}

/// Weight beta of the kappa^(k) term at site j (k = 0: the vertex's beta_0).
inline double term_weight(const Functional& f, int k, std::size_t j) {
  return k == 0 ? f.curvature_weight[j] : f.derivative_weight[k];
}
inline double term_exponent(const Functional& f, int k) {
  return k == 0 ? f.curvature_exponent : f.derivative_exponent[k];
}

/// Local gradient and Hessian on a window of W vertices (2W coordinates), to be scattered.
struct Window {
  long first = 0;  // offset index of the window's first vertex
  int size = 0;    // vertices
  double g[2 * max_window] = {};
  double h[4 * max_window * max_window] = {};
};

/// The kappa^(k) term at site j: value, and (if `window`) its exact gradient and Hessian on its window.
template <int K>
double evaluate_term(const Functional& f, const Geometry& g, long j, Window* window) {
  constexpr int P = primitive_count(K);
  constexpr Stencil st = stencils[K];
  const std::size_t site = g.vertex(j);
  const double beta = term_weight(f, K, site), alpha = term_exponent(f, K);
  const double scale = std::pow(f.reference_length, K + 1);
  if (!window) {
    double kap[5] = {1, 1, 1, 1, 1}, len[4] = {1, 1, 1, 1};
    for (int o = st.klo; o <= st.khi; ++o) kap[o + 2] = g.kappa[g.vertex(j + o)].v;
    for (int o = st.llo; o <= st.lhi; ++o) len[o + 2] = g.length[g.vertex(j + o)].v;
    return term_value(K, beta, alpha, scale, kap, len);
  }
  typedef Dual<P> D;
  D kap[5] = {1, 1, 1, 1, 1}, len[4] = {1, 1, 1, 1};
  // Primitive p: its value, and the window vertex where its own coordinates start.
  const Primitive* prim[P];
  int start[P], dims[P];
  int p = 0;
  const long first = j + st.klo - 1;
  for (int o = st.klo; o <= st.khi; ++o, ++p) {
    prim[p] = &g.kappa[g.vertex(j + o)];
    start[p] = static_cast<int>(j + o - 1 - first);
    dims[p] = 6;
    kap[o + 2] = D::variable(p, prim[p]->v);
  }
  for (int o = st.llo; o <= st.lhi; ++o, ++p) {
    prim[p] = &g.length[g.vertex(j + o)];
    start[p] = static_cast<int>(j + o - first);
    dims[p] = 4;
    len[o + 2] = D::variable(p, prim[p]->v);
  }
  const D t = term_value(K, beta, alpha, scale, kap, len);
  const int W = K + 3, C = 2 * W;
  window->first = first;
  window->size = W;
  for (int i = 0; i < C; ++i) window->g[i] = 0;
  for (int i = 0; i < C * C; ++i) window->h[i] = 0;
  // Jacobian of the primitives in the window coordinates (dense P x C; at most 9 x 14).
  double jac[P][2 * max_window] = {};
  for (int q = 0; q < P; ++q)
    for (int i = 0; i < dims[q]; ++i) jac[q][2 * start[q] + i] = prim[q]->g[i];
  for (int q = 0; q < P; ++q)
    for (int i = 0; i < C; ++i) window->g[i] += t.g[q] * jac[q][i];
  // sum_{p,q} T_pq J_p J_q^T: first M = T'' J (P x C), then J^T M.
  double m[P][2 * max_window] = {};
  for (int a = 0; a < P; ++a)
    for (int b = 0; b < P; ++b) {
      const double tab = t.h[a * P + b];
      if (tab == 0) continue;
      for (int i = 0; i < C; ++i) m[a][i] += tab * jac[b][i];
    }
  for (int a = 0; a < P; ++a)
    for (int i = 0; i < C; ++i) {
      const double ja = jac[a][i];
      if (ja == 0) continue;
      for (int k = 0; k < C; ++k) window->h[i * C + k] += ja * m[a][k];
    }
  // sum_p T_p d2p/dc2 on the primitive's own coordinates.
  for (int q = 0; q < P; ++q) {
    const int o = 2 * start[q], d = dims[q];
    for (int r = 0; r < d; ++r)
      for (int s = 0; s < d; ++s) window->h[(o + r) * C + o + s] += t.g[q] * prim[q]->h[r * d + s];
  }
  // J^T M is symmetric up to rounding: make it exactly symmetric, so that the stored diagonal blocks are.
  for (int i = 0; i < C; ++i)
    for (int k = i + 1; k < C; ++k) window->h[i * C + k] = window->h[k * C + i] = 0.5 * (window->h[i * C + k] + window->h[k * C + i]);
  return t.v;
}

/// Adds a window's gradient (and Hessian, if given) into the global ones.
inline void scatter(const Geometry& g, const Window& w, std::vector<Vec2>& gradient, Block_banded_hessian* hessian) {
  const int C = 2 * w.size;
  for (int a = 0; a < w.size; ++a) {
    const std::size_t va = g.vertex(w.first + a);
    gradient[va][0] += w.g[2 * a];
    gradient[va][1] += w.g[2 * a + 1];
  }
  if (!hessian) return;
  for (int a = 0; a < w.size; ++a) {
    const std::size_t va = g.vertex(w.first + a);
    for (int b = 0; b < w.size; ++b) {
      const std::size_t vb = g.vertex(w.first + b);
      if (va > vb) continue;  // counted as the transpose of (vb, va)
      for (int r = 0; r < 2; ++r)
        for (int s = 0; s < 2; ++s) hessian->at(va, vb, r, s) += w.h[(2 * a + r) * C + 2 * b + s];
    }
  }
}

/// Sites of the kappa^(k) terms: vertices (even k) or edges (odd k) where the term is present.
template <int K>
double accumulate_terms(const Functional& f, const Geometry& g, std::vector<Vec2>* gradient,
                        Block_banded_hessian* hessian) {
  if (K > 0 && !(f.derivative_weight[K] > 0)) return 0;
  double energy = 0;
  Window window;
  const std::size_t sites = K % 2 == 1 ? g.edges : g.n;
  for (std::size_t j = 0; j < sites; ++j) {
    if (K == 0 && !(f.curvature_weight[j] > 0)) continue;
    if (!term_present(g, K, static_cast<long>(j))) continue;
    if (gradient) {
      energy += evaluate_term<K>(f, g, static_cast<long>(j), &window);
      scatter(g, window, *gradient, hessian);
    } else {
      energy += evaluate_term<K>(f, g, static_cast<long>(j), nullptr);
    }
  }
  return energy;
}

inline double evaluate(const Functional& f, const std::vector<Vec2>& c, std::vector<Vec2>* gradient,
                       Block_banded_hessian* hessian, const char* method) {
  const Geometry g = geometry(f, c, gradient != nullptr, method);
  if (gradient) gradient->assign(g.n, Vec2{{0, 0}});
  if (hessian) hessian->reset(g.n, f.half_bandwidth(), f.closed);
  double energy = 0;
  // Length term: sum beta_j l_j.
  for (std::size_t e = 0; e < g.edges; ++e) {
    const double beta = f.length_weight[e];
    if (!(beta > 0)) continue;
    const Primitive& l = g.length[e];
    energy += beta * l.v;
    if (!gradient) continue;
    const std::size_t v[2] = {e, (e + 1) % g.n};
    for (int a = 0; a < 2; ++a)
      for (int r = 0; r < 2; ++r) (*gradient)[v[a]][r] += beta * l.g[2 * a + r];
    if (!hessian) continue;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        if (v[a] > v[b]) continue;
        for (int r = 0; r < 2; ++r)
          for (int s = 0; s < 2; ++s) hessian->at(v[a], v[b], r, s) += beta * l.h[(2 * a + r) * 4 + 2 * b + s];
      }
  }
  energy += accumulate_terms<0>(f, g, gradient, hessian);
  energy += accumulate_terms<1>(f, g, gradient, hessian);
  energy += accumulate_terms<2>(f, g, gradient, hessian);
  energy += accumulate_terms<3>(f, g, gradient, hessian);
  energy += accumulate_terms<4>(f, g, gradient, hessian);
  FAIR_ASSERT_MSG(std::isfinite(energy), method, ": energy ", energy);
  return energy;
}

}  // namespace functional_detail

/// F(c) of Sec. 2.2.3 with true curvature; c = polygon vertices (closed: no repeated last vertex).
/// Invalid_input_error: fewer than 2 (open) / 3 (closed) vertices, non-finite coordinates, coincident
/// consecutive vertices (naming the indices). Precondition_error: weights of the wrong size,
/// negative or non-finite weights, exponents < 1, L0 <= 0.
inline double energy(const Functional& f, const std::vector<Vec2>& c) {
  return functional_detail::evaluate(f, c, nullptr, nullptr, "fair::internal::optimal::energy");
}

/// Energy and its exact gradient dF/dc_j (size n).
inline double energy_and_gradient(const Functional& f, const std::vector<Vec2>& c, std::vector<Vec2>& gradient) {
  return functional_detail::evaluate(f, c, &gradient, nullptr, "fair::internal::optimal::energy_and_gradient");
}

/// Energy, gradient and exact Hessian; `hessian` is reset to n vertices, half-bandwidth
/// f.half_bandwidth(), cyclic iff f.closed.
inline double energy_gradient_hessian(const Functional& f, const std::vector<Vec2>& c, std::vector<Vec2>& gradient,
                                      Block_banded_hessian& hessian) {
  return functional_detail::evaluate(f, c, &gradient, &hessian, "fair::internal::optimal::energy_gradient_hessian");
}

/// Normals n_j of Sec. 2.3.2, unit: the LEFT normal (-t_y, t_x) of the bisector t_{j-1} + t_j of the unit
/// edge directions (open ends: of the end edge). The paper's * is the right normal; the sign does not
/// matter for offsets delta_j n_j. At an exact reversal (t_{j-1} = -t_j) the bisector vanishes and the
/// limit direction t_j (up to sign) is used.
inline std::vector<Vec2> vertex_normals(const std::vector<Vec2>& c, bool closed) {
  const char* method = "fair::internal::optimal::vertex_normals";
  const std::size_t n = c.size();
  const std::size_t minimum = closed ? 3 : 2;
  if (n < minimum)
    throw Invalid_input_error(message(method, ": needs at least ", minimum, " vertices, got ", n));
  const std::size_t edges = closed ? n : n - 1;
  std::vector<Vec2> t(edges);
  for (std::size_t e = 0; e < edges; ++e) {
    const Vec2& a = c[e];
    const Vec2& b = c[(e + 1) % n];
    const double dx = b[0] - a[0], dy = b[1] - a[1], l = std::sqrt(dx * dx + dy * dy);
    if (!(l > 0) || !std::isfinite(l))
      throw Invalid_input_error(message(method, ": edge ", e, " from (", a[0], ", ", a[1], ") to (", b[0], ", ",
                                        b[1], ") has length ", l));
    t[e] = Vec2{{dx / l, dy / l}};
  }
  std::vector<Vec2> normals(n);
  for (std::size_t j = 0; j < n; ++j) {
    Vec2 d;
    if (!closed && j == 0) {
      d = t[0];
    } else if (!closed && j == n - 1) {
      d = t[edges - 1];
    } else {
      const Vec2& ti = t[(j + edges - 1) % edges];
      const Vec2& to = t[j % edges];
      d = Vec2{{ti[0] + to[0], ti[1] + to[1]}};
      const double m = std::sqrt(d[0] * d[0] + d[1] * d[1]);
      if (m > 0) {
        d = Vec2{{d[0] / m, d[1] / m}};
      } else {
        normals[j] = to;
        continue;
      }
    }
    normals[j] = Vec2{{-d[1], d[0]}};
  }
  return normals;
}

/// The discrete true curvature kappa_j per vertex (0 at open ends and zero_curvature vertices).
inline std::vector<double> discrete_curvatures(const Functional& f, const std::vector<Vec2>& c) {
  const functional_detail::Geometry g =
      functional_detail::geometry(f, c, false, "fair::internal::optimal::discrete_curvatures");
  std::vector<double> kappa(g.n, 0.0);
  for (std::size_t j = 0; j < g.n; ++j)
    if (g.active[j]) kappa[j] = g.kappa[j].v;
  return kappa;
}

/// Reduction to normal offsets delta_j with fixed normals n_j (Sec. 2.3.2): reduced_gradient[a] =
/// g_{f_a} . n_{f_a}, reduced_hessian(a, b) = n_{f_a}^T H_{f_a f_b} n_{f_b}, where f_0 < f_1 < ... are the
/// free vertices (free[j] = 1) in increasing index: reduced index a <-> vertex f_a. Dropping fixed
/// vertices does not widen the band (the reduced, cyclic if H is, distance is at most the original),
/// so reduced_hessian has H's half-bandwidth and cyclicity. (A fixed vertex j does not decouple its
/// neighbours: kappa_j couples c_{j-1} and c_{j+1}, so the reduced closed system stays cyclic.)
inline void normal_offset_system(const std::vector<Vec2>& gradient, const Block_banded_hessian& hessian,
                                 const std::vector<Vec2>& normals, const std::vector<unsigned char>& free,
                                 std::vector<double>& reduced_gradient, Banded_symmetric& reduced_hessian) {
  const std::size_t n = hessian.vertices(), w = hessian.half_bandwidth();
  require(gradient.size() == n && normals.size() == n && free.size() == n,
          "fair::internal::optimal::normal_offset_system: sizes gradient ", gradient.size(), ", normals ",
          normals.size(), ", free ", free.size(), " differ from the Hessian's ", n, " vertices");
  std::vector<std::size_t> index(n, n);
  std::size_t m = 0;
  for (std::size_t j = 0; j < n; ++j)
    if (free[j]) index[j] = m++;
  reduced_gradient.assign(m, 0.0);
  reduced_hessian.reset(m, w, hessian.cyclic());
  const std::size_t reach = hessian.cyclic() ? std::min(w, n - 1) : w;
  for (std::size_t i = 0; i < n; ++i) {
    if (!free[i]) continue;
    const Vec2& ni = normals[i];
    reduced_gradient[index[i]] = gradient[i][0] * ni[0] + gradient[i][1] * ni[1];
    for (std::size_t d = 0; d <= reach; ++d) {
      if (!hessian.cyclic() && i + d >= n) break;
      const std::size_t j = (i + d) % n;
      if (!free[j] || !hessian.in_band(i, j)) continue;
      const Vec2& nj = normals[j];
      double v = 0;
      for (int r = 0; r < 2; ++r)
        for (int s = 0; s < 2; ++s) v += ni[r] * hessian.at(i, j, r, s) * nj[s];
      reduced_hessian.at(index[i], index[j]) = v;
    }
  }
}

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_FUNCTIONAL_H
