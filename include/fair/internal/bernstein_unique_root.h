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
// control polygon with the axis. The final bracket [lower, upper] is CERTIFIED: the sign of p at
// each end is proven by evaluating de Casteljau in CGAL::Interval_nt<false> (outward rounding
// under CGAL::Protect_FPU_rounding<true>), falling back to exact Gmpq evaluation at a point where
// the interval result contains 0. p(lower) and p(upper) have opposite signs (or one is exactly
// 0, and then lower == upper), so the unique root lies in [lower, upper].
//
// Accuracy. The bracket is first grown from the Newton iterate by doubling steps until the
// interval signs are certain; it is then shrunk by bisection (exact fallback where needed) until
// it is at most 8 ulps wide. So upper - lower <= 8 ulp(upper) always, and typically 1-2 ulps
// for a well-conditioned root (exact evaluation is needed only within about
// n * eps * max|b_i| / |p'(root)| of the root).

#ifndef FAIR_INTERNAL_BERNSTEIN_UNIQUE_ROOT_H
#define FAIR_INTERNAL_BERNSTEIN_UNIQUE_ROOT_H

#include <fair/Errors.h>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace fair {

/// Result of certified_unique_root.
struct Unique_root {
  enum Status {
    UNIQUE_ROOT, ///< exactly one distinct root in [0,1]; it lies in [lower, upper]
    NO_ROOT,     ///< certainly no root in [0,1]
    UNDECIDED    ///< the coefficients do not prove 0 or 1 roots: use Bernstein_root_isolation
  };
  Status status = UNDECIDED;
  double root = 0;   ///< for UNIQUE_ROOT: a point of [lower, upper]
  double lower = 0;  ///< certified bracket (lower == upper == root when the root is exact)
  double upper = 0;
  int sign_variations = 0;          ///< of the coefficient sequence, zeros skipped
  bool used_exact_fallback = false; ///< whether some sign needed exact Gmpq evaluation
};

namespace internal {

constexpr std::size_t unique_root_stack_coefficients = 32;

/// Interval enclosure of p(x) by de Casteljau; the caller must hold a
/// CGAL::Protect_FPU_rounding<true>. `work` has room for m values.
inline CGAL::Interval_nt<false> interval_de_casteljau(const double* b, std::size_t m, double x,
                                                      CGAL::Interval_nt<false>* work) {
  typedef CGAL::Interval_nt<false> I;
  const I t(x), s = I(1) - t;
  for (std::size_t i = 0; i < m; ++i) work[i] = I(b[i]);
  for (std::size_t r = 1; r < m; ++r)
    for (std::size_t i = 0; i + r < m; ++i) work[i] = s * work[i] + t * work[i + 1];
  return work[0];
}

/// Exact sign of p(x) (Gmpq de Casteljau; the double x is an exact rational).
inline int exact_sign_de_casteljau(const double* b, std::size_t m, double x) {
  const CGAL::Gmpq t(x), s = CGAL::Gmpq(1) - t;
  std::vector<CGAL::Gmpq> w(b, b + m);
  for (std::size_t r = 1; r < m; ++r)
    for (std::size_t i = 0; i + r < m; ++i) w[i] = s * w[i] + t * w[i + 1];
  return CGAL::sign(w[0]);
}

/// Certified sign of p(x): interval filter, exact fallback. Requires rounding protection.
inline int certified_sign(const double* b, std::size_t m, double x, CGAL::Interval_nt<false>* work,
                          bool& used_exact) {
  const CGAL::Interval_nt<false> v = interval_de_casteljau(b, m, x, work);
  if (v.inf() > 0) return 1;
  if (v.sup() < 0) return -1;
  if (v.inf() == 0 && v.sup() == 0) return 0;
  used_exact = true;
  return exact_sign_de_casteljau(b, m, x);
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

/// The core routine on m = degree + 1 coefficients b[0..m-1].
inline Unique_root certified_unique_root(const double* b, std::size_t m) {
  require(m >= 1, "certified_unique_root: no coefficients");
  Unique_root out;
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
      out.status = Unique_root::UNIQUE_ROOT;
      out.root = out.lower = out.upper = zero_at_0 ? 0.0 : 1.0;
    }
    return out;
  }
  if (out.sign_variations == 0) { out.status = Unique_root::NO_ROOT; return out; }
  if (out.sign_variations != 1) return out;
  out.status = Unique_root::UNIQUE_ROOT;

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

