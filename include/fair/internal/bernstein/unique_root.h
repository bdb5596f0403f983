// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fast certified root of a double Bernstein polynomial with exactly one sign change (the
// situation of eq. (7) of Yan, Schiller, Schaefer, "kappa-curves", whose Appendix A proves the
// coefficient sequence has one sign change). No heap allocation for up to 32 coefficients.
//
// Certificate. The coefficients are exact doubles, so their signs, and hence the sign variation
// count V, are exact. Descartes' rule in Bernstein form: V = 1 with b_0, b_n != 0 proves exactly
// one root in (0,1), and it is simple. The root is then approximated by Newton's method in
// double, safeguarded by bisection of a (heuristic) bracket, starting from the crossing of the
// control polygon with the axis, and stopped at the rounding noise. The final bracket
// [lower, upper] is CERTIFIED: the sign of p at each end is proven by evaluating de Casteljau in
// CGAL::Interval_nt<false> (outward rounding under CGAL::Protect_FPU_rounding<true>), falling
// back to exact evaluation in GMP integers (the double point is dyadic) where the interval
// result contains 0. p(lower) and p(upper) have opposite signs (or p is exactly 0 at one point,
// and then lower == upper), so the unique root lies in [lower, upper].
//
// Accuracy. The bracket is first grown from the Newton iterate by geometric steps (factor 1.5
// from one ulp) until the interval signs are certain; it is then shrunk by bisection, with the
// exact fallback where needed, to at most max_ulps ulps of its upper end (default 8; 1 gives
// adjacent doubles). On eq. (7) the default bracket is 3.8 ulps wide on average and needs no
// exact evaluation; exact evaluation is needed only within about n eps max|b_i| / |p'(root)|
// of the root.

#ifndef FAIR_INTERNAL_BERNSTEIN_UNIQUE_ROOT_H
#define FAIR_INTERNAL_BERNSTEIN_UNIQUE_ROOT_H

