// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Interactive editing with κ-curves (Yan, Schiller, Schaefer): a closed curve with automatic
// (circle-reproducing) weights, a point dragged several times -- each re-solve starts from the
// previous solution and solves locally around the moved point -- and an open data set for which
// no κ-curve exists, whose offending point the report names (doc/kappa_existence.md).
// Exits non-zero if a re-solve does not converge, is not warm, or the report misses the point.

#include <fair/Kappa_curve_2.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <iostream>
#include <vector>

int main() {
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef K::Point_2 Point_2;

  // Twelve corners of a star, automatic weights (eq. 16).
  std::vector<Point_2> star;
  for (int i = 0; i < 12; ++i) {
    const double a = 2 * M_PI * i / 12, r = i % 2 ? 1.0 : 0.8;
    star.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  fair::Kappa_curve_options options;
  options.closed = true;
  options.weights = fair::Kappa_weights::AUTOMATIC;
  fair::Kappa_curve_2<K> curve(star, options);
  std::cout << "cold: " << curve.report() << '\n';
  if (curve.report().status != fair::Kappa_curve_status::INTERIOR) return 1;

  // Drag point 3 outwards in small steps, as a user would.
  for (int step = 1; step <= 5; ++step) {
    const double s = 1 + 0.02 * step;
    curve.move_point(3, Point_2(s * star[3].x(), s * star[3].y()));
    const fair::Kappa_curve_report& r = curve.report();
    std::cout << "drag " << step << ": warm " << r.warm_started << ", Jacobians " << r.iterations
              << ", residual " << r.residual << ", piece 3 weight " << curve.piece(3).weight() << '\n';
    if (r.status != fair::Kappa_curve_status::INTERIOR || !r.warm_started) return 1;
  }

  // Open data without an interior solution: the first interior point can only be interpolated on
  // a join (t = 1), where it is not a curvature maximum. The curve is still returned (it
  // interpolates, is G1 and has continuous |kappa|); the report says which point to move.
  const std::vector<Point_2> data = {{0.8420396853122557, 0.73342007152880162},
                                     {0.46358155033629755, 0.8249558033892006},
                                     {0.4147174195865368, 0.82380946371988828},
                                     {0.27611375678874384, 0.64727747335147212}};
  const fair::Kappa_curve_2<K> open(data);
  std::cout << "open: " << open.report().status << ", points on a join:";
  for (const std::size_t i : open.report().points_on_joins) std::cout << ' ' << i;
  std::cout << '\n';
  return open.report().status == fair::Kappa_curve_status::ON_JOINS &&
                 open.report().points_on_joins == std::vector<std::size_t>{1}
             ? 0
             : 1;
}
