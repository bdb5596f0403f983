// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The Hessian of the optimal-curve functional (functional.h) in the vertex coordinates
// (x_0, y_0, x_1, y_1, ...): a symmetric band matrix of 2x2 vertex blocks, cyclic for closed
// curves, stored by the rule of linear_algebra/symmetric_band.h (doc/optimal_curves.md, "Banded
// solve"). The Newton system itself is its scalar reduction (reduced_system.h).

#ifndef FAIR_INTERNAL_OPTIMAL_HESSIAN_H
#define FAIR_INTERNAL_OPTIMAL_HESSIAN_H

#include <fair/internal/linear_algebra/symmetric_band.h>

#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace optimal {

using linear_algebra::Banded_symmetric;
using linear_algebra::solve_banded_positive_definite;

/// Symmetric block-banded (cyclic if closed) matrix of 2x2 vertex blocks, half-bandwidth w in vertices:
/// the Hessian of the functional in the coordinates (x_0, y_0, x_1, y_1, ...). Block (i, i) is stored in
/// full (both off-diagonal entries); block (j, i) is the transpose of block (i, j).
class Block_banded_hessian {
public:
  /// Zero matrix of `vertices` x `vertices` blocks.
  void reset(std::size_t vertices, std::size_t half_bandwidth, bool cyclic) {
    layout_.reset(vertices, half_bandwidth, cyclic);
    data_.assign(layout_.slots() * 4, 0.0);
  }
  std::size_t vertices() const { return layout_.n; }
  std::size_t half_bandwidth() const { return layout_.w; }
  bool cyclic() const { return layout_.cyclic; }
  /// Whether block (i, j) lies within the band (cyclic distance <= w).
  bool in_band(std::size_t i, std::size_t j) const { return layout_.in_band(i, j); }
  /// Entry (row, col) of block (i, j), i.e. d^2 F / d c_i[row] d c_j[col]; Internal_error outside the band.
  double& at(std::size_t i, std::size_t j, int row, int col) {
    bool t;
    const std::size_t s = layout_.slot(i, j, t);
    return data_[s * 4 + (t ? col * 2 + row : row * 2 + col)];
  }
  double at(std::size_t i, std::size_t j, int row, int col) const {
    bool t;
    const std::size_t s = layout_.slot(i, j, t);
    return data_[s * 4 + (t ? col * 2 + row : row * 2 + col)];
  }
  /// Adds the 2x2 block b (row-major) to block (i, j) (one slot lookup for the four entries).
  void add_block(std::size_t i, std::size_t j, const double b[4]) {
    bool t;
    double* d = &data_[layout_.slot(i, j, t) * 4];
    if (t) {
      d[0] += b[0];
      d[1] += b[2];
      d[2] += b[1];
      d[3] += b[3];
    } else {
      for (int k = 0; k < 4; ++k) d[k] += b[k];
    }
  }

private:
  linear_algebra::Band_layout layout_;
  std::vector<double> data_;
};

}  // namespace optimal
}  // namespace internal
}  // namespace fair

#endif  // FAIR_INTERNAL_OPTIMAL_HESSIAN_H
