// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair._fair: the Python binding of the library (issue 28; doc/python.md). One translation unit
// (compile cost: doc/python.md, "Build"). Every family is solved in CGAL::Simple_cartesian<double>,
// the kernel of fair-curves, and reported by the library's own writers (fair/io/write_json.h:
// family_to_json; fair/io/write_dxf.h), with the same extra members as the program's commands
// (tools/fair-curves/*_command.cpp), so that curve.to_json() equals `fair-curves ... -o` for the
// same input. The certificate is the library's exact one (fair/io/certify_curve.h, exact
// rationals). The Python layer (python/fair/__init__.py) adds the curve object, pickling and
// sampling; this file only converts, solves (without the GIL) and reports.

#include <fair/Basic_shape_design.h>
#include <fair/io/write_design_json.h>
#include <fair/Catmull_rom_2.h>
#include <fair/Cardinal_spline_2.h>
#include <fair/Csr_spline_2.h>
#include <fair/Cubic_bspline_2.h>
#include <fair/Cubic_interpolating_spline_2.h>
#include <fair/Cubic_quasi_interpolant_2.h>
#include <fair/Errors.h>
#include <fair/Fairness_metrics.h>
#include <fair/Four_point_subdivision_2.h>
#include <fair/Kappa_certificate.h>
#include <fair/Kappa_curve_2.h>
#include <fair/Nurbs_curve_2.h>
#include <fair/Optimal_curve_2.h>
#include <fair/Spline_convexity.h>
#include <fair/io/certify_curve.h>
#include <fair/io/enum_names.h>
#include <fair/io/read_design.h>
#include <fair/io/read_points.h>
#include <fair/io/write_dxf.h>
#include <fair/io/write_json.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace {

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 Point_2;
typedef py::array_t<double, py::array::c_style | py::array::forcecast> Array;

/// What Python sees of a solved curve: the program's curve JSON (family_to_json) and the NURBS
/// it evaluates. Built without the GIL, immutable afterwards (so threads may share it).
struct Solved_curve {
  std::string method;
  nlohmann::json json;
  std::optional<fair::Nurbs_curve_2<K>> nurbs;  // absent only when a failed solve left no pieces
  std::shared_ptr<const fair::Kappa_curve_2<K>> kappa;  // a kappa-curve, for its exact certificate
};

/// An (N, 2) array or a sequence of pairs as points: a wrong shape, a value that is not a number,
/// NaN or inf is fair::Invalid_input_error (fair.InvalidInputError, a ValueError), as in the
/// library; too few points or equal consecutive points by fair::io::check_point_file, the
/// program's own check (so the messages are the program's, naming "points").
std::vector<Point_2> to_points(const py::object& object, const char* what) {
  Array a;
  try {
    a = Array::ensure(object);
  } catch (const py::error_already_set&) {
  }
  if (!a) {
    PyErr_Clear();
    throw fair::Invalid_input_error(fair::internal::message(what, ": expected an (N, 2) array of numbers"));
  }
  if (a.ndim() != 2 || a.shape(1) != 2)
    throw fair::Invalid_input_error(fair::internal::message(what, ": expected an (N, 2) array of numbers, got shape (",
                                                            a.ndim() ? a.shape(0) : 0, a.ndim() > 1 ? ", " : "",
                                                            a.ndim() > 1 ? std::to_string(a.shape(1)) : "", ")"));
  std::vector<Point_2> out;
  auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < r.shape(0); ++i) {
    if (!std::isfinite(r(i, 0)) || !std::isfinite(r(i, 1)))
      throw fair::Invalid_input_error(
          fair::internal::message(what, ": point ", i, " is not finite: (", r(i, 0), ", ", r(i, 1), ")"));
    out.emplace_back(r(i, 0), r(i, 1));
  }
  return out;
}

/// A number option (a Python int or float): anything else is fair::Invalid_input_error naming the
/// option, as the program's option_number (pybind11's cast_error would be an untyped RuntimeError).
double number_option(const py::object& o, const char* what) {
  try {
    return o.cast<double>();
  } catch (const py::cast_error&) {
    throw fair::Invalid_input_error(fair::internal::message(what, ": expected a number, got ", std::string(py::repr(o))));
  }
}

/// An iteration count: an integer >= 0 (an integral float too), at most 1e9 like the program's.
std::size_t count_option(const py::object& o, const char* what) {
  const double v = number_option(o, what);
  if (!(v >= 0) || v != std::floor(v) || v > 1e9)
    throw fair::Invalid_input_error(fair::internal::message(what, ": expected an integer >= 0, got ", std::string(py::repr(o))));
  return static_cast<std::size_t>(v);
}

