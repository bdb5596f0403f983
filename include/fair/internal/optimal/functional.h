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
// the dual numbers of common/dual.h, the primitives' own gradients and Hessians likewise, and the chain rule
//   dT/dc = sum_p T_p dp/dc,   d2T/dc2 = sum_{p,q} T_pq (dp/dc)(dq/dc)^T + sum_p T_p d2p/dc2
// gives the exact local gradient and Hessian on the term's window of k + 3 consecutive vertices.
// Cost O(n) for the energy and gradient, O(n w^2) for the Hessian.

#ifndef FAIR_INTERNAL_OPTIMAL_FUNCTIONAL_H
#define FAIR_INTERNAL_OPTIMAL_FUNCTIONAL_H

#include <fair/Errors.h>
#include <fair/Optimal_curve_options.h>
#include <fair/internal/optimal/curvature.h>
#include <fair/internal/optimal/hessian.h>
#include <fair/internal/optimal/vec2.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

/// Highest curvature derivative of eq. 5 the discretisation provides (the d <= 4).
constexpr int max_derivative_order = 4;

struct Functional {                    // eq. 5 discretised as in Sec. 2.2.3, TRUE curvature (issue 11)
  bool closed = false;
  double reference_length = 1;         // L0 (input polygon length), > 0
  std::vector<double> length_weight;   // beta per EDGE (edge j = c_j -> c_{j+1}); size = number of edges
  std::vector<double> curvature_weight;  // beta_0 per VERTEX; size = number of vertices
  double curvature_exponent = 2;       // alpha_0 >= 1 (|x|^a at 0 for a < 2: see abs_pow in common/dual.h)
  std::array<double, 5> derivative_weight{{0, 0, 0, 0, 0}};    // beta_k, k = 1..4 (index 0 ignored)
  std::array<double, 5> derivative_exponent{{2, 2, 2, 2, 2}};  // alpha_k >= 1 (index 0 ignored)
  Curvature_discretisation discretisation = Curvature_discretisation::REGULARISED;
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

/// beta |kappa^(k) L0^(k+1)|^alpha times l_j (odd k) or s_j (even k): one term of Sec. 2.2.3, at site 0.
/// kap[o + 2] and len[o + 2] must be set on the stencil of k. The recursion is evaluated level by level
/// (level m on the offsets it needs, shrinking by one per level: k(k+1)/2 differences, not 2^k).
template <class T>
T term_value(int k, double beta, double alpha, double scale, const T* kap, const T* len) {
  int lo = stencils[k].klo, hi = stencils[k].khi;
  T level[5];
  for (int o = lo; o <= hi; ++o) level[o - lo] = kap[o + 2];
  for (int m = 1; m <= k; ++m) {
    if (m % 2 == 1) {  // on edge o: (D(o + 1) - D(o)) / l_o, o in [lo, hi - 1]
      for (int o = lo; o < hi; ++o) level[o - lo] = (level[o + 1 - lo] - level[o - lo]) / len[o + 2];
      --hi;
    } else {  // at vertex o: (D(o) - D(o - 1)) / s_o, o in [lo + 1, hi]; stored shifted down by one
      for (int o = lo + 1; o <= hi; ++o) level[o - 1 - lo] = (level[o - lo] - level[o - 1 - lo]) / (0.5 * (len[o + 1] + len[o + 2]));
      ++lo;
    }
  }
  // lo == hi == 0 now (the stencil table is built so).
  const T measure = k % 2 == 1 ? len[2] : 0.5 * (len[1] + len[2]);
  return beta * abs_pow(level[0] * scale, alpha) * measure;
}

/// The checks of every entry point: counts, finiteness, distinct neighbours, weights and exponents.
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

/// What an evaluation computes.
enum class Order { VALUE, GRADIENT, HESSIAN };

/// A primitive with its gradient and (HESSIAN) Hessian in its own coordinates (6 for kappa, 4 for l).
/// Only the parts the evaluation order needs are written (v; g for GRADIENT; g and h for HESSIAN), and
/// only those are read: no zeroing of 43 doubles per primitive.
struct Primitive {
  double v;
  double g[6];
  double h[36];
};

inline void edge_length(const Vec2& a, const Vec2& b, Order order, Primitive& p) {
  // l = |b - a|, t = (b - a)/l: dl/da = -t, dl/db = t; d2l = [P -P; -P P] with P = (I - t t^T)/l.
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  p.v = std::sqrt(dx * dx + dy * dy);
  if (order == Order::VALUE) return;
  const double t[2] = {dx / p.v, dy / p.v};
  for (int r = 0; r < 2; ++r) {
    p.g[r] = -t[r];
    p.g[2 + r] = t[r];
  }
  if (order != Order::HESSIAN) return;
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) {
      const double q = ((r == c ? 1.0 : 0.0) - t[r] * t[c]) / p.v;
      p.h[r * 4 + c] = q;
      p.h[(2 + r) * 4 + 2 + c] = q;
      p.h[r * 4 + 2 + c] = -q;
      p.h[(2 + r) * 4 + c] = -q;
    }
}

