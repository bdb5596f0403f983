// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Quadratic design from sparse data (Karciauskas-Peters Sec. 7, eq. 12, Figs. 16 and 19):
// from a sparse polygon q_0..q_{n-1} with parameters t_i, the quadratic Bezier shapes
// {q_i, m_i, q_{i+1}} with m_i = mu_{i+1} m_i^L + (1 - mu_{i+1}) m_i^R, where m_i^L (m_i^R) is the
// middle Bezier coefficient on [t_i, t_{i+1}] of the quadratic f_i (f_{i+1}) interpolating the
// points around q_i (q_{i+1}), and mu_{i+1} = kappa_{i+1} / (kappa_i + kappa_{i+1}) weighs each side by
// the curvature of the other (eq. 6). Derivation and the end rule in doc/exact_conversion.md.
// Then the Sec. 6 conversion of the chain of shapes with the designer's marks ("rounding
// areas", Fig. 19b) into one C2 cubic spline that retains each shape exactly between its
// second and second-to-last mark.
// Exactness: m_i^L, m_i^R are exact in an exact kernel; mu needs curvatures (square roots),
// computed in double and converted exactly to FT, so m_i is exact for those rounded weights;
// chordal parameters are rounded the same way (Knot_spacing.h); uniform or given parameters keep
// everything but mu exact. O(n).

#ifndef FAIR_QUADRATIC_DESIGN_H
#define FAIR_QUADRATIC_DESIGN_H

#include <fair/Bezier_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/Errors.h>
#include <fair/Knot_spacing.h>
#include <fair/Rational_bezier_2.h>
#include <fair/internal/classic/common.h>
#include <fair/internal/common/input_checks.h>
#include <fair/internal/exact_conversion/chain.h>
#include <fair/internal/exact_conversion/quadratic_design.h>

#include <CGAL/number_utils.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace fair {

/// Options of quadratic_design_shapes.
struct Quadratic_design_options {
  /// Parameters t_i of the points when none are given.
  Knot_spacing spacing = Knot_spacing::CHORDAL;
  /// eq. 6's tolerance: mu = 1/2 where kappa_i + kappa_{i+1} <= epsilon (curvature units, 1/length).
  double epsilon = 1e-12;
  /// quadratic_design_spline: the rounding area rho of rounding_marks (0 < rho < 1/2; a double,
  /// converted exactly to FT).
  double rounding = 0.25;
};

/// The quadratic shapes {q_i, m_i, q_{i+1}} (Bezier_2 of degree 2): n-1 of them for an open
/// polygon, n for a closed one (the last from q_{n-1} back to q_0). Open ends are one-sided: the
/// first shape takes m_0^R, the last m_{n-2}^L (both from the end's only local quadratic), so
/// three points give one parabola; two points give the segment with its midpoint.
/// \throws Invalid_input_error for fewer than 2 points (3 closed), non-finite or coincident
/// consecutive points, or a local quadratic whose tangent vanishes at its middle point.
template <class K>
std::vector<Bezier_2<K>> quadratic_design_shapes(const std::vector<typename K::Point_2>& q, bool closed = false,
                                                 const Quadratic_design_options& options = {}) {
  const char* fn = "quadratic_design_shapes";
  internal::common::check_interpolation_input(q, closed ? 3 : 2, closed, fn);
  const std::vector<typename K::FT> h = internal::classic::classic_knot_intervals<K>(q, closed, options.spacing, fn);
  return internal::exact_conversion::quadratic_shapes<K>(q, h, closed, options.epsilon, fn);
}

/// The same with given parameters t_0 < t_1 < ... (n of them open; n+1 closed, the last being
/// the parameter of the return to q_0).
/// \throws Invalid_input_error as above, or if the parameters are too few, too many, not
/// finite or not strictly increasing.
template <class K>
std::vector<Bezier_2<K>> quadratic_design_shapes(const std::vector<typename K::Point_2>& q,
                                                 const std::vector<typename K::FT>& parameters, bool closed = false,
                                                 double epsilon = Quadratic_design_options().epsilon) {
  typedef typename K::FT FT;
  const char* fn = "quadratic_design_shapes";
  internal::common::check_interpolation_input(q, closed ? 3 : 2, closed, fn);
  const std::size_t expected = closed ? q.size() + 1 : q.size();
  if (parameters.size() != expected)
    throw Invalid_input_error(internal::message(fn, ": ", q.size(), " points need ", expected, " parameters, got ",
                                                parameters.size()));
  std::vector<FT> h;
  for (std::size_t i = 0; i + 1 < parameters.size(); ++i) {
    const double a = CGAL::to_double(parameters[i]), b = CGAL::to_double(parameters[i + 1]);
    if (!std::isfinite(a) || !std::isfinite(b) || !(parameters[i] < parameters[i + 1]))
      throw Invalid_input_error(internal::message(fn, ": parameters must be finite and increase strictly, but t[", i,
                                                  "] = ", a, ", t[", i + 1, "] = ", b));
    h.push_back(parameters[i + 1] - parameters[i]);
  }
  return internal::exact_conversion::quadratic_shapes<K>(q, h, closed, epsilon, fn);
}

