// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// What `fair-curves kappa` makes of its options and writes for a kappa-curve: the curve options
// of the command line, the curve JSON of -o and the one-line report. Shared by the kappa command
// and the kappa sessions of `fair-curves serve` (kappa_session.h, defined in kappa_command.cpp), so
// that a curve solved (or re-solved warm) inside the server is written byte for byte as the
// command writes it.

#ifndef FAIR_CURVES_KAPPA_OUTPUT_H
#define FAIR_CURVES_KAPPA_OUTPUT_H

#include "kappa_session.h"
#include "tool_common.h"

#include <fair/Kappa_curve_2.h>
#include <fair/io/enum_names.h>
#include <fair/io/read_points.h>
#include <fair/io/write_json.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace fair_curves {
namespace kappa {

/// Fewest points of a kappa-curve (Kappa_curve_2: one interior point of an open curve, a
/// triangle for a closed one), checked here to name the file in the message.
constexpr std::size_t minimum_points = 3;
/// Exit code of an unsolved solve (outputs written, "status": "unsolved"), unless --allow-unsolved.
constexpr int unsolved_exit_code = 3;

/// The curve options that the command-line options ask for, before the point file is read
/// (CLI::ValidationError for a bad --weights or --clamp, or one that does not apply).
inline fair::Kappa_curve_options curve_options(const Kappa_command_options& o) {
  using namespace fair_curves;
  fair::Kappa_curve_options options;
  // "1" and "auto" are the spellings of fair::io (enum_names.h); anything else must be a weight.
  if (!fair::io::try_parse_spelling(o.weights, options.weights) || options.weights == fair::Kappa_weights::FIXED) {
    const double w = option_number(o.weights, "--weights");
    if (!(w > 0)) throw CLI::ValidationError("--weights", "expected auto, 1 or a weight > 0, got '" + o.weights + "'");
    options.weights = fair::Kappa_weights::FIXED;
  }
  if (!o.tension_file.empty() && options.weights != fair::Kappa_weights::AUTOMATIC)
    throw CLI::ValidationError("--tension", "tension applies to --weights auto only");
  if (o.clamp_given) {
    if (options.weights != fair::Kappa_weights::AUTOMATIC)
      throw CLI::ValidationError("--clamp", "the weight clamp applies to --weights auto only");
    // option_number rejects NaN, inf and text that is not a number; the clamp of eq. 16 must
    // moreover be > 0 (eq. 15 alone gives weights -> 0 as a piece degenerates, Sec. 4.4.1).
    options.weight_clamp = option_number(o.clamp, "--clamp");
    if (!(options.weight_clamp > 0))
      throw CLI::ValidationError("--clamp", "expected a weight clamp > 0, got '" + o.clamp + "'");
  }
  if (!o.max_iterations.empty()) {
    const double cap = option_number(o.max_iterations, "--max-iterations");
    if (!(cap >= 0) || cap != std::floor(cap) || cap > 1e9)
      throw CLI::ValidationError("--max-iterations", "expected an integer >= 0, got '" + o.max_iterations + "'");
    options.max_iterations = static_cast<std::size_t>(cap);
  }
  return options;
}

/// The curve JSON of -o (fair::io::curve_to_json): the pieces with each piece's input point and
/// its parameter t beside them, the weights asked for, the status and the solve report.
inline std::string curve_json(const Kappa_command_options& o, const fair::Kappa_curve_2<fair_curves::Kernel>& curve) {
  const fair::Kappa_curve_options& options = curve.options();
  std::vector<nlohmann::json> per_piece;
  for (std::size_t j = 0; j < curve.number_of_pieces(); ++j)
    per_piece.push_back({{"point", curve.point_index(j)}, {"t", curve.t(j)}});
  nlohmann::json extra{{"weights", fair::io::spelling(options.weights)}};
  if (options.weights == fair::Kappa_weights::FIXED) extra["fixed_weight"] = fair_curves::option_number(o.weights, "--weights");
  if (options.weights == fair::Kappa_weights::AUTOMATIC) extra["weight_clamp"] = options.weight_clamp;
  std::ostringstream out;
  fair::io::write_json(out, fair::io::family_to_json(curve, "kappa", extra, per_piece));
  return out.str();
}

/// " point 1 7" or " points 1 7" for the indices `points`.
inline std::string point_list(const std::vector<std::size_t>& points) {
  std::string s = points.size() == 1 ? " point" : " points";
  for (const std::size_t i : points) s += " " + std::to_string(i);
  return s;
}

/// The line of an unsolved outcome, by its reason (fair::Kappa_curve_unsolved_reason):
/// beyond the density limit, plainly that no kappa-curve exists for the data, how many points are
/// beyond the limit (the first few listed) and the commands made for dense samples; otherwise how
/// far (the residual) and where (the worst points), and the points at a curvature minimum.
inline std::string unsolved_line(const fair::Kappa_curve_2<fair_curves::Kernel>& curve) {
  using namespace fair_curves;
  const fair::Kappa_curve_report& r = curve.report();
  std::ostringstream line;
  line << "unsolved: ";
  if (r.reason == fair::Kappa_curve_unsolved_reason::BEYOND_DENSITY_LIMIT) {
    // Thousands of points on dense data: the count and the first few (all of them in the JSON).
    const std::vector<std::size_t>& d = r.points_beyond_density_limit;
    const std::size_t shown = std::min<std::size_t>(d.size(), 8);
    line << "no kappa-curve exists for this data: " << d.size() << " of " << curve.points().size()
         << (d.size() == 1 ? " points is" : " points are")
         << " beyond the density limit (kappa-curves need sparse points; doc/kappa_existence.md, Sec. 7):"
         << point_list({d.begin(), d.begin() + static_cast<std::ptrdiff_t>(shown)}) << (shown < d.size() ? " ..." : "")
         << "; fair-curves csr and fair-curves optimal are made for dense samples";
    return line.str();
  }
  if (!(r.residual <= curve.options().tolerance)) {  // NaN included
    line << "residual " << format_number(r.residual, 3) << " > tolerance " << format_number(curve.options().tolerance)
         << ", worst";
    for (const fair::Kappa_point_residual& p : r.worst_points)
      line << " " << p.point << " (" << format_number(p.residual, 3) << ")";
    if (!r.points_at_minima.empty()) line << "; ";
  }
  if (!r.points_at_minima.empty())
    line << "at a curvature minimum, not a maximum:" << point_list(r.points_at_minima);
  return line.str();
}

/// The report on stdout: one line on the solve and its outcome (interior, on joins, unsolved;
/// the points on joins and at minima by 0-based input index).
inline std::string summary(const Kappa_command_options& o, const fair::Kappa_curve_2<fair_curves::Kernel>& curve) {
  using namespace fair_curves;
  const fair::Kappa_curve_options& options = curve.options();
  const fair::Kappa_curve_report& r = curve.report();
  std::ostringstream report;
  report << o.input << ": " << curve.number_of_pieces() << " pieces, " << (options.closed ? "closed" : "open")
         << ", weights " << o.weights
         << (options.weights == fair::Kappa_weights::AUTOMATIC ? " (clamp " + format_number(options.weight_clamp) + ")" : "")
         << ", " << r.refinement_passes << " passes and " << r.iterations << " iterations, residual "
         << format_number(r.residual, 3) << ", energy " << format_number(r.energy(), 3) << "; ";
  switch (r.status) {
    case fair::Kappa_curve_status::INTERIOR: report << "interior: every point at a curvature maximum of its piece"; break;
    case fair::Kappa_curve_status::ON_JOINS:
      // No interior solution: the box-constrained one (doc/kappa_existence.md).
      report << "on joins:" << point_list(r.points_on_joins)
             << " on a join (t or lambda at 0 or 1), not at a curvature maximum; the rest interior";
      break;
    case fair::Kappa_curve_status::UNSOLVED: report << unsolved_line(curve); break;
  }
  report << "\n";
  return report.str();
}

/// The options of the solve of `data`, as the command makes them: `options`, those of the command
/// line (curve_options, called first so that a usage error comes before a data error), closed by the option or by the file, the point checks of the command (too few
/// points, coinciding neighbours: fair::Parse_error naming the file), the fixed weights, and the
/// tensions that `read_tensions(points)` returns when --tension is given (the command reads its
/// file; fair-curves serve parses the rows of its request).
template <class Read_tensions>
fair::Kappa_curve_options solve_options(const Kappa_command_options& o, fair::Kappa_curve_options options,
                                        const fair::io::Point_file<Kernel>& data, Read_tensions read_tensions) {
  options.closed = o.closed || data.closed;
  fair::io::check_point_file(data, minimum_points, options.closed, "fair-curves kappa");
  if (options.weights == fair::Kappa_weights::FIXED)
    options.fixed_weights.assign(data.points.size(), option_number(o.weights, "--weights"));
  if (!o.tension_file.empty()) options.tension = read_tensions(data.points.size());
  return options;
}

} // namespace kappa
} // namespace fair_curves

#endif // FAIR_CURVES_KAPPA_OUTPUT_H
