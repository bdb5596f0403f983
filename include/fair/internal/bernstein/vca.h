// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Descartes / Vincent-Collins-Akritas bisection on Bernstein coefficients with an interval
// filter. The polynomial is given by exact rational Bernstein coefficients E on [0,1].
//
// Certificate. For a node [l,r] the Bernstein coefficients of p restricted to [l,r] bound the
// number of roots of p in the open interval (l,r): by Descartes' rule in Bernstein form the
// number of roots counted with multiplicity is at most the sign variation count V and has its
// parity. V = 0 proves no root, V = 1 proves exactly one simple root. Roots at the end points
// are found exactly: p(l) is the first coefficient of the node, and every subdivision point is
// checked exactly, so such a root is reported as a point interval [m,m] whose multiplicity is
// the number of leading zero coefficients of the node starting at m (t^k divides a Bernstein
// polynomial iff its first k coefficients vanish).
//
// Interval filter. Nodes are first subdivided in CGAL::Interval_nt<false> (under
// CGAL::Protect_FPU_rounding<true>); each interval coefficient encloses the exact coefficient,
// so a variation count that is the same for every choice inside the intervals is the exact
// count. Only when the count is uncertain and may be 0 or 1 does a node switch to exact Gmpq
// coefficients (computed from E by blossoming on [l,r]); its subtree then stays exact.
//
// Termination. For a square-free polynomial the bisection terminates (two-circle theorem)
// after about log2(1 / root separation) levels. A multiple root inside an open node never gets
// V < 2, hence the depth cap: when it is hit, run() returns false and the caller removes
// multiple roots first.

#ifndef FAIR_INTERNAL_BERNSTEIN_VCA_H
#define FAIR_INTERNAL_BERNSTEIN_VCA_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Errors.h>
#include <fair/internal/bernstein/dyadic.h>
#include <fair/internal/bernstein/sign.h>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace bernstein {

/// One root found by the bisection: the closed interval [lower, upper] (a point when
/// lower == upper, else the root is in the open interval), its multiplicity when known (0 when
/// not yet determined), and the sign of p just to the right of `lower` (for refinement).
struct Isolation_leaf {
  CGAL::Gmpq lower, upper;
  int multiplicity;
  int sign_after_lower;
};

typedef CGAL::Interval_nt<false> Unprotected_interval;

/// Splits integer Bernstein coefficients at 1/2 in place: `w` becomes the left half and
/// `right` the right half, each times a positive power of two (the bisection needs signs only).
/// Why integers: halving Gmpq coefficients normalises a fraction (a gcd and an allocation) per
/// operation, which made 230-digit inputs take seconds under the sanitizers.
/// Derivation: de Casteljau at 1/2 has levels w^(r)_i = (w^(r-1)_(i-1) + w^(r-1)_i) / 2 with
/// left_i = w^(i)_i and right_(n-r) = w^(r)_n. The scaled levels u^(r) = 2^r w^(r) obey
/// u^(r)_i = u^(r-1)_(i-1) + u^(r-1)_i (additions only), so 2^n left_i = 2^(n-i) u^(i)_i and
/// 2^n right_(n-r) = 2^(n-r) u^(r)_n are integers. Each half is then divided by the largest
/// power of two common to its coefficients, which keeps their size that of the reduced
/// rational coefficients (n bits more per level at most).
inline void split_half(Mpz_array& w, Mpz_array& right) {
  const std::size_t n = w.size() - 1;
  right = Mpz_array(n + 1);
  mpz_mul_2exp(right[n], w[n], static_cast<unsigned long>(n));
  for (std::size_t r = 1; r <= n; ++r) {
    for (std::size_t i = n; i >= r; --i) mpz_add(w[i], w[i - 1], w[i]);
    mpz_mul_2exp(right[n - r], w[n], static_cast<unsigned long>(n - r));
  }
  for (std::size_t i = 0; i < n; ++i) mpz_mul_2exp(w[i], w[i], static_cast<unsigned long>(n - i));
  remove_common_power_of_two(w);
  remove_common_power_of_two(right);
}

