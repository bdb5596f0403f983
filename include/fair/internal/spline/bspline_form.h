// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The non-uniform cubic C2 B-spline with single breakpoints t_0 < ... < t_m, open (clamped) or
// closed (periodic), in homogeneous coordinates (w d, w): its Bezier pieces (Karciauskas & Peters
// eq. 2), the control points from C2 Bezier pieces (eq. 3) and Boehm knot insertion.
//
// Indexing. The paper's c_i is the control point of breakpoint t_i: its basis function is
// supported on [t_{i-2}, t_{i+2}]. Closed: i is periodic (mod m) and the breakpoints extend
// periodically, t_{i+m} = t_i + (t_m - t_0). Open (clamped, the knot vector t_0 x4, t_1, ...,
// t_{m-1}, t_m x4): i runs over -1..m+1, the breakpoints extend by repetition (t_k = t_0 for
// k < 0, t_k = t_m for k > m), so h_{-1} = h_m = 0, and then c_{-1} = b_0^0, c_0 = b_1^0,
// c_m = b_2^{m-1}, c_{m+1} = b_3^{m-1} follow from the same formulas (eq. 10 of the paper, with
// its end points named c_{-1}, c_0 as corrected in doc/cubic_splines.md). One set of formulas
// thus serves both kinds of spline.
//
// With h_i = t_{i+1} - t_i and S_i = h_{i-1} + h_i + h_{i+1}, piece i over [t_i, t_{i+1}] has
//   b_1^i = ((h_i + h_{i+1}) c_i + h_{i-1} c_{i+1}) / S_i                 (eq. 2, e_i = h_{i-1}/S_i)
//   b_2^i = (h_{i+1} c_i + (h_{i-1} + h_i) c_{i+1}) / S_i                 (ẽ_i = h_{i+1}/S_i)
//   b_0^i = (h_i b_2^{i-1} + h_{i-1} b_1^i) / (h_{i-1} + h_i)              (x_i = h_{i-1}/(h_{i-1}+h_i))
// which is eq. 2 with beta_i = h_i / h_{i-1} multiplied out, so that it stays defined at a
// clamped end where h_{-1} = 0 (beta_0 = infinity). Every denominator is >= h_i > 0.
// Exactness: only +, -, *, / on FT: exact in an exact kernel.

#ifndef FAIR_INTERNAL_SPLINE_BSPLINE_FORM_H
#define FAIR_INTERNAL_SPLINE_BSPLINE_FORM_H

#include <fair/Errors.h>

#include <array>
#include <cstddef>
#include <vector>

