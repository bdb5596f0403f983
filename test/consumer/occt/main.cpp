// A consumer of the installed package's occt component (test/consumer/run_consumer_test.cmake):
// a closed cubic spline converted to OCCT's periodic Geom2d_BSplineCurve, evaluated by OCCT at
// the spline's knots (where it must pass through the interpolated points), and back.
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/occt/Geom2d_conversion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <iostream>
#include <vector>

int main() {
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  try {
    const std::vector<K::Point_2> q = {{0, 0}, {2, -1}, {4, 0.5}, {3, 3}, {0, 2}};
    fair::Cubic_interpolating_spline_options options;
    options.closed = true;
    const fair::Cubic_interpolating_spline_2<K> spline(q, options);
    const fair::Nurbs_curve_2<K> nurbs = spline.spline().nurbs();
    const Handle(Geom2d_BSplineCurve) g = fair::occt::to_geom2d_bspline(nurbs);
    if (!g->IsPeriodic() || g->NbPoles() != static_cast<int>(q.size())) {
      std::cerr << "unexpected OCCT curve: periodic " << g->IsPeriodic() << ", " << g->NbPoles() << " poles\n";
      return 1;
    }
    const std::vector<double> t = nurbs.breakpoints();
    for (std::size_t i = 0; i < q.size(); ++i) {
      const gp_Pnt2d p = g->Value(t[i]);
      if (std::hypot(p.X() - q[i].x(), p.Y() - q[i].y()) > 1e-12) {
        std::cerr << "OCCT's curve misses point " << i << '\n';
        return 1;
      }
    }
    const fair::Nurbs_curve_2<K> back = fair::occt::from_geom2d_bspline<K>(g);
    if (back.control_points() != nurbs.control_points() || back.knots() != nurbs.knots()) {
      std::cerr << "the round trip changed the curve\n";
      return 1;
    }
  } catch (const fair::Error& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
  std::cout << "fair occt consumer ok\n";
  return 0;
}