inline void split_half_interval(std::vector<Unprotected_interval>& w, std::vector<Unprotected_interval>& right) {
  CGAL::Protect_FPU_rounding<true> protect;
  const std::size_t n = w.size() - 1;
  right.resize(n + 1);
  right[n] = w[n];
  for (std::size_t r = 1; r <= n; ++r) {
    for (std::size_t i = n; i >= r; --i) w[i] = (w[i - 1] + w[i]) * 0.5;
    right[n - r] = w[n];
  }
}

inline std::vector<Unprotected_interval> to_intervals(const std::vector<CGAL::Gmpq>& x) {
  std::vector<Unprotected_interval> out;
  out.reserve(x.size());
  for (const CGAL::Gmpq& q : x) out.push_back(Unprotected_interval(CGAL::to_interval(q)));
  return out;
}

/// Sign of the first coefficient whose sign is certainly nonzero (0 if none).
template <class T>
int first_certain_sign(const std::vector<T>& c) {
  for (const T& x : c) {
    const std::pair<int, int> r = sign_range_of(x);
    if (r.first == r.second && r.first != 0) return r.first;
  }
  return 0;
}

inline int first_certain_sign(const Mpz_array& c) {
  for (std::size_t i = 0; i < c.size(); ++i)
    if (mpz_sgn(c[i]) != 0) return mpz_sgn(c[i]);
  return 0;
}

inline int leading_zero_count(const std::vector<CGAL::Gmpq>& c) {
  int k = 0;
  while (k < static_cast<int>(c.size()) && CGAL::is_zero(c[static_cast<std::size_t>(k)])) ++k;
  return k;
}

inline int leading_zero_count(const Mpz_array& c) {
  std::size_t k = 0;
  while (k < c.size() && mpz_sgn(c[k]) == 0) ++k;
  return static_cast<int>(k);
}

/// Sign variations of exact integer coefficients, zeros skipped.
inline int sign_variations(const Mpz_array& c) {
  int count = 0, last = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const int s = mpz_sgn(c[i]);
    if (s == 0) continue;
    if (last != 0 && s != last) ++count;
    last = s;
  }
  return count;
}

class Vca_isolator {
public:
  /// `use_interval_filter` = false runs the same bisection in exact arithmetic throughout (for
  /// testing: both must give identical leaves, since a certain filtered count is the exact one).
  /// `enclosure`, if given, holds intervals enclosing E (e.g. from the input number type);
  /// otherwise they are computed from E.
  explicit Vca_isolator(const std::vector<CGAL::Gmpq>& exact, bool use_interval_filter = true,
                        std::vector<Unprotected_interval> enclosure = {})
    : E_(exact), filter_(use_interval_filter), enclosure_(std::move(enclosure)) {}

