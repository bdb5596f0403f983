// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The checks of Optimal_curve_2's data and options before the solve (doc/optimal_curves.md,
// "Errors"): typed errors naming the offending point, value or option.

#ifndef FAIR_INTERNAL_OPTIMAL_INPUT_CHECKS_H
#define FAIR_INTERNAL_OPTIMAL_INPUT_CHECKS_H

#include <fair/Errors.h>
#include <fair/Optimal_curve_options.h>
#include <fair/internal/common/checks.h>
#include <fair/internal/optimal/vec2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

/// The shortest edge between consecutive data points, as a fraction of the data's chord length,
/// that check_solve_input accepts (2^-40, about 9.1e-13): the spline fits of the polygon fail at a
/// few ulps of the length, and this keeps a margin of about 2^13.
constexpr double resolved_edge_fraction = 0x1p-40;

/// Checks the data and options (typed errors naming the value).
inline void check_solve_input(const std::vector<Vec2>& p, const Optimal_curve_options& o) {
  const char* fn = "fair::Optimal_curve_2";
  const std::size_t minimum = o.closed ? 3 : 2;
  if (p.size() < minimum)
    throw Invalid_input_error(message(fn, ": needs at least ", minimum, " points for a", o.closed ? " closed" : "n open",
                                      " curve, got ", p.size()));
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!std::isfinite(p[i][0]) || !std::isfinite(p[i][1]))
      throw Invalid_input_error(message(fn, ": point ", i, " = (", p[i][0], ", ", p[i][1], ") has a non-finite coordinate"));
  const std::size_t pairs = o.closed ? p.size() : p.size() - 1;
  for (std::size_t i = 0; i < pairs; ++i) {
    const std::size_t j = (i + 1) % p.size();
    if (p[i][0] == p[j][0] && p[i][1] == p[j][1])
      throw Invalid_input_error(message(fn, ": consecutive points ", i, " and ", j, " coincide at (", p[i][0], ", ", p[i][1], ")"));
  }
  // Points distinct in double but closer than about 1e-12 of the data's chord length: the polygon's
  // chord parameters (spline_fit.h, chord_breakpoints) and the spline systems built on their
  // powers of 1/h fail a few ulps of the length (a fuzz finding of session 19: an edge 2e-16 of
  // the length); 2^-40 keeps a margin of about 2^13 above that. Where the differences or their
  // sum overflow (coordinates near 1e308; review R19: the check was skipped there) the edges are
  // measured again in units of a power of two near the largest coordinate (exact division). Only
  // then: at ordinary extents those units would send tiny edges into the subnormal range, where
  // the comparison fails (review R20).
  double unit = 1;
  auto edge_in_units = [&](std::size_t i) {
    const std::size_t j = (i + 1) % p.size();
    return std::hypot(p[j][0] / unit - p[i][0] / unit, p[j][1] / unit - p[i][1] / unit);
  };
  auto chord_length = [&] {
    double length = 0;
    for (std::size_t i = 0; i < pairs; ++i) length += edge_in_units(i);
    return length;
  };
  double length = chord_length();
  if (!std::isfinite(length)) {
    double largest = 0;
    for (const Vec2& q : p) largest = std::max(largest, std::max(std::abs(q[0]), std::abs(q[1])));
    unit = std::ldexp(1.0, std::ilogb(largest));  // largest > 0: consecutive points differ
    length = chord_length();
  }
  for (std::size_t i = 0; i < pairs; ++i) {
    const std::size_t j = (i + 1) % p.size();
    const double d = edge_in_units(i);
    if (d / resolved_edge_fraction < length)  // d * 2^40, exact: no underflow at subnormal extents
      throw Invalid_input_error(message(fn, ": consecutive points ", i, " = (", p[i][0], ", ", p[i][1], ") and ", j, " = (",
                                        p[j][0], ", ", p[j][1], ") are ", d / length, " of the data's chord length apart",
                                        " (less than ", resolved_edge_fraction,
                                        "): too close to be resolved reliably in double; merge them"));
  }
  auto weight = [&](double w, const char* name) {
    require(std::isfinite(w) && w >= 0, fn, ": ", name, " = ", w, " must be finite and >= 0");
  };
  weight(o.length_weight, "length_weight (beta)");
  weight(o.curvature_weight, "curvature_weight (beta_0)");
  require(std::isfinite(o.curvature_exponent) && o.curvature_exponent >= 1, fn, ": curvature_exponent (alpha_0) = ",
          o.curvature_exponent, " must be >= 1");
  bool derivative = false;
  for (int k = 1; k <= 4; ++k) {
    weight(o.derivative_weight[k], "derivative_weight (beta_k)");
    require(std::isfinite(o.derivative_exponent[k]) && o.derivative_exponent[k] >= 1, fn, ": derivative_exponent[", k,
            "] (alpha_k) = ", o.derivative_exponent[k], " must be >= 1");
    derivative = derivative || o.derivative_weight[k] > 0;
  }
  require(std::isfinite(o.lambda_length_scale) && o.lambda_length_scale >= 0, fn, ": lambda_length_scale (q) = ",
          o.lambda_length_scale, " must be finite and >= 0 (0 = q(eta) of eq. 12)");
  require(o.lambda == -1 || (o.lambda >= 0 && o.lambda <= 1), fn, ": lambda = ", o.lambda, " must be in [0, 1] (or -1 = off)");
  if (!o.segment_lambda.empty()) {
    const std::size_t segments = o.closed ? p.size() : p.size() - 1;
    require(o.segment_lambda.size() == segments, fn, ": segment_lambda has ", o.segment_lambda.size(),
            " values, the curve has ", segments, " segments");
    for (std::size_t i = 0; i < segments; ++i)
      require(o.segment_lambda[i] >= 0 && o.segment_lambda[i] <= 1, fn, ": segment_lambda[", i, "] = ",
              o.segment_lambda[i], " must be in [0, 1]");
  }
  const bool lambda_design = o.lambda != -1 || !o.segment_lambda.empty();
  require(lambda_design || derivative || o.length_weight > 0 || o.curvature_weight > 0, fn,
          ": every weight is zero (length_weight = curvature_weight = 0, no derivative_weight): F = 0 has no minimiser");
  require(std::isfinite(o.resolution) && o.resolution > 0, fn, ": resolution = ", o.resolution, " must be > 0");
  require(o.resolution <= max_optimal_resolution, fn, ": resolution = ", o.resolution, " exceeds the cap ",
          max_optimal_resolution, " (fair::max_optimal_resolution; doc/optimal_curves.md)");
  require(std::isfinite(o.tolerance) && o.tolerance > 0, fn, ": tolerance = ", o.tolerance, " must be > 0");
  require(o.max_vertices >= 1, fn, ": max_vertices = ", o.max_vertices, " must be >= 1");
  require(o.max_levels >= 1 && o.max_iterations_per_level >= 1, fn, ": max_levels = ", o.max_levels,
          " and max_iterations_per_level = ", o.max_iterations_per_level, " must be >= 1");
}

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_INPUT_CHECKS_H
