// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Rational_quadratic_bezier_2<Kernel>: a conic arc as a rational quadratic Bezier piece in
// standard form (Yan, Schiller, Schaefer, "Circle reproduction with interpolatory curves at
// local maximal curvature points", eq. 1 -- "the paper" below):
//
//   c(t) = ((1-t)^2 P0 + 2(1-t)t w P1 + t^2 P2) / W(t),   W(t) = (1-t)^2 + 2(1-t)t w + t^2,
//
// t in [0,1], w > 0, and P0, P1, P2 not collinear (a genuine conic arc, never a segment).
// Models the CurvePiece_2 concept of doc/contributing.md.
//
// Closed forms used throughout (s = 1-t, D = det(P1-P0, P2-P1) = twice the signed area of the
// control triangle):
//   c'(t)  = V(t) / W(t)^2,  V = 2 [ w s^2 (P1-P0) + s t (P2-P0) + w t^2 (P2-P1) ]
//   c''(t) = (V' W - 2 V W') / W^3,  W' = 2 (w-1)(1-2t)
//   det(c', c'') = 4 w D / W^3   (the homogeneous 3x3 determinant of a quadratic is constant)
//   kappa(t) = 4 w D W^3 / |V|^3.
// Guarantees: everything returning FT (points, derivatives, squared curvature, end curvatures
// of eq. 5, the eq.-4 polynomial, implicit coefficients of eq. 14, the squared weight of eq. 15,
// the conic type) is exact in an exact kernel (EPECK, Simple_cartesian<Gmpq>) and a handful of
// rounded operations in a floating kernel. Root isolation (eq. 4 extrema, eq. 7 parameter) is
// certified in EVERY kernel: it runs on the exact rational values of the inputs. Functions
// returning double (curvature, eccentricity) are computed in double (relative error ~1e-15 for
// well-conditioned pieces; the conditioning degrades as the control triangle flattens).

#ifndef FAIR_RATIONAL_QUADRATIC_BEZIER_2_H
#define FAIR_RATIONAL_QUADRATIC_BEZIER_2_H

#include <fair/Bernstein_polynomial.h>
#include <fair/Bernstein_root_isolation.h>
#include <fair/Conic_type.h>
#include <fair/Errors.h>
#include <fair/Rational_bezier_2.h>
#include <fair/internal/common/exact_conversion.h>
#include <fair/internal/conic/interpolation.h>
#include <fair/internal/conic/scaled.h>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Sqrt_extension.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <utility>
#include <vector>

namespace fair {

/// How |kappa| behaves at a root of the eq.-4 polynomial.
enum class Curvature_extremum_kind {
  MAXIMUM,   ///< |kappa| increases before and decreases after (local maximum)
  MINIMUM,   ///< |kappa| decreases before and increases after (local minimum)
  STATIONARY ///< a root of even multiplicity: kappa' = 0 but no extremum
};

inline const char* to_string(Curvature_extremum_kind k) {
  switch (k) {
    case Curvature_extremum_kind::MAXIMUM: return "maximum";
    case Curvature_extremum_kind::MINIMUM: return "minimum";
    case Curvature_extremum_kind::STATIONARY: return "stationary";
  }
  return "unknown";
}
inline std::ostream& operator<<(std::ostream& out, Curvature_extremum_kind k) { return out << to_string(k); }

/// A certified critical point of the curvature in (0,1). The root is exactly t_lower when
/// t_lower == t_upper, otherwise it lies in the open interval (t_lower, t_upper).
struct Curvature_extremum {
  CGAL::Gmpq t_lower, t_upper;
  double t = 0.5;        ///< a double in [t_lower, t_upper], within a few ulps of the root
  int multiplicity = 1;  ///< exact multiplicity as a root of the eq.-4 polynomial
  Curvature_extremum_kind kind = Curvature_extremum_kind::MAXIMUM;
};

namespace internal {

/// The Bernstein coefficients of the numerator of kappa'(t), eq. 4 of the paper, in any number
/// type. The paper's polynomial E satisfies  W' |V|^2 - W V.V' = -4 E  (checked symbolically),
/// and d|kappa|/dt has the sign of W' |V|^2 - W V.V', hence the sign of -E.
template <class NT>
std::vector<NT> eq4_coefficients(const NT& x0, const NT& y0, const NT& x1, const NT& y1, const NT& x2,
                                 const NT& y2, const NT& w) {
  const NT ax = x0 - x1, ay = y0 - y1;   // P0 - P1
  const NT bx = x0 - x2, by = y0 - y2;   // P0 - P2
  const NT cx = x1 - x2, cy = y1 - y2;   // P1 - P2
  const NT n01 = ax * ax + ay * ay, n02 = bx * bx + by * by, n12 = cx * cx + cy * cy;
  const NT w2 = w * w, w3 = w2 * w;
  const NT quarter = NT(1) / NT(4), half = NT(1) / NT(2);
  // (P2 - P0).(P0 - 2 P1 + P2) = -(P0-P2).((P0-P1) - (P1-P2))
  const NT mid = -(bx * (ax - cx) + by * (ay - cy));
  return {NT(-2) * w3 * n01 + w * (ax * bx + ay * by),
          -(w2 * n01) + quarter * n02,
          half * w * mid,
          -(quarter * n02) + w2 * n12,
          -(w * (bx * cx + by * cy)) + NT(2) * w3 * n12};
}

template <class NT>
void check_finite_value(const NT& x, const char* fn, const char* what) {
  const double d = CGAL::to_double(x);
  require(std::isfinite(d), fn, ": ", what, " = ", d, " is not finite");
}

/// Interval fast path for the extrema of eq. 4 (see Rational_quadratic_bezier_2::
/// curvature_extrema). Inputs: enclosures of the exact coordinates of P0, P1, P2 and of w, and
/// `exact()` returning the exact eq.-4 coefficients (called only if an interval sign is
/// undecided near the root). Returns 0 when the enclosed coefficients certify that E has no root
/// in [0,1] (no sign variation); 1 when they certify exactly one simple root in (0,1) (one
/// variation, nonzero ends), which is then stored in `x` with a certified bracket (E(t_lower),
/// E(t_upper) of opposite exact signs, or t_lower == t_upper == the exact root, detected for
/// roots that are dyadic with at most 32 significant bits after the binary point) and its kind
/// (E from - to + is a MAXIMUM of |kappa|); -1 when the intervals cannot decide (the caller then
/// runs the exact isolation). Accuracy: the bracket is a few ulps wide (see
/// internal/conic/interpolation.h); cost ~1 us when no exact evaluation is needed.
template <class Exact_coefficients>
int eq4_unique_extremum(const conic::Rq_interval& x0, const conic::Rq_interval& y0, const conic::Rq_interval& x1, const conic::Rq_interval& y1,
                        const conic::Rq_interval& x2, const conic::Rq_interval& y2, const conic::Rq_interval& w,
                        Exact_coefficients exact, Curvature_extremum& x) {
  conic::Rq_interval b[5];
  int sign[5];
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const std::vector<conic::Rq_interval> c = eq4_coefficients<conic::Rq_interval>(x0, y0, x1, y1, x2, y2, w);
    int last = 0, variations = 0;
    for (int i = 0; i < 5; ++i) {
      b[i] = c[static_cast<std::size_t>(i)];
      if (b[i].inf() > 0) sign[i] = 1;
      else if (b[i].sup() < 0) sign[i] = -1;
      else return -1;
      if (last != 0 && sign[i] != last) ++variations;
      last = sign[i];
    }
    if (variations == 0) return 0;
    if (variations != 1) return -1;
    if (sign[0] > 0)
      for (int i = 0; i < 5; ++i) b[i] = -b[i]; // certified_unique_root_quartic wants f(0) < 0
  }
  const int flip = sign[0];
  bool have_exact = false;
  std::array<CGAL::Gmpq, 5> e;
  auto exact_sign = [&](double t) {
    if (!have_exact) {
      const std::vector<CGAL::Gmpq> v = exact();
      for (std::size_t i = 0; i < 5; ++i) e[i] = flip > 0 ? CGAL::Gmpq(-v[i]) : v[i];
      have_exact = true;
    }
    return conic::quartic_sign_exact(e, t);
  };
  const conic::Rational_quadratic_extremum_parameter r = conic::certified_unique_root_quartic(b, exact_sign);
  x.multiplicity = 1;
  x.kind = sign[0] < 0 ? Curvature_extremum_kind::MAXIMUM : Curvature_extremum_kind::MINIMUM;
  x.t = r.t;
  const double m = std::ldexp(std::nearbyint(std::ldexp(r.t, 32)), -32); // shortest dyadic nearby
  if (r.t_lower < m && m < r.t_upper && exact_sign(m) == CGAL::ZERO) {
    x.t = m;
    x.t_lower = x.t_upper = CGAL::Gmpq(m); // a short dyadic exact root (e.g. 1/2 by symmetry)
    return 1;
  }
  x.t_lower = CGAL::Gmpq(r.t_lower);
  x.t_upper = CGAL::Gmpq(r.t_upper);
  return 1;
}

} // namespace internal

