// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The two tests of Proposition 1 (Karciauskas-Peters Sec. 6):
//  (a) convexity of a control polygon with exact predicates (Kernel::Orientation_2,
//      Compare_x_2, Collinear_are_strictly_ordered_along_line_2);
//  (b) regularity and the sign of the curvature numerator of a rational Bezier piece
//      c = (X, Y)/W of degree n,
//        det(c', c'') = det[[X, Y, W], [X', Y', W'], [X'', Y'', W'']] / W^3.
//      The determinant is computed as products of Bernstein polynomials of degrees n, n-1, n-2:
//      product degree 3n - 3 (6 for a cubic); its true degree is 3n - 6 (3 for a cubic, a
//      constant for a conic: the leading terms cancel). For a polynomial piece (W = 1) it is
//      x'y'' - y'x'' of product degree 2n - 3 and true degree 2n - 4 (2 for a cubic). Since
//      W > 0 its sign is the sign of the curvature -- but only where c' != 0, so the piece must
//      first be certified regular: the hodograph numerators (X'W - XW', Y'W - YW') (product
//      degree 2n - 1, true degree 2n - 2; polynomial: (x', y')) have no common root in [0,1].
//      Both decided by an interval filter (CGAL::Interval_nt on the coefficients: certainly no
//      sign variation of D => its sign is certain; the hodograph coefficients in an open
//      half-plane => regular), then exactly (Gmpq coefficients: no variation, or certified root
//      isolation: a root of odd multiplicity inside (0,1) is an inflection; a root in [0,1] of
//      |hodograph numerator|^2 is a singular point).
//      Exact for the FT coefficients of the pieces: in a double kernel these are the stored,
//      rounded Bezier points and products w x, w y, not the spline's control points and weights.

#ifndef FAIR_INTERNAL_EXACT_CONVERSION_CONVEXITY_H
#define FAIR_INTERNAL_EXACT_CONVERSION_CONVEXITY_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Bernstein_root_isolation.h>
#include <fair/internal/bernstein/curvature.h>
#include <fair/internal/bernstein/sign.h>
#include <fair/internal/bernstein/signed_roots.h>
#include <fair/Errors.h>
#include <fair/Rational_bezier_2.h>
#include <fair/internal/common/constants.h>
#include <fair/internal/common/exact_conversion.h>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace exact_conversion {

constexpr std::size_t no_index = std::numeric_limits<std::size_t>::max();

struct Polygon_convexity {
  bool convex = true;
  std::size_t violation = no_index;     // original index of the first violating vertex
  CGAL::Orientation orientation = CGAL::COLLINEAR;
};

/// (a) Is the polygon convex? An open polygon is closed by the edge from its last to its first
/// vertex (then every Bezier polygon of the spline, cut from it by corner cutting, is convex).
/// Repeated consecutive vertices are skipped; a collinear vertex is allowed when it lies strictly
/// between its neighbours (Lemma 1: no strong convexity), a reversal is not; the turns must all
/// have one sign and the edge directions must wind once (at most two sign changes of dx).
template <class K>
Polygon_convexity polygon_convexity(const std::vector<typename K::Point_2>& p, bool closed) {
  typedef typename K::Point_2 Point_2;
  Polygon_convexity out;
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (idx.empty() || !(p[idx.back()] == p[i])) idx.push_back(i);
  while (idx.size() > 1 && p[idx.back()] == p[idx.front()]) idx.pop_back();
  const std::size_t n = idx.size();
  if (n < 3) return out;
  const K k;
  const typename K::Orientation_2 orient = k.orientation_2_object();
  const typename K::Collinear_are_strictly_ordered_along_line_2 between = k.collinear_are_strictly_ordered_along_line_2_object();
  auto v = [&](std::size_t i) -> const Point_2& { return p[idx[(i + n) % n]]; };
  std::vector<CGAL::Orientation> o(n);
  CGAL::Orientation s = CGAL::COLLINEAR;
  for (std::size_t i = 0; i < n; ++i) {
    o[i] = orient(v(i + n - 1), v(i), v(i + 1));
    if (s == CGAL::COLLINEAR) s = o[i];
  }
  if (s == CGAL::COLLINEAR) {
    // All on one line: an open polygon is a straight run if it never reverses (the two closing
    // vertices reverse by construction); a closed one always reverses somewhere.
    for (std::size_t i = 0; i < n; ++i) {
      if (!closed && (i == 0 || i + 1 == n)) continue;
      if (!between(v(i + n - 1), v(i), v(i + 1))) {
        out.convex = false;
        out.violation = idx[i];
        return out;
      }
    }
    return out;
  }
  out.orientation = s;
  for (std::size_t i = 0; i < n; ++i) {
    const bool ok = (o[i] == s) || (o[i] == CGAL::COLLINEAR && between(v(i + n - 1), v(i), v(i + 1)));
    if (!ok) {
      out.convex = false;
      out.violation = idx[i];
      return out;
    }
  }
  // Winding number one: the sign of dx along the closed polygon changes exactly twice.
  int changes = 0;
  CGAL::Comparison_result last = CGAL::EQUAL;
  for (std::size_t i = 0; i < 2 * n; ++i) { // twice round, counting the changes of the second lap
    const CGAL::Comparison_result d = k.compare_x_2_object()(v(i + 1), v(i));
    if (d == CGAL::EQUAL) continue;
    if (i >= n && last != CGAL::EQUAL && d != last && ++changes > 2) {
      out.convex = false;
      out.violation = idx[i % n];
      return out;
    }
    last = d;
  }
  return out;
}

