// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Rational_quadratic_bezier_2<Kernel>: a conic arc as a rational quadratic Bezier piece in
// standard form (Yan, Schiller, Schaefer, "Circle reproduction with interpolatory curves at
// local maximal curvature points", eq. 1 -- "the paper" below):
//
//   c(t) = ((1-t)^2 P0 + 2(1-t)t w P1 + t^2 P2) / W(t),   W(t) = (1-t)^2 + 2(1-t)t w + t^2,
//
// t in [0,1], w > 0, and P0, P1, P2 not collinear (a genuine conic arc, never a segment).
// Models the CurvePiece_2 concept of doc/contributing.md. Declares with it its vocabulary: Conic_type
// (conic_type()), Curvature_extremum and Curvature_extremum_kind (curvature_extrema()).
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
#include <fair/Errors.h>
#include <fair/Rational_bezier_2.h>
#include <fair/internal/common/exact_conversion.h>
#include <fair/internal/conic/curvature_extrema.h>
#include <fair/internal/conic/implicit_form.h>
#include <fair/internal/conic/orientation.h>
#include <fair/internal/conic/scaled.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Sqrt_extension.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <type_traits>
#include <utility>
#include <vector>

namespace fair {

/// The affine type of a non-degenerate conic a x^2 + b xy + c y^2 + d x + e y + f = 0, decided
/// by the sign of the discriminant b^2 - 4ac (negative: ellipse, zero: parabola, positive:
/// hyperbola). For a rational quadratic Bezier piece in standard form with weight w > 0 and
/// non-collinear control points this is w < 1, w = 1, w > 1 respectively (conic_type()).
enum class Conic_type { ELLIPSE, PARABOLA, HYPERBOLA };

inline const char* to_string(Conic_type type) {
  switch (type) {
    case Conic_type::ELLIPSE: return "ellipse";
    case Conic_type::PARABOLA: return "parabola";
    case Conic_type::HYPERBOLA: return "hyperbola";
  }
  return "unknown";
}

inline std::ostream& operator<<(std::ostream& out, Conic_type type) { return out << to_string(type); }

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

/// A certified critical point of the curvature of a piece in (0,1), as returned by
/// Rational_quadratic_bezier_2::curvature_extrema() (eq. 4). The root is exactly t_lower when
/// t_lower == t_upper, otherwise it lies in the open interval (t_lower, t_upper).
struct Curvature_extremum {
  CGAL::Gmpq t_lower, t_upper;
  double t = 0.5;        ///< a double <= the root and within one ulp of it (Bernstein_root_isolation::root_approximation)
  int multiplicity = 1;  ///< exact multiplicity as a root of the eq.-4 polynomial
  Curvature_extremum_kind kind = Curvature_extremum_kind::MAXIMUM;
};

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
    orientation_ = internal::conic::checked_orientation<K>(p0, p1, p2, w);
    for (int i = 0; i < 3; ++i) {
      xd_[i] = CGAL::to_double(p_[i].x());
      yd_[i] = CGAL::to_double(p_[i].y());
    }
    wd_ = CGAL::to_double(w);
    edges_ = internal::conic::Scaled_edges(xd_, yd_);
    // D = det(P1-P0, P2-P1), unscaled; exact decision of D != 0 (see internal/conic/scaled.h).
    area_ = internal::conic::twice_signed_area(edges_, p0, p1, p2);
  }

  // ---------------------------------------------------------------- access
  /// 2: the piece is a rational quadratic (BernsteinPiece_2, doc/concepts.md).
  std::size_t degree() const { return 2; }
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

  /// c(t), eq. 1; t in [0,1]. Formed as the convex combination sum_i (b_i / W) P_i: the
  /// coefficients b_i / W lie in [0, 1] and sum to 1, so no intermediate exceeds the largest
  /// coordinate (the weighted sum before the division overflowed to inf for a piece near DBL_MAX).
  /// For w > 1 the b_i are divided by w first (b1 = 2 w s t overflowed for w near DBL_MAX, and
  /// inf / inf gave NaN: fuzz finding conic/regress-point-huge-weight), so every b_i stays <= 2.
  /// In a floating FT each coordinate is then clamped to the control points' range, where the exact value lies:
  /// in double, coefficients that sum to 1 + ulp turned three coordinates of -DBL_MAX into -inf
  /// (conic/regress-point-sum-beyond-dbl-max); the clamp only removes rounding beyond the range.
  /// The same value in an exact kernel; in double it differs from the sum-then-divide form by
  /// rounding only (a few ulp of the largest coordinate, test_kappa.cpp).
  Point_2 point(const FT& t) const {
    check_parameter(t, "point");
    const bool heavy = w_ > FT(1);
    const FT s = FT(1) - t, b0 = heavy ? s * s / w_ : s * s, b1 = heavy ? FT(2) * s * t : FT(2) * w_ * s * t,
             b2 = heavy ? t * t / w_ : t * t, W = b0 + b1 + b2;
    const FT a0 = b0 / W, a1 = b1 / W, a2 = b2 / W;
    // Only in a floating FT: an exact value lies in the range already, and comparing it with an
    // end point equal to it (t = 0, 1) would force EPECK's exact fallback on every call.
    const auto clamped = [](const FT& v, const FT& c0, const FT& c1, const FT& c2) {
      if constexpr (CGAL::Algebraic_structure_traits<FT>::Is_exact::value && !std::is_floating_point<FT>::value) {
        (void)c0, (void)c1, (void)c2;
        return v;
      } else {
        const FT lo = (std::min)((std::min)(c0, c1), c2), hi = (std::max)((std::max)(c0, c1), c2);
        return v < lo ? lo : (hi < v ? hi : v);
      }
    };
    return Point_2(clamped(a0 * p_[0].x() + a1 * p_[1].x() + a2 * p_[2].x(), p_[0].x(), p_[1].x(), p_[2].x()),
                   clamped(a0 * p_[0].y() + a1 * p_[1].y() + a2 * p_[2].y(), p_[0].y(), p_[1].y(), p_[2].y()));
  }

  /// c'(t) = V(t) / W(t)^2 (see the file comment); t in [0,1].
  /// \throws Precondition_error in a floating kernel when the value (or V(t), W(t)^2 on the way)
  /// is beyond double: c'(0) = 2w (P1 - P0), so a huge weight on huge differences has no
  /// representable derivative (fuzz finding conic/open-derivative-overflow); as curvature().
  Vector_2 derivative(const FT& t) const {
    check_parameter(t, "derivative");
    const FT W = denominator(t);
    const Vector_2 V = hodograph_numerator(t);
    return checked_finite(V / (W * W), "derivative", t);
  }

  /// c''(t) = (V' W - 2 V W') / W^3; t in [0,1].
  /// \throws Precondition_error in a floating kernel when the value is beyond double (as derivative()).
  Vector_2 second_derivative(const FT& t) const {
    check_parameter(t, "second_derivative");
    const FT W = denominator(t), W1 = FT(2) * (w_ - FT(1)) * (FT(1) - FT(2) * t);
    const Vector_2 V = hodograph_numerator(t), V1 = hodograph_numerator_derivative(t);
    return checked_finite((V1 * W - V * (FT(2) * W1)) / (W * W * W), "second_derivative", t);
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
    return Polynomial(internal::conic::eq4_coefficients<FT>(p_[0].x(), p_[0].y(), p_[1].x(), p_[1].y(), p_[2].x(),
                                                     p_[2].y(), w_));
  }

  /// True iff the eq.-4 polynomial vanishes identically (decided exactly on the exact values
  /// of the inputs): the arc is a circular arc and kappa is constant.
  bool has_constant_curvature() const {
    for (const CGAL::Gmpq& c : exact_eq4()) if (!CGAL::is_zero(c)) return false;
    return true;
  }

  /// The certified critical points of kappa in the open interval (0,1), sorted, each with its
  /// kind (odd multiplicity: MAXIMUM or MINIMUM of |kappa|; even: STATIONARY). Certified in every
  /// kernel: computed on the exact values of the inputs (interval fast path, exact Bernstein root
  /// isolation otherwise; see internal/conic/curvature_extrema.h). Empty for a circular arc
  /// (has_constant_curvature()). At most 2 entries for an ellipse (w < 1), at most 1 for a
  /// parabola or hyperbola (Sec. 3.1 of the paper).
  std::vector<Curvature_extremum> curvature_extrema() const {
    using internal::common::to_interval_nt;
    Curvature_extremum x;
    const int fast = internal::conic::eq4_unique_extremum(
      to_interval_nt(p_[0].x()), to_interval_nt(p_[0].y()), to_interval_nt(p_[1].x()), to_interval_nt(p_[1].y()),
      to_interval_nt(p_[2].x()), to_interval_nt(p_[2].y()), to_interval_nt(w_), [this]() { return exact_eq4(); }, x);
    if (fast == 0) return {};
    if (fast == 1) return {x};
    const Bernstein_polynomial<CGAL::Gmpq> E(exact_eq4());
    if (E.is_zero()) return {}; // circular arc: constant curvature, no isolated extrema
    return internal::conic::isolated_curvature_extrema<Curvature_extremum>(E);
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
  /// of the conic carrying the arc, exact in FT, normalised so that F(P1) = D^2 > 0 (closed form
  /// in internal/conic/implicit_form.h).
  std::array<FT, 6> implicit_coefficients() const {
    const FT x[3] = {p_[0].x(), p_[1].x(), p_[2].x()}, y[3] = {p_[0].y(), p_[1].y(), p_[2].y()};
    return internal::conic::implicit_coefficients(x, y, w_);
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

  /// Eccentricity of the conic (double): 0 circle, (0,1) ellipse, 1 parabola, > 1 hyperbola,
  /// relative error ~1e-15 at any scale or weight (no overflow or underflow). Exact at the special
  /// values: 0 for a circle and 1 for w == 1, both decided exactly on the exact input values
  /// (method in internal/conic/implicit_form.h).
  double eccentricity() const {
    if (conic_type() == Conic_type::PARABOLA) return 1.0;
    using internal::common::to_gmpq;
    const CGAL::Gmpq x[3] = {to_gmpq(p_[0].x()), to_gmpq(p_[1].x()), to_gmpq(p_[2].x())};
    const CGAL::Gmpq y[3] = {to_gmpq(p_[0].y()), to_gmpq(p_[1].y()), to_gmpq(p_[2].y())};
    typedef CGAL::Gmpq Q;
    const std::array<Q, 6> k = internal::conic::implicit_coefficients(x, y, to_gmpq(w_));
    const Q &a = k[0], &b = k[1], &c = k[2], &d = k[3], &e = k[4], &f = k[5];
    if (CGAL::is_zero(a - c) && CGAL::is_zero(b)) return 0.0;
    // eta = -sign(4 det M) of the 3x3 conic matrix, exact (internal/conic/implicit_form.h).
    const Q det4 = Q(4) * a * c * f + b * e * d - a * e * e - c * d * d - f * b * b;
    const bool eta_positive = CGAL::sign(det4) != CGAL::POSITIVE;
    // eps^2 = 2R / (eta (a + c) + R), R = sqrt(D2), D2 = (a - c)^2 + b^2. On a flat control
    // triangle eta (a + c) + R cancels to nothing in double (issue 29 #5: P1 = (1, 1e-9), w = 2
    // gave a denominator <= 0). Where eta (a + c) < 0 it is rewritten without cancellation as
    //   eta (a + c) + R = (R^2 - (a + c)^2) / (R - eta (a + c)) = (b^2 - 4ac) / (R - eta (a + c)),
    // with the discriminant b^2 - 4ac exact. The exact D2, A = eta (a + c) and b^2 - 4ac are
    // scaled by exact powers of two (eps is homogeneous of degree 0) so that their doubles
    // neither overflow nor underflow, whatever the scale of the input and the weight.
    const Q D2 = (a - c) * (a - c) + b * b, A = eta_positive ? a + c : -(a + c), disc = b * b - Q(4) * a * c;
    // 2^(-2s) D2 is near 1: log2 |p/q| is within 1 of bits(p) - bits(q).
    const long bits = long(mpz_sizeinbase(mpq_numref(D2.mpq()), 2)) - long(mpz_sizeinbase(mpq_denref(D2.mpq()), 2));
    const long s = bits / 2;
    auto scaled = [](const Q& v, long shift) {
      Q r;  // a fresh value: a copy of v would share (and modify) v's GMP number
      if (shift >= 0) mpq_div_2exp(r.mpq(), v.mpq(), static_cast<unsigned long>(shift));
      else mpq_mul_2exp(r.mpq(), v.mpq(), static_cast<unsigned long>(-shift));
      return CGAL::to_double(r);
    };
    const double d2 = scaled(D2, 2 * s), as = scaled(A, s), ds = scaled(disc, 2 * s);
    const double R = std::sqrt(d2);
    double eps2;
    if (as >= 0) eps2 = 2.0 * R / (as + R);
    else eps2 = 2.0 * R * (R - as) / ds;
    FAIR_ASSERT_MSG(!(eps2 < 0), "Rational_quadratic_bezier_2::eccentricity: eps^2 = ", eps2, " (R = ", R,
                    ", eta (a + c) = ", as, ", b^2 - 4ac = ", ds, ")");
    // A hyperbola that is nearly its line pair (w near the largest double) can have an
    // eccentricity beyond the double range: refused, not returned as inf.
    if (!std::isfinite(eps2))
      throw Invalid_input_error(internal::message("Rational_quadratic_bezier_2::eccentricity: the eccentricity of the "
                                                  "conic with weight w = ", wd_, " overflows double precision"));
    return std::sqrt(eps2);
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
      return FT(internal::conic::minimum_eccentricity_weight_squared(
        CGAL::to_double(p0.x()), CGAL::to_double(p0.y()), CGAL::to_double(p1.x()), CGAL::to_double(p1.y()),
        CGAL::to_double(p2.x()), CGAL::to_double(p2.y())));
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
    return internal::conic::eq4_coefficients<CGAL::Gmpq>(to_gmpq(p_[0].x()), to_gmpq(p_[0].y()), to_gmpq(p_[1].x()),
                                                   to_gmpq(p_[1].y()), to_gmpq(p_[2].x()), to_gmpq(p_[2].y()),
                                                   to_gmpq(w_));
  }

  /// `v`, unless a floating kernel overflowed (or met inf - inf) computing it.
  Vector_2 checked_finite(const Vector_2& v, const char* fn, const FT& t) const {
    if constexpr (internal::common::Is_floating_nt<FT>::value) {
      const double x = CGAL::to_double(v.x()), y = CGAL::to_double(v.y());
      internal::require(std::isfinite(x) && std::isfinite(y), "Rational_quadratic_bezier_2::", fn, ": the value at t = ",
                        CGAL::to_double(t), " is beyond double precision (w = ", CGAL::to_double(w_),
                        ", control points up to ", std::max({std::abs(xd_[0]), std::abs(xd_[1]), std::abs(xd_[2]),
                                                             std::abs(yd_[0]), std::abs(yd_[1]), std::abs(yd_[2])}),
                        "); scale the piece down");
    }
    return v;
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

  double end_curvature(int i) const {
    return internal::conic::end_curvature(area_, edges_, wd_, i,
                                          i == 0 ? "Rational_quadratic_bezier_2::curvature_at_source (eq. 5)"
                                                 : "Rational_quadratic_bezier_2::curvature_at_target (eq. 5)");
  }

  std::array<Point_2, 3> p_;
  FT w_;
  CGAL::Orientation orientation_;
  double xd_[3], yd_[3], wd_;
  internal::conic::Scaled_edges edges_;  // P1-P0, P2-P1, P2-P0 times 2^-k (exact power of two)
  internal::conic::Scaled_double area_;  // D = det(P1-P0, P2-P1), unscaled
};

} // namespace fair

#endif // FAIR_RATIONAL_QUADRATIC_BEZIER_2_H
