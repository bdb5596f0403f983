// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Building the NURBS form (fair::Nurbs_curve_2) of the families whose representation is a
// sequence of pieces or of spline runs rather than one C2 spline (doc/nurbs.md §7):
//
//  - C0 assembly (append_c0, then finish_c0): open clamped parts of one degree p (a Bezier piece
//    is the clamped NURBS on [t_j, t_{j+1}] with knots t_j^(p+1), t_{j+1}^(p+1)) joined end to
//    start. At a join the two clamped end knots (p + 1 copies each) become one knot of
//    multiplicity p, the join's control point is kept once (the previous part's value) and every
//    control point before and after keeps its value: the B-spline basis functions of a knot of
//    multiplicity p are C0 there and the spans on either side have their own Bernstein bases, so
//    each span's Bezier points are exactly the part's. The next part's knots are shifted to
//    start where the previous one ends; its weights are multiplied by one constant (the same
//    curve) so that they agree at the join.
//  - closed with a C0 seam (finish_c0(closed = true)): from the open form Q_0 .. Q_M on the
//    clamped knots v_0 .. v_{M+p+1} whose last control point is its first, the periodic form
//    with the seam knot of multiplicity p: one period of knots from the domain start is
//    v_p .. v_{M+p} (a, the interior knots, b^p), the control points Q_0 .. Q_{M-1} followed by
//    the first p again (Nurbs_curve_2's closed form, N = M).
//  - C1 cubic Hermite pieces (hermite_cubic_nurbs): piece j with Bezier points b^j_0..b^j_3 on
//    [t_j, t_{j+1}], C1 in t (b^j_3 - b^j_2) / h_j = (b^{j+1}_1 - b^{j+1}_0) / h_{j+1}: degree 3,
//    interior knots of multiplicity 2, control points b^0_0, b^0_1, b^0_2, b^1_1, b^1_2, ...,
//    b^{m-1}_1, b^{m-1}_2, b^{m-1}_3. The join b^j_3 = b^{j+1}_0 is not a control point: the
//    NURBS forms it as (h_{j+1} b^j_2 + h_j b^{j+1}_1) / (h_j + h_{j+1}), which is the join
//    exactly when the pieces are C1 exactly (as they are in an exact kernel). Closed: the
//    periodic form with the seam knot of multiplicity 2, control points b^{m-1}_2, b^0_1, b^0_2,
//    ..., b^{m-1}_1, then the first 3 again.
//
// Only +, -, *, / of FT (the weight scale of a join is a quotient): exact in an exact kernel.
// O(total number of control points).

#ifndef FAIR_INTERNAL_NURBS_ASSEMBLY_H
#define FAIR_INTERNAL_NURBS_ASSEMBLY_H

#include <fair/Errors.h>
#include <fair/Nurbs_curve_2.h>
#include <fair/internal/common/piece_detection.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace nurbs {

/// The stored form of a NURBS under assembly.
template <class K>
struct Nurbs_data {
  std::size_t p = 0;
  std::vector<typename K::FT> u;
  std::vector<typename K::Point_2> P;
  std::vector<typename K::FT> w;
};

/// The knots u_0 .. u_{N+2p} of a periodic curve of degree p from one period of knots starting
/// at the domain start, `period` = u_p .. u_{p+N} (N + 1 values, u_{p+N} = u_p + T), extended by
/// u_{k+N} = u_k + T (N >= p: the extension reads only the given period).
template <class FT>
std::vector<FT> periodic_knots(std::size_t p, const std::vector<FT>& period) {
  const std::size_t N = period.size() - 1;
  require(N >= p, "fair::internal::nurbs::periodic_knots: a period of ", N, " knot intervals for degree ", p);
  const FT T = period.back() - period.front();
  std::vector<FT> u(N + 2 * p + 1);
  for (std::size_t k = 0; k <= N; ++k) u[p + k] = period[k];
  for (std::size_t k = 0; k < p; ++k) u[k] = u[k + N] - T;
  for (std::size_t k = p + N + 1; k < u.size(); ++k) u[k] = u[k - N] + T;
  return u;
}

