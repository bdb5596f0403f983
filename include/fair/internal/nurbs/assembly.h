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
// Checks (review findings 6-8): the parts must join -- each part's end is the next one's start
// (C0), a closed loop's last end is its first start, a Hermite join is the C1 join the NURBS
// forms -- exactly in an exact FT; in a floating-point FT to join_tolerance (2^-36, about
// 1.5e-11, of the largest |coordinate| of the parts: families' joints carry a few ulps of
// rounding, a real gap is far larger). Otherwise Precondition_error naming the two pieces (or
// runs) and the two points. A closed loop of rational parts must also close in the weights: the
// parts are scaled to agree at each join, so around the loop the weight comes back multiplied by
// the product of the parts' end-weight ratios w_p / w_0; a periodic NURBS has one weight at its
// seam, so the product must be 1 (to join_tolerance in double). Making it 1 would take the Moebius
// reparametrisation w_i -> rho^i w_i of one part with rho^p equal to the product, a p-th root
// (not in FT) that also changes the part's parameter: refused instead (doc/nurbs.md §7).
//
// Only +, -, *, / of FT (the weight scale of a join is a quotient): exact in an exact kernel.
// O(total number of control points).

#ifndef FAIR_INTERNAL_NURBS_ASSEMBLY_H
#define FAIR_INTERNAL_NURBS_ASSEMBLY_H

#include <fair/Errors.h>
#include <fair/Nurbs_curve_2.h>
#include <fair/internal/common/piece_detection.h>
#include <fair/internal/nurbs/blossom.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <type_traits>
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
  std::size_t parts = 0; // the parts appended so far
  double extent = 0;     // the largest |coordinate| of their control points (join_tolerance)
};

/// The largest |coordinate| of `P` and `extent`.
template <class Points>
double coordinate_extent(const Points& P, double extent = 0) {
  for (const auto& x : P)
    extent = std::max({extent, std::fabs(CGAL::to_double(x.x())), std::fabs(CGAL::to_double(x.y()))});
  return extent;
}

/// How far apart two points that must be one may be (file comment): 0 in an exact FT,
/// 2^-36 extent in a floating-point FT.
template <class FT>
double join_tolerance(double extent) {
  return std::is_floating_point<FT>::value ? std::ldexp(extent, -36) : 0.0;
}

/// Throws unless `end` (of part `j`) and `start` (of part `next`, or what `start_name` says) are
/// one point (file comment).
template <class K>
void require_join(const typename K::Point_2& end, const typename K::Point_2& start, double extent, const char* who,
                  const char* part, std::size_t j, std::size_t next, const char* what, const char* start_name = nullptr) {
  const double tolerance = join_tolerance<typename K::FT>(extent);
  const bool joined = tolerance == 0 ? end == start
                                     : std::fabs(CGAL::to_double(end.x() - start.x())) <= tolerance &&
                                           std::fabs(CGAL::to_double(end.y() - start.y())) <= tolerance;
  if (joined) return;
  std::ostringstream name;
  if (start_name) name << start_name << " of " << part << "s " << j << " and " << next << " is";
  else name << part << " " << next << " starts at";
  require(false, who, ": ", part, " ", j, " ends at (", CGAL::to_double(end.x()), ", ", CGAL::to_double(end.y()),
          ") but ", name.str(), " (", CGAL::to_double(start.x()), ", ", CGAL::to_double(start.y()), "): ", what,
          tolerance == 0 ? " (exactly)" : " (to 2^-36 of the largest |coordinate|)");
}

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
/// knots; every later one is shifted to start at out.u.back(). \throws Precondition_error,
/// naming `who` and the `part` ("piece", "run") indices, unless the part is clamped and starts
/// where the previous one ends (file comment).
template <class K>
void append_c0(Nurbs_data<K>& out, const std::vector<typename K::FT>& u, const std::vector<typename K::Point_2>& P,
               const std::vector<typename K::FT>& w, const char* who, const char* part) {
  typedef typename K::FT FT;
  const std::size_t p = out.p;
  require(P.size() >= p + 1 && u.size() == P.size() + p + 1 && (w.empty() || w.size() == P.size()),
          "fair::internal::nurbs::append_c0: a part of ", P.size(), " control points, ", u.size(), " knots and ",
          w.size(), " weights for degree ", p);
  const std::size_t j = out.parts++;
  // clamped: the part's first and last control points are its ends
  require(u[0] == u[p] && u[P.size()] == u.back(), who, ": ", part, " ", j, " is not clamped (its end knots ",
          "are not repeated ", p + 1, " times), so its end control points are not its ends");
  out.extent = coordinate_extent(P, out.extent);
  if (out.P.empty()) {
    out.u = u;
    out.P = P;
    out.w = w.empty() ? std::vector<FT>(P.size(), FT(1)) : w;
    return;
  }
  require_join<K>(out.P.back(), P.front(), out.extent, who, part, j - 1, j, "the curve is not continuous (C0) there");
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
/// there must agree. \throws Precondition_error otherwise, naming `who` and the `part`s.
template <class K>
Nurbs_curve_2<K> finish_c0(Nurbs_data<K> d, bool closed, const char* who, const char* part) {
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
  require_join<K>(d.P.back(), d.P.front(), d.extent, who, part, d.parts - 1, 0, "the closed loop does not close");
  if (!polynomial) { // (not in require's arguments: they are evaluated even when it holds, and d.w is empty then)
    const double ratio = CGAL::to_double(d.w.back() / d.w.front());
    const bool closes = std::is_floating_point<FT>::value ? std::fabs(ratio - 1) <= std::ldexp(1.0, -36)
                                                           : d.w.back() == d.w.front();
    require(closes, who, ": a closed loop of rational ", part, "s whose end-weight ratios w_p / w_0 multiply to ",
            ratio, ", not 1: scaled to agree at every join, the weights at the seam differ, and a periodic NURBS ",
            "has one weight there (making the product 1 would need a p-th root and a new parameter; doc/nurbs.md §7)");
  }
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
    append_c0(d, u, std::vector<typename K::Point_2>(cp.begin(), cp.end()), piece_weights(pieces[j]), who, "piece");
  }
  return finish_c0(std::move(d), closed, who, "piece");
}

