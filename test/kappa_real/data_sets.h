// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The real data sets of test_kappa_real as point sets (origin and licence of every file:
// test/data/real/SOURCES.md; what is asserted: doc/real_data.md):
//  - quickdraw: the strokes of hand-drawn Quick, Draw! sketches (quickdraw_angel.json, parsed
//    here): open, or closed when the stroke returns to within 5 % of its size of its start;
//  - feather: the SVG <polyline> (open) and <polygon> (closed) elements of the Feather icons;
//  - coastlines: digitised coastlines of Natural Earth (LineStrings in longitude, latitude),
//    closed where the line returns to its start (islands), open otherwise;
//  - glyphs: TrueType contours of DejaVu glyphs (glyph_outlines.h), closed.
// Strokes with fewer than 3 points are skipped (no kappa-curve); everything else is kept, also
// sets the library must reject (all points collinear): the test asserts the typed error there.

#ifndef FAIR_TEST_KAPPA_REAL_DATA_SETS_H
#define FAIR_TEST_KAPPA_REAL_DATA_SETS_H

#include "glyph_outlines.h"

#include <CGAL/Kernel/global_functions_2.h>
#include <CGAL/enum.h>

#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace kappa_real {

struct Point_set {
  std::string data_set;   ///< "quickdraw", "feather", "glyphs", "glyphs-dense"
  std::string name;       ///< where in the data set
  std::vector<Xy> points;
  bool closed = false;
};

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("read_text: cannot open " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A JSON value made only of arrays and numbers (the "drawing" member of Quick, Draw!).
struct Json_array {
  bool is_number = false;
  double number = 0;
  std::vector<Json_array> items;
};

inline void skip_blanks(const std::string& s, std::size_t& i) {
  while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
}

inline Json_array parse_json_array(const std::string& s, std::size_t& i) {
  skip_blanks(s, i);
  Json_array v;
  if (i < s.size() && s[i] == '[') {
    ++i;
    skip_blanks(s, i);
    if (i < s.size() && s[i] == ']') { ++i; return v; }
    for (;;) {
      v.items.push_back(parse_json_array(s, i));
      skip_blanks(s, i);
      if (i >= s.size()) throw std::runtime_error("parse_json_array: unterminated array");
      if (s[i] == ']') { ++i; return v; }
      if (s[i] != ',') throw std::runtime_error("parse_json_array: expected ',' at offset " + std::to_string(i));
      ++i;
    }
  }
  const char* begin = s.c_str() + i;
  char* end = nullptr;
  v.number = std::strtod(begin, &end);
  if (end == begin) throw std::runtime_error("parse_json_array: expected a number at offset " + std::to_string(i));
  v.is_number = true;
  i += static_cast<std::size_t>(end - begin);
  return v;
}

/// A stroke is closed when its end is within this fraction of its bounding-box diagonal of its
/// start (a hand-drawn closed loop); then an exactly repeated start point is dropped.
constexpr double closing_gap = 0.05;

inline double diagonal(const std::vector<Xy>& p) {
  double x0 = p[0].x, x1 = p[0].x, y0 = p[0].y, y1 = p[0].y;
  for (const Xy& q : p) { x0 = std::min(x0, q.x); x1 = std::max(x1, q.x); y0 = std::min(y0, q.y); y1 = std::max(y1, q.y); }
  return std::hypot(x1 - x0, y1 - y0);
}

/// Open point sets with consecutive repeats removed; closed when the stroke closes.
inline Point_set stroke_set(std::string data_set, std::string name, std::vector<Xy> raw, bool closed_hint) {
  std::vector<Xy> p;
  for (const Xy& q : raw)
    if (p.empty() || !(p.back() == q)) p.push_back(q);
  Point_set s;
  s.data_set = std::move(data_set);
  s.name = std::move(name);
  bool closed = closed_hint;
  if (p.size() >= 4 && std::hypot(p.back().x - p.front().x, p.back().y - p.front().y) <= closing_gap * diagonal(p)) closed = true;
  if (closed) p = without_repeats_cyclic(p);
  s.points = std::move(p);
  s.closed = closed;
  return s;
}

/// The strokes of every drawing of a Quick, Draw! simplified file (one JSON array of
/// drawings, or one drawing per line): members "key_id" and "drawing".
inline std::vector<Point_set> quickdraw_strokes(const std::string& path) {
  const std::string text = read_text(path);
  std::vector<Point_set> out;
  std::size_t at = 0;
  for (;;) {
    const std::size_t key = text.find("\"key_id\":\"", at);
    if (key == std::string::npos) break;
    const std::size_t key_begin = key + 10;
    const std::string id = text.substr(key_begin, text.find('"', key_begin) - key_begin);
    std::size_t i = text.find("\"drawing\":", key_begin);
    if (i == std::string::npos) throw std::runtime_error("quickdraw_strokes: drawing " + id + " has no \"drawing\"");
    i += 10;
    const Json_array drawing = parse_json_array(text, i);
    for (std::size_t s = 0; s < drawing.items.size(); ++s) {
      const Json_array& stroke = drawing.items[s];
      if (stroke.items.size() < 2 || stroke.items[0].items.size() != stroke.items[1].items.size())
        throw std::runtime_error("quickdraw_strokes: drawing " + id + " stroke " + std::to_string(s) + " malformed");
      std::vector<Xy> p;
      for (std::size_t k = 0; k < stroke.items[0].items.size(); ++k)
        p.push_back(Xy{stroke.items[0].items[k].number, -stroke.items[1].items[k].number});  // y down in the data
      Point_set ps = stroke_set("quickdraw", "drawing " + id + " stroke " + std::to_string(s), std::move(p), false);
      if (ps.points.size() >= 3) out.push_back(std::move(ps));
    }
    at = i;
  }
  return out;
}

/// The LineString features of a GeoJSON file with one Feature per line (member "coordinates",
/// [longitude, latitude] pairs, used as planar x, y).
inline std::vector<Point_set> geojson_lines(const std::string& path, const std::string& data_set) {
  const std::string text = read_text(path);
  std::vector<Point_set> out;
  std::size_t at = 0;
  for (std::size_t feature = 0;; ++feature) {
    std::size_t i = text.find("\"coordinates\":", at);
    if (i == std::string::npos) break;
    i += 14;
    const Json_array line = parse_json_array(text, i);
    std::vector<Xy> p;
    for (const Json_array& xy : line.items) {
      if (xy.items.size() < 2) throw std::runtime_error("geojson_lines: feature " + std::to_string(feature) + " malformed");
      p.push_back(Xy{xy.items[0].number, xy.items[1].number});
    }
    Point_set ps = stroke_set(data_set, "feature " + std::to_string(feature), std::move(p), false);
    if (ps.points.size() >= 3) out.push_back(std::move(ps));
    at = i;
  }
  return out;
}

/// The <polyline points="..."> (open) and <polygon points="..."> (closed) lines of
/// feather_polylines.txt ('#' lines are comments).
inline std::vector<Point_set> feather_polylines(const std::string& path) {
  std::istringstream in(read_text(path));
  std::vector<Point_set> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t space = line.find(' ');
    const bool polygon = line.find("<polygon") != std::string::npos;
    const std::size_t q = line.find("points=\"");
    if (space == std::string::npos || q == std::string::npos)
      throw std::runtime_error("feather_polylines: malformed line: " + line);
    std::string numbers = line.substr(q + 8, line.find('"', q + 8) - (q + 8));
    for (char& c : numbers) if (c == ',') c = ' ';
    std::istringstream ns(numbers);
    std::vector<Xy> p;
    double x, y;
    while (ns >> x >> y) p.push_back(Xy{x, -y});
    Point_set ps = stroke_set("feather", line.substr(0, space) + (polygon ? " polygon" : " polyline"), std::move(p), polygon);
    if (ps.points.size() >= 3) out.push_back(std::move(ps));
  }
  return out;
}

/// The points of a set in a CGAL kernel.
template <class Point>
std::vector<Point> to_points(const std::vector<Xy>& p) {
  std::vector<Point> q;
  for (const Xy& xy : p) q.emplace_back(xy.x, xy.y);
  return q;
}

/// Whether every point lies on the line through the first two (exact predicate of the kernel).
template <class Point>
bool all_collinear(const std::vector<Point>& q) {
  for (std::size_t i = 2; i < q.size(); ++i)
    if (CGAL::orientation(q[0], q[1], q[i]) != CGAL::COLLINEAR) return false;
  return true;
}

} // namespace kappa_real

#endif // FAIR_TEST_KAPPA_REAL_DATA_SETS_H
