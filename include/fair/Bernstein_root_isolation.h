// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Certified isolation of the real roots in [0,1] of a polynomial in Bernstein form.
//
// What is certified. The input coefficients are converted EXACTLY to rationals (a double, a
// CGAL::Gmpfr and a point CGAL::Interval_nt are dyadic rationals; CGAL::Gmpq and EPECK's FT are
// exact), and the statements below are about the polynomial with exactly those coefficients:
//  - every distinct root in [0,1] lies in exactly one returned interval and every interval holds
//    exactly one distinct root;
//  - an interval with lower == upper is the exact root (roots at 0, 1 and at dyadic subdivision
//    points are found exactly); otherwise the root is in the OPEN interval (lower, upper);
//  - intervals are sorted and pairwise disjoint; end points are exact CGAL::Gmpq (dyadic);
//  - multiplicity is exact.
// For a non-point CGAL::Interval_nt coefficient the root set is not one polynomial's, and the
// constructor throws Precondition_error.
//
// Method. Descartes / Vincent-Collins-Akritas bisection on Bernstein coefficients (see
// internal/bernstein/vca.h): interval-filtered subdivision with exact Gmpq fallback on the
// subintervals whose sign pattern is uncertain; a sign-variation count of 0 or 1 proves the
// count of roots in a subinterval. If the bisection reaches depth 30 (roots closer than about
// 1e-9, or a multiple root inside a subinterval), Yun's square-free factorisation over Q is
// computed; a square-free polynomial is then bisected further, otherwise its square-free part
// is isolated and each root's multiplicity is read off the factor that vanishes there.
// Fallback. The bisection of a square-free polynomial always terminates; a hard cap of 4000
// levels (roots closer than 2^-4000) throws Non_convergence_error rather than loop.
//
// Refinement. refine() bisects an interval with exact sign evaluation (an interval de Casteljau
// filter first, exact integer de Casteljau at the dyadic bisection point when the filter is
// inconclusive) until the requested width. root_approximation() shrinks the interval to two
// adjacent doubles by double Newton iteration and an interval-certified bracket (as
// certified_unique_root), then, if need be, by exact bisection until it lies within [d, next(d)]
// for a double d, which it returns: within one ulp of the root.

#ifndef FAIR_BERNSTEIN_ROOT_ISOLATION_H
#define FAIR_BERNSTEIN_ROOT_ISOLATION_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Errors.h>
#include <fair/internal/bernstein/dyadic.h>
#include <fair/internal/bernstein/exact.h>
#include <fair/internal/bernstein/unique_root.h>
#include <fair/internal/bernstein/vca.h>
#include <fair/internal/common/exact_conversion.h>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <utility>
#include <vector>

namespace fair {

/// An isolating interval of one distinct root. If `lower == upper` the root is exactly
/// `lower`; otherwise it lies in the open interval (lower, upper).
struct Isolating_interval {
  CGAL::Gmpq lower, upper;
  int multiplicity = 1;

  bool is_point() const { return lower == upper; }
  /// Whether the root could be x: x == lower for a point, lower < x < upper otherwise.
  bool may_contain(const CGAL::Gmpq& x) const { return is_point() ? x == lower : (lower < x && x < upper); }
  CGAL::Gmpq width() const { return upper - lower; }
  /// The midpoint, rounded to double (accurate to the interval width plus one ulp).
  double approximation() const { return CGAL::to_double((lower + upper) / 2); }

  friend std::ostream& operator<<(std::ostream& out, const Isolating_interval& I) {
    out << "[" << CGAL::to_double(I.lower) << ", " << CGAL::to_double(I.upper) << "]";
    if (I.multiplicity != 1) out << " x" << I.multiplicity;
    return out;
  }
};

/// The certified real roots in [0,1] of one Bernstein polynomial (see the file comment).
class Bernstein_root_isolation {
public:
  /// Isolates the roots of p in [0,1].
  /// \throws Precondition_error if p is the zero polynomial, has a non-finite coefficient or a
  /// non-point interval coefficient; Non_convergence_error if the depth cap is hit.
  template <class NT>
  explicit Bernstein_root_isolation(const Bernstein_polynomial<NT>& p)
    : p_(exact_coefficients(p.coefficients())) {
    const std::vector<CGAL::Gmpq>& E = p_.coefficients();
    bool zero = true;
    for (const CGAL::Gmpq& c : E) zero = zero && CGAL::is_zero(c);
    internal::require(!zero, "Bernstein_root_isolation: the zero polynomial (", p,
                      ") vanishes on all of [0,1]; it has no isolated roots");
    std::vector<internal::bernstein::Unprotected_interval> enclosure;
    enclosure.reserve(E.size());
    for (const NT& c : p.coefficients()) enclosure.push_back(internal::bernstein::Unprotected_interval(CGAL::to_interval(c)));
    isolate(std::move(enclosure));
  }

