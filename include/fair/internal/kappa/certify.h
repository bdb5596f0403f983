// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact certification of a kappa-curve (fair::certify and fair::certify_pieces in
// Kappa_curve_2.h, the result fair::Kappa_certificate).
//
// certify(curve) -> certify_curve -> certify_parameters. The solver's lambda_i, t_i, w_i are
// doubles, i.e. exact dyadic rationals. With them held fixed, eq. 18 is solved EXACTLY and
// fraction-free (exact_eq18.h): P_i = N_i / Delta with integers N_i and Delta > 0. The join
// points E_i = (1-lambda_i) P_{i-1} + lambda_i P_i (eq. 9) are formed exactly.
// The checks then run on the SCALED curve rho * c with rho = Delta / 2^s in [1,2) (s = bit length
// of Delta minus 1): its control points rho P_i = N_i / 2^s and rho E_i, and the scaled points
// rho Q_i, are dyadic rationals, on which Gmpq arithmetic needs no expensive gcd (GMP strips
// powers of two). Every certified property is invariant under this positive scaling: Q_i ==
// c_i(t_i), orientation and strict order (G1), the parameters of the curvature extrema
// (eq. 4 scales by a positive factor), the relative |kappa| mismatch (eq. 5, both curvatures
// scale by 1/rho); a nonzero interpolation distance is reported as measured on the scaled curve,
// an upper bound for the unscaled one (rho >= 1; at most 2x loose).
// certify_pieces(curve) -> certify_returned_pieces -> certify_exact: the same checks on the
// returned pieces converted exactly to Gmpq (no scaling, O(n)).
// Exactly: Q_i == c_i(t_i), E_i shared (C0), orientation(P_{i-1}, E_i, P_i) == COLLINEAR with E_i
// strictly between (G1). The eq.-4 numerator: interval filter (interval_filters.h) on
// enclosures of the exact scaled coordinates -- exact signs of the 5 Bernstein coefficients
// (Descartes: 0 or exactly 1 simple root in (0,1)) and a certified sign change at t_i -/+ delta --
// with the exact isolation (Rational_quadratic_bezier_2::curvature_extrema) as the fallback
// whenever an interval sign is undecided. The relative |kappa| mismatch at each join,
// (|k1| - |k2|) / (|k1| + |k2|), is enclosed by outward-rounded interval arithmetic (eq. 5).
// The certificate's exact_pieces are the unscaled pieces in original coordinates (canonical
// Gmpq N_i / Delta, exact_integer.h canonical_fractions): building them costs a few gcds of
// ~200 n-bit integers per piece, which dominates for long curves.

#ifndef FAIR_INTERNAL_KAPPA_CERTIFY_H
#define FAIR_INTERNAL_KAPPA_CERTIFY_H

#include <fair/Errors.h>
#include <fair/internal/kappa/certificate_record.h>
#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/internal/common/exact_conversion.h>
#include <fair/internal/kappa/exact_eq18.h>
#include <fair/internal/kappa/exact_integer.h>
#include <fair/internal/kappa/interval_filters.h>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// How certify_* decide: FILTERED runs the filters first -- eq4_filtered_extremum for the
/// curvature extrema (exact isolation only where it is undecided), the interval sign of the
/// control triangle's area, and the exact but cheap G1 identity E_j - P_{j-1} == lambda_j
/// (P_j - P_{j-1}) -- with the exact predicates as fallback; EXACT always runs the exact
/// predicates and Rational_quadratic_bezier_2::curvature_extrema (for tests of the filters).
enum class Certify_mode { FILTERED, EXACT };

typedef Kappa_certificate::Exact_kernel Exact_kernel;
typedef Exact_kernel::Point_2 Exact_point;
typedef CGAL::Interval_nt<false> Interval;

/// Outward-rounded enclosures of the exact control points (E_j, P_j, E_{j+1}) and weights w_j
/// of n pieces (E has n + 1 entries), for the interval filters.
struct Piece_enclosures {
  std::vector<Interval> ex, ey, px, py, w;

