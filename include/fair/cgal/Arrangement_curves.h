// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::to_arrangement_curves<ArrTraits>(curve, out): the pieces of a Nurbs_curve_2 as curves of
// a CGAL 2D arrangement, exactly, so that CGAL computes their intersections, overlaps and faces
// with exact predicates (doc/nurbs.md, "CGAL arrangements"). Two traits classes are supported:
//
//  - CGAL::Arr_Bezier_curve_traits_2<Rat_kernel, Alg_kernel, Nt_traits>: every polynomial piece
//    (any degree: every cubic spline, a kappa-curve with unit weights, degree-1 pieces) as a
//    Bezier curve with its control points converted to exact rationals;
//  - CGAL::Arr_conic_traits_2<Rat_kernel, Alg_kernel, Nt_traits>: pieces of degree <= 2,
//    rational or not (a kappa-curve with any weights): a quadratic piece with weights w0, w1,
//    w2 as the conic arc from P0 to P2 on the conic
//        w0 w2 L1(X)^2 - 4 w1^2 L0(X) L2(X) = 0,
//    L0(X) = det(P1 - X, P2 - X), L1(X) = det(P2 - X, P0 - X), L2(X) = det(P0 - X, P1 - X),
//    (eq. 14 of Yan et al. for the standard form, whose weight is w1 / sqrt(w0 w2): the curve is
//    tau1^2 = 4 w1^2 / (w0 w2) tau0 tau2 in the barycentric coordinates tau_i = L_i / D of the
//    control triangle), with rational coefficients because only w1^2 and w0 w2 appear (w1^2 of
//    a double w1 is rational, its square root is not needed), traversed with the orientation of
//    the triangle (P0, P1, P2) (the arc turns towards P1); a piece of degree 1, or of degree 2
//    with collinear control points P1 in [P0, P2], as the segment P0 P2.
//
// Every coordinate converts exactly (cgal/internal/exact_rational.h) and the pieces of a
// Nurbs_curve_2 share their joints bit for bit (a closed curve's last piece ends on the first's
// start), so consecutive curves meet at one arrangement vertex: the arrangement of a simple
// closed curve has exactly two faces.
//
// Usage (CORE number types, as CGAL's examples):
//   typedef CGAL::CORE_algebraic_number_traits Nt_traits;
//   typedef CGAL::Cartesian<Nt_traits::Rational> Rat_kernel;
//   typedef CGAL::Cartesian<Nt_traits::Algebraic> Alg_kernel;
//   typedef CGAL::Arr_conic_traits_2<Rat_kernel, Alg_kernel, Nt_traits> Traits;
//   std::vector<Traits::Curve_2> curves;
//   fair::to_arrangement_curves<Traits>(kappa.nurbs(), std::back_inserter(curves));
//   CGAL::Arrangement_2<Traits> arr; CGAL::insert(arr, curves.begin(), curves.end());
//
// Limitation: a hyperbolic piece (standard weight > 1) whose conic's axes are rotated (an xy
// term) is refused: CGAL 5.5's conic arcs pick the hyperbola's branch by a wrong axis then
// (see the code). Elliptic and parabolic pieces of any orientation, and axis-parallel
// hyperbolic ones, are converted.
//
// Errors: Precondition_error for a rational curve given to the Bezier traits, a piece of
// degree > 2 given to the conic traits, a quadratic piece with collinear control points that
// folds back (P1 outside [P0, P2]), and the rotated hyperbolic piece above; the message names
// the piece.

#ifndef FAIR_CGAL_ARRANGEMENT_CURVES_H
#define FAIR_CGAL_ARRANGEMENT_CURVES_H

#include <fair/Errors.h>
#include <fair/Nurbs_curve_2.h>
#include <fair/cgal/internal/exact_rational.h>
#include <fair/internal/common/checks.h>

#include <CGAL/Kernel/global_functions_2.h>

#include <cstddef>
#include <type_traits>
#include <vector>

// The two traits class templates, declared only: a program includes the one it uses (and pays
// for compiling that one only).
namespace CGAL {
template <class RatKernel, class AlgKernel, class NtTraits, class BoundingTraits>
class Arr_Bezier_curve_traits_2;
template <class RatKernel, class AlgKernel, class NtTraits>
class Arr_conic_traits_2;
}  // namespace CGAL

