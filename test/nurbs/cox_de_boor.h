// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The independent oracle of the NURBS tests: a Nurbs_curve_2 evaluated by the Cox-de Boor
// recursion, literally, from its knots, control points and weights alone -- nothing of the
// class's blossoming, pieces or joints (doc/nurbs.md §3, §7):
//
//   N_{k,0}(x) = 1 on the span of x, 0 elsewhere,
//   N_{k,p}(x) = (x - u_k)/(u_{k+p} - u_k) N_{k,p-1}(x) + (u_{k+p+1} - x)/(u_{k+p+1} - u_{k+1}) N_{k+1,p-1}(x)
//
// (0/0 = 0), c(x) = sum_k N_{k,p} w_k P_k / sum_k N_{k,p} w_k. The side says which span a knot
// belongs to: RIGHT uses the half-open spans [u_k, u_{k+1}) (the value at x from the right), LEFT
// the spans (u_k, u_{k+1}] (the limit from the left). Outside the domain, where the stored vector
// still has spans (a closed curve's periodic extension), the sum misses one basis function of the
// missing index -1 or n; at u_p from the left and at u_n from the right that function is 0 unless
// the knot has multiplicity p + 1, which a closed curve's seam never has, so c(u_p^-) and c(u_n^+)
// are the periodic curve's values there.

#ifndef FAIR_TEST_NURBS_COX_DE_BOOR_H
#define FAIR_TEST_NURBS_COX_DE_BOOR_H

#include <fair/Nurbs_curve_2.h>

#include <cstddef>
#include <vector>

namespace fair_test {

enum class Side { LEFT, RIGHT };

template <class FT>
FT cox_de_boor_basis(const std::vector<FT>& u, std::size_t k, std::size_t p, const FT& x, Side side) {
  if (p == 0) {
    if (!(u[k] < u[k + 1])) return FT(0);
    const bool in = side == Side::RIGHT ? !(x < u[k]) && x < u[k + 1] : u[k] < x && !(u[k + 1] < x);
    return in ? FT(1) : FT(0);
  }
  FT v(0);
  if (u[k + p] != u[k]) v = v + (x - u[k]) / (u[k + p] - u[k]) * cox_de_boor_basis(u, k, p - 1, x, side);
  if (u[k + p + 1] != u[k + 1])
    v = v + (u[k + p + 1] - x) / (u[k + p + 1] - u[k + 1]) * cox_de_boor_basis(u, k + 1, p - 1, x, side);
  return v;
}

/// c(x) from the given side (see the file comment).
template <class K>
typename K::Point_2 cox_de_boor(const fair::Nurbs_curve_2<K>& c, const typename K::FT& x, Side side) {
  typedef typename K::FT FT;
  FT X(0), Y(0), W(0);
  for (std::size_t k = 0; k < c.number_of_control_points(); ++k) {
    const FT b = cox_de_boor_basis(c.knots(), k, c.degree(), x, side) * c.weights()[k];
    X = X + b * c.control_points()[k].x();
    Y = Y + b * c.control_points()[k].y();
    W = W + b;
  }
  return typename K::Point_2(X / W, Y / W);
}

/// c(x) for x in the domain: from the right, except at the domain's end u_n (from the left).
template <class K>
typename K::Point_2 cox_de_boor(const fair::Nurbs_curve_2<K>& c, const typename K::FT& x) {
  return cox_de_boor(c, x, x < c.domain().second ? Side::RIGHT : Side::LEFT);
}

}  // namespace fair_test

#endif  // FAIR_TEST_NURBS_COX_DE_BOOR_H
