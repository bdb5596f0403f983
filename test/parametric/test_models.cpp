// Tests of the ParametricCurve_2 models, the Fresnel integrals and the marked-point parameters
// (Parametric_curve_2.h, Marked_point_parameters.h): known values, independent oracles
// (quadrature, finite differences, the printed eq. 4), degenerate inputs and typed errors.

#include <fair/Marked_point_parameters.h>
#include <fair/Parametric_curve_2.h>
#include <fair/internal/metrics/quadrature.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

using fair_test::pi;

// Reference values of C(x), S(x): mpmath 1.3 fresnelc/fresnels at 30 digits.
struct Fresnel_reference {
  double x, c, s;
};
const Fresnel_reference fresnel_table[] = {
    {0.1, 0.099997532627085073601, 0.00052358954761221068668}, {0.5, 0.49234422587144639288, 0.064732432859999277611},
    {1, 0.77989340037682282947, 0.43825914739035476608},       {1.5, 0.44526117603982153506, 0.69750496008209301308},
    {1.6, 0.36546168344048765296, 0.63888768350938083462},     {2, 0.4882534060753407545, 0.3434156783636982422},
    {3, 0.60572078929768562956, 0.4963129989673750361},        {5, 0.5636311887040122311, 0.49919138191711688675},
    {10, 0.49989869420551572361, 0.4681699785848822404},       {37.5, 0.49675345773238294253, 0.50784286709856039234},
    {100, 0.49999989867881789756, 0.49681690114783755327}};

TEST(Fresnel, KnownValuesBothRegimes) {
  for (const Fresnel_reference& r : fresnel_table) {
    const fair::Fresnel_integrals f = fair::fresnel_integrals(r.x);
    EXPECT_NEAR(f.c, r.c, 2e-15) << "x = " << r.x;
    EXPECT_NEAR(f.s, r.s, 2e-15) << "x = " << r.x;
    const fair::Fresnel_integrals g = fair::fresnel_integrals(-r.x); // odd
    EXPECT_EQ(g.c, -f.c);
    EXPECT_EQ(g.s, -f.s);
  }
  const fair::Fresnel_integrals z = fair::fresnel_integrals(0.0);
  EXPECT_EQ(z.c, 0.0);
  EXPECT_EQ(z.s, 0.0);
}

TEST(Fresnel, ContinuousAtTheHandoverAndTendsToOneHalf) {
  const double x = fair::internal::parametric::fresnel_series_limit;
  const fair::Fresnel_integrals a = fair::fresnel_integrals(x), b = fair::fresnel_integrals(std::nextafter(x, 10.0));
  EXPECT_NEAR(a.c, b.c, 4e-15);
  EXPECT_NEAR(a.s, b.s, 4e-15);
  // C(x) - 1/2 ~ sin(pi x^2/2)/(pi x): within 1/(pi x) of 1/2
  for (double big : {1e3, 1e5, 1e8}) {
    const fair::Fresnel_integrals f = fair::fresnel_integrals(big);
    EXPECT_LE(std::fabs(f.c - 0.5), 1.0 / (pi * big) * (1 + 1e-6));
    EXPECT_LE(std::fabs(f.s - 0.5), 1.0 / (pi * big) * (1 + 1e-6));
  }
  EXPECT_THROW(fair::fresnel_integrals(NAN), fair::Precondition_error);
}

TEST(Fresnel, AgreesWithAdaptiveQuadratureOnSeededArguments) {
  std::mt19937 rng(20261201);
  std::uniform_real_distribution<double> d(0.0, 6.0);
  fair::Quadrature_options o;
  o.relative_tolerance = 1e-15;
  o.absolute_tolerance = 1e-16;
  for (int k = 0; k < 40; ++k) {
    const double x = d(rng);
    const double c = fair::internal::metrics::adaptive_integral([](double t) { return std::cos(0.5 * pi * t * t); }, 0, x,
                                                                o, "test").value;
    const double s = fair::internal::metrics::adaptive_integral([](double t) { return std::sin(0.5 * pi * t * t); }, 0, x,
                                                                o, "test").value;
    const fair::Fresnel_integrals f = fair::fresnel_integrals(x);
    EXPECT_NEAR(f.c, c, 3e-15) << "x = " << x;
    EXPECT_NEAR(f.s, s, 3e-15) << "x = " << x;
  }
}

