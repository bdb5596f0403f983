// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves cardinal: the Cardinal spline through a point file, with the curvature-variation-
// minimising parameter and auxiliary points of J. Li (eqs. 18-20; doc/cardinal_splines.md), or a
// given parameter. Writes the curve as cubic Bezier pieces (JSON, SVG, curvature plot).

#include "registry.h"
#include "tool_common.h"

#include <fair/Cardinal_spline_2.h>
#include <fair/Fairness_metrics.h>
#include <fair/io/enum_names.h>
#include <fair/io/read_points.h>
#include <fair/io/svg.h>
#include <fair/io/write_json.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Simple_cartesian.h>

#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace {

struct Cardinal_options {
  std::string input, alpha = "optimal", json_out, svg_out, plot_out, aux_start, aux_end;
  bool closed = false, exact = false;
};

/// Exit code of an optimal alpha that eq. 18 does not have (status no_optimum: the curve is
/// the Catmull-Rom spline; outputs written).
constexpr int no_optimum_exit_code = 3;

// What `cardinal` computed, for the JSON, the report and the figures.
template <class K>
struct Cardinal_result {
  fair::io::Point_file<K> data;
  bool closed = false, explicit_aux = false;
  std::optional<fair::Cardinal_spline_2<K>> curve;
  fair::Quadrature_estimate energy_parameter, energy_arc_length;
};

/// Cap on the decimal digits of the common denominator of the input coordinates with --exact:
/// the sums of eq. 18 and the pieces are rationals over (a power of) that denominator, so GMP's
/// work grows with its size (issue 29 #22: 199 points with 50-digit p/q, a common denominator of
/// some 10^4 digits, took 11.6 s). Listed with every cap in doc/hardening.md.
constexpr std::size_t max_exact_denominator_digits = 2000;

/// Refuses, with --exact, input whose coordinates' common denominator (the lcm of all
/// denominators, doubles being dyadic) has more than max_exact_denominator_digits digits.
template <class Points>
void check_exact_input_size(const Points& points, const std::string& file) {
  CGAL::Gmpz lcm(1);
  for (const auto& p : points)
    for (const CGAL::Gmpq* c : {&p.x(), &p.y()}) {
      mpz_lcm(lcm.mpz(), lcm.mpz(), mpq_denref(c->mpq()));
      const std::size_t digits = mpz_sizeinbase(lcm.mpz(), 10);
      if (digits > max_exact_denominator_digits)
        throw fair::Invalid_input_error(fair::internal::message(
            file, ": with --exact the common denominator of the coordinates has more than ",
            max_exact_denominator_digits, " digits (", digits, " after ", &p - &points[0] + 1,
            " points): exact arithmetic on it would take minutes; round the p/q coordinates or drop --exact"));
    }
}

/// The double of an exact (or double) value the report prints: refused when it is beyond the
/// double range, as the double computation refuses it (issue 29 #16), never printed as inf.
template <class FT>
double reported_double(const FT& v, const char* what) {
  const double d = CGAL::to_double(v);
  if (!std::isfinite(d))
    throw fair::Invalid_input_error(fair::internal::message(
        "cardinal: ", what, " is beyond the double range: the coordinates are too large"));
  return d;
}

