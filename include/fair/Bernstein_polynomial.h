// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Univariate polynomials in the Bernstein basis of [0,1]:
//
//     p(t) = sum_{i=0}^{n} b_i B_i^n(t),   B_i^n(t) = C(n,i) (1-t)^{n-i} t^i .
//
// This is the exact core of the library: every operation below is exact when NT is an exact
// field type (CGAL::Gmpq, EPECK's FT = CGAL::Lazy_exact_nt<CGAL::Gmpq>), returns an enclosure
// of the exact result when NT = CGAL::Interval_nt<> (outward rounded), and is the usual
// rounded floating-point computation for NT = double or CGAL::Gmpfr. Accuracy for double:
// de Casteljau evaluation at t in [0,1] is backward stable (each step is a convex combination,
// so the computed value is the exact value of a polynomial whose coefficients differ from b_i by
// at most about 2 n eps |b_i|); the other operations (split, restriction, derivative, elevation,
// product, basis conversion) are a small fixed number of rounded operations per output
// coefficient. Basis conversion to and from the power basis is ill-conditioned for high degree
// in floating point (the binomial factors grow like 2^n); use an exact NT when that matters.
//
// Certified root isolation lives in <fair/Bernstein_root_isolation.h>.

#ifndef FAIR_BERNSTEIN_POLYNOMIAL_H
#define FAIR_BERNSTEIN_POLYNOMIAL_H

#include <fair/Errors.h>
#include <fair/internal/bernstein/sign.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <ostream>
#include <utility>
#include <vector>

namespace fair {

/// \brief A polynomial of degree at most n, stored by its n+1 Bernstein coefficients on [0,1].
///
/// `NT` must model a field-like number type with +, -, *, / and construction from int
/// (double, CGAL::Interval_nt<>, CGAL::Gmpq, CGAL::Lazy_exact_nt<CGAL::Gmpq>, CGAL::Gmpfr).
/// The stored degree is the length of the coefficient vector minus one; it is not reduced
/// when the leading power coefficient vanishes (degree elevation keeps the polynomial).
template <class NT>
class Bernstein_polynomial {
public:
  typedef NT Number_type;

  /// The zero polynomial, stored with degree 0 (one coefficient equal to 0).
  Bernstein_polynomial() : b_(1, NT(0)) {}

  /// The polynomial with Bernstein coefficients `coefficients`; degree = size - 1.
  /// \throws Precondition_error if `coefficients` is empty.
  explicit Bernstein_polynomial(std::vector<NT> coefficients) : b_(std::move(coefficients)) {
    internal::require(!b_.empty(),
                      "Bernstein_polynomial: the coefficient vector is empty (need degree + 1 >= 1 coefficients)");
  }

  std::size_t degree() const { return b_.size() - 1; }
  const std::vector<NT>& coefficients() const { return b_; }
  const NT& operator[](std::size_t i) const { return b_[i]; }

  /// p(t) by de Casteljau's algorithm (valid for any t; a convex combination for t in [0,1]).
  NT evaluate(const NT& t) const {
    std::vector<NT> w(b_);
    const NT s = NT(1) - t;
    for (std::size_t r = 1; r < w.size(); ++r)
      for (std::size_t i = 0; i + r < w.size(); ++i) w[i] = s * w[i] + t * w[i + 1];
    return w[0];
  }
  NT operator()(const NT& t) const { return evaluate(t); }

  /// de Casteljau subdivision at t: the pieces on [0,t] and on [t,1], each reparametrised to
  /// [0,1] (left(u) = p(t u), right(u) = p(t + (1-t) u)). Any t is accepted (extrapolation).
  std::pair<Bernstein_polynomial, Bernstein_polynomial> split(const NT& t) const {
    const std::size_t n = degree();
    std::vector<NT> w(b_), left(n + 1), right(n + 1);
    const NT s = NT(1) - t;
    left[0] = w[0];
    right[n] = w[n];
    for (std::size_t r = 1; r <= n; ++r) {
      for (std::size_t i = 0; i + r <= n; ++i) w[i] = s * w[i] + t * w[i + 1];
      left[r] = w[0];
      right[n - r] = w[n - r];
    }
    return std::make_pair(Bernstein_polynomial(std::move(left)), Bernstein_polynomial(std::move(right)));
  }

