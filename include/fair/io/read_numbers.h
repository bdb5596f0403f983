// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Reading files of numbers: the per-point tensions of kappa-curves (fair-curves kappa
// --tension) and the per-segment lambdas of optimal curves (fair-curves optimal --lambda-file).
// The same grammar as a point CSV file (fair/io/internal/text_lines.h: '#' comments, blank lines
// skipped, comma- or blank-separated fields) and the same strict numbers (fair::io::parse_number:
// a decimal or an exact "p/q"; NaN, infinities, hexadecimal and trailing garbage refused). Every
// problem throws fair::Parse_error naming the file and the 1-based line (line 0: the whole file,
// e.g. a wrong count). The constraint files of optimal curves are read by fair/io/read_constraints.h
// on the same rows. See doc/io.md.

#ifndef FAIR_IO_READ_NUMBERS_H
#define FAIR_IO_READ_NUMBERS_H

#include <fair/Errors.h>
#include <fair/io/internal/text_lines.h>
#include <fair/io/parsing.h>

#include <cstddef>
#include <string>
#include <vector>

namespace fair {
namespace io {

/// One data line of a number file: its 1-based line and its numbers.
struct Number_row {
  std::size_t line = 0;
  std::vector<Parsed_number> numbers;
  std::vector<std::string> texts;  ///< the fields as written, for messages
};

/// The rows of a number file whose every data line has exactly `fields` numbers; `layout`
/// describes a line for the message of a wrong field count (e.g. "i tx ty"), `what` names a
/// number in the message of a bad one. Throws Parse_error(file, line, ...).
inline std::vector<Number_row> parse_number_rows(const std::string& text, const std::string& file, std::size_t fields,
                                                 const char* layout, const char* what = "number") {
  std::vector<Number_row> out;
  for (const internal::Text_line& l : internal::data_lines(text, file)) {
    if (l.fields.size() != fields)
      throw Parse_error(file, l.number,
                        fair::internal::message("expected '", layout, "' (", fields, fields == 1 ? " number" : " numbers",
                                                " per line), got ", l.fields.size(), " fields in ",
                                                internal::quoted(l.text)));
    Number_row row;
    row.line = l.number;
    row.texts = l.fields;
    for (const std::string& f : l.fields) row.numbers.push_back(parse_number(f, file, l.number, what));
    out.push_back(std::move(row));
  }
  return out;
}

/// Parses a tension file: one tension mu_i > 0 per line, one line per input point (`points`;
/// 0: any count). The tensions of fair::Kappa_curve_options::tension (eq. 16 with tension).
inline std::vector<double> parse_tensions(const std::string& text, const std::string& file, std::size_t points = 0) {
  std::vector<double> out;
  for (const Number_row& row : parse_number_rows(text, file, 1, "mu", "tension")) {
    const double v = row.numbers[0].value;
    if (!(v > 0))
      throw Parse_error(file, row.line, "tension " + internal::quoted(row.texts[0]) + " must be > 0");
    out.push_back(v);
  }
  if (out.empty()) throw Parse_error(file, 0, "no tension in the file");
  if (points != 0 && out.size() != points)
    throw Parse_error(file, 0, fair::internal::message("expected one tension per input point: ", points,
                                                       " lines, got ", out.size()));
  return out;
}

/// Reads a tension file (parse_tensions).
inline std::vector<double> read_tensions(const std::string& file, std::size_t points = 0) {
  return parse_tensions(read_text_file(file), file, points);
}

/// Parses a lambda file: one lambda_i in [0, 1] per line (eq. 10 of the optimal curves, the
/// trade-off between the polygon and the int kappa^2 curve on segment i), exactly `segments`
/// lines (n - 1 for an open curve of n points, n for a closed one). The lambdas of
/// fair::Optimal_curve_options::segment_lambda.
inline std::vector<double> parse_segment_lambdas(const std::string& text, const std::string& file,
                                                 std::size_t segments) {
  std::vector<double> out;
  for (const Number_row& row : parse_number_rows(text, file, 1, "lambda", "lambda")) {
    const double v = row.numbers[0].value;
    if (!(v >= 0 && v <= 1))
      throw Parse_error(file, row.line, "lambda " + internal::quoted(row.texts[0]) + " is not in [0, 1]");
    out.push_back(v);
  }
  if (out.size() != segments)
    throw Parse_error(file, 0, fair::internal::message("expected one lambda per input segment: ", segments,
                                                       " lines, got ", out.size()));
  return out;
}

/// Reads a lambda file (parse_segment_lambdas).
inline std::vector<double> read_segment_lambdas(const std::string& file, std::size_t segments) {
  return parse_segment_lambdas(read_text_file(file), file, segments);
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_READ_NUMBERS_H