/// Appends the open clamped part (degree out.p, knots `u`, control points `P`, weights `w` or
/// empty for all 1) to `out`, C0 at the join (see the file comment). The first part keeps its
/// knots; every later one is shifted to start at out.u.back().
template <class K>
void append_c0(Nurbs_data<K>& out, const std::vector<typename K::FT>& u, const std::vector<typename K::Point_2>& P,
               const std::vector<typename K::FT>& w) {
  typedef typename K::FT FT;
  const std::size_t p = out.p;
  require(P.size() >= p + 1 && u.size() == P.size() + p + 1 && (w.empty() || w.size() == P.size()),
          "fair::internal::nurbs::append_c0: a part of ", P.size(), " control points, ", u.size(), " knots and ",
          w.size(), " weights for degree ", p);
  if (out.P.empty()) {
    out.u = u;
    out.P = P;
    out.w = w.empty() ? std::vector<FT>(P.size(), FT(1)) : w;
    return;
  }
  const FT offset = out.u.back() - u.front();
  const FT scale = w.empty() ? out.w.back() : out.w.back() / w.front();
  out.u.pop_back();  // the join: p + 1 copies of the end knot become p
  for (std::size_t k = p + 1; k < u.size(); ++k) out.u.push_back(u[k] + offset);
  for (std::size_t k = 1; k < P.size(); ++k) {
    out.P.push_back(P[k]);
    out.w.push_back(w.empty() ? scale : w[k] * scale);
  }
}

/// The weights of a Bezier piece (empty for a polynomial one).
template <class Piece>
std::vector<typename Piece::FT> piece_weights(const Piece& piece) {
  if constexpr (common::Is_bezier<Piece>::value) {
    return {};
  } else {
    const auto w = piece.weights();
    return std::vector<typename Piece::FT>(w.begin(), w.end());
  }
}

/// The curve of the C0 assembly. closed: the periodic form with a C0 seam (file comment); the
/// last control point must be the first (its value is replaced by the first's) and the weights
/// there must agree. \throws Precondition_error otherwise, naming `who`.
template <class K>
Nurbs_curve_2<K> finish_c0(Nurbs_data<K> d, bool closed, const char* who) {
  typedef typename K::FT FT;
  const bool polynomial = [&] {
    for (const FT& w : d.w)
      if (w != d.w.front()) return false;
    return true;
  }();
  if (polynomial) d.w.clear();
  if (!closed) return Nurbs_curve_2<K>(d.p, std::move(d.u), std::move(d.P), std::move(d.w), false);
  const std::size_t p = d.p, M = d.P.size() - 1;
  require(M >= p, who, ": a closed curve of ", M, " control points for degree ", p);
  require(polynomial || d.w.back() == d.w.front(), who, ": the weights at the seam differ (",
          CGAL::to_double(d.w.back()), " and ", CGAL::to_double(d.w.front()), ")");
  std::vector<FT> period(d.u.begin() + static_cast<long>(p), d.u.begin() + static_cast<long>(M + p) + 1);
  std::vector<typename K::Point_2> P(d.P.begin(), d.P.begin() + static_cast<long>(M));
  for (std::size_t k = 0; k < p; ++k) P.push_back(P[k]);
  std::vector<FT> w;
  if (!polynomial) {
    w.assign(d.w.begin(), d.w.begin() + static_cast<long>(M));
    for (std::size_t k = 0; k < p; ++k) w.push_back(w[k]);
  }
  return Nurbs_curve_2<K>(p, periodic_knots(p, period), std::move(P), std::move(w), true);
}