  Piece_enclosures(const std::vector<Exact_point>& E, const std::vector<Exact_point>& P,
                   const std::vector<CGAL::Gmpq>& weights) {
    const std::size_t n = P.size();
    ex.resize(n + 1); ey.resize(n + 1); px.resize(n); py.resize(n); w.resize(n);
    for (std::size_t j = 0; j <= n; ++j) { ex[j] = enclose(E[j].x()); ey[j] = enclose(E[j].y()); }
    for (std::size_t j = 0; j < n; ++j) { px[j] = enclose(P[j].x()); py[j] = enclose(P[j].y()); w[j] = enclose(weights[j]); }
  }
  static Interval enclose(const CGAL::Gmpq& q) {
    const std::pair<double, double> x = CGAL::to_interval(q);
    return Interval(x.first, x.second);
  }
};

/// The exact control points and weights of n pieces (E[n] == E[0] for closed curves), their
/// parameters t_j, the interpolated points Q_j and the indices of these in the curve's points.
struct Exact_pieces_data {
  const std::vector<std::size_t>& point_index;
  const std::vector<Exact_point>& E;
  const std::vector<Exact_point>& P;
  const std::vector<CGAL::Gmpq>& w;
  const std::vector<double>& t;
  const std::vector<Exact_point>& Q;
};

/// Piece j is a genuine conic arc: w_j > 0, E_j != E_{j+1} and the control points not collinear
/// (by the interval sign of the control triangle's area when it is certain, else exactly).
inline bool is_valid_piece(const Exact_pieces_data& d, const Piece_enclosures& enc, std::size_t j, Certify_mode mode) {
  int area_sign = 0;
  if (mode == Certify_mode::FILTERED) {
    CGAL::Protect_FPU_rounding<true> guard;
    const Interval det = (enc.px[j] - enc.ex[j]) * (enc.ey[j + 1] - enc.ey[j]) -
                         (enc.py[j] - enc.ey[j]) * (enc.ex[j + 1] - enc.ex[j]);
    area_sign = det.inf() > 0 ? 1 : (det.sup() < 0 ? -1 : 0);
  }
  return d.w[j] > 0 && d.E[j] != d.E[j + 1] &&
         (area_sign != 0 || Exact_kernel::Orientation_2()(d.E[j], d.P[j], d.E[j + 1]) != CGAL::COLLINEAR);
}

/// point_on_piece (c_j(t_j) == Q_j exactly) and otherwise a certified upper bound of the
/// distance, multiplied by inverse_scale_upper (>= 1/rho for a curve scaled by rho).
inline void certify_interpolation(const Exact_pieces_data& d, std::size_t j, double inverse_scale_upper,
                                  Kappa_certificate::Piece& pc) {
  typedef CGAL::Gmpq Q;
  // c_j(t_j) == Q_j  <=>  (1-t)^2 E_j + 2 (1-t) t w P_j + t^2 E_{j+1} == W(t) Q_j  (eq. 1)
  const Q t(d.t[j]), u = Q(1) - t, c0 = u * u, c1 = Q(2) * u * t * d.w[j], c2 = t * t, D = c0 + c1 + c2;
  const Q cx = c0 * d.E[j].x() + c1 * d.P[j].x() + c2 * d.E[j + 1].x();
  const Q cy = c0 * d.E[j].y() + c1 * d.P[j].y() + c2 * d.E[j + 1].y();
  pc.point_on_piece = cx == D * d.Q[j].x() && cy == D * d.Q[j].y();
  if (pc.point_on_piece) {
    pc.interpolation_error = 0;
    return;
  }
  // Certified upper bound of the distance: sqrt of an upper bound, rounded up twice.
  const double inf = std::numeric_limits<double>::infinity();
  const Exact_point c(cx / D, cy / D);
  const double d2 = CGAL::to_interval(CGAL::squared_distance(c, d.Q[j])).second;
  pc.interpolation_error = std::nextafter(std::nextafter(std::sqrt(d2), inf) * inverse_scale_upper, inf);
}

/// The interval filter for the curvature extrema of piece j: true if it decided -- no extremum
/// (pc unchanged), or a unique one, then recorded in pc with its bracket around t_j.
inline bool filtered_extremum_at_t(const Piece_enclosures& enc, std::size_t j, double t, Kappa_certificate::Piece& pc) {
  const Interval xy[6] = {enc.ex[j], enc.ey[j], enc.px[j], enc.py[j], enc.ex[j + 1], enc.ey[j + 1]};
  Curvature_extremum_kind kind = Curvature_extremum_kind::MAXIMUM;
  double lo = 0, hi = 0, dist = 0;
  const int roots = eq4_filtered_extremum(xy, enc.w[j], t, kind, lo, hi, dist);
  if (roots != 1) return roots == 0;
  pc.extrema = 1;
  pc.maxima = kind == Curvature_extremum_kind::MAXIMUM ? 1 : 0;
  pc.has_extremum_at_t = true;
  pc.kind_at_t = kind;
  pc.root_lower = lo;
  pc.root_upper = hi;
  pc.root_distance = dist;
  return true;
}

