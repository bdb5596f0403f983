// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Tensor_product_spline<FT, Coefficient>: a bicubic C2 tensor-product B-spline surface with
// single breakpoints u_0 < ... < u_mu and v_0 < ... < v_mv, each direction open (clamped) or
// closed (periodic), converted to and from its grid of bicubic Bezier patches by eq. 11 of
// Karciauskas & Peters -- eq. 3 applied in each direction (doc/surfaces_of_revolution.md has the
// derivation; the printed eq. 11 is right, with beta-dot_i = h_i/h_{i-1} the knot-interval ratio
// in u and beta-ddot_j the one in v).
//
// Layout of the net, per direction as in Cubic_spline_2: open, m + 3 control points
// (d_0 = b_0 at the start, d_1 = b_1, d_{i+1} = the c_i of breakpoint i, d_{m+1} = b_2,
// d_{m+2} = the end); closed, m control points, d_i of breakpoint i. net[k][l]: k along u, l along v.
//
// Coefficients: any type with a Tensor_coefficient_traits specialisation (its scalar coordinates):
// CGAL Point_3 and Vector_3 of any kernel, and fair::Homogeneous_point_3<FT> (w x, w y, w z, w)
// for rational surfaces -- eqs. 2, 3, 11 are linear, so they act on homogeneous coordinates
// unchanged. Exact in an exact number type (only +, -, *, /).

#ifndef FAIR_TENSOR_PRODUCT_SPLINE_H
#define FAIR_TENSOR_PRODUCT_SPLINE_H

#include <fair/Errors.h>
#include <fair/Rational_bezier_2.h>
#include <fair/internal/spline/checks.h>  // c2_relative_tolerance, is_exact_number
#include <fair/internal/tensor/cartesian_traits.h>
#include <fair/internal/tensor/net.h>

#include <CGAL/Point_3.h>
#include <CGAL/Vector_3.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fair {

/// A point of projective 3-space in homogeneous coordinates (x, y, z, w) = (w X, w Y, w Z, w).
template <class FT_>
struct Homogeneous_point_3 {
  typedef FT_ FT;
  FT x{0}, y{0}, z{0}, w{1};
  bool operator==(const Homogeneous_point_3& o) const { return x == o.x && y == o.y && z == o.z && w == o.w; }
  bool operator!=(const Homogeneous_point_3& o) const { return !(*this == o); }
};

/// The scalar coordinates of a coefficient type: FT, dimension, coordinate(v, i), make(array).
template <class V>
struct Tensor_coefficient_traits;

template <class K>
struct Tensor_coefficient_traits<CGAL::Point_3<K>> : internal::tensor::Cartesian_3_traits<CGAL::Point_3<K>, K> {};

template <class K>
struct Tensor_coefficient_traits<CGAL::Vector_3<K>> : internal::tensor::Cartesian_3_traits<CGAL::Vector_3<K>, K> {};

template <class FT_>
struct Tensor_coefficient_traits<Homogeneous_point_3<FT_>> {
  typedef Homogeneous_point_3<FT_> Coefficient;
  typedef FT_ FT;
  static constexpr std::size_t dimension = 4;
  static FT coordinate(const Coefficient& p, std::size_t i) { return i == 0 ? p.x : (i == 1 ? p.y : (i == 2 ? p.z : p.w)); }
  static Coefficient make(const std::array<FT, 4>& x) { return Coefficient{x[0], x[1], x[2], x[3]}; }
};

/// A bicubic tensor-product Bezier patch sum_r sum_s b[r][s] B_r(u) B_s(v), (u, v) in [0,1]^2.
template <class Coefficient>
struct Bicubic_bezier_patch {
  typedef Tensor_coefficient_traits<Coefficient> Traits;
  typedef typename Traits::FT FT;
  std::array<std::array<Coefficient, 4>, 4> b;  ///< b[r][s]: r along u, s along v

  /// The value at (u, v), coordinate by coordinate by de Casteljau (exact in an exact FT).
  Coefficient point(const FT& u, const FT& v) const {
    std::array<FT, Traits::dimension> out;
    for (std::size_t a = 0; a < Traits::dimension; ++a) {
      std::array<FT, 4> col;
      for (std::size_t r = 0; r < 4; ++r) {
        const std::array<FT, 4> row{{Traits::coordinate(b[r][0], a), Traits::coordinate(b[r][1], a),
                                     Traits::coordinate(b[r][2], a), Traits::coordinate(b[r][3], a)}};
        col[r] = internal::tensor::de_casteljau(row, v);
      }
      out[a] = internal::tensor::de_casteljau(col, u);
    }
    return Traits::make(out);
  }
};