/// kappa with its derivatives in (a, b, c): evaluated as a dual over the 4 edge-vector coordinates
/// (u = b - a, v = c - b), then mapped by the constant Jacobian d(u, v)/d(a, b, c): the block of vertex
/// X in {a, b, c} is sum_P coef[X][P] d/dP with coef a = (-1, 0), b = (1, -1), c = (0, 1).
template <bool S>
Primitive dual_curvature(Curvature_discretisation d, const Vec2& a, const Vec2& b, const Vec2& c) {
  typedef Dual<4, S> D;
  const D k = local_curvature(d, D::variable(0, b[0] - a[0]), D::variable(1, b[1] - a[1]), D::variable(2, c[0] - b[0]),
                              D::variable(3, c[1] - b[1]));
  static constexpr double coef[3][2] = {{-1, 0}, {1, -1}, {0, 1}};
  Primitive p;
  p.v = k.v;
  for (int x = 0; x < 3; ++x)
    for (int r = 0; r < 2; ++r) p.g[2 * x + r] = coef[x][0] * k.g[r] + coef[x][1] * k.g[2 + r];
  if constexpr (S)
    for (int x = 0; x < 3; ++x)
      for (int y = 0; y < 3; ++y)
        for (int r = 0; r < 2; ++r)
          for (int s = 0; s < 2; ++s) {
            double v = 0;
            for (int P = 0; P < 2; ++P)
              for (int Q = 0; Q < 2; ++Q) v += coef[x][P] * coef[y][Q] * k.h[(2 * P + r) * 4 + 2 * Q + s];
            p.h[(2 * x + r) * 6 + 2 * y + s] = v;
          }
  return p;
}

/// The polygon, which vertices are active, and the primitives computed on demand. The curvature of a
/// vertex is used by up to 5 consecutive terms; a cache of 8 slots (tagged by vertex) holds the ones of
/// the current window of the single pass over the sites (no O(n) storage of primitives).
class Geometry {
public:
  std::size_t n = 0, edges = 0;
  bool closed = false;

