// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Fast certified solver for the parameter of a curvature extremum of a rational quadratic
// (Yan, Schiller, Schaefer, "Circle reproduction with interpolatory curves at local maximal
// curvature points", eq. 7 and Appendix A). Given the end points P0, P2, the interpolated
// point Q and the weight w > 0, the parameter t in (0,1) at which the standard-form rational
// quadratic through P0, Q (at t), P2 has a curvature extremum at Q is the unique root in (0,1)
// of the quartic
//
//   f(t) = -w A (1-t)^4 - (A+B) (1-t)^3 t + (B+C) (1-t) t^3 + w C t^4            (eq. 7)
//
//   A = |P0-Q|^2,  B = (P0-Q).(P2-Q),  C = |P2-Q|^2,
//
// whose Bernstein coefficients are (eq. A.1 with w0 = w2 = 1, w1 = w)
//
//   ( -w A,  -(A+B)/4,  0,  (B+C)/4,  w C ).
//
// Certificate (Appendix A carried out in code): A > 0 and C > 0 (P0 != Q != P2) and w > 0 give
// b0 < 0 < b4; (A+B) + (B+C) = |v0+v2|^2 >= 0 (eq. A.2) forbids A+B < 0 and B+C < 0 together,
// i.e. b1 > 0 > b3, so the coefficient signs have exactly one variation and,
// by Descartes' rule of signs in the Bernstein basis, f has exactly one root in (0,1), simple.
// The code does not trust the proof: it determines the four signs (by interval arithmetic, or
// exactly with CGAL::Gmpq when the intervals cannot decide) and counts the variations.
//
// Root refinement: certified_unique_root_quartic (internal/conic/quartic_root.h), the shared
// certified-bracket mechanism of the Bernstein internals
// (fair::internal::bernstein::tighten_double_bracket, internal/bernstein/unique_root.h), fed with interval
// ENCLOSURES of the exact coefficients (CGAL::Interval_nt, outward rounding) and an exact
// fallback that evaluates f exactly (CGAL::Gmpq) at double points: safeguarded Newton in double,
// a bracket grown by certified interval signs, then shrunk to <= 32 ulps by bisection with the
// exact fallback where the intervals cannot decide.
//
// Guarantee: for the exact values of the double inputs, f(t_lower) < 0 < f(t_upper), or
// t_lower == t_upper is the exact root (f(t) == 0 exactly). Hence the exact root lies in
// [t_lower, t_upper]; t is a double inside it. The bracket is at most 32 ulps wide (relative
// accuracy ~1e-15 for well-conditioned inputs).
// Fallback: overflow or underflow of the double enclosures (coordinates beyond ~1e150 or below
// ~1e-150) only makes the filter fail; the exact stage then decides, so there is no failure mode.
// Unlike fair::certified_unique_root (Bernstein_root_isolation.h), which certifies the root of
// the quartic with ROUNDED double coefficients, this certifies the root for the exact inputs.

#ifndef FAIR_INTERNAL_CONIC_INTERPOLATION_H
#define FAIR_INTERNAL_CONIC_INTERPOLATION_H

#include <fair/Errors.h>
#include <fair/internal/common/exact_conversion.h>
#include <fair/internal/conic/quartic_root.h>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>

