// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The library's shape in one program: the closed-form Cardinal optimum of Li et al. computed
// exactly in EPECK, and a κ-curve solved in floating point, then certified piece by piece in
// exact arithmetic. Exits non-zero if a published value or a certificate does not hold.

#include <fair/Cardinal_spline_2.h>
#include <fair/Kappa_certificate.h>
#include <fair/Kappa_curve_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <iostream>
#include <vector>

int main() {
  typedef CGAL::Exact_predicates_exact_constructions_kernel K;
  typedef K::Point_2 Point_2;

  // Data set 1 of Li et al.: the optimal tension is the rational 9192/12241 (Table 1: 0.7509).
  const double px[] = {35, 16, 15, 25, 40, 65, 50, 60, 80}, py[] = {47, 40, 15, 36, 15, 25, 40, 42, 37};
  std::vector<Point_2> data;
  for (int i = 0; i < 9; ++i) data.emplace_back(px[i], py[i]);
  const fair::Cardinal_spline_2<K> cardinal(data);  // alpha* of eq. 18 and the optimal end points
  const fair::Cardinal_spline_report<K>& optimum = cardinal.report();
  std::cout << "Cardinal alpha* = " << optimum.alpha.exact() << " ~ " << CGAL::to_double(optimum.alpha) << '\n'
            << optimum << '\n';
  if (cardinal.status() != fair::Cardinal_spline_status::OPTIMAL || optimum.alpha != K::FT(9192) / K::FT(12241))
    return 1;

  // The published open polynomial κ-curve through four points, certified exactly.
  const std::vector<Point_2> q = {{-1, 0}, {0, 1}, {1, 0}, {2, 1}};
  const fair::Kappa_curve_2<K> curve(q);
  std::cout << curve.report() << '\n';
  const fair::Kappa_certificate certificate = fair::certify_pieces(curve);
  std::cout << certificate << '\n';
  if (!certificate.all_g1() || !certificate.all_unique_maxima()) return 1;
  std::cout << "interpolation error <= " << certificate.max_interpolation_error() << '\n';
  return certificate.max_interpolation_error() < 1e-12 ? 0 : 1;
}
