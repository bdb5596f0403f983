// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// What fair-curves reports about one conic piece (fair::Rational_quadratic_bezier_2): its
// type, eccentricity, end curvatures and certified curvature extrema, as text, table rows,
// JSON and figure marks. Shared by the `conic` subcommand and the demo.

#ifndef FAIR_CURVES_CONIC_REPORT_H
#define FAIR_CURVES_CONIC_REPORT_H

#include "tool_common.h"

#include <fair/Rational_quadratic_bezier_2.h>

#include <CGAL/number_utils.h>

#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace fair_curves {

typedef fair::Rational_quadratic_bezier_2<Kernel> Conic_piece;

struct Conic_extremum_report {
  std::string kind;                 // maximum, minimum, stationary
  double t = 0;                     // within one ulp of the root
  std::string t_lower, t_upper;     // exact rational bounds of the isolating interval
  double t_lower_d = 0, t_upper_d = 0;
  double curvature = 0;             // signed curvature at t
};

struct Conic_report {
  std::string type;
  double weight = 0, eccentricity = 0;
  double curvature_source = 0, curvature_target = 0;  // eq. 5
  bool constant_curvature = false;
  std::vector<Conic_extremum_report> extrema;
};

inline std::string gmpq_text(const CGAL::Gmpq& q) {
  std::ostringstream out;
  out << q;
  return out.str();
}

template <class K>
Conic_report conic_report(const fair::Rational_quadratic_bezier_2<K>& piece) {
  Conic_report r;
  r.type = fair::to_string(piece.conic_type());
  r.weight = CGAL::to_double(piece.weight());
  r.eccentricity = piece.eccentricity();
  r.curvature_source = piece.curvature_at_source();
  r.curvature_target = piece.curvature_at_target();
  r.constant_curvature = piece.has_constant_curvature();
  for (const fair::Curvature_extremum& x : piece.curvature_extrema()) {
    Conic_extremum_report e;
    e.kind = fair::to_string(x.kind);
    e.t = x.t;
    e.t_lower = gmpq_text(x.t_lower);
    e.t_upper = gmpq_text(x.t_upper);
    e.t_lower_d = CGAL::to_double(x.t_lower);
    e.t_upper_d = CGAL::to_double(x.t_upper);
    e.curvature = piece.curvature(x.t);
    r.extrema.push_back(e);
  }
  return r;
}

/// Rows for a gallery table.
inline std::vector<std::pair<std::string, std::string>> conic_measurements(const Conic_report& r) {
  std::vector<std::pair<std::string, std::string>> rows = {
      {"conic type", r.type},
      {"weight w", format_number(r.weight, 10)},
      {"eccentricity", format_number(r.eccentricity, 10)},
      {"curvature at t = 0 (eq. 5)", format_number(r.curvature_source, 10)},
      {"curvature at t = 1 (eq. 5)", format_number(r.curvature_target, 10)}};
  if (r.constant_curvature) rows.emplace_back("curvature extrema", "none: circular arc, constant curvature");
  else if (r.extrema.empty()) rows.emplace_back("curvature extrema in (0,1)", "none (monotone curvature)");
  for (std::size_t i = 0; i < r.extrema.size(); ++i) {
    const Conic_extremum_report& e = r.extrema[i];
    const std::string k = "extremum " + std::to_string(i + 1) + ": ";
    rows.emplace_back(k + "kind", e.kind);
    rows.emplace_back(k + "t (certified interval)", "[" + format_number(e.t_lower_d, 17) + ", " +
                                                        format_number(e.t_upper_d, 17) + "]");
    rows.emplace_back(k + "curvature", format_number(e.curvature, 12));
  }
  return rows;
}

/// Figure marks at the extrema.
inline std::vector<Curve_mark> conic_marks(const Conic_report& r) {
  std::vector<Curve_mark> marks;
  for (const Conic_extremum_report& e : r.extrema)
    marks.push_back(Curve_mark{0, e.t, e.kind + " k=" + format_number(e.curvature, 4)});
  return marks;
}

inline nlohmann::json conic_json(const Conic_report& r) {
  nlohmann::json extrema = nlohmann::json::array();
  for (const Conic_extremum_report& e : r.extrema)
    extrema.push_back({{"kind", e.kind},
                       {"t", e.t},
                       {"t_interval_exact", {e.t_lower, e.t_upper}},
                       {"curvature", e.curvature}});
  return {{"type", r.type},
          {"eccentricity", r.eccentricity},
          {"curvature_at_source", r.curvature_source},
          {"curvature_at_target", r.curvature_target},
          {"constant_curvature", r.constant_curvature},
          {"curvature_extrema", extrema}};
}

template <class K>
std::string conic_text(const fair::Rational_quadratic_bezier_2<K>& piece, const Conic_report& r) {
  std::ostringstream out;
  out.precision(17);
  out << "conic piece:";
  for (std::size_t i = 0; i < 3; ++i)
    out << " P" << i << " = (" << CGAL::to_double(piece.control_point(i).x()) << ", "
        << CGAL::to_double(piece.control_point(i).y()) << "),";
  out << " w = " << r.weight << "\n";
  out << "type: " << r.type << "\n";
  out << "eccentricity: " << r.eccentricity << "\n";
  out << "curvature at t = 0: " << r.curvature_source << ", at t = 1: " << r.curvature_target << "\n";
  if (r.constant_curvature) out << "curvature extrema: none (circular arc, constant curvature)\n";
  else out << "certified curvature extrema in (0,1): " << r.extrema.size() << "\n";
  for (const Conic_extremum_report& e : r.extrema)
    out << "  " << e.kind << " at t = " << e.t << " (exact root in [" << e.t_lower << ", " << e.t_upper
        << "]), curvature " << e.curvature << "\n";
  return out.str();
}

} // namespace fair_curves

#endif // FAIR_CURVES_CONIC_REPORT_H