/// The program's check of a point file (count, equal consecutive points) on `points`.
void check_points(const std::vector<Point_2>& points, std::size_t minimum, bool closed, const char* method) {
  fair::io::Point_file<K> data;
  data.file = "points";
  data.points = points;
  fair::io::check_point_file(data, minimum, closed, method);
}

template <class Curve>
Solved_curve solved(const Curve& curve, const std::string& method, const nlohmann::json& extra = nlohmann::json::object(),
                    const std::vector<nlohmann::json>& per_piece = {}) {
  Solved_curve s;
  s.method = method;
  s.json = fair::io::family_to_json(curve, method, extra, per_piece);
  fair::io::check_json_finite(s.json);
  if (!curve.pieces().empty()) s.nurbs = curve.nurbs();
  return s;
}

// ------------------------------------------------------------------ the families
// Each takes its points and options with the GIL held, and solves with it released.

Solved_curve kappa_curve(const py::object& points, bool closed, const py::object& weights, const py::object& tension,
                         const py::object& clamp, const py::object& max_iterations, bool throw_on_failure) {
  fair::Kappa_curve_options options;
  options.closed = closed;
  options.throw_on_failure = throw_on_failure;
  std::vector<Point_2> p = to_points(points, "points");
  // fair-curves kappa --weights: "1" (UNIT), "auto", or a weight W > 0 for every point.
  double fixed = 1;
  if (py::isinstance<py::str>(weights)) {
    const std::string w = weights.cast<std::string>();
    if (w != "auto" && w != "1")
      throw fair::Invalid_input_error("weights: expected \"auto\", 1 or a number > 0, got '" + w + "'");
    options.weights = w == "auto" ? fair::Kappa_weights::AUTOMATIC : fair::Kappa_weights::UNIT;
  } else {
    fixed = number_option(weights, "weights");
    if (!(fixed > 0) || !std::isfinite(fixed))
      throw fair::Invalid_input_error(fair::internal::message("weights: expected \"auto\" or a number > 0, got ", fixed));
    options.weights = fixed == 1 ? fair::Kappa_weights::UNIT : fair::Kappa_weights::FIXED;
  }
  if (!tension.is_none() || !clamp.is_none())
    if (options.weights != fair::Kappa_weights::AUTOMATIC)
      throw fair::Invalid_input_error("tension and clamp apply to weights=\"auto\" only");
  if (!clamp.is_none()) {
    options.weight_clamp = number_option(clamp, "clamp");
    if (!(options.weight_clamp > 0) || !std::isfinite(options.weight_clamp))
      throw fair::Invalid_input_error(fair::internal::message("clamp: expected a number > 0, got ", options.weight_clamp));
  }
  if (!tension.is_none()) {
    Array t = Array::ensure(tension);
    if (!t || t.ndim() != 1 || static_cast<std::size_t>(t.shape(0)) != p.size())
      throw fair::Invalid_input_error(fair::internal::message("tension: expected one number per point (", p.size(), ")"));
    options.tension.assign(t.data(), t.data() + t.shape(0));
  }
  if (!max_iterations.is_none()) options.max_iterations = count_option(max_iterations, "max_iterations");
  py::gil_scoped_release release;
  check_points(p, 3, closed, "kappa_curve");
  if (options.weights == fair::Kappa_weights::FIXED) options.fixed_weights.assign(p.size(), fixed);
  auto kept = std::make_shared<const fair::Kappa_curve_2<K>>(p, options);
  const fair::Kappa_curve_2<K>& curve = *kept;
  // The members of fair-curves kappa -o (kappa_command.cpp, curve_json).
  std::vector<nlohmann::json> per_piece;
  for (std::size_t j = 0; j < curve.number_of_pieces(); ++j)
    per_piece.push_back({{"point", curve.point_index(j)}, {"t", curve.t(j)}});
  nlohmann::json extra{{"weights", fair::io::spelling(options.weights)}};
  if (options.weights == fair::Kappa_weights::FIXED) extra["fixed_weight"] = fixed;
  if (options.weights == fair::Kappa_weights::AUTOMATIC) extra["weight_clamp"] = options.weight_clamp;
  Solved_curve s = solved(curve, "kappa", extra, per_piece);
  s.kappa = std::move(kept);
  return s;
}