/// The exact certified isolation (with its own interval fast path) of the curvature extrema of
/// piece j, and the one nearest to t_j.
inline void exact_extremum_at_t(const Exact_pieces_data& d, std::size_t j, Kappa_certificate::Piece& pc) {
  typedef CGAL::Gmpq Q;
  const Q t(d.t[j]);
  const Rational_quadratic_bezier_2<Exact_kernel> piece(d.E[j], d.P[j], d.E[j + 1], d.w[j]);
  const std::vector<Curvature_extremum> ext = piece.curvature_extrema();
  pc.extrema = ext.size();
  for (const Curvature_extremum& x : ext) {
    if (x.kind == Curvature_extremum_kind::MAXIMUM) ++pc.maxima;
    const double distance = CGAL::to_interval(std::max(CGAL::abs(t - x.t_lower), CGAL::abs(x.t_upper - t))).second;
    if (distance < pc.root_distance) {
      pc.root_distance = distance;
      pc.has_extremum_at_t = true;
      pc.kind_at_t = x.kind;
      pc.root_lower = CGAL::to_interval(x.t_lower).first;
      pc.root_upper = CGAL::to_interval(x.t_upper).second;
    }
  }
}

/// Everything certified about piece j alone.
inline Kappa_certificate::Piece certify_piece(const Exact_pieces_data& d, const Piece_enclosures& enc, std::size_t j,
                                              double inverse_scale_upper, Certify_mode mode) {
  Kappa_certificate::Piece pc;
  pc.point_index = d.point_index[j];
  pc.t = d.t[j];
  pc.valid_piece = is_valid_piece(d, enc, j, mode);
  if (!pc.valid_piece) return pc;
  certify_interpolation(d, j, inverse_scale_upper, pc);
  if (!(mode == Certify_mode::FILTERED && filtered_extremum_at_t(enc, j, d.t[j], pc))) exact_extremum_at_t(d, j, pc);
  pc.maximum_at_t = pc.has_extremum_at_t && pc.maxima == 1 && pc.kind_at_t == Curvature_extremum_kind::MAXIMUM;
  pc.unique_maximum = pc.maximum_at_t && pc.extrema == 1;
  return pc;
}

/// The join at the start of piece j when some piece is not a valid conic piece: reported as not
/// G1 with an unknown mismatch, so that all_g1() and max_kappa_mismatch() cannot read as success.
inline Kappa_certificate::Join undecided_join(std::size_t j) {
  Kappa_certificate::Join jn;
  jn.piece = j;
  jn.c0 = jn.g1 = false;
  jn.kappa_mismatch_lower = -std::numeric_limits<double>::infinity();
  jn.kappa_mismatch_upper = std::numeric_limits<double>::infinity();
  return jn;
}

/// G1 at the join E_j between pieces a = j-1 and j: P_a, E_j, P_j collinear with E_j strictly
/// between. Sufficient and cheap (no product of two long numbers): E_j - P_a == lambda_j (P_j -
/// P_a) exactly with 0 < lambda_j < 1 and P_a != P_j; otherwise the exact orientation and order.
inline bool is_g1_join(const Exact_pieces_data& d, std::size_t a, std::size_t j, Certify_mode mode,
                       const std::vector<double>* lambda) {
  const std::vector<Exact_point>& E = d.E;
  const std::vector<Exact_point>& P = d.P;
  if (mode == Certify_mode::FILTERED && lambda != nullptr && (*lambda)[j] > 0 && (*lambda)[j] < 1 && P[a] != P[j]) {
    const CGAL::Gmpq l((*lambda)[j]);
    if (E[j].x() - P[a].x() == l * (P[j].x() - P[a].x()) && E[j].y() - P[a].y() == l * (P[j].y() - P[a].y()))
      return true;
  }
  return Exact_kernel::Orientation_2()(P[a], E[j], P[j]) == CGAL::COLLINEAR &&
         CGAL::collinear_are_strictly_ordered_along_line(P[a], E[j], P[j]);
}

