// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact sign evaluation at dyadic points (k / 2^e), the points every bisection and every double
// produce, in integer arithmetic (GMP mpz, no rational normalisation): the exact fallback of the
// interval filters in the root isolation and the unique-root path.

#ifndef FAIR_INTERNAL_BERNSTEIN_DYADIC_H
#define FAIR_INTERNAL_BERNSTEIN_DYADIC_H

#include <CGAL/Gmpq.h>

#include <gmp.h>

#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

namespace fair {
namespace internal {

/// A fixed-size array of GMP integers (RAII).
class Mpz_array {
public:
  explicit Mpz_array(std::size_t n = 0) : n_(n), v_(n ? new __mpz_struct[n] : nullptr) {
    for (std::size_t i = 0; i < n_; ++i) mpz_init(&v_[i]);
  }
  ~Mpz_array() {
    for (std::size_t i = 0; i < n_; ++i) mpz_clear(&v_[i]);
  }
  Mpz_array(const Mpz_array&) = delete;
  Mpz_array& operator=(const Mpz_array&) = delete;
  Mpz_array(Mpz_array&& o) noexcept : n_(o.n_), v_(std::move(o.v_)) { o.n_ = 0; }
  Mpz_array& operator=(Mpz_array&& o) noexcept {
    if (this != &o) {
      for (std::size_t i = 0; i < n_; ++i) mpz_clear(&v_[i]);
      n_ = o.n_;
      v_ = std::move(o.v_);
      o.n_ = 0;
    }
    return *this;
  }
  std::size_t size() const { return n_; }
  mpz_ptr operator[](std::size_t i) { return &v_[i]; }
  mpz_srcptr operator[](std::size_t i) const { return &v_[i]; }

private:
  std::size_t n_;
  std::unique_ptr<__mpz_struct[]> v_;
};

/// Writes a finite x >= 0 as k / 2^e exactly (k integer, e >= 0).
inline void dyadic_parts(double x, mpz_ptr k, unsigned long& e) {
  int ex = 0;
  const double f = std::frexp(x, &ex); // x = f 2^ex, f in [0.5, 1) or 0
  mpz_set_d(k, std::ldexp(f, 53));     // exact: f has at most 53 significant bits
  const long shift = 53 - static_cast<long>(ex);
  if (shift >= 0) {
    e = static_cast<unsigned long>(shift);
  } else {
    mpz_mul_2exp(k, k, static_cast<unsigned long>(-shift));
    e = 0;
  }
}

/// Writes x = k / 2^e if x is dyadic (its denominator a power of two); false otherwise.
inline bool dyadic_parts(const CGAL::Gmpq& x, mpz_ptr k, unsigned long& e) {
  mpz_srcptr den = mpq_denref(x.mpq());
  const unsigned long bits = static_cast<unsigned long>(mpz_sizeinbase(den, 2)) - 1;
  if (mpz_scan1(den, 0) != bits) return false;
  mpz_set(k, mpq_numref(x.mpq()));
  e = bits;
  return true;
}

/// Integer power-basis coefficients c with c_i = D a_i for a common positive D (so the signs
/// of sum c_i x^i and sum a_i x^i agree).
inline Mpz_array integer_power_coefficients(const std::vector<CGAL::Gmpq>& a) {
  Mpz_array c(a.size());
  mpz_t D;
  mpz_init_set_ui(D, 1);
  for (const CGAL::Gmpq& q : a) mpz_lcm(D, D, mpq_denref(q.mpq()));
  for (std::size_t i = 0; i < a.size(); ++i) {
    mpz_divexact(c[i], D, mpq_denref(a[i].mpq()));
    mpz_mul(c[i], c[i], mpq_numref(a[i].mpq()));
  }
  mpz_clear(D);
  return c;
}

/// Sign of sum c_i x^i at x = k / 2^e: the sign of sum c_i k^i 2^(e (n-i)) (homogeneous Horner).
inline int sign_power_at_dyadic(const Mpz_array& c, mpz_srcptr k, unsigned long e) {
  const std::size_t m = c.size();
  if (m == 0) return 0;
  mpz_t v, t;
  mpz_init_set(v, c[m - 1]);
  mpz_init(t);
  for (std::size_t i = m - 1; i-- > 0;) {
    mpz_mul(v, v, k);
    mpz_mul_2exp(t, c[i], e * static_cast<unsigned long>(m - 1 - i));
    mpz_add(v, v, t);
  }
  const int s = mpz_sgn(v);
  mpz_clear(v);
  mpz_clear(t);
  return s;
}

/// Exact sign of the Bernstein polynomial with double coefficients b[0..m-1] at the double x in
/// [0,1]: b_i = K_i 2^(E_i) are scaled to integers and de Casteljau is run homogeneously,
/// w_i <- (2^e - k) w_i + k w_{i+1}, which multiplies p(x) by 2^(e n) > 0.
inline int exact_sign_bernstein_at(const double* b, std::size_t m, double x) {
  Mpz_array w(m);
  long min_exp = 0;
  bool first = true;
  std::vector<long> exps(m, 0);
  for (std::size_t i = 0; i < m; ++i) {
    if (b[i] == 0) continue;
    int ex = 0;
    std::frexp(b[i], &ex);
    exps[i] = static_cast<long>(ex) - 53; // b_i = K_i 2^(ex - 53) with K_i an integer
    if (first || exps[i] < min_exp) min_exp = exps[i];
    first = false;
  }
  for (std::size_t i = 0; i < m; ++i) {
    if (b[i] == 0) continue;
    int ex = 0;
    const double f = std::frexp(b[i], &ex);
    mpz_set_d(w[i], std::ldexp(f, 53));
    mpz_mul_2exp(w[i], w[i], static_cast<unsigned long>(exps[i] - min_exp));
  }
  Mpz_array kd(3); // k, 2^e - k, scratch
  unsigned long e = 0;
  dyadic_parts(x, kd[0], e);
  mpz_set_ui(kd[1], 1);
  mpz_mul_2exp(kd[1], kd[1], e);
  mpz_sub(kd[1], kd[1], kd[0]);
  for (std::size_t r = 1; r < m; ++r)
    for (std::size_t i = 0; i + r < m; ++i) {
      mpz_mul(w[i], w[i], kd[1]);
      mpz_mul(kd[2], w[i + 1], kd[0]);
      mpz_add(w[i], w[i], kd[2]);
    }
  return mpz_sgn(w[0]);
}

} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_BERNSTEIN_DYADIC_H
