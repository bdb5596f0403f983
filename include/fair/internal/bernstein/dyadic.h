// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact sign evaluation at dyadic points (k / 2^e), the points every bisection and every double
// produce, in integer arithmetic (GMP mpz, no rational normalisation): the exact fallback of the
// interval filters in the root isolation and the unique-root path.

#ifndef FAIR_INTERNAL_BERNSTEIN_DYADIC_H
#define FAIR_INTERNAL_BERNSTEIN_DYADIC_H

#include <CGAL/Gmpq.h>

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

namespace fair {
namespace internal {
namespace bernstein {

/// A fixed-size array of GMP integers (RAII, deep copies).
class Mpz_array {
public:
  explicit Mpz_array(std::size_t n = 0) : n_(n), v_(n ? new __mpz_struct[n] : nullptr) {
    for (std::size_t i = 0; i < n_; ++i) mpz_init(&v_[i]);
  }
  ~Mpz_array() {
    for (std::size_t i = 0; i < n_; ++i) mpz_clear(&v_[i]);
  }
  Mpz_array(const Mpz_array& o) : n_(o.n_), v_(o.n_ ? new __mpz_struct[o.n_] : nullptr) {
    for (std::size_t i = 0; i < n_; ++i) mpz_init_set(&v_[i], &o.v_[i]);
  }
  Mpz_array& operator=(const Mpz_array& o) {
    if (this != &o) {
      Mpz_array copy(o);
      *this = std::move(copy);
    }
    return *this;
  }
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

/// Divides every coefficient by the largest power of two that divides them all (none if all
/// are zero): a positive factor, so every sign and every root is kept.
inline void remove_common_power_of_two(Mpz_array& c) {
  mp_bitcnt_t shift = ~static_cast<mp_bitcnt_t>(0);
  for (std::size_t i = 0; i < c.size(); ++i)
    if (mpz_sgn(c[i]) != 0) shift = std::min(shift, mpz_scan1(c[i], 0));
  if (shift == ~static_cast<mp_bitcnt_t>(0) || shift == 0) return;
  for (std::size_t i = 0; i < c.size(); ++i) mpz_tdiv_q_2exp(c[i], c[i], shift);
}

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

/// Integer coefficients c_i = D a_i for the common positive D = lcm of the denominators (so a
/// polynomial with coefficients c has the signs of the one with coefficients a, in any basis).
inline Mpz_array integer_scaled(const std::vector<CGAL::Gmpq>& a) {
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

/// Integer Bernstein coefficients B_i = 2^(-E) b_i of double coefficients (E the smallest
/// exponent of a nonzero b_i), exact.
inline Mpz_array integer_scaled(const double* b, std::size_t m) {
  Mpz_array w(m);
  long min_exp = 0;
  bool first = true;
  for (std::size_t i = 0; i < m; ++i) {
    if (b[i] == 0) continue;
    int ex = 0;
    std::frexp(b[i], &ex);
    const long e = static_cast<long>(ex) - 53; // b_i = K_i 2^(ex - 53) with K_i an integer
    if (first || e < min_exp) min_exp = e;
    first = false;
  }
  for (std::size_t i = 0; i < m; ++i) {
    if (b[i] == 0) continue;
    int ex = 0;
    const double f = std::frexp(b[i], &ex);
    mpz_set_d(w[i], std::ldexp(f, 53));
    mpz_mul_2exp(w[i], w[i], static_cast<unsigned long>(static_cast<long>(ex) - 53 - min_exp));
  }
  return w;
}

/// Sign of the Bernstein polynomial with integer coefficients B at x = k / 2^e, by homogeneous
/// de Casteljau w_i <- (2^e - k) w_i + k w_{i+1}, which multiplies p(x) by 2^(e n) > 0.
/// `work` is scratch space of B.size() + 2 integers.
inline int sign_bernstein_at_dyadic(const Mpz_array& B, mpz_srcptr k, unsigned long e, Mpz_array& work) {
  const std::size_t m = B.size();
  for (std::size_t i = 0; i < m; ++i) mpz_set(work[i], B[i]);
  mpz_ptr kc = work[m], tmp = work[m + 1];
  mpz_set_ui(kc, 1);
  mpz_mul_2exp(kc, kc, e);
  mpz_sub(kc, kc, k); // 2^e - k
  for (std::size_t r = 1; r < m; ++r)
    for (std::size_t i = 0; i + r < m; ++i) {
      mpz_mul(work[i], work[i], kc);
      mpz_mul(tmp, work[i + 1], k);
      mpz_add(work[i], work[i], tmp);
    }
  return mpz_sgn(work[0]);
}

/// Exact sign of the Bernstein polynomial with double coefficients b[0..m-1] at the double x.
inline int exact_sign_bernstein_at(const double* b, std::size_t m, double x) {
  const Mpz_array B = integer_scaled(b, m);
  Mpz_array work(m + 3);
  unsigned long e = 0;
  dyadic_parts(x, work[m + 2], e);
  return sign_bernstein_at_dyadic(B, work[m + 2], e, work);
}

} // namespace bernstein
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_BERNSTEIN_DYADIC_H
