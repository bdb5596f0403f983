// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Exact conversion of a kernel's number type to the rational type of a CGAL arrangement traits
// class (CORE::BigRat, CGAL::Gmpq, mpq_class, boost's gmp_rational), through GMP's mpq: a double
// is a dyadic rational and converts exactly (mpq_set_d), an exact type (Gmpq, mpq_class when
// CGAL_USE_GMPXX, boost's gmp_rational, EPECK's Lazy_exact_nt of any of them) gives its exact
// value. Nothing is rounded, so
// two coordinates that are equal in FT are equal rationals: the shared joints of the pieces of
// a Nurbs_curve_2 stay shared in the arrangement.

#ifndef FAIR_CGAL_INTERNAL_EXACT_RATIONAL_H
#define FAIR_CGAL_INTERNAL_EXACT_RATIONAL_H

#include <CGAL/Gmpq.h>
#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/number_utils.h>

#include <boost/multiprecision/gmp.hpp>
#ifdef CGAL_USE_GMPXX
#include <gmpxx.h>
#endif

#include <type_traits>

namespace fair {
namespace internal {
namespace arrangement {

inline CGAL::Gmpq to_gmpq(double x) { return CGAL::Gmpq(x); }
inline CGAL::Gmpq to_gmpq(float x) { return CGAL::Gmpq(static_cast<double>(x)); }
inline CGAL::Gmpq to_gmpq(int x) { return CGAL::Gmpq(x); }
inline CGAL::Gmpq to_gmpq(const CGAL::Gmpq& x) { return x; }
template <boost::multiprecision::expression_template_option E>
CGAL::Gmpq to_gmpq(const boost::multiprecision::number<boost::multiprecision::gmp_rational, E>& x) {
  return CGAL::Gmpq(x.backend().data());
}
#ifdef CGAL_USE_GMPXX
inline CGAL::Gmpq to_gmpq(const mpq_class& x) { return CGAL::Gmpq(x.get_mpq_t()); }
#endif
template <class ET>
CGAL::Gmpq to_gmpq(const CGAL::Lazy_exact_nt<ET>& x) {
  return to_gmpq(CGAL::exact(x));
}

/// x as the rational type `Rational`, exactly (any type constructible from GMP's mpq_srcptr).
template <class Rational, class FT>
Rational exact_rational(const FT& x) {
  const CGAL::Gmpq q = to_gmpq(x);
  if constexpr (std::is_same<Rational, CGAL::Gmpq>::value) {
    return q;
  } else {
    static_assert(std::is_constructible<Rational, mpq_srcptr>::value,
                  "fair::to_arrangement_curves: the traits' Rational must be constructible from a GMP mpq");
    return Rational(q.mpq());
  }
}

}  // namespace arrangement
}  // namespace internal
}  // namespace fair

#endif  // FAIR_CGAL_INTERNAL_EXACT_RATIONAL_H