namespace fair {
namespace internal {
namespace spline {

/// A point in homogeneous coordinates (w x, w y, w).
template <class FT>
struct Homogeneous_point {
  FT x, y, w;
};

/// A point of a polynomial spline (its weight is 1 and is not stored).
template <class FT>
struct Affine_point {
  FT x, y;
};

/// a p + b q.
template <class FT>
Homogeneous_point<FT> combine(const FT& a, const Homogeneous_point<FT>& p, const FT& b, const Homogeneous_point<FT>& q) {
  return Homogeneous_point<FT>{a * p.x + b * q.x, a * p.y + b * q.y, a * p.w + b * q.w};
}
template <class FT>
Affine_point<FT> combine(const FT& a, const Affine_point<FT>& p, const FT& b, const Affine_point<FT>& q) {
  return Affine_point<FT>{a * p.x + b * q.x, a * p.y + b * q.y};
}

/// (a p + b q) / s.
template <class FT>
Homogeneous_point<FT> combine(const FT& a, const Homogeneous_point<FT>& p, const FT& b, const Homogeneous_point<FT>& q,
                              const FT& s) {
  return Homogeneous_point<FT>{(a * p.x + b * q.x) / s, (a * p.y + b * q.y) / s, (a * p.w + b * q.w) / s};
}
template <class FT>
Affine_point<FT> combine(const FT& a, const Affine_point<FT>& p, const FT& b, const Affine_point<FT>& q, const FT& s) {
  return Affine_point<FT>{(a * p.x + b * q.x) / s, (a * p.y + b * q.y) / s};
}

/// f (a - 2 b + c).
template <class FT>
Homogeneous_point<FT> scaled_second_difference(const FT& f, const Homogeneous_point<FT>& a,
                                               const Homogeneous_point<FT>& b, const Homogeneous_point<FT>& c) {
  return Homogeneous_point<FT>{f * (a.x - FT(2) * b.x + c.x), f * (a.y - FT(2) * b.y + c.y),
                               f * (a.w - FT(2) * b.w + c.w)};
}
template <class FT>
Affine_point<FT> scaled_second_difference(const FT& f, const Affine_point<FT>& a, const Affine_point<FT>& b,
                                          const Affine_point<FT>& c) {
  return Affine_point<FT>{f * (a.x - FT(2) * b.x + c.x), f * (a.y - FT(2) * b.y + c.y)};
}

inline long floor_div(long a, long b) {
  long q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}

/// t_k for any k (the periodic or clamped extension of the breakpoints t_0..t_m).
template <class FT>
FT extended_knot(const std::vector<FT>& t, bool closed, long k) {
  const long m = static_cast<long>(t.size()) - 1;
  if (!closed) return t[static_cast<std::size_t>(k < 0 ? 0 : (k > m ? m : k))];
  const long q = floor_div(k, m);
  const FT period = t.back() - t.front();
  return t[static_cast<std::size_t>(k - q * m)] + FT(q) * period;
}

/// h_i = t_{i+1} - t_i for any i. Open: t_{i+1} - t_i inside [0, m), else the clamped
/// extension's t_k - t_k = 0. Closed: from the reduced index, so that h_{i+m} == h_i bit for bit
/// and the last piece of a closed spline ends exactly where the first begins.
template <class FT>
FT knot_interval(const std::vector<FT>& t, bool closed, long i) {
  const long m = static_cast<long>(t.size()) - 1;
  if (closed) i -= floor_div(i, m) * m;
  else if (i < 0 || i >= m) return t[i < 0 ? 0 : static_cast<std::size_t>(m)] - t[i < 0 ? 0 : static_cast<std::size_t>(m)];
  return t[static_cast<std::size_t>(i + 1)] - t[static_cast<std::size_t>(i)];
}

/// The intervals h_{i-2} .. h_{i+2} around piece i: direct differences in the interior (most
/// pieces), knot_interval near the ends.
template <class FT>
void intervals_around(const std::vector<FT>& t, bool closed, long i, FT (&h)[5]) {
  const long m = static_cast<long>(t.size()) - 1;
  if (i >= 2 && i + 3 <= m) {
    const FT* u = t.data() + (i - 2);
    for (int k = 0; k < 5; ++k) h[k] = u[k + 1] - u[k];
  } else {
    for (int k = 0; k < 5; ++k) h[k] = knot_interval(t, closed, i - 2 + k);
  }
}

/// eq. 2: the four Bezier points of piece i from its control points c = (c_{i-1}, c_i, c_{i+1},
/// c_{i+2}) and the intervals h = (h_{i-2}, ..., h_{i+2}) (the formulas of the header comment;
/// b_0 uses b_2^{i-1} and b_3 uses b_1^{i+1}, the only points of the neighbours it needs).
template <class FT, class P>
std::array<P, 4> bezier_points_of(const P (&c)[4], const FT (&h)[5]) {
  const FT &hm2 = h[0], &hm = h[1], &hi = h[2], &hp = h[3], &hp2 = h[4];
  const P left2 = combine(hi, c[0], hm2 + hm, c[1], hm2 + hm + hi);               // b_2^{i-1}
  const FT s = hm + hi + hp;
  const P mid1 = combine(hi + hp, c[1], hm, c[2], s), mid2 = combine(hp, c[1], hm + hi, c[2], s);  // b_1^i, b_2^i
  const P right1 = combine(hp + hp2, c[2], hi, c[3], hi + hp + hp2);              // b_1^{i+1}
  return {combine(hi, left2, hm, mid1, hm + hi), mid1, mid2, combine(hp, mid2, hi, right1, hi + hp)};
}

/// The storage index of c_j: open d_{j+1} (-1 <= j <= m+1), closed d_{j mod m}.
inline std::size_t control_index(long j, long m, bool closed) {
  if (!closed) return static_cast<std::size_t>(j + 1);
  if (j < 0) j += m;
  else if (j >= m) j -= m;
  return static_cast<std::size_t>(j);
}

/// The homogeneous control points and breakpoints of a spline, with the index extensions above.
template <class FT>
class Bspline_form {
public:
  typedef Homogeneous_point<FT> Point;

