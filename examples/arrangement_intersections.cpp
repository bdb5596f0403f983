// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Designed curves in a CGAL arrangement, exactly (fair/cgal/Arrangement_curves.h, doc/nurbs.md
// section 9): the intersections of a κ-curve and a cubic interpolating spline, and a
// self-intersection check of two outlines. Each curve's exchange form (nurbs()) becomes
// CGAL::Arr_Bezier_curve_traits_2 curves with exact rational control points; CGAL then decides
// every crossing and face with exact predicates. Exits non-zero if a count is not the expected one.

#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Kappa_curve_2.h>
#include <fair/cgal/Arrangement_curves.h>

#include <CGAL/Arr_Bezier_curve_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/CORE_algebraic_number_traits.h>
#include <CGAL/Cartesian.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstddef>
#include <iostream>
#include <iterator>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef CGAL::CORE_algebraic_number_traits Nt_traits;
typedef CGAL::Cartesian<Nt_traits::Rational> Rat_kernel;
typedef CGAL::Cartesian<Nt_traits::Algebraic> Alg_kernel;
typedef CGAL::Arr_Bezier_curve_traits_2<Rat_kernel, Alg_kernel, Nt_traits> Traits;
typedef CGAL::Arrangement_2<Traits> Arrangement;

// The vertices where two curves cross (degree 4), computed exactly and printed.
std::size_t print_crossings(const Arrangement& arr) {
  Traits::Bezier_cache cache;
  std::size_t crossings = 0;
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    if (v->degree() != 4) continue;
    ++crossings;
    v->point().make_exact(cache);  // an intersection point is an isolating box until asked
    std::cout.precision(17);
    std::cout << "  crossing (" << CGAL::to_double(v->point().x()) << ", " << CGAL::to_double(v->point().y())
              << ")\n";
  }
  return crossings;
}

// A closed outline through `points` (a closed cubic interpolating spline): its arrangement has
// 2 faces when it is simple; each self-crossing is a vertex of degree 4 and adds a face.
bool check_outline(const char* name, const std::vector<Point>& points, std::size_t expected_crossings) {
  fair::Cubic_interpolating_spline_options options;
  options.closed = true;
  const fair::Cubic_interpolating_spline_2<K> outline(points, options);
  std::vector<Traits::Curve_2> curves;
  fair::to_arrangement_curves<Traits>(outline.nurbs(), std::back_inserter(curves));
  Arrangement arr;
  CGAL::insert(arr, curves.begin(), curves.end());
  std::cout << name << ": " << curves.size() << " Bezier curves, " << arr.number_of_faces() << " faces\n";
  const std::size_t crossings = print_crossings(arr);
  std::cout << "  " << (crossings == 0 ? "simple" : "self-intersecting") << '\n';
  return crossings == expected_crossings && arr.number_of_faces() == 2 + expected_crossings;
}

int main() {
  try {
    // A κ-curve with unit weights has parabolic (polynomial) pieces, exact as Bezier curves.
    const fair::Kappa_curve_2<K> wave({{0, 0}, {2, 2}, {4, 0}, {6, 2}, {8, 0}});
    const fair::Cubic_interpolating_spline_2<K> line({{-1, 1}, {1.5, 1.3}, {3, 0.7}, {5, 1.2}, {7, 0.8}, {9, 1}});
    std::vector<Traits::Curve_2> curves;
    fair::to_arrangement_curves<Traits>(wave.nurbs(), std::back_inserter(curves));
    fair::to_arrangement_curves<Traits>(line.nurbs(), std::back_inserter(curves));
    Arrangement arr;
    CGAL::insert(arr, curves.begin(), curves.end());
    std::cout << "kappa-curve x cubic spline: " << arr.number_of_vertices() << " vertices, " << arr.number_of_edges()
              << " edges\n";
    const bool crossings_ok = print_crossings(arr) == 4;

    const bool simple_ok = check_outline("simple outline", {{4, 0}, {1, 3}, {-3, 2}, {-3, -2}, {1, -3}}, 0);
    const bool bow_tie_ok = check_outline("bow tie", {{4, 1}, {4, -1}, {-4, 1}, {-4, -1}}, 1);
    return crossings_ok && simple_ok && bow_tie_ok ? 0 : 1;
  } catch (const fair::Error& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
}