template <class K>
class Rational_quadratic_bezier_2 {
public:
  typedef K Kernel;
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Bernstein_polynomial<FT> Polynomial;
  /// Numbers a0 + a1 sqrt(r) over FT (exact comparisons in an exact kernel).
  typedef CGAL::Sqrt_extension<FT, FT, CGAL::Tag_true, CGAL::Tag_true> Sqrt_extension_FT;

  /// The standard-form piece P0, P1, P2 with weight w on P1 (eq. 1).
  /// \throws Precondition_error if a coordinate or w is not finite, w <= 0, P0 == P2, or the
  /// control points are collinear (which includes P0 == P1 and P1 == P2), decided exactly by
  /// Kernel::Orientation_2.
  Rational_quadratic_bezier_2(const Point_2& p0, const Point_2& p1, const Point_2& p2, const FT& w)
    : p_{{p0, p1, p2}}, w_(w) {
    const char* fn = "Rational_quadratic_bezier_2";
    for (int i = 0; i < 3; ++i) {
      const double x = CGAL::to_double(p_[i].x()), y = CGAL::to_double(p_[i].y());
      internal::require(std::isfinite(x) && std::isfinite(y), fn, ": control point P", i, " = (", x, ", ", y,
                        ") is not finite");
    }
    const double wd = CGAL::to_double(w);
    internal::require(std::isfinite(wd) && w > FT(0), fn, ": the weight must be finite and > 0, got w = ", wd);
    internal::require(p0 != p2, fn, ": degenerate piece, P0 == P2 = (", CGAL::to_double(p0.x()), ", ",
                      CGAL::to_double(p0.y()), ")");
    if constexpr (internal::common::Is_floating_nt<FT>::value) {
      // Exact whatever the scale (Simple_cartesian<double>'s own predicate underflows near 1e-300
      // and overflows near 1e300): interval filter, then the exact rational determinant.
      orientation_ = internal::conic::exact_orientation_of_doubles(CGAL::to_double(p0.x()), CGAL::to_double(p0.y()),
                                                            CGAL::to_double(p1.x()), CGAL::to_double(p1.y()),
                                                            CGAL::to_double(p2.x()), CGAL::to_double(p2.y()));
    } else {
      // Interval filter on enclosures of the exact coordinates first: the exact determinant
      // over Gmpq (Simple_cartesian<Gmpq>) costs a dozen gcds; EPECK filters on its own.
      typedef CGAL::Interval_nt<false> I;
      CGAL::Orientation filtered = CGAL::COLLINEAR;
      {
        CGAL::Protect_FPU_rounding<true> guard;
        const I x0(CGAL::to_interval(p0.x())), y0(CGAL::to_interval(p0.y())), x1(CGAL::to_interval(p1.x()));
        const I y1(CGAL::to_interval(p1.y())), x2(CGAL::to_interval(p2.x())), y2(CGAL::to_interval(p2.y()));
        const I d = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0);
        if (d.inf() > 0) filtered = CGAL::LEFT_TURN;
        else if (d.sup() < 0) filtered = CGAL::RIGHT_TURN;
      }
      orientation_ = filtered != CGAL::COLLINEAR ? filtered : K().orientation_2_object()(p0, p1, p2);
    }
    internal::require(orientation_ != CGAL::COLLINEAR, fn, ": degenerate piece, collinear control points P0 = (",
                      CGAL::to_double(p0.x()), ", ", CGAL::to_double(p0.y()), "), P1 = (", CGAL::to_double(p1.x()),
                      ", ", CGAL::to_double(p1.y()), "), P2 = (", CGAL::to_double(p2.x()), ", ",
                      CGAL::to_double(p2.y()), ")");
    for (int i = 0; i < 3; ++i) {
      xd_[i] = CGAL::to_double(p_[i].x());
      yd_[i] = CGAL::to_double(p_[i].y());
    }
    wd_ = wd;
    edges_ = internal::conic::Scaled_edges(xd_, yd_);
    // D = det(P1-P0, P2-P1) as an unscaled (mantissa, exponent) pair; from the exact inputs when
    // the scaled double determinant cancels (see internal/conic/scaled.h).
    const double ds = edges_.ex[0] * edges_.ey[1] - edges_.ey[0] * edges_.ex[1];
    if (std::abs(ds) >= 0x1p-40) {
      area_ = internal::conic::Scaled_double::of(ds);
      area_.e += 2L * edges_.k;
    } else {
      using internal::common::to_gmpq;
      const CGAL::Gmpq x0 = to_gmpq(p0.x()), y0 = to_gmpq(p0.y()), x1 = to_gmpq(p1.x()), y1 = to_gmpq(p1.y());
      const CGAL::Gmpq x2 = to_gmpq(p2.x()), y2 = to_gmpq(p2.y());
      area_ = internal::conic::scaled_from_gmpq((x1 - x0) * (y2 - y1) - (y1 - y0) * (x2 - x1));
    }
  }

  // ---------------------------------------------------------------- access
  const Point_2& source() const { return p_[0]; }
  const Point_2& target() const { return p_[2]; }
  const Point_2& control_point(std::size_t i) const {
    internal::require(i < 3, "Rational_quadratic_bezier_2::control_point: index ", i, " > 2");
    return p_[i];
  }
  const FT& weight() const { return w_; }
  /// P0, P1, P2 (for drawing the control polygon).
  std::vector<Point_2> control_points() const { return std::vector<Point_2>(p_.begin(), p_.end()); }
  /// The weights (1, w, 1) of the standard form.
  std::vector<FT> weights() const { return {FT(1), w_, FT(1)}; }
  /// The same arc as a general rational Bezier piece.
  Rational_bezier_2<K> to_rational_bezier() const { return Rational_bezier_2<K>(*this); }

  /// Orientation of the control triangle (exact, Kernel::Orientation_2): LEFT_TURN iff the arc
  /// turns left (kappa > 0 everywhere), RIGHT_TURN iff it turns right. Never COLLINEAR. The
  /// control polygon of a valid piece is a non-degenerate triangle, hence convex, and the arc
  /// lies inside it (w > 0: convex combination of P0, P1, P2).
  CGAL::Orientation orientation() const { return orientation_; }

  // ---------------------------------------------------------------- evaluation (exact in FT)
  /// W(t) = (1-t)^2 + 2(1-t)t w + t^2 > 0.
  FT denominator(const FT& t) const {
    const FT s = FT(1) - t;
    return s * s + FT(2) * w_ * s * t + t * t;
  }

  /// c(t), eq. 1; t in [0,1].
  Point_2 point(const FT& t) const {
    check_parameter(t, "point");
    const FT s = FT(1) - t, b0 = s * s, b1 = FT(2) * w_ * s * t, b2 = t * t, W = b0 + b1 + b2;
    return Point_2((b0 * p_[0].x() + b1 * p_[1].x() + b2 * p_[2].x()) / W,
                   (b0 * p_[0].y() + b1 * p_[1].y() + b2 * p_[2].y()) / W);
  }

  /// c'(t) = V(t) / W(t)^2 (see the file comment); t in [0,1].
  Vector_2 derivative(const FT& t) const {
    check_parameter(t, "derivative");
    const FT W = denominator(t);
    const Vector_2 V = hodograph_numerator(t);
    return V / (W * W);
  }

  /// c''(t) = (V' W - 2 V W') / W^3; t in [0,1].
  Vector_2 second_derivative(const FT& t) const {
    check_parameter(t, "second_derivative");
    const FT W = denominator(t), W1 = FT(2) * (w_ - FT(1)) * (FT(1) - FT(2) * t);
    const Vector_2 V = hodograph_numerator(t), V1 = hodograph_numerator_derivative(t);
    return (V1 * W - V * (FT(2) * W1)) / (W * W * W);
  }

  /// D = det(P1 - P0, P2 - P1): twice the signed area Delta(P0, P1, P2) of eq. 5 (exact).
  FT twice_signed_area() const {
    return (p_[1].x() - p_[0].x()) * (p_[2].y() - p_[1].y()) - (p_[1].y() - p_[0].y()) * (p_[2].x() - p_[1].x());
  }

  /// kappa(t)^2 = 16 w^2 D^2 W^6 / |V|^6, exact in an exact kernel. |V| > 0 on [0,1] for a
  /// valid piece: with e1 = P1-P0, e2 = P2-P1 (independent), V/2 = (w s^2 + s t) e1 +
  /// (s t + w t^2) e2 has a nonzero coefficient, so no division by zero can occur.
  FT squared_curvature(const FT& t) const {
    check_parameter(t, "squared_curvature");
    const FT W = denominator(t), D = twice_signed_area();
    const Vector_2 V = hodograph_numerator(t);
    const FT v2 = V * V, W3 = W * W * W;
    return FT(16) * w_ * w_ * D * D * W3 * W3 / (v2 * v2 * v2);
  }

  /// Signed curvature kappa(t) = 4 w D W^3 / |V|^3 in double (positive iff LEFT_TURN), relative
  /// error ~1e-15 at every scale: computed on the edge vectors scaled by an exact power of two
  /// and rescaled exactly (internal/conic/scaled.h), so it is scale-covariant
  /// (kappa of the piece scaled by 2^j is kappa 2^-j, bit for bit).
  /// \throws Precondition_error if t is not in [0,1], or if kappa(t) is not representable in
  /// double (|kappa| > DBL_MAX or below the smallest subnormal).
  double curvature(double t) const {
    internal::require(t >= 0 && t <= 1, "Rational_quadratic_bezier_2::curvature: t = ", t, " is not in [0,1]");
    const double s = 1.0 - t, w = wd_;
    const internal::conic::Scaled_edges& e = edges_;
    const double Vx = 2.0 * (w * s * s * e.ex[0] + s * t * e.ex[2] + w * t * t * e.ex[1]);
    const double Vy = 2.0 * (w * s * s * e.ey[0] + s * t * e.ey[2] + w * t * t * e.ey[1]);
    const double W = s * s + 2.0 * w * s * t + t * t;
    const double n = std::hypot(Vx, Vy); // |V| 2^-k
    internal::require(n > 0 && std::isfinite(n), "Rational_quadratic_bezier_2::curvature: |c'(", t,
                      ")| W^2 is not representable in double (scaled value ", n, ")");
    internal::conic::Scaled_double r = internal::conic::Scaled_double::of(W);
    r /= internal::conic::Scaled_double::of(n);
    const internal::conic::Scaled_double r1 = r;
    r *= r1;
    r *= r1;
    r *= internal::conic::Scaled_double::of(4.0 * w);
    r *= area_;
    r.e -= 3L * e.k;
    return r.to_double("Rational_quadratic_bezier_2::curvature: the curvature");
  }

  /// eq. 5: kappa(0)^2 = Delta^2 / (w^4 |P1-P0|^6), exact (Delta = D/2).
  FT squared_curvature_at_source() const {
    const FT D = twice_signed_area(), l = (p_[1] - p_[0]) * (p_[1] - p_[0]);
    return D * D / (FT(4) * w_ * w_ * w_ * w_ * l * l * l);
  }
  /// eq. 5: kappa(1)^2 = Delta^2 / (w^4 |P2-P1|^6), exact.
  FT squared_curvature_at_target() const {
    const FT D = twice_signed_area(), l = (p_[2] - p_[1]) * (p_[2] - p_[1]);
    return D * D / (FT(4) * w_ * w_ * w_ * w_ * l * l * l);
  }
  /// eq. 5, signed, in double: kappa(0) = Delta / (w^2 |P1-P0|^3), scale-robust like curvature().
  /// \throws Precondition_error if the value is not representable in double.
  double curvature_at_source() const { return end_curvature(0); }
  /// eq. 5, signed, in double: kappa(1) = Delta / (w^2 |P2-P1|^3), scale-robust like curvature().
  /// \throws Precondition_error if the value is not representable in double.
  double curvature_at_target() const { return end_curvature(1); }

  // ---------------------------------------------------------------- curvature extrema (eq. 4)
  /// The numerator of kappa'(t) in Bernstein form, eq. 4 (exact in FT; degree 4, of effective
  /// degree 3 when w = 1). Sign convention of the paper: d|kappa|/dt has the sign of -E(t), so a
  /// root where E goes from - to + is a maximum of |kappa|.
  Polynomial curvature_derivative_numerator() const {
    return Polynomial(internal::eq4_coefficients<FT>(p_[0].x(), p_[0].y(), p_[1].x(), p_[1].y(), p_[2].x(),
                                                     p_[2].y(), w_));
  }

  /// True iff the eq.-4 polynomial vanishes identically (decided exactly on the exact values
  /// of the inputs): the arc is a circular arc and kappa is constant.
  bool has_constant_curvature() const {
    for (const CGAL::Gmpq& c : exact_eq4()) if (!CGAL::is_zero(c)) return false;
    return true;
  }

  /// The certified critical points of kappa in the open interval (0,1), sorted, each with its
  /// kind. Method: certified isolation (fair::Bernstein_root_isolation) of the eq.-4 polynomial
  /// built exactly from the exact values of the inputs; then, for a root of multiplicity m,
  /// the exact sign sigma of E just right of the root: E(upper) for an open interval (there is
  /// no other root in (root, upper)), or the m-th derivative of E at an exact (point) root.
  /// Odd m: E changes sign, -,+ means MAXIMUM of |kappa| and +,- MINIMUM; even m: STATIONARY.
  /// Empty for a circular arc (has_constant_curvature()). At most 2 entries for an ellipse
  /// (w < 1), at most 1 for a parabola or hyperbola (Sec. 3.1 of the paper).
  /// Fast path (same results, ~1 us instead of ~30 us): the eq.-4 coefficients are enclosed by
  /// interval arithmetic on enclosures of the exact inputs; when their signs are certain and
  /// show 0 variations (no root in [0,1]) or 1 variation (exactly one simple root in (0,1),
  /// Descartes' rule in the Bernstein basis), the root is bracketed by
  /// internal::conic::certified_unique_root_quartic (certified for the exact inputs: E(t_lower) and
  /// E(t_upper) have opposite exact signs, bracket a few ulps wide, exact fallback inside);
  /// see internal::eq4_unique_extremum. Otherwise the exact isolation below runs.
  std::vector<Curvature_extremum> curvature_extrema() const {
    std::vector<Curvature_extremum> out;
    {
      Curvature_extremum x;
      const int fast = internal::eq4_unique_extremum(
        internal::common::to_interval_nt(p_[0].x()), internal::common::to_interval_nt(p_[0].y()), internal::common::to_interval_nt(p_[1].x()),
        internal::common::to_interval_nt(p_[1].y()), internal::common::to_interval_nt(p_[2].x()), internal::common::to_interval_nt(p_[2].y()),
        internal::common::to_interval_nt(w_), [this]() { return exact_eq4(); }, x);
      if (fast == 0) return out;
      if (fast == 1) {
        out.push_back(x);
        return out;
      }
    }
    const Bernstein_polynomial<CGAL::Gmpq> E(exact_eq4());
    if (E.is_zero()) return out; // circular arc: constant curvature, no isolated extrema
    Bernstein_root_isolation iso(E);
    for (std::size_t i = 0; i < iso.number_of_roots(); ++i) {
      const Isolating_interval I = iso[i];
      if (I.is_point() && (CGAL::is_zero(I.lower) || I.lower == CGAL::Gmpq(1))) continue; // t = 0 or 1
      Curvature_extremum x;
      x.multiplicity = I.multiplicity;
      int right = 0;
      for (int attempt = 0; right == 0 && attempt < 4000; ++attempt) {
        const Isolating_interval& J = iso[i];
        if (J.is_point()) {
          Bernstein_polynomial<CGAL::Gmpq> d = E;
          for (int k = 0; k < J.multiplicity; ++k) d = d.derivative();
          right = CGAL::sign(d.evaluate(J.lower));
        } else {
          // No other root in (root, upper): E(upper) is the sign just right of the root unless
          // upper is itself the next root; likewise for lower. Otherwise bisect once more.
          right = CGAL::sign(E.evaluate(J.upper));
          if (right == 0) {
            const int l = CGAL::sign(E.evaluate(J.lower));
            right = (J.multiplicity % 2 == 1) ? -l : l;
          }
          if (right == 0) iso.refine(i, J.width() / 2);
        }
      }
      internal::require(right != 0, "Rational_quadratic_bezier_2::curvature_extrema: internal error, no sign ",
                        "next to the root in ", iso[i]);
      const int left = (I.multiplicity % 2 == 1) ? -right : right;
      if (I.multiplicity % 2 == 0) x.kind = Curvature_extremum_kind::STATIONARY;
      else x.kind = (left < 0 && right > 0) ? Curvature_extremum_kind::MAXIMUM : Curvature_extremum_kind::MINIMUM;
      x.t = iso.root_approximation(i);
      x.t_lower = iso[i].lower;
      x.t_upper = iso[i].upper;
      out.push_back(x);
    }
    return out;
  }

  // ---------------------------------------------------------------- conic (eq. 14, eq. 15)
  /// Conic type, exact: w < 1 ellipse, w = 1 parabola, w > 1 hyperbola. This agrees with the
  /// sign of the discriminant b^2 - 4ac = 16 w^2 (w^2 - 1) D^2 of implicit_coefficients().
  Conic_type conic_type() const {
    const CGAL::Comparison_result c = CGAL::compare(w_, FT(1));
    return c == CGAL::SMALLER ? Conic_type::ELLIPSE : (c == CGAL::EQUAL ? Conic_type::PARABOLA : Conic_type::HYPERBOLA);
  }

  /// Coefficients {a, b, c, d, e, f} of the implicit equation (eq. 14)
  ///   a x^2 + b xy + c y^2 + d x + e y + f = 0
  /// of the conic carrying the arc, exact in FT. Closed form (the resultant of eq. 1, written
  /// in barycentric coordinates of the control triangle, where the curve is
  /// tau1^2 = 4 w^2 tau0 tau2): F = L1^2 - 4 w^2 L0 L2 with the affine functions
  /// L0(X) = det(P1-X, P2-X), L1(X) = det(P2-X, P0-X), L2(X) = det(P0-X, P1-X)
  /// (L_i = D tau_i). Normalisation: F(P1) = L1(P1)^2 = D^2 > 0 (L0(P1) = L2(P1) = 0).
  std::array<FT, 6> implicit_coefficients() const {
    FT al[3], be[3], ga[3];
    for (int i = 0; i < 3; ++i) {
      const Point_2& pj = p_[(i + 1) % 3];
      const Point_2& pk = p_[(i + 2) % 3];
      al[i] = pj.y() - pk.y();
      be[i] = pk.x() - pj.x();
      ga[i] = pj.x() * pk.y() - pj.y() * pk.x();
    }
    const FT m = FT(4) * w_ * w_;
    return {{al[1] * al[1] - m * al[0] * al[2],
             FT(2) * al[1] * be[1] - m * (al[0] * be[2] + be[0] * al[2]),
             be[1] * be[1] - m * be[0] * be[2],
             FT(2) * al[1] * ga[1] - m * (al[0] * ga[2] + ga[0] * al[2]),
             FT(2) * be[1] * ga[1] - m * (be[0] * ga[2] + ga[0] * be[2]),
             ga[1] * ga[1] - m * ga[0] * ga[2]}};
  }

  /// F(x, y) of implicit_coefficients() at p (exact): zero iff p is on the conic.
  FT implicit_value(const Point_2& p) const {
    const std::array<FT, 6> c = implicit_coefficients();
    return c[0] * p.x() * p.x() + c[1] * p.x() * p.y() + c[2] * p.y() * p.y() + c[3] * p.x() + c[4] * p.y() + c[5];
  }

  /// b^2 - 4ac of eq. 14 (exact).
  FT conic_discriminant() const {
    const std::array<FT, 6> c = implicit_coefficients();
    return c[1] * c[1] - FT(4) * c[0] * c[2];
  }

  /// Eccentricity of the conic (double): 0 circle, (0,1) ellipse, 1 parabola, > 1 hyperbola.
  /// eps = sqrt(2R / (eta (a + c) + R)), R = sqrt((a-c)^2 + b^2), eta = -sign(det M) of the
  /// 3x3 conic matrix (the paper's formula assumes eta = 1). Computed from a copy translated to
  /// P0 and scaled by an exact power of two (eccentricity is similarity invariant), and with
  /// the quadratic part divided by 4 w^2 when that exceeds 1, so no overflow or underflow at any
  /// scale or weight. Exact at the special values: returns 0 when (a-c)^2 + b^2 == 0 and 1 when
  /// w == 1, both decided exactly on the exact input values; eta is decided exactly too.
  double eccentricity() const {
    if (conic_type() == Conic_type::PARABOLA) return 1.0;
    double eta = 1.0;
    {
      // Exact: the circle test and eta = -sign(det M) (for large w the conic is nearly the line
      // pair P0P1, P1P2, det M nearly 0, and its sign in double would be rounding noise).
      using internal::common::to_gmpq;
      typedef CGAL::Gmpq Q;
      Q al[3], be[3], ga[3];
      for (int i = 0; i < 3; ++i) {
        const Point_2& pj = p_[(i + 1) % 3];
        const Point_2& pk = p_[(i + 2) % 3];
        const Q xj = to_gmpq(pj.x()), yj = to_gmpq(pj.y()), xk = to_gmpq(pk.x()), yk = to_gmpq(pk.y());
        al[i] = yj - yk;
        be[i] = xk - xj;
        ga[i] = xj * yk - yj * xk;
      }
      const Q ww = to_gmpq(w_), m = Q(4) * ww * ww;
      const Q a = al[1] * al[1] - m * al[0] * al[2], c = be[1] * be[1] - m * be[0] * be[2];
      const Q b = Q(2) * al[1] * be[1] - m * (al[0] * be[2] + be[0] * al[2]);
      if (CGAL::is_zero(a - c) && CGAL::is_zero(b)) return 0.0;
      const Q d = Q(2) * al[1] * ga[1] - m * (al[0] * ga[2] + ga[0] * al[2]);
      const Q e = Q(2) * be[1] * ga[1] - m * (be[0] * ga[2] + ga[0] * be[2]);
      const Q f = ga[1] * ga[1] - m * ga[0] * ga[2];
      // 4 det [[a, b/2, d/2], [b/2, c, e/2], [d/2, e/2, f]]
      const Q det4 = Q(4) * a * c * f + b * e * d - a * e * e - c * d * d - f * b * b;
      eta = CGAL::sign(det4) == CGAL::POSITIVE ? -1.0 : 1.0;
    }
    const double X[3] = {0.0, edges_.ex[0], edges_.ex[2]}, Y[3] = {0.0, edges_.ey[0], edges_.ey[2]};
    double al[3], be[3];
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      al[i] = Y[j] - Y[k]; be[i] = X[k] - X[j];
    }
    // The quadratic part of eq. 14 is u + m v with m = 4 w^2; for m > 1 it is divided by m
    // (the eccentricity is invariant under positive scaling), so that weights up to the largest
    // double do not overflow.
    const double m4 = 4.0 * wd_ * wd_;
    const double s = m4 > 1.0 ? 1.0 / (4.0 * wd_) / wd_ : 1.0, m = m4 > 1.0 ? 1.0 : m4;
    const double a = s * al[1] * al[1] - m * al[0] * al[2];
    const double b = s * 2.0 * al[1] * be[1] - m * (al[0] * be[2] + be[0] * al[2]);
    const double c = s * be[1] * be[1] - m * be[0] * be[2];
    const double R = std::hypot(a - c, b);
    const double den = eta * (a + c) + R;
    internal::require(den > 0 && R >= 0, "Rational_quadratic_bezier_2::eccentricity: internal error, R = ", R,
                      ", eta (a+c) + R = ", den);
    return std::sqrt(2.0 * R / den);
  }

  /// eq. 15 squared: w_hat^2 = |P2-P0|^2 / (2 (|P0-P1|^2 + |P2-P1|^2)), exact (rational).
  FT minimum_eccentricity_weight_squared() const {
    return minimum_eccentricity_weight_squared(p_[0], p_[1], p_[2]);
  }
  /// eq. 15 in double: the weight minimising the eccentricity for these control points
  /// (scale-invariant: from the edge vectors scaled by an exact power of two).
  double minimum_eccentricity_weight() const {
    const internal::conic::Scaled_edges& e = edges_;
    return std::sqrt(e.squared_length(2) / (2.0 * (e.squared_length(0) + e.squared_length(1))));
  }
  /// eq. 15 exactly, w_hat = sqrt(w_hat^2) as a CGAL::Sqrt_extension (meant for exact kernels):
  /// e.g. the clamp of eq. 16, mu w_hat > 1/2, is decided exactly by
  /// CGAL::compare(w * mu, Sqrt_extension_FT(FT(1) / FT(2))).
  Sqrt_extension_FT minimum_eccentricity_weight_sqrt_extension() const {
    return Sqrt_extension_FT(FT(0), FT(1), minimum_eccentricity_weight_squared());
  }
  /// eq. 15 squared for arbitrary P0, P1, P2 (P0 != P1 or P1 != P2). Exact in an exact kernel;
  /// in a floating kernel computed from the edge vectors scaled by an exact power of two (no
  /// overflow or underflow at any scale, relative error ~1e-15).
  static FT minimum_eccentricity_weight_squared(const Point_2& p0, const Point_2& p1, const Point_2& p2) {
    if constexpr (internal::common::Is_floating_nt<FT>::value) {
      const double x[3] = {CGAL::to_double(p0.x()), CGAL::to_double(p1.x()), CGAL::to_double(p2.x())};
      const double y[3] = {CGAL::to_double(p0.y()), CGAL::to_double(p1.y()), CGAL::to_double(p2.y())};
      const internal::conic::Scaled_edges e(x, y);
      const double den = 2.0 * (e.squared_length(0) + e.squared_length(1));
      internal::require(!e.degenerate && den > 0 && std::isfinite(den),
                        "minimum_eccentricity_weight_squared (eq. 15): P0 == P1 == P2 = (", x[1], ", ", y[1], ")");
      return FT(e.squared_length(2) / den);
    }
    const FT den = FT(2) * ((p0 - p1) * (p0 - p1) + (p2 - p1) * (p2 - p1));
    internal::require(!CGAL::is_zero(den), "minimum_eccentricity_weight_squared (eq. 15): P0 == P1 == P2 = (",
                      CGAL::to_double(p1.x()), ", ", CGAL::to_double(p1.y()), ")");
    return ((p2 - p0) * (p2 - p0)) / den;
  }

  // ---------------------------------------------------------------- subdivision
  /// Split at s in (0,1) by homogeneous de Casteljau, then back to standard form:
  /// the homogeneous pieces have weights (1, 1-s+sw, W(s)) and (W(s), (1-s)w+s, 1); the
  /// reparametrisation t -> t / (rho (1-t) + t) that makes the end weights 1 divides the middle
  /// weights by sqrt(W(s)). Exact in an exact kernel when W(s) is the square of a rational
  /// (e.g. always for a parabola, W = 1); otherwise the standard-form weight is irrational and
  /// this throws Precondition_error (use split_homogeneous(), which is always exact). In a
  /// floating kernel the weights carry the rounding of one sqrt.
  std::pair<Rational_quadratic_bezier_2, Rational_quadratic_bezier_2> split(const FT& s) const {
    internal::require(s > FT(0) && s < FT(1), "Rational_quadratic_bezier_2::split: s = ", CGAL::to_double(s),
                      " is not in (0,1)");
    const FT W = denominator(s), r = FT(1) - s;
    FT root(1);
    internal::require(internal::common::sqrt_in(W, root), "Rational_quadratic_bezier_2::split: W(s) = ",
                      CGAL::to_double(W), " at s = ", CGAL::to_double(s),
                      " is not the square of a rational, so the standard-form weights are irrational; "
                      "use split_homogeneous() for an exact split");
    const FT wl = r + s * w_, wr = r * w_ + s;
    const Point_2 m = point(s);
    const Point_2 l1((r * p_[0].x() + s * w_ * p_[1].x()) / wl, (r * p_[0].y() + s * w_ * p_[1].y()) / wl);
    const Point_2 r1((r * w_ * p_[1].x() + s * p_[2].x()) / wr, (r * w_ * p_[1].y() + s * p_[2].y()) / wr);
    return std::make_pair(Rational_quadratic_bezier_2(p_[0], l1, m, wl / root),
                          Rational_quadratic_bezier_2(m, r1, p_[2], wr / root));
  }

  /// Exact split at s in (0,1) as two general rational Bezier pieces (homogeneous de Casteljau,
  /// end weights not normalised).
  std::pair<Rational_bezier_2<K>, Rational_bezier_2<K>> split_homogeneous(const FT& s) const {
    return to_rational_bezier().split(s);
  }

  /// The same arc traversed backwards: c_rev(t) = c(1-t) (P2, P1, P0, same w).
  Rational_quadratic_bezier_2 reversed() const { return Rational_quadratic_bezier_2(p_[2], p_[1], p_[0], w_); }

  friend std::ostream& operator<<(std::ostream& out, const Rational_quadratic_bezier_2& q) {
    return out << "Rational_quadratic_bezier_2[(" << q.xd_[0] << ", " << q.yd_[0] << "), (" << q.xd_[1] << ", "
               << q.yd_[1] << "), (" << q.xd_[2] << ", " << q.yd_[2] << "), w = " << q.wd_ << "]";
  }