/// D (internal/bernstein/curvature.h), with the polynomial shortcut x'y'' - y'x'' when W = 1.
template <class NT>
Bernstein_polynomial<NT> curvature_numerator(const Bernstein_polynomial<NT>& X, const Bernstein_polynomial<NT>& Y,
                                             const Bernstein_polynomial<NT>& W, bool polynomial) {
  return polynomial ? bernstein::polynomial_curvature_determinant(X, Y) : bernstein::curvature_determinant(X, Y, W);
}

enum class Piece_decision { FILTER, EXACT, UNDECIDED };

struct Piece_sign {
  int sign = 0;              // +1 / -1: curvature >= 0 / <= 0 on the piece (zeros allowed); 0: straight
  bool inflection = false;   // the curvature changes sign inside (0,1) (exact certificate)
  bool singular = false;     // c' = 0 somewhere on [0,1] (exact certificate): sign means nothing
  Piece_decision decision = Piece_decision::UNDECIDED;
};

template <class NT, class FT>
Bernstein_polynomial<NT> converted(const Bernstein_polynomial<FT>& p, NT (*f)(const FT&)) {
  std::vector<NT> c;
  for (const FT& x : p.coefficients()) c.push_back(f(x));
  return Bernstein_polynomial<NT>(std::move(c));
}

template <class FT>
CGAL::Interval_nt<false> interval_of(const FT& x) { return common::to_interval_nt(x); }
template <class FT>
CGAL::Gmpq gmpq_of(const FT& x) { return common::to_gmpq(x, "spline_convexity"); }

/// The numerators (A_x, A_y) of the hodograph c' = (X'W - XW', Y'W - YW')/W^2 (polynomial: X', Y').
/// W > 0, so c'(t) = 0 iff A_x(t) = A_y(t) = 0.
template <class NT>
void hodograph_numerators(const Bernstein_polynomial<NT>& X, const Bernstein_polynomial<NT>& Y,
                          const Bernstein_polynomial<NT>& W, bool polynomial, Bernstein_polynomial<NT>& Ax,
                          Bernstein_polynomial<NT>& Ay) {
  if (!polynomial) {
    bernstein::hodograph_numerators(X, Y, W, Ax, Ay);
    return;
  }
  Ax = X.derivative();
  Ay = Y.derivative();
}

/// The sign of D on [0,1] when its interval coefficients certainly have no sign variation
/// (sign_variation_bounds().upper == 0, so every coefficient is >= 0 or every one <= 0): +1 / -1
/// if one is certainly nonzero, 0 if all are exactly zero (straight); false if undecided.
inline bool certain_constant_sign(const Bernstein_polynomial<CGAL::Interval_nt<false>>& D, int& sign) {
  if (sign_variation_bounds(D).upper != 0) return false;
  sign = 0;
  bool zero = true;
  for (const CGAL::Interval_nt<false>& c : D.coefficients()) {
    const std::pair<int, int> r = bernstein::sign_range_of(c);
    if (r.first == r.second && r.first != 0) sign = r.first;
    if (r.first != 0 || r.second != 0) zero = false;
  }
  return sign != 0 || zero;
}

/// Regularity filter: the hodograph's Bernstein coefficients a_0..a_k (interval enclosures) have a
/// direction d with d.a_i >= 0 for all i and d.a_0 > 0, d.a_k > 0, all certain. Then
/// d.c'(t) = sum B_i(t) d.a_i / W^2 > 0 on [0,1] (at t = 0, 1 only a_0, a_k count; inside, every
/// B_i > 0), so c' != 0. d is the middle of the smallest arc holding the coefficients' (double)
/// directions when that arc is shorter than a half turn; d is a double vector, exact in the
/// interval arithmetic, so the test is certified whatever rounding chose it.
inline bool certainly_regular(const Bernstein_polynomial<CGAL::Interval_nt<false>>& Ax,
                              const Bernstein_polynomial<CGAL::Interval_nt<false>>& Ay) {
  typedef CGAL::Interval_nt<false> I;
  const std::vector<I>& ax = Ax.coefficients();
  const std::vector<I>& ay = Ay.coefficients();
  if (ax.size() != ay.size() || ax.empty()) return false;
  std::vector<double> angle;
  for (std::size_t i = 0; i < ax.size(); ++i) {
    const double x = 0.5 * (ax[i].inf() + ax[i].sup()), y = 0.5 * (ay[i].inf() + ay[i].sup());
    if (!std::isfinite(x) || !std::isfinite(y)) return false;
    if (x != 0 || y != 0) angle.push_back(std::atan2(y, x));
  }
  if (angle.empty()) return false;
  std::sort(angle.begin(), angle.end());
  using common::pi;
  // The largest gap between circularly consecutive directions; the arc holding them all is its complement.
  std::size_t at = angle.size() - 1;
  double gap = angle.front() + 2 * pi - angle.back();
  for (std::size_t i = 0; i + 1 < angle.size(); ++i)
    if (angle[i + 1] - angle[i] > gap) { gap = angle[i + 1] - angle[i]; at = i; }
  if (gap <= pi) return false;
  const double first = angle[(at + 1) % angle.size()];
  const double mid = first + (2 * pi - gap) / 2;
  const I dx(std::cos(mid)), dy(std::sin(mid));
  for (std::size_t i = 0; i < ax.size(); ++i) {
    const I dot = dx * ax[i] + dy * ay[i];
    const bool end = i == 0 || i + 1 == ax.size();
    if (end ? !(dot.inf() > 0) : !(dot.inf() >= 0)) return false;
  }
  return true;
}

