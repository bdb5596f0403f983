// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// One C2 spline from a chain of polynomial Bezier shapes of degree <= 3 whose consecutive end
// points agree (Fig. 9, case (a)), each converted by eqs. 9-10 with the same interior marks
// 0 < u_1 < ... < u_{m-1} < 1. The control polygon is the concatenation of the shapes' polygons
// d^j_0..d^j_{m+2} with each shared end point once. Knots: shape j occupies [o_j, o_j + 1]
// (its own u, shifted); at a junction the three points d^j_{m+1}, q_{j+1}, d^{j+1}_1 get the
// breakpoints o_j + 1, o_j + 1 + (1 - u_{m-1}), o_{j+1} = that + u_1, so the knot intervals
// around d^j_{m+1} are both 1 - u_{m-1}, around d^{j+1}_1 both u_1: beta = 1 at them, and
// beta = u_1 / (1 - u_{m-1}) at q_{j+1} (= 1, the paper's "beta := 1", for symmetric marks).
// Every control point of shape j's interior keeps its knots and blossom, so the spline equals
// shape j exactly on [o_j + u_2, o_j + u_{m-2}] (on [o_0, o_0 + u_{m-2}] for the first shape of an
// open chain, which is clamped like eq. 10, and on [o_j + u_2, o_j + 1] for the last).

#ifndef FAIR_INTERNAL_EXACT_CONVERSION_CHAIN_H
#define FAIR_INTERNAL_EXACT_CONVERSION_CHAIN_H

#include <fair/Bezier_2.h>
#include <fair/Errors.h>
#include <fair/Rational_bezier_2.h>
#include <fair/internal/exact_conversion/blossom.h>

#include <CGAL/number_utils.h>

#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace exact_conversion {

template <class K>
struct Chain_layout {
  std::vector<typename K::FT> breakpoints;     // open: t_0..t_M; closed: t_0..t_M (t_M = t_0 + period)
  std::vector<typename K::Point_2> control_points;
  std::vector<typename K::FT> weights;
  bool rational = false;                         // some shape is rational
};

template <class K>
Chain_layout<K> chain_layout(const std::vector<Rational_bezier_2<K>>& shapes, const std::vector<typename K::FT>& u, bool closed,
                             const char* fn) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  const std::size_t n = shapes.size();
  if (n == 0) throw Invalid_input_error(message(fn, ": needs at least one shape"));
  if (closed && n < 2) throw Invalid_input_error(message(fn, ": a closed chain needs at least two shapes, got ", n));
  check_marks(u, fn);
  for (std::size_t j = 0; j + (closed ? 0 : 1) < n; ++j) {
    const Point_2& a = shapes[j].control_points().back();
    const Point_2& b = shapes[(j + 1) % n].control_points().front();
    const FT& wa = shapes[j].weights().back();
    const FT& wb = shapes[(j + 1) % n].weights().front();
    if (!(wa == wb))
      throw Invalid_input_error(message(fn, ": shape ", j, " ends with weight ", CGAL::to_double(wa), " but shape ",
                                        (j + 1) % n, " starts with weight ", CGAL::to_double(wb),
                                        "; shared end points need equal weights (e.g. conics in standard form)"));
    if (!(a == b))
      throw Invalid_input_error(message(fn, ": shape ", j, " ends at (", CGAL::to_double(a.x()), ", ", CGAL::to_double(a.y()),
                                        ") but shape ", (j + 1) % n, " starts at (", CGAL::to_double(b.x()), ", ",
                                        CGAL::to_double(b.y()), "); consecutive shapes must share their end point"));
  }
  const std::size_t m = u.size() + 1;
  const FT u1 = u.empty() ? FT(1) : u.front(), um1 = u.empty() ? FT(0) : u.back();
  const FT P = FT(2) - um1 + u1; // the parameter length of one shape plus its junction
  std::vector<std::vector<Homogeneous<FT>>> d(n);
  Chain_layout<K> out;
  for (std::size_t j = 0; j < n; ++j) {
    d[j] = de_boor_points(homogeneous_cubic(shapes[j], fn), u);
    out.rational = out.rational || !shapes[j].is_polynomial();
  }
  std::vector<FT>& t = out.breakpoints;
  struct Sink {
    Chain_layout<K>& l;
    void push_back(const Homogeneous<FT>& h) {
      l.control_points.push_back(Point_2(h.x / h.w, h.y / h.w));
      l.weights.push_back(h.w);
    }
  } c{out};
  const FT start = closed ? u1 : FT(0);
  for (std::size_t j = 0; j < n; ++j) {
    const FT o = start + FT(int(j)) * P;
    if (closed) { t.push_back(o - u1); c.push_back(d[j][0]); t.push_back(o); c.push_back(d[j][1]); }
    else if (j == 0) { t.push_back(o); c.push_back(d[j][0]); c.push_back(d[j][1]); }
    for (std::size_t i = 1; i < m; ++i) { t.push_back(o + u[i - 1]); c.push_back(d[j][i + 1]); }
    t.push_back(o + FT(1));
    c.push_back(d[j][m + 1]);
    if (!closed && j + 1 == n) c.push_back(d[j][m + 2]);
    if (!closed && j + 1 < n) {
      t.push_back(o + FT(1) + (FT(1) - um1)); c.push_back(d[j][m + 2]);
      t.push_back(o + P); c.push_back(d[j + 1][1]);
    }
  }
  if (closed) t.push_back(FT(int(n)) * P);
  return out;
}

} // namespace exact_conversion
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_EXACT_CONVERSION_CHAIN_H