private:
  std::vector<CGAL::Gmpq> exact_eq4() const {
    using internal::common::to_gmpq;
    return internal::eq4_coefficients<CGAL::Gmpq>(to_gmpq(p_[0].x()), to_gmpq(p_[0].y()), to_gmpq(p_[1].x()),
                                                   to_gmpq(p_[1].y()), to_gmpq(p_[2].x()), to_gmpq(p_[2].y()),
                                                   to_gmpq(w_));
  }

  void check_parameter(const FT& t, const char* fn) const {
    internal::require(t >= FT(0) && t <= FT(1), "Rational_quadratic_bezier_2::", fn, ": t = ", CGAL::to_double(t),
                      " is not in [0,1]");
  }

  // V(t) = 2 [ w s^2 (P1-P0) + s t (P2-P0) + w t^2 (P2-P1) ]
  Vector_2 hodograph_numerator(const FT& t) const {
    const FT s = FT(1) - t;
    return (p_[1] - p_[0]) * (FT(2) * w_ * s * s) + (p_[2] - p_[0]) * (FT(2) * s * t) +
           (p_[2] - p_[1]) * (FT(2) * w_ * t * t);
  }
  // V'(t) = 2 [ -2 w s (P1-P0) + (1-2t) (P2-P0) + 2 w t (P2-P1) ]
  Vector_2 hodograph_numerator_derivative(const FT& t) const {
    const FT s = FT(1) - t;
    return (p_[1] - p_[0]) * (FT(-4) * w_ * s) + (p_[2] - p_[0]) * (FT(2) * (FT(1) - FT(2) * t)) +
           (p_[2] - p_[1]) * (FT(4) * w_ * t);
  }

  // eq. 5 on the scaled edge i (0: P1-P0, 1: P2-P1): D / (2 w^2 |e_i|^3), rescaled exactly.
  double end_curvature(int i) const {
    const double l = std::hypot(edges_.ex[i], edges_.ey[i]); // in [1, 2 sqrt 2) or exactly scaled
    internal::conic::Scaled_double r = area_, wq = internal::conic::Scaled_double::of(wd_), lq = internal::conic::Scaled_double::of(l);
    r /= wq;
    r /= wq;
    r /= lq;
    r /= lq;
    r /= lq;
    r.e -= 1L + 3L * edges_.k;
    return r.to_double(i == 0 ? "Rational_quadratic_bezier_2::curvature_at_source (eq. 5)"
                              : "Rational_quadratic_bezier_2::curvature_at_target (eq. 5)");
  }

  std::array<Point_2, 3> p_;
  FT w_;
  CGAL::Orientation orientation_;
  double xd_[3], yd_[3], wd_;
  internal::conic::Scaled_edges edges_;  // P1-P0, P2-P1, P2-P0 times 2^-k (exact power of two)
  internal::conic::Scaled_double area_;  // D = det(P1-P0, P2-P1), unscaled
};

