// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves metrics: the fairness figures (include/fair/Fairness_metrics.h, doc/fairness_metrics.md)
// of any curve JSON the program writes ({"format": "fair-curve", "pieces": [{"control_points":
// [[x, y], ...], "weights": [...]?}, ...]}). Coordinates are read exactly (decimal numbers as the
// nearest double, "p/q" strings as rationals), so the feature counts are certified for exactly
// the curve in the file.

#include "registry.h"
#include "tool_common.h"

#include <fair/Bezier_2.h>
#include <fair/Fairness_metrics.h>
#include <fair/io/parsing.h>
#include <fair/io/read_points.h>
#include <fair/io/svg.h>
#include <fair/io/write_json.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<CGAL::Gmpq> Exact_kernel;

// A rational Bezier piece as read from a file: what the metrics need (control_points() and
// weights(): the metrics evaluate it through its Bernstein form).
struct File_rational_piece {
  typedef Exact_kernel Kernel;
  typedef Exact_kernel::FT FT;
  typedef Exact_kernel::Point_2 Point_2;
  typedef Exact_kernel::Vector_2 Vector_2;
  std::vector<Point_2> cp;
  std::vector<FT> w;
  const std::vector<Point_2>& control_points() const { return cp; }
  const std::vector<FT>& weights() const { return w; }
};

struct File_curve {
  std::vector<File_rational_piece> pieces;
  bool rational = false;
  std::vector<fair::Bezier_2<Exact_kernel>> polynomial() const {
    std::vector<fair::Bezier_2<Exact_kernel>> out;
    for (const File_rational_piece& p : pieces) out.emplace_back(p.cp);
    return out;
  }
};

// What a file that is not a curve JSON gets told.
const char* const not_a_curve = "expected a curve JSON written by fair-curves (an object with a \"pieces\" array)";

File_curve read_curve_file(const std::string& file) {
  using fair::io::Json_value;
  using fair::Parse_error;
  const std::string text = fair::io::read_text_file(file);
  Json_value root;
  try {
    root = fair::io::parse_json(text, file);
  } catch (const Parse_error& e) {
    // A points CSV, or any other text: say what was expected, then the parser's reason.
    const std::string what = e.what();
    const std::string prefix = file + (e.line() ? ":" + std::to_string(e.line()) : std::string()) + ": ";
    throw Parse_error(file, e.line(),
                      std::string(not_a_curve) + "; " + (what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what));
  }
  if (root.kind != Json_value::OBJECT) throw Parse_error(file, root.line, not_a_curve);
  const Json_value* pieces = root.find("pieces");
  if (!pieces) throw Parse_error(file, root.line, std::string(not_a_curve) + "; this JSON object has no \"pieces\"");
  if (pieces->kind != Json_value::ARRAY || pieces->items.empty())
    throw Parse_error(file, pieces->line, "\"pieces\" must be a nonempty array");
  auto number = [&](const Json_value& v, const std::string& what) {
    if (v.kind != Json_value::NUMBER && v.kind != Json_value::STRING)
      throw Parse_error(file, v.line, what + " must be a number, got " + Json_value::kind_name(v.kind));
    return fair::io::to_ft<CGAL::Gmpq>(fair::io::parse_number(v.text, file, v.line, what.c_str()));
  };
  auto point = [&](const Json_value& xy, const std::string& what) {
    if (xy.kind != Json_value::ARRAY || xy.items.size() != 2)
      throw Parse_error(file, xy.line, what + ": expected an [x, y] pair");
    return Exact_kernel::Point_2(number(xy.items[0], what + " x"), number(xy.items[1], what + " y"));
  };
  File_curve curve;
  for (std::size_t i = 0; i < pieces->items.size(); ++i) {
    const Json_value& p = pieces->items[i];
    const std::string name = "piece " + std::to_string(i);
    if (p.kind != Json_value::OBJECT) throw Parse_error(file, p.line, name + ": expected an object");
    File_rational_piece piece;
    const Json_value* cps = p.find("control_points");
    if (!cps && p.find("P0") && p.find("P1") && p.find("P2")) {
      // The conic pieces of `fair-curves kappa`: {"P0", "P1", "P2", "w"}, the standard rational
      // quadratic form with weights (1, w, 1) (w absent: 1).
      for (const char* key : {"P0", "P1", "P2"}) piece.cp.push_back(point(*p.find(key), name + " " + key));
      const Json_value* w = p.find("w");
      const CGAL::Gmpq wm = w ? number(*w, name + " w") : CGAL::Gmpq(1);
      if (!(wm > 0)) throw Parse_error(file, w->line, name + ": the weight w must be > 0");
      piece.w = {CGAL::Gmpq(1), wm, CGAL::Gmpq(1)};
      if (wm != 1) curve.rational = true;
      curve.pieces.push_back(std::move(piece));
      continue;
    }
    if (!cps || cps->kind != Json_value::ARRAY || cps->items.empty())
      throw Parse_error(file, p.line, name + ": needs a nonempty \"control_points\" array (or \"P0\", \"P1\", \"P2\", \"w\")");
    for (std::size_t k = 0; k < cps->items.size(); ++k)
      piece.cp.push_back(point(cps->items[k], name + " control point " + std::to_string(k)));
    if (const Json_value* w = p.find("weights")) {
      if (w->kind != Json_value::ARRAY || w->items.size() != cps->items.size())
        throw Parse_error(file, w->line, name + ": \"weights\" must be an array with one weight per control point");
      for (const Json_value& x : w->items) {
        piece.w.push_back(number(x, name + " weight"));
        if (!(piece.w.back() > 0)) throw Parse_error(file, x.line, name + ": weights must be > 0");
      }
      curve.rational = true;
    } else {
      piece.w.assign(piece.cp.size(), CGAL::Gmpq(1));
    }
    curve.pieces.push_back(std::move(piece));
  }
  return curve;
}

