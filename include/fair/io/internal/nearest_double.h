// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// nearest_double_of(x): the double nearest to a kernel number (ties to even), for the writers
// whose formats hold doubles only (DXF, SVG paths). CGAL::to_double is not that in the exact
// kernels (measured, CGAL 5.5): for CGAL::Gmpq it truncates towards zero (mpq_get_d: 1/10 gives
// 0.099999999999999992, one ulp below the nearest 0.10000000000000001), and for EPECK's
// Lazy_exact_nt it is the midpoint of the interval approximation, which after x.exact() is the
// rounding of the midpoint of the two neighbours (1/3 gives 0.33333333333333337, the upper
// one, where the nearest is 0.33333333333333331) and before it may be several ulps off (1/1000
// as a lazy sum of thousandths gave 0.00099999999999998701). Here:
//   - double: itself;
//   - CGAL::Gmpq, mpq_class: fair::io::internal::nearest_double (number_parsing.h), exact;
//   - a lazy number (EPECK's FT): its exact value, then as above;
//   - any other number type: CGAL::to_double (no stronger claim can be made for it).
// A value beyond the double range gives +-inf (the writers refuse it by name); a non-zero value
// below the smallest subnormal gives +-0.

#ifndef FAIR_IO_INTERNAL_NEAREST_DOUBLE_H
#define FAIR_IO_INTERNAL_NEAREST_DOUBLE_H

#include <fair/io/parsing.h>  // fair::io::internal::nearest_double, Lazy_exact_type

#include <CGAL/Gmpq.h>
#include <CGAL/number_utils.h>

#include <type_traits>

#ifdef CGAL_USE_GMPXX
#include <gmpxx.h>
#endif

namespace fair {
namespace io {
namespace internal {

template <class FT>
double nearest_double_of(const FT& x) {
  if constexpr (std::is_floating_point<FT>::value) {
    return static_cast<double>(x);
  } else if constexpr (std::is_same<FT, CGAL::Gmpq>::value) {
    Rational_rounding status;
    return nearest_double(x, status);
#ifdef CGAL_USE_GMPXX
  } else if constexpr (std::is_same<FT, mpq_class>::value) {
    CGAL::Gmpq q;
    mpq_set(q.mpq(), x.get_mpq_t());
    return nearest_double_of(q);
#endif
  } else if constexpr (!std::is_void<typename Lazy_exact_type<FT>::type>::value) {
    return nearest_double_of(x.exact());
  } else {
    return CGAL::to_double(x);
  }
}

} // namespace internal
} // namespace io
} // namespace fair

#endif // FAIR_IO_INTERNAL_NEAREST_DOUBLE_H