/// fair::certify(kappa-curve) (fair/Kappa_certificate.h): the exact curve of the solver's state
/// certified fraction-free in exact rationals, as a dict of Kappa_certificate's verdicts, per piece
/// and per join. Only the verdicts and bounds: the exact pieces stay in C++.
py::dict kappa_certificate(const Solved_curve& c) {
  if (!c.kappa) throw fair::Precondition_error("kappa_certificate: not a kappa-curve");
  std::optional<fair::Kappa_certificate> cert;
  {
    py::gil_scoped_release release;
    cert.emplace(fair::certify(*c.kappa));
  }
  py::list pieces, joins;
  for (const auto& p : cert->pieces) {
    py::dict d;
    d["point"] = p.point_index;
    d["valid_piece"] = p.valid_piece;
    d["point_on_piece"] = p.point_on_piece;
    d["interpolation_error"] = p.interpolation_error;
    d["extrema"] = p.extrema;
    d["maxima"] = p.maxima;
    d["unique_maximum"] = p.unique_maximum;
    d["maximum_at_t"] = p.maximum_at_t;
    d["t"] = p.t;
    d["root_interval"] = py::make_tuple(p.root_lower, p.root_upper);
    d["root_distance"] = p.root_distance;
    pieces.append(d);
  }
  for (const auto& j : cert->joins) {
    py::dict d;
    d["piece"] = j.piece;
    d["c0"] = j.c0;
    d["g1"] = j.g1;
    d["kappa_mismatch"] = py::make_tuple(j.kappa_mismatch_lower, j.kappa_mismatch_upper);
    joins.append(d);
  }
  py::dict out;
  out["status"] = fair::io::spelling(cert->status);
  out["proves_outcome"] = cert->proves_outcome();
  out["valid"] = cert->valid();
  out["all_points_on_pieces"] = cert->all_points_on_pieces();
  out["all_g1"] = cert->all_g1();
  out["all_maxima_at_points"] = cert->all_maxima_at_points();
  out["max_kappa_mismatch"] = cert->max_kappa_mismatch();
  out["max_root_distance"] = cert->max_root_distance();
  out["max_interpolation_error"] = cert->max_interpolation_error();
  out["pieces"] = pieces;
  out["joins"] = joins;
  return out;
}

Solved_curve cardinal_spline(const py::object& points, bool closed, const py::object& alpha, bool throw_on_failure) {
  fair::Cardinal_spline_options options;
  options.closed = closed;
  options.throw_on_failure = throw_on_failure;
  if (!alpha.is_none()) {
    options.alpha = number_option(alpha, "alpha");
    if (!(*options.alpha > 0) || !std::isfinite(*options.alpha))
      throw fair::Invalid_input_error(fair::internal::message("alpha: expected a number > 0, got ", *options.alpha));
  }
  std::vector<Point_2> p = to_points(points, "points");
  py::gil_scoped_release release;
  check_points(p, !options.alpha ? (closed ? 3 : 4) : 3, closed, "cardinal_spline");
  const fair::Cardinal_spline_2<K> curve(p, options);
  // The members of fair-curves cardinal -o (cardinal_command.cpp, cardinal_json).
  const fair::Quadrature_estimate e = fair::curvature_variation_energy(curve.pieces(), fair::Energy_measure::PARAMETER);
  const fair::Quadrature_estimate s = fair::curvature_variation_energy(curve.pieces(), fair::Energy_measure::ARC_LENGTH);
  const nlohmann::json extra{{"energy_true", e.value}, {"energy_true_error", e.error_bound}, {"energy_true_arc_length", s.value}};
  return solved(curve, "cardinal", extra);
}

Solved_curve csr_spline(const py::object& samples, bool closed, const std::string& knots) {
  fair::Csr_spline_options options;
  options.closed = closed;
  if (!fair::io::try_parse_spelling(knots, options.knot_spacing))
    throw fair::Invalid_input_error("knots: expected " + fair::io::spellings_list<fair::Knot_spacing>() + ", got '" +
                                    knots + "'");
  std::vector<Point_2> p = to_points(samples, "samples");
  py::gil_scoped_release release;
  check_points(p, closed ? 4 : 3, closed, "csr_spline");
  const fair::Csr_spline_2<K> csr(p, options);
  // The members of fair-curves csr -o (csr_command.cpp).
  nlohmann::json d = nlohmann::json::array(), kappa = nlohmann::json::array();
  for (double v : csr.distances_to_samples()) d.push_back(v);
  for (double v : csr.discrete_curvatures()) kappa.push_back(v);
  const nlohmann::json extra{{"knot_spacing", fair::io::spelling(options.knot_spacing)},
                             {"epsilon_rule", fair::to_string(options.epsilon_rule)},
                             {"relative_epsilon", options.relative_epsilon},
                             {"discrete_curvatures", kappa},
                             {"distances_to_samples", d},
                             {"max_distance_to_samples", csr.max_distance_to_samples()}};
  return solved(csr, "csr", extra);
}

