// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The one linear (affine, when the coefficients sum to 1) combination of points of the library,
// coordinate by coordinate in the kernel's FT (exact in an exact kernel). Used by the classic
// baselines, the parametric construction (eq. 7) and the quadratic design (eq. 12).

#ifndef FAIR_INTERNAL_COMMON_COMBINATION_H
#define FAIR_INTERNAL_COMMON_COMBINATION_H

namespace fair {
namespace internal {
namespace common {

/// a p + b q + c r (affine when a + b + c = 1).
template <class K>
typename K::Point_2 combine(const typename K::FT& a, const typename K::Point_2& p, const typename K::FT& b,
                            const typename K::Point_2& q, const typename K::FT& c, const typename K::Point_2& r) {
  return typename K::Point_2(a * p.x() + b * q.x() + c * r.x(), a * p.y() + b * q.y() + c * r.y());
}

/// a p + b q + c r + d s (affine when a + b + c + d = 1).
template <class K>
typename K::Point_2 combine(const typename K::FT& a, const typename K::Point_2& p, const typename K::FT& b,
                            const typename K::Point_2& q, const typename K::FT& c, const typename K::Point_2& r,
                            const typename K::FT& d, const typename K::Point_2& s) {
  return typename K::Point_2(a * p.x() + b * q.x() + c * r.x() + d * s.x(), a * p.y() + b * q.y() + c * r.y() + d * s.y());
}

} // namespace common
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_COMMON_COMBINATION_H