/// Everything certified about the join at the start of piece j (C0 is set by the caller from
/// the exact pieces).
inline Kappa_certificate::Join certify_join(const Exact_pieces_data& d, const Piece_enclosures& enc, std::size_t j,
                                            Certify_mode mode, const std::vector<double>* lambda) {
  const std::size_t n = d.P.size(), a = (j + n - 1) % n;
  Kappa_certificate::Join jn;
  jn.piece = j;
  jn.c0 = true;
  jn.g1 = is_g1_join(d, a, j, mode, lambda);
  const Interval A[2] = {enc.ex[a], enc.ey[a]}, Pa[2] = {enc.px[a], enc.py[a]}, Ej[2] = {enc.ex[j], enc.ey[j]};
  const Interval Pj[2] = {enc.px[j], enc.py[j]}, B[2] = {enc.ex[j + 1], enc.ey[j + 1]};
  relative_mismatch_interval(A, Pa, Ej, Pj, B, enc.w[a], enc.w[j], jn.kappa_mismatch_lower, jn.kappa_mismatch_upper);
  return jn;
}

/// The exact per-piece and per-join checks of certify() and certify_pieces() on the exact pieces
/// `d` of the curve scaled by a positive factor rho (Q_j = rho * Q_i). All checks are invariant
/// under the scaling; a nonzero interpolation distance is multiplied by inverse_scale_upper >=
/// 1/rho. Fills pieces and joins (joins decided only when every piece is valid); `exact_pieces`
/// is left to the caller. O(n) pieces of bounded work each, plus the arithmetic on the given
/// numbers (dyadic rationals in certify(): no big gcds).
inline void certify_scaled(bool closed, const Exact_pieces_data& d, double inverse_scale_upper, Certify_mode mode,
                           Kappa_certificate& cert, const std::vector<double>* lambda = nullptr) {
  const std::size_t n = d.P.size();
  const Piece_enclosures enc(d.E, d.P, d.w);
  cert.pieces.clear();
  cert.joins.clear();
  bool all_valid = true;
  for (std::size_t j = 0; j < n; ++j) {
    cert.pieces.push_back(certify_piece(d, enc, j, inverse_scale_upper, mode));
    all_valid = all_valid && cert.pieces.back().valid_piece;
  }
  for (std::size_t j = (closed ? 0 : 1); j < n; ++j)
    cert.joins.push_back(all_valid ? certify_join(d, enc, j, mode, lambda) : undecided_join(j));
}

/// Builds cert.exact_pieces from the exact control points (E_j, P_j, E_{j+1}) and weights of the
/// valid pieces and records C0 at the joins on them (true by construction when neighbouring
/// pieces are built from the same E_j; a check of the assembled curve, not a proof of more).
inline void attach_exact_pieces(const std::vector<Exact_point>& E, const std::vector<Exact_point>& P,
                                const std::vector<CGAL::Gmpq>& w, Kappa_certificate& cert) {
  const std::size_t n = P.size();
  for (std::size_t j = 0; j < n; ++j)
    if (cert.pieces[j].valid_piece) cert.exact_pieces.emplace_back(E[j], P[j], E[j + 1], w[j]);
  if (cert.exact_pieces.size() == n)
    for (Kappa_certificate::Join& jn : cert.joins)
      jn.c0 = cert.exact_pieces[(jn.piece + n - 1) % n].target() == cert.exact_pieces[jn.piece].source();
}

/// certify_scaled on unscaled pieces, plus exact_pieces built from them (and C0 recorded).
inline Kappa_certificate certify_exact(bool closed, const std::vector<std::size_t>& point_index,
                                       const std::vector<Exact_point>& E, const std::vector<Exact_point>& P,
                                       const std::vector<CGAL::Gmpq>& w, const std::vector<double>& tt,
                                       const std::vector<Exact_point>& Qp, Certify_mode mode = Certify_mode::FILTERED,
                                       const std::vector<double>* lambda = nullptr) {
  Kappa_certificate cert;
  certify_scaled(closed, Exact_pieces_data{point_index, E, P, w, tt, Qp}, 1.0, mode, cert, lambda);
  attach_exact_pieces(E, P, w, cert);
  return cert;
}

/// The control points of the curve built from the exact solution P_j = N_j / Delta of eq. 18:
/// E[j] by eq. 9 (E[0] = s, E[n] = e for an open curve, E[n] == E[0] for a closed one).
struct Exact_control_points {
  std::vector<Exact_point> E, P;
};

