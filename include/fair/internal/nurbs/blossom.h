// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The two algorithms of the NURBS exchange form, in homogeneous coordinates (w x, w y, w), where
// a rational B-spline is a polynomial one (doc/nurbs.md §3):
//
//  - the blossom (polar form) of the polynomial piece on a non-empty span [u_i, u_{i+1}],
//      f_i(x_1, ..., x_p) = d^p_i  with  d^0_k = P_k (k = i-p .. i),
//      d^r_k = (1 - a) d^{r-1}_{k-1} + a d^{r-1}_k,  a = (x_r - u_k) / (u_{k+p+1-r} - u_k),
//    for r = 1..p, k = i .. i-p+r (de Boor's algorithm with the r-th argument in step r). The
//    denominators are positive: k <= i < i+1 <= k+p+1-r. The Bezier points of the span are
//    b_j = f_i(a^{p-j}, b^j) with a = u_i, b = u_{i+1} (Ramshaw's theorem);
//  - knot insertion (Boehm): inserting x in [u_i, u_{i+1}) replaces P_{i-p+1} .. P_i by
//      Q_k = a_k P_k + (1 - a_k) P_{k-1},  a_k = (x - u_k) / (u_{k+p} - u_k),
//    and keeps the other points (shifted by one after i). For a closed (periodic) curve the same
//    formula holds on the infinite periodic sequences; one period of the result is
//    Q_{i-p+1} .. Q_i, P_i, ..., P_{i+N-p} (indices of P modulo N), see doc/nurbs.md §4.
//
//  - the clamped form of a curve on its domain (clamped_form): the control points of the knot
//    vector u_p^(p+1), the knots inside (u_p, u_n), u_n^(p+1) are the blossom values at its knot
//    windows (de Boor-Ramshaw), each taken from a span of the curve that the window's basis
//    function covers (any such span: the curve is one polynomial there). Opens a closed curve at
//    its seam u_p = u_n.
//
// Only +, -, *, / of the number type: exact in an exact kernel; in double each result is a
// convex combination chain of p steps (backward stable). Cost: O(p^2) per blossom value,
// O(p^3) per span's Bezier points, O(n + p) per insertion (the copy), O(n p^2) per clamped form.
//
// In a floating-point number type the weights are scaled by one power of two before w x is
// formed (homogeneous_points: the largest into [1/2, 1], exact), so that w x cannot overflow
// where x is finite (review finding 5); an exact type is not scaled.

#ifndef FAIR_INTERNAL_NURBS_BLOSSOM_H
#define FAIR_INTERNAL_NURBS_BLOSSOM_H

