// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Conic_type: the affine type of a non-degenerate conic section.

#ifndef FAIR_CONIC_TYPE_H
#define FAIR_CONIC_TYPE_H

#include <ostream>

namespace fair {

/// The affine type of a non-degenerate conic a x^2 + b xy + c y^2 + d x + e y + f = 0, decided
/// by the sign of the discriminant b^2 - 4ac (negative: ellipse, zero: parabola, positive:
/// hyperbola). For a rational quadratic Bezier piece in standard form with weight w > 0 and
/// non-collinear control points this is w < 1, w = 1, w > 1 respectively.
enum class Conic_type { ELLIPSE, PARABOLA, HYPERBOLA };

inline const char* to_string(Conic_type type) {
  switch (type) {
    case Conic_type::ELLIPSE: return "ellipse";
    case Conic_type::PARABOLA: return "parabola";
    case Conic_type::HYPERBOLA: return "hyperbola";
  }
  return "unknown";
}

inline std::ostream& operator<<(std::ostream& out, Conic_type type) { return out << to_string(type); }

} // namespace fair

#endif // FAIR_CONIC_TYPE_H
