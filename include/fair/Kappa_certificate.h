// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Certification of kappa-curves: fair::certify(curve) and fair::certify_pieces(curve), and
// fair::Kappa_certificate, what they certified about a fair::Kappa_curve_2, exactly or by
// outward-rounded intervals. Include this header to certify; Kappa_curve_2.h alone does not pull
// in the exact machinery (GMP integers, interval filters). How it is computed:
// include/fair/internal/kappa/certify.h and doc/kappa_curves.md.

#ifndef FAIR_KAPPA_CERTIFICATE_H
#define FAIR_KAPPA_CERTIFICATE_H

#include <fair/Kappa_curve_report.h>
#include <fair/Rational_quadratic_bezier_2.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <ostream>
#include <vector>

namespace fair {

/// The certificate of a kappa-curve (see certify() and certify_pieces() below):
/// per piece and per join what holds exactly, and certified bounds where it does not. All
/// members are plain data; the queries are O(n).
struct Kappa_certificate {
  typedef CGAL::Simple_cartesian<CGAL::Gmpq> Exact_kernel;
  /// Default bound of valid() on the relative |kappa| mismatch at the joins: far above the
  /// solver's 1e-12 residual, far below a visible curvature jump.
  static constexpr double default_kappa_tolerance = 1e-9;
  /// Default bound of valid() on |root - t_i|: the same margin for the parameter of the maximum.
  static constexpr double default_t_tolerance = 1e-9;
  struct Piece {
    std::size_t point_index = 0;
    bool valid_piece = false;      ///< exact control points not collinear (a genuine conic arc)
    bool point_on_piece = false;   ///< Q_i == c_i(t_i) exactly
    /// Certified upper bound on |c_i(t_i) - Q_i| (0 when point_on_piece; infinity if not valid).
    double interpolation_error = std::numeric_limits<double>::infinity();
    std::size_t extrema = 0;       ///< certified curvature extrema in (0,1) (roots of eq. 4)
    std::size_t maxima = 0;        ///< of which maxima of |kappa|
    bool unique_maximum = false;   ///< exactly one root in (0,1) and it is a maximum
    /// The extremum nearest t_i is a maximum and the piece's only maximum. An elliptic piece
    /// (w_i < 1, automatic weights) may also hold a minimum elsewhere in (0,1) (the paper, after
    /// eq. 4): that is still a kappa-curve piece, but not unique_maximum.
    bool maximum_at_t = false;
    double t = 0;                  ///< t_i (its exact value is this double)
    /// The certified extremum nearest to t_i: its kind, isolating interval (outward rounded)
    /// and an upper bound on |root - t_i| (infinity when the piece has no extremum). With
    /// w_i < 1 (automatic weights) Q_i can be a curvature minimum (Sec. 3.2): kind says so.
    bool has_extremum_at_t = false;
    Curvature_extremum_kind kind_at_t = Curvature_extremum_kind::MAXIMUM;
    double root_lower = 0, root_upper = 0;
    double root_distance = std::numeric_limits<double>::infinity();
  };
  struct Join {
    std::size_t piece = 0;         ///< the join at the start of this piece
    bool c0 = false;               ///< both pieces share the exact point
    bool g1 = false;               ///< P_{i-1}, E_i, P_i exactly collinear, E_i strictly between
    double kappa_mismatch_lower = 0, kappa_mismatch_upper = 0;  ///< (|k1|-|k2|)/(|k1|+|k2|) enclosure
  };
  std::vector<Piece> pieces;
  std::vector<Join> joins;
  std::vector<Rational_quadratic_bezier_2<Exact_kernel>> exact_pieces;
  /// The outcome of the solve that was certified (its Kappa_curve_report::status) and the
  /// points it reported on joins (Kappa_curve_report::points_on_joins). What the certificate
  /// proves per outcome: proves_outcome().
  Kappa_curve_status status = Kappa_curve_status::UNSOLVED;
  std::vector<std::size_t> points_on_joins;

