// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves shapes: design with basic shapes (Karciauskas-Peters Sec. 6, Fig. 9). Reads a
// design file (doc/basic_shapes.md), merges the shapes into one C2 cubic spline and writes the
// join report, the spline as the library's curve JSON with its "bspline" member, and an SVG of
// the curve, its control polygon, the marked points and the curvature plot, with the
// Proposition 1 report (fair::spline_convexity: convex polygon, locally convex curve). --exact
// computes in EPECK and writes exact rationals as "p/q" strings.

#include "basic_shapes_figures.h"
#include "registry.h"
#include "tool_common.h"

#include <fair/Basic_shape_design.h>
#include <fair/Spline_convexity.h>
#include <fair/io/read_design.h>
#include <fair/io/svg.h>
#include <fair/io/write_design_json.h>
#include <fair/io/write_json.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Shapes_options {
  std::string input, json_out, svg_out;
  bool exact = false;
};

template <class E>
std::string convexity_text(const fair::Spline_convexity_report<E>& c) {
  std::ostringstream out;
  out << "Proposition 1: control polygon " << (c.polygon_convex ? "convex" : "not convex");
  if (c.polygon_violation != c.npos) out << " (first violation at control point " << c.polygon_violation << ")";
  out << ", curve " << (c.curve_locally_convex ? "locally convex" : "not locally convex");
  if (!c.inflected_pieces.empty()) out << " (" << c.inflected_pieces.size() << " inflected pieces)";
  out << "; certified by the interval filter on " << c.pieces_by_filter << " pieces, exactly on " << c.pieces_exact
      << "\n";
  return out.str();
}

template <class K>
std::string report_text(const fair::io::Design_file<K>& f, const fair::Basic_shape_design_2<K>& d, bool exact) {
  using fair_curves::format_number;
  std::ostringstream out;
  out << f.file << ": " << f.shapes.size() << " shapes, " << (f.closed ? "closed" : "open") << ", merge tolerance "
      << format_number(f.merge_tolerance) << " (distance " << format_number(d.merge_distance) << ")\n";
  for (std::size_t s = 0; s < f.shapes.size(); ++s) {
    out << "shape " << s << " (" << f.types[s] << "): " << f.marked_points[s].size() << " marks, pieces";
    for (const fair::Shape_span& span : d.spans)
      if (span.shape == s)
        out << " [" << span.first_piece << ", " << span.end_piece << ") exact on [" << span.first_exact << ", "
            << span.end_exact << ")";
    out << "\n";
  }
  for (const fair::Shape_join& j : d.joins)
    out << "join shape " << j.before << " -> shape " << j.after << (j.inside ? " (inside)" : "") << ": "
        << fair::to_string(j.kind) << ", distance " << format_number(j.distance) << ", control point "
        << j.control_point << "\n";
  out << "spline: " << d.spline.number_of_pieces() << " pieces, " << d.spline.number_of_control_points()
      << " control points, " << (d.spline.is_rational() ? "rational" : "polynomial") << ", "
      << (exact ? "exact (EPECK)" : "double") << "\n";
  return out.str();
}

template <class K>
void run(const Shapes_options& o) {
  using namespace fair_curves;
  const fair::io::Design_file<K> f = fair::io::read_design<K>(o.input);
  const fair::Basic_shape_design_2<K> d = fair::basic_shape_design(f.shapes, f.options());
  // Certified for the written spline's data also without --exact (an exact copy of the doubles).
  const auto convexity = certified_convexity(d.spline);
  std::string json_text, svg_text;
  if (!o.json_out.empty()) {
    std::ostringstream out;
    nlohmann::json extra = fair::io::design_to_json(f, d, o.exact);
    extra["convexity"] = fair::io::convexity_to_json(convexity);
    extra["bspline"] = fair::io::nurbs_to_json(d.nurbs());
    // The design's points are its marked points, shape after shape.
    std::vector<typename K::Point_2> points;
    for (const auto& shape_marks : f.marked_points) points.insert(points.end(), shape_marks.begin(), shape_marks.end());
    fair::io::write_json(out, fair::io::curve_to_json("shapes", f.closed, points, d.spline.pieces(), extra));
    json_text = out.str();
  }
  if (!o.svg_out.empty()) {
    std::vector<fair::io::Xy> marks;
    for (const auto& shape_marks : f.marked_points)
      for (const auto& p : shape_marks) marks.push_back(fair::io::Xy{CGAL::to_double(p.x()), CGAL::to_double(p.y())});
    const Curve_figures figures = design_figures(to_double_spline(d.spline), marks,
                                                 o.input + ": " + std::to_string(f.shapes.size()) +
                                                     " basic shapes, C2 cubic spline");
    svg_text = stack_svg(figures.curve_svg, figures.curvature_svg);
  }
  write_outputs(report_text(f, d, o.exact) + convexity_text(convexity), o.json_out, json_text,
                export_files(d.nurbs(), {{o.svg_out, svg_text}}));
}

} // namespace

void register_shapes_command(CLI::App& app) {
  auto options = std::make_shared<Shapes_options>();
  CLI::App* sub = app.add_subcommand(
      "shapes", "Design with basic shapes (Karciauskas-Peters Sec. 6): the shapes of a design file (segments, "
                "circle arcs, conics, rational cubics, spirals, involutes, clothoids with marked points) merged into one "
                "C2 cubic spline, with the Proposition 1 convexity report");
  sub->add_option("design", options->input, "the design file (JSON, see doc/basic_shapes.md)")->required();
  sub->add_flag("--exact", options->exact, "compute in EPECK and write exact rationals as \"p/q\" strings");
  sub->add_option("-o,--output", options->json_out,
                  "write the spline (pieces and \"bspline\") and the join report as JSON ('-': only JSON on stdout)");
  sub->add_option("--svg", options->svg_out, "draw the curve, its control polygon, the marks and its curvature plot");
  fair_curves::add_export_options(sub);
  sub->callback([options] {
    if (options->exact) run<CGAL::Exact_predicates_exact_constructions_kernel>(*options);
    else run<fair_curves::Kernel>(*options);
  });
}
FAIR_CURVES_COMMAND(register_shapes_command)
