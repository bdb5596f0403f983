// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact conversions of the number types the library accepts: the exact rational value of a
// kernel number or polynomial coefficient as a CGAL::Gmpq (to_gmpq), and back (from_gmpq), and
// the exact square root of a rational when it is rational. The certified algorithms (root
// isolation, curvature extrema, kappa certificates, fairness metrics) run on the exact rational
// values of the inputs, whatever the kernel: a double coordinate is the dyadic rational it
// stores, and so are a CGAL::Gmpfr and a point CGAL::Interval_nt.
//
// The one gmpxx test is CGAL_USE_GMPXX: CGAL itself uses mpq_class (EPECK's exact type, and
// <CGAL/mpq_class.h>) exactly when it is defined; otherwise EPECK's exact type is CGAL::Gmpq or
// boost::multiprecision's GMP rational (CGAL 5.5 picks by configuration), both covered here.

#ifndef FAIR_INTERNAL_COMMON_EXACT_CONVERSION_H
#define FAIR_INTERNAL_COMMON_EXACT_CONVERSION_H

#include <fair/Errors.h>

#include <CGAL/Gmpfr.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/number_utils.h>
#ifdef CGAL_USE_GMPXX
#include <CGAL/mpq_class.h>
#endif

#include <boost/multiprecision/gmp.hpp>

#include <cmath>
#include <type_traits>
#include <gmp.h>

namespace fair {
namespace internal {
namespace common {

// Every overload takes the name of the calling function for the error message.

/// The exact rational value of x. \throws Precondition_error for a non-finite double.
inline CGAL::Gmpq to_gmpq(double x, const char* context = "to_gmpq") {
  require(std::isfinite(x), context, ": the value ", x, " is not finite");
  return CGAL::Gmpq(x);
}
inline CGAL::Gmpq to_gmpq(int x, const char* = "to_gmpq") { return CGAL::Gmpq(x); }
inline CGAL::Gmpq to_gmpq(const CGAL::Gmpq& x, const char* = "to_gmpq") { return x; }
/// \throws Precondition_error for NaN or an infinity.
inline CGAL::Gmpq to_gmpq(const CGAL::Gmpfr& x, const char* context = "to_gmpq") {
  require(x.is_number(), context, ": the value ", x, " is not finite");
  return CGAL::Gmpq(x);
}
/// A point interval [x, x] is the number x. \throws Precondition_error for a wider interval
/// (certified algorithms are about one number, not a range) or a non-finite end.
template <bool Protected>
CGAL::Gmpq to_gmpq(const CGAL::Interval_nt<Protected>& x, const char* context = "to_gmpq") {
  require(x.inf() == x.sup(), context, ": the interval [", x.inf(), ", ", x.sup(),
          "] is not a single number; certified results are about one exact number, so pass point "
          "intervals or exact values");
  return to_gmpq(x.inf(), context);
}
/// boost::multiprecision's GMP rational (an exact type of EPECK, see the file comment).
template <boost::multiprecision::expression_template_option E>
CGAL::Gmpq to_gmpq(const boost::multiprecision::number<boost::multiprecision::gmp_rational, E>& x,
                   const char* = "to_gmpq") {
  return CGAL::Gmpq(x.backend().data());
}
#ifdef CGAL_USE_GMPXX
inline CGAL::Gmpq to_gmpq(const mpq_class& x, const char* = "to_gmpq") { return CGAL::Gmpq(x.get_mpq_t()); }
#endif
/// Lazy exact numbers (EPECK's FT): the exact value, computed on demand.
template <class ET>
CGAL::Gmpq to_gmpq(const CGAL::Lazy_exact_nt<ET>& x, const char* context = "to_gmpq") {
  return to_gmpq(x.exact(), context);
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
template <boost::multiprecision::expression_template_option E>
struct From_gmpq<boost::multiprecision::number<boost::multiprecision::gmp_rational, E>> {
  boost::multiprecision::number<boost::multiprecision::gmp_rational, E> operator()(const CGAL::Gmpq& q) const {
    boost::multiprecision::number<boost::multiprecision::gmp_rational, E> r;
    mpq_set(r.backend().data(), q.mpq());
    return r;
  }
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
