// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The line grammar shared by every text data file of fair/io (point CSV files, tension, lambda
// and constraint files): lines split at '\n', '#' starts a comment, blank lines are skipped,
// fields are separated by commas or, on a line without a comma, by blanks, whitespace around a
// field is ignored, and a control byte (NUL, ...) is refused as "not a text file". Every field
// that should be a number goes through the one strict parser, fair::io::parse_number. A UTF-8
// byte-order mark at the start is refused by name.

#ifndef FAIR_IO_INTERNAL_TEXT_LINES_H
#define FAIR_IO_INTERNAL_TEXT_LINES_H

#include <fair/Errors.h>
#include <fair/io/parsing.h>

#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace fair {
namespace io {
namespace internal {

inline std::string trim(const std::string& s) {
  const char* space = " \t\r\f\v";
  const std::size_t b = s.find_first_not_of(space);
  if (b == std::string::npos) return std::string();
  const std::size_t e = s.find_last_not_of(space);
  return s.substr(b, e - b + 1);
}

/// The fields of a (comment-free, trimmed) line: comma-separated when it has a comma, otherwise
/// blank-separated ("x y", as many tools write them).
inline std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  if (line.find(',') != std::string::npos) {
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = line.find(',', start);
      fields.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  } else {
    std::istringstream in(line);
    std::string f;
    while (in >> f) fields.push_back(f);
  }
  return fields;
}

/// Rejects bytes that cannot appear in a text data file (NUL and other control characters).
inline void check_text_line(const std::string& line, const std::string& file, std::size_t number) {
  for (std::size_t k = 0; k < line.size(); ++k) {
    const unsigned char c = static_cast<unsigned char>(line[k]);
    if (c < 0x20 && c != '\t' && c != '\r' && c != '\f' && c != '\v') {
      const char* digits = "0123456789abcdef";
      const std::string hex = {'0', 'x', digits[c >> 4], digits[c & 15]};
      throw Parse_error(file, number,
                        fair::internal::message("unreadable line: control byte ", hex, " at column ", k + 1,
                                                " (is this a text file?)"));
    }
  }
}

/// One data line of a text file: its 1-based number and its fields.
struct Text_line {
  std::size_t number = 0;
  std::string text;  ///< the line without its comment, trimmed
  std::vector<std::string> fields;
};

/// The data lines of `text` (comments and blank lines dropped), each split into fields.
/// Parse_error(file, line) on a control byte. Linear in the size of the text.
inline std::vector<Text_line> data_lines(const std::string& text, const std::string& file) {
  std::vector<Text_line> out;
  if (has_byte_order_mark(text)) throw Parse_error(file, 1, byte_order_mark_message);
  std::size_t start = 0, number = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    start = end + 1;
    ++number;
    check_text_line(line, file, number);
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    line = trim(line);
    if (line.empty()) continue;
    out.push_back(Text_line{number, line, split_fields(line)});
  }
  return out;
}

} // namespace internal
} // namespace io
} // namespace fair

#endif // FAIR_IO_INTERNAL_TEXT_LINES_H