  /// Number of distinct roots in [0,1].
  std::size_t number_of_roots() const { return intervals_.size(); }
  /// Number of roots in [0,1] counted with multiplicity.
  std::size_t number_of_roots_with_multiplicity() const {
    std::size_t k = 0;
    for (const Isolating_interval& I : intervals_) k += static_cast<std::size_t>(I.multiplicity);
    return k;
  }
  const std::vector<Isolating_interval>& intervals() const { return intervals_; }
  const Isolating_interval& operator[](std::size_t i) const { return intervals_[i]; }
  /// The polynomial with the exact rational coefficients the certificates are about.
  const Bernstein_polynomial<CGAL::Gmpq>& polynomial() const { return p_; }
  /// Whether multiple roots forced the square-free factorisation.
  bool used_square_free_factorization() const { return used_square_free_; }

  /// Shrinks interval i by bisection until its width is <= width (width > 0). The root stays
  /// inside; if a bisection point is the root the interval becomes the point [root, root].
  void refine(std::size_t i, const CGAL::Gmpq& width) {
    internal::require(i < intervals_.size(), "Bernstein_root_isolation::refine: index ", i, " out of range (",
                      intervals_.size(), " roots)");
    internal::require(width > 0, "Bernstein_root_isolation::refine: width ", width, " must be positive");
    for (int step = 0; intervals_[i].upper - intervals_[i].lower > width; ++step) {
      if (step > max_refine_bisections)
        throw Non_convergence_error("Bernstein_root_isolation::refine: bisection cap", max_refine_bisections, 0.0);
      bisect(i);
    }
  }

  /// A double within one ulp of root i (refines interval i as needed). Double Newton with a
  /// certified bracket (interval signs, exact integer fallback) shrinks the interval to two
  /// adjacent doubles and the lower one is returned; otherwise the interval is split exactly at
  /// doubles until it is a point or lies within [d, next(d)], and d is returned.
  double root_approximation(std::size_t i) {
    internal::require(i < intervals_.size(), "Bernstein_root_isolation::root_approximation: index ", i,
                      " out of range (", intervals_.size(), " roots)");
    Isolating_interval& I = intervals_[i];
    if (I.is_point()) return CGAL::to_double(I.lower);
    tighten_in_double(i, 1);
    const double L = CGAL::to_double(I.lower), H = CGAL::to_double(I.upper);
    if (I.is_point()) return L;
    if (CGAL::Gmpq(L) == I.lower && CGAL::Gmpq(H) == I.upper && H <= std::nextafter(L, 2.0)) return L;
    // Exact splits at doubles: the double nearest the middle while one lies inside, else the one
    // just above the lower end. The interval ends when it is a point or lies within [d, next(d)]
    // (then d is returned). A split at the midpoint instead would never stop on a root that is
    // itself a double (0.25, 1) when the ends are not dyadic: they close in from both sides.
    for (int step = 0; !I.is_point(); ++step) {
      const double below = double_at_or_below(I.lower), above = std::nextafter(below, 2.0);
      if (CGAL::Gmpq(above) >= I.upper) return below;  // the root is in (lower, upper) within [below, above]
      if (step > max_approximation_bisections)
        throw Non_convergence_error("Bernstein_root_isolation::root_approximation: bisection cap",
                                    max_approximation_bisections, 0.0);
      CGAL::Gmpq m(CGAL::to_double((I.lower + I.upper) / 2));
      if (!(I.lower < m && m < I.upper)) m = CGAL::Gmpq(above);  // lower < above < upper
      split(i, m);
    }
    return CGAL::to_double(I.lower);
  }
  std::vector<double> root_approximations() {
    std::vector<double> out;
    for (std::size_t i = 0; i < intervals_.size(); ++i) out.push_back(root_approximation(i));
    return out;
  }

private:
  template <class NT>
  static std::vector<CGAL::Gmpq> exact_coefficients(const std::vector<NT>& c) {
    std::vector<CGAL::Gmpq> out;
    out.reserve(c.size());
    for (const NT& x : c) out.push_back(internal::common::to_gmpq(x, "Bernstein_root_isolation: coefficient"));
    return out;
  }