namespace fair {
namespace internal {
namespace conic {

/// Result of the certified unique-root solver of eq. 7: the certified root of the eq.-A.1
/// quartic and its certified sign variation count.
struct Rational_quadratic_extremum_parameter : Quartic_root {
  int sign_variations = 1;   ///< the certified variation count of eq. A.1 (always 1)
};

/// Number of sign variations (zeros skipped) of the eq.-A.1 sign pattern
/// (-sign(w A), -sign(A+B), 0, sign(B+C), sign(w C)), given the exact signs of its parts.
inline int eq7_sign_variations(int sign_A, int sign_AB, int sign_BC, int sign_C, int sign_w) {
  const int s[5] = {-sign_w * sign_A, -sign_AB, 0, sign_BC, sign_w * sign_C};
  int last = 0, count = 0;
  for (int x : s) {
    if (x == 0) continue;
    if (last != 0 && x != last) ++count;
    last = x;
  }
  return count;
}

/// Bernstein coefficients of eq. 7 (eq. A.1) in any number type (exact for an exact one).
template <class NT>
std::array<NT, 5> eq7_coefficients(const NT& p0x, const NT& p0y, const NT& qx, const NT& qy, const NT& p2x,
                                   const NT& p2y, const NT& w) {
  const NT v0x = p0x - qx, v0y = p0y - qy, v2x = p2x - qx, v2y = p2y - qy;
  const NT sx = v0x + v2x, sy = v0y + v2y;
  const NT A = v0x * v0x + v0y * v0y, C = v2x * v2x + v2y * v2y;
  const NT AB = v0x * sx + v0y * sy, BC = v2x * sx + v2y * sy; // A+B, B+C
  const NT quarter = NT(1) / NT(4);
  return {{-(w * A), -(AB * quarter), NT(0), BC * quarter, w * C}};
}

/// eq. 7 / Appendix A in double with interval filter and exact fallback; see the file comment.
/// Inputs: P0 = (p0x, p0y), Q = (qx, qy), P2 = (p2x, p2y), weight w of P1.
/// \throws Precondition_error if a value is not finite, w <= 0, P0 == Q or P2 == Q.
inline Rational_quadratic_extremum_parameter
rational_quadratic_extremum_parameter(double p0x, double p0y, double qx, double qy, double p2x,
                                      double p2y, double w) {
  const char* fn = "rational_quadratic_extremum_parameter (eq. 7)";
  require(std::isfinite(p0x) && std::isfinite(p0y) && std::isfinite(qx) && std::isfinite(qy) &&
              std::isfinite(p2x) && std::isfinite(p2y),
          fn, ": non-finite input P0 = (", p0x, ", ", p0y, "), Q = (", qx, ", ", qy, "), P2 = (",
          p2x, ", ", p2y, ")");
  require(std::isfinite(w) && w > 0, fn, ": the weight must be finite and > 0, got w = ", w);
  require(!(p0x == qx && p0y == qy), fn, ": P0 == Q = (", qx, ", ", qy, ")");
  require(!(p2x == qx && p2y == qy), fn, ": P2 == Q = (", qx, ", ", qy, ")");

  Rq_interval b[5];
  int sA, sAB, sBC, sC;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const Rq_interval v0x = Rq_interval(p0x) - Rq_interval(qx), v0y = Rq_interval(p0y) - Rq_interval(qy);
    const Rq_interval v2x = Rq_interval(p2x) - Rq_interval(qx), v2y = Rq_interval(p2y) - Rq_interval(qy);
    const Rq_interval sx = v0x + v2x, sy = v0y + v2y;
    const Rq_interval A = CGAL::square(v0x) + CGAL::square(v0y);
    const Rq_interval C = CGAL::square(v2x) + CGAL::square(v2y);
    const Rq_interval AB = v0x * sx + v0y * sy, BC = v2x * sx + v2y * sy;
    const Rq_interval W(w);
    b[0] = -(W * A);
    b[1] = -(AB * 0.25);
    b[2] = Rq_interval(0);
    b[3] = BC * 0.25;
    b[4] = W * C;
    const CGAL::Uncertain<CGAL::Sign> uA = CGAL::sign(A), uAB = CGAL::sign(AB), uBC = CGAL::sign(BC),
                                      uC = CGAL::sign(C);
    sA = uA.is_certain() ? int(uA.make_certain()) : 2;
    sAB = uAB.is_certain() ? int(uAB.make_certain()) : 2;
    sBC = uBC.is_certain() ? int(uBC.make_certain()) : 2;
    sC = uC.is_certain() ? int(uC.make_certain()) : 2;
  }
  // Exact coefficients, computed only when a sign is uncertain or the filter fails.
  std::optional<std::array<CGAL::Gmpq, 5>> exact; // Gmpq construction allocates: only on demand
  auto exact_coefficients = [&]() -> const std::array<CGAL::Gmpq, 5>& {
    if (!exact)
      exact.emplace(eq7_coefficients<CGAL::Gmpq>(CGAL::Gmpq(p0x), CGAL::Gmpq(p0y), CGAL::Gmpq(qx), CGAL::Gmpq(qy),
                                           CGAL::Gmpq(p2x), CGAL::Gmpq(p2y), CGAL::Gmpq(w)));
    return *exact;
  };
  int extra = 0;
  if (sA == 2 || sAB == 2 || sBC == 2 || sC == 2) {
    const std::array<CGAL::Gmpq, 5>& e = exact_coefficients();
    // b0 = -wA, b1 = -(A+B)/4, b3 = (B+C)/4, b4 = wC with w > 0.
    sA = -int(CGAL::sign(e[0]));
    sAB = -int(CGAL::sign(e[1]));
    sBC = int(CGAL::sign(e[3]));
    sC = int(CGAL::sign(e[4]));
    extra = 1;
  }
  const int variations = eq7_sign_variations(sA, sAB, sBC, sC, 1);
  // Appendix A: exactly one variation. Anything else is a bug, never a property of the input.
  FAIR_ASSERT_MSG(variations == 1 && sA > 0 && sC > 0, fn, ": eq. A.1 has ", variations,
                  " sign variations (signs A ", sA, ", A+B ", sAB, ", B+C ", sBC, ", C ", sC, ") for P0 = (", p0x,
                  ", ", p0y, "), Q = (", qx, ", ", qy, "), P2 = (", p2x, ", ", p2y, "), w = ", w);
  // The unique simple root with f(0) < 0 < f(1) exactly (the enclosures of b0, b4 may straddle
  // 0 after underflow; the shared bracket mechanism then decides by exact signs).
  Rational_quadratic_extremum_parameter out;
  static_cast<Quartic_root&>(out) =
    certified_unique_root_quartic(b, [&](double t) { return quartic_sign_exact(exact_coefficients(), t); });
  out.exact_evaluations += extra;
  out.sign_variations = variations;
  return out;
}

/// The input checks of eq. 7 in a non-floating kernel (rational_quadratic_extremum_parameter
/// checks the double inputs itself). \throws Precondition_error if a coordinate or w is not
/// finite, w <= 0, P0 == Q or P2 == Q.
template <class Point_2, class FT>
void check_eq7_input(const Point_2& p0, const Point_2& q, const Point_2& p2, const FT& w, const char* fn) {
  const char* names[3] = {"P0", "Q", "P2"};
  const Point_2* pts[3] = {&p0, &q, &p2};
  for (int i = 0; i < 3; ++i) {
    const double x = CGAL::to_double(pts[i]->x()), y = CGAL::to_double(pts[i]->y());
    require(std::isfinite(x), fn, ": ", names[i], " = ", x, " is not finite");
    require(std::isfinite(y), fn, ": ", names[i], " = ", y, " is not finite");
  }
  require(std::isfinite(CGAL::to_double(w)) && w > FT(0), fn, ": the weight must be finite and > 0, got w = ",
          CGAL::to_double(w));
  require(p0 != q, fn, ": P0 == Q = (", CGAL::to_double(q.x()), ", ", CGAL::to_double(q.y()), ")");
  require(p2 != q, fn, ": P2 == Q = (", CGAL::to_double(q.x()), ", ", CGAL::to_double(q.y()), ")");
}

/// eq. 7 / Appendix A in a non-floating kernel, on the exact eq.-A.1 coefficients `b` (FT):
/// the coefficient signs are exact, and the bracket is certified by interval evaluation of
/// enclosures of the exact coefficients, exact (Gmpq) evaluation where those cannot decide.
template <class FT>
Rational_quadratic_extremum_parameter exact_rational_quadratic_extremum_parameter(const std::array<FT, 5>& b,
                                                                                  const char* fn) {
  // Appendix A, exactly: the signs of A, A+B, B+C, C (w > 0 checked by check_eq7_input).
  const int sA = -int(CGAL::sign(b[0])), sAB = -int(CGAL::sign(b[1])), sBC = int(CGAL::sign(b[3]));
  const int sC = int(CGAL::sign(b[4]));
  const int variations = eq7_sign_variations(sA, sAB, sBC, sC, 1);
  // Appendix A: exactly one variation. Anything else is a bug, never a property of the input.
  FAIR_ASSERT_MSG(variations == 1 && sA > 0 && sC > 0, fn, ": eq. A.1 has ", variations, " sign variations");
  Rq_interval bi[5];
  for (int i = 0; i < 5; ++i) bi[i] = common::to_interval_nt(b[static_cast<std::size_t>(i)]);
  std::optional<std::array<CGAL::Gmpq, 5>> exact; // Gmpq construction allocates: only on demand
  Rational_quadratic_extremum_parameter out;
  static_cast<Quartic_root&>(out) = certified_unique_root_quartic(bi, [&](double t) {
    if (!exact) {
      exact.emplace();
      for (std::size_t i = 0; i < 5; ++i) (*exact)[i] = common::to_gmpq(b[i]);
    }
    return quartic_sign_exact(*exact, t);
  });
  out.sign_variations = variations;
  return out;
}

/// eq. 6 in double, written relative to Q for accuracy: with s = 1 - t,
///   P1 = Q - (s^2 (P0 - Q) + t^2 (P2 - Q)) / (2 s t w),
/// which is eq. 6 rearranged with (1-t)^2 + 2(1-t)t w + t^2 - 2(1-t)t w = s^2 + t^2 (eq. 8).
/// \throws Precondition_error unless 0 < t < 1 and w > 0 (finite).
inline void rational_quadratic_middle_control_point(double p0x, double p0y, double qx, double qy,
                                                    double p2x, double p2y, double w, double t,
                                                    double& p1x, double& p1y) {
  require(t > 0 && t < 1, "rational_quadratic_middle_control_point (eq. 6): t must be in (0,1), got ", t);
  require(std::isfinite(w) && w > 0, "rational_quadratic_middle_control_point (eq. 6): w must be finite and > 0, got ", w);
  const double s = 1.0 - t, d = 2.0 * s * t * w;
  p1x = qx - (s * s * (p0x - qx) + t * t * (p2x - qx)) / d;
  p1y = qy - (s * s * (p0y - qy) + t * t * (p2y - qy)) / d;
}

} // namespace conic
} // namespace internal
} // namespace fair

#endif // FAIR_INTERNAL_CONIC_INTERPOLATION_H