struct Metrics_options {
  std::string input, json_out, circle, hausdorff, profile_out;
  double tolerance = 0;
  std::size_t samples = 64;
};

/// The --circle value "cx,cy,r" (r >= 0); anything else is a usage error.
std::vector<double> circle_option(const std::string& text) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) v.push_back(fair_curves::option_number(item, "--circle"));
  if (v.size() != 3 || !(v[2] >= 0))
    throw CLI::ValidationError("--circle", "expected \"cx,cy,r\" with r >= 0, got '" + text + "'");
  return v;
}

std::string features_text(const fair::Feature_report& r) {
  std::ostringstream out;
  for (const fair::Curve_feature& f : r.features)
    out << "  piece " << f.piece << " t = " << fair_curves::format_number(f.t, 12) << " at ("
        << fair_curves::format_number(f.x, 8) << ", " << fair_curves::format_number(f.y, 8)
        << "), curvature " << fair_curves::format_number(f.curvature, 8) << (f.at_joint ? " (at a join)" : "") << "\n";
  return out.str();
}

nlohmann::json features_json(const fair::Feature_report& r) {
  nlohmann::json a = nlohmann::json::array();
  for (const fair::Curve_feature& f : r.features)
    a.push_back({{"piece", f.piece}, {"t", f.t}, {"t_lower", CGAL::to_double(f.interval.lower)},
                 {"t_upper", CGAL::to_double(f.interval.upper)}, {"x", f.x}, {"y", f.y},
                 {"curvature", f.curvature}, {"at_joint", f.at_joint}});
  return a;
}

