// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Proposition 1 of Karciauskas-Peters (convexity preservation), decided exactly:
// spline_convexity(s) reports (a) whether the control polygon of a Cubic_spline_2 is convex
// (exact predicates of the kernel: exact in EPICK and EPECK and Simple_cartesian<Gmpq>; in
// Simple_cartesian<double> the predicates are floating point and NOT certified) and (b) whether
// the curve is regular (c' != 0, exact) and locally convex, from the sign of the curvature
// numerator of every Bezier piece in Bernstein form, interval filter first and exact (Gmpq) root
// isolation as fallback -- certified in every kernel for the pieces' FT coefficients as stored (in
// a double kernel: the rounded Bezier points and products w x, w y of the pieces, not the spline's
// control points and weights themselves; doc/exact_conversion.md).
// Prop. 1: a convex polygon (with positive weights and increasing knots) gives a locally
// convex curve; the converse fails (a locally convex curve can have a non-convex polygon).
// O(number of pieces).

#ifndef FAIR_SPLINE_CONVEXITY_H
#define FAIR_SPLINE_CONVEXITY_H

#include <fair/Cubic_spline_2.h>
#include <fair/internal/exact_conversion/convexity.h>

#include <CGAL/enum.h>

#include <cstddef>
#include <limits>
#include <vector>

namespace fair {

/// Options of spline_convexity.
struct Spline_convexity_options {
  /// Decide the pieces the interval filter leaves open exactly (Gmpq); if false they are reported
  /// undecided.
  bool exact_fallback = true;
};

/// The result of spline_convexity on a Cubic_spline_2<K>. No member depends on K yet; the
/// parameter is kept so that the report names the kernel it was computed in (like the library's
/// other result types) and callers' `Spline_convexity_report<K>` stays valid.
template <class K>
struct Spline_convexity_report {
  typedef K Kernel;
  static constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();
  /// (a) The control polygon (closed by its closing edge if the spline is open) is convex.
  bool polygon_convex = true;
  /// Index of the first control point where convexity fails, npos if none.
  std::size_t polygon_violation = npos;
  /// LEFT_TURN / RIGHT_TURN: the polygon's turning sense; COLLINEAR: all points on a line.
  CGAL::Orientation polygon_orientation = CGAL::COLLINEAR;
  /// (b) Every piece is decided and regular, none has an inflection, and all nonzero signs agree.
  bool curve_locally_convex = true;
  /// LEFT_TURN: curvature >= 0 everywhere; RIGHT_TURN: <= 0; COLLINEAR: straight (or not convex).
  CGAL::Orientation curve_orientation = CGAL::COLLINEAR;
  /// Per piece: +1 (curvature >= 0 on it), -1 (<= 0), 0 (straight, or undecided, inflected or singular).
  std::vector<int> piece_signs;
  /// Pieces decided by the interval filter / by the exact fallback.
  std::size_t pieces_by_filter = 0, pieces_exact = 0;
  /// Pieces whose curvature changes sign inside (exact certificate of non-convexity).
  std::vector<std::size_t> inflected_pieces;
  /// Pieces that are not regular: c' = 0 somewhere on the closed piece (a cusp, a reversal, a
  /// join whose neighbouring Bezier points coincide, b_1 = b_0 or b_2 = b_3); exact certificate.
  /// The curvature sign means nothing there: such a curve is never reported locally convex.
  std::vector<std::size_t> singular_pieces;
  /// Pieces left undecided (only with exact_fallback = false).
  std::vector<std::size_t> undecided_pieces;
  /// Proposition 1's hypothesis implies its conclusion on this spline.
  bool proposition_holds() const { return !polygon_convex || curve_locally_convex; }
};

/// Proposition 1 on the spline `s` (open or closed, polynomial or rational): see the file comment.
template <class K>
Spline_convexity_report<K> spline_convexity(const Cubic_spline_2<K>& s, const Spline_convexity_options& options = {}) {
  namespace ec = internal::exact_conversion;
  Spline_convexity_report<K> r;
  const ec::Polygon_convexity pc = ec::polygon_convexity<K>(s.control_points(), s.is_closed());
  r.polygon_convex = pc.convex;
  r.polygon_violation = pc.violation == ec::no_index ? r.npos : pc.violation;
  r.polygon_orientation = pc.orientation;
  int sign = 0;
  for (std::size_t i = 0; i < s.number_of_pieces(); ++i) {
    const ec::Piece_sign ps = ec::piece_sign(s.piece(i), !s.is_rational(), options.exact_fallback);
    if (ps.decision == ec::Piece_decision::FILTER) ++r.pieces_by_filter;
    if (ps.decision == ec::Piece_decision::EXACT) ++r.pieces_exact;
    if (ps.decision == ec::Piece_decision::UNDECIDED) r.undecided_pieces.push_back(i);
    if (ps.inflection) r.inflected_pieces.push_back(i);
    if (ps.singular) r.singular_pieces.push_back(i);
    r.piece_signs.push_back(ps.inflection || ps.singular ? 0 : ps.sign);
    if (ps.decision == ec::Piece_decision::UNDECIDED || ps.inflection || ps.singular) r.curve_locally_convex = false;
    else if (ps.sign != 0) {
      if (sign != 0 && ps.sign != sign) r.curve_locally_convex = false;
      sign = ps.sign;
    }
  }
  r.curve_orientation = !r.curve_locally_convex ? CGAL::COLLINEAR
                        : (sign > 0 ? CGAL::LEFT_TURN : (sign < 0 ? CGAL::RIGHT_TURN : CGAL::COLLINEAR));
  return r;
}

} // namespace fair

#endif // FAIR_SPLINE_CONVEXITY_H
