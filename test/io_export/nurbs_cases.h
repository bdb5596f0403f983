// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The curves the export tests write (DXF, SVG path): every family of the library, open and
// closed, polynomial and rational (kappa-curves with weights != 1), plus NURBS of degree 1 and 5
// and a rational cubic, each as its fair::Nurbs_curve_2 exchange form (nurbs()).

#ifndef FAIR_TEST_IO_EXPORT_NURBS_CASES_H
#define FAIR_TEST_IO_EXPORT_NURBS_CASES_H

#include <fair/Cardinal_spline_2.h>
#include <fair/Catmull_rom_2.h>
#include <fair/Csr_spline_2.h>
#include <fair/Cubic_bspline_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Cubic_quasi_interpolant_2.h>
#include <fair/Cubic_spline_2.h>
#include <fair/Four_point_subdivision_2.h>
#include <fair/Kappa_curve_2.h>
#include <fair/Nurbs_curve_2.h>
#include <fair/Optimal_curve_2.h>

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace fair_test {

template <class C, class = void>
struct Has_nurbs : std::false_type {};
template <class C>
struct Has_nurbs<C, std::void_t<decltype(std::declval<const C&>().nurbs())>> : std::true_type {};

/// The curve's exchange form: every family has nurbs() (issue 26).
template <class K, class Curve>
fair::Nurbs_curve_2<K> nurbs_of(const Curve& c) {
  static_assert(Has_nurbs<Curve>::value, "every family has nurbs()");
  return c.nurbs();
}

template <class K>
struct Nurbs_case {
  std::string name;
  fair::Nurbs_curve_2<K> curve;
};

/// The open test polygon: a wave with a sharp turn (7 points).
template <class K>
std::vector<typename K::Point_2> open_points() {
  typedef typename K::Point_2 P;
  return {P(0, 0), P(1, 1.5), P(2.5, 1.75), P(4, 0.5), P(5, -1), P(6.5, 0.25), P(7, 2)};
}

/// The closed test polygon: a non-convex hexagon.
template <class K>
std::vector<typename K::Point_2> closed_points() {
  typedef typename K::Point_2 P;
  return {P(0, 0), P(3, -0.5), P(5, 1), P(4, 3.5), P(2, 2.25), P(-0.5, 3)};
}

template <class K>
void add_family_cases(std::vector<Nurbs_case<K>>& cases, bool closed) {
  const std::vector<typename K::Point_2> points = closed ? closed_points<K>() : open_points<K>();
  const std::string suffix = closed ? "_closed" : "_open";
  {
    fair::Kappa_curve_options o;
    o.closed = closed;
    cases.push_back({"kappa_unit" + suffix, nurbs_of<K>(fair::Kappa_curve_2<K>(points, o))});
    o.weights = fair::Kappa_weights::AUTOMATIC;
    cases.push_back({"kappa_auto" + suffix, nurbs_of<K>(fair::Kappa_curve_2<K>(points, o))});
  }
  {
    fair::Cardinal_spline_options o;
    o.closed = closed;
    cases.push_back({"cardinal" + suffix, nurbs_of<K>(fair::Cardinal_spline_2<K>(points, o))});
  }
  {
    fair::Catmull_rom_options o;
    o.closed = closed;
    o.knot_spacing = fair::Knot_spacing::CENTRIPETAL;
    cases.push_back({"catmull_rom" + suffix, nurbs_of<K>(fair::Catmull_rom_2<K>(points, o))});
  }
  {
    fair::Cubic_interpolating_spline_options o;
    o.closed = closed;
    cases.push_back({"cubic" + suffix, nurbs_of<K>(fair::Cubic_interpolating_spline_2<K>(points, o))});
  }
  {
    fair::Cubic_bspline_options o;
    o.closed = closed;
    cases.push_back({"bspline" + suffix, nurbs_of<K>(fair::Cubic_bspline_2<K>(points, o))});
  }
  {
    fair::Cubic_quasi_interpolant_options o;
    o.closed = closed;
    cases.push_back({"quasi" + suffix, nurbs_of<K>(fair::Cubic_quasi_interpolant_2<K>(points, o))});
  }
  {
    fair::Csr_spline_options o;
    o.closed = closed;
    cases.push_back({"csr" + suffix, nurbs_of<K>(fair::Csr_spline_2<K>(points, o))});
  }
  {
    fair::Optimal_curve_options o;
    o.closed = closed;
    cases.push_back({"optimal" + suffix, nurbs_of<K>(fair::Optimal_curve_2<K>(points, o))});
  }
}

/// NURBS not made by a family: degree 1 and 5, a rational cubic (open and closed).
template <class K>
void add_direct_cases(std::vector<Nurbs_case<K>>& cases) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  cases.push_back({"polyline_degree_1", fair::Nurbs_curve_2<K>(1, {0, 0, 1, 3, 4, 4}, {P(0, 0), P(1, 2), P(3, 1), P(4, 3)})});
  cases.push_back({"quintic_open", fair::Nurbs_curve_2<K>(5, {0, 0, 0, 0, 0, 0, FT(1) / 3, 1, 1, 1, 1, 1, 1},
                                                           {P(0, 0), P(1, 3), P(2, -1), P(3, 4), P(4, 0), P(5, 2), P(6, 1)})});
  const std::vector<FT> w{1, FT(3), FT(1) / 2, 2, FT(5) / 4, 1};
  cases.push_back({"rational_cubic_open", fair::Nurbs_curve_2<K>(3, {0, 0, 0, 0, 1, FT(5) / 2, 4, 4, 4, 4},
                                                                  {P(0, 0), P(1, 2), P(3, 3), P(4, 0), P(6, 1), P(7, 3)}, w)});
  // closed rational cubic, periodic form: 4 unique points, the first 3 repeated, knot period 4
  const std::vector<P> q{P(0, 0), P(4, 0), P(4, 3), P(0, 3)};
  const std::vector<FT> qw{1, 3, FT(1) / 2, 2};
  cases.push_back({"rational_cubic_closed",
                   fair::Nurbs_curve_2<K>(3, {-3, -2, -1, 0, 1, 2, 3, 4, 5, 6, 7},
                                          {q[0], q[1], q[2], q[3], q[0], q[1], q[2]},
                                          {qw[0], qw[1], qw[2], qw[3], qw[0], qw[1], qw[2]}, true)});
}

/// Every case.
template <class K>
std::vector<Nurbs_case<K>> nurbs_cases() {
  std::vector<Nurbs_case<K>> cases;
  add_family_cases(cases, false);
  add_family_cases(cases, true);
  add_direct_cases(cases);
  return cases;
}

} // namespace fair_test

#endif // FAIR_TEST_IO_EXPORT_NURBS_CASES_H
