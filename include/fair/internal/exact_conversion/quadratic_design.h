// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Quadratic design from a sparse polygon (Karciauskas-Peters Sec. 7, eq. 12, Figs. 16, 19).
// f_i is the quadratic interpolating q_{i-1}, q_i, q_{i+1} at t_{i-1}, t_i, t_{i+1};
// h_i = t_{i+1} - t_i, beta_i = h_i / h_{i-1}. Restricted to [t_i, t_{i+1}] its middle Bezier
// coefficient is f_i(t_i) + (h_i/2) f_i'(t_i) with (Lagrange, differentiated at t_i)
//   f_i'(t_i) = -h_i/(h_{i-1}(h_{i-1}+h_i)) q_{i-1} + (h_i-h_{i-1})/(h_{i-1}h_i) q_i + h_{i-1}/(h_i(h_{i-1}+h_i)) q_{i+1},
// so m_i^L = 1/2 ( -beta_i^2/(1+beta_i) q_{i-1} + (1+beta_i) q_i + 1/(1+beta_i) q_{i+1} )   (as printed);
// f_{i+1} restricted to [t_i, t_{i+1}] has middle coefficient f_{i+1}(t_{i+1}) - (h_i/2) f_{i+1}'(t_{i+1}),
// the mirror image with beta' = h_i/h_{i+1} = 1/beta_{i+1}:
//   m_i^R = 1/2 ( -1/(beta_{i+1}^2+beta_{i+1}) q_{i+2} + (1+beta_{i+1})/beta_{i+1} q_{i+1} + beta_{i+1}/(1+beta_{i+1}) q_i )  (as printed).
// m_i = mu_{i+1} m_i^L + (1 - mu_{i+1}) m_i^R (eq. 12), mu_{i+1} = kappa_{i+1}/(kappa_i + kappa_{i+1}) (eq. 6),
// 1/2 when kappa_i + kappa_{i+1} <= epsilon; kappa_i = |curvature of f_i at t_i| (double).

#ifndef FAIR_INTERNAL_EXACT_CONVERSION_QUADRATIC_DESIGN_H
#define FAIR_INTERNAL_EXACT_CONVERSION_QUADRATIC_DESIGN_H

#include <fair/Bezier_2.h>
#include <fair/Errors.h>
#include <fair/internal/common/combination.h>
#include <fair/internal/common/curvature.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace exact_conversion {

/// m_i^L from q_{i-1}, q_i, q_{i+1} and beta_i = h_i / h_{i-1}.
template <class K>
typename K::Point_2 middle_left(const typename K::Point_2& qm, const typename K::Point_2& q0, const typename K::Point_2& qp,
                                const typename K::FT& beta) {
  typedef typename K::FT FT;
  const FT half(FT(1) / FT(2));
  return common::combine<K>(-half * beta * beta / (FT(1) + beta), qm, half * (FT(1) + beta), q0, half / (FT(1) + beta), qp);
}

/// m_i^R from q_i, q_{i+1}, q_{i+2} and beta_{i+1} = h_{i+1} / h_i.
template <class K>
typename K::Point_2 middle_right(const typename K::Point_2& q0, const typename K::Point_2& qp, const typename K::Point_2& qpp,
                                 const typename K::FT& beta) {
  typedef typename K::FT FT;
  const FT half(FT(1) / FT(2));
  return common::combine<K>(-half / (beta * beta + beta), qpp, half * (FT(1) + beta) / beta, qp, half * beta / (FT(1) + beta), q0);
}

