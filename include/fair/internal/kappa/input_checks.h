// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The checks of a Kappa_curve_2's input before a solve: the points (fair::internal::common
// checks, plus "not all collinear": every piece would be a segment, which is not a conic arc)
// and the options (weights, tension, clamp, tolerance).

#ifndef FAIR_INTERNAL_KAPPA_INPUT_CHECKS_H
#define FAIR_INTERNAL_KAPPA_INPUT_CHECKS_H

#include <fair/Errors.h>
#include <fair/Kappa_curve_options.h>
#include <fair/internal/common/input_checks.h>

#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// Fewest input points of a kappa-curve: one interior point between the two end points of an
/// open curve, a triangle for a closed one.
constexpr std::size_t minimum_points = 3;

/// Range of FIXED weights, AUTOMATIC tension and clamp: w^2 lambda^2 of eq. 10 and w^3 of eq. 4
/// stay normal doubles (a subnormal weight gave 0/0 in the abs(kappa) mismatch; fuzz finding).
constexpr double minimum_weight = 1e-12;
constexpr double maximum_weight = 1e12;

/// Whether v is a weight-like option value in [minimum_weight, maximum_weight].
inline bool weight_in_range(double v) { return v >= minimum_weight && v <= maximum_weight; }

/// The options that apply to m input points: FIXED weights, AUTOMATIC tension and clamp
/// (Invalid_input_error), the tolerance (Precondition_error).
inline void check_options(const Kappa_curve_options& opt, std::size_t m, const char* fn) {
  if (opt.weights == Kappa_weights::FIXED) {
    if (opt.fixed_weights.size() != m)
      throw Invalid_input_error(message(fn, ": FIXED weights need one weight per point (", m, "), got ",
                                        opt.fixed_weights.size()));
    for (std::size_t i = 0; i < m; ++i)
      if (!weight_in_range(opt.fixed_weights[i]))
        throw Invalid_input_error(message(fn, ": weight ", i, " = ", opt.fixed_weights[i], " must be finite and > 0 (in [",
                                          minimum_weight, ", ", maximum_weight, "])"));
  }
  if (opt.weights == Kappa_weights::AUTOMATIC) {
    if (!opt.tension.empty() && opt.tension.size() != m)
      throw Invalid_input_error(message(fn, ": tension needs one value per point (", m, "), got ", opt.tension.size()));
    for (std::size_t i = 0; i < opt.tension.size(); ++i)
      if (!weight_in_range(opt.tension[i]))
        throw Invalid_input_error(message(fn, ": tension ", i, " = ", opt.tension[i], " must be finite and > 0 (in [",
                                          minimum_weight, ", ", maximum_weight, "])"));
    if (!weight_in_range(opt.weight_clamp))
      throw Invalid_input_error(message(fn, ": weight clamp ", opt.weight_clamp, " must be finite and > 0 (in [",
                                        minimum_weight, ", ", maximum_weight, "])"));
  }
  require(std::isfinite(opt.tolerance) && opt.tolerance >= 0, fn, ": tolerance ", opt.tolerance,
          " must be finite and >= 0");
}

/// Invalid_input_error if all points are collinear (exactly, in the kernel K): every piece
/// would be a straight segment, which is not a conic piece.
template <class K>
void check_not_collinear(const std::vector<typename K::Point_2>& q, const char* fn) {
  const std::size_t m = q.size();
  // The point farthest (L1, in double) from q[0] spans the line with it.
  std::size_t far = 1;
  double best = -1;
  const double x0 = CGAL::to_double(q[0].x()), y0 = CGAL::to_double(q[0].y());
  for (std::size_t i = 1; i < m; ++i) {
    const double d = std::abs(CGAL::to_double(q[i].x()) - x0) + std::abs(CGAL::to_double(q[i].y()) - y0);
    if (d > best) { best = d; far = i; }
  }
  const typename K::Orientation_2 orient = K().orientation_2_object();
  for (std::size_t i = 1; i < m; ++i)
    if (orient(q[0], q[far], q[i]) != CGAL::COLLINEAR) return;
  throw Invalid_input_error(message(
      fn, ": all ", m, " points are collinear (through (", x0, ", ", y0, ") and (", CGAL::to_double(q[far].x()),
      ", ", CGAL::to_double(q[far].y()), ")): a kappa-curve would consist of straight segments, which are not ",
      "conic pieces; use the polyline"));
}

/// Largest extent (max |q_i - q_0| over both coordinates) of the input: the solve forms squared
/// lengths of the control triangles, which overflow beyond about 1e154 (points scaled by 1e155,
/// an extent of 6e155, were called "locally collinear", issue 29 #20); inputs at scale 1e150
/// (extents up to 2.5e150) solve and certify (test_kappa, test_kappa_certify). 1e152 keeps a
/// factor 1e4 of headroom in the squares. kappa-curves are invariant under scaling, so the
/// message asks for scaled input.
constexpr double maximum_extent = 1e152;

template <class K>
void check_extent(const std::vector<typename K::Point_2>& q, const char* fn) {
  const double x0 = CGAL::to_double(q[0].x()), y0 = CGAL::to_double(q[0].y());
  double extent = 0;
  for (const auto& p : q)
    extent = std::max({extent, std::abs(CGAL::to_double(p.x()) - x0), std::abs(CGAL::to_double(p.y()) - y0)});
  if (!(extent <= maximum_extent))
    throw Invalid_input_error(message(fn, ": the points span ", extent, ", beyond ", maximum_extent,
                                      ", where the squared lengths of the solve overflow double; kappa-curves do not "
                                      "depend on the scale: scale the input down"));
}

/// All checks of a Kappa_curve_2's points and options before a solve.
template <class K>
void check_curve_input(const std::vector<typename K::Point_2>& q, const Kappa_curve_options& options) {
  const char* fn = "Kappa_curve_2";
  common::check_interpolation_input(q, minimum_points, options.closed, fn);
  check_options(options, q.size(), fn);
  check_extent<K>(q, fn);
  check_not_collinear<K>(q, fn);
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_INPUT_CHECKS_H