// The jet against 6th-order central differences of the value (and of the first derivative).
template <class Curve>
void expect_consistent_jet(const Curve& f, double tol) {
  const double a = f.parameter_begin(), b = f.parameter_end(), h = 1e-3 * (b - a);
  for (int k = 1; k < 10; ++k) {
    const double u = a + (b - a) * k / 10.0;
    auto diff = [&](auto get) {
      return (get(f.jet(u + 3 * h)) - 9 * get(f.jet(u + 2 * h)) + 45 * get(f.jet(u + h)) - 45 * get(f.jet(u - h)) +
              9 * get(f.jet(u - 2 * h)) - get(f.jet(u - 3 * h))) /
             (60 * h);
    };
    const fair::Curve_jet_2 j = f.jet(u);
    const double scale = 1 + std::hypot(j.dx, j.dy) + std::hypot(j.ddx, j.ddy);
    EXPECT_NEAR(diff([](const fair::Curve_jet_2& q) { return q.x; }), j.dx, tol * scale) << "u = " << u;
    EXPECT_NEAR(diff([](const fair::Curve_jet_2& q) { return q.y; }), j.dy, tol * scale) << "u = " << u;
    EXPECT_NEAR(diff([](const fair::Curve_jet_2& q) { return q.dx; }), j.ddx, tol * scale) << "u = " << u;
    EXPECT_NEAR(diff([](const fair::Curve_jet_2& q) { return q.dy; }), j.ddy, tol * scale) << "u = " << u;
  }
}

TEST(ParametricModels, JetsAreTheDerivativesOfTheValues) {
  expect_consistent_jet(fair::Archimedean_spiral_2(0.1, 0.2, 0.5, 12.0, 1, -2), 1e-9);
  expect_consistent_jet(fair::Circle_involute_2(0.7, 0.3, 6.0, -1, 1), 1e-9);
  expect_consistent_jet(fair::Circle_involute_2(0.7, -6.0, -0.3), 1e-9);
  expect_consistent_jet(fair::Clothoid_2(0.3, -0.7, -2.0, 4.0, 2.0, 1, 1, 0.4), 1e-9);
  expect_consistent_jet(fair::Parametric_circle_arc_2(1, 2, 3, -1.0, 4.0), 1e-9);
  expect_consistent_jet(fair::Parametric_conic_arc_2(0, 0, 1, 2, 3, 0, 0.4), 1e-9);
  expect_consistent_jet(fair::Parametric_conic_arc_2(0, 0, 1, 2, 3, 0, 3.0), 1e-9);
  expect_consistent_jet(fair::Parametric_conic_arc_2(0, 0, 1, 2, 3, 0, -0.6), 1e-9);
}

TEST(ParametricModels, ClothoidIsTheFresnelCurveAndMatchesQuadrature) {
  // kappa0 = 0, c = pi, scale 1: (C(s), S(s)); also with 0 outside the domain
  for (const fair::Clothoid_2& f : {fair::Clothoid_2(0, pi, 0.0, 3.0), fair::Clothoid_2(0, pi, 2.0, 5.0)}) {
    for (int k = 0; k <= 20; ++k) {
      const double s = f.parameter_begin() + (f.parameter_end() - f.parameter_begin()) * k / 20.0;
      const fair::Fresnel_integrals r = fair::fresnel_integrals(s);
      const fair::Curve_jet_2 j = f.jet(s);
      EXPECT_NEAR(j.x, r.c, 1e-14) << "s = " << s;
      EXPECT_NEAR(j.y, r.s, 1e-14) << "s = " << s;
      EXPECT_NEAR(std::hypot(j.dx, j.dy), 1.0, 1e-15);
    }
  }
  // general: origin, direction, scale, against adaptive quadrature of the phase integral
  const double k0 = 0.3, c = -0.7, th = 0.4, sc = 2.0;
  const fair::Clothoid_2 f(k0, c, -2.0, 4.0, sc, 1, -1, th);
  fair::Quadrature_options o;
  o.relative_tolerance = 1e-15;
  o.absolute_tolerance = 1e-16;
  for (int k = 0; k <= 12; ++k) {
    const double s = -2.0 + 0.5 * k;
    const double ix = fair::internal::metrics::adaptive_integral(
        [&](double t) { return std::cos(th + k0 * t + 0.5 * c * t * t); }, 0, s, o, "test").value;
    const double iy = fair::internal::metrics::adaptive_integral(
        [&](double t) { return std::sin(th + k0 * t + 0.5 * c * t * t); }, 0, s, o, "test").value;
    const fair::Curve_jet_2 j = f.jet(s);
    EXPECT_NEAR(j.x, 1 + sc * ix, 1e-14);
    EXPECT_NEAR(j.y, -1 + sc * iy, 1e-14);
    const double kappa = (j.dx * j.ddy - j.dy * j.ddx) / std::pow(std::hypot(j.dx, j.dy), 3);
    EXPECT_NEAR(kappa, f.curvature(s), 1e-15);
    EXPECT_NEAR(kappa, (k0 + c * s) / sc, 1e-15);
  }
  // c = 0: a circle of radius scale/kappa0 through the origin with direction theta0 = 0
  const fair::Clothoid_2 circle(0.5, 0, 0.0, 10.0);
  for (double s : {0.0, 1.0, 5.5, 10.0}) {
    const fair::Curve_jet_2 j = circle.jet(s);
    EXPECT_NEAR(std::hypot(j.x, j.y - 2.0), 2.0, 1e-14);
  }
  EXPECT_THROW(fair::Clothoid_2(0, 1, 0.0, 1e4), fair::Precondition_error); // turns 5e7 rad
  EXPECT_THROW(fair::Clothoid_2(0, 1, 0.0, 1.0, 0.0), fair::Precondition_error);
  EXPECT_THROW(f.jet(4.5), fair::Precondition_error);
}