/// Cubic Bezier pieces, C1 in the parameter whose breakpoints are `t` (m + 1 values for m
/// pieces), as the degree-3 NURBS with interior knots of multiplicity 2 (file comment).
template <class K, class Piece>
Nurbs_curve_2<K> hermite_cubic_nurbs(const std::vector<Piece>& pieces, const std::vector<typename K::FT>& t,
                                     bool closed, const char* who) {
  typedef typename K::FT FT;
  const std::size_t m = pieces.size();
  require(m >= 1 && t.size() == m + 1, who, ": ", m, " pieces and ", t.size(), " breakpoints");
  // the joins (file comment): C0, and the point the NURBS forms from b^j_2 and b^{j+1}_1 is the join
  double extent = 0;
  for (const Piece& b : pieces) extent = coordinate_extent(b.control_points(), extent);
  for (std::size_t j = 0; j + 1 < m || (closed && j < m); ++j) {
    const std::size_t k = (j + 1) % m;
    const FT h0 = t[j + 1] - t[j], h1 = t[k + 1] - t[k];
    const auto& a = pieces[j].control_points();
    const auto& b = pieces[k].control_points();
    require_join<K>(a[3], b[0], extent, who, "piece", j, k,
                    k == 0 ? "the closed loop does not close" : "the curve is not continuous (C0) there");
    const typename K::Point_2 formed = CGAL::ORIGIN + ((a[2] - CGAL::ORIGIN) * h1 + (b[1] - CGAL::ORIGIN) * h0) / (h0 + h1);
    require_join<K>(a[3], formed, extent, who, "piece", j, k,
                    "the pieces are not C1 in the parameter there (b^j_3 - b^j_2) / h_j != (b^{j+1}_1 - b^{j+1}_0) / h_{j+1}",
                    "the join the NURBS forms, (h_{j+1} b^j_2 + h_j b^{j+1}_1) / (h_j + h_{j+1}),");
  }
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

/// The curve c on its domain as an open clamped NURBS (blossom.h, clamped_form): the same knots
/// inside the domain, the same curve; a closed curve is opened at its seam u_p (its start) =
/// u_n (its end). Exact in an exact kernel.
template <class K>
Nurbs_curve_2<K> opened(const Nurbs_curve_2<K>& c) {
  typedef typename K::FT FT;
  int e = 0;
  const std::vector<Homogeneous_point<FT>> H = homogeneous_points(c.control_points(), c.weights(), e);
  std::vector<FT> v;
  const std::vector<Homogeneous_point<FT>> Q = clamped_form(c.degree(), c.knots(), H, v);
  std::vector<typename K::Point_2> P;
  std::vector<FT> w;
  for (const Homogeneous_point<FT>& q : Q) {
    P.push_back(typename K::Point_2(q.x / q.w, q.y / q.w));
    w.push_back(scaled_by_power_of_two(q.w, e));
  }
  if (!c.is_rational()) w.clear();
  return Nurbs_curve_2<K>(c.degree(), std::move(v), std::move(P), std::move(w), false);
}

/// Open clamped C2 cubic spline runs (anything with nurbs() and is_closed(), e.g.
/// Cubic_spline_2) joined end to start at corners (fair::Polygon_spline_runs): one NURBS whose
/// knot at each corner has multiplicity 3 (C0); each run keeps its own breakpoints, shifted to
/// start where the previous run ends. One run that is closed (periodic) when `closed` and open
/// when not is that run's own NURBS; one periodic run asked for open is opened at its seam
/// (opened(); review finding 9: it came back closed). closed: the last run ends where the first
/// starts (periodic form, the seam at the first run's start, multiplicity 3).
template <class K, class Spline>
Nurbs_curve_2<K> spline_runs_nurbs(const std::vector<Spline>& runs, bool closed, const char* who) {
  require(!runs.empty(), who, ": no spline");
  if (runs.size() == 1 && runs.front().is_closed() == closed) return runs.front().nurbs();
  if (runs.size() == 1 && !closed) return opened(runs.front().nurbs());
  Nurbs_data<K> d;
  d.p = 3;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    require(!runs[r].is_closed(), who, ": run ", r, " is periodic");
    const Nurbs_curve_2<K> c = runs[r].nurbs();
    append_c0(d, c.knots(), c.control_points(), c.is_rational() ? c.weights() : std::vector<typename K::FT>{}, who,
              "run");
  }
  return finish_c0(std::move(d), closed, who, "run");
}

}  // namespace nurbs
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_NURBS_ASSEMBLY_H