  /// Isolates the roots of E in [0,1]. Returns false when a node deeper than `depth_cap` would
  /// be needed (leaves() is then incomplete).
  bool run(int depth_cap) {
    leaves_.clear();
    const std::size_t n = E_.size() - 1;
    // Roots at 0 and 1, with multiplicity from the leading / trailing zeros.
    if (CGAL::is_zero(E_[0])) leaves_.push_back({CGAL::Gmpq(0), CGAL::Gmpq(0), leading_zero_count(E_), 0});
    if (n > 0 && CGAL::is_zero(E_[n])) {
      std::vector<CGAL::Gmpq> rev(E_.rbegin(), E_.rend());
      leaves_.push_back({CGAL::Gmpq(1), CGAL::Gmpq(1), leading_zero_count(rev), 0});
    }
    if (n == 0) return true;
    std::vector<Node> stack;
    Node root;
    root.exact = !filter_;
    if (!filter_) root.X = integer_scaled(E_);
    else if (enclosure_.size() == E_.size()) root.I = std::move(enclosure_);
    else root.I = to_intervals(E_);
    stack.push_back(std::move(root));
    while (!stack.empty()) {
      Node node = std::move(stack.back());
      stack.pop_back();
      if (!node.exact) {
        const Sign_variation_count v = sign_variation_bounds<Sign_variation_count>(node.I.begin(), node.I.end());
        if (v.upper == 0) continue;
        if (v.certain() && v.lower == 1) {
          leaves_.push_back({node.lower(), node.upper(), 1, first_certain_sign(node.I)});
          continue;
        }
        if (v.lower >= 2) {
          if (node.depth + 1 > depth_cap) return false;
          Node right;
          split_half_interval(node.I, right.I);
          const std::pair<int, int> mid_sign = sign_range_of(right.I[0]);
          if (mid_sign.first > 0 || mid_sign.second < 0) { // p(mid) certainly nonzero
            node.bisect(right);
            stack.push_back(std::move(right));
            stack.push_back(std::move(node));
            continue;
          }
          // p(mid) may vanish: redo this node exactly (the intervals were overwritten).
        }
        // Uncertain count that may be 0 or 1, or p(mid) possibly zero: go exact.
        node.X = integer_scaled(Bernstein_polynomial<CGAL::Gmpq>(E_).restricted(node.lower(), node.upper()).coefficients());
        node.exact = true;
        node.I.clear();
      }
      const int variations = sign_variations(node.X);
      if (variations == 0) continue;
      if (variations == 1) {
        leaves_.push_back({node.lower(), node.upper(), 1, first_certain_sign(node.X)});
        continue;
      }
      if (node.depth + 1 > depth_cap) return false;
      Node right;
      split_half(node.X, right.X);
      right.exact = true;
      node.bisect(right);
      if (mpz_sgn(right.X[0]) == 0) leaves_.push_back({right.lower(), right.lower(), leading_zero_count(right.X), 0});
      stack.push_back(std::move(right));
      stack.push_back(std::move(node));
    }
    std::sort(leaves_.begin(), leaves_.end(),
              [](const Isolation_leaf& a, const Isolation_leaf& b) { return a.lower < b.lower; });
    return true;
  }

  std::vector<Isolation_leaf>& leaves() { return leaves_; }

private:
  // A subdivision node [lo, hi]. Its end points are dyadic k / 2^depth: they are kept as exact
  // doubles while depth <= max_double_node_depth (cheap), and as Gmpq below.
  // k / 2^depth in [0,1] is an exact double while depth <= 52 (53-bit significand).
  static constexpr int max_double_node_depth = 52;
  struct Node {
    double lo_d = 0, hi_d = 1;
    CGAL::Gmpq lo_q, hi_q;
    bool rational = false;
    int depth = 0;
    bool exact = false;
    std::vector<Unprotected_interval> I;
    Mpz_array X; // exact: the node's Bernstein coefficients times a positive integer

    CGAL::Gmpq lower() const { return rational ? lo_q : CGAL::Gmpq(lo_d); }
    CGAL::Gmpq upper() const { return rational ? hi_q : CGAL::Gmpq(hi_d); }
    // Halves this node: it becomes [lo, mid] and `right` becomes [mid, hi].
    void bisect(Node& right) {
      right.depth = ++depth;
      if (!rational && depth <= max_double_node_depth) {
        const double mid = 0.5 * (lo_d + hi_d); // exact: both are multiples of 2^-(depth-1)
        right.lo_d = mid;
        right.hi_d = hi_d;
        right.rational = false;
        hi_d = mid;
        return;
      }
      if (!rational) {
        lo_q = CGAL::Gmpq(lo_d);
        hi_q = CGAL::Gmpq(hi_d);
        rational = true;
      }
      const CGAL::Gmpq mid = (lo_q + hi_q) / 2;
      right.lo_q = mid;
      right.hi_q = hi_q;
      right.rational = true;
      hi_q = mid;
    }
  };

  const std::vector<CGAL::Gmpq>& E_;
  bool filter_;
  std::vector<Unprotected_interval> enclosure_;
  std::vector<Isolation_leaf> leaves_;
};

} // namespace bernstein
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_BERNSTEIN_VCA_H