/// The patch of the surface of revolution of a profile piece (x(u), y(u)) about the y-axis over
/// the rotation given by a circle piece (c(v), s(v)) (c^2 + s^2 = 1, e.g. a rational arc): the
/// point (x c, y, x s). In homogeneous coordinates the product of two rational cubics (X, Y, W)
/// and (C, S, V) is bilinear: b_rs = (X_r C_s, Y_r V_s, X_r S_s, W_r V_s), X_r = w_r x_r, ...
/// \throws Precondition_error unless both pieces are cubic.
template <class K>
Bicubic_bezier_patch<Homogeneous_point_3<typename K::FT>> revolution_patch(const Rational_bezier_2<K>& profile,
                                                                           const Rational_bezier_2<K>& circle) {
  internal::require(profile.degree() == 3 && circle.degree() == 3, "fair::revolution_patch: needs cubic pieces, got ",
                    "degrees ", profile.degree(), " and ", circle.degree(), " (degree-elevate first)");
  Bicubic_bezier_patch<Homogeneous_point_3<typename K::FT>> p;
  for (std::size_t r = 0; r < 4; ++r)
    for (std::size_t s = 0; s < 4; ++s) {
      const auto& a = profile.control_point(r);
      const auto& c = circle.control_point(s);
      const typename K::FT wa = profile.weight(r), wc = circle.weight(s);
      p.b[r][s] = Homogeneous_point_3<typename K::FT>{wa * a.x() * wc * c.x(), wa * a.y() * wc, wa * a.x() * wc * c.y(),
                                                      wa * wc};
    }
  return p;
}

template <class Coefficient>
class Tensor_product_spline {
public:
  typedef Tensor_coefficient_traits<Coefficient> Traits;
  typedef typename Traits::FT FT;
  typedef Bicubic_bezier_patch<Coefficient> Patch;

  /// The surface with breakpoints tu, tv and net[k][l] ((mu + 3) or mu rows, (mv + 3) or mv
  /// columns, by openness). \throws Precondition_error on too few or non-increasing or non-finite
  /// breakpoints (>= 2 open, >= 4 closed) or a net of the wrong shape.
  Tensor_product_spline(std::vector<FT> tu, std::vector<FT> tv, std::vector<std::vector<Coefficient>> net,
                        bool u_closed = false, bool v_closed = false)
    : tu_(std::move(tu)), tv_(std::move(tv)), net_(std::move(net)), u_closed_(u_closed), v_closed_(v_closed) {
    check_breakpoints();
    const std::size_t rows = controls(tu_, u_closed_), cols = controls(tv_, v_closed_);
    internal::require(net_.size() == rows, "fair::Tensor_product_spline: ", tu_.size() - 1, " patches along u need ",
                      rows, " rows of control points, got ", net_.size());
    for (std::size_t k = 0; k < rows; ++k)
      internal::require(net_[k].size() == cols, "fair::Tensor_product_spline: row ", k, " has ", net_[k].size(),
                        " control points, ", cols, " needed");
  }

  /// eq. 11: the net of the C2 surface whose patches are patches[i][j] over [u_i, u_i+1] x
  /// [v_j, v_j+1]. \throws Precondition_error on a grid of the wrong shape; Invalid_input_error
  /// unless the patches are C2 for these breakpoints (the net's patches must reproduce them:
  /// exactly in an exact FT, else to 1e-9 of the largest coordinate).
  static Tensor_product_spline from_bezier_patches(std::vector<FT> tu, std::vector<FT> tv,
                                                   const std::vector<std::vector<Patch>>& patches,
                                                   bool u_closed = false, bool v_closed = false) {
    check_breakpoints(tu, tv, u_closed, v_closed);
    internal::require(patches.size() == tu.size() - 1, "fair::Tensor_product_spline::from_bezier_patches: ",
                      tu.size() - 1, " intervals along u but ", patches.size(), " rows of patches");
    internal::tensor::Patch_grid<Coefficient> b(patches.size());
    for (std::size_t i = 0; i < patches.size(); ++i) {
      internal::require(patches[i].size() == tv.size() - 1, "fair::Tensor_product_spline::from_bezier_patches: ",
                        tv.size() - 1, " intervals along v but row ", i, " has ", patches[i].size(), " patches");
      for (const Patch& p : patches[i]) b[i].push_back(p.b);
    }
    std::vector<std::vector<Coefficient>> net = internal::tensor::net_from_patches<Traits>(tu, tv, b, u_closed, v_closed);
    Tensor_product_spline s(std::move(tu), std::move(tv), std::move(net), u_closed, v_closed);
    s.check_reproduces(b);
    return s;
  }

  const std::vector<FT>& u_breakpoints() const { return tu_; }
  const std::vector<FT>& v_breakpoints() const { return tv_; }
  const std::vector<std::vector<Coefficient>>& control_net() const { return net_; }
  bool is_u_closed() const { return u_closed_; }
  bool is_v_closed() const { return v_closed_; }
  std::size_t number_of_patches_u() const { return tu_.size() - 1; }
  std::size_t number_of_patches_v() const { return tv_.size() - 1; }

