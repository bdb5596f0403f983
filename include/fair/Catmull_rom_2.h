// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Catmull_rom_2<Kernel>: the Catmull-Rom spline (E. Catmull, R. Rom, "A class of local
// interpolating splines", 1974; reference [6] of Yan, Schiller & Schaefer) through points
// p_0..p_n, with uniform, centripetal or chordal knots, as cubic fair::Bezier_2 pieces.
//
// Construction. Piece i is the cubic Hermite interpolant of p_i, p_{i+1} on [u_i, u_{i+1}] whose
// end derivatives m_i are those of the parabola through p_{i-1}, p_i, p_{i+1} at u_i:
//   m_i = (1/h_{i-1} - 1/(h_{i-1}+h_i)) (p_i - p_{i-1}) + (1/h_i - 1/(h_{i-1}+h_i)) (p_{i+1} - p_i).
// For uniform knots this is m_i = (p_{i+1} - p_{i-1}) / 2, eq. (4) of Li et al. ("Curvature
// variation minimization of Cardinal splines") with alpha = 1/2; for non-uniform knots it is the
// tangent of the Barry-Goldman pyramid evaluation, so centripetal knots give the "centripetal
// Catmull-Rom" curve of Yuksel, Schaefer & Keyser (2011).
//
// Open curves, end handling (documented choice): the end derivatives m_0 and m_n are those of
// the parabola through the first (last) three points, i.e. the data are extended by quadratic
// extrapolation. With two points the curve is the straight segment. Alternatively the caller
// supplies the auxiliary points p_{-1}, p_{n+1} of Li et al. eq. (1) (for uniform knots
// p_{-1} = p_0 is allowed: it is Li et al.'s choice for their Fig. 1).
// Closed curves: all indices mod the point count; one piece per point.
//
// Properties. Interpolates every point; C1 (not C2) in the knot parameter; local (piece i
// depends on p_{i-1}..p_{i+2}); O(n). Reproduction: if the data are samples of a quadratic
// polynomial q at the knots, p_i = q(u_i), the curve is q (the parabola tangents are then exact
// and cubic Hermite interpolation reproduces q) -- with the quadratic end handling this holds up to
// the ends. Cubics are not reproduced (m_i = q'(u_i) + h_{i-1} h_i q'''/6).
//
// Exactness: uniform knots keep every number rational (exact interpolation, exact C1 in EPECK and
// Simple_cartesian<Gmpq>); centripetal/chordal knots are computed in double, converted exactly to
// FT, and everything after is exact for those knots (see Knot_spacing).

#ifndef FAIR_CATMULL_ROM_2_H
#define FAIR_CATMULL_ROM_2_H

#include <fair/Bezier_2.h>
#include <fair/Errors.h>
#include <fair/Knot_spacing.h>
#include <fair/internal/classic/common.h>
#include <fair/internal/common/input_checks.h>
#include <fair/internal/nurbs/assembly.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace fair {

/// The options of a Catmull_rom_2 (doc/concepts.md).
struct Catmull_rom_options {
  /// Closed: one piece per point, the last from the last point back to the first (>= 3 points).
  bool closed = false;
  /// The knots u_i (uniform: the classic Catmull-Rom spline; centripetal, chordal: Knot_spacing.h).
  Knot_spacing knot_spacing = Knot_spacing::UNIFORM;
};

template <class K>
class Catmull_rom_2 {
public:
  typedef K Kernel;
  typedef Catmull_rom_options Options;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Bezier_2<K> Piece;