  void isolate(std::vector<internal::bernstein::Unprotected_interval> enclosure) {
    const std::vector<CGAL::Gmpq>& E = p_.coefficients();
    {
      internal::bernstein::Vca_isolator vca(E, true, std::move(enclosure));
      if (vca.run(square_free_depth)) return accept(E, vca.leaves());
    }
    used_square_free_ = true;
    const std::vector<internal::bernstein::Q_polynomial> factors =
        internal::bernstein::q_square_free_factorization(p_.to_power_basis());
    bool square_free = true;
    for (std::size_t k = 1; k < factors.size(); ++k) square_free = square_free && factors[k].size() <= 1;
    if (square_free) {
      internal::bernstein::Vca_isolator vca(E);
      if (!vca.run(hard_cap)) throw_cap();
      return accept(E, vca.leaves());
    }
    // Square-free part: the product of the factors (monic, so the product is exact).
    internal::bernstein::Q_polynomial sqf(1, CGAL::Gmpq(1));
    for (const internal::bernstein::Q_polynomial& f : factors) sqf = multiply(sqf, f);
    const std::vector<CGAL::Gmpq> S = Bernstein_polynomial<CGAL::Gmpq>::from_power_basis(sqf).coefficients();
    internal::bernstein::Vca_isolator vca(S);
    if (!vca.run(hard_cap)) throw_cap();
    std::vector<internal::bernstein::Isolation_leaf>& leaves = vca.leaves();
    for (internal::bernstein::Isolation_leaf& leaf : leaves) {
      leaf.multiplicity = 0;
      for (std::size_t k = 0; k < factors.size() && leaf.multiplicity == 0; ++k) {
        if (factors[k].size() <= 1) continue;
        if (vanishes_in(factors[k], leaf)) leaf.multiplicity = static_cast<int>(k + 1);
      }
      FAIR_ASSERT_MSG(leaf.multiplicity != 0, "Bernstein_root_isolation: no square-free factor of ", p_,
                      " vanishes in [", leaf.lower, ", ", leaf.upper, "]");
    }
    accept(S, leaves);
  }

  static internal::bernstein::Q_polynomial multiply(const internal::bernstein::Q_polynomial& a, const internal::bernstein::Q_polynomial& b) {
    internal::bernstein::Q_polynomial c(a.size() + b.size() - 1, CGAL::Gmpq(0));
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
    return c;
  }

  static CGAL::Gmpq horner(const internal::bernstein::Q_polynomial& a, const CGAL::Gmpq& x) {
    CGAL::Gmpq v(0);
    for (std::size_t k = a.size(); k-- > 0;) v = v * x + a[k];
    return v;
  }

  // A square-free factor f has at most one root, a simple one, in an isolating leaf (it divides
  // the square-free part); in the open case it has one iff the signs of f just inside the two
  // ends differ, read off the first and last nonzero Bernstein coefficients on [lower, upper].
  static bool vanishes_in(const internal::bernstein::Q_polynomial& f, const internal::bernstein::Isolation_leaf& leaf) {
    if (leaf.lower == leaf.upper) return CGAL::is_zero(horner(f, leaf.lower));
    const std::vector<CGAL::Gmpq> c =
        Bernstein_polynomial<CGAL::Gmpq>::from_power_basis(f).restricted(leaf.lower, leaf.upper).coefficients();
    int first = 0, last = 0;
    for (const CGAL::Gmpq& x : c)
      if (!CGAL::is_zero(x)) { first = CGAL::sign(x); break; }
    for (std::size_t k = c.size(); k-- > 0;)
      if (!CGAL::is_zero(c[k])) { last = CGAL::sign(c[k]); break; }
    return first != last;
  }

