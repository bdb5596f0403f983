// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Curvature_extremum: a certified critical point of the curvature of a conic piece, as
// returned by Rational_quadratic_bezier_2::curvature_extrema() (eq. 4 of Yan, Schiller,
// Schaefer, "Circle reproduction with interpolatory curves at local maximal curvature points").

#ifndef FAIR_CURVATURE_EXTREMUM_H
#define FAIR_CURVATURE_EXTREMUM_H

#include <CGAL/Gmpq.h>

#include <ostream>

namespace fair {

/// How |kappa| behaves at a root of the eq.-4 polynomial.
enum class Curvature_extremum_kind {
  MAXIMUM,   ///< |kappa| increases before and decreases after (local maximum)
  MINIMUM,   ///< |kappa| decreases before and increases after (local minimum)
  STATIONARY ///< a root of even multiplicity: kappa' = 0 but no extremum
};

inline const char* to_string(Curvature_extremum_kind k) {
  switch (k) {
    case Curvature_extremum_kind::MAXIMUM: return "maximum";
    case Curvature_extremum_kind::MINIMUM: return "minimum";
    case Curvature_extremum_kind::STATIONARY: return "stationary";
  }
  return "unknown";
}
inline std::ostream& operator<<(std::ostream& out, Curvature_extremum_kind k) { return out << to_string(k); }

/// A certified critical point of the curvature in (0,1). The root is exactly t_lower when
/// t_lower == t_upper, otherwise it lies in the open interval (t_lower, t_upper).
struct Curvature_extremum {
  CGAL::Gmpq t_lower, t_upper;
  double t = 0.5;        ///< a double in [t_lower, t_upper], within a few ulps of the root
  int multiplicity = 1;  ///< exact multiplicity as a root of the eq.-4 polynomial
  Curvature_extremum_kind kind = Curvature_extremum_kind::MAXIMUM;
};

} // namespace fair

#endif // FAIR_CURVATURE_EXTREMUM_H