#include <fair/internal/nurbs/knot_vector.h>
#include <fair/internal/spline/bspline_form.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace fair {
namespace internal {
namespace nurbs {

using spline::Homogeneous_point;

/// 2^e x in a floating-point FT (exact: a change of exponent); x in an exact FT (e is 0 there).
template <class FT>
FT scaled_by_power_of_two(const FT& x, int e) {
  if constexpr (std::is_floating_point<FT>::value) {
    return std::ldexp(x, e);
  } else {
    (void)e;
    return x;
  }
}

/// The exponent e with 2^-e m in [1/2, 1] for m > 0 finite; 0 in an exact FT and for m = 0.
template <class FT>
int normalising_exponent(double m) {
  if (!std::is_floating_point<FT>::value || !(m > 0) || !std::isfinite(m)) return 0;
  int e = 0;
  const double f = std::frexp(m, &e); // m = f 2^e, f in [1/2, 1)
  return f == 0.5 ? e - 1 : e;
}

/// (w_k x_k, w_k y_k, w_k) with the weights scaled by 2^-e, e = normalising_exponent of the
/// largest weight (file comment); `e` receives it (0 in an exact FT).
template <class FT, class Point>
std::vector<Homogeneous_point<FT>> homogeneous_points(const std::vector<Point>& P, const std::vector<FT>& w, int& e) {
  double m = 0;
  for (const FT& x : w) m = std::max(m, CGAL::to_double(x));
  e = normalising_exponent<FT>(m);
  std::vector<Homogeneous_point<FT>> H;
  H.reserve(P.size());
  for (std::size_t k = 0; k < P.size(); ++k) {
    const FT s = scaled_by_power_of_two(w[k], -e);
    H.push_back(Homogeneous_point<FT>{s * P[k].x(), s * P[k].y(), s});
  }
  return H;
}

/// f_i(x_1..x_p) for span i of (p, u, P) (homogeneous control points P).
template <class FT>
Homogeneous_point<FT> blossom(std::size_t p, const std::vector<FT>& u, const std::vector<Homogeneous_point<FT>>& P,
                              std::size_t i, const std::vector<FT>& x) {
  std::vector<Homogeneous_point<FT>> d(P.begin() + static_cast<long>(i - p), P.begin() + static_cast<long>(i) + 1);
  // d[j] holds d^r_{i-p+j}
  for (std::size_t r = 1; r <= p; ++r) {
    for (std::size_t j = p; j >= r; --j) {
      const std::size_t k = i - p + j;
      const FT a = (x[r - 1] - u[k]) / (u[k + p + 1 - r] - u[k]);
      d[j] = spline::combine(FT(1) - a, d[j - 1], a, d[j]);
    }
  }
  return d[p];
}

/// The p + 1 homogeneous Bezier points of the non-empty span i: b_j = f_i(u_i^{p-j}, u_{i+1}^j).
template <class FT>
std::vector<Homogeneous_point<FT>> span_bezier(std::size_t p, const std::vector<FT>& u,
                                               const std::vector<Homogeneous_point<FT>>& P, std::size_t i) {
  std::vector<Homogeneous_point<FT>> b;
  b.reserve(p + 1);
  std::vector<FT> x(p);
  for (std::size_t j = 0; j <= p; ++j) {
    for (std::size_t r = 0; r < p; ++r) x[r] = r < p - j ? u[i] : u[i + 1];
    b.push_back(blossom(p, u, P, i, x));
  }
  return b;
}

/// Open curve: inserts x in span i (u_i <= x < u_{i+1}, or x = u_{i+1} at the domain's end) of
/// (p, u, P) in place.
template <class FT>
void insert_knot_open(std::size_t p, std::vector<FT>& u, std::vector<Homogeneous_point<FT>>& P, std::size_t i,
                      const FT& x) {
  std::vector<Homogeneous_point<FT>> Q;
  Q.reserve(P.size() + 1);
  for (std::size_t k = 0; k + p <= i; ++k) Q.push_back(P[k]);
  for (std::size_t k = i - p + 1; k <= i; ++k) {
    const FT a = (x - u[k]) / (u[k + p] - u[k]);
    Q.push_back(spline::combine(a, P[k], FT(1) - a, P[k - 1]));
  }
  for (std::size_t k = i; k < P.size(); ++k) Q.push_back(P[k]);
  P = std::move(Q);
  u.insert(u.begin() + static_cast<long>(i) + 1, x);
}

/// Closed curve: inserts x, u_p <= x < u_{p+N}, in span i (p <= i < p + N) of the periodic form
/// (p, u, P) with N = n - p unique control points; the result is again in periodic form with
/// N + 1 unique points, the same domain start u_p and period.
template <class FT>
void insert_knot_periodic(std::size_t p, std::vector<FT>& u, std::vector<Homogeneous_point<FT>>& P, std::size_t i,
                          const FT& x) {
  const long N = static_cast<long>(P.size() - p), lp = static_cast<long>(p), li = static_cast<long>(i);
  const FT T = u[p + static_cast<std::size_t>(N)] - u[p];
  // The stored knots cover every index the formula reads (1 <= k, k + p <= n + p - 1).
  std::vector<Homogeneous_point<FT>> period; // new points with indices i-p+1 .. i-p+1+N
  period.reserve(static_cast<std::size_t>(N) + 1);
  for (long k = li - lp + 1; k <= li; ++k) {
    const std::size_t uk = static_cast<std::size_t>(k);
    const FT a = (x - u[uk]) / (u[uk + p] - u[uk]);
    period.push_back(spline::combine(a, P[static_cast<std::size_t>(spline::floor_div(k, N) * -N + k)], FT(1) - a,
                                     P[static_cast<std::size_t>(k - 1 - spline::floor_div(k - 1, N) * N)]));
  }
  for (long k = li + 1; k <= li - lp + 1 + N; ++k)
    period.push_back(P[static_cast<std::size_t>(k - 1 - spline::floor_div(k - 1, N) * N)]);
  const long M = N + 1; // new number of unique points
  // The domain's knots are the old ones with x inserted; outside the domain the knots are the
  // periodic extension v_{k +- M} = v_k +- T (as Cubic_spline_2 forms them), kept monotone where
  // a floating-point sum would round below its neighbour (exact types: no effect).
  std::vector<FT> v(static_cast<std::size_t>(M + 2 * lp) + 1);
  for (long k = lp; k <= lp + M; ++k) {
    const long o = k <= li ? k : k - 1; // old index (k = i + 1 is x itself)
    v[static_cast<std::size_t>(k)] = k == li + 1 ? x : u[static_cast<std::size_t>(o)];
  }
  for (long k = lp + M + 1; k <= M + 2 * lp; ++k) {
    const std::size_t uk = static_cast<std::size_t>(k);
    v[uk] = v[uk - static_cast<std::size_t>(M)] + T;
    if (v[uk] < v[uk - 1]) v[uk] = v[uk - 1];
  }
  for (long k = lp - 1; k >= 0; --k) {
    const std::size_t uk = static_cast<std::size_t>(k);
    v[uk] = v[uk + static_cast<std::size_t>(M)] - T;
    if (v[uk + 1] < v[uk]) v[uk] = v[uk + 1];
  }
  std::vector<Homogeneous_point<FT>> Q(static_cast<std::size_t>(M + lp));
  const long first = li - lp + 1;
  for (long k = 0; k < M + lp; ++k) {
    const long j = k - first - spline::floor_div(k - first, M) * M;
    Q[static_cast<std::size_t>(k)] = period[static_cast<std::size_t>(j)];
  }
  u = std::move(v);
  P = std::move(Q);
}

/// The clamped form on the domain [u_p, u_n] of the curve (p, u, P) (file comment): the knots
/// `v` (u_p p + 1 times, the knots strictly inside the domain, u_n p + 1 times) and the
/// homogeneous control points, one per window v_{k+1} .. v_{k+p}. For an open clamped curve it
/// gives the curve's own knots and points back; a closed one is opened at its seam.
template <class FT>
std::vector<Homogeneous_point<FT>> clamped_form(std::size_t p, const std::vector<FT>& u,
                                               const std::vector<Homogeneous_point<FT>>& P, std::vector<FT>& v) {
  const std::size_t n = P.size();
  v.assign(p + 1, u[p]);
  for (std::size_t k = p + 1; k < n; ++k)
    if (u[p] < u[k] && u[k] < u[n]) v.push_back(u[k]);
  v.insert(v.end(), p + 1, u[n]);
  const std::size_t m = v.size() - p - 1; // control points of the clamped form
  std::vector<Homogeneous_point<FT>> Q;
  Q.reserve(m);
  std::vector<FT> x(p);
  for (std::size_t k = 0; k < m; ++k) {
    // a non-empty span [v_j, v_{j+1}] of the domain under N_{k,p} (support [v_k, v_{k+p+1}]): one
    // exists because no knot inside has multiplicity above p
    std::size_t j = std::max(k, p);
    while (!(v[j] < v[j + 1])) ++j;
    for (std::size_t r = 0; r < p; ++r) x[r] = v[k + 1 + r];
    Q.push_back(blossom(p, u, P, find_span(p, n, u, v[j]), x));
  }
  return Q;
}

}  // namespace nurbs
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_NURBS_BLOSSOM_H
