// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// From a Kappa_curve_2's points and options to the solver's Problem (system.h): the data are
// translated and scaled to the box [-1,1]^2 (so 1e+150 and 1e-150 coordinates behave like unit
// ones; the residuals become dimensionless), the interior points of an open curve become the
// blocks and its end points the fixed ends, and the weight option its per-block values.

#ifndef FAIR_INTERNAL_KAPPA_PROBLEM_SETUP_H
#define FAIR_INTERNAL_KAPPA_PROBLEM_SETUP_H

#include <fair/Errors.h>
#include <fair/Kappa_curve_options.h>
#include <fair/Kappa_curve_report.h>
#include <fair/internal/kappa/system.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// x_normalised = (x - center) / scale: the bounding box of the points onto [-1,1]^2.
struct Normalisation {
  double center_x = 0, center_y = 0, scale = 0;
};

/// The bounding-box normalisation of the points q (in double) and their normalised coordinates
/// x, y. Invalid_input_error for a box of zero or non-finite size.
template <class Point>
Normalisation normalise(const std::vector<Point>& q, std::vector<double>& x, std::vector<double>& y) {
  const std::size_t m = q.size();
  x.resize(m);
  y.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    x[i] = CGAL::to_double(q[i].x());
    y[i] = CGAL::to_double(q[i].y());
  }
  const auto bx = std::minmax_element(x.begin(), x.end()), by = std::minmax_element(y.begin(), y.end());
  // Halves first: no overflow near DBL_MAX.
  Normalisation nz;
  nz.center_x = 0.5 * *bx.first + 0.5 * *bx.second;
  nz.center_y = 0.5 * *by.first + 0.5 * *by.second;
  nz.scale = std::max(0.5 * *bx.second - 0.5 * *bx.first, 0.5 * *by.second - 0.5 * *by.first);
  if (!(nz.scale > 0) || !std::isfinite(nz.scale))
    throw Invalid_input_error(message("Kappa_curve_2: degenerate bounding box (half size ", nz.scale, ")"));
  for (std::size_t i = 0; i < m; ++i) {
    x[i] = (x[i] - nz.center_x) / nz.scale;
    y[i] = (y[i] - nz.center_y) / nz.scale;
  }
  return nz;
}

/// The solver's problem for the normalised points (x, y) of a curve with these options: one
/// block per interpolated point (all points of a closed curve, the interior ones of an open
/// curve, whose first and last points are the fixed end points), the weights per block.
inline Problem make_problem(const std::vector<double>& x, const std::vector<double>& y,
                            const Kappa_curve_options& opt) {
  const std::size_t m = x.size();
  Problem pb;
  pb.closed = opt.closed;
  const std::size_t first = opt.closed ? 0 : 1;
  pb.n = opt.closed ? m : m - 2;
  pb.qx.assign(x.begin() + first, x.begin() + first + pb.n);
  pb.qy.assign(y.begin() + first, y.begin() + first + pb.n);
  if (!opt.closed) { pb.sx = x[0]; pb.sy = y[0]; pb.ex = x[m - 1]; pb.ey = y[m - 1]; }
  pb.clamp = opt.weight_clamp;
  pb.mode = opt.weights;
  if (opt.weights == Kappa_weights::FIXED)
    pb.weight.assign(opt.fixed_weights.begin() + first, opt.fixed_weights.begin() + first + pb.n);
  if (opt.weights == Kappa_weights::AUTOMATIC) {
    if (opt.tension.empty()) pb.tension.assign(pb.n, 1.0);
    else pb.tension.assign(opt.tension.begin() + first, opt.tension.begin() + first + pb.n);
  }
  return pb;
}

/// A state of a previous solve in normalisation `from`, expressed in normalisation `to`: the
/// offsets d_i are relative to Q_i, so only the scale changes.
inline Kappa_solver_state renormalised(Kappa_solver_state st, const Normalisation& from, const Normalisation& to) {
  const double f = from.scale / to.scale;
  for (double& d : st.dx) d *= f;
  for (double& d : st.dy) d *= f;
  return st;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_PROBLEM_SETUP_H