/// The curve scaled by rho = Delta / 2^s in [1, 2): P~_j = N_j / 2^s (dyadic, canonical without
/// a gcd), E~_j by eq. 9 from them, and the scaled points Q~_j = rho Q_j.
inline Exact_control_points scaled_dyadic_curve(bool closed, const std::vector<CGAL::Gmpq>& qx,
                                                const std::vector<CGAL::Gmpq>& qy, const Exact_point& s,
                                                const Exact_point& e, const std::vector<CGAL::Gmpq>& lambda,
                                                const std::vector<Certify_int>& Nx, const std::vector<Certify_int>& Ny,
                                                const Certify_int& Delta, std::vector<Exact_point>& Q_scaled) {
  typedef CGAL::Gmpq Q;
  const std::size_t n = qx.size();
  const mp_bitcnt_t shift = floor_log2(Delta);
  const Q rho = dyadic_fraction(Delta, shift);
  Exact_control_points c;
  c.P.resize(n);
  c.E.resize(n + 1);
  Q_scaled.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    c.P[j] = Exact_point(dyadic_fraction(Nx[j], shift), dyadic_fraction(Ny[j], shift));
    Q_scaled[j] = Exact_point(rho * qx[j], rho * qy[j]);
  }
  for (std::size_t j = (closed ? 0 : 1); j < n; ++j) {
    const Exact_point& A = c.P[(j + n - 1) % n];
    const Q ml = Q(1) - lambda[j];
    c.E[j] = Exact_point(ml * A.x() + lambda[j] * c.P[j].x(), ml * A.y() + lambda[j] * c.P[j].y());
  }
  if (!closed) c.E[0] = Exact_point(rho * s.x(), rho * s.y());
  c.E[n] = closed ? c.E[0] : Exact_point(rho * e.x(), rho * e.y());
  return c;
}

/// The unscaled control points in original coordinates as canonical Gmpq with one big gcd
/// (canonical_fractions): P_j = N_j / Delta, E_j = ((2^k - l) N_{j-1} + l N_j) / (2^k Delta)
/// for lambda_j = l / 2^k.
inline Exact_control_points original_curve(bool closed, const Exact_point& s, const Exact_point& e,
                                           const std::vector<CGAL::Gmpq>& lambda, const std::vector<Certify_int>& Nx,
                                           const std::vector<Certify_int>& Ny, const Certify_int& Delta) {
  const std::size_t n = Nx.size();
  std::vector<Certify_int> Ex(n), Ey(n);
  std::vector<const Certify_int*> X;
  std::vector<mp_bitcnt_t> twos;
  for (std::size_t j = 0; j < n; ++j) {
    X.push_back(&Nx[j]); X.push_back(&Ny[j]);
    twos.push_back(0); twos.push_back(0);
  }
  for (std::size_t j = (closed ? 0 : 1); j < n; ++j) {
    const std::size_t a = (j + n - 1) % n;
    const mp_bitcnt_t k = dyadic_combination(lambda[j], Nx[a], Nx[j], Ex[j]);
    dyadic_combination(lambda[j], Ny[a], Ny[j], Ey[j]);
    X.push_back(&Ex[j]); X.push_back(&Ey[j]);
    twos.push_back(k); twos.push_back(k);
  }
  const std::vector<CGAL::Gmpq> F = canonical_fractions(X, twos, Delta);
  Exact_control_points c;
  c.P.resize(n);
  c.E.resize(n + 1);
  for (std::size_t j = 0; j < n; ++j) c.P[j] = Exact_point(F[2 * j], F[2 * j + 1]);
  if (!closed) c.E[0] = s;
  for (std::size_t j = (closed ? 0 : 1), r = 2 * n; j < n; ++j, r += 2) c.E[j] = Exact_point(F[r], F[r + 1]);
  c.E[n] = closed ? c.E[0] : e;
  return c;
}

