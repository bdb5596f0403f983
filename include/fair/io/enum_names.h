// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The text spellings of the library's option and status enums, as files, JSON and command lines
// write them: one table per enum, from which both directions are derived (fair::io::spelling
// and fair::io::parse_spelling), so that what is written always reads back. Where the library
// already spells an enum (fair::to_string of Knot_spacing, Kappa_curve_status,
// Optimal_curve_status) the table takes that spelling, so there is still one.
//
//   Knot_spacing            uniform, centripetal, chordal
//   Kappa_weights           1, auto, fixed     (the --weights spellings of fair-curves kappa)
//   Kappa_curve_status      interior, on_joins, unsolved
//   Kappa_curve_unsolved_reason  none, beyond_density_limit, points_at_minima, no_convergence
//   Optimal_curve_solver    newton, cg
//   Curvature_discretisation regularised, circumcircle, turning_angle
//   Point_constraint_kind   tangent, normal, corner
//   Optimal_curve_status    converged, diverging, capped
//   Cardinal_spline_status  optimal, given_alpha, no_optimum

#ifndef FAIR_IO_ENUM_NAMES_H
#define FAIR_IO_ENUM_NAMES_H

#include <fair/Cardinal_spline_report.h>
#include <fair/Errors.h>
#include <fair/Kappa_curve_options.h>
#include <fair/Kappa_curve_report.h>
#include <fair/Knot_spacing.h>
#include <fair/Optimal_curve_options.h>
#include <fair/Optimal_curve_report.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace fair {
namespace io {

/// The spelling table of an enum: `table()` lists every value once with its spelling.
/// Specialised below for each enum of the library that is written or read as text.
template <class Enum>
struct Enum_spellings;

#define FAIR_IO_SPELLINGS(ENUM, ...)                                                       \
  template <>                                                                              \
  struct Enum_spellings<ENUM> {                                                            \
    static const std::vector<std::pair<ENUM, const char*>>& table() {                      \
      static const std::vector<std::pair<ENUM, const char*>> t = {__VA_ARGS__};           \
      return t;                                                                            \
    }                                                                                      \
  };

FAIR_IO_SPELLINGS(Knot_spacing, {Knot_spacing::UNIFORM, fair::to_string(Knot_spacing::UNIFORM)},
                  {Knot_spacing::CENTRIPETAL, fair::to_string(Knot_spacing::CENTRIPETAL)},
                  {Knot_spacing::CHORDAL, fair::to_string(Knot_spacing::CHORDAL)})
FAIR_IO_SPELLINGS(Kappa_weights, {Kappa_weights::UNIT, "1"}, {Kappa_weights::AUTOMATIC, "auto"},
                  {Kappa_weights::FIXED, "fixed"})
FAIR_IO_SPELLINGS(Kappa_curve_status, {Kappa_curve_status::INTERIOR, fair::to_string(Kappa_curve_status::INTERIOR)},
                  {Kappa_curve_status::ON_JOINS, fair::to_string(Kappa_curve_status::ON_JOINS)},
                  {Kappa_curve_status::UNSOLVED, fair::to_string(Kappa_curve_status::UNSOLVED)})
FAIR_IO_SPELLINGS(Kappa_curve_unsolved_reason,
                  {Kappa_curve_unsolved_reason::NONE, fair::to_string(Kappa_curve_unsolved_reason::NONE)},
                  {Kappa_curve_unsolved_reason::BEYOND_DENSITY_LIMIT,
                   fair::to_string(Kappa_curve_unsolved_reason::BEYOND_DENSITY_LIMIT)},
                  {Kappa_curve_unsolved_reason::POINTS_AT_MINIMA,
                   fair::to_string(Kappa_curve_unsolved_reason::POINTS_AT_MINIMA)},
                  {Kappa_curve_unsolved_reason::NO_CONVERGENCE,
                   fair::to_string(Kappa_curve_unsolved_reason::NO_CONVERGENCE)})
FAIR_IO_SPELLINGS(Optimal_curve_solver, {Optimal_curve_solver::NEWTON, "newton"},
                  {Optimal_curve_solver::CONJUGATE_GRADIENT, "cg"})
FAIR_IO_SPELLINGS(Curvature_discretisation, {Curvature_discretisation::REGULARISED, "regularised"},
                  {Curvature_discretisation::CIRCUMCIRCLE, "circumcircle"},
                  {Curvature_discretisation::TURNING_ANGLE, "turning_angle"})
FAIR_IO_SPELLINGS(Point_constraint_kind, {Point_constraint_kind::TANGENT, "tangent"},
                  {Point_constraint_kind::NORMAL, "normal"}, {Point_constraint_kind::CORNER, "corner"})
FAIR_IO_SPELLINGS(Optimal_curve_status,
                  {Optimal_curve_status::CONVERGED, fair::to_string(Optimal_curve_status::CONVERGED)},
                  {Optimal_curve_status::DIVERGING, fair::to_string(Optimal_curve_status::DIVERGING)},
                  {Optimal_curve_status::CAPPED, fair::to_string(Optimal_curve_status::CAPPED)})
FAIR_IO_SPELLINGS(Cardinal_spline_status,
                  {Cardinal_spline_status::OPTIMAL, fair::to_string(Cardinal_spline_status::OPTIMAL)},
                  {Cardinal_spline_status::GIVEN_ALPHA, fair::to_string(Cardinal_spline_status::GIVEN_ALPHA)},
                  {Cardinal_spline_status::NO_OPTIMUM, fair::to_string(Cardinal_spline_status::NO_OPTIMUM)})

/// The spelling of `value`. Throws Precondition_error for a value outside the table (a cast).
template <class Enum>
const char* spelling(Enum value) {
  for (const auto& e : Enum_spellings<Enum>::table())
    if (e.first == value) return e.second;
  throw Precondition_error(fair::internal::message("fair::io::spelling: no spelling for the enum value ",
                                                   static_cast<long long>(value)));
}

/// "a, b or c": every spelling of Enum, for messages.
template <class Enum>
std::string spellings_list() {
  const auto& t = Enum_spellings<Enum>::table();
  std::string out;
  for (std::size_t i = 0; i < t.size(); ++i)
    out += (i == 0 ? "" : (i + 1 == t.size() ? " or " : ", ")) + std::string(t[i].second);
  return out;
}

/// Whether `text` is a spelling of Enum; if so, `value` is set to its value.
template <class Enum>
bool try_parse_spelling(const std::string& text, Enum& value) {
  for (const auto& e : Enum_spellings<Enum>::table())
    if (text == e.second) {
      value = e.first;
      return true;
    }
  return false;
}

/// The value spelled `text` (exactly, case-sensitive). Throws Invalid_input_error "expected a, b
/// or c, got 'text'" otherwise; `what` (e.g. "knot spacing") starts the message when not empty.
template <class Enum>
Enum parse_spelling(const std::string& text, const std::string& what = std::string()) {
  Enum value{};
  if (try_parse_spelling(text, value)) return value;
  throw Invalid_input_error((what.empty() ? std::string() : what + ": ") + "expected " + spellings_list<Enum>() +
                            ", got '" + text + "'");
}

#undef FAIR_IO_SPELLINGS

} // namespace io
} // namespace fair

#endif // FAIR_IO_ENUM_NAMES_H