template <class Piece>
void report(const std::vector<Piece>& curve, const Metrics_options& o, const File_curve* other) {
  const fair::Fairness_report r = fair::fairness_report(curve);
  const fair::Feature_report infl = fair::inflections(curve), ext = fair::curvature_extrema(curve);
  const fair::Quadrature_estimate cv_t = fair::curvature_variation_energy(curve, fair::Energy_measure::PARAMETER);
  using fair_curves::format_number;
  std::ostringstream text; // the report: on stdout unless stdout is the JSON ("-o -")
  text << o.input << ": " << r.pieces << " pieces\n"
            << "arc length = " << format_number(r.length.value, 12) << "\n"
            << "bending energy int k^2 ds = " << format_number(r.bending.value, 12) << " (error estimate "
            << format_number(r.bending.error_bound, 2) << ")\n"
            << "curvature variation int (dk/ds)^2 ds = " << format_number(r.curvature_variation.value, 12)
            << " (error estimate " << format_number(r.curvature_variation.error_bound, 2) << ")\n"
            << "curvature variation sum int (dk/dt)^2 dt = " << format_number(cv_t.value, 12) << "\n"
            << "curvature range = [" << format_number(r.min_curvature, 8) << ", " << format_number(r.max_curvature, 8)
            << "]\n"
            << "inflections: " << infl.count() << (infl.certified ? " (certified)" : " (sampled)") << "\n"
            << features_text(infl) << "curvature extrema: " << ext.count()
            << (ext.certified ? " (certified)" : " (sampled)") << "\n"
            << features_text(ext);
  nlohmann::json j{{"pieces", r.pieces},
                   {"arc_length", r.length.value},
                   {"bending_energy", r.bending.value},
                   {"bending_energy_error", r.bending.error_bound},
                   {"curvature_variation_arc_length", r.curvature_variation.value},
                   {"curvature_variation_arc_length_error", r.curvature_variation.error_bound},
                   {"curvature_variation_parameter", cv_t.value},
                   {"min_curvature", r.min_curvature},
                   {"max_curvature", r.max_curvature},
                   {"certified", infl.certified && ext.certified},
                   {"inflections", features_json(infl)},
                   {"curvature_extrema", features_json(ext)}};
  if (!o.circle.empty()) {
    const std::vector<double> v = circle_option(o.circle);
    const fair::Circle_deviation d =
        fair::max_circle_deviation(curve, typename Piece::Point_2(v[0], v[1]), v[2]);
    text << "max deviation from the circle = " << format_number(d.max_deviation, 12) << " (piece " << d.piece
              << ", t = " << format_number(d.t, 10) << ")\n";
    j["circle_deviation"] = d.max_deviation;
  }
  if (other) {
    // Default tolerance: 1e-5 of the larger bounding box diagonal.
    double tol = o.tolerance;
    if (!(tol > 0)) {
      double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
      for (const auto& p : curve)
        for (const auto& q : p.control_points()) {
          xmin = std::min(xmin, CGAL::to_double(q.x())); xmax = std::max(xmax, CGAL::to_double(q.x()));
          ymin = std::min(ymin, CGAL::to_double(q.y())); ymax = std::max(ymax, CGAL::to_double(q.y()));
        }
      tol = std::max(1e-300, 1e-5 * std::hypot(xmax - xmin, ymax - ymin));
    }
    const double h = other->rational ? fair::hausdorff_distance(curve, other->pieces, tol)
                                     : fair::hausdorff_distance(curve, other->polynomial(), tol);
    text << "Hausdorff distance to " << o.hausdorff << " = " << format_number(h, 10) << " (sampling tolerance "
              << format_number(tol, 3) << ")\n";
    j["hausdorff_distance"] = h;
    j["hausdorff_tolerance"] = tol;
  }
  std::string profile_text;
  if (!o.profile_out.empty()) {
    std::ostringstream out;
    out.precision(17);
    out << "piece,t,arc_length,x,y,curvature\n";
    for (const fair::Curvature_sample& s : fair::curvature_profile(curve, o.samples))
      out << s.piece << ',' << s.t << ',' << s.arc_length << ',' << s.x << ',' << s.y << ',' << s.curvature << '\n';
    profile_text = out.str();
  }
  std::string json_text;
  if (!o.json_out.empty()) {
    std::ostringstream out;
    fair::io::write_json(out, j);
    json_text = out.str();
  }
  fair_curves::write_outputs(text.str(), o.json_out, json_text, {{o.profile_out, profile_text}});
}

void run_metrics(const Metrics_options& o) {
  if (!o.circle.empty()) circle_option(o.circle); // usage error before reading any file
  const File_curve curve = read_curve_file(o.input);
  File_curve other;
  if (!o.hausdorff.empty()) other = read_curve_file(o.hausdorff);
  const File_curve* second = o.hausdorff.empty() ? nullptr : &other;
  if (curve.rational) report(curve.pieces, o, second);
  else report(curve.polynomial(), o, second);
}

} // namespace

void register_metrics_command(CLI::App& app) {
  auto options = std::make_shared<Metrics_options>();
  CLI::App* sub = app.add_subcommand(
      "metrics", "Fairness figures of a curve JSON written by fair-curves: length, bending energy, curvature "
                 "variation, curvature range, certified inflections and curvature extrema");
  sub->add_option("curve", options->input, "the curve file: JSON with \"pieces\" written by fair-curves (conic, cardinal, kappa, ...)")->required();
  sub->add_option("--circle", options->circle, "also the largest deviation from the circle \"cx,cy,r\"");
  sub->add_option("--hausdorff", options->hausdorff, "also the Hausdorff distance to another curve file");
  sub->add_option("--tolerance", options->tolerance,
                  "sampling tolerance of the Hausdorff distance (default 1e-5 of the bounding box diagonal)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--profile", options->profile_out, "write curvature against arc length samples as CSV");
  sub->add_option("--samples", options->samples, "profile samples per piece (default 64)")->check(CLI::Range(1, 100000));
  sub->add_option("-o,--output", options->json_out, "write the figures as JSON ('-' for stdout)");
  sub->callback([options] { run_metrics(*options); });
}
FAIR_CURVES_COMMAND(register_metrics_command)