/// The certificate of the exact curve defined by exact points (qx, qy) (and end points s, e of
/// an open curve) and the rational parameters lambda, t, w (doubles, exact): eq. 18 solved
/// exactly and fraction-free (exact_eq18_integer), checks on the dyadic scaled curve
/// (certify_scaled), exact_pieces in original coordinates. lambda[0] is ignored for open curves.
/// Requires 0 < lambda_i, t_i < 1 and w_i > 0 (true for a Kappa_curve_2): otherwise the exact
/// elimination can meet a zero pivot (Internal_error).
inline Kappa_certificate certify_parameters(bool closed, const std::vector<std::size_t>& point_index,
                                            const std::vector<CGAL::Gmpq>& qx, const std::vector<CGAL::Gmpq>& qy,
                                            const CGAL::Gmpq& sx, const CGAL::Gmpq& sy, const CGAL::Gmpq& ex,
                                            const CGAL::Gmpq& ey, const std::vector<double>& lambda_d,
                                            const std::vector<double>& t_d, const std::vector<double>& w_d,
                                            Certify_mode mode = Certify_mode::FILTERED) {
  typedef CGAL::Gmpq Q;
  const std::size_t n = qx.size();
  // The unused lambda_0 of an open curve is replaced by 1/2 (any value in (0,1) would do).
  std::vector<Q> lambda(n), t(n), w(n);
  for (std::size_t j = 0; j < n; ++j) {
    lambda[j] = Q(closed || j > 0 ? lambda_d[j] : 0.5);
    t[j] = Q(t_d[j]);
    w[j] = Q(w_d[j]);
  }
  std::vector<Certify_int> Nx, Ny;
  Certify_int Delta;
  exact_eq18_integer(closed, qx, qy, sx, sy, ex, ey, lambda, t, w, Nx, Ny, Delta);
  const Exact_point s(sx, sy), e(ex, ey);
  std::vector<Exact_point> Q_scaled;
  const Exact_control_points scaled = scaled_dyadic_curve(closed, qx, qy, s, e, lambda, Nx, Ny, Delta, Q_scaled);
  Kappa_certificate cert;
  // rho >= 1, so 1 is an upper bound of 1/rho for the interpolation distance.
  certify_scaled(closed, Exact_pieces_data{point_index, scaled.E, scaled.P, w, t_d, Q_scaled}, 1.0, mode, cert,
                 &lambda_d);
  const Exact_control_points original = original_curve(closed, s, e, lambda, Nx, Ny, Delta);
  attach_exact_pieces(original.E, original.P, w, cert);
  return cert;
}

/// The exact point of a kernel point.
template <class Point>
Exact_point exact_point(const Point& p) {
  return Exact_point(common::to_gmpq(p.x()), common::to_gmpq(p.y()));
}

/// certify(curve): the exact inputs of a Kappa_curve_2 (its points and solver parameters) for
/// certify_parameters.
template <class Curve>
Kappa_certificate certify_curve(const Curve& curve, Certify_mode mode) {
  typedef CGAL::Gmpq Q;
  const std::size_t n = curve.number_of_pieces(), m = curve.points().size();
  const bool closed = curve.is_closed();
  std::vector<Q> qx(n), qy(n);
  std::vector<std::size_t> index(n);
  for (std::size_t j = 0; j < n; ++j) {
    index[j] = curve.point_index(j);
    const auto& q = curve.points()[index[j]];
    qx[j] = common::to_gmpq(q.x());
    qy[j] = common::to_gmpq(q.y());
  }
  Exact_point s(0, 0), e(0, 0);
  if (!closed) {
    s = exact_point(curve.points()[0]);
    e = exact_point(curve.points()[m - 1]);
  }
  const auto& st = curve.state();
  return certify_parameters(closed, index, qx, qy, s.x(), s.y(), e.x(), e.y(), st.lambda, st.t, st.w, mode);
}

/// certify_pieces(curve): the returned pieces of a Kappa_curve_2 converted exactly, for
/// certify_exact.
template <class Curve>
Kappa_certificate certify_returned_pieces(const Curve& curve, Certify_mode mode = Certify_mode::FILTERED) {
  const std::size_t n = curve.number_of_pieces();
  std::vector<Exact_point> E(n + 1), P(n), Qp(n);
  std::vector<CGAL::Gmpq> w(n);
  std::vector<double> t(n);
  std::vector<std::size_t> index(n);
  for (std::size_t j = 0; j < n; ++j) {
    const auto& pc = curve.piece(j);
    E[j] = exact_point(pc.control_point(0));
    P[j] = exact_point(pc.control_point(1));
    w[j] = common::to_gmpq(pc.weight());
    t[j] = curve.t(j);
    index[j] = curve.point_index(j);
    Qp[j] = exact_point(curve.points()[index[j]]);
  }
  E[n] = exact_point(curve.piece(n - 1).control_point(2));
  return certify_exact(curve.is_closed(), index, E, P, w, t, Qp, mode, &curve.state().lambda);
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_CERTIFY_H