  Geometry(const Functional& f, const std::vector<Vec2>& c, Order order, const char* method)
    : n(c.size()), edges(f.closed ? c.size() : c.size() - 1), closed(f.closed), f_(f), c_(c), order_(order),
      method_(method) {
    for (long& t : tag_) t = -1000;  // no offset index: they start at -2
  }
  std::size_t vertex(long j) const {  // offset index -> vertex (mod n when closed)
    const long m = static_cast<long>(n);
    return static_cast<std::size_t>(closed ? ((j % m) + m) % m : j);
  }
  bool kappa_active(long j) const {
    if (!closed && (j <= 0 || j >= static_cast<long>(n) - 1)) return false;
    return f_.zero_curvature.empty() || !f_.zero_curvature[vertex(j)];
  }
  /// kappa at the active vertex of offset index j (cached by j, not by vertex, so that the consecutive
  /// offsets of one term, also across the wrap of a closed polygon, occupy distinct slots).
  const Primitive& kappa(long j) {
    const std::size_t slot = static_cast<std::size_t>(((j % cache_size_l) + cache_size_l) % cache_size_l);
    if (tag_[slot] != j) {
      cache_[slot] = compute_kappa(vertex(j));
      tag_[slot] = j;
    }
    return cache_[slot];
  }
  Primitive length(std::size_t e) const {
    Primitive p;
    length(e, p);
    return p;
  }
  void length(std::size_t e, Primitive& p) const { edge_length(c_[e], c_[(e + 1) % n], order_, p); }

private:
  static constexpr std::size_t cache_size = 8;
  static constexpr long cache_size_l = 8;
  Primitive compute_kappa(std::size_t j) const {
    const Vec2& a = c_[(j + n - 1) % n];
    const Vec2& b = c_[j];
    const Vec2& d = c_[(j + 1) % n];
    if (f_.discretisation == Curvature_discretisation::CIRCUMCIRCLE && a[0] == d[0] && a[1] == d[1])
      throw Invalid_input_error(message(method_, ": vertices ", (j + n - 1) % n, " and ", (j + 1) % n,
                                        " around vertex ", j, " coincide at (", a[0], ", ", a[1],
                                        "): the circumcircle curvature is infinite"));
    Primitive p;
    if (order_ == Order::HESSIAN)
      p = dual_curvature<true>(f_.discretisation, a, b, d);
    else if (order_ == Order::GRADIENT)
      p = dual_curvature<false>(f_.discretisation, a, b, d);
    else
      p.v = local_curvature(f_.discretisation, b[0] - a[0], b[1] - a[1], d[0] - b[0], d[1] - b[1]);
    if (!std::isfinite(p.v))
      throw Invalid_input_error(message(method_, ": the curvature at vertex ", j, " = (", b[0], ", ", b[1],
                                        ") is not finite (", p.v, ")"));
    return p;
  }
  const Functional& f_;
  const std::vector<Vec2>& c_;
  Order order_;
  const char* method_;
  Primitive cache_[cache_size];
  long tag_[cache_size];
};

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

/// The kappa^(k) term at site j: its value, and (GRADIENT, HESSIAN) its exact gradient and Hessian on
/// its window of k + 3 vertices.
template <int K, Order O>
double evaluate_term(const Functional& f, Geometry& g, long j, Window& window) {
  constexpr int P = primitive_count(K);
  constexpr Stencil st = stencils[K];
  const std::size_t site = g.vertex(j);
  const double beta = term_weight(f, K, site), alpha = term_exponent(f, K);
  double scale = f.reference_length;  // L0^(K+1)
  for (int i = 0; i < K; ++i) scale *= f.reference_length;
  if constexpr (O == Order::VALUE) {
    double kap[5] = {1, 1, 1, 1, 1}, len[4] = {1, 1, 1, 1};
    for (int o = st.klo; o <= st.khi; ++o) kap[o + 2] = g.kappa(j + o).v;
    for (int o = st.llo; o <= st.lhi; ++o) len[o + 2] = g.length(g.vertex(j + o)).v;
    return term_value(K, beta, alpha, scale, kap, len);
  } else {
    constexpr bool S = O == Order::HESSIAN;
    typedef Dual<P, S> D;
    D kap[5] = {1, 1, 1, 1, 1}, len[4] = {1, 1, 1, 1};
    // Primitive q: its value and derivatives, and the window vertex where its own coordinates start.
    // (The at most 5 curvatures of one term occupy distinct cache slots: the pointers stay valid.)
    const Primitive* prim[P];
    Primitive lengths[st.lhi - st.llo + 1];
    int start[P], dims[P];
    int p = 0;
    const long first = j + st.klo - 1;
    for (int o = st.klo; o <= st.khi; ++o, ++p) {
      prim[p] = &g.kappa(j + o);
      start[p] = static_cast<int>(j + o - 1 - first);
      dims[p] = 6;
      kap[o + 2] = D::variable(p, prim[p]->v);
    }
    for (int o = st.llo; o <= st.lhi; ++o, ++p) {
      g.length(g.vertex(j + o), lengths[o - st.llo]);
      prim[p] = &lengths[o - st.llo];
      start[p] = static_cast<int>(j + o - first);
      dims[p] = 4;
      len[o + 2] = D::variable(p, prim[p]->v);
    }
    const D t = term_value(K, beta, alpha, scale, kap, len);
    const int W = K + 3, C = 2 * W;
    window.first = first;
    window.size = W;
    for (int i = 0; i < C; ++i) window.g[i] = 0;
    for (int q = 0; q < P; ++q)
      for (int i = 0; i < dims[q]; ++i) window.g[2 * start[q] + i] += t.g[q] * prim[q]->g[i];
    if constexpr (S) {
      for (int i = 0; i < C * C; ++i) window.h[i] = 0;
      // Jacobian of the primitives in the window coordinates (dense P x C, C = 2(K + 3); at most 9 x 14).
      double jac[P][2 * (K + 3)] = {};
      for (int q = 0; q < P; ++q)
        for (int i = 0; i < dims[q]; ++i) jac[q][2 * start[q] + i] = prim[q]->g[i];
      // sum_{p,q} T_pq J_p J_q^T: first M = T'' J (P x C), then J^T M.
      double m[P][2 * (K + 3)] = {};
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
          for (int k = 0; k < C; ++k) window.h[i * C + k] += ja * m[a][k];
        }
      // sum_q T_q d2q/dc2 on the primitive's own coordinates.
      for (int q = 0; q < P; ++q) {
        const int o = 2 * start[q], d = dims[q];
        for (int r = 0; r < d; ++r)
          for (int s = 0; s < d; ++s) window.h[(o + r) * C + o + s] += t.g[q] * prim[q]->h[r * d + s];
      }
      // J^T M is symmetric up to rounding: make it exactly symmetric, so that the stored diagonal
      // blocks are.
      for (int i = 0; i < C; ++i)
        for (int k = i + 1; k < C; ++k)
          window.h[i * C + k] = window.h[k * C + i] = 0.5 * (window.h[i * C + k] + window.h[k * C + i]);
    }
    return t.v;
  }
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
      const double block[4] = {w.h[(2 * a) * C + 2 * b], w.h[(2 * a) * C + 2 * b + 1], w.h[(2 * a + 1) * C + 2 * b],
                               w.h[(2 * a + 1) * C + 2 * b + 1]};
      hessian->add_block(va, vb, block);
    }
  }
}