  /// The open (>= 2 points, quadratic end extrapolation) or closed (>= 3 points) Catmull-Rom
  /// spline. Throws Invalid_input_error for too few points, non-finite coordinates or coincident
  /// consecutive points (and, when closed, coincident last and first points).
  explicit Catmull_rom_2(std::vector<Point_2> points, const Catmull_rom_options& options = {})
    : points_(std::move(points)), options_(options) {
    const char* method = "Catmull_rom_2";
    const bool closed = options_.closed;
    const Knot_spacing spacing = options_.knot_spacing;
    internal::common::check_interpolation_input(points_, closed ? 3 : 2, closed, method);
    const std::vector<FT> h = internal::classic::classic_knot_intervals<K>(points_, closed, spacing, method);
    const std::size_t n = points_.size();
    std::vector<Vector_2> m(n);
    if (closed) {
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t im = (i + n - 1) % n;
        m[i] = parabola_tangent(points_[im], points_[i], points_[(i + 1) % n], h[im], h[i]);
      }
    } else if (n == 2) {
      m[0] = m[1] = (points_[1] - points_[0]) / h[0];
    } else {
      for (std::size_t i = 1; i + 1 < n; ++i)
        m[i] = parabola_tangent(points_[i - 1], points_[i], points_[i + 1], h[i - 1], h[i]);
      // Quadratic end handling: derivative at u_0 (u_n) of the parabola through the end triple,
      // Newton form q(u) = p_0 + (u - u_0) D01 + (u - u_0)(u - u_1) D012.
      const Vector_2 d01 = (points_[1] - points_[0]) / h[0], d12 = (points_[2] - points_[1]) / h[1];
      m[0] = d01 - (d12 - d01) * (h[0] / (h[0] + h[1]));
      const Vector_2 da = (points_[n - 2] - points_[n - 3]) / h[n - 3];
      const Vector_2 db = (points_[n - 1] - points_[n - 2]) / h[n - 2];
      m[n - 1] = db + (db - da) * (h[n - 2] / (h[n - 3] + h[n - 2]));
    }
    assemble(h, m);
  }

  /// Expert: the open spline with the caller's auxiliary points p_{-1} = `before` and p_{n+1} =
  /// `after` (Li et al. eq. (1)); >= 2 points. With uniform knots an auxiliary point may coincide
  /// with its neighbour (then the end derivative is (p_1 - p_0)/2); with centripetal/chordal knots
  /// it must differ from it. Throws Invalid_input_error for bad data or auxiliary points, and
  /// Precondition_error for options.closed (a closed curve has no auxiliary points).
  Catmull_rom_2(std::vector<Point_2> points, const Point_2& before, const Point_2& after,
                const Catmull_rom_options& options = {})
    : points_(std::move(points)), options_(options) {
    const char* method = "Catmull_rom_2";
    internal::require(!options_.closed, "Catmull_rom_2: a closed curve has no auxiliary points");
    const Knot_spacing spacing = options_.knot_spacing;
    internal::common::check_interpolation_input(points_, 2, false, method);
    std::vector<Point_2> extended;
    extended.reserve(points_.size() + 2);
    extended.push_back(before);
    extended.insert(extended.end(), points_.begin(), points_.end());
    extended.push_back(after);
    internal::common::check_finite_points(extended, "Catmull_rom_2 (auxiliary points)");
    const std::vector<FT> he = internal::classic::classic_knot_intervals<K>(extended, false, spacing, method);
    const std::size_t n = points_.size();
    std::vector<Vector_2> m(n);
    for (std::size_t i = 0; i < n; ++i)
      m[i] = parabola_tangent(extended[i], extended[i + 1], extended[i + 2], he[i], he[i + 1]);
    assemble(std::vector<FT>(he.begin() + 1, he.end() - 1), m);
  }

  /// The cubic Bezier pieces; piece i runs from point i to point i+1 (mod n when closed).
  const std::vector<Piece>& pieces() const { return pieces_; }
  std::size_t number_of_pieces() const { return pieces_.size(); }
  /// The curve in the exchange form (fair/Nurbs_curve_2.h; doc/nurbs.md, "Catmull_rom_2"): degree
  /// 3 on knots() (piece i on [u_i, u_{i+1}]), interior knots of multiplicity 2 (C1 in u, not C2).
  /// Closed: the periodic form. Exactly the pieces in an exact kernel. O(n).
  Nurbs_curve_2<K> nurbs() const {
    return internal::nurbs::hermite_cubic_nurbs<K>(pieces_, knots_, options_.closed, "Catmull_rom_2::nurbs");
  }
  const std::vector<Point_2>& points() const { return points_; }
  /// The knots u_0 = 0 < u_1 < ... (one more than the number of pieces).
  const std::vector<FT>& knots() const { return knots_; }
  /// The derivatives m_i = c'(u_i) with respect to the knot parameter (one per point).
  const std::vector<Vector_2>& derivatives() const { return derivatives_; }
  bool is_closed() const { return options_.closed; }
  const Catmull_rom_options& options() const { return options_; }

private:
  // Derivative at the middle knot of the parabola through a, b, c with intervals hm, hp.
  static Vector_2 parabola_tangent(const Point_2& a, const Point_2& b, const Point_2& c, const FT& hm,
                                   const FT& hp) {
    const FT s = hm + hp;
    return (b - a) * (FT(1) / hm - FT(1) / s) + (c - b) * (FT(1) / hp - FT(1) / s);
  }

  void assemble(const std::vector<FT>& h, const std::vector<Vector_2>& m) {
    knots_ = internal::classic::classic_cumulative_knots(h);
    derivatives_ = m;
    pieces_ = internal::classic::classic_hermite_pieces<K>(points_, m, h, "Catmull_rom_2");
  }

  std::vector<Point_2> points_;
  Catmull_rom_options options_;
  std::vector<FT> knots_;
  std::vector<Vector_2> derivatives_;
  std::vector<Piece> pieces_;
};

} // namespace fair

#endif // FAIR_CATMULL_ROM_2_H
