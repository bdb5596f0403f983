// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair::Knot_spacing: how the classic interpolants (Cubic_interpolating_spline_2, Catmull_rom_2)
// space the parameter values of their interpolation points.

#ifndef FAIR_KNOT_SPACING_H
#define FAIR_KNOT_SPACING_H

namespace fair {

/// How the parameter values (knots) u_0 < u_1 < ... of interpolation points are spaced.
/// With h_i = u_{i+1} - u_i:
///  - uniform:     h_i = 1 (rational: every construction stays exact in an exact kernel);
///  - centripetal: h_i = |p_{i+1} - p_i|^(1/2);
///  - chordal:     h_i = |p_{i+1} - p_i|.
/// The two non-uniform spacings need square roots: h_i is computed in double (std::hypot, then
/// std::sqrt) and converted exactly to FT. Everything after that is carried out in FT, so in an
/// exact kernel the curve interpolates exactly and is exactly C1/C2 *for those rounded knots*;
/// only the knots themselves carry a relative error of about 1e-16.
enum class Knot_spacing { UNIFORM, CENTRIPETAL, CHORDAL };

inline const char* to_string(Knot_spacing s) {
  switch (s) {
    case Knot_spacing::UNIFORM: return "uniform";
    case Knot_spacing::CENTRIPETAL: return "centripetal";
    case Knot_spacing::CHORDAL: return "chordal";
  }
  return "?";
}

} // namespace fair

#endif // FAIR_KNOT_SPACING_H