  void accept(const std::vector<CGAL::Gmpq>& witness, const std::vector<internal::bernstein::Isolation_leaf>& leaves) {
    witness_ = witness;
    witness_intervals_.clear();
    intervals_.clear();
    sign_after_lower_.clear();
    for (const internal::bernstein::Isolation_leaf& leaf : leaves) {
      Isolating_interval I;
      I.lower = leaf.lower;
      I.upper = leaf.upper;
      I.multiplicity = leaf.multiplicity;
      intervals_.push_back(I);
      sign_after_lower_.push_back(leaf.sign_after_lower);
    }
  }

  void throw_cap() const {
    throw Non_convergence_error(internal::message("Bernstein_root_isolation: subdivision depth cap ", hard_cap,
                                                  " reached for ", p_, " (roots closer than 2^-", hard_cap, ")"),
                                static_cast<std::size_t>(hard_cap), 0.0);
  }

  void prepare_witness() {
    if (!witness_intervals_.empty()) return;
    witness_intervals_ = internal::bernstein::to_intervals(witness_);
    witness_approx_.clear();
    for (const internal::bernstein::Unprotected_interval& c : witness_intervals_) witness_approx_.push_back(CGAL::to_double(c));
    witness_integer_ = internal::bernstein::integer_scaled(witness_);
    integer_work_ = internal::bernstein::Mpz_array(witness_.size() + 3);
    scratch_.resize(witness_.size());
  }

  // Sign of the witness at x in [0,1]: interval de Casteljau first, exact Horner if uncertain.
  int witness_sign(const CGAL::Gmpq& x) {
    prepare_witness();
    {
      CGAL::Protect_FPU_rounding<true> protect;
      const internal::bernstein::Unprotected_interval t(CGAL::to_interval(x));
      const internal::bernstein::Unprotected_interval s = internal::bernstein::Unprotected_interval(1) - t;
      std::vector<internal::bernstein::Unprotected_interval>& w = scratch_;
      w = witness_intervals_;
      for (std::size_t r = 1; r < w.size(); ++r)
        for (std::size_t k = 0; k + r < w.size(); ++k) w[k] = s * w[k] + t * w[k + 1];
      if (w[0].inf() > 0) return 1;
      if (w[0].sup() < 0) return -1;
    }
    return exact_witness_sign(x);
  }

  // Exact sign of the witness at x: integer homogeneous de Casteljau when x is dyadic (always,
  // for the end points this class produces), rational de Casteljau otherwise.
  int exact_witness_sign(const CGAL::Gmpq& x) {
    const std::size_t m = witness_.size();
    unsigned long e = 0;
    if (internal::bernstein::dyadic_parts(x, integer_work_[m + 2], e))
      return internal::bernstein::sign_bernstein_at_dyadic(witness_integer_, integer_work_[m + 2], e, integer_work_);
    return CGAL::sign(Bernstein_polynomial<CGAL::Gmpq>(witness_).evaluate(x));
  }
  int exact_witness_sign(double x) {
    const std::size_t m = witness_.size();
    unsigned long e = 0;
    internal::bernstein::dyadic_parts(x, integer_work_[m + 2], e);
    return internal::bernstein::sign_bernstein_at_dyadic(witness_integer_, integer_work_[m + 2], e, integer_work_);
  }

  // If interval i has double end points, shrinks it to at most max_ulps ulps with the double Newton /
  // interval-certified bracketing of internal/bernstein/unique_root.h.
  void tighten_in_double(std::size_t i, double max_ulps) {
    Isolating_interval& I = intervals_[i];
    if (I.is_point()) return;
    const double L = CGAL::to_double(I.lower), H = CGAL::to_double(I.upper);
    if (CGAL::Gmpq(L) != I.lower || CGAL::Gmpq(H) != I.upper) return;
    prepare_witness();
    const internal::bernstein::Double_bracket r = internal::bernstein::tighten_double_bracket(
        witness_intervals_.data(), witness_approx_.data(), witness_.size(), L, H, sign_after_lower_[i],
        L + (H - L) / 2, [this](double x) { return exact_witness_sign(x); }, max_ulps);
    if (r.exact_root) {
      I.lower = I.upper = CGAL::Gmpq(r.root);
      return;
    }
    if (r.lower != L) {
      // The witness has sign sign_after_lower just after the new lower end, as before.
      I.lower = CGAL::Gmpq(r.lower);
    }
    if (r.upper != H) I.upper = CGAL::Gmpq(r.upper);
  }

