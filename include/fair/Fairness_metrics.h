// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fairness metrics of a planar curve given as a std::vector of CurvePiece_2 pieces (joined end to
// start): fair::Bezier_2, the rational pieces (anything with control_points() and weights(),
// c = sum B_i w_i P_i / sum B_i w_i, w_i > 0) and any other model of the concept; what a piece
// type must provide for each treatment is in fair/Curve_traits.h.
// The user manual is doc/fairness_metrics.md.
//
//  - curvature_profile: curvature against arc length samples;
//  - arc_length, bending_energy (int kappa^2 ds), curvature_variation_energy (int (dkappa/ds)^2 ds,
//    or int (dkappa/dt)^2 dt per piece): adaptive Gauss-Kronrod quadrature in double with an
//    error estimate (fair/Quadrature.h), capped (Non_convergence_error);
//  - inflections and curvature_extrema: CERTIFIED for Bernstein-form pieces. The piece's
//    homogeneous form (X, Y, W) is converted exactly to rationals and
//        D = det(P, P', P'')                    (P = (X, Y, W); D = x'y'' - y'x'' when W = 1),
//        N = 2 (D' W + 3 D W') |A|^2 - 6 D W (A . A'),   A = (X'W - X W', Y'W - Y W'),
//    satisfy sign(kappa) = sign(D) and sign(dkappa/dt) = sign(N) wherever the piece is regular
//    (kappa = D W^3 / |A|^3). Their roots in [0,1] are isolated by fair::Bernstein_root_isolation
//    and the signs between roots are evaluated exactly, so the counts are exact for the curve
//    with exactly the given (double or rational) control points. Generic pieces fall back to
//    sampling (certified = false);
//  - max_circle_deviation: max | |c(t) - C| - r |, its candidates being the certified roots of
//    d/dt |c - C|^2 and the piece ends;
//  - hausdorff_distance(_bounds): the Hausdorff distance of two curves with certified bounds, by
//    bounded subdivision (internal/metrics/hausdorff.h).
// Curvature is undefined at a singular point (c' = 0): the quadratures throw Precondition_error
// when they meet one, and the certified features are only meaningful on regular pieces.

#ifndef FAIR_FAIRNESS_METRICS_H
#define FAIR_FAIRNESS_METRICS_H

#include <fair/Bernstein_root_isolation.h>
#include <fair/Curve_sampling.h>
#include <fair/Curve_traits.h>
#include <fair/Errors.h>
#include <fair/Quadrature.h>
#include <fair/internal/metrics/energies.h>
#include <fair/internal/metrics/pieces.h>
#include <fair/internal/metrics/quadrature.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {

/// Measure of the curvature variation energy.
enum class Energy_measure {
  ARC_LENGTH, ///< int (d kappa / ds)^2 ds: geometric, independent of the parametrisation
  PARAMETER   ///< sum over pieces of int_0^1 (d kappa / dt)^2 dt (Li's eq. 5)
};

/// One sample of the curvature profile: the sample of the one sampler (Curve_sampling.h), with
/// piece, t, arc_length, x, y, the signed curvature and the unit normal.
typedef Curve_sample Curvature_sample;

/// One curvature feature (inflection or curvature extremum).
struct Curve_feature {
  std::size_t piece = 0;
  /// Parameter in the piece (within one ulp of the certified root when certified).
  double t = 0;
  /// Certified isolating interval of t (point interval when exact); [t,t] when not certified.
  Isolating_interval interval;
  double x = 0, y = 0;
  double curvature = 0;
  /// True when the feature sits at a join of two pieces (a sign change of the curvature across a
  /// join, only possible when the curve is not G2 there).
  bool at_joint = false;
};

/// The features of a curve and how far they can be trusted.
struct Feature_report {
  std::vector<Curve_feature> features;
  /// Pieces on which the defining polynomial vanishes identically: straight pieces for
  /// inflections, pieces of constant curvature (segments, circular arcs) for curvature extrema.
  std::vector<std::size_t> degenerate_pieces;
  /// True when every piece is in Bernstein form with exactly converted coordinates.
  bool certified = true;
  std::size_t count() const { return features.size(); }
};

} // namespace fair

