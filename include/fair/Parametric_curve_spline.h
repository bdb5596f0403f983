// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Parametric curves in the cubic C2 spline framework (Karciauskas-Peters, Sec. 5): a
// ParametricCurve_2 f (Parametric_curve_2.h) with marks u_0 < u_1 < ... < u_m (u_0, u_m the ends
// of the part of f used) ->
//   - quintic_pieces: the quintic 2-jet interpolants of eq. 7, with LOCAL derivatives h_i f',
//     h_i^2 f'' (h_i = u_{i+1} - u_i; the paper's eq. 7 read literally does not reproduce cubics);
//   - parametric_curve_spline: the open cubic C2 spline with breakpoints u_i whose control
//     point c_i comes from the 2-jet of f at u_i (eq. 8 then eq. 3; in closed form
//     c_i = f(u_i) + (h_i - h_{i-1})/3 f'(u_i) - h_{i-1} h_i / 6 f''(u_i)); its ends are eq. 10's
//     Bezier points f(u_0), f(u_0) + h_0/3 f'(u_0) and their mirror images at u_m;
//   - parametric_curve_hybrid: quintics on [u_2, u_{m-2}], the cubic spline outside, joined C2.
// Accuracy (measured, doc/parametric_curves.md): the quintics converge as O(h^6) in position, the
// spline as O(h^4); cubic precision: a cubic f is reproduced, exactly in an exact kernel when its
// jets are doubles. The jets are double, every later step is computed in FT from FT(double).
// Complexity O(m).

#ifndef FAIR_PARAMETRIC_CURVE_SPLINE_H
#define FAIR_PARAMETRIC_CURVE_SPLINE_H

#include <fair/Bezier_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/Errors.h>
#include <fair/Parametric_curve_2.h>
#include <fair/internal/parametric/construction.h>

#include <array>
#include <cstddef>
#include <vector>

namespace fair {

/// Options of the constructions of this header.
struct Parametric_spline_options {
  /// Reject a mark where f' = 0 (no tangent: the spline's curvature there would be unbounded).
  bool require_regular = true;
};

/// The m quintic pieces of eq. 7 (piece i over [u_i, u_{i+1}], parametrised over [0, 1]):
/// b_0 = f(u_i), b_1 = b_0 + h_i/5 f'(u_i), b_2 = b_0 + 2h_i/5 f'(u_i) + h_i^2/20 f''(u_i),
/// and the mirror images at u_{i+1}; so the pieces join C2 in the global parameter u.
/// \throws Invalid_input_error for fewer than 2 marks, marks not strictly increasing or outside
/// f's domain, a non-finite jet, or (require_regular) f' = 0 at a mark.
template <class K, class Curve>
std::vector<Bezier_2<K>> quintic_pieces(const Curve& f, const std::vector<double>& marks,
                                        const Parametric_spline_options& options = Parametric_spline_options()) {
  internal::parametric::check_marks(f, marks, 1, "fair::quintic_pieces");
  const std::vector<Curve_jet_2> j = internal::parametric::jets_at(f, marks, options.require_regular, "fair::quintic_pieces");
  std::vector<Bezier_2<K>> q;
  q.reserve(marks.size() - 1);
  for (std::size_t i = 0; i + 1 < marks.size(); ++i)
    q.push_back(internal::parametric::quintic_piece<K>(marks[i], j[i], marks[i + 1], j[i + 1]));
  return q;
}

/// The open (clamped) cubic C2 spline approximating f on [u_0, u_m], breakpoints = the marks
/// (m >= 1 pieces; m = 1 is the cubic Hermite interpolant of the end 2-jets' tangents).
/// Control points (layout of Cubic_spline_2): d_0 = f(u_0), d_1 = f(u_0) + h_0/3 f'(u_0) (eq. 8 on
/// the first quintic, eq. 10: the end is the Bezier end of the first piece, no phantom interval,
/// so no beta is needed there), d_{i+1} = c_i by eq. 3 from the eq.-8 cubic 2-jet of quintic i
/// (1 <= i <= m-1), d_{m+1} = f(u_m) - h_{m-1}/3 f'(u_m), d_{m+2} = f(u_m). So the spline starts
/// at f(u_0), ends at f(u_m), tangent to f there. \throws as quintic_pieces.
template <class K, class Curve>
Cubic_spline_2<K> parametric_curve_spline(const Curve& f, const std::vector<double>& marks,
                                          const Parametric_spline_options& options = Parametric_spline_options()) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  namespace ip = internal::parametric;
  ip::check_marks(f, marks, 1, "fair::parametric_curve_spline");
  const char* fn = "fair::parametric_curve_spline";
  const bool regular = options.require_regular;
  const std::size_t m = marks.size() - 1;
  std::vector<FT> t;
  t.reserve(m + 1);
  for (double u : marks) t.push_back(FT(u));
  std::vector<Point_2> d;
  d.reserve(m + 3);
  Point_2 bb1, bb2;
  // the quintic's 2-jet at the start of piece 0 (eq. 7) -> eq. 8
  std::array<Point_2, 3> b = ip::quintic_end<K>(ip::jet_at(f, marks[0], 0, regular, fn), marks[0], marks[1], true);
  ip::cubic_jet<K>(b, bb1, bb2);
  d.push_back(b[0]);
  d.push_back(bb1);
  for (std::size_t i = 1; i < m; ++i) {
    // eq. 3 on the cubic 2-jet at u_i of piece i: c_i = (1 + 1/beta_i) b_1^i - (1/beta_i) b_2^i
    ip::cubic_jet<K>(ip::quintic_end<K>(ip::jet_at(f, marks[i], i, regular, fn), marks[i], marks[i + 1], true), bb1, bb2);
    const FT inv_beta = (t[i] - t[i - 1]) / (t[i + 1] - t[i]);
    d.push_back(internal::common::combine<K>(FT(1) + inv_beta, bb1, -inv_beta, bb2, FT(0), bb2));
  }
  // the 2-jet at the end of piece m-1 (b5, b4, b3), mirrored
  b = ip::quintic_end<K>(ip::jet_at(f, marks[m], m, regular, fn), marks[m - 1], marks[m], false);
  ip::cubic_jet<K>(b, bb1, bb2);
  d.push_back(bb1);
  d.push_back(b[0]);
  return Cubic_spline_2<K>(std::move(t), std::move(d));
}