#include <fair/Errors.h>
#include <fair/internal/bernstein/dyadic.h>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {
namespace internal {
namespace bernstein {

/// Coefficient count up to which the work arrays live on the stack (no heap allocation).
constexpr std::size_t unique_root_stack_coefficients = 32;

/// Newton iterations of tighten_double_bracket: from the control polygon's crossing a handful
/// suffice (quadratic convergence, a bisection step whenever Newton leaves the bracket); the cap
/// only bounds an iteration that wanders in the rounding noise.
constexpr int max_newton_iterations = 100;

/// Newton stops once |p(t)| is below this fraction of n eps max|b_i| (the rounding noise of a
/// double de Casteljau evaluation of degree n - 1 is a small multiple of that bound).
constexpr double newton_noise_fraction = 0.25;

/// Growth factor of the steps that grow the certified bracket from one ulp: slower than
/// doubling, so the bracket rarely overshoots 8 ulps and needs exact bisection.
constexpr double bracket_growth_factor = 1.5;

/// Steps of bracket growth and of bisection: 1.5^k times the smallest subnormal reaches 1 after
/// fewer than 1840 steps, and halving [0, 1] reaches adjacent doubles after fewer than 1100, so
/// the cap is never the reason a loop ends.
constexpr int max_bracket_steps = 2200;

/// Interval enclosure of p(x) for interval coefficients c; needs rounding protection.
inline CGAL::Interval_nt<false> interval_de_casteljau(const CGAL::Interval_nt<false>* c, std::size_t m, double x,
                                                      CGAL::Interval_nt<false>* work) {
  typedef CGAL::Interval_nt<false> I;
  const I t(x), s = I(1) - t;
  for (std::size_t i = 0; i < m; ++i) work[i] = c[i];
  for (std::size_t r = 1; r < m; ++r)
    for (std::size_t i = 0; i + r < m; ++i) work[i] = s * work[i] + t * work[i + 1];
  return work[0];
}

/// p(t) and p'(t) in double by de Casteljau (round to nearest).
inline void double_de_casteljau(const double* b, std::size_t m, double t, double* work, double& f, double& df) {
  const double s = 1 - t;
  for (std::size_t i = 0; i < m; ++i) work[i] = b[i];
  for (std::size_t r = 1; r + 1 < m; ++r)
    for (std::size_t i = 0; i + r < m; ++i) work[i] = s * work[i] + t * work[i + 1];
  if (m == 1) { f = work[0]; df = 0; return; }
  f = s * work[0] + t * work[1];
  df = double(m - 1) * (work[1] - work[0]);
}

inline int sign_of(double x) { return (x > 0) - (x < 0); }

/// Result of tighten_double_bracket.
struct Double_bracket {
  double lower, upper, root;
  bool exact_root;  // lower == upper == root is the root
  bool used_exact;  // some sign needed the exact fallback
};

/// Certified tightening of a double bracket around the unique root of a polynomial.
///
/// Precondition: on the open interval (L, H) the polynomial p (of degree m-1) has exactly one
/// root, a simple one, with sign `s_low` on (L, root) and -s_low on (root, H). `c` holds
/// intervals enclosing the exact Bernstein coefficients of p on [0,1] (point intervals for
/// double input) and `approx` double approximations of them (used only by Newton). `exact_sign`
/// is called as exact_sign(x) -> int for a double x where the interval filter is inconclusive.
///
/// Method: safeguarded Newton in double from `start`, then a certified bracket grown from the
/// Newton iterate by geometric steps (interval signs), then shrunk by bisection (exact fallback)
/// to at most `max_ulps` ulps (of its upper end; 1 means adjacent doubles). The returned
/// [lower, upper] is inside [L, H] and contains the root.
/// Must be called in round-to-nearest mode; protects the rounding mode itself.
template <class ExactSign>
Double_bracket tighten_double_bracket(const CGAL::Interval_nt<false>* c, const double* approx, std::size_t m,
                                      double L, double H, int s_low, double start, ExactSign exact_sign,
                                      double max_ulps = 8) {
  Double_bracket out{L, H, start, false, false};
  double stack_d[unique_root_stack_coefficients];
  CGAL::Interval_nt<false> stack_i[unique_root_stack_coefficients];
  std::vector<double> heap_d;
  std::vector<CGAL::Interval_nt<false>> heap_i;
  double* wd = stack_d;
  CGAL::Interval_nt<false>* wi = stack_i;
  if (m > unique_root_stack_coefficients) {
    heap_d.resize(m);
    heap_i.resize(m);
    wd = heap_d.data();
    wi = heap_i.data();
  }
  // Safeguarded Newton in double; [lo, hi] is only a guide here.
  double t = (start > L && start < H) ? start : L + (H - L) / 2;
  if (!(t > L && t < H)) return out; // no double strictly inside: [L, H] is already minimal
  // Stop at the rounding noise of the double evaluation (a fraction of n eps max|b_i|): further
  // iterates only wander inside the region where no floating-point sign is reliable.
  double lo = L, hi = H;
  double noise = 0;
  for (std::size_t i = 0; i < m; ++i) noise = std::max(noise, std::fabs(approx[i]));
  noise *= newton_noise_fraction * double(m) * std::numeric_limits<double>::epsilon();
  for (int it = 0; it < max_newton_iterations; ++it) {
    double f, df;
    double_de_casteljau(approx, m, t, wd, f, df);
    if (std::fabs(f) <= noise) break;
    if (sign_of(f) == s_low) lo = t; else hi = t;
    double tn = t - f / df;
    if (!(tn > lo && tn < hi)) tn = lo + (hi - lo) / 2;
    const double step = std::fabs(tn - t);
    if (!(tn > L && tn < H)) break;
    t = tn;
    if (step <= 2 * std::numeric_limits<double>::epsilon() * std::fabs(t) || !(hi - lo > 0)) break;
  }

  CGAL::Protect_FPU_rounding<true> protect;
  double A = L, B = H; // certified: the root is in (A, B)
  // Records the certified sign s of p at x in (L, H); returns true if x is the root.
  auto classify = [&](double x, int s) -> bool {
    if (s == 0) { out.lower = out.upper = out.root = x; out.exact_root = true; return true; }
    if (s == s_low) { if (x > A) A = x; }
    else if (x < B) B = x;
    return false;
  };
  auto interval_sign = [&](double x, int& s) -> bool { // false if inconclusive
    const CGAL::Interval_nt<false> v = interval_de_casteljau(c, m, x, wi);
    if (v.inf() > 0) { s = 1; return true; }
    if (v.sup() < 0) { s = -1; return true; }
    if (v.inf() == 0 && v.sup() == 0) { s = 0; return true; }
    return false;
  };
  int s;
  if (interval_sign(t, s) && classify(t, s)) return out;
  // Grow a certified end on each side of t by steps growing from one ulp by
  // bracket_growth_factor, interval signs only; reaching L or H ends the search (their sides
  // are known).
  for (int side = 0; side < 2; ++side) {
    double d = std::fabs(t) * std::numeric_limits<double>::epsilon();
    if (d < std::numeric_limits<double>::denorm_min()) d = std::numeric_limits<double>::denorm_min();
    for (int k = 0; k < max_bracket_steps; ++k, d *= bracket_growth_factor) {
      if (side == 0 ? A >= t : B <= t) break; // this side is certified already
      const double x = side == 0 ? t - d : t + d;
      if (side == 0 ? x <= A : x >= B) break;
      if (interval_sign(x, s) && classify(x, s)) return out;
    }
  }
  // Shrink to at most max_ulps ulps by bisection, exact fallback where the interval is
  // inconclusive.
  for (int k = 0; k < max_bracket_steps; ++k) {
    const double ulp = std::nextafter(B, std::numeric_limits<double>::infinity()) - B;
    if (B - A <= max_ulps * ulp) break;
    const double mid = A + (B - A) / 2;
    if (!(mid > A && mid < B)) break;
    if (!interval_sign(mid, s)) {
      out.used_exact = true;
      s = exact_sign(mid);
    }
    if (classify(mid, s)) return out;
  }
  out.lower = A;
  out.upper = B;
  out.root = t < A ? A : (t > B ? B : t);
  return out;
}

/// The core routine on m = degree + 1 coefficients b[0..m-1]. The certified bracket is at most
/// `max_ulps` ulps wide (>= 1; 1 asks for adjacent doubles, at the price of more exact
/// evaluations near the root). `Result` is fair::Unique_root: a template parameter, so that its
/// one declaration stays in Bernstein_root_isolation.h, which includes this file.
template <class Result>
Result certified_unique_root(const double* b, std::size_t m, double max_ulps = 8) {
  require(m >= 1, "certified_unique_root: no coefficients");
  require(max_ulps >= 1, "certified_unique_root: max_ulps = ", max_ulps, " must be >= 1");
  Result out;
  bool all_zero = true;
  int last = 0;
  for (std::size_t i = 0; i < m; ++i) {
    if (!std::isfinite(b[i]))
      throw Precondition_error(message("certified_unique_root: coefficient ", i, " = ", b[i], " is not finite"));
    const int s = sign_of(b[i]);
    if (s != 0) {
      all_zero = false;
      if (last != 0 && s != last) ++out.sign_variations;
      last = s;
    }
  }
  require(!all_zero, "certified_unique_root: the zero polynomial has no isolated root");
  const std::size_t n = m - 1;
  const bool zero_at_0 = b[0] == 0, zero_at_1 = b[n] == 0;
  if (zero_at_0 || zero_at_1) {
    // Roots at the end points are exact; the variation count bounds the roots in (0,1).
    if (out.sign_variations == 0 && zero_at_0 != zero_at_1) {
      out.status = Result::UNIQUE_ROOT;
      out.root = out.lower = out.upper = zero_at_0 ? 0.0 : 1.0;
    }
    return out;
  }
  if (out.sign_variations == 0) { out.status = Result::NO_ROOT; return out; }
  if (out.sign_variations != 1) return out;
  out.status = Result::UNIQUE_ROOT;

  const int s0 = sign_of(b[0]);
  // Start at the crossing of the control polygon with the axis.
  double t = 0.5;
  {
    std::size_t j = 0; // last coefficient with sign s0 before the change
    for (std::size_t i = 1; i <= n; ++i) {
      const int s = sign_of(b[i]);
      if (s == s0) j = i;
      else if (s == -s0) {
        t = (double(j) + b[j] / (b[j] - b[i]) * double(i - j)) / double(n);
        break;
      }
    }
  }
  CGAL::Interval_nt<false> stack_c[unique_root_stack_coefficients];
  std::vector<CGAL::Interval_nt<false>> heap_c;
  CGAL::Interval_nt<false>* c = stack_c;
  if (m > unique_root_stack_coefficients) {
    heap_c.resize(m);
    c = heap_c.data();
  }
  for (std::size_t i = 0; i < m; ++i) c[i] = CGAL::Interval_nt<false>(b[i]);
  // Exact fallback: integer-scaled coefficients, built on first use only.
  Mpz_array B, work;
  auto exact_sign = [&](double x) {
    if (B.size() == 0) {
      B = integer_scaled(b, m);
      work = Mpz_array(m + 3);
    }
    unsigned long e = 0;
    dyadic_parts(x, work[m + 2], e);
    return sign_bernstein_at_dyadic(B, work[m + 2], e, work);
  };
  const Double_bracket r = tighten_double_bracket(c, b, m, 0.0, 1.0, s0, t, exact_sign, max_ulps);
  out.lower = r.lower;
  out.upper = r.upper;
  out.root = r.root;
  out.used_exact_fallback = r.used_exact;
  return out;
}

} // namespace bernstein
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_BERNSTEIN_UNIQUE_ROOT_H
