// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// Reading the curve JSON that fair::io::curve_to_json writes (every command of fair-curves
// writes it; doc/io.md): an object with a nonempty "pieces" array, each piece
// {"degree": n, "control_points": [[x, y], ...], "weights": [w_0, ..., w_n]?} (other members of
// the document and of a piece, such as the kappa-curve's "point" and "t", are ignored), plus an
// optional "closed" and "method". Coordinates and weights are JSON numbers (the nearest double)
// or exact "p/q" strings (exact in an exact kernel), so that the metrics of an exact kernel are
// certified for exactly the curve in the file. Every problem throws fair::Parse_error naming
// the file, the line and the piece.

#ifndef FAIR_IO_READ_CURVE_H
#define FAIR_IO_READ_CURVE_H

#include <fair/Bezier_2.h>
#include <fair/Errors.h>
#include <fair/Rational_bezier_2.h>
#include <fair/io/parsing.h>
#include <fair/io/read_nurbs.h>  // the "bspline" member: fair::io::read_nurbs

#include <cstddef>
#include <string>
#include <vector>

namespace fair {
namespace io {

/// The contents of a curve JSON.
template <class K>
struct Curve_file {
  std::string file;
  std::string method;            ///< "method", empty when absent
  bool closed = false;           ///< "closed", false when absent
  bool rational = false;         ///< some piece has "weights"
  std::vector<Rational_bezier_2<K>> pieces;  ///< unit weights where a piece has none

  /// The pieces as polynomial Bezier curves (meaningful when !rational: the weights dropped).
  std::vector<Bezier_2<K>> polynomial_pieces() const {
    std::vector<Bezier_2<K>> out;
    out.reserve(pieces.size());
    for (const Rational_bezier_2<K>& p : pieces) out.emplace_back(p.control_points());
    return out;
  }
};

/// What a file that is not a curve JSON is told.
constexpr const char* not_a_curve_json =
    "expected a curve JSON written by fair::io::curve_to_json (an object with a \"pieces\" array)";

/// Parses the text of a curve JSON; `file` names it in error messages.
template <class K>
Curve_file<K> parse_curve_json(const std::string& text, const std::string& file) {
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  Json_value root;
  try {
    root = parse_json(text, file);
  } catch (const Parse_error& e) {
    // A points CSV, or any other text: say what was expected, then the parser's reason.
    const std::string what = e.what();
    const std::string prefix = file + (e.line() ? ":" + std::to_string(e.line()) : std::string()) + ": ";
    throw Parse_error(file, e.line(),
                      std::string(not_a_curve_json) + "; " +
                          (what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what));
  }
  if (root.kind != Json_value::OBJECT) throw Parse_error(file, root.line, not_a_curve_json);
  Curve_file<K> out;
  out.file = file;
  if (const Json_value* m = root.find("method")) {
    if (m->kind != Json_value::STRING) throw Parse_error(file, m->line, "\"method\" must be a string");
    out.method = m->text;
  }
  if (const Json_value* c = root.find("closed")) {
    if (c->kind != Json_value::BOOLEAN) throw Parse_error(file, c->line, "\"closed\" must be true or false");
    out.closed = c->flag;
  }
  const Json_value* pieces = root.find("pieces");
  if (!pieces) throw Parse_error(file, root.line, std::string(not_a_curve_json) + "; this JSON object has no \"pieces\"");
  if (pieces->kind != Json_value::ARRAY || pieces->items.empty())
    throw Parse_error(file, pieces->line, "\"pieces\" must be a nonempty array");
  auto number = [&](const Json_value& v, const std::string& what) {
    if (v.kind != Json_value::NUMBER && v.kind != Json_value::STRING)
      throw Parse_error(file, v.line, what + " must be a number, got " + Json_value::kind_name(v.kind));
    return to_ft<FT>(parse_number(v.text, file, v.line, what.c_str()));
  };
  auto point = [&](const Json_value& xy, const std::string& what) {
    if (xy.kind != Json_value::ARRAY || xy.items.size() != 2)
      throw Parse_error(file, xy.line, what + ": expected an [x, y] pair");
    return Point_2(number(xy.items[0], what + " x"), number(xy.items[1], what + " y"));
  };
  for (std::size_t i = 0; i < pieces->items.size(); ++i) {
    const Json_value& p = pieces->items[i];
    const std::string name = "piece " + std::to_string(i);
    if (p.kind != Json_value::OBJECT) throw Parse_error(file, p.line, name + ": expected an object");
    const Json_value* cps = p.find("control_points");
    if (!cps || cps->kind != Json_value::ARRAY || cps->items.empty())
      throw Parse_error(file, p.line, name + ": needs a nonempty \"control_points\" array");
    std::vector<Point_2> cp;
    for (std::size_t k = 0; k < cps->items.size(); ++k)
      cp.push_back(point(cps->items[k], name + " control point " + std::to_string(k)));
    if (const Json_value* d = p.find("degree")) {
      // The degree is redundant; a file whose degree disagrees with its control points is corrupt.
      if (d->kind != Json_value::NUMBER || d->text != std::to_string(cp.size() - 1))
        throw Parse_error(file, d->line, fair::internal::message(name, ": \"degree\" must be ", cp.size() - 1,
                                                                 " (one less than its control points)"));
    }
    std::vector<FT> w(cp.size(), FT(1));
    if (const Json_value* wv = p.find("weights")) {
      if (wv->kind != Json_value::ARRAY || wv->items.size() != cp.size())
        throw Parse_error(file, wv->line, name + ": \"weights\" must be an array with one weight per control point");
      for (std::size_t k = 0; k < cp.size(); ++k) {
        w[k] = number(wv->items[k], name + " weight");
        if (!(w[k] > FT(0))) throw Parse_error(file, wv->items[k].line, name + ": weights must be > 0");
      }
      out.rational = true;
    }
    out.pieces.emplace_back(std::move(cp), std::move(w));
  }
  return out;
}

/// Reads a curve JSON file (parse_curve_json).
template <class K>
Curve_file<K> read_curve_json(const std::string& file) {
  return parse_curve_json<K>(read_text_file(file), file);
}

} // namespace io
} // namespace fair

#endif // FAIR_IO_READ_CURVE_H
