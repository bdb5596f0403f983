// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Bicubic C2 tensor-product nets <-> grids of bicubic Bezier patches (Karciauskas & Peters,
// eq. 11; derivation in doc/surfaces_of_revolution.md).
//
// Both maps are tensor products of the curve maps of internal/spline/bspline_form.h (eq. 3 from
// pieces to control points, eq. 2 back, with the eq.-10 end points of an open direction), which
// are linear and act on each scalar coordinate of the coefficients separately. So a coefficient
// of any dimension is cut into chunks of three coordinates, each chunk is carried through the
// curve maps as one spline::Homogeneous_point (its x, y, w slots simply hold three coordinates),
// and the chunks are put back together: one implementation of eqs. 2 and 3 for curves and
// surfaces. Applying the curve map along v for every row of coefficients and then along u for
// every column is eq. 11 in the interior (the two maps commute: they act on different indices).

#ifndef FAIR_INTERNAL_TENSOR_NET_H
#define FAIR_INTERNAL_TENSOR_NET_H

#include <fair/Errors.h>
#include <fair/internal/spline/bspline_form.h>

#include <array>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace tensor {

/// The pieces of one curve: four Bezier coefficients each.
template <class V>
using Curve_pieces = std::vector<std::array<V, 4>>;

template <class Traits>
constexpr std::size_t chunks() {
  return (Traits::dimension + 2) / 3;
}

template <class Traits, class V>
spline::Homogeneous_point<typename Traits::FT> chunk(const V& v, std::size_t c) {
  typedef typename Traits::FT FT;
  FT x[3] = {FT(0), FT(0), FT(0)};
  for (std::size_t a = 0; a < 3 && 3 * c + a < Traits::dimension; ++a) x[a] = Traits::coordinate(v, 3 * c + a);
  return spline::Homogeneous_point<FT>{x[0], x[1], x[2]};
}

template <class Traits>
typename Traits::Coefficient assemble(const std::vector<spline::Homogeneous_point<typename Traits::FT>>& parts) {
  std::array<typename Traits::FT, Traits::dimension> x;
  for (std::size_t k = 0; k < Traits::dimension; ++k) {
    const spline::Homogeneous_point<typename Traits::FT>& p = parts[k / 3];
    x[k] = (k % 3 == 0) ? p.x : ((k % 3 == 1) ? p.y : p.w);
  }
  return Traits::make(x);
}

/// eq. 3 (+ eq. 10 ends): the control points of the C2 spline with these pieces.
template <class Traits>
std::vector<typename Traits::Coefficient> control_from_pieces(const std::vector<typename Traits::FT>& breakpoints,
                                                              const Curve_pieces<typename Traits::Coefficient>& pieces,
                                                              bool closed) {
  typedef typename Traits::FT FT;
  typedef spline::Homogeneous_point<FT> H;
  std::vector<std::vector<H>> per_chunk;
  for (std::size_t c = 0; c < chunks<Traits>(); ++c) {
    std::vector<std::array<H, 4>> b;
    b.reserve(pieces.size());
    for (const auto& p : pieces) b.push_back({chunk<Traits>(p[0], c), chunk<Traits>(p[1], c), chunk<Traits>(p[2], c),
                                              chunk<Traits>(p[3], c)});
    per_chunk.push_back(spline::control_from_bezier(breakpoints, b, closed));
  }
  std::vector<typename Traits::Coefficient> out;
  const std::size_t n = per_chunk.front().size();
  out.reserve(n);
  std::vector<H> parts(chunks<Traits>());
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t c = 0; c < parts.size(); ++c) parts[c] = per_chunk[c][k];
    out.push_back(assemble<Traits>(parts));
  }
  return out;
}

/// eq. 2: the pieces of the spline with these control points.
template <class Traits>
Curve_pieces<typename Traits::Coefficient> pieces_from_control(const std::vector<typename Traits::FT>& breakpoints,
                                                               const std::vector<typename Traits::Coefficient>& control,
                                                               bool closed) {
  typedef typename Traits::FT FT;
  typedef spline::Homogeneous_point<FT> H;
  const std::size_t m = breakpoints.size() - 1;
  std::vector<std::vector<std::array<H, 4>>> per_chunk;
  for (std::size_t c = 0; c < chunks<Traits>(); ++c) {
    std::vector<H> d;
    d.reserve(control.size());
    for (const auto& v : control) d.push_back(chunk<Traits>(v, c));
    const spline::Bspline_form<FT> form(breakpoints, d, closed);
    std::vector<std::array<H, 4>> b;
    for (std::size_t i = 0; i < m; ++i) b.push_back(form.bezier_points(static_cast<long>(i)));
    per_chunk.push_back(std::move(b));
  }
  Curve_pieces<typename Traits::Coefficient> out(m);
  std::vector<H> parts(chunks<Traits>());
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t r = 0; r < 4; ++r) {
      for (std::size_t c = 0; c < parts.size(); ++c) parts[c] = per_chunk[c][i][r];
      out[i][r] = assemble<Traits>(parts);
    }
  return out;
}

