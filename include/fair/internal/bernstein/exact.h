// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact rational helpers for the root isolation of Bernstein polynomials: power-basis
// polynomial arithmetic over Q (division, monic gcd, Yun's square-free factorisation), used to
// remove multiple roots before Descartes bisection. Everything here is exact; nothing rounds.
// (The exact conversion of the coefficients is fair::internal::common::to_gmpq.)

#ifndef FAIR_INTERNAL_BERNSTEIN_EXACT_H
#define FAIR_INTERNAL_BERNSTEIN_EXACT_H

#include <fair/Errors.h>

#include <CGAL/Gmpq.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace bernstein {

// ------------------------------------------------------------------ power basis over Q
// A polynomial is a vector of coefficients of t^0, t^1, ...; the zero polynomial is empty.
typedef std::vector<CGAL::Gmpq> Q_polynomial;

inline void trim(Q_polynomial& a) {
  while (!a.empty() && CGAL::is_zero(a.back())) a.pop_back();
}

inline Q_polynomial q_derivative(const Q_polynomial& a) {
  Q_polynomial d;
  for (std::size_t k = 1; k < a.size(); ++k) d.push_back(CGAL::Gmpq(static_cast<long>(k)) * a[k]);
  trim(d);
  return d;
}

/// Euclidean division a = q b + r with deg r < deg b; b must be nonzero.
inline std::pair<Q_polynomial, Q_polynomial> q_divmod(Q_polynomial a, const Q_polynomial& b) {
  FAIR_ASSERT_MSG(!b.empty(), "q_divmod: division by the zero polynomial");
  trim(a);
  Q_polynomial q;
  if (a.size() >= b.size()) q.assign(a.size() - b.size() + 1, CGAL::Gmpq(0));
  while (a.size() >= b.size()) {
    const std::size_t shift = a.size() - b.size();
    const CGAL::Gmpq f = a.back() / b.back();
    q[shift] = f;
    for (std::size_t k = 0; k < b.size(); ++k) a[shift + k] -= f * b[k];
    a.pop_back(); // the leading term cancels exactly
    trim(a);
  }
  trim(q);
  return std::make_pair(q, a);
}

inline Q_polynomial q_monic(Q_polynomial a) {
  trim(a);
  if (a.empty()) return a;
  const CGAL::Gmpq lead = a.back();
  for (CGAL::Gmpq& c : a) c /= lead;
  return a;
}

/// Monic greatest common divisor (Euclid over Q; the degrees involved are small).
inline Q_polynomial q_gcd(Q_polynomial a, Q_polynomial b) {
  trim(a);
  trim(b);
  while (!b.empty()) {
    Q_polynomial r = q_divmod(a, b).second;
    a = q_monic(b);
    b = q_monic(r);
  }
  return q_monic(a);
}

inline Q_polynomial q_exact_quotient(const Q_polynomial& a, const Q_polynomial& b) {
  return q_divmod(a, b).first;
}

inline Q_polynomial q_subtract(Q_polynomial a, const Q_polynomial& b) {
  if (a.size() < b.size()) a.resize(b.size(), CGAL::Gmpq(0));
  for (std::size_t k = 0; k < b.size(); ++k) a[k] -= b[k];
  trim(a);
  return a;
}

/// Yun's square-free factorisation of a nonzero f: f = c * prod_i factors[i-1]^i with each
/// factor square-free, monic, and the factors pairwise coprime (factors may be constant 1).
inline std::vector<Q_polynomial> q_square_free_factorization(Q_polynomial f) {
  trim(f);
  FAIR_ASSERT_MSG(!f.empty(), "q_square_free_factorization: zero polynomial");
  std::vector<Q_polynomial> factors;
  if (f.size() == 1) return factors;
  const Q_polynomial df = q_derivative(f);
  const Q_polynomial b = q_gcd(f, df);
  Q_polynomial c = q_exact_quotient(f, b);
  Q_polynomial d = q_subtract(q_exact_quotient(df, b), q_derivative(c));
  while (c.size() > 1) {
    const Q_polynomial a = q_gcd(c, d);
    factors.push_back(a);
    c = q_exact_quotient(c, a);
    d = q_subtract(q_exact_quotient(d, a), q_derivative(c));
  }
  return factors;
}

} // namespace bernstein
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_BERNSTEIN_EXACT_H
