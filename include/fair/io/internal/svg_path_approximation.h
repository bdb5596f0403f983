// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The certified cubic approximation of fair::io::svg_path (fair/io/write_svg_path.h, whose file
// comment derives the bound (B)): a rational or high-degree Bezier piece, as homogeneous
// Bernstein coefficients (w x, w y, w) in double, is replaced by Hermite cubics, halving the
// parameter interval until (B) plus its rounding term is within the tolerance.

#ifndef FAIR_IO_INTERNAL_SVG_PATH_APPROXIMATION_H
#define FAIR_IO_INTERNAL_SVG_PATH_APPROXIMATION_H

#include <fair/Errors.h>
#include <fair/io/internal/nearest_double.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace fair {
namespace io {
namespace internal {


typedef std::array<double, 3> Svg_homogeneous; // (w x, w y, w)

/// Binomial coefficient in double (degrees here are small).
inline double svg_binomial(std::size_t n, std::size_t k) {
  double b = 1;
  for (std::size_t i = 1; i <= k; ++i) b = b * double(n - k + i) / double(i);
  return b;
}

/// Splits the homogeneous Bernstein coefficients at s = 1/2.
inline void svg_split(const std::vector<Svg_homogeneous>& H, std::vector<Svg_homogeneous>& left,
                      std::vector<Svg_homogeneous>& right) {
  const std::size_t q = H.size() - 1;
  std::vector<Svg_homogeneous> b = H;
  left.assign(q + 1, {});
  right.assign(q + 1, {});
  left[0] = b[0];
  right[q] = b[q];
  for (std::size_t r = 1; r <= q; ++r) {
    for (std::size_t k = 0; k + r <= q; ++k)
      for (int c = 0; c < 3; ++c) b[k][c] = 0.5 * (b[k][c] + b[k + 1][c]);
    left[r] = b[0];
    right[q - r] = b[q - r];
  }
}

/// A cubic of the approximation: its Bezier points, standing for the local parameters [s0, s1]
/// of the piece (in [0, 1]), and its certified bound (B).
struct Svg_cubic {
  double s0 = 0, s1 = 1;
  std::array<std::array<double, 2>, 4> points{};
  double error_bound = 0;
};

/// The Hermite cubic of the (sub-)piece H and its bound (B) with the rounding term.
inline Svg_cubic svg_hermite(const std::vector<Svg_homogeneous>& H) {
  const std::size_t q = H.size() - 1;
  const double eps = std::numeric_limits<double>::epsilon();
  const std::array<double, 2> c0{H[0][0] / H[0][2], H[0][1] / H[0][2]};
  const std::array<double, 2> c1{H[q][0] / H[q][2], H[q][1] / H[q][2]};
  std::array<double, 2> d0, d1;
  for (int c = 0; c < 2; ++c) {
    d0[c] = double(q) * (H[1][c] - H[1][2] * c0[c]) / H[0][2];
    d1[c] = double(q) * (H[q - 1][2] * c1[c] - H[q - 1][c]) / H[q][2];
  }
  Svg_cubic s;
  s.points = {c0, {c0[0] + d0[0] / 3, c0[1] + d0[1] / 3}, {c1[0] - d1[0] / 3, c1[1] - d1[1] / 3}, c1};
  // E_k = (elevated A)_k - (W C)_k, k = 0 .. q + 3.
  const std::size_t m = q + 3;
  double max_e = 0, min_w = std::numeric_limits<double>::infinity(), max_a = 0, max_w = 0, max_c = 0;
  for (const Svg_homogeneous& h : H) {
    min_w = std::min(min_w, h[2]);
    max_w = std::max(max_w, h[2]);
    max_a = std::max(max_a, std::max(std::fabs(h[0]), std::fabs(h[1])));
  }
  for (const auto& p : s.points) max_c = std::max(max_c, std::max(std::fabs(p[0]), std::fabs(p[1])));
  for (std::size_t k = 0; k <= m; ++k) {
    std::array<double, 2> e{0, 0};
    const double bm = svg_binomial(m, k);
    // elevation of A (degree q) by 3: A_k^{(m)} = sum_i C(q,i) C(3,k-i) / C(m,k) A_i
    // product W C: (WC)_k = sum_{i+j=k} C(q,i) C(3,j) / C(m,k) W_i C_j
    for (std::size_t i = 0; i <= q; ++i) {
      if (i > k || k - i > 3) continue;
      const std::size_t j = k - i;
      const double f = svg_binomial(q, i) * svg_binomial(3, j) / bm;
      for (int c = 0; c < 2; ++c) e[c] += f * (H[i][c] - H[i][2] * s.points[j][c]);
    }
    max_e = std::max(max_e, std::hypot(e[0], e[1]));
  }
  const double rounding = 32 * double(q + 4) * eps * (max_a + max_w * max_c);
  s.error_bound = (max_e + rounding) / min_w;
  return s;
}

/// The cubics of the (sub-)piece H, on [t0, t1] of the piece's local parameter: the Hermite
/// cubic if its bound is within the tolerance, else those of the two halves (depth: halvings so far).
inline void svg_approximate(const std::vector<Svg_homogeneous>& H, std::size_t piece, double t0, double t1,
                            double tolerance, int depth, std::vector<Svg_cubic>& out) {
  Svg_cubic s = svg_hermite(H);
  if (s.error_bound <= tolerance) {
    s.s0 = t0;
    s.s1 = t1;
    out.push_back(s);
    return;
  }
  constexpr int max_depth = 40;
  if (depth >= max_depth)
    throw Non_convergence_error("fair::io::svg_path: piece " + std::to_string(piece) + " needs more than " +
                                    std::to_string(max_depth) + " halvings for the tolerance",
                                static_cast<std::size_t>(depth), s.error_bound);
  std::vector<Svg_homogeneous> left, right;
  svg_split(H, left, right);
  const double tm = 0.5 * (t0 + t1);
  svg_approximate(left, piece, t0, tm, tolerance, depth + 1, out);
  svg_approximate(right, piece, tm, t1, tolerance, depth + 1, out);
}

inline std::string svg_number(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v == 0 ? 0.0 : v);
  return buffer;
}

template <class FT>
double svg_finite(const FT& x, std::size_t piece, const char* what) {
  const double d = nearest_double_of(x);
  if (!std::isfinite(d))
    throw Precondition_error("fair::io::svg_path: piece " + std::to_string(piece) + ": a " + what +
                             " is not finite as a double");
  return d;
}

} // namespace internal
} // namespace io
} // namespace fair

#endif // FAIR_IO_INTERNAL_SVG_PATH_APPROXIMATION_H