  bool all_points_on_pieces() const { for (const Piece& p : pieces) if (!p.point_on_piece) return false; return true; }
  bool all_unique_maxima() const { for (const Piece& p : pieces) if (!p.unique_maximum) return false; return true; }
  /// Every piece's only maximum of |kappa| is the extremum nearest its t_i (maximum_at_t): what
  /// valid() requires (a minimum elsewhere on an elliptic piece is allowed).
  bool all_maxima_at_points() const { for (const Piece& p : pieces) if (!p.maximum_at_t) return false; return true; }
  bool all_g1() const { for (const Join& j : joins) if (!(j.c0 && j.g1)) return false; return true; }
  /// Largest certified upper bound on |c_i(t_i) - Q_i| over the pieces.
  double max_interpolation_error() const {
    double m = 0;
    for (const Piece& p : pieces) m = std::max(m, p.interpolation_error);
    return m;
  }
  /// As valid(), but interpolation only up to `interpolation_tolerance` (absolute, in the
  /// curve's coordinates): the criterion for certify_pieces(), whose pieces pass through the
  /// Q_i up to the rounding of the solver's P_i.
  bool valid_within(double interpolation_tolerance, double kappa_tolerance = default_kappa_tolerance,
                    double t_tolerance = default_t_tolerance) const {
    return max_interpolation_error() <= interpolation_tolerance && all_maxima_at_points() && all_g1() &&
           max_kappa_mismatch() <= kappa_tolerance && max_root_distance() <= t_tolerance;
  }
  /// Largest |relative |kappa| mismatch| over the joins (certified upper bound).
  double max_kappa_mismatch() const {
    double m = 0;
    for (const Join& j : joins) m = std::max(m, std::max(std::abs(j.kappa_mismatch_lower), std::abs(j.kappa_mismatch_upper)));
    return m;
  }
  /// Largest distance from t_i to the nearest certified curvature extremum (infinity if a piece
  /// has none).
  double max_root_distance() const { double m = 0; for (const Piece& p : pieces) m = std::max(m, p.root_distance); return m; }
  /// Number of pieces whose Q_i is a certified curvature minimum rather than a maximum.
  std::size_t minima_at_points() const {
    std::size_t k = 0;
    for (const Piece& p : pieces) k += p.has_extremum_at_t && p.kind_at_t == Curvature_extremum_kind::MINIMUM;
    return k;
  }
  /// Everything exact holds and |kappa| matches within `kappa_tolerance` and each maximum lies
  /// within `t_tolerance` of t_i.
  bool valid(double kappa_tolerance = default_kappa_tolerance, double t_tolerance = default_t_tolerance) const {
    return all_points_on_pieces() && all_maxima_at_points() && all_g1() && max_kappa_mismatch() <= kappa_tolerance &&
           max_root_distance() <= t_tolerance;
  }
  /// The ON_JOINS properties: every Q_i on its piece, C0 and G1 exactly, |kappa| matching within
  /// `kappa_tolerance` at every join, and every piece whose point is NOT in points_on_joins with
  /// its only curvature maximum within `t_tolerance` of t_i (maximum_at_t); a piece of a listed point has either
  /// its t_i within join_t_margin of 0 or 1 (the point on a join) or that same interior maximum
  /// (listed for a lambda at a bound).
  bool valid_on_joins(double kappa_tolerance = default_kappa_tolerance, double t_tolerance = default_t_tolerance) const {
    if (!(all_points_on_pieces() && all_g1() && max_kappa_mismatch() <= kappa_tolerance)) return false;
    for (const Piece& p : pieces) {
      const bool interior_maximum = p.maximum_at_t && p.root_distance <= t_tolerance;
      const bool listed = std::find(points_on_joins.begin(), points_on_joins.end(), p.point_index) != points_on_joins.end();
      const bool on_join = p.t <= join_t_margin || p.t >= 1 - join_t_margin;
      if (!(interior_maximum || (listed && on_join))) return false;
    }
    return true;
  }
  /// A listed point's t_i within this of 0 or 1 counts as on a join (the solver's margin for
  /// points_on_joins).
  static constexpr double join_t_margin = 1e-4;
  /// Whether the certificate proves the outcome of `status`: INTERIOR, valid(); ON_JOINS,
  /// valid_on_joins(); UNSOLVED promises nothing beyond what the members say (false).
  bool proves_outcome(double kappa_tolerance = default_kappa_tolerance, double t_tolerance = default_t_tolerance) const {
    switch (status) {
      case Kappa_curve_status::INTERIOR: return valid(kappa_tolerance, t_tolerance);
      case Kappa_curve_status::ON_JOINS: return valid_on_joins(kappa_tolerance, t_tolerance);
      case Kappa_curve_status::UNSOLVED: break;
    }
    return false;
  }
  friend std::ostream& operator<<(std::ostream& out, const Kappa_certificate& c) {
    out << "Kappa_certificate{pieces " << c.pieces.size() << ", Q_i on pieces " << c.all_points_on_pieces()
        << ", maxima at points " << c.all_maxima_at_points() << ", G1 " << c.all_g1() << ", max |kappa| mismatch <= "
        << c.max_kappa_mismatch() << ", max |root - t_i| <= " << c.max_root_distance() << ", outcome " << c.status;
    if (!c.points_on_joins.empty()) {
      out << " (points on joins:";
      for (const std::size_t i : c.points_on_joins) out << ' ' << i;
      out << ')';
    }
    out << "}";
    for (const Piece& p : c.pieces)
      if (!(p.point_on_piece && p.maximum_at_t))
        out << "\n  piece for point " << p.point_index << ": valid " << p.valid_piece << ", on piece "
            << p.point_on_piece << ", extrema " << p.extrema << ", maxima " << p.maxima << ", nearest extremum "
            << (p.has_extremum_at_t ? to_string(p.kind_at_t) : "none") << " at distance <= " << p.root_distance;
    return out;
  }
};

} // namespace fair

