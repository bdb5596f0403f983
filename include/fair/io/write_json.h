// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Writing points, curves and the solvers' reports as JSON (nlohmann-json) and points as CSV.
// See doc/io.md. The one curve JSON of every method (curve_to_json with the method, the input
// points and the pieces): {"format": "fair-curve", "version": 1, "method", "closed", "points",
// "pieces": [{"degree", "control_points", "weights"?}, ...]} plus the method's members
// ("bspline": the NURBS of the curve, nurbs_to_json; "status" and "report" for the solver families).
//
// A coordinate is written as the JSON number of its nearest double (shortest text that reads
// back to the same double). In an exact kernel a coordinate that is not exactly a double is
// written as the string "p/q" of its exact value instead, which fair::io::read_points reads
// back exactly. Nothing non-finite is ever written: the writers throw
// fair::Precondition_error instead of emitting NaN, inf, or nlohmann's "null" for them.

#ifndef FAIR_IO_WRITE_JSON_H
#define FAIR_IO_WRITE_JSON_H

#include <fair/Cubic_spline_2.h>
#include <fair/Curve_traits.h>
#include <fair/Cardinal_spline_report.h>
#include <fair/Errors.h>
#include <fair/Kappa_curve_report.h>
#include <fair/Nurbs_curve_2.h>
#include <fair/Optimal_curve_report.h>
#include <fair/io/enum_names.h>
#include <fair/io/internal/nearest_double.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/number_utils.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace fair {
namespace io {
namespace internal {

template <class T, class = void>
struct Has_exact_member : std::false_type {};
template <class T>
struct Has_exact_member<T, std::void_t<decltype(std::declval<const T&>().exact())>> : std::true_type {};

/// A piece that states only its middle weight (a conic piece in standard form, weights (1, w, 1)).
template <class T, class = void>
struct Has_weight_member : std::false_type {};
template <class T>
struct Has_weight_member<T, std::void_t<decltype(std::declval<const T&>().weight())>> : std::true_type {};

/// The text "p/q" (or "p") of an exact number type whose stream output is a rational;
/// empty if the output is anything else.
template <class ET>
std::string rational_text(const ET& x) {
  std::ostringstream out;
  out << x;
  std::string s = out.str();
  std::size_t i = (!s.empty() && s[0] == '-') ? 1 : 0;
  bool slash = false, digits = false;
  for (; i < s.size(); ++i) {
    if (s[i] == '/' && !slash && digits) { slash = true; digits = false; continue; }
    if (s[i] < '0' || s[i] > '9') return std::string();
    digits = true;
  }
  if (!digits) return std::string();
  if (slash && s.size() > 2 && s.compare(s.size() - 2, 2, "/1") == 0) s.erase(s.size() - 2);
  return s;
}

} // namespace internal

/// The exact text of a number: "p/q" (or "p", lowest terms, sign on p) when FT is an exact
/// rational type (CGAL::Gmpq, Lazy_exact_nt<Gmpq> as in EPECK, ...); otherwise the value as a
/// decimal with 17 significant digits, which reads back as the same double. Throws
/// Precondition_error if the value is not finite; `what` names it in the message.
template <class FT>
std::string number_text(const FT& x, const std::string& what = "value") {
  const double d = CGAL::to_double(x);
  typedef typename CGAL::Algebraic_structure_traits<FT>::Is_exact Is_exact;
  if constexpr (Is_exact::value && !std::is_floating_point<FT>::value) {
    std::string text;
    if constexpr (internal::Has_exact_member<FT>::value) text = internal::rational_text(x.exact());
    else text = internal::rational_text(x);
    if (!text.empty()) return text;
  }
  if (!std::isfinite(d))
    throw Precondition_error(fair::internal::message("fair::io::number_text: the ", what, " is not finite: ", d));
  std::ostringstream out;
  out.precision(17);
  out << d;
  return out.str();
}

/// A coordinate as JSON: the nearest double, or "p/q" when FT is exact and the value is not
/// a double. Throws Precondition_error if the value is not finite; `what` names it.
template <class FT>
nlohmann::json number_to_json(const FT& x, const std::string& what = "value") {
  const double d = CGAL::to_double(x);
  if (!std::isfinite(d))
    throw Precondition_error(fair::internal::message("fair::io: refusing to write the non-finite ",
                                                     what, " ", d));
  typedef typename CGAL::Algebraic_structure_traits<FT>::Is_exact Is_exact;
  if constexpr (Is_exact::value && !std::is_floating_point<FT>::value) {
    if (!(FT(d) == x)) {
      std::string text;
      if constexpr (internal::Has_exact_member<FT>::value) text = internal::rational_text(x.exact());
      else text = internal::rational_text(x);
      if (!text.empty()) return text;
    }
  }
  return d;
}

/// A point as the JSON pair [x, y].
template <class Point_2>
nlohmann::json point_to_json(const Point_2& p, const std::string& what = "point") {
  return nlohmann::json::array({number_to_json(p.x(), what + " x"), number_to_json(p.y(), what + " y")});
}

/// {"points": [[x, y], ...], "closed": closed}: the format fair::io::read_points reads.
template <class Point_2>
nlohmann::json points_to_json(const std::vector<Point_2>& points, bool closed = false) {
  nlohmann::json pts = nlohmann::json::array();
  for (std::size_t i = 0; i < points.size(); ++i)
    pts.push_back(point_to_json(points[i], fair::internal::message("point ", i)));
  return nlohmann::json{{"points", std::move(pts)}, {"closed", closed}};
}

/// One piece: {"degree": n, "control_points": [[x, y], ...]} and, for a rational piece (a
/// piece with weights() returning a range, or weight() returning the middle weight of a
/// rational quadratic in standard form), "weights": [w_0, ..., w_n].
template <class Piece>
nlohmann::json piece_to_json(const Piece& piece, std::size_t index = 0) {
  nlohmann::json out;
  const auto cps = piece.control_points();
  nlohmann::json cp = nlohmann::json::array();
  std::size_t k = 0;
  for (const auto& p : cps)
    cp.push_back(point_to_json(p, fair::internal::message("piece ", index, " control point ", k++)));
  out["degree"] = cp.empty() ? 0 : cp.size() - 1;
  out["control_points"] = std::move(cp);
  if constexpr (Piece_traits<Piece>::kind == Piece_kind::RATIONAL_BEZIER) {
    nlohmann::json w = nlohmann::json::array();
    for (const auto& wi : piece.weights())
      w.push_back(number_to_json(wi, fair::internal::message("piece ", index, " weight")));
    out["weights"] = std::move(w);
  } else if constexpr (internal::Has_weight_member<Piece>::value) {
    out["weights"] = nlohmann::json::array(
        {1, number_to_json(piece.weight(), fair::internal::message("piece ", index, " weight")), 1});
  }
  return out;
}

/// A curve: {"format": "fair-curve", "version": 1, "pieces": [...]} plus the members of
/// `extra` (method-specific fields such as the input points or the method's parameters).
/// Throws Precondition_error if `extra` is not an object, redefines one of the members above,
/// or holds a non-finite number.
template <class PieceRange>
nlohmann::json curve_to_json(const PieceRange& pieces,
                             const nlohmann::json& extra = nlohmann::json::object()) {
  nlohmann::json out{{"format", "fair-curve"}, {"version", 1}};
  nlohmann::json ps = nlohmann::json::array();
  std::size_t i = 0;
  for (const auto& piece : pieces) ps.push_back(piece_to_json(piece, i++));
  out["pieces"] = std::move(ps);
  fair::internal::require(extra.is_object(), "fair::io::curve_to_json: extra must be a JSON object, got ",
                          extra.type_name());
  for (auto it = extra.begin(); it != extra.end(); ++it) {
    fair::internal::require(!out.contains(it.key()), "fair::io::curve_to_json: extra member \"",
                            it.key(), "\" would overwrite a member of the curve");
    out[it.key()] = it.value();
  }
  return out;
}

/// The one curve JSON of every method: curve_to_json(pieces, extra) preceded by "method",
/// "closed" and the input "points" ([[x, y], ...]). `piece_extra`, when not empty, holds one JSON
/// object per piece whose members are written beside the piece's own (the kappa-curve's "point"
/// and "t"). Throws Precondition_error if `piece_extra` has another size, redefines a member of a
/// piece, or `extra` redefines a member of the curve.
template <class Point_2, class PieceRange>
nlohmann::json curve_to_json(const std::string& method, bool closed, const std::vector<Point_2>& points,
                             const PieceRange& pieces, const nlohmann::json& extra = nlohmann::json::object(),
                             const std::vector<nlohmann::json>& piece_extra = {}) {
  fair::internal::require(extra.is_object(), "fair::io::curve_to_json: extra must be a JSON object, got ",
                          extra.type_name());
  nlohmann::json head{{"method", method}, {"closed", closed}};
  nlohmann::json pts = nlohmann::json::array();
  for (std::size_t i = 0; i < points.size(); ++i)
    pts.push_back(point_to_json(points[i], fair::internal::message("point ", i)));
  head["points"] = std::move(pts);
  for (auto it = extra.begin(); it != extra.end(); ++it) {
    fair::internal::require(!head.contains(it.key()), "fair::io::curve_to_json: extra member \"", it.key(),
                            "\" would overwrite a member of the curve");
    head[it.key()] = it.value();
  }
  nlohmann::json out = curve_to_json(pieces, head);
  if (!piece_extra.empty()) {
    nlohmann::json& ps = out["pieces"];
    fair::internal::require(piece_extra.size() == ps.size(), "fair::io::curve_to_json: ", piece_extra.size(),
                            " piece extras for ", ps.size(), " pieces");
    for (std::size_t i = 0; i < ps.size(); ++i)
      for (auto it = piece_extra[i].begin(); it != piece_extra[i].end(); ++it) {
        fair::internal::require(!ps[i].contains(it.key()), "fair::io::curve_to_json: piece extra member \"", it.key(),
                                "\" would overwrite a member of piece ", i);
        ps[i][it.key()] = it.value();
      }
  }
  return out;
}

/// A kappa-curve's solve report: {"status": "interior" | "on_joins" | "unsolved", "reason":
/// "none" | "beyond_density_limit" | "points_at_minima" | "no_convergence", the counts,
/// "residuals" (the dimensionless residuals of the report), "energy" (its terms and total),
/// "weight_blend" (automatic weights: 1 when eq. 16 holds, s < 1 for weights 1 + s (w~ - 1) blended
/// towards 1, doc/kappa_curves.md), and the point lists (0-based input indices)}.
inline nlohmann::json to_json(const Kappa_curve_report& r) {
  nlohmann::json worst = nlohmann::json::array();
  for (const Kappa_point_residual& p : r.worst_points) worst.push_back({{"point", p.point}, {"residual", p.residual}});
  return nlohmann::json{{"status", spelling(r.status)},
                        {"reason", spelling(r.reason)},
                        {"warm_started", r.warm_started},
                        {"refinement_passes", r.refinement_passes},
                        {"iterations", r.iterations},
                        {"residuals",
                         {{"max", r.residual},
                          {"interpolation", r.interpolation_residual},
                          {"max_curvature_eq7", r.curvature_residual},
                          {"abs_curvature_continuity", r.g2_residual},
                          {"weight_eq16", r.weight_residual}}},
                        {"energy",
                         {{"total", r.energy()},
                          {"interpolation", r.energy_interpolation},
                          {"curvature_eq12", r.energy_curvature},
                          {"g2_eq11", r.energy_g2},
                          {"weight_eq13", r.energy_weight}}},
                        {"weight_blend", r.weight_blend},
                        {"bounds_active", r.bounds_active},
                        {"points_on_joins", r.points_on_joins},
                        {"points_at_minima", r.points_at_minima},
                        {"worst_points", std::move(worst)},
                        {"points_beyond_density_limit", r.points_beyond_density_limit}};
}

/// An optimal curve's solve report: {"status": "converged" | "diverging" | "capped", "energy",
/// "iterations", "gradient_norm", "levels": [{"vertices", "iterations", "energy",
/// "gradient_norm", "status"}, ...]} (one level per polygon of the hierarchy, coarse to fine),
/// "extent_ratio", "self_intersections", "input_self_intersections" (issue 25 §2).
inline nlohmann::json to_json(const Optimal_curve_report& r) {
  nlohmann::json levels = nlohmann::json::array();
  for (const Optimal_curve_level& l : r.levels)
    levels.push_back({{"vertices", l.vertices}, {"iterations", l.iterations}, {"energy", l.energy},
                      {"gradient_norm", l.gradient_norm}, {"status", spelling(l.status)}});
  return nlohmann::json{{"status", spelling(r.status)},
                        {"energy", r.energy},
                        {"iterations", r.iterations},
                        {"gradient_norm", r.gradient_norm},
                        {"levels", std::move(levels)},
                        {"extent_ratio", r.extent_ratio},
                        {"self_intersections", r.self_intersections},
                        {"input_self_intersections", r.input_self_intersections}};
}

/// A Cardinal spline's report: {"status": "optimal" | "given_alpha" | "no_optimum", "alpha" (the
/// alpha used), "aux_start", "aux_end" ([x, y]: the auxiliary points of an open curve; of a closed
/// one its first and last point, as the report holds them), "energy" (eq. 10 at alpha)}. In an
/// exact kernel the numbers that are not doubles are "p/q" strings (alpha* of data set 1 of [Li]:
/// "9192/12241").
template <class K>
nlohmann::json to_json(const Cardinal_spline_report<K>& r) {
  return nlohmann::json{{"status", spelling(r.status)},
                        {"alpha", number_to_json(r.alpha, "alpha")},
                        {"aux_start", point_to_json(r.aux_start, "aux_start")},
                        {"aux_end", point_to_json(r.aux_end, "aux_end")},
                        {"energy", number_to_json(r.energy, "energy")}};
}

/// The "bspline" member of the curve format, the one writer of every family's NURBS
/// (Nurbs_curve_2, fair/Nurbs_curve_2.h; every family's nurbs()):
///   {"degree": p, "closed": c, "knots": [u_0, ..., u_{n+p}] (the full vector, multiplicities
///    written out), "control_points": [[x, y], ... n ...], "weights": [w_0, ..., w_{n-1}]}
/// with "weights" only when the curve is rational (is_rational()). Open curves are clamped, a
/// closed one is in the periodic form (the last p control points repeat the first p), so
/// #knots = #control points + p + 1 either way. Exact kernels write "p/q" strings for values that
/// are not doubles. fair::io::read_nurbs (fair/io/read_nurbs.h) reads it back, exactly.
template <class K>
nlohmann::json nurbs_to_json(const Nurbs_curve_2<K>& curve) {
  nlohmann::json knots = nlohmann::json::array(), control = nlohmann::json::array();
  for (std::size_t k = 0; k < curve.knots().size(); ++k)
    knots.push_back(number_to_json(curve.knots()[k], fair::internal::message("knot ", k)));
  const auto& points = curve.control_points();
  for (std::size_t k = 0; k < points.size(); ++k)
    control.push_back(point_to_json(points[k], fair::internal::message("bspline control point ", k)));
  nlohmann::json out{{"degree", curve.degree()},
                     {"closed", curve.is_closed()},
                     {"knots", std::move(knots)},
                     {"control_points", std::move(control)}};
  if (curve.is_rational()) {
    nlohmann::json weights = nlohmann::json::array();
    for (std::size_t k = 0; k < curve.weights().size(); ++k)
      weights.push_back(number_to_json(curve.weights()[k], fair::internal::message("bspline weight ", k)));
    out["weights"] = std::move(weights);
  }
  return out;
}

/// The curve format (curve_to_json) of the spline's pieces plus its "bspline" member
/// (nurbs_to_json of spline.nurbs()) and the members of `extra`.
template <class K>
nlohmann::json spline_curve_to_json(const Cubic_spline_2<K>& spline,
                                    const nlohmann::json& extra = nlohmann::json::object()) {
  nlohmann::json out = curve_to_json(spline.pieces(), extra);
  fair::internal::require(!out.contains("bspline"), "fair::io::spline_curve_to_json: extra member \"bspline\" would ",
                          "overwrite the spline");
  out["bspline"] = nurbs_to_json(spline.nurbs());
  return out;
}

namespace internal {

template <class C, class = void>
struct Has_report : std::false_type {};
template <class C>
struct Has_report<C, std::void_t<decltype(std::declval<const C&>().report())>> : std::true_type {};
/// A curve with the exchange form (every family of the library: nurbs()).
template <class C, class = void>
struct Has_nurbs : std::false_type {};
template <class C>
struct Has_nurbs<C, std::void_t<decltype(std::declval<const C&>().nurbs())>> : std::true_type {};

} // namespace internal

/// The curve JSON of a curve of any family (doc/concepts.md): curve_to_json(method,
/// curve.is_closed(), curve.points(), curve.pieces(), extra, piece_extra) plus "bspline"
/// (nurbs_to_json(curve.nurbs()), for every family that has nurbs() and pieces) and, for the
/// solver families, "status" and "report" (to_json(curve.report())). The one writer of every
/// family's pieces and B-spline, so that the program cannot disagree with itself.
template <class Curve>
nlohmann::json family_to_json(const Curve& curve, const std::string& method,
                              const nlohmann::json& extra = nlohmann::json::object(),
                              const std::vector<nlohmann::json>& piece_extra = {}) {
  fair::internal::require(extra.is_object(), "fair::io::family_to_json: extra must be a JSON object, got ",
                          extra.type_name());
  nlohmann::json members = nlohmann::json::object();
  if constexpr (internal::Has_report<Curve>::value) {
    members["status"] = spelling(curve.report().status);
    members["report"] = to_json(curve.report());
  }
  // (a failed optimal solve may leave a curve without pieces, and so without a NURBS)
  if constexpr (internal::Has_nurbs<Curve>::value)
    if (!curve.pieces().empty()) members["bspline"] = nurbs_to_json(curve.nurbs());
  for (auto it = extra.begin(); it != extra.end(); ++it) {
    fair::internal::require(!members.contains(it.key()), "fair::io::family_to_json: extra member \"", it.key(),
                            "\" would overwrite a member of the curve");
    members[it.key()] = it.value();
  }
  return curve_to_json(method, curve.is_closed(), curve.points(), curve.pieces(), members, piece_extra);
}

/// The members of an optimal curve's JSON beside its pieces (for family_to_json's `extra`):
/// "polygon", "interpolation_indices", "curvatures", "fit_max_distance" (fair::Optimal_curve_2),
/// and "quintic" {"pieces", "max_distance"} when the C4 quintic fit is given
/// (fair::Polygon_quintic_fit, the curves with a derivative term). One writer for the program and
/// the Python module.
template <class Optimal_curve, class Quintic_fit>
nlohmann::json optimal_curve_members(const Optimal_curve& curve, const Quintic_fit* quintic) {
  nlohmann::json polygon = nlohmann::json::array();
  for (const auto& p : curve.polygon()) polygon.push_back(point_to_json(p, "polygon vertex"));
  nlohmann::json extra{{"polygon", std::move(polygon)},
                       {"interpolation_indices", curve.interpolation_indices()},
                       {"curvatures", curve.curvatures()},
                       {"fit_max_distance", curve.spline().max_distance}};
  if (quintic) {
    nlohmann::json pieces = nlohmann::json::array();
    for (std::size_t i = 0; i < quintic->pieces.size(); ++i) pieces.push_back(piece_to_json(quintic->pieces[i], i));
    extra["quintic"] = {{"pieces", std::move(pieces)}, {"max_distance", quintic->max_distance}};
  }
  return extra;
}

/// Throws Precondition_error if `j` holds a non-finite number anywhere (`path` names it).
inline void check_json_finite(const nlohmann::json& j, const std::string& path = "$") {
  if (j.is_number_float() && !std::isfinite(j.get<double>()))
    throw Precondition_error("fair::io: refusing to write the non-finite number at " + path);
  if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i)
      check_json_finite(j[i], path + "[" + std::to_string(i) + "]");
  if (j.is_object())
    for (auto it = j.begin(); it != j.end(); ++it) check_json_finite(it.value(), path + "." + it.key());
}