  /// The piece on [a,b] reparametrised to [0,1]: q(u) = p(a + (b-a) u). Computed without
  /// division by blossoming, q_i = blossom_p(a,...,a (n-i times), b,...,b (i times)), so it is
  /// exact for exact NT and valid for any a, b (a > b reverses the direction). O(n^3).
  Bernstein_polynomial restricted(const NT& a, const NT& b) const {
    const std::size_t n = degree();
    std::vector<NT> level(b_), out(n + 1), w;
    const NT sa = NT(1) - a, sb = NT(1) - b;
    for (std::size_t i = 0; i <= n; ++i) {
      // `level` holds the de Casteljau level i for parameter b (n - i + 1 entries).
      w.assign(level.begin(), level.begin() + static_cast<std::ptrdiff_t>(n - i + 1));
      for (std::size_t r = 1; r <= n - i; ++r)
        for (std::size_t k = 0; k + r <= n - i; ++k) w[k] = sa * w[k] + a * w[k + 1];
      out[i] = w[0];
      for (std::size_t k = 0; k + i < n; ++k) level[k] = sb * level[k] + b * level[k + 1];
    }
    return Bernstein_polynomial(std::move(out));
  }

  /// d/dt p, of degree n-1 with coefficients n (b_{i+1} - b_i); the derivative of a constant is
  /// the zero polynomial of degree 0.
  Bernstein_polynomial derivative() const {
    const std::size_t n = degree();
    if (n == 0) return Bernstein_polynomial();
    std::vector<NT> d(n);
    const NT nn(static_cast<int>(n));
    for (std::size_t i = 0; i < n; ++i) d[i] = nn * (b_[i + 1] - b_[i]);
    return Bernstein_polynomial(std::move(d));
  }

  /// The same polynomial written with degree n + times:
  /// c_i = (i b_{i-1} + (n+1-i) b_i) / (n+1), applied `times` times (exact for exact NT).
  Bernstein_polynomial elevated(std::size_t times = 1) const {
    std::vector<NT> c(b_);
    for (std::size_t k = 0; k < times; ++k) {
      const std::size_t n = c.size() - 1;
      std::vector<NT> e(n + 2);
      const NT m(static_cast<int>(n + 1));
      e[0] = c[0];
      e[n + 1] = c[n];
      for (std::size_t i = 1; i <= n; ++i)
        e[i] = (NT(static_cast<int>(i)) * c[i - 1] + NT(static_cast<int>(n + 1 - i)) * c[i]) / m;
      c.swap(e);
    }
    return Bernstein_polynomial(std::move(c));
  }

  /// The polynomial sum_k a[k] t^k written in the Bernstein basis of degree a.size()-1:
  /// b_i = sum_{k<=i} C(i,k)/C(n,k) a_k. \throws Precondition_error if `a` is empty.
  static Bernstein_polynomial from_power_basis(const std::vector<NT>& a) {
    internal::require(!a.empty(), "Bernstein_polynomial::from_power_basis: empty coefficient vector");
    const std::size_t n = a.size() - 1;
    const std::vector<std::vector<NT>> C = internal::bernstein::binomial_table<NT>(n);
    std::vector<NT> b(n + 1, NT(0));
    for (std::size_t i = 0; i <= n; ++i)
      for (std::size_t k = 0; k <= i; ++k) b[i] = b[i] + C[i][k] * a[k] / C[n][k];
    return Bernstein_polynomial(std::move(b));
  }

  /// Power-basis coefficients a[k] (of t^k), k = 0..n:
  /// a_k = C(n,k) sum_{i<=k} (-1)^{k-i} C(k,i) b_i (division free).
  std::vector<NT> to_power_basis() const {
    const std::size_t n = degree();
    const std::vector<std::vector<NT>> C = internal::bernstein::binomial_table<NT>(n);
    std::vector<NT> a(n + 1, NT(0));
    for (std::size_t k = 0; k <= n; ++k) {
      NT s(0);
      for (std::size_t i = 0; i <= k; ++i) {
        const NT term = C[k][i] * b_[i];
        s = ((k - i) % 2 == 0) ? s + term : s - term;
      }
      a[k] = C[n][k] * s;
    }
    return a;
  }

  /// True iff every coefficient is certainly zero (for CGAL::Interval_nt: every coefficient is
  /// the point interval [0,0]).
  bool is_zero() const {
    for (const NT& c : b_)
      if (!CGAL::certainly(CGAL::is_zero(c))) return false;
    return true;
  }

  /// The Bernstein polynomial of p(1-t): the coefficients in reverse order.
  Bernstein_polynomial reversed() const {
    return Bernstein_polynomial(std::vector<NT>(b_.rbegin(), b_.rend()));
  }

