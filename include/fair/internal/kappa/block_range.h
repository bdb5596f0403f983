// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The blocks a solve works on (Block_range: all, or a contiguous range around an edited point
// for the local warm start) and the operations on them shared by Newton's method and
// Levenberg-Marquardt: a projected step, the residuals of the range.

#ifndef FAIR_INTERNAL_KAPPA_BLOCK_RANGE_H
#define FAIR_INTERNAL_KAPPA_BLOCK_RANGE_H

#include <fair/internal/kappa/solve_settings.h>
#include <fair/internal/kappa/system.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace kappa {

/// The blocks a (local) Levenberg-Marquardt solve works on: all, or the cyclic (closed) /
/// clipped (open) range first, first+1, ..., first+count-1. In a range solve only the unknowns
/// of these blocks vary and only their residuals are minimised; the others stay fixed.
struct Block_range {
  bool all = true;
  std::size_t first = 0, count = 0;
}; 

/// Block of the ii-th unknown block of a range.
inline std::size_t range_block(const Problem& pb, const Block_range& range, std::size_t ii) {
  return range.all ? ii : (range.first + ii) % pb.n;
}

/// trial = st + alpha * delta on the blocks of `range`, the unknowns of the ii-th block at
/// delta[4 pos(ii) ...], projected onto the bounds.
template <class Position>
void stepped_state(const Problem& pb, const Block_range& range, const Kappa_solver_state& st, const std::vector<double>& delta,
                   double alpha, Position pos, Kappa_solver_state& trial) {
  trial = st;
  const std::size_t na = range.all ? pb.n : range.count;
  for (std::size_t ii = 0; ii < na; ++ii) {
    const std::size_t i = range_block(pb, range, ii), p = 4 * pos(ii);
    trial.dx[i] += alpha * delta[p];
    trial.dy[i] += alpha * delta[p + 1];
    trial.lambda[i] += alpha * delta[p + 2];
    trial.t[i] += alpha * delta[p + 3];
  }
  project_bounds(trial);
}

/// The residuals of the blocks of `range` (all: evaluate()) into F; returns max |r|.
inline double evaluate_range(const Problem& pb, const Kappa_solver_state& s, const Block_range& range, std::vector<double>& F) {
  if (range.all) return evaluate(pb, s, F);
  F.resize(4 * range.count);
  Window<double> win;
  double mx = 0;
  for (std::size_t ii = 0; ii < range.count; ++ii) {
    const std::size_t i = range_block(pb, range, ii);
    build_window(pb, s, i, win);
    double r[4];
    block_residuals(pb, s, i, win, r);
    for (int c = 0; c < 4; ++c) {
      F[4 * ii + c] = r[c];
      const double a = std::abs(r[c]);
      mx = (a > mx || std::isnan(a)) ? a : mx;
    }
  }
  return mx;
}

} // namespace kappa
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_KAPPA_BLOCK_RANGE_H