/// Writes `j` (indented) to `out`, after check_json_finite.
inline void write_json(std::ostream& out, const nlohmann::json& j) {
  check_json_finite(j);
  out << j.dump(2) << '\n';
}

/// Writes `j` to `file`; throws fair::Error if the file cannot be written.
inline void write_json_file(const std::string& file, const nlohmann::json& j) {
  check_json_finite(j);
  std::ofstream out(file);
  if (!out) throw Error("fair::io: cannot open " + file + " for writing");
  out << j.dump(2) << '\n';
  out.close();
  if (!out) throw Error("fair::io: error while writing " + file);
}

/// Writes points as CSV, one "x,y" line each: the nearest doubles with 17 significant digits (read
/// back to the same doubles), after the header line "x,y". Throws Precondition_error on a non-finite value.
template <class Point_2>
void write_points_csv(std::ostream& out, const std::vector<Point_2>& points) {
  std::ostringstream text;
  text << std::setprecision(std::numeric_limits<double>::max_digits10);
  text << "x,y\n";
  for (std::size_t i = 0; i < points.size(); ++i) {
    // The nearest doubles: CGAL::to_double is not that in the exact kernels (io/internal/nearest_double.h).
    const double x = internal::nearest_double_of(points[i].x()), y = internal::nearest_double_of(points[i].y());
    if (!std::isfinite(x) || !std::isfinite(y))
      throw Precondition_error(fair::internal::message("fair::io::write_points_csv: point ", i, " = (", x,
                                                       ", ", y, ") is not finite"));
    text << x << ',' << y << '\n';
  }
  out << text.str();
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_WRITE_JSON_H
