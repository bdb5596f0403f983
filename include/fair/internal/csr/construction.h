// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The csr-spline construction (Karciauskas & Peters, Sec. 4, eq. 6 corrected): from samples
// q_i and breakpoints t_i to the control points of the cubic C2 B-spline, one local affine
// stencil per control point, O(n), no solve. Derivations and end conditions: doc/csr_splines.md.
//
// Control point c_i of the breakpoint t_i (eq. 6):
//   c_i = (1 - nu_i) (mu_i p_i^L + (1 - mu_i) p_i) + nu_i ((1 - mu_{i+1}) p_i^R + mu_{i+1} p_i)
//       = wL p_i^L + (1 - wL - wR) p_i + wR p_i^R,
//   wL = (1 - nu_i) mu_i,  wR = nu_i (1 - mu_{i+1}),
//   mu_i = ratio(kappa_i, kappa_{i-1}), nu_i = ratio(kappa_{i-1}, kappa_{i+1}),
//   1 - mu_{i+1} = ratio(kappa_i, kappa_{i+1})  (stencils.h: curvature_ratio).
// The weights are computed in double (curvatures need square roots) and converted exactly to FT;
// then wC = 1 - wL - wR is formed in FT, so c_i is an exact affine combination of p_i^L, p_i,
// p_i^R in an exact kernel. Since each of these reproduces quadratics (they are blossoms of the
// quadratic interpolants), the spline reproduces quadratic data exactly, whatever the weights.
//
// Open curves (samples q_0..q_m, breakpoints t_0..t_m): the clamped end. f_0 := f_1 and
// f_m := f_{m-1} (the one-sided quadratics), so p_1^L = p_1, p_{m-1}^R = p_{m-1}, kappa_0 is the
// curvature of f_1 at q_0 and kappa_m that of f_{m-1} at q_m; the first two control points are
// q_0 and b_1^0 of f_1, the last two b_2^{m-1} of f_{m-1} and q_m. Control points in the order of
// Cubic_spline_2 (open): q_0, b_1^0, c_1, ..., c_{m-1}, b_2^{m-1}, q_m.
// Closed curves (samples q_0..q_{m-1}, breakpoints t_0..t_m, t_m closing back to q_0): indices
// mod m, control point i is c_i.

#ifndef FAIR_INTERNAL_CSR_CONSTRUCTION_H
#define FAIR_INTERNAL_CSR_CONSTRUCTION_H

#include <fair/Errors.h>
#include <fair/Knot_spacing.h>
#include <fair/internal/classic/common.h>
#include <fair/internal/common/input_checks.h>
#include <fair/internal/csr/stencils.h>

#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace csr {

/// What the construction hands to Csr_spline_2.
template <class K>
struct Construction {
  std::vector<typename K::FT> breakpoints;
  std::vector<typename K::Point_2> control_points;
  std::vector<double> curvatures;  ///< kappa_i, one per sample
  double epsilon = 0;              ///< the absolute epsilon used (relative epsilon / extent)
};

/// x in double, the same value however x was computed: CGAL::to_double of a lazy exact number
/// (EPECK) returns its current interval approximation, which depends on the expression that
/// produced it (t_{j+1} - t_j is not as tight as the double it came from), so the curvature
/// weights would depend on how the knots were given. The exact value's double does not.
template <class NT>
double stable_double(const NT& x) {
  return CGAL::to_double(x);
}
template <class ET>
double stable_double(const CGAL::Lazy_exact_nt<ET>& x) {
  return CGAL::to_double(x.exact());
}

/// Throws Invalid_input_error unless `t` has `expected` entries, all finite and strictly increasing.
template <class FT>
void check_parameters(const std::vector<FT>& t, std::size_t expected, bool closed, const char* method) {
  if (t.size() != expected)
    throw Invalid_input_error(message(method, ": ", t.size(), " parameters given for ", closed ? "a closed" : "an open",
                                      " curve that needs ", expected, closed ? " (one per sample and the closing one)"
                                                                            : " (one per sample)"));
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double ti = CGAL::to_double(t[i]);
    if (!std::isfinite(ti))
      throw Invalid_input_error(message(method, ": parameter ", i, " = ", ti, " is not finite"));
    if (i > 0 && !(t[i - 1] < t[i]))
      throw Invalid_input_error(message(method, ": parameters ", i - 1, " and ", i, " (", CGAL::to_double(t[i - 1]),
                                        ", ", ti, ") are not strictly increasing"));
  }
}