/// Constraints as an (k, 3) array of rows (index, dx, dy), or (k, 5) rows (index, in dx, in dy,
/// out dx, out dy) for corners.
void add_constraints(const py::object& rows, fair::Point_constraint_kind kind, std::vector<fair::Point_constraint>& out) {
  if (rows.is_none()) return;
  const std::size_t columns = kind == fair::Point_constraint_kind::CORNER ? 5 : 3;
  Array a = Array::ensure(rows);
  if (!a || a.ndim() != 2 || static_cast<std::size_t>(a.shape(1)) != columns)
    throw fair::Invalid_input_error(fair::internal::message(fair::io::spelling(kind), " constraints: expected a (k, ",
                                                            columns, ") array of rows (index, dx, dy",
                                                            columns == 5 ? ", out dx, out dy" : "", ")"));
  auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < r.shape(0); ++i) {
    for (std::size_t c = 0; c < columns; ++c)
      if (!std::isfinite(r(i, c))) throw fair::Invalid_input_error(fair::internal::message(fair::io::spelling(kind), " constraint ", i, " is not finite"));
    // (an index of 2^64 or more would wrap in the cast: review finding; 2^53 bounds every exact index)
    if (r(i, 0) < 0 || r(i, 0) != std::floor(r(i, 0)) || r(i, 0) >= 9007199254740992.0)
      throw fair::Invalid_input_error(fair::internal::message(fair::io::spelling(kind), " constraint ", i, ": the index must be an integer in [0, 2^53), got ", r(i, 0)));
    fair::Point_constraint c;
    c.index = static_cast<std::size_t>(r(i, 0));
    c.kind = kind;
    c.direction = {{r(i, 1), r(i, 2)}};
    if (columns == 5) c.outgoing = {{r(i, 3), r(i, 4)}};
    out.push_back(c);
  }
}