// The machinery needs the struct above (internal/kappa/certify.h includes this header, whose
// guard is then already set), and certify() below needs the machinery.
#include <fair/Kappa_curve_2.h>
#include <fair/internal/kappa/certify.h>

namespace fair {

/// Certifies `curve` exactly: the exact curve defined by the solver's rational lambda_i, t_i,
/// w_i (doubles, i.e. exact dyadic rationals; state()) and the exact input points, with eq. 18
/// solved exactly and fraction-free. Returns the Kappa_certificate: Q_i == c_i(t_i), C0 and G1
/// exactly; the number and kind of curvature extrema of each piece and the distance of the
/// nearest one to t_i; the relative |kappa| mismatch at each join by outward-rounded intervals;
/// the exact pieces in Kappa_certificate::Exact_kernel; the outcome and the points on joins of
/// report(). Use Kappa_certificate::proves_outcome() (valid() for INTERIOR, valid_on_joins()
/// for ON_JOINS).
/// Any kernel (its numbers are converted exactly). Complexity: O(n) products of O(n)-bit
/// numbers (the exact control points have ~150 n bits), O(n M(n)) bit operations; timings in
/// doc/benchmarks.md. \throws Internal_error if the exact elimination meets a zero pivot
/// (impossible for the 0 < lambda_i, t_i < 1, w_i > 0 of a Kappa_curve_2).
template <class K>
Kappa_certificate certify(const Kappa_curve_2<K>& curve) {
  Kappa_certificate c = internal::kappa::certify_curve(curve, internal::kappa::Certify_mode::FILTERED);
  c.status = curve.report().status;
  c.points_on_joins = curve.report().points_on_joins;
  return c;
}

/// Certifies the pieces that `curve` returns, piece by piece in O(n): their exact control
/// points (in an exact kernel: P_j the solver's rounded P_{j,1}, E_j = (1 - lambda_j) P_{j-1} +
/// lambda_j P_j formed exactly, so C0 and G1 hold exactly by construction and are verified),
/// the parameters t_j, and the exact input points. What is certified, exactly or by outward
/// rounded intervals: C0 and G1 at every join; |c_j(t_j) - Q_j| <= interpolation_error (not 0:
/// the P_j carry the rounding of the solve, ~1e-16 relative); the number and kind of curvature
/// extrema of each piece and the distance of the nearest one to t_j; the relative |kappa|
/// mismatch at each join. Use Kappa_certificate::valid_within(). With a floating-point kernel
/// the pieces' E_j are rounded, and G1 generally fails exactly (as it is reported).
template <class K>
Kappa_certificate certify_pieces(const Kappa_curve_2<K>& curve) {
  Kappa_certificate c = internal::kappa::certify_returned_pieces(curve);
  c.status = curve.report().status;
  c.points_on_joins = curve.report().points_on_joins;
  return c;
}

} // namespace fair

#endif // FAIR_KAPPA_CERTIFICATE_H