/// The csr-spline of the samples q. `parameters` null: knots by `spacing`; otherwise the given
/// breakpoints (q.size() of them open, q.size() + 1 closed). Throws Invalid_input_error for fewer
/// than 3 (open) / 4 (closed) samples, non-finite or coincident consecutive samples, bad
/// parameters, and control points that overflow double.
template <class K>
Construction<K> construct(const std::vector<typename K::Point_2>& q, const std::vector<typename K::FT>* parameters,
                          bool closed, Knot_spacing spacing, bool add_epsilon, double relative_epsilon,
                          const char* method) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  common::check_interpolation_input(q, closed ? 4 : 3, closed, method);
  const std::size_t n = q.size();
  Construction<K> out;
  std::vector<FT> h;
  if (parameters) {
    check_parameters(*parameters, closed ? n + 1 : n, closed, method);
    out.breakpoints = *parameters;
    h.reserve(out.breakpoints.size() - 1);
    for (std::size_t j = 0; j + 1 < out.breakpoints.size(); ++j) h.push_back(out.breakpoints[j + 1] - out.breakpoints[j]);
  } else {
    h = classic::classic_knot_intervals<K>(q, closed, spacing, method);
    out.breakpoints = classic::classic_cumulative_knots(h);
  }
  const std::size_t m = h.size();  // pieces: n - 1 open, n closed

  // The extent for epsilon.
  double xmin = stable_double(q[0].x()), xmax = xmin, ymin = stable_double(q[0].y()), ymax = ymin;
  for (const Point_2& p : q) {
    const double x = stable_double(p.x()), y = stable_double(p.y());
    xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
  }
  const double extent = std::hypot(xmax - xmin, ymax - ymin);
  // Capped at infinite_curvature / 2 (DBL_MAX / 8): a large relative epsilon over a tiny extent
  // would overflow to inf, and then (a + eps) / (a + b + 2 eps) of the add-epsilon rule is NaN.
  out.epsilon = (extent > 0 && std::isfinite(extent)) ? std::min(relative_epsilon / extent, infinite_curvature / 2) : 0.0;

  // Index i + k (|k| <= 2 < size) modulo `size`, without an integer division (this runs ~10
  // times per sample).
  auto wrap = [](std::size_t i, int k, std::size_t size) {
    if (k < 0) {
      const std::size_t a = static_cast<std::size_t>(-k);
      return i >= a ? i - a : i + size - a;
    }
    const std::size_t j = i + static_cast<std::size_t>(k);
    return j >= size ? j - size : j;
  };
  // kappa_i = |curvature of f_i at q_i| (open ends: of the one-sided quadratic), from the samples
  // and intervals in double (stable_double: the same doubles however the knots were computed;
  // the coordinates are the inputs, so in EPECK this costs no exact evaluation, the intervals one
  // each). No arrays of chords: memory traffic, not arithmetic, bounds this pass for large n.
  std::vector<double>& kappa = out.curvatures;
  kappa.resize(n);
  auto curvature = [&](std::size_t j, Quadratic_node at) {  // the quadratic through q_j, q_{j+1}, q_{j+2}
    const std::size_t j1 = wrap(j, 1, n), j2 = wrap(j, 2, n);
    const double x0 = stable_double(q[j].x()), y0 = stable_double(q[j].y()), x1 = stable_double(q[j1].x()),
                 y1 = stable_double(q[j1].y()), x2 = stable_double(q[j2].x()), y2 = stable_double(q[j2].y());
    return quadratic_curvature(x1 - x0, y1 - y0, stable_double(h[j]), x2 - x1, y2 - y1, stable_double(h[wrap(j, 1, m)]),
                               at);
  };
  if (closed) {
    for (std::size_t i = 0; i < m; ++i) kappa[i] = curvature(wrap(i, -1, m), Quadratic_node::MIDDLE);
  } else {
    kappa[0] = curvature(0, Quadratic_node::FIRST);
    for (std::size_t i = 1; i < m; ++i) kappa[i] = curvature(i - 1, Quadratic_node::MIDDLE);
    kappa[m] = curvature(m - 2, Quadratic_node::LAST);
  }

  // q_i + sum_k w_k (q_{i+k} - q_i) for offsets k = -2..2 (w[2] unused), indices mod n.
  auto apply = [&](std::size_t i, const FT (&w)[5], bool left, bool right) {
    const Point_2& c = q[i];
    FT x = c.x(), y = c.y();
    for (int k = -2; k <= 2; ++k) {
      if (k == 0 || (k == -2 && !left) || (k == 2 && !right)) continue;
      const Point_2& p = q[wrap(i, k, n)];
      x += w[k + 2] * (p.x() - c.x());
      y += w[k + 2] * (p.y() - c.y());
    }
    return Point_2(x, y);
  };
  auto kap = [&](std::size_t i, int k) { return kappa[wrap(i, k, n)]; };
  auto hh = [&](std::size_t i, int k) -> const FT& { return h[wrap(i, k, m)]; };
  const FT zero(0);
  const FT third = FT(1) / FT(3);
  typedef Breakpoint_weights<FT> Weights;
  auto weights_at = [&](std::size_t j) { return breakpoint_weights(hh(j, -1), hh(j, 0)); };
  // c_i from the weights at t_{i-1} (null without f_{i-1}), t_i and t_{i+1} (null without f_{i+1}):
  // a_{-2} = wm_{i-1}, a_{-1} = (1 + beta_{i-1} - beta_i)/3, a_1 = (1 + 1/beta_{i+1} - 1/beta_i)/3,
  // a_2 = wp_{i+1} (stencils.h). Without f_{i-1} (f_{i+1}) the one-sided quadratic stands in:
  // p^L = p (p^R = p), i.e. its weight goes to p.
  auto control_point = [&](std::size_t i, const Weights* prev, const Weights& cur, const Weights* next) {
    const bool left = prev != nullptr, right = next != nullptr;
    const double mu = curvature_ratio(kap(i, 0), kap(i, -1), out.epsilon, add_epsilon);
    const double nu = curvature_ratio(kap(i, -1), kap(i, 1), out.epsilon, add_epsilon);
    const double one_minus_mu_next = curvature_ratio(kap(i, 0), kap(i, 1), out.epsilon, add_epsilon);
    const FT wl(left ? (1 - nu) * mu : 0.0), wr(right ? nu * one_minus_mu_next : 0.0);
    const FT wc = FT(1) - wl - wr;
    FT w[5] = {zero, wc * cur.wm, zero, wc * cur.wp, zero};
    if (left) {
      w[0] = wl * prev->wm;
      w[1] += wl * (FT(1) + prev->beta - cur.beta) * third;
    }
    if (right) {
      w[3] += wr * (FT(1) + next->inv_beta - cur.inv_beta) * third;
      w[4] = wr * next->wp;
    }
    return apply(i, w, left, right);
  };

  std::vector<Point_2>& d = out.control_points;
  if (closed) {
    d.reserve(m);
    Weights prev = weights_at(m - 1), cur = weights_at(0);
    for (std::size_t i = 0; i < m; ++i) {
      const Weights next = weights_at(wrap(i, 1, m));
      d.push_back(control_point(i, &prev, cur, &next));
      prev = cur;
      cur = next;
    }
  } else {
    d.reserve(m + 3);
    FT w1, w2;
    d.push_back(q[0]);
    end_stencil(h[0], h[1], w1, w2);
    d.push_back(Point_2(q[0].x() + w1 * (q[1].x() - q[0].x()) + w2 * (q[2].x() - q[0].x()),
                        q[0].y() + w1 * (q[1].y() - q[0].y()) + w2 * (q[2].y() - q[0].y())));
    Weights prev{}, cur = weights_at(1), next{};
    for (std::size_t i = 1; i < m; ++i) {
      const bool left = i >= 2, right = i + 2 <= m;
      if (right) next = weights_at(i + 1);
      d.push_back(control_point(i, left ? &prev : nullptr, cur, right ? &next : nullptr));
      prev = cur;
      cur = next;
    }
    end_stencil(h[m - 1], h[m - 2], w1, w2);
    d.push_back(Point_2(q[m].x() + w1 * (q[m - 1].x() - q[m].x()) + w2 * (q[m - 2].x() - q[m].x()),
                        q[m].y() + w1 * (q[m - 1].y() - q[m].y()) + w2 * (q[m - 2].y() - q[m].y())));
    d.push_back(q[m]);
  }
  classic::classic_check_finite_output(d, method);
  return out;
}

} // namespace csr
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_CSR_CONSTRUCTION_H