  // The largest double <= q (q in [0, 1]), whatever the rounding of to_double.
  static double double_at_or_below(const CGAL::Gmpq& q) {
    const double d = CGAL::to_double(q);
    return CGAL::Gmpq(d) > q ? std::nextafter(d, -1.0) : d;
  }

  void bisect(std::size_t i) {
    if (!intervals_[i].is_point()) split(i, (intervals_[i].lower + intervals_[i].upper) / 2);
  }

  // Splits interval i (not a point) at m, lower < m < upper, by the exact sign of the witness at m.
  void split(std::size_t i, const CGAL::Gmpq& m) {
    Isolating_interval& I = intervals_[i];
    const int s = witness_sign(m);
    if (s == 0) {
      I.lower = m;
      I.upper = m;
    } else if (s == sign_after_lower_[i]) {
      I.lower = m;
    } else {
      I.upper = m;
    }
  }

  // Bisection depth after which multiple roots are suspected and the square-free factorisation
  // runs (roots closer than 2^-30, about 1e-9, are rare for distinct roots).
  static constexpr int square_free_depth = 30;
  // Subdivision depth cap of a square-free polynomial (roots closer than 2^-4000).
  static constexpr int hard_cap = 4000;
  // Bisections of refine(): a requested width down to 2^-100000.
  static constexpr int max_refine_bisections = 100000;
  // Splits of root_approximation() after the double tightening: the interval lies within
  // [d, next(d)] for a double d after at most ~1100 halvings of [0,1] (subnormals included); the
  // cap is a safety net. (Until session 19 it bisected at midpoints until both ends truncated to
  // the same double, which never happens for a root that is a double between non-dyadic ends:
  // 5000 exact bisections, 7-15 s, then this cap: a metrics fuzz finding.)
  static constexpr int max_approximation_bisections = 5000;

  Bernstein_polynomial<CGAL::Gmpq> p_;
  std::vector<Isolating_interval> intervals_;
  std::vector<int> sign_after_lower_;
  std::vector<CGAL::Gmpq> witness_;
  // Lazily prepared for refinement: interval enclosures, double approximations and integer
  // coefficients of the witness, and scratch buffers.
  std::vector<internal::bernstein::Unprotected_interval> witness_intervals_;
  std::vector<double> witness_approx_;
  internal::bernstein::Mpz_array witness_integer_;  // the witness scaled to integer Bernstein coefficients
  internal::bernstein::Mpz_array integer_work_;
  std::vector<internal::bernstein::Unprotected_interval> scratch_;
  bool used_square_free_ = false;
};

/// The isolating intervals of the roots of p in [0,1] (see Bernstein_root_isolation).
template <class NT>
std::vector<Isolating_interval> isolate_roots(const Bernstein_polynomial<NT>& p) {
  return Bernstein_root_isolation(p).intervals();
}

/// Result of certified_unique_root: the fast certified root of a double Bernstein polynomial
/// with exactly one sign change.
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

/// Fast certified path for the common case of exactly one sign change (see
/// internal/bernstein/unique_root.h for the method and accuracy).
/// `max_ulps` (>= 1) bounds the width of the certified bracket.
inline Unique_root certified_unique_root(const Bernstein_polynomial<double>& p, double max_ulps = 8) {
  return internal::bernstein::certified_unique_root<Unique_root>(p.coefficients().data(), p.coefficients().size(),
                                                                 max_ulps);
}

/// The same on N = degree + 1 coefficients in a std::array: no heap allocation for N <= 32.
template <std::size_t N>
Unique_root certified_unique_root(const std::array<double, N>& b, double max_ulps = 8) {
  static_assert(N >= 1, "certified_unique_root: at least one coefficient");
  return internal::bernstein::certified_unique_root<Unique_root>(b.data(), N, max_ulps);
}

} // namespace fair

#endif // FAIR_BERNSTEIN_ROOT_ISOLATION_H