// Reads and checks the input, then builds the spline (fair::Cardinal_spline_2): the optimum of
// eq. 18 with the auxiliary points of eqs. 19-20, or the given alpha with the given auxiliary
// points or those optimal for it (eqs. 16-17).
template <class K>
Cardinal_result<K> compute_cardinal(const Cardinal_options& o) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 P;
  Cardinal_result<K> r;
  r.data = fair::io::read_point_file<K>(o.input);
  r.closed = o.closed || r.data.closed;
  const bool optimal = o.alpha == "optimal";
  r.explicit_aux = !o.aux_start.empty() || !o.aux_end.empty();
  if (r.closed && r.explicit_aux)
    throw CLI::ValidationError("--aux-start/--aux-end", "a closed curve has no auxiliary points");
  if (r.explicit_aux && (o.aux_start.empty() || o.aux_end.empty()))
    throw CLI::ValidationError("--aux-start/--aux-end", "give both auxiliary points or neither");
  const std::size_t minimum = optimal ? (r.closed ? 3 : 4) : (r.closed ? 3 : (r.explicit_aux ? 2 : 3));
  fair::io::check_point_file(r.data, minimum, r.closed, "fair-curves cardinal");
  if constexpr (std::is_same<FT, CGAL::Gmpq>::value) check_exact_input_size(r.data.points, o.input);

  fair::Cardinal_spline_options options;
  options.closed = r.closed;
  if (r.explicit_aux) {
    const fair_curves::Point_2 a = fair_curves::option_point(o.aux_start, "--aux-start");
    const fair_curves::Point_2 b = fair_curves::option_point(o.aux_end, "--aux-end");
    r.curve.emplace(r.data.points, FT(fair_curves::option_number(o.alpha, "--alpha")), P(a.x(), a.y()), P(b.x(), b.y()),
                    options);
  } else {
    if (!optimal) options.alpha = fair_curves::option_number(o.alpha, "--alpha");
    r.curve.emplace(r.data.points, options);
  }
  reported_double(r.curve->approximate_energy(), "the energy of eq. 10");
  reported_double(r.curve->alpha(), "alpha");
  if (!r.closed)
    for (const P& a : {r.curve->aux_start(), r.curve->aux_end()}) {
      reported_double(a.x(), "an auxiliary point");
      reported_double(a.y(), "an auxiliary point");
    }
  r.energy_parameter = fair::curvature_variation_energy(r.curve->pieces(), fair::Energy_measure::PARAMETER);
  r.energy_arc_length = fair::curvature_variation_energy(r.curve->pieces(), fair::Energy_measure::ARC_LENGTH);
  return r;
}

// The curve JSON: the pieces, the status and the report (alpha, auxiliary points, eq. 10), and
// the true curvature variation of eq. 5.
template <class K>
nlohmann::json cardinal_json(const Cardinal_result<K>& r) {
  const nlohmann::json extra{{"energy_true", r.energy_parameter.value},
                             {"energy_true_error", r.energy_parameter.error_bound},
                             {"energy_true_arc_length", r.energy_arc_length.value}};
  return fair::io::family_to_json(*r.curve, "cardinal", extra);
}

// The text report (stdout unless the JSON goes there).
template <class K>
std::string cardinal_report(const Cardinal_result<K>& r, const Cardinal_options& o) {
  using fair_curves::format_number;
  const fair::Cardinal_spline_2<K>& c = *r.curve;
  std::ostringstream report;
  report << "cardinal: " << r.data.points.size() << " points, " << (r.closed ? "closed" : "open") << ", "
         << c.number_of_pieces() << " cubic pieces, " << c.status() << "\n";
  const char* why = c.status() == fair::Cardinal_spline_status::OPTIMAL
                        ? " (optimal, eq. 18)"
                        : (c.status() == fair::Cardinal_spline_status::GIVEN_ALPHA
                               ? " (given)"
                               : " (eq. 18 has no positive optimum: Catmull-Rom)");
  report << "alpha = " << format_number(CGAL::to_double(c.alpha()), 10)
         << (o.exact ? " = " + fair::io::number_text(c.alpha()) : std::string()) << why << "\n";
  if (!r.closed) {
    report << "aux_start = (" << format_number(CGAL::to_double(c.aux_start().x()), 10) << ", "
           << format_number(CGAL::to_double(c.aux_start().y()), 10) << ")"
           << (r.explicit_aux ? " (given)" : " (eq. 19)") << "\n";
    report << "aux_end = (" << format_number(CGAL::to_double(c.aux_end().x()), 10) << ", "
           << format_number(CGAL::to_double(c.aux_end().y()), 10) << ")"
           << (r.explicit_aux ? " (given)" : " (eq. 20)") << "\n";
  }
  report << "energy_approx (eq. 10) = " << format_number(CGAL::to_double(c.approximate_energy()), 10) << "\n";
  report << "energy_true (eq. 5, int (dk/dt)^2 dt) = " << format_number(r.energy_parameter.value, 10)
         << " (error estimate " << format_number(r.energy_parameter.error_bound, 2) << ")\n";
  report << "energy_true_arc_length (int (dk/ds)^2 ds) = " << format_number(r.energy_arc_length.value, 10) << "\n";
  return report.str();
}