TEST(ParametricModels, SpiralThroughItsCenterIsRegular) {
  const double b = 0.25;
  const fair::Archimedean_spiral_2 f(-b * 1.0, b, 0.0, 3.0); // r = 0 at theta = 1
  const fair::Curve_jet_2 j = f.jet(1.0);
  EXPECT_NEAR(std::hypot(j.x, j.y), 0.0, 1e-17);
  EXPECT_NEAR(std::hypot(j.dx, j.dy), b, 1e-16);
  const double kappa = (j.dx * j.ddy - j.dy * j.ddx) / std::pow(std::hypot(j.dx, j.dy), 3);
  EXPECT_NEAR(kappa, 2 / b, 1e-13);
  EXPECT_THROW(fair::Archimedean_spiral_2(0, 0, 0, 1), fair::Precondition_error);
  EXPECT_THROW(fair::Archimedean_spiral_2(0, 1, 2, 1), fair::Precondition_error);
  EXPECT_THROW(fair::Archimedean_spiral_2(0, 1, 0, INFINITY), fair::Precondition_error);
}

TEST(ParametricModels, DegenerateParametersThrowTypedErrorsNamingThem) {
  try {
    fair::Circle_involute_2(1.0, -0.5, 2.0);
    FAIL() << "the cusp was accepted";
  } catch (const fair::Precondition_error& e) {
    EXPECT_NE(std::string(e.what()).find("cusp"), std::string::npos) << e.what();
  }
  EXPECT_THROW(fair::Circle_involute_2(1.0, 0.0, 2.0), fair::Precondition_error);
  EXPECT_THROW(fair::Circle_involute_2(-1.0, 1.0, 2.0), fair::Precondition_error);
  EXPECT_THROW(fair::Parametric_circle_arc_2(0, 0, 0, 0, 1), fair::Precondition_error);
  EXPECT_THROW(fair::Parametric_circle_arc_2(0, 0, 1, 1, 1), fair::Precondition_error);
  EXPECT_THROW(fair::Parametric_conic_arc_2(0, 0, 1, 1, 2, 0, -1.0), fair::Precondition_error);
  EXPECT_THROW(fair::Parametric_conic_arc_2(0, 0, 1, 1, 2, 0, 0.0), fair::Precondition_error);
  EXPECT_THROW(fair::Parametric_conic_arc_2(0, NAN, 1, 1, 2, 0, 1.0), fair::Precondition_error);
  const fair::Parametric_circle_arc_2 arc(0, 0, 1, 0, 1);
  EXPECT_THROW(arc.jet(1.5), fair::Precondition_error);
  EXPECT_THROW(arc.jet(NAN), fair::Precondition_error);
}

// The standard rational quadratic arc of opening alpha from (1,0): w = cos(alpha/2),
// P1 = (1, tan(alpha/2)).
fair::Parametric_conic_arc_2 standard_arc(double alpha) {
  return fair::Parametric_conic_arc_2(1, 0, 1, std::tan(alpha / 2), std::cos(alpha), std::sin(alpha), std::cos(alpha / 2));
}