/// The "rounding area" marks of Fig. 19b on every shape: {rho/2, rho, 1 - rho, 1 - rho/2}. The
/// spline then keeps each shape exactly on [rho, 1 - rho] and rounds the joins in between.
/// \throws Precondition_error unless 0 < rho < 1/2.
template <class FT>
std::vector<FT> rounding_marks(const FT& rho) {
  internal::require(rho > FT(0) && FT(2) * rho < FT(1), "rounding_marks: rho = ", CGAL::to_double(rho),
                    " must be in (0, 1/2)");
  return {rho / FT(2), rho, FT(1) - rho, FT(1) - rho / FT(2)};
}

/// One C2 cubic spline from a chain of rational (or polynomial) Bezier shapes of degree <= 3
/// whose consecutive end points agree exactly, with equal weights there (closed: also the last
/// and the first), every shape converted by exact_spline with the same interior marks
/// (0 < u_1 < ... < 1) and the polygons concatenated with the shared end points as control points
/// (beta = 1 at the added control points; at the shared point beta = u_1 / (1 - u_{m-1}), 1 for
/// symmetric marks). Shape j occupies the parameter interval [j P, j P + 1] (closed: shifted by
/// u_1), P = 2 + u_1 - u_{m-1}, and is reproduced exactly (exact kernel) between its marks u_2
/// and u_{m-2}, and up to the clamped end of an open chain. (The basic-shape design
/// (include/fair/Basic_shape_design.h) also merges close and separate ends; this is the chain of
/// shapes that share their ends.) O(total marks).
/// \throws Invalid_input_error for no shape (fewer than 2 closed), end points or end weights that
/// differ, or bad marks; Precondition_error for a degree above 3.
template <class K>
Cubic_spline_2<K> bezier_chain_spline(const std::vector<Rational_bezier_2<K>>& shapes,
                                      const std::vector<typename K::FT>& marks, bool closed = false) {
  internal::exact_conversion::Chain_layout<K> l =
      internal::exact_conversion::chain_layout<K>(shapes, marks, closed, "bezier_chain_spline");
  if (!l.rational) return Cubic_spline_2<K>(std::move(l.breakpoints), std::move(l.control_points), closed);
  return Cubic_spline_2<K>(std::move(l.breakpoints), std::move(l.control_points), std::move(l.weights), closed);
}

/// The same for polynomial shapes (a polynomial spline).
template <class K>
Cubic_spline_2<K> bezier_chain_spline(const std::vector<Bezier_2<K>>& shapes, const std::vector<typename K::FT>& marks,
                                      bool closed = false) {
  std::vector<Rational_bezier_2<K>> r;
  r.reserve(shapes.size());
  for (const Bezier_2<K>& b : shapes) r.push_back(Rational_bezier_2<K>(b.control_points()));
  return bezier_chain_spline(r, marks, closed);
}

/// The whole Sec. 7 pipeline: quadratic_design_shapes, then bezier_chain_spline with
/// rounding_marks(options.rounding) -- the C2 spline that retains every quadratic shape exactly
/// on [rho, 1 - rho] of its parameter and rounds the joins (Fig. 19b, c).
/// \throws as quadratic_design_shapes; Precondition_error for a rounding outside (0, 1/2).
template <class K>
Cubic_spline_2<K> quadratic_design_spline(const std::vector<typename K::Point_2>& q, bool closed = false,
                                          const Quadratic_design_options& options = {}) {
  typedef typename K::FT FT;
  internal::require(options.rounding > 0 && options.rounding < 0.5, "quadratic_design_spline: rounding ",
                    options.rounding, " must be in (0, 1/2)");
  return bezier_chain_spline(quadratic_design_shapes<K>(q, closed, options), rounding_marks(FT(options.rounding)), closed);
}

} // namespace fair

#endif // FAIR_QUADRATIC_DESIGN_H
