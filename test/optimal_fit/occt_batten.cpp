// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// A peer, side by side (issue 11 §5): OCCT's FairCurve_Batten (constant section, free sliding:
// the free-length elastica, min int kappa^2 ds with clamped end tangents) against
// fair::Optimal_curve_2 with beta = 0, beta_0 = 1 and the same tangents (taken from OCCT's curve,
// so that no angle convention can differ). Compiled only when OCCT is found
// (test/optimal_fit/optional.cmake).
//
// What is measured: the Hausdorff distance between OCCT's curve (20000 parameter samples, a
// polyline within ~1e-9 of it) and the optimal polygon, both directions, point-to-segment.
// The bound: the optimal polygon at resolution rho has edges whose sagitta is below
// extent / rho (the subdivision criterion of Sec. 2.3.1) and vertices on the discrete minimiser,
// which is O(h^2) from the continuous one; OCCT's batten is a degree-9 B-spline whose energy is
// converged to its tolerance 1e-9. Hence H <= 2 extent / rho is a safe bound (the chord is 1).

#include "test_support.h"

#include <fair/Optimal_curve_2.h>
#include <fair/Polygon_spline_fit.h>

// OCCT after CGAL: OCCT defines a macro `Handle` that would break CGAL's headers.
#include <FairCurve_AnalysisCode.hxx>
#include <FairCurve_Batten.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec2d.hxx>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

typedef fair_test::SC_double K;

double segment_distance(double px, double py, double ax, double ay, double bx, double by) {
  const double ex = bx - ax, ey = by - ay, l = ex * ex + ey * ey;
  const double s = std::min(1.0, std::max(0.0, ((px - ax) * ex + (py - ay) * ey) / l));
  return std::hypot(px - ax - s * ex, py - ay - s * ey);
}

double polyline_distance(double x, double y, const std::vector<std::array<double, 2>>& line) {
  double d = HUGE_VAL;
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
    d = std::min(d, segment_distance(x, y, line[i][0], line[i][1], line[i + 1][0], line[i + 1][1]));
  return d;
}

TEST(Occt_batten, FreeLengthElasticaMatchesOptimalCurve) {
  const double rho = 1000;
  const double angles[][2] = {{0.5, 0.5}, {0.6, 0.2}};
  for (const auto& a : angles) {
    FairCurve_Batten batten(gp_Pnt2d(0, 0), gp_Pnt2d(1, 0), 0.01);
    batten.SetFreeSliding(Standard_True);
    batten.SetAngle1(a[0]);
    batten.SetAngle2(a[1]);
    FairCurve_AnalysisCode code;
    ASSERT_TRUE(batten.Compute(code, 200, 1e-9));
    ASSERT_EQ(code, FairCurve_OK);
    const Handle(Geom2d_BSplineCurve) c = batten.Curve();
    gp_Pnt2d p;
    gp_Vec2d t0, t1;
    c->D1(c->FirstParameter(), p, t0);
    c->D1(c->LastParameter(), p, t1);
    std::vector<std::array<double, 2>> occt;
    for (int k = 0; k <= 20000; ++k) {
      const gp_Pnt2d q = c->Value(c->FirstParameter() + (c->LastParameter() - c->FirstParameter()) * k / 20000.0);
      occt.push_back({{q.X(), q.Y()}});
    }

    fair::Optimal_curve_options o;
    o.lambda = -1;  // the raw weights of eq. 5
    o.length_weight = 0;
    o.curvature_weight = 1;
    o.resolution = rho;
    fair::Point_constraint c0, c1;
    c0.index = 0;
    c0.kind = fair::Point_constraint_kind::TANGENT;
    c0.direction = {{t0.X(), t0.Y()}};
    c1.index = 1;
    c1.kind = fair::Point_constraint_kind::TANGENT;
    c1.direction = {{t1.X(), t1.Y()}};
    o.constraints = {c0, c1};
    const fair::Optimal_curve_2<K> curve({K::Point_2(0, 0), K::Point_2(1, 0)}, o);
    ASSERT_EQ(curve.report().status, fair::Optimal_curve_status::CONVERGED) << "angles " << a[0] << ", " << a[1];
    std::vector<std::array<double, 2>> polygon;
    for (const K::Point_2& v : curve.polygon()) polygon.push_back({{v.x(), v.y()}});
    double h_occt = 0, h_polygon = 0;
    for (const auto& q : occt) h_occt = std::max(h_occt, polyline_distance(q[0], q[1], polygon));
    for (const auto& v : polygon) h_polygon = std::max(h_polygon, polyline_distance(v[0], v[1], occt));
    const double extent = 1; // the chord; the arch is lower than it is wide
    ::testing::Test::RecordProperty("hausdorff_" + std::to_string(static_cast<int>(100 * a[0])) + "_" +
                                        std::to_string(static_cast<int>(100 * a[1])),
                                    std::to_string(std::max(h_occt, h_polygon)) + " with " +
                                        std::to_string(polygon.size()) + " vertices");
    EXPECT_LE(std::max(h_occt, h_polygon), 2 * extent / rho)
        << "angles " << a[0] << ", " << a[1] << ": H(OCCT -> polygon) = " << h_occt
        << ", H(polygon -> OCCT) = " << h_polygon << ", " << polygon.size() << " vertices";
    // the spline through the polygon stays as close
    const fair::Polygon_spline_fit<K> fit = fair::fit_cubic_spline<K>(curve.polygon(), false);
    EXPECT_LE(fit.max_distance, extent / rho);
  }
}

} // namespace