namespace fair {

/// Which traits classes to_arrangement_curves writes for (true for the two CGAL families).
template <class ArrTraits>
struct Is_bezier_arrangement_traits : std::false_type {};
template <class R, class A, class N, class B>
struct Is_bezier_arrangement_traits<CGAL::Arr_Bezier_curve_traits_2<R, A, N, B>> : std::true_type {};
template <class ArrTraits>
struct Is_conic_arrangement_traits : std::false_type {};
template <class R, class A, class N>
struct Is_conic_arrangement_traits<CGAL::Arr_conic_traits_2<R, A, N>> : std::true_type {};

/// Writes one ArrTraits::Curve_2 per piece of `curve` (in order) to `out`, exactly (file
/// comment); returns the advanced iterator.
/// \throws Precondition_error as listed in the file comment.
template <class ArrTraits, class K, class OutputIterator>
OutputIterator to_arrangement_curves(const Nurbs_curve_2<K>& curve, OutputIterator out) {
  static_assert(Is_bezier_arrangement_traits<ArrTraits>::value || Is_conic_arrangement_traits<ArrTraits>::value,
                "fair::to_arrangement_curves: ArrTraits must be CGAL::Arr_Bezier_curve_traits_2 or CGAL::Arr_conic_traits_2");
  typedef typename ArrTraits::Rational Rational;
  typedef typename ArrTraits::Rat_point_2 Rat_point_2;
  typedef typename ArrTraits::Curve_2 Curve_2;
  using internal::arrangement::exact_rational;
  const char* who = "fair::to_arrangement_curves";
  const auto& pieces = curve.pieces();
  const bool rational = curve.is_rational();

  for (std::size_t j = 0; j < pieces.size(); ++j) {
    const auto& piece = pieces[j];
    std::vector<Rat_point_2> P;
    for (const auto& p : piece.control_points())
      P.push_back(Rat_point_2(exact_rational<Rational>(p.x()), exact_rational<Rational>(p.y())));

    if constexpr (Is_bezier_arrangement_traits<ArrTraits>::value) {
      internal::require(!rational, who, ": piece ", j, " is rational (weights differ): Arr_Bezier_curve_traits_2 takes ",
                        "polynomial pieces only, use Arr_conic_traits_2 for a rational quadratic curve");
      *out++ = Curve_2(P.begin(), P.end());
    } else {
      typedef typename ArrTraits::Rat_kernel Rat_kernel;
      typedef typename ArrTraits::Rat_segment_2 Rat_segment_2;
      typedef typename ArrTraits::Point_2 Point_2;
      typedef typename ArrTraits::Nt_traits Nt_traits;
      internal::require(piece.degree() <= 2, who, ": piece ", j, " has degree ", piece.degree(),
                        ": Arr_conic_traits_2 takes pieces of degree <= 2, use Arr_Bezier_curve_traits_2 for a ",
                        "polynomial curve of higher degree");
      const Rat_kernel rk;
      const CGAL::Orientation turn = piece.degree() == 2 ? rk.orientation_2_object()(P[0], P[1], P[2]) : CGAL::COLLINEAR;
      if (turn == CGAL::COLLINEAR) {
        // a straight piece: the segment P0 P2, provided the curve runs through it monotonically
        internal::require(piece.degree() == 1 || rk.collinear_are_ordered_along_line_2_object()(P[0], P[1], P[2]), who,
                          ": piece ", j, " is straight and folds back (its middle control point is outside the ",
                          "segment of its ends): no conic arc traces it");
        *out++ = Curve_2(Rat_segment_2(P.front(), P.back()));
        continue;
      }
      // w0 w2 L1^2 - 4 w1^2 L0 L2 (file comment) with L_i = al_i x + be_i y + ga_i
      const Rational w0 = exact_rational<Rational>(piece.weight(0)), w1 = exact_rational<Rational>(piece.weight(1)),
                     w2 = exact_rational<Rational>(piece.weight(2));
      Rational al[3], be[3], ga[3];
      for (int i = 0; i < 3; ++i) {
        const int a = (i + 1) % 3, b = (i + 2) % 3;
        al[i] = P[a].y() - P[b].y();
        be[i] = P[b].x() - P[a].x();
        ga[i] = P[a].x() * P[b].y() - P[a].y() * P[b].x();
      }
      const Rational s = w0 * w2, m = Rational(4) * w1 * w1;
      const Rational r = s * al[1] * al[1] - m * al[0] * al[2];                         // x^2
      const Rational q = s * be[1] * be[1] - m * be[0] * be[2];                         // y^2
      const Rational t = Rational(2) * s * al[1] * be[1] - m * (al[0] * be[2] + be[0] * al[2]);  // xy
      const Rational u = Rational(2) * s * al[1] * ga[1] - m * (al[0] * ga[2] + ga[0] * al[2]);  // x
      const Rational v = Rational(2) * s * be[1] * ga[1] - m * (be[0] * ga[2] + ga[0] * be[2]);  // y
      const Rational w = s * ga[1] * ga[1] - m * ga[0] * ga[2];                         // 1
      // CGAL 5.5's _Conic_arc_2 tells the branches of a hyperbola apart by the line through its
      // centre with normal (sin phi, cos phi), phi the axes' rotation (_build_hyperbolic_arc_data):
      // right only when the axes are those of the coordinates (t = 0). A rotated hyperbolic piece
      // would fail an assertion there, or in a build without assertions give wrong arrangements.
      internal::require(!(CGAL::sign(Rational(4) * r * q - t * t) == CGAL::NEGATIVE && CGAL::sign(t) != CGAL::ZERO), who,
                        ": piece ", j, " is a hyperbolic arc (weight w1 / sqrt(w0 w2) > 1) with rotated axes, which ",
                        "CGAL's Arr_conic_traits_2 does not place on the right branch (doc/nurbs.md, \"CGAL arrangements\")");
      const Nt_traits nt;
      const Point_2 source(nt.convert(P[0].x()), nt.convert(P[0].y()));
      const Point_2 target(nt.convert(P[2].x()), nt.convert(P[2].y()));
      const Curve_2 arc(r, q, t, u, v, w, turn, source, target);
      internal::require(arc.is_valid(), who, ": piece ", j, " gives an invalid conic arc");
      *out++ = arc;
    }
  }
  return out;
}

}  // namespace fair

#endif  // FAIR_CGAL_ARRANGEMENT_CURVES_H