/// |curvature| at t_i of the quadratic through q_{i-1}, q_i, q_{i+1} at t_i - hm, t_i, t_i + hp (double).
/// \throws Invalid_input_error where its tangent vanishes.
template <class K>
double local_quadratic_curvature(const typename K::Point_2& qm, const typename K::Point_2& q0, const typename K::Point_2& qp,
                                 const typename K::FT& hm, const typename K::FT& hp, std::size_t i, const char* fn) {
  const double a = CGAL::to_double(hm), b = CGAL::to_double(hp);
  const double ax = CGAL::to_double(q0.x() - qm.x()) / a, ay = CGAL::to_double(q0.y() - qm.y()) / a; // [q_{i-1}, q_i]
  const double bx = CGAL::to_double(qp.x() - q0.x()) / b, by = CGAL::to_double(qp.y() - q0.y()) / b; // [q_i, q_{i+1}]
  const double d1x = (b * ax + a * bx) / (a + b), d1y = (b * ay + a * by) / (a + b);                 // f'(t_i)
  const double d2x = 2 * (bx - ax) / (a + b), d2y = 2 * (by - ay) / (a + b);                         // f''
  if (!(std::hypot(d1x, d1y) > 0) || !std::isfinite(d1x + d1y + d2x + d2y))
    throw Invalid_input_error(message(fn, ": the local quadratic at point ", i, " has tangent (", d1x, ", ", d1y,
                                      ") there; its curvature is undefined"));
  return std::fabs(common::signed_curvature(d1x, d1y, d2x, d2y));
}

/// eq. 6: kappa_b / (kappa_a + kappa_b), 1/2 when the sum is <= epsilon.
inline double curvature_weight(double kappa_a, double kappa_b, double epsilon) {
  return kappa_a + kappa_b > epsilon ? kappa_b / (kappa_a + kappa_b) : 0.5;
}

/// The shapes {q_i, m_i, q_{i+1}} from the knot intervals h (n-1 open, n closed). Open ends are
/// one-sided: the first segment has only m_0^R, the last only m_{n-2}^L (two points: the midpoint).
template <class K>
std::vector<Bezier_2<K>> quadratic_shapes(const std::vector<typename K::Point_2>& q, const std::vector<typename K::FT>& h,
                                          bool closed, double epsilon, const char* fn) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  const std::size_t n = q.size(), segments = closed ? n : n - 1;
  auto Q = [&](std::size_t i) -> const Point_2& { return q[i % n]; };
  auto H = [&](std::size_t i) -> const FT& { return h[i % segments]; };
  // kappa_i for every point with two neighbours (index i + n to stay unsigned)
  std::vector<double> kappa(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    if (closed || (i > 0 && i + 1 < n))
      kappa[i] = local_quadratic_curvature<K>(Q(i + n - 1), Q(i), Q(i + 1), H(i + segments - 1), H(i), i, fn);
  std::vector<Bezier_2<K>> out;
  for (std::size_t i = 0; i < segments; ++i) {
    const bool has_left = closed || i >= 1, has_right = closed || i + 2 < n;
    Point_2 m;
    if (has_left && has_right) {
      const Point_2 L = middle_left<K>(Q(i + n - 1), Q(i), Q(i + 1), H(i) / H(i + segments - 1));
      const Point_2 R = middle_right<K>(Q(i), Q(i + 1), Q(i + 2), H(i + 1) / H(i));
      const FT mu(curvature_weight(kappa[i], kappa[(i + 1) % n], epsilon));
      m = Point_2(mu * L.x() + (FT(1) - mu) * R.x(), mu * L.y() + (FT(1) - mu) * R.y());
    } else if (has_left) {
      m = middle_left<K>(Q(i + n - 1), Q(i), Q(i + 1), H(i) / H(i + segments - 1));
    } else if (has_right) {
      m = middle_right<K>(Q(i), Q(i + 1), Q(i + 2), H(i + 1) / H(i));
    } else {
      m = Point_2((Q(i).x() + Q(i + 1).x()) / FT(2), (Q(i).y() + Q(i + 1).y()) / FT(2));
    }
    out.push_back(Bezier_2<K>(std::vector<Point_2>{Q(i), m, Q(i + 1)}));
  }
  return out;
}

} // namespace exact_conversion
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_EXACT_CONVERSION_QUADRATIC_DESIGN_H
