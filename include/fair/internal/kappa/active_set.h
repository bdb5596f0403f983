// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The active set of the box constraints 0 < t_i < 1 (doc/kappa_curves.md, "Points on joins"):
// a t_i on its face is fixed there with its eq. 7 dropped (t_on_face, drop_face_equations), a
// free t_i that a step leaves near a bound is put on it (snap_to_faces, first_crossing), and a
// fixed t_i whose multiplier -- the one-sided derivative of |kappa| at the join, from eq. 4's
// numerator (Eq4_of_piece) -- is negative is released to its piece's maximum (release_faces).

#ifndef FAIR_INTERNAL_KAPPA_ACTIVE_SET_H
#define FAIR_INTERNAL_KAPPA_ACTIVE_SET_H

#include <fair/internal/conic/curvature_extrema.h>
#include <fair/internal/kappa/block_range.h>
#include <fair/internal/kappa/solve_settings.h>
#include <fair/internal/kappa/system.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// The active set of the box-constrained problem (doc/kappa_curves.md, "Points on joins"): t_i
/// is FIXED on its face when it sits on the projection bound parameter_margin or
/// 1 - parameter_margin. The set is a function of the state alone, so it survives warm starts
/// without extra bookkeeping. On the face Q_i is (to O(parameter_margin)) the end point of its
/// piece, eq. 7 of the piece holds by itself (its residual is O(u^2), u the distance of t_i to
/// the bound: doc/kappa_existence.md, Sec. 1) and its row degenerates (a zero gradient at the
/// face root): the Newton system drops that equation together with the unknown t_i.
inline bool t_on_face(double t) { return t <= parameter_margin || t >= 1 - parameter_margin; }

/// Drops the equations of the active set from the residuals F of the blocks of `range` (r_2 of
/// a block whose t_i is on its face: set to 0); returns the max |r| of the equations that remain.
inline double drop_face_equations(const Problem& pb, const Kappa_solver_state& st, const Block_range& range,
                                  std::vector<double>& F) {
  const std::size_t na = range.all ? pb.n : range.count;
  double mx = 0;
  for (std::size_t ii = 0; ii < na; ++ii) {
    const std::size_t i = range.all ? ii : (range.first + ii) % pb.n;
    if (t_on_face(st.t[i])) F[4 * ii + 2] = 0.0;
    for (int c = 0; c < 4; ++c) {
      const double a = std::abs(F[4 * ii + c]);
      mx = (a > mx || std::isnan(a)) ? a : mx;
    }
  }
  return mx;
}

/// Relative size (to the terms of eq. 4's coefficients, before their cancellation) below which a
/// derivative of eq. 4's numerator counts as zero: the piece is a circular arc to that relative
/// accuracy (the numerator vanishes identically for a circle) and has no extremum worth the name.
constexpr double minimum_derivative_floor = 1e-8;

/// The numerator E of kappa' (eq. 4, fair::internal::conic::eq4_coefficients; E goes from - to +
/// at a maximum of |kappa|) of the piece of block i in the Bernstein basis of degree 4, and the
/// size of the terms of its coefficients (for relative tests). The weight is the piece's own
/// (1, the user's, or eq. 16 of the current control points).
struct Eq4_of_piece {
  std::vector<double> b;
  double size = 0;
  double value(double t) const {
    const double u = 1 - t;
    return b[0] * u * u * u * u + 4 * b[1] * u * u * u * t + 6 * b[2] * u * u * t * t + 4 * b[3] * u * t * t * t +
           b[4] * t * t * t * t;
  }
  /// E'(t) / 4 (Bernstein basis of degree 3).
  double derivative(double t) const {
    const double u = 1 - t;
    return (b[1] - b[0]) * u * u * u + 3 * (b[2] - b[1]) * u * u * t + 3 * (b[3] - b[2]) * u * t * t +
           (b[4] - b[3]) * t * t * t;
  }
};
inline Eq4_of_piece eq4_of_piece(const Problem& pb, const Kappa_solver_state& st, std::size_t i) {
  Window<double> win;
  build_window(pb, st, i, win);
  Piece_values<double> pv;
  piece_values(pb, st, i, win, 2, pv);
  const double* X = win.X[2];
  const double w = pv.w;
  Eq4_of_piece e;
  e.b = conic::eq4_coefficients<double>(pv.E0[0], pv.E0[1], X[0], X[1], pv.E2[0], pv.E2[1], w);
  const auto sq = [](double x, double y) { return x * x + y * y; };
  e.size = (w * w * w + w + 1) * (sq(pv.E0[0] - X[0], pv.E0[1] - X[1]) + sq(X[0] - pv.E2[0], X[1] - pv.E2[1]) +
                                  sq(pv.E0[0] - pv.E2[0], pv.E0[1] - pv.E2[1]));
  return e;
}

