// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The curvature polynomials of a planar rational Bezier curve c = (X, Y)/W in Bernstein form,
// in any number type (exact Gmpq for certificates, CGAL::Interval_nt for filters):
//  - D = det[[X, Y, W], [X', Y', W'], [X'', Y'', W'']], with det(c', c'') = D / W^3, so for
//    W > 0 the sign of the curvature where c' != 0. As Bernstein products of degrees n, n-1,
//    n-2 it is stored with degree 3n - 3; its true degree is 3n - 6 (the leading terms cancel).
//    For a polynomial curve (W = 1) it reduces to x'y'' - y'x'' (stored degree 2n - 3, true
//    degree 2n - 4).
//  - the hodograph numerators A = (X'W - XW', Y'W - YW'), c' = A / W^2 (stored degree 2n - 1,
//    true degree 2n - 2).

#ifndef FAIR_INTERNAL_BERNSTEIN_CURVATURE_H
#define FAIR_INTERNAL_BERNSTEIN_CURVATURE_H

#include <fair/Bernstein_polynomial.h>

namespace fair {
namespace internal {
namespace bernstein {

/// x'y'' - y'x'' of a polynomial curve (x, y).
template <class NT>
Bernstein_polynomial<NT> polynomial_curvature_determinant(const Bernstein_polynomial<NT>& X,
                                                          const Bernstein_polynomial<NT>& Y) {
  const Bernstein_polynomial<NT> X1 = X.derivative(), Y1 = Y.derivative();
  return X1 * Y1.derivative() - Y1 * X1.derivative();
}

/// det[[X, Y, W], [X', Y', W'], [X'', Y'', W'']] of a rational curve (X, Y)/W.
template <class NT>
Bernstein_polynomial<NT> curvature_determinant(const Bernstein_polynomial<NT>& X, const Bernstein_polynomial<NT>& Y,
                                               const Bernstein_polynomial<NT>& W) {
  const Bernstein_polynomial<NT> X1 = X.derivative(), Y1 = Y.derivative(), W1 = W.derivative();
  const Bernstein_polynomial<NT> X2 = X1.derivative(), Y2 = Y1.derivative(), W2 = W1.derivative();
  return X * (Y1 * W2 - W1 * Y2) - Y * (X1 * W2 - W1 * X2) + W * (X1 * Y2 - Y1 * X2);
}

/// The hodograph numerators Ax = X'W - XW', Ay = Y'W - YW' of a rational curve (X, Y)/W.
template <class NT>
void hodograph_numerators(const Bernstein_polynomial<NT>& X, const Bernstein_polynomial<NT>& Y,
                          const Bernstein_polynomial<NT>& W, Bernstein_polynomial<NT>& Ax,
                          Bernstein_polynomial<NT>& Ay) {
  const Bernstein_polynomial<NT> W1 = W.derivative();
  Ax = X.derivative() * W - X * W1;
  Ay = Y.derivative() * W - Y * W1;
}

} // namespace bernstein
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_BERNSTEIN_CURVATURE_H