Solved_curve optimal_curve(const py::object& points, bool closed, const py::object& lam, const py::object& length_weight,
                           const py::object& curvature_weight, const py::object& curvature_exponent,
                           const py::object& resolution, const std::string& solver, const py::object& tangents,
                           const py::object& normals, const py::object& corners, const py::object& segment_lambda,
                           const py::object& derivative_weight, bool throw_on_failure) {
  fair::Optimal_curve_options options;
  options.closed = closed;
  options.throw_on_failure = throw_on_failure;
  // The option logic of fair-curves optimal (optimal_command.cpp, curve_options): lambda designs
  // beta and beta_0 (eq. 10); explicit weights switch the design off (lambda = -1).
  if (!lam.is_none() && (!length_weight.is_none() || !curvature_weight.is_none()))
    throw fair::Invalid_input_error("lam sets the length and curvature weights (eq. 10): drop length_weight/curvature_weight");
  auto number = [](const py::object& o, const char* what, double low, double high) {
    const double v = number_option(o, what);
    if (!(v >= low && v <= high))
      throw fair::Invalid_input_error(fair::internal::message(what, ": expected a value in [", low, ", ", high, "], got ", v));
    return v;
  };
  if (!lam.is_none() && !segment_lambda.is_none())
    throw fair::Invalid_input_error("lam and segment_lambda exclude each other");
  if (!segment_lambda.is_none() && (!length_weight.is_none() || !curvature_weight.is_none()))
    throw fair::Invalid_input_error("segment_lambda sets the length and curvature weights (eq. 10): drop length_weight/curvature_weight");
  if (!lam.is_none()) options.lambda = number(lam, "lam", 0, 1);
  if (!length_weight.is_none() || !curvature_weight.is_none() || !segment_lambda.is_none()) options.lambda = -1;
  if (!segment_lambda.is_none()) {
    // One lambda per segment (the program's --lambda-file); its count and range are checked by
    // the solve (internal/optimal/hierarchy.h).
    Array l = Array::ensure(segment_lambda);
    if (!l || l.ndim() != 1) throw fair::Invalid_input_error("segment_lambda: expected one number per segment");
    options.segment_lambda.assign(l.data(), l.data() + l.shape(0));
  }
  if (!length_weight.is_none()) options.length_weight = number(length_weight, "length_weight", 0, HUGE_VAL);
  if (!curvature_weight.is_none()) options.curvature_weight = number(curvature_weight, "curvature_weight", 0, HUGE_VAL);
  if (!curvature_exponent.is_none()) options.curvature_exponent = number(curvature_exponent, "curvature_exponent", 1, HUGE_VAL);
  if (!resolution.is_none()) options.resolution = number(resolution, "resolution", 1e-300, fair::max_optimal_resolution);
  if (!fair::io::try_parse_spelling(solver, options.solver))
    throw fair::Invalid_input_error("solver: expected " + fair::io::spellings_list<fair::Optimal_curve_solver>() +
                                    ", got '" + solver + "'");
  if (!tangents.is_none() && !normals.is_none())
    throw fair::Invalid_input_error("tangents and normals exclude each other (give a normal as a tangent)");
  // The program's --derivative-weight K:BK[:AK]: {k: beta_k} or {k: (beta_k, alpha_k)}, k in 1..4
  // (the C^(k+1) curves of Sec. 3.3; with any beta_k > 0 the C4 quintic smoothing spline,
  // Optimal_curve_2::quintic_spline, is returned too).
  bool derivative_term = false;
  if (!derivative_weight.is_none()) {
    if (!py::isinstance<py::dict>(derivative_weight))
      throw fair::Invalid_input_error("derivative_weight: expected a dict {k: beta_k} or {k: (beta_k, alpha_k)}, k in 1..4");
    for (const auto& item : py::reinterpret_borrow<py::dict>(derivative_weight)) {
      const double kd = number_option(py::reinterpret_borrow<py::object>(item.first), "derivative_weight key");
      if (!(kd >= 1 && kd <= 4 && kd == std::floor(kd)))
        throw fair::Invalid_input_error(fair::internal::message("derivative_weight: the order k must be 1, 2, 3 or 4, got ", kd));
      const std::size_t k = static_cast<std::size_t>(kd);
      py::object value = py::reinterpret_borrow<py::object>(item.second);
      if (py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) {
        py::sequence pair = py::reinterpret_borrow<py::sequence>(value);
        if (pair.size() != 2) throw fair::Invalid_input_error("derivative_weight: a value is beta_k or (beta_k, alpha_k)");
        options.derivative_exponent[k] = number(py::object(pair[1]), "derivative_weight exponent alpha_k", 1, HUGE_VAL);
        value = py::object(pair[0]);
      }
      options.derivative_weight[k] = number(value, "derivative_weight beta_k", 0, HUGE_VAL);
      derivative_term = derivative_term || options.derivative_weight[k] > 0;
    }
  }
  add_constraints(tangents, fair::Point_constraint_kind::TANGENT, options.constraints);
  add_constraints(normals, fair::Point_constraint_kind::NORMAL, options.constraints);
  add_constraints(corners, fair::Point_constraint_kind::CORNER, options.constraints);
  std::vector<Point_2> p = to_points(points, "points");
  py::gil_scoped_release release;
  check_points(p, closed ? 3 : 2, closed, "optimal_curve");
  const fair::Optimal_curve_2<K> curve(p, options);
  // The members of fair-curves optimal -o (fair::io::optimal_curve_members), with the quintic fit
  // where a derivative term is on, as the program writes it.
  std::unique_ptr<fair::Polygon_quintic_fit<K>> quintic;
  if (derivative_term)
    quintic.reset(new fair::Polygon_quintic_fit<K>(curve.quintic_spline()));
  const nlohmann::json extra = fair::io::optimal_curve_members(curve, quintic.get());
  return solved(curve, "optimal", extra);
}