template <class K>
void run_cardinal_in(const Cardinal_options& o) {
  const Cardinal_result<K> r = compute_cardinal<K>(o);
  const nlohmann::json out = cardinal_json(r);
  std::string json_text, svg_text, plot_text;
  if (!o.json_out.empty()) {
    std::ostringstream s;
    fair::io::write_json(s, out);
    json_text = s.str();
  }
  if (!o.svg_out.empty() || !o.plot_out.empty()) {
    fair_curves::Curve_case c;
    c.title = o.input + ": Cardinal spline, alpha = " + fair_curves::format_number(CGAL::to_double(r.curve->alpha()), 6);
    c.title_in_figure = true;
    c.input_points = fair::io::to_xy(r.data.points);
    fair_curves::Curve_figures f = fair_curves::make_curve_figures(r.curve->pieces(), c);
    svg_text = std::move(f.curve_svg);
    plot_text = std::move(f.curvature_svg);
  }
  fair_curves::write_outputs(cardinal_report(r, o), o.json_out, json_text,
                             fair_curves::export_files(r.curve->nurbs(), {{o.svg_out, svg_text}, {o.plot_out, plot_text}}));
  if (r.curve->status() == fair::Cardinal_spline_status::NO_OPTIMUM) {
    std::cerr << "fair-curves cardinal: " << o.input
              << ": eq. 18 has no positive optimum, the curve is Catmull-Rom (alpha = 1/2; outputs written; exit code "
              << no_optimum_exit_code << ")\n";
    throw fair_curves::Exit_code{no_optimum_exit_code};
  }
}

void run_cardinal(const Cardinal_options& o) {
  // Usage errors before any work: --alpha is 'optimal' or a finite value > 0 (the domain of
  // Cardinal_spline_2: alpha <= 0 collapses or reverses the tangents).
  if (o.alpha != "optimal" && !(fair_curves::option_number(o.alpha, "--alpha") > 0))
    throw CLI::ValidationError("--alpha", "expected 'optimal' or a value > 0, got '" + o.alpha + "'");
  if (o.exact) run_cardinal_in<CGAL::Simple_cartesian<CGAL::Gmpq>>(o);
  else run_cardinal_in<fair_curves::Kernel>(o);
}

} // namespace

void register_cardinal_command(CLI::App& app) {
  auto options = std::make_shared<Cardinal_options>();
  CLI::App* sub = app.add_subcommand(
      "cardinal", "Cardinal spline through a point file, with the curvature-variation-minimising parameter and "
                  "auxiliary points of Li (eqs. 18-20), or a given parameter alpha = (1 - tension)/2");
  sub->add_option("input", options->input, "the point file (.csv, .txt or .json)")->required();
  sub->add_flag("--closed", options->closed, "closed (periodic) curve; no auxiliary points");
  sub->add_option("--alpha", options->alpha,
                  "'optimal' (default, eq. 18 / its closed analogue) or a value > 0 (1/2: Catmull-Rom); with a "
                  "value and no --aux-*, the auxiliary points are the optimal ones for it (eqs. 19-20)");
  sub->add_option("--aux-start", options->aux_start, "auxiliary point p_{-1} \"x,y\" (open curves, with --aux-end)");
  sub->add_option("--aux-end", options->aux_end, "auxiliary point p_{n+1} \"x,y\" (open curves, with --aux-start)");
  sub->add_flag("--exact", options->exact,
                "compute in exact rational arithmetic (the input doubles / p/q values exactly); the JSON writes "
                "the numbers that are not doubles as \"p/q\" strings (report.alpha, report.energy, ...)");
  sub->add_option("-o,--output", options->json_out, "write the curve as JSON ('-' for stdout)");
  sub->add_option("--svg", options->svg_out, "draw the curve with its curvature comb");
  sub->add_option("--plot", options->plot_out, "plot the curvature against arc length");
  fair_curves::add_export_options(sub);
  sub->callback([options] { run_cardinal(*options); });
}
FAIR_CURVES_COMMAND(register_cardinal_command)