  // ---------------------------------------------------------------- arithmetic
  Bernstein_polynomial operator-() const {
    std::vector<NT> c(b_);
    for (NT& x : c) x = -x;
    return Bernstein_polynomial(std::move(c));
  }
  /// Sum; the operand of lower degree is elevated to the common degree first.
  friend Bernstein_polynomial operator+(const Bernstein_polynomial& p, const Bernstein_polynomial& q) {
    return combine(p, q, false);
  }
  friend Bernstein_polynomial operator-(const Bernstein_polynomial& p, const Bernstein_polynomial& q) {
    return combine(p, q, true);
  }
  /// Product, of degree m+n: c_k = sum_{i+j=k} C(m,i) C(n,j) / C(m+n,k) p_i q_j.
  friend Bernstein_polynomial operator*(const Bernstein_polynomial& p, const Bernstein_polynomial& q) {
    const std::size_t m = p.degree(), n = q.degree();
    const std::vector<std::vector<NT>> C = internal::bernstein::binomial_table<NT>(m + n);
    std::vector<NT> c(m + n + 1, NT(0));
    for (std::size_t i = 0; i <= m; ++i)
      for (std::size_t j = 0; j <= n; ++j) c[i + j] = c[i + j] + (C[m][i] * C[n][j]) * (p.b_[i] * q.b_[j]);
    for (std::size_t k = 0; k <= m + n; ++k) c[k] = c[k] / C[m + n][k];
    return Bernstein_polynomial(std::move(c));
  }
  friend Bernstein_polynomial operator*(const NT& s, const Bernstein_polynomial& p) {
    std::vector<NT> c(p.b_);
    for (NT& x : c) x = s * x;
    return Bernstein_polynomial(std::move(c));
  }
  friend Bernstein_polynomial operator*(const Bernstein_polynomial& p, const NT& s) { return s * p; }

  Bernstein_polynomial& operator+=(const Bernstein_polynomial& q) { return *this = *this + q; }
  Bernstein_polynomial& operator-=(const Bernstein_polynomial& q) { return *this = *this - q; }
  Bernstein_polynomial& operator*=(const Bernstein_polynomial& q) { return *this = *this * q; }

  friend std::ostream& operator<<(std::ostream& out, const Bernstein_polynomial& p) {
    out << "Bernstein[";
    for (std::size_t i = 0; i < p.b_.size(); ++i) out << (i ? ", " : "") << p.b_[i];
    return out << "]";
  }

private:
  static Bernstein_polynomial combine(const Bernstein_polynomial& p, const Bernstein_polynomial& q, bool minus) {
    const std::size_t n = std::max(p.degree(), q.degree());
    const Bernstein_polynomial pe = p.elevated(n - p.degree()), qe = q.elevated(n - q.degree());
    std::vector<NT> c(n + 1);
    for (std::size_t i = 0; i <= n; ++i) c[i] = minus ? pe.b_[i] - qe.b_[i] : pe.b_[i] + qe.b_[i];
    return Bernstein_polynomial(std::move(c));
  }

  std::vector<NT> b_;
};

/// Bounds on the number of sign variations of a coefficient sequence whose signs may be
/// uncertain (CGAL::Interval_nt): the result of sign_variation_bounds. For exact and floating
/// NT, lower == upper always. An uncertain coefficient may take any sign (including 0), so
/// `lower` counts it as zero and `upper` lets it take whichever sign maximises the count.
struct Sign_variation_count {
  int lower = 0;
  int upper = 0;
  /// The count is known. It may be known even when some signs are not: (?) gives 0..0, while
  /// (+, ?) gives 0..1.
  bool certain() const { return lower == upper; }
  /// The count; \throws Precondition_error if it is not certain.
  int count() const {
    internal::require(certain(), "Sign_variation_count::count: the sign variation count is uncertain, between ",
                      lower, " and ", upper);
    return lower;
  }
};

/// Sign variation bounds of the Bernstein coefficients (zero coefficients skipped).
/// By Descartes' rule in Bernstein form, the number of roots of p in the open interval (0,1),
/// counted with multiplicity, is at most the variation count and has the same parity.
template <class NT>
Sign_variation_count sign_variation_bounds(const Bernstein_polynomial<NT>& p) {
  return internal::bernstein::sign_variation_bounds<Sign_variation_count>(p.coefficients().begin(),
                                                                         p.coefficients().end());
}

/// The number of sign variations of the Bernstein coefficients of p, zero coefficients skipped
/// (Descartes' rule on (0,1)). For CGAL::Interval_nt coefficients whose signs leave the count
/// undetermined, \throws Precondition_error (use sign_variation_bounds to avoid the exception).
template <class NT>
int sign_variations(const Bernstein_polynomial<NT>& p) {
  const Sign_variation_count v = sign_variation_bounds(p);
  internal::require(v.certain(), "sign_variations: the coefficient signs of ", p,
                    " leave the sign variation count uncertain (between ", v.lower, " and ", v.upper,
                    "); use sign_variation_bounds");
  return v.lower;
}

} // namespace fair

#endif // FAIR_BERNSTEIN_POLYNOMIAL_H
