// A tiny consumer of the installed package: find_package(fair) + fair::fair must bring CGAL,
// GMP/MPFR (EPECK) with it, and fair::io nlohmann-json (the JSON writer). all_public_headers.cpp
// (generated) includes every other public header.
#include <fair/Kappa_curve_2.h>
#include <fair/Rational_quadratic_bezier_2.h>
#include <fair/io/write_json.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <iostream>
#include <vector>

int main() {
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
  try {
    // The published open polynomial kappa-curve of Yan et al.: middle control points
    // (-0.08187, 1.71183) and (1.08187, -0.711831).
    const std::vector<K::Point_2> q = {{-1, 0}, {0, 1}, {1, 0}, {2, 1}};
    const fair::Kappa_curve_2<K> curve(q);
    const K::Point_2 p = curve.pieces().front().control_points()[1];
    if (std::abs(p.x() + 0.08187) > 1e-4 || std::abs(p.y() - 1.71183) > 1e-4) {
      std::cerr << "unexpected control point " << p << '\n';
      return 1;
    }
    // The curve as JSON (fair::io).
    const nlohmann::json json = fair::io::curve_to_json(curve.pieces());
    if (json.at("format") != "fair-curve" || json.at("pieces").size() != curve.number_of_pieces()) {
      std::cerr << "unexpected curve JSON " << json.dump() << '\n';
      return 1;
    }
    // An exact conic piece: w = 1 is a parabola, decided exactly.
    const fair::Rational_quadratic_bezier_2<EK> parabola({0, 0}, {1, 2}, {2, 0}, 1);
    if (parabola.conic_type() != fair::Conic_type::PARABOLA) {
      std::cerr << "unexpected conic type\n";
      return 1;
    }
  } catch (const fair::Error& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
  std::cout << "fair consumer ok\n";
  return 0;
}