/// The kappa^(K) term at site j (vertex j for even K, edge j for odd K), if present: its value, and
/// its derivatives added into gradient/hessian.
template <int K, Order O>
double site_term(const Functional& f, Geometry& g, std::size_t j, Window& window, std::vector<Vec2>* gradient,
                 Block_banded_hessian* hessian) {
  if (j >= (K % 2 == 1 ? g.edges : g.n)) return 0;
  if (!(term_weight(f, K, j) > 0)) return 0;
  if (!term_present(g, K, static_cast<long>(j))) return 0;
  const double e = evaluate_term<K, O>(f, g, static_cast<long>(j), window);
  if constexpr (O != Order::VALUE) scatter(g, window, *gradient, hessian);
  return e;
}

/// Finite input can still overflow (an edge of 1e-200 gives kappa^2 ~ 1e400): then the polygon is
/// unusable for this functional, reported as Invalid_input_error with its shortest edge, never as NaN.
inline void check_finite_result(const Geometry& g, const std::vector<Vec2>& c, double energy,
                                const std::vector<Vec2>* gradient, const Block_banded_hessian* hessian,
                                const char* method) {
  bool finite = std::isfinite(energy);
  if (finite && gradient)
    for (const Vec2& v : *gradient) finite = finite && std::isfinite(v[0]) && std::isfinite(v[1]);
  if (finite && hessian)
    for (std::size_t i = 0; i < g.n; ++i)
      for (std::size_t d = 0; d <= std::min(hessian->half_bandwidth(), g.n - 1); ++d) {
        const std::size_t j = (i + d) % g.n;
        if ((!g.closed && i + d >= g.n) || !hessian->in_band(i, j)) continue;
        for (int r = 0; r < 2; ++r)
          for (int t = 0; t < 2; ++t) finite = finite && std::isfinite(hessian->at(i, j, r, t));
      }
  if (finite) return;
  std::size_t shortest = 0;
  double length = INFINITY;
  for (std::size_t e = 0; e < g.edges; ++e) {
    const double l = g.length(e).v;
    if (l < length) {
      length = l;
      shortest = e;
    }
  }
  throw Invalid_input_error(message(method, ": the functional overflows on this polygon (energy ", energy,
                                    "; shortest edge ", shortest, " from (", c[shortest][0], ", ", c[shortest][1],
                                    ") has length ", length, ")"));
}

