// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact conversions used by the conic pieces: the exact rational value of a kernel number
// (double, CGAL::Gmpq, mpq_class, CGAL::Lazy_exact_nt<...>) as a CGAL::Gmpq, and the exact
// square root of a rational when it is rational. The certified root isolation of
// Rational_quadratic_bezier_2 always runs on the exact rational values of the inputs, whatever
// the kernel: a double coordinate is the dyadic rational it stores.

#ifndef FAIR_INTERNAL_COMMON_EXACT_CONVERSION_H
#define FAIR_INTERNAL_COMMON_EXACT_CONVERSION_H

#include <fair/Errors.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/number_utils.h>
#ifdef CGAL_USE_GMPXX
#include <CGAL/mpq_class.h>
#endif

#include <cmath>
#include <type_traits>
#include <gmp.h>

namespace fair {
namespace internal {
namespace common {

/// The exact rational value of x. \throws Precondition_error for a non-finite double.
inline CGAL::Gmpq to_gmpq(double x) {
  require(std::isfinite(x), "to_gmpq: non-finite value ", x);
  return CGAL::Gmpq(x);
}
inline CGAL::Gmpq to_gmpq(const CGAL::Gmpq& x) { return x; }
#ifdef CGAL_USE_GMPXX
inline CGAL::Gmpq to_gmpq(const mpq_class& x) { return CGAL::Gmpq(x.get_mpq_t()); }
#endif
template <class ET>
CGAL::Gmpq to_gmpq(const CGAL::Lazy_exact_nt<ET>& x) {
  return to_gmpq(x.exact());
}

/// Converts an exact rational back to the number type NT (exact unless NT is a floating type,
/// in which case it is rounded to nearest by CGAL::to_double).
template <class NT>
struct From_gmpq {
  NT operator()(const CGAL::Gmpq& q) const { return NT(q); }
};
template <>
struct From_gmpq<double> {
  double operator()(const CGAL::Gmpq& q) const { return CGAL::to_double(q); }
};
template <class ET>
struct From_gmpq<CGAL::Lazy_exact_nt<ET>> {
  CGAL::Lazy_exact_nt<ET> operator()(const CGAL::Gmpq& q) const { return CGAL::Lazy_exact_nt<ET>(From_gmpq<ET>()(q)); }
};
#ifdef CGAL_USE_GMPXX
template <>
struct From_gmpq<mpq_class> {
  mpq_class operator()(const CGAL::Gmpq& q) const { return mpq_class(q.mpq()); }
};
#endif
template <class NT>
NT from_gmpq(const CGAL::Gmpq& q) {
  return From_gmpq<NT>()(q);
}

/// True iff NT is a floating-point type (rounded arithmetic): double or float.
template <class NT>
struct Is_floating_nt {
  static const bool value = std::is_floating_point<NT>::value;
};

/// The exact square root of a non-negative rational q when it is rational: returns true and
/// sets `root`; returns false when q is not the square of a rational (numerator or denominator
/// in lowest terms not a perfect square) or q < 0.
inline bool exact_rational_sqrt(const CGAL::Gmpq& q, CGAL::Gmpq& root) {
  if (CGAL::sign(q) == CGAL::NEGATIVE) return false;
  const CGAL::Gmpz num = q.numerator(), den = q.denominator();
  if (!mpz_perfect_square_p(num.mpz()) || !mpz_perfect_square_p(den.mpz())) return false;
  CGAL::Gmpz rn, rd;
  mpz_sqrt(rn.mpz(), num.mpz());
  mpz_sqrt(rd.mpz(), den.mpz());
  root = CGAL::Gmpq(rn, rd);
  return true;
}

/// sqrt(x) in NT: rounded (std::sqrt) for floating NT, exact for rational NT when the root is
/// rational. Returns false when the root is not representable exactly in a rational NT.
template <class NT>
bool sqrt_in(const NT& x, NT& root) {
  if constexpr (Is_floating_nt<NT>::value) {
    const double d = CGAL::to_double(x);
    if (!(d >= 0)) return false;
    root = NT(std::sqrt(d));
    return true;
  } else {
    CGAL::Gmpq r;
    if (!exact_rational_sqrt(to_gmpq(x), r)) return false;
    root = from_gmpq<NT>(r);
    return true;
  }
}

/// An interval enclosing the exact value of x (CGAL::to_interval is certified for double,
/// Gmpq and Lazy_exact_nt).
template <class NT>
CGAL::Interval_nt<false> to_interval_nt(const NT& x) {
  return CGAL::Interval_nt<false>(CGAL::to_interval(x));
}

} // namespace common
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_COMMON_EXACT_CONVERSION_H
