// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Design with basic shapes (Karciauskas-Peters, Sec. 6, Fig. 9): line segments, circle arcs,
// conic arcs, rational cubics and parametric curves, each with the points the designer marked on
// it, become open clamped C^2 cubic splines (`Cubic_spline_2`, first and last control point the
// shape's end points); their control polygons are merged into ONE open or closed C^2 spline.
// Consecutive end points that agree exactly become one control point; end points closer than
// the merge tolerance are averaged into one; end points farther apart are both kept, and the edge
// between them becomes part of the control polygon.
//
// The knot decision ("beta := 1", left open by the paper; derivation in doc/basic_shapes.md):
// every shape's breakpoints are scaled and shifted so that its first knot interval equals the
// previous shape's last one, and every interval created at a join has that same length. Then
// every new beta equals 1 and each shape's pieces on [u_2, u_{m-2}] (its whole extent at the
// clamped ends of an open design) are reproduced exactly: they depend only on the shape's own
// knots u_0..u_m (up to an affine map) and control points c_1..c_{m-1}. Rational shapes: the
// homogeneous control points of each shape are scaled by one constant (the same curve) so that
// the weights agree across every join. Exact in an exact kernel (EPECK, Simple_cartesian<Gmpq>).

#ifndef FAIR_BASIC_SHAPE_DESIGN_H
#define FAIR_BASIC_SHAPE_DESIGN_H

#include <fair/Cubic_spline_2.h>
#include <fair/Errors.h>
#include <fair/Parametric_curve_spline.h>
#include <fair/Rational_bezier_2.h>
#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/internal/nurbs/assembly.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace fair {

/// How two consecutive end points were joined (Fig. 9).
enum class Shape_join_kind {
  AGREE,     ///< (a) the points are equal: one control point
  AVERAGED,  ///< (b) closer than the merge tolerance: one control point, their midpoint
  EDGE       ///< (c) apart: both kept, the edge between them is part of the control polygon
};

/// "agree", "averaged", "edge".
inline const char* to_string(Shape_join_kind kind) {
  switch (kind) {
    case Shape_join_kind::AGREE: return "agree";
    case Shape_join_kind::AVERAGED: return "averaged";
    case Shape_join_kind::EDGE: return "edge";
  }
  return "?";
}

/// One join of the design: the end of shape `before` (its last part) to the start of shape
/// `after`; for the closing join of a closed design after = 0. Joins between the parts of one
/// shape (the sub-arcs of a split circle arc) are listed with before == after and inside = true;
/// they are always merged (AGREE, or AVERAGED when rounding made the points differ).
struct Shape_join {
  std::size_t before = 0, after = 0;
  bool inside = false;
  Shape_join_kind kind = Shape_join_kind::AGREE;
  double distance = 0;       ///< |end - start| (in double)
  std::size_t control_point = 0;  ///< index in the merged control polygon of the (first) join point
};

/// Where a part of a shape lies in the merged spline: its pieces [first_piece, end_piece) and,
/// among them, the pieces [first_exact, end_exact) that reproduce the part exactly.
struct Shape_span {
  std::size_t shape = 0, part = 0;
  std::size_t first_piece = 0, end_piece = 0;
  std::size_t first_exact = 0, end_exact = 0;
};

/// Options of basic_shape_design.
struct Basic_shape_design_options {
  bool closed = false;  ///< periodic: the last shape's end is joined to the first shape's start
  /// End points closer than merge_tolerance * D are averaged, where D is the diagonal of the
  /// bounding box of all control points of all shapes (so that a scaled design merges the same
  /// joins). 0: only exactly equal points are merged. Must be finite and >= 0.
  double merge_tolerance = 1e-9;
};

/// A basic shape: one or more open clamped spline parts (a circle arc of a large opening is split
/// into sub-arcs), each a `Cubic_spline_2` whose first and last control points are its end points,
/// joined end to start exactly.
template <class K>
class Basic_shape_2 {
public:
  typedef K Kernel;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef Cubic_spline_2<K> Spline;

  /// Any open clamped spline as a shape (e.g. from parametric_curve_spline or exact_spline).
  /// \throws Precondition_error if `part` is closed.
  explicit Basic_shape_2(Spline part, std::string kind = "spline");
  /// Several parts joined end to start (their joins are always merged).
  /// \throws Precondition_error if there is none or one is closed.
  Basic_shape_2(std::vector<Spline> parts, std::string kind);

  /// The segment from `from` to `to`, linearly parametrised over [0,1], knots at the marked
  /// parameters 0 < u_1 < ... < u_{m-1} < 1 (linear precision). Exact.
  /// \throws Invalid_input_error if from == to or the marks are not strictly increasing in (0,1).
  static Basic_shape_2 segment(const Point_2& from, const Point_2& to, const std::vector<FT>& marks = {});