/// The hybrid curve of Sec. 5 as m degree-5 pieces (piece i over [u_i, u_{i+1}], on [0, 1]):
/// the quintics of eq. 7 on [u_2, u_{m-2}], the cubic spline (degree-elevated) on [u_0, u_1] and
/// [u_{m-1}, u_m], and on [u_1, u_2], [u_{m-2}, u_{m-1}] the quintic with the spline's 2-jet at
/// u_1 (resp. u_{m-1}) and f's 2-jet at u_2 (resp. u_{m-2}). C2 in u at every breakpoint by
/// construction. (Replacing the spline's pieces by the quintics without these transitions is
/// not C2: the spline does not interpolate f's 2-jets.) Needs m >= 4. \throws as quintic_pieces.
template <class K, class Curve>
std::vector<Bezier_2<K>> parametric_curve_hybrid(const Curve& f, const std::vector<double>& marks,
                                                 const Parametric_spline_options& options = Parametric_spline_options()) {
  typedef typename K::Point_2 Point_2;
  internal::parametric::check_marks(f, marks, 4, "fair::parametric_curve_hybrid");
  const std::vector<Bezier_2<K>> q = quintic_pieces<K>(f, marks, options);
  const Cubic_spline_2<K> s = parametric_curve_spline<K>(f, marks, options);
  const std::size_t m = q.size();
  auto elevated = [&](std::size_t i) { return s.polynomial_piece(i).elevated().elevated(); };
  std::vector<Bezier_2<K>> out;
  out.reserve(m);
  out.push_back(elevated(0));
  const std::vector<Point_2> e1 = elevated(1).control_points(), e2 = elevated(m - 2).control_points();
  const std::vector<Point_2>& q1 = q[1].control_points();
  out.push_back(Bezier_2<K>(std::vector<Point_2>{e1[0], e1[1], e1[2], q1[3], q1[4], q1[5]}));
  for (std::size_t i = 2; i + 2 < m; ++i) out.push_back(q[i]);
  const std::vector<Point_2>& q2 = q[m - 2].control_points();
  out.push_back(Bezier_2<K>(std::vector<Point_2>{q2[0], q2[1], q2[2], e2[3], e2[4], e2[5]}));
  out.push_back(elevated(m - 1));
  return out;
}

} // namespace fair

#endif // FAIR_PARAMETRIC_CURVE_SPLINE_H
