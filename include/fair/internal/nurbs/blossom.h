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
// Only +, -, *, / of the number type: exact in an exact kernel; in double each result is a
// convex combination chain of p steps (backward stable). Cost: O(p^2) per blossom value,
// O(p^3) per span's Bezier points, O(n + p) per insertion (the copy).

#ifndef FAIR_INTERNAL_NURBS_BLOSSOM_H
#define FAIR_INTERNAL_NURBS_BLOSSOM_H

#include <fair/internal/spline/bspline_form.h>

#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace nurbs {

using spline::Homogeneous_point;

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

}  // namespace nurbs
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_NURBS_BLOSSOM_H