// Eq. 4 as printed in the paper.
double eq4_printed(double ai, double a, bool first_case) {
  if (first_case)
    return (std::sin(ai + a / 2) - std::sin(a / 2) - std::sin(ai)) / (2 * (std::cos(a / 2) - 1) * (std::sin(a / 2) + std::sin(ai)));
  return (1 + std::cos(ai + a / 2) - std::cos(a / 2) - std::cos(ai)) /
         (2 * (std::cos(a / 2) - 1) * (std::cos(a / 2) + std::cos(ai)));
}

TEST(MarkedPointParameters, ClosedFormEqualsPrintedEq4AndNearestParameterOnCircles) {
  for (double degrees : {30.0, 90.0, 150.0, 179.0, 200.0, 239.0, 300.0}) {
    const double alpha = degrees * pi / 180;
    const fair::Parametric_conic_arc_2 arc = standard_arc(alpha);
    for (int k = 1; k < 12; ++k) {
      const double ai = alpha * k / 12.0;
      const double u = fair::circle_arc_parameter(ai, alpha);
      // the arc passes through C(alpha_i) at u
      const fair::Curve_jet_2 j = arc.jet(u);
      EXPECT_NEAR(j.x, std::cos(ai), 1e-14) << degrees << " " << ai;
      EXPECT_NEAR(j.y, std::sin(ai), 1e-14) << degrees << " " << ai;
      // eq. 5 finds the same parameter
      EXPECT_NEAR(fair::nearest_parameter(arc, std::cos(ai), std::sin(ai), 0, 1), u, 1e-13);
      // eq. 4 printed, in the case it is meant for; both cases agree where both are defined
      const bool first = ai < pi;
      EXPECT_NEAR(eq4_printed(ai, alpha, first), u, 1e-12) << degrees << " " << ai;
      if (std::fabs(std::sin(alpha / 2) + std::sin(ai)) > 1e-3 && std::fabs(std::cos(alpha / 2) + std::cos(ai)) > 1e-3) {
        EXPECT_NEAR(eq4_printed(ai, alpha, !first), u, 1e-10) << degrees << " " << ai;
      }
    }
    EXPECT_EQ(fair::circle_arc_parameter(0, alpha), 0.0);
    EXPECT_EQ(fair::circle_arc_parameter(alpha, alpha), 1.0);
  }
  EXPECT_THROW(fair::circle_arc_parameter(0.5, 2 * pi), fair::Precondition_error);
  EXPECT_THROW(fair::circle_arc_parameter(1.5, 1.0), fair::Precondition_error);
  EXPECT_THROW(fair::circle_arc_parameter(-0.1, 1.0), fair::Precondition_error);
}

TEST(MarkedPointParameters, ClosedFormIsWellConditionedWhereEq4Cancels) {
  // tiny alpha_i: eq. 4's numerator sin(ai + a/2) - sin(a/2) - sin(ai) cancels; the closed
  // form keeps full relative accuracy (reference: u = sin(ai/2) / (...) to first order = ai / a).
  const double alpha = 1.0, ai = 1e-9;
  const double u = fair::circle_arc_parameter(ai, alpha);
  EXPECT_NEAR(u / (std::sin(ai / 2) / (std::sin(ai / 2) + std::sin((alpha - ai) / 2))), 1.0, 1e-15);
  EXPECT_GT(std::fabs(eq4_printed(ai, alpha, true) / u - 1), 1e-9); // the printed form loses digits
}

