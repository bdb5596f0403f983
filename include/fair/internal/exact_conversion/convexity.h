// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The two tests of Proposition 1 (Karciauskas-Peters Sec. 6):
//  (a) convexity of a control polygon with exact predicates (Kernel::Orientation_2,
//      Compare_x_2, Collinear_are_strictly_ordered_along_line_2);
//  (b) the sign of the curvature numerator of a rational Bezier piece c = (X, Y)/W,
//        det(c', c'') = det[[X, Y, W], [X', Y', W'], [X'', Y'', W'']] / W^3,
//      a Bernstein polynomial of degree 3n (n = 3: degree 9 written as products of degree
//      3 + 2 + 1 = 6; we keep the product degree 6) -- for a polynomial piece (W = 1) it is
//      x'y'' - y'x'' of degree 2n - 3 = 3. Since W > 0 its sign is the sign of the curvature.
//      Decided by an interval filter (CGAL::Interval_nt on the coefficients: certainly no sign
//      variation => the sign is certain), then exactly (Gmpq coefficients: no variation, or
//      certified root isolation: a root of odd multiplicity inside (0,1) is an inflection).

#ifndef FAIR_INTERNAL_EXACT_CONVERSION_CONVEXITY_H
#define FAIR_INTERNAL_EXACT_CONVERSION_CONVEXITY_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Bernstein_root_isolation.h>
#include <fair/Errors.h>
#include <fair/Rational_bezier_2.h>
#include <fair/internal/common/exact_conversion.h>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/enum.h>

#include <cstddef>
#include <limits>
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

/// det[[X,Y,W],[X',Y',W'],[X'',Y'',W'']] (rational) or X'Y'' - Y'X'' (polynomial, W = 1).
template <class NT>
Bernstein_polynomial<NT> curvature_numerator(const Bernstein_polynomial<NT>& X, const Bernstein_polynomial<NT>& Y,
                                             const Bernstein_polynomial<NT>& W, bool polynomial) {
  const Bernstein_polynomial<NT> X1 = X.derivative(), Y1 = Y.derivative(), X2 = X1.derivative(), Y2 = Y1.derivative();
  if (polynomial) return X1 * Y2 - Y1 * X2;
  const Bernstein_polynomial<NT> W1 = W.derivative(), W2 = W1.derivative();
  return X * (Y1 * W2 - W1 * Y2) - Y * (X1 * W2 - W1 * X2) + W * (X1 * Y2 - Y1 * X2);
}

enum class Piece_decision { FILTER, EXACT, UNDECIDED };

struct Piece_sign {
  int sign = 0;              // +1 / -1: curvature >= 0 / <= 0 on the piece (zeros allowed); 0: straight
  bool inflection = false;   // the curvature changes sign inside (0,1) (exact certificate)
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

/// (b) The sign of the curvature of one piece on [0,1].
template <class K>
Piece_sign piece_sign(const Rational_bezier_2<K>& c, bool polynomial, bool exact_fallback) {
  typedef typename K::FT FT;
  Piece_sign out;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    typedef CGAL::Interval_nt<false> I;
    const Bernstein_polynomial<I> D = curvature_numerator(converted<I, FT>(c.homogeneous_x(), &interval_of<FT>),
                                                          converted<I, FT>(c.homogeneous_y(), &interval_of<FT>),
                                                          converted<I, FT>(c.homogeneous_w(), &interval_of<FT>), polynomial);
    int lo = 1, hi = -1;
    bool certain = true;
    for (const I& x : D.coefficients()) {
      const CGAL::Uncertain<CGAL::Sign> sg = CGAL::sign(x);
      if (!CGAL::is_certain(sg)) { certain = false; break; }
      const int v = int(CGAL::get_certain(sg));
      if (v == 0) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    if (certain && !(lo < 0 && hi > 0)) {
      out.sign = hi > 0 ? 1 : (lo < 0 ? -1 : 0);
      out.decision = Piece_decision::FILTER;
      return out;
    }
  }
  if (!exact_fallback) return out;
  out.decision = Piece_decision::EXACT;
  const Bernstein_polynomial<CGAL::Gmpq> D = curvature_numerator(converted<CGAL::Gmpq, FT>(c.homogeneous_x(), &gmpq_of<FT>),
                                                                  converted<CGAL::Gmpq, FT>(c.homogeneous_y(), &gmpq_of<FT>),
                                                                  converted<CGAL::Gmpq, FT>(c.homogeneous_w(), &gmpq_of<FT>), polynomial);
  if (D.is_zero()) return out; // straight piece
  if (sign_variations(D) == 0) {
    for (const CGAL::Gmpq& x : D.coefficients())
      if (!CGAL::is_zero(x)) { out.sign = int(CGAL::sign(x)); break; }
    return out;
  }
  const std::vector<Isolating_interval> roots = isolate_roots(D);
  std::vector<CGAL::Gmpq> probes; // points of [0,1] that are certainly not roots
  CGAL::Gmpq left(0);
  for (const Isolating_interval& r : roots) {
    const bool at_end = r.is_point() && (r.lower == CGAL::Gmpq(0) || r.lower == CGAL::Gmpq(1));
    if (!at_end && (r.multiplicity % 2 == 1)) out.inflection = true;
    if (left < r.lower) probes.push_back((left + r.lower) / 2);
    left = r.upper;
  }
  if (left < CGAL::Gmpq(1)) probes.push_back((left + CGAL::Gmpq(1)) / 2);
  for (const CGAL::Gmpq& t : probes) {
    const CGAL::Gmpq v = D.evaluate(t);
    if (!CGAL::is_zero(v)) { out.sign = int(CGAL::sign(v)); break; }
  }
  FAIR_ASSERT_MSG(out.inflection || out.sign != 0, "spline_convexity: a nonzero polynomial is nonzero between its roots");
  return out;
}

} // namespace exact_conversion
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_EXACT_CONVERSION_CONVEXITY_H
