// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Parsing the text of point and curve files, with every error reported at its file and 1-based
// line: strict numbers (decimal, or exact "p/q" for exact kernels) and their conversion to a
// kernel's FT, whole-file reading, and a small JSON reader that keeps the line of every value
// (a general-purpose JSON library does not). fair/io/read_points.h is built on these; so is the
// curve reader of fair-curves metrics. See doc/io.md.

#ifndef FAIR_IO_PARSING_H
#define FAIR_IO_PARSING_H

#include <fair/Errors.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace fair {
namespace io {

/// A parsed coordinate: the nearest double and, for "p/q" input, the exact digits.
struct Parsed_number {
  double value = 0;
  bool rational = false;               ///< written as "p/q"
  std::string numerator, denominator;  ///< digits (sign on the numerator) when rational
};

/// `text` as a finite decimal number: the JSON number grammar, also accepting a leading '+'
/// and a missing integer part (".5"), correctly rounded to the nearest double (locale
/// independent). Throws Parse_error(file, line, ...) starting with `what` and the text, with
/// the reason: empty, NaN, infinite, hexadecimal, overflow, underflow or trailing garbage.
inline double parse_decimal(const std::string& text, const std::string& file, std::size_t line, const char* what);

/// A coordinate: a decimal number (as parse_decimal) or an exact rational "p/q" with integers p
/// and q > 0. For a rational, `value` is the correctly rounded quotient when |p|, |q| < 2^53.
/// Throws Parse_error(file, line, ...) as parse_decimal, also for a zero denominator or a
/// quotient outside the range of double.
inline Parsed_number parse_number(const std::string& text, const std::string& file, std::size_t line,
                                  const char* what);

/// A parsed coordinate as FT: exactly p/q when the number was a rational and FT is an exact
/// field type (CGAL::Gmpq, EPECK's FT), otherwise FT(value). Every kernel sees the same value
/// for a decimal number.
template <class FT>
FT to_ft(const Parsed_number& number);

/// The whole contents of `file`. Throws Parse_error(file, 0, ...) if it is a directory, cannot
/// be opened (the message gives the system's reason) or cannot be read.
inline std::string read_text_file(const std::string& file);

/// One JSON value and the 1-based line on which it starts.
struct Json_value {
  enum Kind { NULL_VALUE, BOOLEAN, NUMBER, STRING, ARRAY, OBJECT };
  Kind kind = NULL_VALUE;
  std::size_t line = 0;
  bool flag = false;                                        ///< BOOLEAN
  std::string text;                                         ///< NUMBER token or STRING contents
  std::vector<Json_value> items;                            ///< ARRAY elements
  std::vector<std::pair<std::string, Json_value>> members;  ///< OBJECT members, in order

  /// The member named `key` of an OBJECT, or nullptr. Linear in the number of members.
  const Json_value* find(const std::string& key) const {
    for (const auto& m : members)
      if (m.first == key) return &m.second;
    return nullptr;
  }
  /// "null", "a boolean", "a number", ... for error messages.
  static const char* kind_name(Kind kind) {
    switch (kind) {
      case NULL_VALUE: return "null";
      case BOOLEAN: return "a boolean";
      case NUMBER: return "a number";
      case STRING: return "a string";
      case ARRAY: return "an array";
      case OBJECT: return "an object";
    }
    return "?";
  }
};

/// `text` parsed as one JSON value (RFC 8259; numbers are checked by parse_decimal, so NaN or
/// an out-of-range number is reported precisely; nesting deeper than 64 levels is refused).
/// `file` names the source in messages. Throws Parse_error at the line of the first problem
/// (line 0 for an empty text). Linear in the size of the text.
inline Json_value parse_json(const std::string& text, const std::string& file);

} // namespace io
} // namespace fair

// The definitions.
#include <fair/io/internal/number_parsing.h>
#include <fair/io/internal/json_lines.h>

#endif // FAIR_IO_PARSING_H
