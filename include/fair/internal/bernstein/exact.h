// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact rational helpers for the root isolation of Bernstein polynomials:
//  - exact conversion of every supported coefficient type to CGAL::Gmpq,
//  - power-basis polynomial arithmetic over Q (division, monic gcd, Yun's square-free
//    factorisation), used to remove multiple roots before Descartes bisection.
// Everything here is exact; nothing rounds.

#ifndef FAIR_INTERNAL_BERNSTEIN_EXACT_H
#define FAIR_INTERNAL_BERNSTEIN_EXACT_H

#include <fair/Errors.h>

#include <CGAL/Gmpfr.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <boost/multiprecision/gmp.hpp>
#if __has_include(<gmpxx.h>)
#include <gmpxx.h>
#define FAIR_HAS_GMPXX 1
#endif

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace bernstein {

// ------------------------------------------------------------------ exact conversion to Q
// A double, a Gmpfr and a point interval are dyadic rationals: their conversion is exact.

inline CGAL::Gmpq to_exact_rational(double x, const char* where) {
  if (!std::isfinite(x)) throw Precondition_error(message(where, ": coefficient ", x, " is not finite"));
  return CGAL::Gmpq(x);
}
inline CGAL::Gmpq to_exact_rational(const CGAL::Gmpq& x, const char*) { return x; }
inline CGAL::Gmpq to_exact_rational(const CGAL::Gmpfr& x, const char* where) {
  if (!x.is_number()) throw Precondition_error(message(where, ": coefficient ", x, " is not finite"));
  return CGAL::Gmpq(x);
}
template <bool P>
CGAL::Gmpq to_exact_rational(const CGAL::Interval_nt<P>& x, const char* where) {
  if (x.inf() != x.sup())
    throw Precondition_error(message(where, ": interval coefficient [", x.inf(), ", ", x.sup(),
                                     "] is not a single number; isolation certifies the roots of one "
                                     "polynomial, so pass point intervals or exact coefficients"));
  return to_exact_rational(x.inf(), where);
}
/// The exact values behind CGAL::Lazy_exact_nt: CGAL::Gmpq, boost::multiprecision's GMP
/// rational or gmpxx's mpq_class (EPECK's exact type in CGAL 5.5 depends on the configuration).
inline CGAL::Gmpq exact_value_to_gmpq(const CGAL::Gmpq& x) { return x; }
template <boost::multiprecision::expression_template_option E>
CGAL::Gmpq exact_value_to_gmpq(const boost::multiprecision::number<boost::multiprecision::gmp_rational, E>& x) {
  return CGAL::Gmpq(x.backend().data());
}
#ifdef FAIR_HAS_GMPXX
inline CGAL::Gmpq exact_value_to_gmpq(const mpq_class& x) { return CGAL::Gmpq(x.get_mpq_t()); }
#endif
/// Lazy exact numbers (EPECK's FT): the exact value, computed on demand.
template <class NT>
CGAL::Gmpq to_exact_rational(const NT& x, const char*) {
  return exact_value_to_gmpq(x.exact());
}

template <class NT>
std::vector<CGAL::Gmpq> to_exact_rationals(const std::vector<NT>& v, const char* where) {
  std::vector<CGAL::Gmpq> out;
  out.reserve(v.size());
  for (const NT& x : v) out.push_back(to_exact_rational(x, where));
  return out;
}

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
  require(!b.empty(), "q_divmod: division by the zero polynomial");
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
  require(!f.empty(), "q_square_free_factorization: zero polynomial");
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