  /// eq. 2 tensored: every patch, patches()[i][j]; O(size of the net).
  std::vector<std::vector<Patch>> patches() const {
    const internal::tensor::Patch_grid<Coefficient> b =
        internal::tensor::patches_from_net<Traits>(tu_, tv_, net_, u_closed_, v_closed_);
    std::vector<std::vector<Patch>> out(b.size());
    for (std::size_t i = 0; i < b.size(); ++i)
      for (const auto& p : b[i]) out[i].push_back(Patch{p});
    return out;
  }

  /// The value at global parameters (u, v) in [u_0, u_mu] x [v_0, v_mv] (exact in an exact FT).
  /// Cost O(size of the net) (it converts all patches). \throws Precondition_error outside.
  Coefficient point(const FT& u, const FT& v) const {
    const std::size_t i = locate(tu_, u, "u"), j = locate(tv_, v, "v");
    const Patch p = patches()[i][j];
    return p.point((u - tu_[i]) / (tu_[i + 1] - tu_[i]), (v - tv_[j]) / (tv_[j + 1] - tv_[j]));
  }

private:
  static std::size_t controls(const std::vector<FT>& t, bool closed) { return closed ? t.size() - 1 : t.size() + 2; }

  // At least 2 breakpoints (1 patch) open, 4 (3 patches) closed; finite, strictly increasing.
  static void check_breakpoints(const std::vector<FT>& tu, const std::vector<FT>& tv, bool uc, bool vc) {
    const std::vector<FT>* t[2] = {&tu, &tv};
    const bool closed[2] = {uc, vc};
    for (int d = 0; d < 2; ++d) {
      const char* name = d == 0 ? "u" : "v";
      const std::size_t minimum = closed[d] ? 4 : 2;
      internal::require(t[d]->size() >= minimum, "fair::Tensor_product_spline: needs at least ", minimum, " ", name,
                        "-breakpoints ", closed[d] ? "(closed)" : "(open)", ", got ", t[d]->size());
      for (std::size_t i = 0; i < t[d]->size(); ++i) {
        const double x = CGAL::to_double((*t[d])[i]);
        internal::require(std::isfinite(x), "fair::Tensor_product_spline: ", name, "-breakpoint ", i, " = ", x,
                          " is not finite");
        if (i > 0)
          internal::require((*t[d])[i - 1] < (*t[d])[i], "fair::Tensor_product_spline: ", name, "-breakpoints ", i - 1,
                            " and ", i, " are not increasing (", CGAL::to_double((*t[d])[i - 1]), ", ", x, ")");
      }
    }
  }
  void check_breakpoints() const { check_breakpoints(tu_, tv_, u_closed_, v_closed_); }

  static std::size_t locate(const std::vector<FT>& t, const FT& x, const char* name) {
    internal::require(t.front() <= x && x <= t.back(), "fair::Tensor_product_spline::point: ", name, " = ",
                      CGAL::to_double(x), " is outside [", CGAL::to_double(t.front()), ", ", CGAL::to_double(t.back()), "]");
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), x) - t.begin());
    return std::min(k == 0 ? 0 : k - 1, t.size() - 2);
  }

  void check_reproduces(const internal::tensor::Patch_grid<Coefficient>& b) const {
    const bool exact = internal::spline::is_exact_number<FT>();
    double extent = 0;
    if (!exact)
      for (const auto& row : b)
        for (const auto& p : row)
          for (const auto& r : p)
            for (const Coefficient& c : r)
              for (std::size_t a = 0; a < Traits::dimension; ++a)
                extent = std::max(extent, std::fabs(CGAL::to_double(Traits::coordinate(c, a))));
    const double tolerance = internal::spline::c2_relative_tolerance * std::max(extent, 1e-300);
    const internal::tensor::Patch_grid<Coefficient> back =
        internal::tensor::patches_from_net<Traits>(tu_, tv_, net_, u_closed_, v_closed_);
    for (std::size_t i = 0; i < b.size(); ++i)
      for (std::size_t j = 0; j < b[i].size(); ++j)
        for (std::size_t r = 0; r < 4; ++r)
          for (std::size_t s = 0; s < 4; ++s)
            for (std::size_t a = 0; a < Traits::dimension; ++a) {
              const FT x = Traits::coordinate(b[i][j][r][s], a), y = Traits::coordinate(back[i][j][r][s], a);
              const bool same = exact ? x == y : std::fabs(CGAL::to_double(x) - CGAL::to_double(y)) <= tolerance;
              if (!same)
                throw Invalid_input_error(internal::message(
                    "fair::Tensor_product_spline::from_bezier_patches: the patches are not C2 for these breakpoints: ",
                    "coordinate ", a, " of b_", r, s, " of patch (", i, ", ", j, ") is ", CGAL::to_double(x),
                    ", the C2 surface through the patches' interior coefficients gives ", CGAL::to_double(y)));
            }
  }

  std::vector<FT> tu_, tv_;
  std::vector<std::vector<Coefficient>> net_;
  bool u_closed_, v_closed_;
};

} // namespace fair

#endif // FAIR_TENSOR_PRODUCT_SPLINE_H