// The implementations need the report types above.
#include <fair/internal/metrics/circle_deviation.h>
#include <fair/internal/metrics/features.h>
#include <fair/internal/metrics/hausdorff.h>

namespace fair {

/// Arc length of the curve, int |c'(t)| dt over every piece.
template <class Piece>
Quadrature_estimate arc_length(const std::vector<Piece>& curve, const Quadrature_options& options = Quadrature_options()) {
  return internal::metrics::arc_length(curve, options);
}

/// Bending (strain) energy int kappa^2 ds = sum over pieces of int_0^1 kappa(t)^2 |c'(t)| dt.
/// \throws Precondition_error at a singular point met by the quadrature; Invalid_input_error if the
/// integral overflows double.
template <class Piece>
Quadrature_estimate bending_energy(const std::vector<Piece>& curve, const Quadrature_options& options = Quadrature_options()) {
  return internal::metrics::bending_energy(curve, options);
}

/// Curvature variation energy: int (dkappa/ds)^2 ds = sum int_0^1 (dkappa/dt)^2 / |c'| dt
/// (Energy_measure::ARC_LENGTH), or sum int_0^1 (dkappa/dt)^2 dt (Energy_measure::PARAMETER, eq. 5
/// of Li's paper). Derivatives of order 3 are exact for Bernstein-form pieces.
/// \throws Precondition_error at a singular point met by the quadrature; Invalid_input_error if the
/// integral overflows double.
template <class Piece>
Quadrature_estimate curvature_variation_energy(const std::vector<Piece>& curve,
                                               Energy_measure measure = Energy_measure::ARC_LENGTH,
                                               const Quadrature_options& options = Quadrature_options()) {
  return internal::metrics::curvature_variation_energy(curve, measure == Energy_measure::ARC_LENGTH, options);
}

/// Curvature against arc length at samples_per_piece + 1 uniform parameters of every piece (the
/// first sample of a piece after the first is the previous piece's end, so both one-sided values
/// at a join appear): the sampler of fair::sample_curve, with arc lengths to the accuracy of
/// `options`.
/// \throws Precondition_error at a singular sample point.
template <class Piece>
std::vector<Curvature_sample> curvature_profile(const std::vector<Piece>& curve,
                                                std::size_t samples_per_piece = default_samples_per_piece,
                                                const Quadrature_options& options = Quadrature_options()) {
  internal::metrics::check_curve(curve, "curvature_profile");
  Quadrature_options o = options;
  o.initial_subintervals = 1; // each sampling interval is already a small part of the piece
  return internal::metrics::sample_pieces(curve, samples_per_piece, o, internal::metrics::At_singular_sample::THROW,
                                         "curvature_profile")
      .samples;
}

/// The inflections: the points where the signed curvature changes sign (odd-multiplicity roots of
/// D inside pieces, and sign changes across joins). Certified for Bernstein-form pieces
/// (see the file comment); an even-multiplicity root (curvature touching 0) is not an inflection.
template <class Piece>
Feature_report inflections(const std::vector<Piece>& curve) {
  return internal::metrics::certified_features(curve, internal::metrics::Feature_kind::INFLECTION, "inflections");
}

/// The curvature extrema: the points where dkappa/dt changes sign inside a piece or across a join
/// (a join where kappa is continuous but kappa' changes sign; a C1 join with a curvature jump is
/// reported only when the one-sided slopes differ in sign). Certified for Bernstein-form pieces.
template <class Piece>
Feature_report curvature_extrema(const std::vector<Piece>& curve) {
  return internal::metrics::certified_features(curve, internal::metrics::Feature_kind::CURVATURE_EXTREMUM,
                                                "curvature_extrema");
}

/// The largest deviation of a curve from a reference circle.
struct Circle_deviation {
  double max_deviation = 0; ///< max over the curve of | |c(t) - center| - radius |
  std::size_t piece = 0;    ///< where it is reached
  double t = 0;
  bool certified = true;    ///< candidates from certified root isolation (else 4096 samples per piece)
};

/// max | |c(t) - center| - radius | over the curve. For Bernstein-form pieces the candidates are the
/// piece ends and the certified roots of d/dt |c - C|^2 (numerator (B . B') W - |B|^2 W',
/// B = (X - Cx W, Y - Cy W)), so the maximum is exact up to rounding of the final evaluation.
/// \throws Invalid_input_error when a deviation overflows double precision.
template <class Piece>
Circle_deviation max_circle_deviation(const std::vector<Piece>& curve, const typename Piece::Point_2& center,
                                      double radius) {
  internal::metrics::check_curve(curve, "max_circle_deviation");
  internal::require(std::isfinite(radius) && radius >= 0, "max_circle_deviation: radius ", radius,
                    " must be finite and >= 0");
  Circle_deviation out;
  const double cx = CGAL::to_double(center.x()), cy = CGAL::to_double(center.y());
  internal::metrics::Certification_budget budget(curve.size());
  for (std::size_t i = 0; i < curve.size(); ++i) {
    internal::metrics::Piece_jet<Piece> jet(curve[i]);
    const std::vector<double> ts = internal::metrics::circle_deviation_candidates(curve[i], center, budget, out.certified);
    for (double t : ts) {
      const internal::metrics::Jet j = jet(t);
      const double d = std::fabs(std::hypot(j.x - cx, j.y - cy) - radius);
      // A center or radius near the largest double: the difference overflows (issue 29 #14).
      if (!std::isfinite(d))
        throw Invalid_input_error(internal::message("max_circle_deviation: the deviation from the circle of center (",
                                                    cx, ", ", cy, ") and radius ", radius,
                                                    " overflows double precision (piece ", i, ", t = ", t, ")"));
      if (d > out.max_deviation || (i == 0 && t == 0.0)) {
        out.max_deviation = d;
        out.piece = i;
        out.t = t;
      }
    }
  }
  return out;
}

/// Certified bounds of the Hausdorff distance of two curves (hausdorff_distance_bounds).
struct Hausdorff_bounds {
  double lower = 0, upper = 0; ///< lower <= H(a, b) <= upper (up to the rounding allowance)
  /// upper - lower <= tolerance; false when a work cap was met or the rounding allowance of the
  /// coordinates alone exceeds the tolerance (the bounds still hold).
  bool converged = true;
  /// The rounding allowance subtracted from lower and added to upper: 64 (degree + 1) eps times
  /// the largest coordinate, summed over the two curves. Above half the tolerance no work can
  /// converge (it widens both bounds, unless lower is clamped at 0).
  double rounding_allowance = 0;
  /// False when a curve has generic pieces (sampled, not certified).
  bool certified = true;
  std::size_t segments_a = 0, segments_b = 0; ///< sizes of the polylines used
  double value() const { return 0.5 * (lower + upper); }
};

/// The Hausdorff distance H(a, b) = max(sup_{p in a} d(p, b), sup_{q in b} d(q, a)) by bounded
/// subdivision with certified bounds (internal/metrics/hausdorff.h, doc/fairness_metrics.md):
/// each curve is replaced by a polyline through its points within a certified distance
/// e <= tolerance / 8 (convex-hull bound of its Bernstein pieces, halving the worst piece), the
/// directed distances of the polylines are bracketed by branch and bound (exact convex bounds per
/// nearest segment), and lower/upper follow by the triangle inequality; upper - lower <= tolerance.
/// The work grows like sqrt(1/tolerance) in the curved parts and log(1/tolerance) elsewhere, and is
/// capped (2^12 sub-pieces per curve, 2^14 refinements per direction): converged = false then,
/// and also when upper - lower ends wider than the tolerance for another reason: coordinates so
/// large that the rounding allowance alone exceeds it (a segment out to 4e34 at tolerance 1e-2,
/// a metrics fuzz finding of session 17).
/// \throws Precondition_error for an empty curve or a tolerance not finite and > 0;
/// Invalid_input_error for a coordinate beyond DBL_MAX / 8 or a rational piece whose weights
/// differ by a factor above 1e100.
template <class PieceA, class PieceB>
Hausdorff_bounds hausdorff_distance_bounds(const std::vector<PieceA>& a, const std::vector<PieceB>& b,
                                           double tolerance) {
  internal::metrics::check_curve(a, "hausdorff_distance");
  internal::metrics::check_curve(b, "hausdorff_distance");
  internal::require(std::isfinite(tolerance) && tolerance > 0, "hausdorff_distance: tolerance ", tolerance,
                    " must be finite and > 0");
  using namespace internal::metrics;
  const Certified_polyline pa = certified_polyline(a, tolerance / 8, "the first curve"),
                           pb = certified_polyline(b, tolerance / 8, "the second curve");
  const Polyline_grid ga(pa.vertices), gb(pb.vertices);
  const Directed_bounds ab = directed_polyline_bounds(pa.vertices, gb, tolerance / 2),
                        ba = directed_polyline_bounds(pb.vertices, ga, tolerance / 2);
  Hausdorff_bounds out;
  const double e = pa.error + pb.error;
  out.lower = std::max(0.0, std::max(ab.lower, ba.lower) - e);
  out.upper = std::max(ab.upper, ba.upper) + e;
  out.rounding_allowance = pa.rounding + pb.rounding;
  out.converged = pa.converged && pb.converged && ab.converged && ba.converged && out.upper - out.lower <= tolerance;
  out.certified = pa.certified && pb.certified;
  out.segments_a = pa.vertices.size() - 1;
  out.segments_b = pb.vertices.size() - 1;
  if (!std::isfinite(out.upper))
    throw Invalid_input_error(internal::message("hausdorff_distance: the distance overflows double precision"));
  return out;
}

/// The Hausdorff distance within `tolerance`: the midpoint of hausdorff_distance_bounds.
/// \throws Non_convergence_error when a work cap leaves the bounds further apart than
/// `tolerance` (the message gives them); the errors of hausdorff_distance_bounds.
template <class PieceA, class PieceB>
double hausdorff_distance(const std::vector<PieceA>& a, const std::vector<PieceB>& b, double tolerance) {
  const Hausdorff_bounds h = hausdorff_distance_bounds(a, b, tolerance);
  if (!h.converged && h.upper - h.lower > tolerance) {
    if (h.rounding_allowance > tolerance / 2)
      throw Non_convergence_error(internal::message("hausdorff_distance: the distance is between ", h.lower, " and ",
                                                    h.upper, "; the tolerance ", tolerance,
                                                    " is below the rounding allowance ", h.rounding_allowance,
                                                    " of the curves' coordinates (scale the curves down or raise the tolerance)"),
                                  h.segments_a + h.segments_b, h.upper - h.lower);
    throw Non_convergence_error(internal::message("hausdorff_distance: the work cap (", internal::metrics::max_hausdorff_segments,
                                                  " sub-pieces per curve, ", internal::metrics::max_hausdorff_refinements,
                                                  " refinements) was reached with the distance between ", h.lower,
                                                  " and ", h.upper, ", wider than the tolerance ", tolerance),
                                h.segments_a + h.segments_b, h.upper - h.lower);
  }
  return h.value();
}

/// The headline fairness figures of a curve.
struct Fairness_report {
  std::size_t pieces = 0;
  Quadrature_estimate length, bending, curvature_variation;
  double min_curvature = 0, max_curvature = 0; ///< over the profile samples and the extrema
  std::size_t inflection_count = 0, curvature_extremum_count = 0;
  bool certified = true; ///< counts certified (see Feature_report::certified)
};

template <class Piece>
Fairness_report fairness_report(const std::vector<Piece>& curve, const Quadrature_options& options = Quadrature_options()) {
  Fairness_report r;
  r.pieces = curve.size();
  r.length = arc_length(curve, options);
  r.bending = bending_energy(curve, options);
  r.curvature_variation = curvature_variation_energy(curve, Energy_measure::ARC_LENGTH, options);
  const std::vector<Curvature_sample> prof = curvature_profile(curve, default_samples_per_piece, options);
  r.min_curvature = r.max_curvature = prof.front().curvature;
  for (const Curvature_sample& s : prof) {
    r.min_curvature = std::min(r.min_curvature, s.curvature);
    r.max_curvature = std::max(r.max_curvature, s.curvature);
  }
  const Feature_report infl = inflections(curve), ext = curvature_extrema(curve);
  for (const Curve_feature& f : ext.features) {
    r.min_curvature = std::min(r.min_curvature, f.curvature);
    r.max_curvature = std::max(r.max_curvature, f.curvature);
  }
  r.inflection_count = infl.count();
  r.curvature_extremum_count = ext.count();
  r.certified = infl.certified && ext.certified;
  return r;
}

} // namespace fair

#endif // FAIR_FAIRNESS_METRICS_H
