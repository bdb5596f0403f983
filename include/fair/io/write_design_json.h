// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The JSON report of a basic-shape design (doc/basic_shapes.md) and of Proposition 1's convexity
// certificate (fair/Spline_convexity.h): what `fair-curves shapes -o` writes beside the curve and
// what the Python module's `basic_shape_design(...).report` holds, from one place.

#ifndef FAIR_IO_WRITE_DESIGN_JSON_H
#define FAIR_IO_WRITE_DESIGN_JSON_H

#include <fair/Basic_shape_design.h>
#include <fair/Spline_convexity.h>
#include <fair/io/read_design.h>
#include <fair/io/write_json.h>

#include <CGAL/enum.h>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <utility>

namespace fair {
namespace io {

/// "left", "right" or "collinear".
inline const char* orientation_name(CGAL::Orientation o) {
  return o == CGAL::LEFT_TURN ? "left" : (o == CGAL::RIGHT_TURN ? "right" : "collinear");
}

/// Proposition 1 (fair::spline_convexity): the polygon's convexity and the curve's local
/// convexity, with how each piece was decided (interval filter or exactly).
template <class E>
nlohmann::json convexity_to_json(const Spline_convexity_report<E>& c) {
  nlohmann::json j{{"polygon_convex", c.polygon_convex},
                   {"polygon_orientation", orientation_name(c.polygon_orientation)},
                   {"curve_locally_convex", c.curve_locally_convex},
                   {"curve_orientation", orientation_name(c.curve_orientation)},
                   {"inflected_pieces", c.inflected_pieces},
                   {"pieces_by_filter", c.pieces_by_filter},
                   {"pieces_exact", c.pieces_exact},
                   {"proposition_holds", c.proposition_holds()}};
  if (c.polygon_violation != c.npos) j["polygon_violation"] = c.polygon_violation;
  return j;
}

/// The design's report: its file, the merge tolerance and distance, the joins of consecutive
/// shapes, and per shape its type, its parts (piece ranges, the exact ones among them) and its
/// marked points. Throws Precondition_error on a non-finite marked point.
template <class K>
nlohmann::json design_to_json(const Design_file<K>& f, const Basic_shape_design_2<K>& d, bool exact) {
  nlohmann::json joins = nlohmann::json::array(), shapes = nlohmann::json::array();
  for (const Shape_join& j : d.joins)
    joins.push_back({{"before", j.before}, {"after", j.after}, {"inside", j.inside}, {"kind", to_string(j.kind)},
                     {"distance", j.distance}, {"control_point", j.control_point}});
  for (std::size_t s = 0; s < f.shapes.size(); ++s) {
    nlohmann::json parts = nlohmann::json::array(), marks = nlohmann::json::array();
    for (const Shape_span& span : d.spans)
      if (span.shape == s)
        parts.push_back({{"first_piece", span.first_piece}, {"end_piece", span.end_piece},
                         {"first_exact", span.first_exact}, {"end_exact", span.end_exact}});
    for (const auto& p : f.marked_points[s]) marks.push_back(point_to_json(p, "marked point"));
    shapes.push_back({{"type", f.types[s]}, {"parts", std::move(parts)}, {"marked_points", std::move(marks)}});
  }
  return nlohmann::json{{"design", f.file},
                        {"exact", exact},
                        {"merge_tolerance", f.merge_tolerance},
                        {"merge_distance", d.merge_distance},
                        {"joins", std::move(joins)},
                        {"shapes", std::move(shapes)}};
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_WRITE_DESIGN_JSON_H
