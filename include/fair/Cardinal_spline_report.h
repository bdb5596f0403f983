// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// What the construction of a fair::Cardinal_spline_2 chose and reached (Cardinal_spline_report)
// and how its alpha was chosen (Cardinal_spline_status). Eq. numbers refer to J. Li, "Curvature
// variation minimizing Cardinal spline curves" (doc/cardinal_splines.md).

#ifndef FAIR_CARDINAL_SPLINE_REPORT_H
#define FAIR_CARDINAL_SPLINE_REPORT_H

#include <CGAL/number_utils.h>
#include <CGAL/Origin.h>

#include <ostream>

namespace fair {

/// OPTIMAL: alpha is Li's alpha* of eq. 18 (> 0); GIVEN_ALPHA: alpha was given (options or an
/// expert constructor); NO_OPTIMUM: eq. 18 has no positive optimum (alpha* <= 0, or its
/// denominator D = sum |d_i|^2 is 0) and the curve is the Catmull-Rom spline, alpha = 1/2 (a
/// failure: throw_on_failure turns it into a Solve_error). JSON spelling: "optimal",
/// "given_alpha", "no_optimum".
enum class Cardinal_spline_status { OPTIMAL, GIVEN_ALPHA, NO_OPTIMUM };

/// "optimal", "given_alpha" or "no_optimum".
inline const char* to_string(Cardinal_spline_status s) {
  switch (s) {
    case Cardinal_spline_status::OPTIMAL: return "optimal";
    case Cardinal_spline_status::GIVEN_ALPHA: return "given_alpha";
    case Cardinal_spline_status::NO_OPTIMUM: break;
  }
  return "no_optimum";
}
inline std::ostream& operator<<(std::ostream& out, Cardinal_spline_status s) { return out << to_string(s); }

/// The parameter used, the auxiliary points and the energy of eq. 10 there, in the kernel's FT
/// (exact in an exact kernel).
template <class K>
struct Cardinal_spline_report {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  Cardinal_spline_status status = Cardinal_spline_status::NO_OPTIMUM;
  /// The alpha used: alpha* (OPTIMAL), the given one (GIVEN_ALPHA) or 1/2 (NO_OPTIMUM).
  FT alpha = FT(1) / FT(2);
  /// p_{-1} and p_{n+1} of an open curve; closed: the first and the last point (not used).
  Point_2 aux_start = Point_2(CGAL::ORIGIN);
  Point_2 aux_end = Point_2(CGAL::ORIGIN);
  /// eq. 10 at alpha with these auxiliary points: sum over all segments of |r_i'''|^2 (eq. 9).
  FT energy = FT(0);

  friend bool operator==(const Cardinal_spline_report& a, const Cardinal_spline_report& b) {
    return a.status == b.status && a.alpha == b.alpha && a.aux_start == b.aux_start && a.aux_end == b.aux_end &&
           a.energy == b.energy;
  }
  friend bool operator!=(const Cardinal_spline_report& a, const Cardinal_spline_report& b) { return !(a == b); }

  /// One line, numbers in double: "Cardinal_spline_report{optimal, alpha 0.75, aux_start (46.6,
  /// 26.6), aux_end (83.3, 31.7), energy 1.9964e+05}".
  friend std::ostream& operator<<(std::ostream& out, const Cardinal_spline_report& r) {
    return out << "Cardinal_spline_report{" << r.status << ", alpha " << CGAL::to_double(r.alpha) << ", aux_start ("
               << CGAL::to_double(r.aux_start.x()) << ", " << CGAL::to_double(r.aux_start.y()) << "), aux_end ("
               << CGAL::to_double(r.aux_end.x()) << ", " << CGAL::to_double(r.aux_end.y()) << "), energy "
               << CGAL::to_double(r.energy) << "}";
  }
};

} // namespace fair

#endif // FAIR_CARDINAL_SPLINE_REPORT_H