  const int s0 = sign_of(b[0]);
  // Start at the crossing of the control polygon with the axis.
  double t = 0.5;
  {
    std::size_t j = 0; // last nonzero coefficient with sign s0
    for (std::size_t i = 1; i <= n; ++i) {
      const int s = sign_of(b[i]);
      if (s == s0) j = i;
      else if (s == -s0) {
        t = (double(j) + b[j] / (b[j] - b[i]) * double(i - j)) / double(n);
        break;
      }
    }
    if (!(t > 0 && t < 1)) t = 0.5;
  }
  // Safeguarded Newton in double; the bracket [lo, hi] is only a guide here.
  double lo = 0, hi = 1;
  for (int it = 0; it < 100; ++it) {
    double f, df;
    double_de_casteljau(b, m, t, wd, f, df);
    if (f == 0) break;
    if (sign_of(f) == s0) lo = t; else hi = t;
    double tn = t - f / df;
    if (!(tn > lo && tn < hi)) tn = 0.5 * (lo + hi);
    const double step = std::fabs(tn - t);
    t = tn;
    if (step <= 2 * std::numeric_limits<double>::epsilon() * t || hi - lo <= std::numeric_limits<double>::min()) break;
  }

  // Certification.
  CGAL::Protect_FPU_rounding<true> protect;
  bool exact = false;
  double L = 0, H = 1; // certified: sign(p(L)) = s0, sign(p(H)) = -s0 (true at 0 and 1)
  bool haveL = false, haveH = false;
  auto classify = [&](double x, int s) -> bool { // returns true if x is an exact root
    if (s == 0) { out.root = out.lower = out.upper = x; return true; }
    if (s == s0) { if (x > L || !haveL) { L = x; haveL = true; } }
    else { if (x < H || !haveH) { H = x; haveH = true; } }
    return false;
  };
  {
    const CGAL::Interval_nt<false> v = interval_de_casteljau(b, m, t, wi);
    if (v.inf() > 0 || v.sup() < 0) classify(t, v.inf() > 0 ? 1 : -1);
    else if (v.inf() == 0 && v.sup() == 0) { classify(t, 0); out.used_exact_fallback = exact; return out; }
  }
  // Grow to each side that is still missing, by doubling steps (interval signs only; the ends
  // 0 and 1 are exact, so this terminates).
  for (int side = 0; side < 2; ++side) {
    bool& have = side == 0 ? haveL : haveH;
    if (have) continue;
    // The missing end is on the side where p has the required sign. Below the root p has sign
    // s0, so L is searched downwards from t and H upwards.
    double d = std::fabs(t) * std::numeric_limits<double>::epsilon();
    if (d < std::numeric_limits<double>::denorm_min()) d = std::numeric_limits<double>::denorm_min();
    for (int k = 0; k < 2200 && !have; ++k, d *= 2) {
      double x = side == 0 ? t - d : t + d;
      if (x <= 0) x = 0;
      if (x >= 1) x = 1;
      const CGAL::Interval_nt<false> v = interval_de_casteljau(b, m, x, wi);
      if (v.inf() > 0 || v.sup() < 0) classify(x, v.inf() > 0 ? 1 : -1);
      else if (v.inf() == 0 && v.sup() == 0) { classify(x, 0); out.used_exact_fallback = exact; return out; }
      if (x == 0 || x == 1) break;
    }
  }
  // Shrink to at most 8 ulps by bisection with exact fallback.
  for (int k = 0; k < 2200; ++k) {
    const double ulp = std::nextafter(H, 2.0) - H;
    if (H - L <= 8 * ulp) break;
    const double mid = L + (H - L) / 2;
    if (!(mid > L && mid < H)) break;
    if (classify(mid, certified_sign(b, m, mid, wi, exact))) { out.used_exact_fallback = exact; return out; }
  }
  out.lower = L;
  out.upper = H;
  out.root = t < L ? L : (t > H ? H : t);
  out.used_exact_fallback = exact;
  return out;
}

/// Fixed-size overload (no heap allocation for N <= 32).
template <std::size_t N>
Unique_root certified_unique_root(const std::array<double, N>& b) {
  static_assert(N >= 1, "certified_unique_root: at least one coefficient");
  return certified_unique_root(b.data(), N);
}

} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_BERNSTEIN_UNIQUE_ROOT_H