Solved_curve interpolating_spline(const py::object& points, const std::string& method, bool closed, const std::string& end,
                                  const std::string& knots, const py::object& start_derivative,
                                  const py::object& end_derivative) {
  // The option logic of fair-curves spline (spline_command.cpp, run_spline).
  const bool clamped = end == "clamped";
  if (end != "natural" && end != "not-a-knot" && !clamped)
    throw fair::Invalid_input_error("end: expected natural, not-a-knot or clamped, got '" + end + "'");
  if (method != "cubic" && method != "catmull-rom" && method != "four-point" && method != "quasi" && method != "bspline")
    throw fair::Invalid_input_error("method: expected cubic, catmull-rom, four-point, quasi or bspline, got '" + method + "'");
  if (end != "natural" && method != "cubic") throw fair::Invalid_input_error("end applies to method=\"cubic\" only");
  // The knots of the cubic (Cubic_interpolating_spline_options::knot_spacing; the library's and
  // the program's default is uniform).
  fair::Knot_spacing spacing = fair::Knot_spacing::UNIFORM;
  if (!fair::io::try_parse_spelling(knots, spacing))
    throw fair::Invalid_input_error("knots: expected " + fair::io::spellings_list<fair::Knot_spacing>() + ", got '" +
                                    knots + "'");
  if (spacing != fair::Knot_spacing::UNIFORM && method != "cubic")
    throw fair::Invalid_input_error("knots applies to method=\"cubic\" only");
  if (clamped != (!start_derivative.is_none() && !end_derivative.is_none()) ||
      (!clamped && (!start_derivative.is_none() || !end_derivative.is_none())))
    throw fair::Invalid_input_error("start_derivative/end_derivative: give both with end=\"clamped\", and only then");
  if (clamped && closed) throw fair::Invalid_input_error("end: a closed spline has no ends");
  K::Vector_2 d0, d1;
  if (clamped) {
    const std::vector<Point_2> d = to_points(py::make_tuple(start_derivative, end_derivative), "derivatives");
    d0 = d[0] - CGAL::ORIGIN;
    d1 = d[1] - CGAL::ORIGIN;
  }
  std::vector<Point_2> p = to_points(points, "points");
  py::gil_scoped_release release;
  check_points(p, method == "four-point" ? (closed ? 3 : 4) : (closed ? 3 : 2), closed, "interpolating_spline");
  if (method == "cubic") {
    fair::Cubic_interpolating_spline_options options;
    options.closed = closed;
    options.end_condition = end == "not-a-knot" ? fair::Spline_end_condition::NOT_A_KNOT : fair::Spline_end_condition::NATURAL;
    options.knot_spacing = spacing;
    // fair-curves spline writes "end" for an open cubic; the knots only when not the default.
    nlohmann::json extra = closed ? nlohmann::json::object() : nlohmann::json{{"end", end}};
    if (spacing != fair::Knot_spacing::UNIFORM) extra["knot_spacing"] = fair::io::spelling(spacing);
    if (clamped) return solved(fair::Cubic_interpolating_spline_2<K>(p, d0, d1, options), method, extra);
    return solved(fair::Cubic_interpolating_spline_2<K>(p, options), method, extra);
  }
  if (method == "catmull-rom") {
    fair::Catmull_rom_options options;
    options.closed = closed;
    return solved(fair::Catmull_rom_2<K>(p, options), method);
  }
  if (method == "four-point") {
    fair::Four_point_subdivision_options options;
    options.closed = closed;
    return solved(fair::Four_point_subdivision_2<K>(p, options), method);
  }
  if (method == "quasi") {
    fair::Cubic_quasi_interpolant_options options;
    options.closed = closed;
    return solved(fair::Cubic_quasi_interpolant_2<K>(p, options), method);
  }
  fair::Cubic_bspline_options options;
  options.closed = closed;
  return solved(fair::Cubic_bspline_2<K>(p, options), method);
}

// The basic-shape design (fair::basic_shape_design of a design file, doc/basic_shapes.md) with
// the report of fair-curves shapes -o (fair/io/write_design_json.h: design_to_json, convexity_to_json; and
// basic_shapes_figures.h: certified_convexity, Proposition 1 decided in EPECK on the spline's own
// doubles)
Solved_curve basic_shape_design(const std::string& text, const std::string& name) {
  typedef CGAL::Exact_predicates_exact_constructions_kernel E;
  py::gil_scoped_release release;
  const fair::io::Design_file<K> f = fair::io::parse_design<K>(text, name);
  const fair::Basic_shape_design_2<K> d = fair::basic_shape_design(f.shapes, f.options());
  std::vector<E::FT> t, w;
  std::vector<E::Point_2> cp;
  for (const double x : d.spline.breakpoints()) t.push_back(E::FT(x));
  for (const double x : d.spline.weights()) w.push_back(E::FT(x));
  for (const Point_2& x : d.spline.control_points()) cp.push_back(E::Point_2(E::FT(x.x()), E::FT(x.y())));
  const fair::Spline_convexity_report<E> c = fair::spline_convexity(fair::Cubic_spline_2<E>(t, cp, w, d.spline.is_closed()));
  nlohmann::json extra = fair::io::design_to_json(f, d, false);
  extra["convexity"] = fair::io::convexity_to_json(c);
  extra["bspline"] = fair::io::nurbs_to_json(d.nurbs());
  // The design's points are its marked points, shape after shape.
  std::vector<Point_2> points;
  for (const auto& marks : f.marked_points) points.insert(points.end(), marks.begin(), marks.end());
  Solved_curve s;
  s.method = "shapes";
  s.json = fair::io::curve_to_json("shapes", f.closed, points, d.spline.pieces(), extra);
  fair::io::check_json_finite(s.json);
  s.nurbs = d.nurbs();
  return s;
}