/// Exact regularity: c' = 0 at t iff S = A_x^2 + A_y^2 (>= 0) vanishes at t, so the piece is
/// singular iff S is zero or has a root in [0,1] (certified root isolation; the roots of S are
/// common roots of A_x and A_y, of even multiplicity, handled by its square-free factorisation).
/// This includes the ends: at t = 0, A = n w_0 w_1 (b_1 - b_0), so a join with b_1 = b_0 is singular.
inline bool exactly_singular(const Bernstein_polynomial<CGAL::Gmpq>& Ax, const Bernstein_polynomial<CGAL::Gmpq>& Ay) {
  const Bernstein_polynomial<CGAL::Gmpq> S = Ax * Ax + Ay * Ay;
  if (S.is_zero()) return true;
  bool positive = true;
  for (const CGAL::Gmpq& c : S.coefficients()) positive = positive && c > 0;
  if (positive) return false;
  return Bernstein_root_isolation(S).number_of_roots() > 0;
}

/// (b) The sign of the curvature of one piece on [0,1], and whether the piece is regular.
template <class K>
Piece_sign piece_sign(const Rational_bezier_2<K>& c, bool polynomial, bool exact_fallback) {
  typedef typename K::FT FT;
  Piece_sign out;
  bool regular = false;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    typedef CGAL::Interval_nt<false> I;
    const Bernstein_polynomial<I> X = converted<I, FT>(c.homogeneous_x(), &interval_of<FT>),
                                  Y = converted<I, FT>(c.homogeneous_y(), &interval_of<FT>),
                                  W = converted<I, FT>(c.homogeneous_w(), &interval_of<FT>);
    Bernstein_polynomial<I> Ax, Ay;
    hodograph_numerators(X, Y, W, polynomial, Ax, Ay);
    regular = certainly_regular(Ax, Ay);
    const Bernstein_polynomial<I> D = curvature_numerator(X, Y, W, polynomial);
    int sign = 0;
    if (regular && certain_constant_sign(D, sign)) {
      out.sign = sign;
      out.decision = Piece_decision::FILTER;
      return out;
    }
  }
  if (!exact_fallback) return out;
  out.decision = Piece_decision::EXACT;
  const Bernstein_polynomial<CGAL::Gmpq> X = converted<CGAL::Gmpq, FT>(c.homogeneous_x(), &gmpq_of<FT>),
                                         Y = converted<CGAL::Gmpq, FT>(c.homogeneous_y(), &gmpq_of<FT>),
                                         W = converted<CGAL::Gmpq, FT>(c.homogeneous_w(), &gmpq_of<FT>);
  if (!regular) {
    Bernstein_polynomial<CGAL::Gmpq> Ax, Ay;
    hodograph_numerators(X, Y, W, polynomial, Ax, Ay);
    if (exactly_singular(Ax, Ay)) {
      out.singular = true;
      return out;
    }
  }
  const Bernstein_polynomial<CGAL::Gmpq> D = curvature_numerator(X, Y, W, polynomial);
  if (D.is_zero()) return out; // straight piece
  if (sign_variations(D) == 0) {
    for (const CGAL::Gmpq& x : D.coefficients())
      if (!CGAL::is_zero(x)) { out.sign = int(CGAL::sign(x)); break; }
    return out;
  }
  // A sign change across an interior root (odd multiplicity) is an inflection; an empty gap
  // (a root at 0 or 1) has sign 0 and changes nothing.
  const bernstein::Signed_roots r = bernstein::signed_roots(D);
  for (std::size_t g = 0; g < r.gaps.size(); ++g) {
    if (r.gaps[g] == 0) continue;
    if (out.sign != 0 && out.sign != r.gaps[g]) out.inflection = true;
    out.sign = r.gaps[g];
  }
  FAIR_ASSERT_MSG(out.inflection || out.sign != 0, "spline_convexity: a nonzero polynomial is nonzero between its roots");
  return out;
}

} // namespace exact_conversion
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_EXACT_CONVERSION_CONVEXITY_H
