// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The rational quadratic pieces of a Kappa_curve_2 in its kernel, from the solver's
// normalised solution (system.h, problem_setup.h).

#ifndef FAIR_INTERNAL_KAPPA_PIECES_H
#define FAIR_INTERNAL_KAPPA_PIECES_H

#include <fair/Errors.h>
#include <fair/Kappa_curve_report.h>
#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/internal/kappa/problem_setup.h>
#include <fair/internal/kappa/system.h>

#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// The pieces of the solution st of pb in the kernel K: the middle control points P_j (rounded
/// to the kernel from x_original = center + scale * x_normalised), then the joins E_j of eq. 9
/// computed FROM them in the kernel's arithmetic: in an exact kernel the returned pieces are
/// exactly G1 (E_j on the segment P_{j-1} P_j), which certify_pieces() verifies piece by piece.
/// The end points of an open curve are the input points q.front() and q.back() themselves.
/// Invalid_input_error if a piece degenerates to a straight segment (locally collinear input).
template <class K>
std::vector<Rational_quadratic_bezier_2<K>> assemble_pieces(const Problem& pb, const Kappa_solver_state& st,
                                                            const Normalisation& nz,
                                                            const std::vector<typename K::Point_2>& q) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  const std::size_t n = pb.n;
  FAIR_ASSERT_MSG(st.dx.size() == n && st.dy.size() == n && st.lambda.size() == n && st.t.size() == n &&
                      st.w.size() == n && q.size() == (pb.closed ? n : n + 2),
                  "the solver's state does not match the ", n, " blocks of the problem");
  auto to_point = [&](double px, double py) {
    return Point_2(FT(nz.center_x) + FT(nz.scale) * FT(px), FT(nz.center_y) + FT(nz.scale) * FT(py));
  };
  std::vector<Point_2> P(n), E(n + 1);
  for (std::size_t j = 0; j < n; ++j) P[j] = to_point(pb.qx[j] + st.dx[j], pb.qy[j] + st.dy[j]);
  for (std::size_t j = 0; j < n; ++j) {
    if (!pb.has_start(j)) { E[j] = q.front(); continue; }
    const Point_2& A = P[(j + n - 1) % n];
    const FT l(st.lambda[j]), ml = FT(1) - l;
    E[j] = Point_2(ml * A.x() + l * P[j].x(), ml * A.y() + l * P[j].y());
  }
  E[n] = pb.closed ? E[0] : q.back();
  std::vector<Rational_quadratic_bezier_2<K>> pieces;
  pieces.reserve(n);
  const typename K::Orientation_2 orient = K().orientation_2_object();
  // Coordinates near the top of the double range: centre + scale * p can overflow even though
  // the solver's normalised values are finite. A non-finite point must not reach the kernel's
  // predicates (EPICK's exact fallback cannot represent it; found by fuzzing). And point(t) sums
  // the weighted control points before dividing by W(t) (Rational_quadratic_bezier_2): the
  // numerator is at most max(1, w) times the largest coordinate, so finite coordinates within a
  // factor 2 max(1, w) of DBL_MAX still gave an infinite point of the piece (fuzz finding
  // regress-overflow-point-near-dbl-max: x = -DBL_MAX, w > 1). One check covers both: every
  // coordinate times `reach` >= 2 is finite.
  auto finite_within = [](const Point_2& p, double reach) {
    return std::isfinite(reach * CGAL::to_double(p.x())) && std::isfinite(reach * CGAL::to_double(p.y()));
  };
  // Finite control points can still have differences beyond double (coordinates of both signs
  // near DBL_MAX; fuzz finding huge-coordinates-derivative-*): then the derivative of the piece
  // overflows. Its hodograph has the control vectors 2w (P - E_j), 2w (E_{j+1} - P) over the
  // denominator, and the quotient rule multiplies differences by up to 2 max(w, 1/w)^2 more: refuse
  // unless every difference times 8 max(w, 1/w)^2 is finite, so that every derivative the piece
  // hands out (and its evaluation) stays finite.
  auto differences_finite = [](const Point_2& a, const Point_2& b, double factor) {
    const double dx = CGAL::to_double(b.x()) - CGAL::to_double(a.x());
    const double dy = CGAL::to_double(b.y()) - CGAL::to_double(a.y());
    return std::isfinite(factor * dx) && std::isfinite(factor * dy);
  };
  for (std::size_t j = 0; j < n; ++j) {
    const double w = st.w[j];
    const double spread = (std::isfinite(w) && w > 0) ? std::max(w, 1 / w) : 1.0;
    const double factor = 8 * spread * spread;
    const double reach = 2 * std::max(1.0, spread);
    if (!finite_within(P[j], reach) || !finite_within(E[j], reach) || !finite_within(E[j + 1], reach) ||
        !differences_finite(E[j], P[j], factor) ||
        !differences_finite(P[j], E[j + 1], factor) || !differences_finite(E[j], E[j + 1], factor)) {
      const Point_2& Q = q[pb.point_index(j)];
      throw Invalid_input_error(message("Kappa_curve_2: the control points of the piece through point ",
                                        pb.point_index(j), " = (", CGAL::to_double(Q.x()), ", ", CGAL::to_double(Q.y()),
                                        ") or their differences (its derivatives) overflow double; scale the input down"));
    }
  }
  for (std::size_t j = 0; j < n; ++j) {
    const double w = st.w[j];
    if (!(std::isfinite(w) && w > 0) || E[j] == E[j + 1] || orient(E[j], P[j], E[j + 1]) == CGAL::COLLINEAR) {
      const Point_2& Q = q[pb.point_index(j)];
      throw Invalid_input_error(message(
          "Kappa_curve_2: the piece through point ", pb.point_index(j), " = (", CGAL::to_double(Q.x()), ", ",
          CGAL::to_double(Q.y()), ") degenerates to a straight segment (its control points are ",
          "collinear); the input is locally collinear"));
    }
    pieces.emplace_back(E[j], P[j], E[j + 1], FT(w));
  }
  return pieces;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_PIECES_H