// ------------------------------------------------------------------ evaluation

const fair::Nurbs_curve_2<K>& nurbs_of(const Solved_curve& c) {
  if (!c.nurbs) throw fair::Precondition_error("the solve left no curve (status " + c.json.value("status", std::string("?")) + ")");
  return *c.nurbs;
}

/// c^(nu)(u) for every u (a flat array), as (n, 2); Nurbs_curve_2::derivatives (exact derivatives
/// of the rational curve). A u outside the domain is fair::Precondition_error (a ValueError).
Array evaluate(const Solved_curve& c, const Array& u, int nu) {
  const fair::Nurbs_curve_2<K>& n = nurbs_of(c);
  // The cap: derivatives() costs O(nu^2) per parameter (the Leibniz quotient rule) and, for a
  // rational curve, its terms overflow past order ~150 (review: nu = 170 gave NaN, nu = 10^6 ran
  // for minutes with the GIL released); no geometric use needs more than a few orders.
  constexpr int max_derivative_order = 32;
  if (nu < 0 || nu > max_derivative_order)
    throw fair::Precondition_error(fair::internal::message("nu: expected a derivative order in [0, ", max_derivative_order,
                                                           "], got ", nu));
  Array out({static_cast<py::ssize_t>(u.size()), static_cast<py::ssize_t>(2)});
  const double* in = u.data();
  double* o = out.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < u.size(); ++i) {
      if (!std::isfinite(in[i])) throw fair::Precondition_error(fair::internal::message("u[", i, "] is not finite"));
      if (nu == 0) {
        const Point_2 p = n.point(in[i]);
        o[2 * i] = p.x(), o[2 * i + 1] = p.y();
      } else {
        const K::Vector_2 v = n.derivatives(in[i], static_cast<std::size_t>(nu))[static_cast<std::size_t>(nu)];
        o[2 * i] = v.x(), o[2 * i + 1] = v.y();
      }
      if (!std::isfinite(o[2 * i]) || !std::isfinite(o[2 * i + 1]))
        throw fair::Precondition_error(fair::internal::message("the derivative of order ", nu, " at u[", i, "] = ", in[i],
                                                               " is beyond the double range"));
    }
  }
  return out;
}

Array curvature(const Solved_curve& c, const Array& u) {
  const fair::Nurbs_curve_2<K>& n = nurbs_of(c);
  Array out(u.size());
  const double* in = u.data();
  double* o = out.mutable_data();
  py::gil_scoped_release release;
  for (py::ssize_t i = 0; i < u.size(); ++i) {
    if (!std::isfinite(in[i])) throw fair::Precondition_error(fair::internal::message("u[", i, "] is not finite"));
    o[i] = n.curvature(in[i]);
  }
  return out;
}

py::list certify_file(const std::string& file, const std::string& points_file, double tolerance) {
  std::vector<fair::io::Certified_property> properties;
  {
    py::gil_scoped_release release;
    properties = fair::io::certify_curve_file(file, points_file, tolerance);
  }
  py::list out;
  for (const auto& p : properties) {
    py::dict d;
    d["name"] = p.name;
    d["holds"] = p.holds;
    d["defect"] = p.defect;
    d["detail"] = p.detail;
    out.append(d);
  }
  return out;
}

} // namespace