template <Order O>
double evaluate(const Functional& f, const std::vector<Vec2>& c, std::vector<Vec2>* gradient,
                Block_banded_hessian* hessian, const char* method) {
  check_input(f, c, method);
  Geometry g(f, c, O, method);
  if (gradient) gradient->assign(g.n, Vec2{{0, 0}});
  if (hessian) hessian->reset(g.n, f.half_bandwidth(), f.closed);
  double energy = 0;
  Window window;
  // One pass over the sites in order, so that the curvature cache serves every term of a window.
  for (std::size_t j = 0; j < g.n; ++j) {
    if (j < g.edges && f.length_weight[j] > 0) {  // length term beta_j l_j
      const double beta = f.length_weight[j];
      const Primitive l = g.length(j);
      energy += beta * l.v;
      if constexpr (O != Order::VALUE) {
        const std::size_t v[2] = {j, (j + 1) % g.n};
        for (int a = 0; a < 2; ++a)
          for (int r = 0; r < 2; ++r) (*gradient)[v[a]][r] += beta * l.g[2 * a + r];
        if constexpr (O == Order::HESSIAN)
          for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b) {
              if (v[a] > v[b]) continue;
              double block[4];
              for (int r = 0; r < 2; ++r)
                for (int s = 0; s < 2; ++s) block[2 * r + s] = beta * l.h[(2 * a + r) * 4 + 2 * b + s];
              hessian->add_block(v[a], v[b], block);
            }
      }
    }
    energy += site_term<0, O>(f, g, j, window, gradient, hessian);
    energy += site_term<1, O>(f, g, j, window, gradient, hessian);
    energy += site_term<2, O>(f, g, j, window, gradient, hessian);
    energy += site_term<3, O>(f, g, j, window, gradient, hessian);
    energy += site_term<4, O>(f, g, j, window, gradient, hessian);
  }
  check_finite_result(g, c, energy, gradient, hessian, method);
  return energy;
}

}  // namespace functional_detail

/// F(c) of Sec. 2.2.3 with true curvature; c = polygon vertices (closed: no repeated last vertex).
/// Invalid_input_error: fewer than 2 (open) / 3 (closed) vertices, non-finite coordinates, coincident
/// consecutive vertices (naming the indices). Precondition_error: weights of the wrong size,
/// negative or non-finite weights, exponents < 1, L0 <= 0.
inline double energy(const Functional& f, const std::vector<Vec2>& c) {
  return functional_detail::evaluate<functional_detail::Order::VALUE>(f, c, nullptr, nullptr,
                                                                    "fair::internal::optimal::energy");
}

/// Energy and its exact gradient dF/dc_j (size n).
inline double energy_and_gradient(const Functional& f, const std::vector<Vec2>& c, std::vector<Vec2>& gradient) {
  return functional_detail::evaluate<functional_detail::Order::GRADIENT>(f, c, &gradient, nullptr,
                                                                       "fair::internal::optimal::energy_and_gradient");
}

/// Energy, gradient and exact Hessian; `hessian` is reset to n vertices, half-bandwidth
/// f.half_bandwidth(), cyclic iff f.closed.
inline double energy_gradient_hessian(const Functional& f, const std::vector<Vec2>& c, std::vector<Vec2>& gradient,
                                      Block_banded_hessian& hessian) {
  return functional_detail::evaluate<functional_detail::Order::HESSIAN>(f, c, &gradient, &hessian,
                                                                      "fair::internal::optimal::energy_gradient_hessian");
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
  const char* method = "fair::internal::optimal::discrete_curvatures";
  functional_detail::check_input(f, c, method);
  functional_detail::Geometry g(f, c, functional_detail::Order::VALUE, method);
  std::vector<double> kappa(g.n, 0.0);
  for (std::size_t j = 0; j < g.n; ++j)
    if (g.kappa_active(static_cast<long>(j))) kappa[j] = g.kappa(static_cast<long>(j)).v;
  return kappa;
}

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_FUNCTIONAL_H
