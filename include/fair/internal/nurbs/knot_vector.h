// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The knot vector of a NURBS curve of degree p with n control points: u_0 <= ... <= u_{n+p}
// (n + p + 1 knots), the curve defined on the domain [u_p, u_n] (doc/nurbs.md §1).
//
//  - open: any non-decreasing vector (clamped, u_0 = ... = u_p and u_n = ... = u_{n+p}, is what
//    the library writes; an unclamped open vector is also valid: only the domain is evaluated);
//  - closed (periodic): the last p control points repeat the first p (and their weights), and
//    the knot intervals repeat with period N = n - p: u_{k+N} - u_k = T = u_{p+N} - u_p for
//    every k with 0 <= k <= p + ... (doc/nurbs.md §2). This is the unclamped form every
//    standard B-spline evaluator reads over [u_p, u_n]; N >= p.
//
// Validation throws Precondition_error naming the first offending index and value. In a
// floating-point number type the periodicity of the knots is checked to 64 ulps of the largest
// |u_k| (the knots of a closed spline are formed as t_j + q T, not bit-for-bit periodic); in an
// exact number type exactly.

#ifndef FAIR_INTERNAL_NURBS_KNOT_VECTOR_H
#define FAIR_INTERNAL_NURBS_KNOT_VECTOR_H

#include <fair/Errors.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace fair {
namespace internal {
namespace nurbs {

/// Throws unless `knots` is a valid knot vector of degree p for n control points (see above).
/// Multiplicities: at most p + 1 anywhere, at most p strictly inside the domain (a knot of
/// multiplicity p + 1 inside would split the curve in two).
template <class FT>
void check_knot_vector(std::size_t p, std::size_t n, const std::vector<FT>& u, bool closed, const char* who) {
  require(p >= 1, who, ": degree ", p, " < 1");
  require(p < u.size() && p < n, who, ": degree ", p, " for ", n, " control points and ", u.size(),
          " knots (at least degree + 1 of each)"); // before any p + 1 is formed: it could wrap
  require(n >= p + 1, who, ": ", n, " control points for degree ", p, " (at least ", p + 1, ")");
  require(u.size() == n + p + 1, who, ": ", u.size(), " knots for ", n, " control points of degree ", p,
          " (expected n + p + 1 = ", n + p + 1, ")");
  for (std::size_t k = 0; k < u.size(); ++k) {
    const double d = CGAL::to_double(u[k]);
    require(std::isfinite(d), who, ": knot ", k, " = ", d, " is not finite");
    if (k > 0) // (the message's arguments are evaluated whether or not it is raised)
      require(!(u[k] < u[k - 1]), who, ": knot ", k, " = ", d, " is smaller than knot ", k - 1, " = ",
              CGAL::to_double(u[k - 1]), " (knots must not decrease)");
  }
  require(u[p] < u[n], who, ": the domain [u_", p, ", u_", n, "] = [", CGAL::to_double(u[p]), ", ",
          CGAL::to_double(u[n]), "] is empty");
  std::size_t run = 1;
  for (std::size_t k = 1; k <= u.size(); ++k) {
    if (k < u.size() && u[k] == u[k - 1]) {
      ++run;
      continue;
    }
    const std::size_t last = k - 1; // the run u[k - run] .. u[last] of equal knots
    require(run <= p + 1, who, ": knot ", last, " = ", CGAL::to_double(u[last]), " has multiplicity ", run,
            " > degree + 1 = ", p + 1);
    // a closed curve's seam u_p = u_n is inside the curve too (p + 1 there would open it)
    const bool inside = closed ? (u[p] <= u[last] && u[last] <= u[n]) : (u[p] < u[last] && u[last] < u[n]);
    require(!inside || run <= p, who, ": interior knot ", last, " = ", CGAL::to_double(u[last]),
            " has multiplicity ", run, " > degree ", p, " (the curve would be disconnected there)");
    run = 1;
  }
  if (!closed) return;
  const std::size_t N = n - p;
  require(N >= p, who, ": a closed curve of degree ", p, " needs at least ", 2 * p, " control points (", p,
          " of them repeated), got ", n);
  const FT T = u[p + N] - u[p];
  double scale = 0;
  for (const FT& x : u) scale = std::max(scale, std::fabs(CGAL::to_double(x)));
  const bool floating = std::is_floating_point<FT>::value;
  const double tolerance = floating ? 64 * std::numeric_limits<double>::epsilon() * scale : 0.0;
  for (std::size_t k = 0; k + N < u.size(); ++k) {
    const FT gap = u[k + N] - u[k] - T;
    const bool periodic = floating ? std::fabs(CGAL::to_double(gap)) <= tolerance : CGAL::is_zero(gap);
    require(periodic, who, ": closed curve: knot ", k + N, " - knot ", k, " = ", CGAL::to_double(u[k + N] - u[k]),
            " differs from the period u_", p + N, " - u_", p, " = ", CGAL::to_double(T),
            " (a closed curve's knot intervals repeat with period n - p = ", N, ")");
  }
}

/// The span index i with u_i <= x < u_{i+1}, p <= i < n, for x in the domain [u_p, u_n]; x = u_n
/// gives the last non-empty span. O(log n).
template <class FT>
std::size_t find_span(std::size_t p, std::size_t n, const std::vector<FT>& u, const FT& x) {
  if (!(x < u[n])) {
    std::size_t i = n - 1;
    while (!(u[i] < u[i + 1])) --i; // the domain is non-empty, so this stops at i >= p
    return i;
  }
  // the last k in [p, n) with u_k <= x: upper_bound over u[p+1 .. n]
  const auto it = std::upper_bound(u.begin() + static_cast<long>(p) + 1, u.begin() + static_cast<long>(n) + 1, x);
  return static_cast<std::size_t>(it - u.begin()) - 1;
}

/// The multiplicity of the value x among the knots.
template <class FT>
std::size_t multiplicity(const std::vector<FT>& u, const FT& x) {
  return static_cast<std::size_t>(std::count(u.begin(), u.end(), x));
}

}  // namespace nurbs
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_NURBS_KNOT_VECTOR_H
