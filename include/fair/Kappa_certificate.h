// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Certification of kappa-curves: fair::certify(curve) and fair::certify_pieces(curve), and
// fair::Kappa_certificate, what they certified about a fair::Kappa_curve_2, exactly or by
// outward-rounded intervals. Include this header to certify; Kappa_curve_2.h alone does not pull
// in the exact machinery (GMP integers, interval filters). How it is computed:
// include/fair/internal/kappa/certify.h and doc/kappa_curves.md.

#ifndef FAIR_KAPPA_CERTIFICATE_H
#define FAIR_KAPPA_CERTIFICATE_H

#include <fair/Kappa_curve_2.h>
#include <fair/internal/kappa/certificate_record.h>
#include <fair/internal/kappa/certify.h>


namespace fair {

/// Certifies `curve` exactly: the exact curve defined by the solver's rational lambda_i, t_i,
/// w_i (doubles, i.e. exact dyadic rationals; state()) and the exact input points, with eq. 18
/// solved exactly and fraction-free. Returns the Kappa_certificate: Q_i == c_i(t_i), C0 and G1
/// exactly; the number and kind of curvature extrema of each piece and the distance of the
/// nearest one to t_i; the relative |kappa| mismatch at each join by outward-rounded intervals;
/// the exact pieces in Kappa_certificate::Exact_kernel; the outcome and the points on joins of
/// report(). Use Kappa_certificate::proves_outcome() (valid() for INTERIOR, valid_on_joins()
/// for ON_JOINS).
/// Any kernel (its numbers are converted exactly). Complexity: O(n) products of O(n)-bit
/// numbers (the exact control points have ~150 n bits), O(n M(n)) bit operations; timings in
/// doc/benchmarks.md. \throws Internal_error if the exact elimination meets a zero pivot
/// (impossible for the 0 < lambda_i, t_i < 1, w_i > 0 of a Kappa_curve_2).
template <class K>
Kappa_certificate certify(const Kappa_curve_2<K>& curve) {
  Kappa_certificate c = internal::kappa::certify_curve(curve, internal::kappa::Certify_mode::FILTERED);
  c.status = curve.report().status;
  c.points_on_joins = curve.report().points_on_joins;
  return c;
}

/// Certifies the pieces that `curve` returns, piece by piece in O(n): their exact control
/// points (in an exact kernel: P_j the solver's rounded P_{j,1}, E_j = (1 - lambda_j) P_{j-1} +
/// lambda_j P_j formed exactly, so C0 and G1 hold exactly by construction and are verified),
/// the parameters t_j, and the exact input points. What is certified, exactly or by outward
/// rounded intervals: C0 and G1 at every join; |c_j(t_j) - Q_j| <= interpolation_error (not 0:
/// the P_j carry the rounding of the solve, ~1e-16 relative); the number and kind of curvature
/// extrema of each piece and the distance of the nearest one to t_j; the relative |kappa|
/// mismatch at each join. Use Kappa_certificate::valid_within(). With a floating-point kernel
/// the pieces' E_j are rounded, and G1 generally fails exactly (as it is reported).
template <class K>
Kappa_certificate certify_pieces(const Kappa_curve_2<K>& curve) {
  Kappa_certificate c = internal::kappa::certify_returned_pieces(curve);
  c.status = curve.report().status;
  c.points_on_joins = curve.report().points_on_joins;
  return c;
}

} // namespace fair

#endif // FAIR_KAPPA_CERTIFICATE_H
