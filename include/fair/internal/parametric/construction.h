// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Sec. 5 of Karciauskas-Peters: a parametric curve f with marks u_0 < ... < u_m -> quintic
// pieces (eq. 7 with local derivatives) -> cubic 2-jets (eq. 8) -> C2 spline control points
// (eq. 3). Derivations in doc/parametric_curves.md. The jets are doubles; everything after
// them is computed in the kernel's FT (FT(double) is exact), so in an exact kernel the spline
// is the exact image of the double jets.

#ifndef FAIR_INTERNAL_PARAMETRIC_CONSTRUCTION_H
#define FAIR_INTERNAL_PARAMETRIC_CONSTRUCTION_H

#include <fair/Bezier_2.h>
#include <fair/Errors.h>
#include <fair/Parametric_curve_2.h>
#include <fair/internal/common/combination.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace parametric {

/// Marks are user data: at least min_pieces + 1 of them, finite, strictly increasing, inside
/// f's domain. Throws Invalid_input_error naming the index and the values.
template <class Curve>
void check_marks(const Curve& f, const std::vector<double>& u, std::size_t min_pieces, const char* fn) {
  if (u.size() < min_pieces + 1)
    throw Invalid_input_error(message(fn, ": needs at least ", min_pieces + 1, " marks (", min_pieces, " pieces), got ", u.size()));
  const double a = f.parameter_begin(), b = f.parameter_end();
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (!std::isfinite(u[i]) || u[i] < a || u[i] > b)
      throw Invalid_input_error(message(fn, ": mark ", i, " = ", u[i], " is outside the curve's domain [", a, ", ", b, "]"));
    if (i > 0 && !(u[i - 1] < u[i]))
      throw Invalid_input_error(message(fn, ": marks ", i - 1, " = ", u[i - 1], " and ", i, " = ", u[i],
                                        " are not strictly increasing"));
  }
}

/// The 2-jet of f at mark i (u = u_i); throws Invalid_input_error if it is not finite or (when
/// require_regular) f'(u_i) = 0, where the curve has no tangent.
template <class Curve>
Curve_jet_2 jet_at(const Curve& f, double u, std::size_t i, bool require_regular, const char* fn) {
  const Curve_jet_2 q = f.jet(u);
  if (!(std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.dx) && std::isfinite(q.dy) && std::isfinite(q.ddx) &&
        std::isfinite(q.ddy)))
    throw Invalid_input_error(message(fn, ": the curve's 2-jet at mark ", i, " (u = ", u, ") is not finite"));
  if (require_regular && q.dx == 0 && q.dy == 0)
    throw Invalid_input_error(message(fn, ": the curve is singular at mark ", i, " (u = ", u, "): f' = 0"));
  return q;
}

/// The 2-jets of f at all marks (jet_at each).
template <class Curve>
std::vector<Curve_jet_2> jets_at(const Curve& f, const std::vector<double>& u, bool require_regular, const char* fn) {
  std::vector<Curve_jet_2> j;
  j.reserve(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) j.push_back(jet_at(f, u[i], i, require_regular, fn));
  return j;
}

/// Eq. 7 with local derivatives at one end of a piece: (b0, b1, b2) = (f, f + s h/5 f',
/// f + s 2h/5 f' + h^2/20 f'') with h = u1 - u0 in FT and s = +1 at the start of the piece
/// (u = u_i), s = -1 at its end (u = u_{i+1}: b5, b4, b3).
template <class K>
std::array<typename K::Point_2, 3> quintic_end(const Curve_jet_2& j, double u0, double u1, bool at_start) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  const FT h = FT(u1) - FT(u0), h5 = (at_start ? h : -h) / FT(5), h2 = FT(2) * h5, hh = h * h / FT(20);
  const FT x(j.x), y(j.y), dx(j.dx), dy(j.dy), ax(j.ddx), ay(j.ddy);
  return {P(x, y), P(x + h5 * dx, y + h5 * dy), P(x + h2 * dx + hh * ax, y + h2 * dy + hh * ay)};
}

/// The quintic of eq. 7 on [u_i, u_i+1] reparametrised to [0,1]: the 2-jets (f, h f', h^2 f'')
/// of f at both ends, h = u_i+1 - u_i.
template <class K>
Bezier_2<K> quintic_piece(double u0, const Curve_jet_2& j0, double u1, const Curve_jet_2& j1) {
  const std::array<typename K::Point_2, 3> a = quintic_end<K>(j0, u0, u1, true), b = quintic_end<K>(j1, u0, u1, false);
  return Bezier_2<K>(std::vector<typename K::Point_2>{a[0], a[1], a[2], b[2], b[1], b[0]});
}

/// Eq. 8: the cubic with the quintic's 2-jet (b0, b1, b2) at an end -> its control points
/// (b0, -2/3 b0 + 5/3 b1, b0 - 10/3 b1 + 10/3 b2); returns the second and the third.
template <class K>
void cubic_jet(const std::array<typename K::Point_2, 3>& b, typename K::Point_2& bb1, typename K::Point_2& bb2) {
  typedef typename K::FT FT;
  bb1 = common::combine<K>(FT(-2) / FT(3), b[0], FT(5) / FT(3), b[1], FT(0), b[2]);
  bb2 = common::combine<K>(FT(1), b[0], FT(-10) / FT(3), b[1], FT(10) / FT(3), b[2]);
}

} // namespace parametric
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_PARAMETRIC_CONSTRUCTION_H