/// The multiplier of the face constraint of block i (t_i on its face): the one-sided derivative
/// of |kappa| of piece i at Q_i (the piece's end at the join), taken towards the join, as the
/// sign-carrying value of eq. 4's numerator: -E(t_i) at t_i = 1, +E(t_i) at t_i = 0 (E < 0 where
/// |kappa| increases). Non-negative (|kappa| rises towards the join, so that the maximum of
/// |kappa| over the piece is at Q_i, on the join) is the first-order condition of the
/// constrained solution; negative beyond the floor means the piece's maximum lies inside it and
/// the interior is better: the variable is released.
inline bool face_multiplier_negative(const Problem& pb, const Kappa_solver_state& st, std::size_t i) {
  const Eq4_of_piece e = eq4_of_piece(pb, st, i);
  const double v = e.value(st.t[i]), m = st.t[i] > 0.5 ? -v : v;
  return m < -minimum_derivative_floor * e.size;
}

/// The fixing rule of newton()'s active set, after an accepted step: a free t_i within
/// bound_margin of a bound (where the outcome would call it on a join anyway) is put on that face.
/// This ends the linear "creep" of Newton's method into a root on the face, whose Jacobian is
/// singular there (doc/kappa_existence.md, Sec. 1), in one step. Returns whether any was.
inline bool snap_to_faces(const Problem& pb, const Block_range& range,
                          Kappa_solver_state& st) {
  const std::size_t na = range.all ? pb.n : range.count;
  bool any = false;
  for (std::size_t ii = 0; ii < na; ++ii) {
    const std::size_t i = range_block(pb, range, ii);
    double& t = st.t[i];
    if (t_on_face(t)) continue;
    if (t < bound_margin) { t = parameter_margin; any = true; }
    else if (t > 1 - bound_margin) { t = 1 - parameter_margin; any = true; }
  }
  return any;
}

/// The largest alpha in (0, 1) at which the step alpha delta puts a free t_i of `range` on a
/// bound (the first crossing), or 0 if the full step crosses none.
inline double first_crossing(const Problem& pb, const Block_range& range, const std::vector<double>& delta,
                             const Kappa_solver_state& st) {
  const std::size_t na = range.all ? pb.n : range.count;
  double alpha = 1;
  bool any = false;
  for (std::size_t ii = 0; ii < na; ++ii) {
    const double t = st.t[range_block(pb, range, ii)], d = delta[4 * ii + 3];
    if (t_on_face(t)) continue;
    const double a = d > 0 ? (1 - parameter_margin - t) / d : d < 0 ? (parameter_margin - t) / d : 2.0;
    if (a < alpha) { alpha = a; any = true; }
  }
  return any ? alpha : 0.0;
}

/// A t in (0,1) of the maximum of |kappa| of the piece of block i (the sign change - to + of
/// eq. 4's numerator E, by bisection on the Bernstein quartic), or 1/2 if E has none there.
inline double piece_maximum_parameter(const Eq4_of_piece& e) {
  auto E = [&](double t) { return e.value(t); };
  double lo = parameter_margin, hi = 1 - parameter_margin;
  if (!(E(lo) < 0 && E(hi) > 0)) return 0.5;
  for (int k = 0; k < 60 && hi - lo > 1e-12; ++k) {  // 60 halvings: below 1e-12 from a unit bracket
    const double mid = 0.5 * (lo + hi);
    (E(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}
/// The same for the piece of block i.
inline double piece_maximum_parameter(const Problem& pb, const Kappa_solver_state& st, std::size_t i) {
  return piece_maximum_parameter(eq4_of_piece(pb, st, i));
}

/// Releases of one t_i per Newton run: a t_i released this often and back on its face stays
/// fixed (no cycling; the outcome then lists the point among points_at_minima).
constexpr char max_releases = 2;

/// The release step of newton()'s active set at a root of the reduced system: every block of
/// `range` whose t is on its face with a negative multiplier (face_multiplier_negative) and was
/// not released before is released, t moved to its piece's maximum of |kappa|. Returns whether
/// any was released.
inline bool release_faces(const Problem& pb, Kappa_solver_state& st, const Block_range& range,
                          std::vector<char>& released) {
  const std::size_t na = range.all ? pb.n : range.count;
  bool any = false;
  std::vector<std::size_t> to_release;
  for (std::size_t ii = 0; ii < na; ++ii) {
    const std::size_t i = range.all ? ii : (range.first + ii) % pb.n;
    if (released[ii] >= max_releases || !t_on_face(st.t[i]) || !face_multiplier_negative(pb, st, i)) continue;
    to_release.push_back(ii);
  }
  for (std::size_t ii : to_release) {  // all decided on the same state, then moved
    const std::size_t i = range.all ? ii : (range.first + ii) % pb.n;
    st.t[i] = piece_maximum_parameter(pb, st, i);
    ++released[ii];
    any = true;
  }
  return any;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_ACTIVE_SET_H