  /// Open: control has m + 3 entries (d_0..d_{m+2}, d_{i+1} = c_i); closed: m entries.
  Bspline_form(const std::vector<FT>& breakpoints, const std::vector<Point>& control, bool closed)
    : t_(breakpoints), c_(control), closed_(closed) {
    FAIR_ASSERT(t_.size() >= 2);
    FAIR_ASSERT(static_cast<long>(c_.size()) == (closed_ ? pieces() : pieces() + 3));
  }

  long pieces() const { return static_cast<long>(t_.size()) - 1; }

  /// t_k for any k (periodic or clamped extension).
  FT knot(long k) const { return extended_knot(t_, closed_, k); }

  /// h_i = t_{i+1} - t_i (knot_interval).
  FT interval(long i) const { return knot_interval(t_, closed_, i); }

  /// c_i (open: -1 <= i <= m+1; closed: any i).
  const Point& control(long i) const {
    if (closed_) {
      const long m = pieces();
      return c_[static_cast<std::size_t>(i - floor_div(i, m) * m)];
    }
    FAIR_ASSERT(i >= -1 && i <= pieces() + 1);
    return c_[static_cast<std::size_t>(i + 1)];
  }

  /// The four homogeneous Bezier points of piece i, 0 <= i < m (eq. 2).
  std::array<Point, 4> bezier_points(long i) const {
    FT h[5];
    intervals_around(t_, closed_, i, h);
    const Point c[4] = {control(i - 1), control(i), control(i + 1), control(i + 2)};
    return bezier_points_of(c, h);
  }

private:
  const std::vector<FT>& t_;
  const std::vector<Point>& c_;
  bool closed_;
};

/// The control points c from the homogeneous Bezier points of C2 pieces (eq. 3), in the
/// better-conditioned of its two forms: c_i extrapolates the line through b_1, b_2 of a piece
/// by the ratio of the intervals, so rounding in b_1 - b_2 is amplified by that ratio. Hence
///   h_i >= h_{i-1}:  c_i = ((h_{i-1} + h_i) b_1^i - h_{i-1} b_2^i) / h_i        (piece i)
///   h_i <  h_{i-1}:  c_i = ((h_{i-1} + h_i) b_2^{i-1} - h_i b_1^{i-1}) / h_{i-1}  (piece i-1)
/// both amplifying by at most 2 (exact arithmetic gives the same point for C2 pieces). For an
/// open spline the ends are c_{-1} = b_0^0, c_0 = b_1^0, c_m = b_2^{m-1}, c_{m+1} = b_3^{m-1}.
/// Whether the pieces are C2 is for the caller to check (rebuild the pieces and compare).
template <class FT>
std::vector<Homogeneous_point<FT>> control_from_bezier(const std::vector<FT>& breakpoints,
                                                       const std::vector<std::array<Homogeneous_point<FT>, 4>>& b,
                                                       bool closed) {
  typedef Homogeneous_point<FT> Point;
  const long m = static_cast<long>(breakpoints.size()) - 1;
  FAIR_ASSERT(static_cast<long>(b.size()) == m);
  std::vector<Point> c;
  c.reserve(static_cast<std::size_t>(closed ? m : m + 3));
  if (!closed) c.push_back(b.front()[0]);
  for (long i = 0; i < m; ++i) {
    const FT hm = knot_interval(breakpoints, closed, i - 1), h = knot_interval(breakpoints, closed, i);
    const bool has_left = closed || i > 0; // open: c_0 = b_1^0 (hm = 0 makes the right form exact)
    if (!has_left || !(h < hm)) {
      const std::array<Point, 4>& bi = b[static_cast<std::size_t>(i)];
      c.push_back(combine(hm + h, bi[1], -hm, bi[2], h));
    } else {
      const std::array<Point, 4>& bl = b[static_cast<std::size_t>((i - 1 + m) % m)];
      c.push_back(combine(hm + h, bl[2], -h, bl[1], hm));
    }
  }
  if (!closed) {
    c.push_back(b.back()[2]);
    c.push_back(b.back()[3]);
  }
  return c;
}

/// Boehm's insertion of the knot s, t_j < s < t_{j+1}: the new control points (same layout).
/// q_i = alpha_i c_i + (1 - alpha_i) c_{i-1}, alpha_i = (s - t_{i-2}) / (t_{i+1} - t_{i-2}) for
/// i = j, j+1, j+2 replace c_j, c_{j+1} and are followed by the old c_{j+2}, c_{j+3}, ...
/// (the basis function of c_i has the knots t_{i-2} .. t_{i+2}).
template <class FT>
std::vector<Homogeneous_point<FT>> insert_knot(const std::vector<FT>& breakpoints,
                                               const std::vector<Homogeneous_point<FT>>& control, bool closed, long j,
                                               const FT& s) {
  typedef Homogeneous_point<FT> Point;
  const Bspline_form<FT> form(breakpoints, control, closed);
  const long m = form.pieces();
  std::array<Point, 3> q;
  for (long r = 0; r < 3; ++r) {
    const long i = j + r;
    const FT lo = form.knot(i - 2), hi = form.knot(i + 1);
    const FT alpha = (s - lo) / (hi - lo);
    q[static_cast<std::size_t>(r)] = combine(alpha, form.control(i), FT(1) - alpha, form.control(i - 1));
  }
  std::vector<Point> out;
  if (closed) {
    const long n = m + 1; // new number of control points; new c'_k for k in [j, j+2] (mod n) is q
    out.resize(static_cast<std::size_t>(n));
    for (long k = 0; k < n; ++k) {
      const long r = ((k - j) % n + n) % n;
      out[static_cast<std::size_t>(k)] = r <= 2 ? q[static_cast<std::size_t>(r)] : form.control(j + r - 1);
    }
  } else {
    out.reserve(control.size() + 1);
    for (long k = -1; k <= m + 2; ++k) {
      if (k < j) out.push_back(form.control(k));
      else if (k <= j + 2) out.push_back(q[static_cast<std::size_t>(k - j)]);
      else out.push_back(form.control(k - 1));
    }
  }
  return out;
}

/// De Casteljau of the cubic with Bezier points b at u: the value and the first two derivatives
/// (d/du), in homogeneous or (polynomial spline) affine coordinates.
template <class FT, class P>
std::array<P, 3> cubic_jet(const std::array<P, 4>& b, const FT& u) {
  const FT v = FT(1) - u;
  const P a0 = combine(v, b[0], u, b[1]), a1 = combine(v, b[1], u, b[2]), a2 = combine(v, b[2], u, b[3]);
  const P p0 = combine(v, a0, u, a1), p1 = combine(v, a1, u, a2);
  const P value = combine(v, p0, u, p1);
  const FT three(3), six(6);
  const P d1 = combine(three, p1, -three, p0);
  // second derivative: 6 (b0 - 2 b1 + b2) at level 1 of the de Casteljau triangle
  const P d2 = scaled_second_difference(six, a0, a1, a2);
  return {value, d1, d2};
}

/// The value alone (three levels of de Casteljau).
template <class FT, class P>
P cubic_point(const std::array<P, 4>& b, const FT& u) {
  const FT v = FT(1) - u;
  const P a0 = combine(v, b[0], u, b[1]), a1 = combine(v, b[1], u, b[2]), a2 = combine(v, b[2], u, b[3]);
  return combine(v, combine(v, a0, u, a1), u, combine(v, a1, u, a2));
}

} // namespace spline
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_SPLINE_BSPLINE_FORM_H