TEST(MarkedPointParameters, ConicParameterFromBarycentricCoordinates) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(0.02, 0.98);
  // an ellipse-, a parabola- and a hyperbola-arc, and a complementary (w < 0) arc
  for (double w : {0.3, 1.0, 4.0, -0.4}) {
    const fair::Parametric_conic_arc_2 arc(-1, 0.5, 0.7, 2.0, 2.5, -0.3, w);
    for (int k = 0; k < 20; ++k) {
      const double u = d(rng);
      const fair::Curve_jet_2 j = arc.jet(u);
      EXPECT_NEAR(fair::conic_parameter(arc, j.x, j.y), u, 1e-13) << "w = " << w;
      EXPECT_NEAR(fair::nearest_parameter(arc, j.x, j.y, 0, 1), u, 1e-12) << "w = " << w;
    }
    EXPECT_EQ(fair::conic_parameter(arc, -1, 0.5), 0.0);
    EXPECT_EQ(fair::conic_parameter(arc, 2.5, -0.3), 1.0);
    EXPECT_THROW(fair::conic_parameter(arc, 0.7, 1.0), fair::Invalid_input_error); // off the conic
  }
  EXPECT_THROW(fair::conic_parameter(fair::Parametric_conic_arc_2(0, 0, 1, 1, 2, 2, 1.0), 1, 1), fair::Invalid_input_error);
  EXPECT_THROW(fair::conic_parameter(-0.5, 1.0, 0.5), fair::Precondition_error);
  EXPECT_THROW(fair::conic_parameter(0.0, 1.0, 0.0), fair::Precondition_error);
}

TEST(NearestParameter, FindsTheNearestTurnOfASpiralAndTheEnds) {
  const fair::Archimedean_spiral_2 f(0.0, 0.1, 0.0, 6 * pi); // three turns, 0.2 pi apart
  for (double t : {0.3, 2.0, 7.0, 12.5, 18.0}) {
    const fair::Curve_jet_2 j = f.jet(t);
    EXPECT_NEAR(fair::nearest_parameter(f, j.x, j.y, 0, 6 * pi), t, 1e-12);
  }
  // a point beyond the outer end: nearest is the end parameter (allow_off_curve)
  fair::Nearest_parameter_options o;
  o.allow_off_curve = true;
  const fair::Curve_jet_2 end = f.jet(6 * pi);
  EXPECT_EQ(fair::nearest_parameter(f, end.x + 1, end.y + 0.1, 0, 6 * pi, o), 6 * pi);
  // a point off the curve: least squares foot point, where (f - q) . f' = 0
  const double u = fair::nearest_parameter(f, 0.9, 0.35, 0, 6 * pi, o);
  const fair::Curve_jet_2 j = f.jet(u);
  EXPECT_NEAR(((j.x - 0.9) * j.dx + (j.y - 0.35) * j.dy) / std::hypot(j.dx, j.dy), 0.0, 1e-14);
}

TEST(NearestParameter, RoundTripsSeededParametersOnInvoluteAndClothoid) {
  std::mt19937 rng(31);
  const fair::Circle_involute_2 inv(0.5, 0.2, 9.0);
  const fair::Clothoid_2 clo(-1.0, 0.8, -3.0, 3.0, 1.5);
  std::uniform_real_distribution<double> a(0.2, 9.0), b(-3.0, 3.0);
  for (int k = 0; k < 30; ++k) {
    const double t = a(rng), s = b(rng);
    const fair::Curve_jet_2 p = inv.jet(t), q = clo.jet(s);
    EXPECT_NEAR(fair::nearest_parameter(inv, p.x, p.y, 0.2, 9.0), t, 1e-11) << t;
    EXPECT_NEAR(fair::nearest_parameter(clo, q.x, q.y, -3.0, 3.0), s, 1e-11) << s;
  }
}

TEST(NearestParameter, RejectsPointsOffTheCurveAndBadIntervals) {
  const fair::Parametric_circle_arc_2 arc(0, 0, 2, 0, pi);
  try {
    fair::nearest_parameter(arc, 0.0, 2.5, 0, pi);
    FAIL() << "an off-curve point was accepted";
  } catch (const fair::Invalid_input_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("(0, 2.5)"), std::string::npos) << m;
    EXPECT_NE(m.find("distance 0.5"), std::string::npos) << m;
  }
  EXPECT_NEAR(fair::nearest_parameter(arc, 0.0, 2.0 + 1e-12, 0, pi), pi / 2, 1e-12);
  EXPECT_THROW(fair::nearest_parameter(arc, 0.0, 2.0, 1, 0.5), fair::Precondition_error);
  EXPECT_THROW(fair::nearest_parameter(arc, 0.0, 2.0, -1, 0.5), fair::Precondition_error);
  EXPECT_THROW(fair::nearest_parameter(arc, NAN, 2.0, 0, 1), fair::Precondition_error);
  fair::Nearest_parameter_options o;
  o.samples = 1;
  EXPECT_THROW(fair::nearest_parameter(arc, 0.0, 2.0, 0, 1, o), fair::Precondition_error);
}

} // namespace