PYBIND11_MODULE(_fair, m) {
  m.doc() = "fair: fair interpolating planar curves (the C++ library's binding; use the package `fair`)";

  // fair's errors as Python exceptions (include/fair/Errors.h). Translators registered later are
  // tried first: the base class first, the specific ones after it.
  static py::exception<fair::Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<fair::Invalid_input_error> invalid(
      m, "InvalidInputError", py::make_tuple(error, py::handle(PyExc_ValueError)).ptr());
  static py::exception<fair::Precondition_error> precondition(
      m, "PreconditionError", py::make_tuple(error, py::handle(PyExc_ValueError)).ptr());
  static py::exception<fair::Solve_error> solve(m, "SolveError", error.ptr());
  static py::exception<fair::Non_convergence_error> non_convergence(m, "NonConvergenceError", error.ptr());
  static py::exception<fair::Internal_error> internal(m, "InternalError", error.ptr());
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const fair::Invalid_input_error& e) {  // Parse_error included
      PyErr_SetString(invalid.ptr(), e.what());
    } catch (const fair::Precondition_error& e) {
      PyErr_SetString(precondition.ptr(), e.what());
    } catch (const fair::Solve_error& e) {
      // The exception carries the family's report (Solve_error::report<T>) as `.report`, the
      // dict of to_json(report) (fair/io/write_json.h), as the curve would have had it.
      nlohmann::json r;
      if (const auto* k = e.report<fair::Kappa_curve_report>()) r = fair::io::to_json(*k);
      else if (const auto* o = e.report<fair::Optimal_curve_report>()) r = fair::io::to_json(*o);
      else if (const auto* c = e.report<fair::Cardinal_spline_report<K>>()) r = fair::io::to_json(*c);
      py::object value = py::reinterpret_borrow<py::object>(solve.ptr())(e.what());
      value.attr("report") = r.is_null() ? py::object(py::none()) : py::module_::import("json").attr("loads")(r.dump());
      PyErr_SetObject(solve.ptr(), value.ptr());
    } catch (const fair::Non_convergence_error& e) {
      PyErr_SetString(non_convergence.ptr(), e.what());
    } catch (const fair::Internal_error& e) {
      PyErr_SetString(internal.ptr(), e.what());
    } catch (const fair::Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    }
  });

  py::class_<Solved_curve>(m, "_Solved_curve")
      .def_readonly("method", &Solved_curve::method)
      .def("json_text", [](const Solved_curve& c) { return c.json.dump(); })
      .def("json_pretty", [](const Solved_curve& c) {
        std::ostringstream out;
        fair::io::write_json(out, c.json);
        return out.str();
      })
      .def("nurbs_data", [](const Solved_curve& c) {
        const fair::Nurbs_curve_2<K>& n = nurbs_of(c);
        Array cps({static_cast<py::ssize_t>(n.number_of_control_points()), static_cast<py::ssize_t>(2)});
        for (std::size_t i = 0; i < n.number_of_control_points(); ++i)
          cps.mutable_at(i, 0) = n.control_points()[i].x(), cps.mutable_at(i, 1) = n.control_points()[i].y();
        Array w(n.weights().size()), u(n.knots().size());
        std::copy(n.weights().begin(), n.weights().end(), w.mutable_data());
        std::copy(n.knots().begin(), n.knots().end(), u.mutable_data());
        return py::make_tuple(n.degree(), u, cps, w, n.is_closed(), n.is_rational());
      })
      .def("kappa_certificate", &kappa_certificate)
      .def("domain", [](const Solved_curve& c) { return nurbs_of(c).domain(); })
      .def("evaluate", &evaluate, py::arg("u"), py::arg("nu") = 0)
      .def("curvature", &curvature, py::arg("u"))
      .def("dxf_text", [](const Solved_curve& c) {
        const fair::Nurbs_curve_2<K>& n = nurbs_of(c);
        py::gil_scoped_release release;
        return fair::io::dxf_text(std::vector<fair::Nurbs_curve_2<K>>{n});
      });

  m.def("kappa_curve", &kappa_curve, py::arg("points"), py::arg("closed") = false, py::arg("weights") = 1.0,
        py::arg("tension") = py::none(), py::arg("clamp") = py::none(), py::arg("max_iterations") = py::none(),
        py::arg("throw_on_failure") = false);
  m.def("cardinal_spline", &cardinal_spline, py::arg("points"), py::arg("closed") = false, py::arg("alpha") = py::none(),
        py::arg("throw_on_failure") = false);
  m.def("csr_spline", &csr_spline, py::arg("samples"), py::arg("closed") = false, py::arg("knots") = "chordal");
  m.def("optimal_curve", &optimal_curve, py::arg("points"), py::arg("closed") = false, py::arg("lam") = py::none(),
        py::arg("length_weight") = py::none(), py::arg("curvature_weight") = py::none(),
        py::arg("curvature_exponent") = py::none(), py::arg("resolution") = py::none(), py::arg("solver") = "newton",
        py::arg("tangents") = py::none(), py::arg("normals") = py::none(), py::arg("corners") = py::none(),
        py::arg("segment_lambda") = py::none(), py::arg("derivative_weight") = py::none(),
        py::arg("throw_on_failure") = false);
  m.def("interpolating_spline", &interpolating_spline, py::arg("points"), py::arg("method") = "cubic",
        py::arg("closed") = false, py::arg("end") = "natural", py::arg("knots") = "uniform", py::arg("start_derivative") = py::none(),
        py::arg("end_derivative") = py::none());
  m.def("basic_shape_design", &basic_shape_design, py::arg("text"), py::arg("name") = "design");
  m.def("certify_file", &certify_file, py::arg("file"), py::arg("points_file") = "", py::arg("tolerance") = 0.0);
}
