// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Reading the point constraints of optimal curves (fair::Point_constraint, doc/optimal_curves.md)
// from text files: lines "i x y" (TANGENT: the direction of travel; NORMAL: its left normal) or
// "i tx_in ty_in tx_out ty_out" (CORNER), i a 0-based input index. The grammar and the numbers are
// those of every number file (fair/io/read_numbers.h: comma- or blank-separated, '#' comments,
// decimals or exact "p/q"; an index i is plain digits without a sign or leading zero). Every problem throws fair::Parse_error naming the file and the line:
// a wrong field count, a bad number, an index that is not an integer or is out of range, a zero
// direction, and a point constrained twice (also across files: merge_constraint_files).

#ifndef FAIR_IO_READ_CONSTRAINTS_H
#define FAIR_IO_READ_CONSTRAINTS_H

#include <fair/Errors.h>
#include <fair/Optimal_curve_options.h>
#include <fair/io/read_numbers.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace fair {
namespace io {

/// The constraints of one file, each with its line.
struct Constraint_file {
  std::string file;
  std::vector<Point_constraint> constraints;
  std::vector<std::size_t> lines;  ///< 1-based line of each constraint
};

/// Parses constraints of one `kind` for a curve through `points` input points.
inline Constraint_file parse_constraints(const std::string& text, const std::string& file, Point_constraint_kind kind,
                                         std::size_t points) {
  const bool corner = kind == Point_constraint_kind::CORNER;
  const char* layout =
      corner ? "i tx_in ty_in tx_out ty_out" : (kind == Point_constraint_kind::TANGENT ? "i tx ty" : "i nx ny");
  Constraint_file out;
  out.file = file;
  std::vector<std::size_t> seen(points, 0);
  for (const Number_row& row : parse_number_rows(text, file, corner ? 5 : 3, layout)) {
    const double index = row.numbers[0].value;
    const std::string& written = row.texts[0];
    // An index is written as a plain integer, 0 or [1-9][0-9]*: "1.0", "+1", "01", "1e0" or "2/2"
    // are numbers equal to an integer, not indices (one grammar, issue 29 #17).
    const bool plain = !written.empty() && internal::is_integer_text(written, false) &&
                       (written == "0" || written[0] != '0');
    if (!plain || !(index >= 0) || index != std::floor(index))
      throw Parse_error(file, row.line,
                        "the point index " + internal::quoted(written) + " is not an integer >= 0 written in digits");
    if (index >= static_cast<double>(points))
      throw Parse_error(file, row.line, fair::internal::message("point index ", written,
                                                                " is out of range (the input has ", points, " points)"));
    Point_constraint c;
    c.index = static_cast<std::size_t>(index);
    c.kind = kind;
    c.direction = {{row.numbers[1].value, row.numbers[2].value}};
    if (corner) c.outgoing = {{row.numbers[3].value, row.numbers[4].value}};
    const bool zero =
        (c.direction[0] == 0 && c.direction[1] == 0) || (corner && c.outgoing[0] == 0 && c.outgoing[1] == 0);
    if (zero) throw Parse_error(file, row.line, "a direction is the zero vector");
    if (seen[c.index])
      throw Parse_error(file, row.line, fair::internal::message("point ", c.index, " is already constrained (", file,
                                                                ":", seen[c.index], ")"));
    seen[c.index] = row.line;
    out.constraints.push_back(c);
    out.lines.push_back(row.line);
  }
  return out;
}

/// Reads a constraint file (parse_constraints).
inline Constraint_file read_constraints(const std::string& file, Point_constraint_kind kind, std::size_t points) {
  return parse_constraints(read_text_file(file), file, kind, points);
}

/// The constraints of several files, in order, for Optimal_curve_options::constraints. Throws
/// Parse_error at the second of two constraints on the same point, naming the first.
inline std::vector<Point_constraint> merge_constraint_files(const std::vector<Constraint_file>& files) {
  std::vector<Point_constraint> out;
  std::vector<const Constraint_file*> where;
  std::vector<std::size_t> line;
  for (const Constraint_file& f : files)
    for (std::size_t k = 0; k < f.constraints.size(); ++k) {
      const std::size_t i = f.constraints[k].index;
      if (i >= where.size()) where.resize(i + 1, nullptr), line.resize(i + 1, 0);
      if (where[i])
        throw Parse_error(f.file, f.lines[k], fair::internal::message("point ", i, " is already constrained (",
                                                                      where[i]->file, ":", line[i], ")"));
      where[i] = &f;
      line[i] = f.lines[k];
      out.push_back(f.constraints[k]);
    }
  return out;
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_READ_CONSTRAINTS_H
