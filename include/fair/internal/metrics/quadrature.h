// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Globally adaptive Gauss-Kronrod (7/15 points) quadrature in double, the one adaptive
// quadrature of the library (fairness metrics, arc lengths of the sampler); its options and
// result are the public types of fair/Quadrature.h. The 15-point Kronrod rule integrates
// polynomials of degree <= 22 exactly; the error of a subinterval is estimated by |K15 - G7|
// (the embedded 7-point Gauss rule). This estimate
// is conservative for smooth integrands (the Kronrod value is usually far more accurate than
// the Gauss value it is compared with) but it is not a rigorous bound: an integrand with
// features narrower than the initial subintervals can be missed.

#ifndef FAIR_INTERNAL_METRICS_QUADRATURE_H
#define FAIR_INTERNAL_METRICS_QUADRATURE_H

#include <fair/Errors.h>
#include <fair/Quadrature.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace metrics {

/// Bisections between two exact re-summations of the value and error totals: the running totals
/// are updated by differences, whose rounding would otherwise drift over thousands of steps.
constexpr std::size_t quadrature_resum_period = 64;

struct Gk_interval {
  double a, b, kronrod, error;
  bool operator<(const Gk_interval& o) const { return error < o.error; }
};

/// One 7/15 Gauss-Kronrod step on [a,b]. Throws Precondition_error if f is not finite at a node.
template <class F>
Gk_interval gauss_kronrod_15(F& f, double a, double b, const char* what) {
  // Nodes and weights of the 15-point Kronrod extension of the 7-point Gauss-Legendre rule.
  static const double xk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                               0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                               0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                               0.207784955007898467600689403773245, 0.0};
  static const double wk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                               0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                               0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                               0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
  static const double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                               0.381830050505118944950369775488975, 0.417959183673469387755102040816327};
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  double k = 0, g = 0;
  for (int j = 0; j < 8; ++j) {
    const double x1 = c - h * xk[j];
    const double f1 = f(x1);
    const double f2 = (j == 7) ? 0.0 : f(c + h * xk[j]);
    if (!std::isfinite(f1) || !std::isfinite(f2))
      throw Precondition_error(message(what, ": the integrand is not finite near t = ", x1,
                                       " (a singular point of the curve, c'(t) = 0?)"));
    k += wk[j] * (f1 + f2);
    if (j % 2 == 1) g += wg[j / 2] * (f1 + f2);
  }
  return Gk_interval{a, b, k * h, std::fabs((k - g) * h)};
}

/// int_a^b f(t) dt by globally adaptive Gauss-Kronrod: the subinterval with the largest error
/// estimate is bisected until the total estimate meets the tolerance of `options`.
/// \throws Non_convergence_error when options.max_subintervals is reached first.
template <class F>
Quadrature_estimate adaptive_integral(F f, double a, double b, const Quadrature_options& options, const char* what) {
  // A binary max-heap on the error, kept in a vector (std::push_heap / pop_heap) so that the
  // re-summation below is one linear pass: copying and popping a priority_queue cost
  // O(n log n) per re-summation, most of the time of a run that ends at the cap (a fuzz input,
  // a near-circle whose curvature variation is rounding noise: issue 29).
  // It grows as needed: most integrals need a few subintervals, and reserving for the cap (2 MB)
  // on every call made the allocation most of the time of a metrics run under the sanitizers.
  std::vector<Gk_interval> heap;
  const auto push = [&heap](const Gk_interval& g) {
    heap.push_back(g);
    std::push_heap(heap.begin(), heap.end());
  };
  Quadrature_estimate out;
  const std::size_t m = std::max<std::size_t>(1, options.initial_subintervals);
  double value = 0, error = 0;
  for (std::size_t i = 0; i < m; ++i) {
    const double lo = a + (b - a) * double(i) / double(m), hi = (i + 1 == m) ? b : a + (b - a) * double(i + 1) / double(m);
    push(gauss_kronrod_15(f, lo, hi, what));
  }
  std::size_t count = m;
  auto totals = [&]() {
    // Re-sum from the heap contents to avoid drift from repeated add/subtract.
    value = 0;
    error = 0;
    for (const Gk_interval& g : heap) {
      value += g.kronrod;
      error += g.error;
    }
  };
  totals();
  std::size_t since_resum = 0;
  while (error > std::max(options.absolute_tolerance, options.relative_tolerance * std::fabs(value))) {
    if (count >= options.max_subintervals)
      throw Non_convergence_error(message(what, ": adaptive quadrature reached ", count,
                                          " subintervals with error estimate ", error, " for value ", value),
                                  count, error);
    std::pop_heap(heap.begin(), heap.end());
    const Gk_interval worst = heap.back();
    heap.pop_back();
    const double mid = 0.5 * (worst.a + worst.b);
    if (!(worst.a < mid && mid < worst.b)) { // interval at machine resolution: cannot refine
      push(worst);
      break;
    }
    const Gk_interval l = gauss_kronrod_15(f, worst.a, mid, what), r = gauss_kronrod_15(f, mid, worst.b, what);
    push(l);
    push(r);
    ++count;
    value += l.kronrod + r.kronrod - worst.kronrod;
    error += l.error + r.error - worst.error;
    if (++since_resum == quadrature_resum_period) {
      totals();
      since_resum = 0;
    }
  }
  totals();
  out.value = value;
  out.error_bound = error;
  out.subintervals = count;
  out.evaluations = 15 * (m + 2 * (count - m));
  return out;
}

} // namespace metrics
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_METRICS_QUADRATURE_H
