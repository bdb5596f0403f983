// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Reading planar point files (CSV or JSON, see doc/io.md) into the points of any CGAL kernel.
//
// Every problem -- a missing or unreadable file, an empty file, a malformed line, a wrong
// number of fields, a bad number, NaN or an infinity, trailing garbage -- throws
// fair::Parse_error naming the file and the 1-based line (line 0: the whole file).

#ifndef FAIR_IO_READ_POINTS_H
#define FAIR_IO_READ_POINTS_H

#include <fair/Errors.h>
#include <fair/internal/common/input_checks.h>
#include <fair/io/internal/text_lines.h>
#include <fair/io/parsing.h>

#include <cctype>
#include <cstddef>
#include <filesystem>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace fair {
namespace io {

/// The contents of a point file: the points, the line each point was read from and, for
/// JSON files, whether the file asks for a closed curve.
template <class Kernel_>
struct Point_file {
  typedef Kernel_ Kernel;
  typedef typename Kernel::Point_2 Point_2;

  std::string file;                 ///< the name used in error messages
  std::vector<Point_2> points;
  std::vector<std::size_t> lines;   ///< 1-based line of each point
  bool closed = false;              ///< JSON "closed" member; false when absent
  bool closed_given = false;        ///< whether the file has a "closed" member
};

namespace internal {

/// A field that starts like a word (a header such as "x" or "lon"), but is not one of the
/// spellings of NaN or infinity, which are bad numbers rather than column names.
inline bool looks_like_column_name(const std::string& field) {
  if (field.empty()) return false;
  const unsigned char c = static_cast<unsigned char>(field[0]);
  if (!(std::isalpha(c) || c == '_' || c == '"')) return false;
  std::string lower;
  for (char ch : field) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return lower.rfind("nan", 0) != 0 && lower.rfind("inf", 0) != 0;
}

template <class Kernel>
typename Kernel::Point_2 make_point(const Parsed_number& x, const Parsed_number& y) {
  typedef typename Kernel::FT FT;
  return typename Kernel::Point_2(to_ft<FT>(x), to_ft<FT>(y));
}

} // namespace internal

/// Parses CSV text: one point "x,y" per line (or "x y"), '#' starts a comment, blank lines
/// are skipped, an optional header line of column names may precede the first point, and
/// whitespace around fields is ignored. `file` names the source in error messages.
template <class Kernel>
Point_file<Kernel> parse_points_csv(const std::string& text, const std::string& file) {
  using namespace internal;
  Point_file<Kernel> out;
  out.file = file;
  bool first_data_line = true;
  for (const Text_line& data : data_lines(text, file)) {
    const std::size_t number = data.number;
    const std::vector<std::string>& fields = data.fields;
    if (first_data_line) {
      first_data_line = false;
      bool header = true;
      for (const std::string& f : fields) header = header && looks_like_column_name(f);
      if (header) {
        if (fields.size() != 2)
          throw Parse_error(file, number, fair::internal::message("header line has ", fields.size(),
                                                  " columns, expected 2 (x,y)"));
        continue;
      }
    }
    if (fields.size() != 2)
      throw Parse_error(file, number,
                        fair::internal::message("expected 2 fields \"x,y\", got ", fields.size(), " in ",
                                                        quoted(data.text)));
    const Parsed_number x = parse_number(fields[0], file, number, "x coordinate");
    const Parsed_number y = parse_number(fields[1], file, number, "y coordinate");
    out.points.push_back(make_point<Kernel>(x, y));
    out.lines.push_back(number);
  }
  if (out.points.empty()) throw Parse_error(file, 0, "no points in the file");
  return out;
}

/// Parses JSON text: either {"points": [[x, y], ...], "closed": bool} (other members are
/// ignored) or a bare array of pairs. A coordinate is a JSON number or a string holding a
/// number or an exact rational "p/q".
template <class Kernel>
Point_file<Kernel> parse_points_json(const std::string& text, const std::string& file) {
  using namespace internal;
  Point_file<Kernel> out;
  out.file = file;
  const Json_value root = parse_json(text, file);
  const Json_value* points = &root;
  if (root.kind == Json_value::OBJECT) {
    points = root.find("points");
    if (!points) throw Parse_error(file, root.line, "the JSON object has no \"points\" member");
    if (const Json_value* closed = root.find("closed")) {
      if (closed->kind != Json_value::BOOLEAN)
        throw Parse_error(file, closed->line,
                          fair::internal::message("\"closed\" must be true or false, got ",
                                  Json_value::kind_name(closed->kind)));
      out.closed = closed->flag;
      out.closed_given = true;
    }
  }
  if (points->kind != Json_value::ARRAY)
    throw Parse_error(file, points->line,
                      fair::internal::message("expected an array of [x, y] pairs, got ",
                              Json_value::kind_name(points->kind)));
  for (std::size_t i = 0; i < points->items.size(); ++i) {
    const Json_value& pair = points->items[i];
    if (pair.kind != Json_value::ARRAY)
      throw Parse_error(file, pair.line, fair::internal::message("point ", i, ": expected an [x, y] pair, got ",
                                                 Json_value::kind_name(pair.kind)));
    if (pair.items.size() != 2)
      throw Parse_error(file, pair.line, fair::internal::message("point ", i, ": expected 2 coordinates, got ",
                                                 pair.items.size()));
    Parsed_number xy[2];
    for (int k = 0; k < 2; ++k) {
      const Json_value& c = pair.items[std::size_t(k)];
      const char* what = k == 0 ? "x coordinate" : "y coordinate";
      if (c.kind != Json_value::NUMBER && c.kind != Json_value::STRING)
        throw Parse_error(file, c.line, fair::internal::message("point ", i, ": ", what, " must be a number, got ",
                                                Json_value::kind_name(c.kind)));
      xy[k] = parse_number(c.text, file, c.line, what);
    }
    out.points.push_back(make_point<Kernel>(xy[0], xy[1]));
    out.lines.push_back(pair.line);
  }
  if (out.points.empty()) throw Parse_error(file, points->line, "no points in the file");
  return out;
}

/// Whether a file is read as JSON: by its extension (.json), otherwise by its first
/// non-blank character ('[' or '{').
inline bool is_json_point_text(const std::string& file, const std::string& text) {
  const std::string ext = std::filesystem::path(file).extension().string();
  if (ext == ".json" || ext == ".JSON") return true;
  if (ext == ".csv" || ext == ".CSV" || ext == ".txt" || ext == ".xy") return false;
  const std::size_t k = text.find_first_not_of(" \t\r\n");
  return k != std::string::npos && (text[k] == '[' || text[k] == '{');
}

/// Reads a point file (CSV or JSON, chosen by is_json_point_text) with its line numbers.
template <class Kernel>
Point_file<Kernel> read_point_file(const std::string& file) {
  const std::string text = read_text_file(file);
  return is_json_point_text(file, text) ? parse_points_json<Kernel>(text, file)
                                        : parse_points_csv<Kernel>(text, file);
}

/// Reads the points of a point file (CSV or JSON).
template <class Kernel>
std::vector<typename Kernel::Point_2> read_points(const std::string& file) {
  return read_point_file<Kernel>(file).points;
}

/// Reads CSV points from a stream; `name` is used in error messages.
template <class Kernel>
Point_file<Kernel> read_points_csv(std::istream& in, const std::string& name) {
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parse_points_csv<Kernel>(buffer.str(), name);
}

/// Reads JSON points from a stream; `name` is used in error messages.
template <class Kernel>
Point_file<Kernel> read_points_json(std::istream& in, const std::string& name) {
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parse_points_json<Kernel>(buffer.str(), name);
}

/// The checks of fair::internal::common::check_interpolation_input, reported against the file: too
/// few points names the file, coinciding consecutive points name the line of the second one
/// (for a closed curve the last and the first point are neighbours too).
template <class Kernel>
void check_point_file(const Point_file<Kernel>& data, std::size_t minimum, bool closed,
                      const char* method) {
  const std::size_t n = data.points.size();
  if (n < minimum)
    throw Parse_error(data.file, 0, fair::internal::message(method, ": needs at least ", minimum,
                                                      " points, the file has ", n));
  const std::size_t pairs = n == 0 ? 0 : (closed ? n : n - 1);
  for (std::size_t i = 0; i < pairs; ++i) {
    const std::size_t j = (i + 1) % n;
    if (data.points[i] == data.points[j]) {
      const std::size_t line = j < data.lines.size() ? data.lines[j] : 0;
      const std::size_t other = i < data.lines.size() ? data.lines[i] : 0;
      throw Parse_error(data.file, line,
                        fair::internal::message(method, ": point ", j, " repeats its neighbour ",
                                          "(line ", other, ") at (",
                                          CGAL::to_double(data.points[j].x()), ", ",
                                          CGAL::to_double(data.points[j].y()), ")"));
    }
  }
  // The shared checks (also finiteness, which the parser already guarantees).
  fair::internal::common::check_interpolation_input(data.points, minimum, closed, method);
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_READ_POINTS_H
