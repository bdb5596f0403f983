// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The exact conversion of Karciauskas-Peters Sec. 6 (eqs. 9, 10 as corrected in issue 10),
// in homogeneous coordinates (w x, w y, w):
//  - degree elevation of a rational Bezier piece of degree <= 3 to degree 3;
//  - the blossom f^h[a, b, c] of the homogeneous cubic by three de Casteljau steps (each step
//    is an affine combination, so the result is exact in an exact kernel);
//  - the de Boor points of the clamped spline on 0 = u_0 < u_1 < ... < u_m = 1:
//    d_k = f^h[tau_{k+1}, tau_{k+2}, tau_{k+3}] over the knot vector tau = (0,0,0,0, u_1..u_{m-1},
//    1,1,1,1). For 1 <= k-1 <= m-1 this is eq. 9, c_i = f^h[u_{i-1}, u_i, u_{i+1}]; the two
//    first are f^h[0,0,0] = b_0 and f^h[0,0,u_1] = b_1^0 (the corrected eq. 10), mirrored at the
//    end. The de Boor points of a spline are the blossoms of its pieces at consecutive knot
//    triples (the blossoming principle), so this IS knot insertion of u_1..u_{m-1} into the one
//    Bezier piece, and the spline equals f on all of [0,1].

#ifndef FAIR_INTERNAL_EXACT_CONVERSION_BLOSSOM_H
#define FAIR_INTERNAL_EXACT_CONVERSION_BLOSSOM_H

#include <fair/Errors.h>
#include <fair/Rational_bezier_2.h>
#include <fair/internal/spline/bspline_form.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace fair {
namespace internal {
namespace exact_conversion {

/// A homogeneous point (w x, w y, w): the spline's own type.
template <class FT>
using Homogeneous = spline::Homogeneous_point<FT>;

/// (1 - t) a + t b.
template <class FT>
Homogeneous<FT> lerp(const Homogeneous<FT>& a, const Homogeneous<FT>& b, const FT& t) {
  return spline::combine(FT(1) - t, a, t, b);
}

/// The homogeneous Bezier coefficients of the piece, degree-elevated to 3 (b_i^{n+1} =
/// (i b_{i-1} + (n+1-i) b_i)/(n+1) applied to (w P, w)). \throws Precondition_error if the
/// degree exceeds 3.
template <class K>
std::array<Homogeneous<typename K::FT>, 4> homogeneous_cubic(const Rational_bezier_2<K>& c, const char* fn) {
  typedef typename K::FT FT;
  require(c.degree() <= 3, fn, ": the curve has degree ", c.degree(), "; only degree <= 3 converts exactly to a cubic spline");
  std::vector<Homogeneous<FT>> h;
  for (std::size_t i = 0; i <= c.degree(); ++i) {
    const FT& w = c.weights()[i];
    h.push_back(Homogeneous<FT>{w * c.control_points()[i].x(), w * c.control_points()[i].y(), w});
  }
  while (h.size() < 4) {
    const std::size_t n = h.size() - 1;
    std::vector<Homogeneous<FT>> e(n + 2);
    e[0] = h[0];
    e[n + 1] = h[n];
    for (std::size_t i = 1; i <= n; ++i) {
      const FT a = FT(int(i)) / FT(int(n + 1)), b = FT(int(n + 1 - i)) / FT(int(n + 1));
      e[i] = spline::combine(a, h[i - 1], b, h[i]);
    }
    h.swap(e);
  }
  return {{h[0], h[1], h[2], h[3]}};
}

/// In a floating FT the blossoms are convex combinations of the weights, positive when every
/// weight is a normal positive double; a subnormal weight (5e-324) underflows to 0 in them and
/// w x loses all its digits (issue 29 #9). Refused with the weight named: the curve does not
/// change when all weights are multiplied by one factor, so the user can scale them up. An
/// exact FT has no such limit.
template <class K>
void check_weights(const Rational_bezier_2<K>& c, const char* fn) {
  typedef typename K::FT FT;
  typedef typename CGAL::Algebraic_structure_traits<FT>::Is_exact Is_exact;
  if constexpr (!Is_exact::value || std::is_floating_point<FT>::value) {
    for (std::size_t i = 0; i < c.weights().size(); ++i) {
      const double w = CGAL::to_double(c.weights()[i]);
      if (!(w >= std::numeric_limits<double>::min()) || !std::isfinite(w))
        throw Invalid_input_error(message(fn, ": weight ", i, " = ", w, " is ",
                                          w > 0 ? "subnormal (below 2.2250738585072014e-308)" : "not a positive finite number",
                                          ": the conversion's blossoms underflow in floating point; multiply all weights "
                                          "by one factor (the curve stays the same) or use an exact kernel"));
    }
  }
}

/// The blossom (polar form) f^h[a, b, c] of the homogeneous cubic with coefficients b: three
/// de Casteljau steps with the three arguments (symmetric in a, b, c; f^h[t,t,t] = f^h(t)).
template <class FT>
Homogeneous<FT> blossom(const std::array<Homogeneous<FT>, 4>& b, const FT& u, const FT& v, const FT& t) {
  const Homogeneous<FT> p0 = lerp(b[0], b[1], u), p1 = lerp(b[1], b[2], u), p2 = lerp(b[2], b[3], u);
  const Homogeneous<FT> q0 = lerp(p0, p1, v), q1 = lerp(p1, p2, v);
  return lerp(q0, q1, t);
}

/// Throws Invalid_input_error unless 0 < u_1 < ... < u_{m-1} < 1 and every mark is finite.
template <class FT>
void check_marks(const std::vector<FT>& u, const char* fn) {
  for (std::size_t i = 0; i < u.size(); ++i) {
    const double d = CGAL::to_double(u[i]);
    if (!std::isfinite(d))
      throw Invalid_input_error(message(fn, ": interior parameter ", i, " = ", d, " is not finite"));
    if (!(u[i] > FT(0) && u[i] < FT(1)))
      throw Invalid_input_error(message(fn, ": interior parameter ", i, " = ", d, " is not in the open interval (0, 1)"));
    if (i > 0 && !(u[i - 1] < u[i]))
      throw Invalid_input_error(message(fn, ": interior parameters must increase strictly, but u[", i - 1, "] = ",
                                        CGAL::to_double(u[i - 1]), " >= u[", i, "] = ", d));
  }
}

/// The m+3 homogeneous de Boor points of the clamped spline on the breakpoints 0, u, 1 (see the
/// file comment), O(m).
template <class FT>
std::vector<Homogeneous<FT>> de_boor_points(const std::array<Homogeneous<FT>, 4>& b, const std::vector<FT>& u) {
  std::vector<FT> tau(3, FT(0));
  tau.insert(tau.end(), u.begin(), u.end());
  tau.insert(tau.end(), 3, FT(1));
  std::vector<Homogeneous<FT>> d;
  d.reserve(tau.size() - 2);
  for (std::size_t k = 0; k + 2 < tau.size(); ++k) d.push_back(blossom(b, tau[k], tau[k + 1], tau[k + 2]));
  return d;
}

/// The breakpoints 0, u_1, ..., u_{m-1}, 1.
template <class FT>
std::vector<FT> unit_breakpoints(const std::vector<FT>& u) {
  std::vector<FT> t(1, FT(0));
  t.insert(t.end(), u.begin(), u.end());
  t.push_back(FT(1));
  return t;
}

} // namespace exact_conversion
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_EXACT_CONVERSION_BLOSSOM_H