  /// The conic arc (standard rational quadratic form, weights 1, w, 1), degree-elevated and
  /// converted exactly with knots at the marks in (0,1) (Sec. 6, eqs. 9-10). Exact.
  /// \throws Invalid_input_error for marks not strictly increasing in (0,1).
  static Basic_shape_2 conic(const Rational_quadratic_bezier_2<K>& arc, const std::vector<FT>& marks = {});

  /// The rational Bezier curve of degree <= 3 (elevated to 3), knots at the marks in (0,1). Exact.
  /// \throws Precondition_error for a degree above 3, Invalid_input_error for bad marks.
  static Basic_shape_2 cubic(const Rational_bezier_2<K>& curve, const std::vector<FT>& marks = {});

  /// The circle arc from start_angle to end_angle > start_angle (radians, counter-clockwise,
  /// opening <= 2 pi), split into sub-arcs of at most 180 degrees (circle_arc_split), each a
  /// rational cubic (circle_arc_cubic); the marked angles (strictly increasing, inside the arc) become
  /// knots through the parameter of eq. 4 (circle_arc_parameter). A mark on a split angle is the
  /// join of two sub-arcs already. Accurate to the double angles (cos/sin in double).
  /// \throws Invalid_input_error for radius <= 0, a zero, negative or > 2 pi opening, bad marks.
  static Basic_shape_2 circle_arc(const Point_2& center, const FT& radius, double start_angle, double end_angle,
                                  const std::vector<double>& mark_angles = {});

  /// A parametric curve f (a ParametricCurve_2 of fair/Parametric_curve_2.h: Archimedean_spiral_2,
  /// Circle_involute_2, Clothoid_2, ...) from marks.front() to marks.back(), approximated by
  /// parametric_curve_spline (Sec. 5: breakpoints at the marks, ends included, O(h^4)); the shape
  /// is that spline, which the design keeps exactly on its interior.
  /// \throws Invalid_input_error as parametric_curve_spline (fewer than 2 marks, not increasing, ...).
  template <class Curve>
  static Basic_shape_2 parametric(const Curve& f, const std::vector<double>& marks, std::string kind = "parametric") {
    return Basic_shape_2(parametric_curve_spline<K>(f, marks), std::move(kind));
  }

  const std::vector<Spline>& parts() const { return parts_; }
  const std::string& kind() const { return kind_; }
  const Point_2& source() const { return parts_.front().control_points().front(); }
  const Point_2& target() const { return parts_.back().control_points().back(); }
  /// The shape in the exchange form (fair/Nurbs_curve_2.h; doc/nurbs.md): its parts' NURBS joined
  /// end to start, each keeping its breakpoints (shifted to follow the previous part), knots of
  /// multiplicity 3 where two parts meet (C0 there: a split circle arc is only G1 in this
  /// parameter), rational parts' weights scaled by one constant each so that they agree at the
  /// joins. One part: that part's nurbs(). Exact. O(number of control points).
  Nurbs_curve_2<K> nurbs() const {
    return internal::nurbs::spline_runs_nurbs<K>(parts_, false, "Basic_shape_2::nurbs");
  }

private:
  std::vector<Spline> parts_;
  std::string kind_;
};

/// The merged design: the spline, the report of every join and where each part of each shape lies.
template <class K>
struct Basic_shape_design_2 {
  Cubic_spline_2<K> spline;
  std::vector<Shape_join> joins;  ///< in order; for a closed design the closing join is last
  std::vector<Shape_span> spans;  ///< one per part, in order
  double merge_distance = 0;      ///< merge_tolerance * D, the absolute threshold used
  /// spline.nurbs(): the merged design in the exchange form (degree 3, single interior knots,
  /// clamped when open, periodic when closed; fair/Nurbs_curve_2.h).
  Nurbs_curve_2<K> nurbs() const { return spline.nurbs(); }
};

/// The ONE C^2 spline of the shapes (Fig. 9), open (clamped at the first shape's start and the
/// last shape's end) or closed (periodic). O(total number of control points); exact in an exact
/// kernel. Editing its control points (Cubic_spline_2::with_control_point) keeps C^2.
/// \throws Precondition_error for no shape, a closed part, or a bad merge tolerance;
/// Invalid_input_error for a closed design whose control points all lie on one line (e.g. a lone
/// segment closed on itself: a curve there and back).
template <class K>
Basic_shape_design_2<K> basic_shape_design(const std::vector<Basic_shape_2<K>>& shapes,
                                           const Basic_shape_design_options& options = Basic_shape_design_options());

} // namespace fair

#include <fair/internal/basic_shapes/merge.h>
#include <fair/internal/basic_shapes/shapes.h>

#endif // FAIR_BASIC_SHAPE_DESIGN_H