/// Bezier pieces of degree p joined end to start, piece j on [j, j + 1] (the knots are the piece
/// indices: the curve at u = j + t is piece j at t), interior knots of multiplicity p. closed: the
/// last piece ends where the first starts (periodic form, C0 seam).
template <class K, class Piece>
Nurbs_curve_2<K> bezier_pieces_nurbs(const std::vector<Piece>& pieces, bool closed, const char* who) {
  typedef typename K::FT FT;
  require(!pieces.empty(), who, ": no pieces");
  Nurbs_data<K> d;
  d.p = pieces.front().degree();
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    require(pieces[j].degree() == d.p, who, ": piece ", j, " has degree ", pieces[j].degree(), ", piece 0 ", d.p);
    std::vector<FT> u(d.p + 1, FT(0));
    u.resize(2 * d.p + 2, FT(1));
    const auto cp = pieces[j].control_points();
    append_c0(d, u, std::vector<typename K::Point_2>(cp.begin(), cp.end()), piece_weights(pieces[j]));
  }
  return finish_c0(std::move(d), closed, who);
}

/// Cubic Bezier pieces, C1 in the parameter whose breakpoints are `t` (m + 1 values for m
/// pieces), as the degree-3 NURBS with interior knots of multiplicity 2 (file comment).
template <class K, class Piece>
Nurbs_curve_2<K> hermite_cubic_nurbs(const std::vector<Piece>& pieces, const std::vector<typename K::FT>& t,
                                     bool closed, const char* who) {
  typedef typename K::FT FT;
  const std::size_t m = pieces.size();
  require(m >= 1 && t.size() == m + 1, who, ": ", m, " pieces and ", t.size(), " breakpoints");
  std::vector<typename K::Point_2> P;
  std::vector<FT> u;
  if (!closed) {
    P.push_back(pieces.front().control_point(0));
    for (std::size_t j = 0; j < m; ++j) {
      P.push_back(pieces[j].control_point(1));
      P.push_back(pieces[j].control_point(2));
    }
    P.push_back(pieces.back().control_point(3));
    u.assign(4, t.front());
    for (std::size_t j = 1; j < m; ++j) u.insert(u.end(), 2, t[j]);
    u.insert(u.end(), 4, t.back());
    return Nurbs_curve_2<K>(3, std::move(u), std::move(P), {}, false);
  }
  require(m >= 2, who, ": a closed curve of ", m, " piece");
  P.push_back(pieces.back().control_point(2));
  for (std::size_t j = 0; j < m; ++j) {
    P.push_back(pieces[j].control_point(1));
    if (j + 1 < m) P.push_back(pieces[j].control_point(2));
  }
  for (std::size_t k = 0; k < 3; ++k) P.push_back(P[k]);
  std::vector<FT> period{t.front()};
  for (std::size_t j = 1; j <= m; ++j) period.insert(period.end(), 2, t[j]);
  return Nurbs_curve_2<K>(3, periodic_knots(std::size_t(3), period), std::move(P), {}, true);
}

/// Open clamped C2 cubic spline runs (anything with nurbs() and is_closed(), e.g.
/// Cubic_spline_2) joined end to start at corners (fair::Polygon_spline_runs): one NURBS whose
/// knot at each corner has multiplicity 3 (C0); each run keeps its own breakpoints, shifted to
/// start where the previous run ends. One periodic run, or one run of an open curve, is that
/// run's own NURBS. closed: the last run ends where the first starts (periodic form, the seam
/// at the first run's start, multiplicity 3).
template <class K, class Spline>
Nurbs_curve_2<K> spline_runs_nurbs(const std::vector<Spline>& runs, bool closed, const char* who) {
  require(!runs.empty(), who, ": no spline");
  if (runs.size() == 1 && (runs.front().is_closed() || !closed)) return runs.front().nurbs();
  Nurbs_data<K> d;
  d.p = 3;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    require(!runs[r].is_closed(), who, ": run ", r, " is periodic");
    const Nurbs_curve_2<K> c = runs[r].nurbs();
    append_c0(d, c.knots(), c.control_points(), c.is_rational() ? c.weights() : std::vector<typename K::FT>{});
  }
  return finish_c0(std::move(d), closed, who);
}

}  // namespace nurbs
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_NURBS_ASSEMBLY_H