// ---------------------------------------------------------------- interpolation (eq. 6, eq. 7)

/// The certified parameter at which Q is a curvature extremum (eq. 7), see
/// curvature_extremum_parameter().
template <class K>
struct Curvature_extremum_parameter {
  /// Bernstein coefficients of eq. 7 (eq. A.1): (-wA, -(A+B)/4, 0, (B+C)/4, wC), in FT (exact
  /// in an exact kernel; rounded in a floating kernel, where the certificate uses the exact
  /// values of the double inputs instead).
  Bernstein_polynomial<typename K::FT> polynomial;
  /// The exact root lies in [t_lower, t_upper] (f(t_lower) < 0 < f(t_upper) exactly, or
  /// t_lower == t_upper == root). Dyadic rationals, usually a few ulps apart.
  CGAL::Gmpq t_lower, t_upper;
  double t = 0.5;             ///< double approximation in [t_lower, t_upper]
  int sign_variations = 1;    ///< the certified sign variation count of eq. A.1 (always 1)
  int exact_evaluations = 0;  ///< exact sign evaluations the interval filter needed
};

/// Solves eq. 7: the parameter t in (0,1) at which the standard-form rational quadratic with end
/// points P0, P2, weight w, passing through Q at t (eq. 6), has a critical point of curvature
/// at Q. Verifies EXACTLY (Appendix A) that the eq.-A.1 coefficients have exactly one sign
/// variation, so the root is unique and simple, then refines it with a certified bracket (see
/// internal/conic/interpolation.h for the method and accuracy).
/// For a floating kernel the double fast path (interval filter, exact fallback) is used; for an
/// exact kernel the coefficients and their signs are exact and the bracket is certified by
/// interval evaluation of enclosures of the exact coefficients, exact evaluation if needed.
/// \throws Precondition_error if a coordinate or w is not finite, w <= 0, P0 == Q or P2 == Q.
template <class K>
Curvature_extremum_parameter<K> curvature_extremum_parameter(const typename K::Point_2& p0,
                                                             const typename K::Point_2& q,
                                                             const typename K::Point_2& p2,
                                                             const typename K::FT& w) {
  typedef typename K::FT FT;
  const char* fn = "curvature_extremum_parameter (eq. 7)";
  Curvature_extremum_parameter<K> out;
  const FT v0x = p0.x() - q.x(), v0y = p0.y() - q.y(), v2x = p2.x() - q.x(), v2y = p2.y() - q.y();
  const FT sx = v0x + v2x, sy = v0y + v2y;
  const FT A = v0x * v0x + v0y * v0y, C = v2x * v2x + v2y * v2y;
  const FT AB = v0x * sx + v0y * sy, BC = v2x * sx + v2y * sy;
  const FT quarter = FT(1) / FT(4);
  if constexpr (internal::common::Is_floating_nt<FT>::value) {
    const internal::conic::Rational_quadratic_extremum_parameter r = internal::conic::rational_quadratic_extremum_parameter(
      CGAL::to_double(p0.x()), CGAL::to_double(p0.y()), CGAL::to_double(q.x()), CGAL::to_double(q.y()),
      CGAL::to_double(p2.x()), CGAL::to_double(p2.y()), CGAL::to_double(w));
    out.polynomial = Bernstein_polynomial<FT>(std::vector<FT>{-(w * A), -(AB * quarter), FT(0), BC * quarter, w * C});
    out.t = r.t;
    out.t_lower = CGAL::Gmpq(r.t_lower);
    out.t_upper = CGAL::Gmpq(r.t_upper);
    out.sign_variations = r.sign_variations;
    out.exact_evaluations = r.exact_evaluations;
    return out;
  } else {
    const char* names[3] = {"P0", "Q", "P2"};
    const typename K::Point_2* pts[3] = {&p0, &q, &p2};
    for (int i = 0; i < 3; ++i) {
      internal::check_finite_value(pts[i]->x(), fn, names[i]);
      internal::check_finite_value(pts[i]->y(), fn, names[i]);
    }
    internal::require(std::isfinite(CGAL::to_double(w)) && w > FT(0), fn, ": the weight must be finite and > 0, got w = ",
                      CGAL::to_double(w));
    internal::require(p0 != q, fn, ": P0 == Q = (", CGAL::to_double(q.x()), ", ", CGAL::to_double(q.y()), ")");
    internal::require(p2 != q, fn, ": P2 == Q = (", CGAL::to_double(q.x()), ", ", CGAL::to_double(q.y()), ")");
    const std::vector<FT> b{-(w * A), -(AB * quarter), FT(0), BC * quarter, w * C};
    out.polynomial = Bernstein_polynomial<FT>(b);
    // Appendix A, exactly: the signs of A, A+B, B+C, C (w > 0 checked above).
    const int sA = CGAL::sign(A), sAB = CGAL::sign(AB), sBC = CGAL::sign(BC), sC = CGAL::sign(C);
    const int variations = internal::conic::eq7_sign_variations(sA, sAB, sBC, sC, 1);
    internal::require(variations == 1 && sA > 0 && sC > 0 && sign_variations(out.polynomial) == 1, fn,
                      ": internal error: eq. A.1 has ", variations, " sign variations");
    out.sign_variations = variations;
    internal::conic::Rq_interval bi[5];
    for (int i = 0; i < 5; ++i) bi[i] = internal::common::to_interval_nt(b[i]);
    bool have_exact = false;
    std::array<CGAL::Gmpq, 5> exact;
    const internal::conic::Rational_quadratic_extremum_parameter r =
      internal::conic::certified_unique_root_quartic(bi, [&](double t) {
        if (!have_exact) {
          for (int i = 0; i < 5; ++i) exact[static_cast<std::size_t>(i)] = internal::common::to_gmpq(b[i]);
          have_exact = true;
        }
        return internal::conic::quartic_sign_exact(exact, t);
      });
    out.t = r.t;
    out.t_lower = CGAL::Gmpq(r.t_lower);
    out.t_upper = CGAL::Gmpq(r.t_upper);
    out.exact_evaluations = r.exact_evaluations;
    return out;
  }
}

