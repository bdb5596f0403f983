// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves certify: exact certification of a curve file written by the program
// (fair::io::certify_curve_file, include/fair/io/certify_curve.h): one line per claimed property
// ("holds", "holds exactly", or "FAILS" with where and the defect); exit 0 only when every
// claimed property holds, else 4 (certify_failed_exit_code; the lines are still written).

#include "registry.h"
#include "tool_common.h"

#include <fair/io/certify_curve.h>

#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace {

/// Exit code when a claimed property does not hold.
constexpr int certify_failed_exit_code = 4;

struct Certify_options {
  std::string curve, points, tolerance = "0";
};

void run_certify(const Certify_options& o) {
  using fair_curves::format_number;
  const double tolerance = fair_curves::option_number(o.tolerance, "--tolerance");
  if (!(tolerance >= 0)) throw CLI::ValidationError("--tolerance", "expected a number >= 0, got '" + o.tolerance + "'");
  const std::vector<fair::io::Certified_property> properties = fair::io::certify_curve_file(o.curve, o.points, tolerance);
  std::ostringstream report;
  bool all = true;
  for (const fair::io::Certified_property& p : properties) {
    report << o.curve << ": " << p.name << ": ";
    if (!p.holds) report << "FAILS at " << p.detail << " (defect " << format_number(p.defect, 3) << ")";
    else if (p.defect == 0) report << "holds exactly" << (p.detail.empty() ? "" : " (" + p.detail + ")");
    else report << "holds to " << format_number(p.defect, 3) << " <= tolerance " << format_number(tolerance, 3)
                << (p.detail.empty() ? "" : " (" + p.detail + ")");
    report << "\n";
    all = all && p.holds;
  }
  std::cout << report.str();
  if (!all) throw fair_curves::Exit_code{certify_failed_exit_code};
}

} // namespace

void register_certify_command(CLI::App& app) {
  auto options = std::make_shared<Certify_options>();
  CLI::App* sub = app.add_subcommand(
      "certify", "Certify a curve file exactly (numbers read exactly): C0/G1/|kappa| at the joins, interpolation of "
                 "--points, the kappa-curve's curvature maxima, Proposition 1 convexity; exit 0 when all hold");
  sub->add_option("curve", options->curve, "the curve JSON (written with -o by a curve command)")->required();
  sub->add_option("--points", options->points, "the points the curve should interpolate (.csv, .txt or .json)");
  sub->add_option("--tolerance", options->tolerance,
                  "largest relative defect accepted for a property that does not hold exactly (default 0: exactly)");
  sub->callback([options] { run_certify(*options); });
}
FAIR_CURVES_COMMAND(register_certify_command)