/// A grid of patches b[i][j], each 4 x 4 coefficients b_rs (r along u, s along v).
template <class V>
using Patch_grid = std::vector<std::vector<std::array<std::array<V, 4>, 4>>>;

/// eq. 11 (and its boundary rows by eq. 10): the net c[k][l] from the patches.
template <class Traits>
std::vector<std::vector<typename Traits::Coefficient>> net_from_patches(
    const std::vector<typename Traits::FT>& tu, const std::vector<typename Traits::FT>& tv,
    const Patch_grid<typename Traits::Coefficient>& b, bool u_closed, bool v_closed) {
  typedef typename Traits::Coefficient V;
  const std::size_t mu = tu.size() - 1, mv = tv.size() - 1;
  // Along v, for every patch row i and coefficient row r: rows[i][r][l].
  std::vector<std::array<std::vector<V>, 4>> rows(mu);
  for (std::size_t i = 0; i < mu; ++i)
    for (std::size_t r = 0; r < 4; ++r) {
      Curve_pieces<V> p(mv);
      for (std::size_t j = 0; j < mv; ++j) p[j] = b[i][j][r];
      rows[i][r] = control_from_pieces<Traits>(tv, p, v_closed);
    }
  // Along u, for every column l.
  const std::size_t nv = rows.front()[0].size();
  std::vector<std::vector<V>> columns;
  for (std::size_t l = 0; l < nv; ++l) {
    Curve_pieces<V> p(mu);
    for (std::size_t i = 0; i < mu; ++i)
      for (std::size_t r = 0; r < 4; ++r) p[i][r] = rows[i][r][l];
    columns.push_back(control_from_pieces<Traits>(tu, p, u_closed));
  }
  std::vector<std::vector<V>> net(columns.front().size(), std::vector<V>());
  for (std::size_t k = 0; k < net.size(); ++k) {
    net[k].reserve(nv);
    for (std::size_t l = 0; l < nv; ++l) net[k].push_back(columns[l][k]);
  }
  return net;
}

/// eq. 2 tensored: the patches of the net c[k][l].
template <class Traits>
Patch_grid<typename Traits::Coefficient> patches_from_net(const std::vector<typename Traits::FT>& tu,
                                                          const std::vector<typename Traits::FT>& tv,
                                                          const std::vector<std::vector<typename Traits::Coefficient>>& net,
                                                          bool u_closed, bool v_closed) {
  typedef typename Traits::Coefficient V;
  const std::size_t mu = tu.size() - 1, mv = tv.size() - 1;
  // Along v for every net row k: along_v[k][j][s].
  std::vector<Curve_pieces<V>> along_v;
  along_v.reserve(net.size());
  for (const auto& row : net) along_v.push_back(pieces_from_control<Traits>(tv, row, v_closed));
  Patch_grid<V> out(mu, std::vector<std::array<std::array<V, 4>, 4>>(mv));
  for (std::size_t j = 0; j < mv; ++j)
    for (std::size_t s = 0; s < 4; ++s) {
      std::vector<V> column;
      column.reserve(net.size());
      for (std::size_t k = 0; k < net.size(); ++k) column.push_back(along_v[k][j][s]);
      const Curve_pieces<V> p = pieces_from_control<Traits>(tu, column, u_closed);
      for (std::size_t i = 0; i < mu; ++i)
        for (std::size_t r = 0; r < 4; ++r) out[i][j][r][s] = p[i][r];
    }
  return out;
}

/// The cubic Bernstein combination sum_r B_r(u) x_r, by de Casteljau.
template <class FT>
FT de_casteljau(const std::array<FT, 4>& x, const FT& u) {
  const FT v = FT(1) - u;
  const FT a = v * x[0] + u * x[1], b = v * x[1] + u * x[2], c = v * x[2] + u * x[3];
  const FT d = v * a + u * b, e = v * b + u * c;
  return v * d + u * e;
}

} // namespace tensor
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_TENSOR_NET_H