/// eq. 6: the standard-form piece with end points P0, P2 and weight w that passes through Q at
/// parameter t in (0,1). P1 = Q - ((1-t)^2 (P0-Q) + t^2 (P2-Q)) / (2 (1-t) t w), which is eq. 6
/// rearranged (exact in an exact kernel, so point(t) == Q exactly there).
/// \throws Precondition_error unless 0 < t < 1, or if the resulting piece is degenerate.
template <class K>
Rational_quadratic_bezier_2<K> rational_quadratic_through(const typename K::Point_2& p0,
                                                          const typename K::Point_2& q,
                                                          const typename K::Point_2& p2,
                                                          const typename K::FT& w, const typename K::FT& t) {
  typedef typename K::FT FT;
  internal::require(t > FT(0) && t < FT(1), "rational_quadratic_through (eq. 6): t = ", CGAL::to_double(t),
                    " is not in (0,1)");
  internal::require(std::isfinite(CGAL::to_double(w)) && w > FT(0),
                    "rational_quadratic_through (eq. 6): the weight must be finite and > 0, got w = ",
                    CGAL::to_double(w));
  const FT s = FT(1) - t, d = FT(2) * s * t * w;
  const typename K::Vector_2 v = ((p0 - q) * (s * s) + (p2 - q) * (t * t)) / d;
  return Rational_quadratic_bezier_2<K>(p0, q - v, p2, w);
}

} // namespace fair

#endif // FAIR_RATIONAL_QUADRATIC_BEZIER_2_H
